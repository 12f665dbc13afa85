// The footprint parameters' schema (every row: key, unit, range, default, doc) and what reads
// and writes it: configs, presets, the method's name. The pipeline itself is in pipeline.cpp.
#include <cmath>

#include "core/common/schema.hpp"
#include "core/common/text.hpp"
#include "core/footprint/pipeline.hpp"

namespace lwb::core::footprint {

const char* methodName(Method m) {
    switch (m) {
        case Method::Gcm: return "gcm";
        case Method::Tefm: return "tefm";
        case Method::Gauss: return "gauss";
    }
    return "?";
}

bool parseMethod(const std::string& s, Method* m) {
    const std::string l = toLower(trim(s));
    if (l == "gcm") *m = Method::Gcm;
    else if (l == "tefm") *m = Method::Tefm;
    else if (l == "gauss") *m = Method::Gauss;
    else return false;
    return true;
}

namespace {

// The method, the verdict preset's name and the ROI.
void addMethodAndRoi(Schema<FootprintParams>& s) {
    using F = FootprintParams;
    s.choice("method", LWB_FIELD(F, method), {"gcm", "tefm", "gauss"},
             "centre method: gray centroid, TEFM (paper 001) or the Gaussian fit (paper 000 + Guo + LM)");
    s.text("preset", LWB_FIELD(F, preset), "name of the verdict criteria the verdict values came from (wu2021, yao2021)")
        .stage = kStageVerdict;  // a name only: changing it alone refits nothing
    s.integer("roi.size", LWB_FIELD(F, roi.size), "px", {4, 1024}, {16, 64}, "ROI side N cut around the spot");
    s.boolean("roi.size_strict", LWB_FIELD(F, roi.sizeExplicit),
              "a frame smaller than roi.size is an error instead of a smaller ROI (--roi and --set roi.size turn it on)");
    s.real("roi.blob_sigma", LWB_FIELD(F, roi.blobSigma), "px", {0.3, 50, true, true}, {1, 6},
           "spot scale of the blob search's matched filter (frames without --center)");
}

// Background classes and clipping; the spot domain (segmentation) and its second look.
void addBackgroundAndSegment(Schema<FootprintParams>& s) {
    using F = FootprintParams;
    s.real("background.night_below", LWB_FIELD(F, background.nightBelow), "DN", {-1e9, 1e9}, {0, 3000},
           "background below this is a night shot (paper: 300-500 DN)");
    s.real("background.weak_below", LWB_FIELD(F, background.weakBelow), "DN", {-1e9, 1e9}, {2000, 6000},
           "day background below this is weak noise (paper 000: 4000 DN)");
    s.real("background.strong_above", LWB_FIELD(F, background.strongAbove), "DN", {-1e9, 1e9}, {2000, 8000},
           "day background above this is strong noise (paper 000: 4500 DN)");
    s.real("background.clip_sigma", LWB_FIELD(F, background.clipSigma), "", {0.5, 100, true, true}, {1.5, 5},
           "upper clip, in robust sigma, that removes spot pixels from the background");
    s.integer("background.iterations", LWB_FIELD(F, background.iterations), "", {0, 50}, {0, 10}, "clipping passes");
    s.real("segment.threshold_factor", LWB_FIELD(F, segment.thresholdFactor), "", {0, 1, true, true}, {0.05, 0.5},
           "threshold = background + factor x (peak - background); 1/e^2 = 0.1353 (paper 001 eq. 3)");
    s.integer("segment.peak_smooth", LWB_FIELD(F, segment.peakSmooth), "px", {1, 9}, {1, 9},
              "odd box size smoothing the ROI before the peak is taken; 1 = raw");
    s.boolean("segment.fill_holes", LWB_FIELD(F, segment.fillHoles), "dark pixels enclosed by the domain belong to it");
    s.integer("segment.opening_radius", LWB_FIELD(F, segment.openingRadius), "px", {0, 10}, {0, 5},
              "cut features narrower than 2r+1 px (roads) off the domain; 0 = off");
    s.real("segment.min_peak_snr", LWB_FIELD(F, segment.minPeakSnr), "", {0, 1e6, false, true}, {2, 20},
           "(peak - background) / noise below this: no spot");
    s.integer("segment.min_pixels", LWB_FIELD(F, segment.minPixels), "px", {1, 100000}, {1, 50},
              "a domain smaller than this: no spot");
    s.real("segment.local_look_from", LWB_FIELD(F, segment.localLookFrom), "", {0, 1, true, false}, {0.3, 1},
           "peaks from this x min_peak_snr up get a second look against a ring around them (kept as faint, doubtful)");
    s.real("segment.local_snr_floor", LWB_FIELD(F, segment.localSnrFloor), "", {0, 1, true, false}, {0.5, 1},
           "second look: the peak passes standing this x min_peak_snr ring sigma above the ring's median");
    s.real("segment.texture_snr", LWB_FIELD(F, segment.textureSnr), "", {0, 1e6, false, true}, {5, 40},
           "second look: or this many sigma of the ring's pixel-scale texture (neighbour differences / sqrt 2)");
    s.real("segment.ring_inner_px", LWB_FIELD(F, segment.ringInnerPx), "px", {1, 100}, {4, 12}, "inner radius of that ring");
    s.real("segment.ring_outer_px", LWB_FIELD(F, segment.ringOuterPx), "px", {1, 100}, {6, 16}, "outer radius of that ring");
    s.real("segment.second_spot_min_separation_px", LWB_FIELD(F, segment.secondSpotMinSeparation), "px", {1, 1000, false, true},
           {2, 12}, "two peaks at least this far apart are two spots (the second-spot verdict)");
}

// The gray centroid and TEFM (paper 001).
void addGcmAndTefm(Schema<FootprintParams>& s) {
    using F = FootprintParams;
    s.boolean("gcm.subtract_background", LWB_FIELD(F, gcm.subtractBackground),
              "subtract the background before the gray centroid (the paper weights raw DN)");
    s.real("tefm.background_offset", LWB_FIELD(F, tefm.backgroundOffset), "DN", {0, 1e6, false, true}, {0, 5000},
           "step 1 ground offset subtracted from the chip (paper 001: 2000 DN); null = the estimated background")
        .specials = {{NAN, "estimated"}};
    s.real("tefm.threshold_factor", LWB_FIELD(F, tefm.thresholdFactor), "", {0, 1, true, true}, {0.05, 0.5},
           "step 2: T = factor x max(I - offset); 1/e^2");
    s.integer("tefm.erosion_size", LWB_FIELD(F, tefm.erosionSize), "px", {1, 15}, {1, 9},
              "step 3: odd side of the erosion neighbourhood D1; 1 = none");
    s.boolean("tefm.centroid_on_eroded", LWB_FIELD(F, tefm.centroidOnEroded),
              "step 5 weights: the eroded image (the paper's order) instead of the thresholded one");
}

// The Gaussian fit (paper 000 + Guo + LM) and its uncertainty.
void addGauss(Schema<FootprintParams>& s) {
    using F = FootprintParams;
    s.boolean("gauss.xy_term", LWB_FIELD(F, gauss.xyTerm), "add the f.xy column (tilt); false = the paper's system");
    s.integer("gauss.guo_iterations", LWB_FIELD(F, gauss.guoIterations), "", {0, 50}, {0, 6},
              "model-weighted passes after the first solve (0 = paper)");
    s.boolean("gauss.lm", LWB_FIELD(F, gauss.lmRefine), "Levenberg-Marquardt refinement (false = paper / Guo only)");
    s.integer("gauss.lm_max_iterations", LWB_FIELD(F, gauss.lmMaxIterations), "", {1, 500}, {5, 50}, "LM iteration cap");
    s.real("gauss.lm_tolerance_px", LWB_FIELD(F, gauss.lmTolerancePx), "px", {0, 1, true, true}, {1e-4, 0.01},
           "LM stops when a step moves the centre less than this");
    s.real("gauss.lm_tolerance_fraction", LWB_FIELD(F, gauss.lmToleranceFraction), "", {0, 1}, {0, 0.5},
           "LM also stops when a step moves the centre less than this fraction of its uncertainty (uncertainty_px at the start), and takes that step; 0 = off");
    s.real("gauss.lm_tolerance_shape", LWB_FIELD(F, gauss.lmToleranceShape), "", {0, 1, true, false}, {1e-4, 0.05},
           "LM stops only when the step also changes the amplitude and the shape by less than this fraction of their values");
    s.real("gauss.lm_max_move_px", LWB_FIELD(F, gauss.lmMaxMovePx), "px", {0, 100, true, false}, {0.5, 6},
           "LM results further than this from the log fit are not kept");
    s.real("gauss.lm_max_shape_change", LWB_FIELD(F, gauss.lmMaxShapeChange), "", {1, 100, true, false}, {1.2, 4},
           "nor those whose major sigma or sigma1 x sigma2 changed by more than this factor");
    s.real("gauss.lm_window_sigmas", LWB_FIELD(F, gauss.lmWindowSigmas), "sigma", {1, 20}, {1.5, 5},
           "LM window half-width in major-axis sigma, photon-limited ground");
    s.real("gauss.lm_window_sigmas_textured", LWB_FIELD(F, gauss.lmWindowSigmasTextured), "sigma", {1, 20}, {1, 4},
           "LM window half-width in major-axis sigma, textured ground");
    s.real("gauss.textured_ratio", LWB_FIELD(F, gauss.texturedRatio), "", {1, 1000}, {1, 4},
           "ground counts as textured when its sigma exceeds the photon + read sigma by this factor");
    s.integer("gauss.lm_min_half_width", LWB_FIELD(F, gauss.lmMinHalfWidth), "px", {2, 200}, {2, 8}, "LM window half-width lower bound");
    s.real("gauss.core_fraction", LWB_FIELD(F, gauss.coreFraction), "", {0, 0.9}, {0, 0.8},
           "domain not peaked (brighter ground joined it): log fit again on the pixels joined to the peak above "
           "this fraction of the brightest domain pixel's height; 0 = moments at once");
    s.boolean("gauss.difference_fit", LWB_FIELD(F, gauss.differenceFit),
              "textured ground: LM on neighbouring-pixel differences (whitens real ground's red spectrum)");
    s.real("gauss.lm_window_sigmas_difference", LWB_FIELD(F, gauss.lmWindowSigmasDifference), "sigma", {1, 20}, {1.5, 4},
           "LM window half-width in major-axis sigma for the difference fit");
    s.boolean("gauss.uncertainty_from_ground", LWB_FIELD(F, gauss.uncertaintyFromGround),
              "uncertainty_px from the shot's own ground: the fit's centre templates applied to the ground's "
              "autocovariance measured in the ROI plus photon and read noise; false = the quick estimate below");
    s.real("gauss.uncertainty_scale", LWB_FIELD(F, gauss.uncertaintyScale), "", {0.1, 10}, {0.5, 2},
           "factor on the ground part of that uncertainty for fits with the Cauchy loss (the robust fit beats its "
           "linearisation; calibrated on one photograph, aero1)");
    s.real("gauss.radius95_factor", LWB_FIELD(F, gauss.radius95Factor), "", {1, 10}, {1.5, 3},
           "radius95_px = this x uncertainty_px (a Gaussian error: 1.73; on real ground it is heavier-tailed; calibrated on aero1)");
    s.real("gauss.uncertainty_texture_scale", LWB_FIELD(F, gauss.uncertaintyTextureScale), "", {0, 100}, {0, 6},
           "quick uncertainty (LM's stop; uncertainty_px when uncertainty_from_ground is off): texture shift scale "
           "after the difference fit");
    s.real("gauss.uncertainty_texture_scale_pixel_fit", LWB_FIELD(F, gauss.uncertaintyTextureScalePixelFit), "", {0, 100},
           {0, 8}, "the same after the pixel fit");
    s.real("gauss.uncertainty_deadband", LWB_FIELD(F, gauss.uncertaintyDeadband), "", {0, 10}, {0, 1},
           "quick uncertainty: texture counts beyond (1 + this) x the photon part");
    s.boolean("gauss.noise_weights", LWB_FIELD(F, gauss.noiseWeights), "LM weights 1 / (photon + read + ground-texture variance)");
    s.boolean("gauss.robust_loss", LWB_FIELD(F, gauss.robustLoss), "textured ground: Cauchy loss instead of least squares");
    s.real("gauss.robust_scale", LWB_FIELD(F, gauss.robustScale), "sigma", {0.1, 100, true, true}, {0.5, 4},
           "Cauchy scale in residual sigma");
}

// The verdict criteria and the camera.
void addVerdictAndCamera(Schema<FootprintParams>& s) {
    using F = FootprintParams;
    s.beginStage(kStageVerdict);
    s.range("verdict.axis_ratio", LWB_FIELD(F, verdict.axisRatio.enabled), LWB_FIELD(F, verdict.axisRatio.lo),
            LWB_FIELD(F, verdict.axisRatio.hi), "", {0, 1000}, {1, 3},
            "good spots have C = sigma_x / sigma_y in this range (paper 000: (1, 1.5)); null = not checked");
    s.range("verdict.major_axis_px", LWB_FIELD(F, verdict.majorAxisPx.enabled), LWB_FIELD(F, verdict.majorAxisPx.lo),
            LWB_FIELD(F, verdict.majorAxisPx.hi), "px", {0, 10000}, {0, 40},
            "full major axis at 1/e^2 (paper 000: (10, 18))");
    s.range("verdict.tilt_deg", LWB_FIELD(F, verdict.tiltDeg.enabled), LWB_FIELD(F, verdict.tiltDeg.lo),
            LWB_FIELD(F, verdict.tiltDeg.hi), "deg", {-90, 90}, {-90, 90}, "tilt of the x-near axis (paper 000: (-30, 30))");
    s.range("verdict.eccentricity", LWB_FIELD(F, verdict.eccentricity.enabled), LWB_FIELD(F, verdict.eccentricity.lo),
            LWB_FIELD(F, verdict.eccentricity.hi), "", {0, 1}, {0, 1}, "spot eccentricity (paper 001: 0.2-0.8)");
    s.real(
         "verdict.mse_max", [](const F& p) { return p.verdict.mseEnabled ? p.verdict.mseMax : NAN; },
         [](F& p, double v) {
             p.verdict.mseEnabled = !std::isnan(v);
             if (!std::isnan(v)) p.verdict.mseMax = v;
         },
         "", {0, 1e6, true, false}, {1e-7, 1e-3}, "fit residual limit (paper 000 eq. 8, f normalised to unit sum); null = off")
        .specials = {{NAN, "off"}};
    s.real(
         "verdict.max_uncertainty_px",
         [](const F& p) { return p.verdict.maxUncertaintyEnabled ? p.verdict.maxUncertaintyPx : NAN; },
         [](F& p, double v) {
             p.verdict.maxUncertaintyEnabled = !std::isnan(v);
             if (!std::isnan(v)) p.verdict.maxUncertaintyPx = v;
         },
         "px", {0, 1e6, true, false}, {0.05, 2},
         "a centre whose 1-sigma radial uncertainty (uncertainty_px) exceeds this is doubtful; null = off")
        .specials = {{NAN, "off"}};
    s.boolean("verdict.check_edge", LWB_FIELD(F, verdict.checkEdge), "the spot's 1/e^2 ellipse must lie inside the ROI");
    s.real("verdict.edge_extent", LWB_FIELD(F, verdict.edgeExtent), "", {0.5, 5}, {0.8, 2},
           "the edge check uses the 1/e^2 ellipse times this (1.25: the 2.5 sigma ellipse)");
    s.boolean("verdict.check_saturation", LWB_FIELD(F, verdict.checkSaturation), "saturated spot pixels make a shot doubtful");
    s.integer("verdict.saturation_max_pixels", LWB_FIELD(F, verdict.saturationMaxPixels), "px", {0, 1e6}, {0, 20},
              "more saturated domain pixels than this: doubtful");
    s.boolean("verdict.check_second_spot", LWB_FIELD(F, verdict.checkSecondSpot), "a second separate peak makes a shot doubtful");
    s.real("verdict.second_spot_fraction", LWB_FIELD(F, verdict.secondSpotFraction), "", {0, 10, true, false}, {0.1, 1},
           "a separate peak this strong (of the main amplitude): doubtful");
    s.beginStage(kStageFit);  // the camera weights the fit
    s.real("camera.gain_e_per_dn", LWB_FIELD(F, camera.gainEPerDn), "e-/DN", {0, 1e4, true, true}, {0.5, 10},
           "camera gain, for photon noise weights and the Cramer-Rao bound");
    s.real("camera.read_noise_e", LWB_FIELD(F, camera.readNoiseE), "e-", {0, 1e5, false, true}, {0, 100}, "read noise (rms)");
    s.real("camera.saturation_dn", LWB_FIELD(F, camera.saturationDn), "DN", {0, 1e9, true, false}, {4095, 65535},
           "full scale (16383 for 14-bit data)");
}

// The rules between fields.
void addRules(Schema<FootprintParams>& s) {
    using F = FootprintParams;
    s.rule([](const F& p) -> std::string {
        if (!(p.background.nightBelow <= p.background.weakBelow && p.background.weakBelow <= p.background.strongAbove))
            return "noise class thresholds must satisfy background.night_below <= weak_below <= strong_above";
        // Fuzz finding 5: --set preset=<anything> was taken, then the written config could
        // not be read back (a config file's preset must name known criteria).
        if (VerdictParams known; !verdictPreset(p.preset, &known))
            return "preset = \"" + printableExcerpt(p.preset, 40) + "\": must be wu2021 or yao2021";
        if (p.segment.peakSmooth % 2 == 0) return "segment.peak_smooth must be odd (1, 3, 5, 7 or 9 px)";
        if (p.tefm.erosionSize % 2 == 0) return "tefm.erosion_size must be odd (1..15 px)";
        if (!(p.segment.ringInnerPx < p.segment.ringOuterPx)) return "segment.ring_inner_px must be below ring_outer_px";
        return {};
    });
}

}  // namespace

const Schema<FootprintParams>& footprintSchema() {
    static const Schema<FootprintParams> schema = [] {
        Schema<FootprintParams> s("footprint");
        addMethodAndRoi(s);
        addBackgroundAndSegment(s);
        addGcmAndTefm(s);
        addGauss(s);
        addVerdictAndCamera(s);
        addRules(s);
        return s;
    }();
    return schema;
}

std::string validate(const FootprintParams& p) { return footprintSchema().validate(p); }

bool applyPreset(const std::string& name, FootprintParams* p) {
    if (!verdictPreset(name, &p->verdict)) return false;
    p->preset = name;
    return true;
}

bool footprintParamsFromJson(const Json& j, FootprintParams* out, std::string* error, const JsonParseResult* doc) {
    FootprintParams p = *out;
    // A hand-written config may name only a preset: its verdict criteria come first, and any
    // verdict value the file gives overrides them.
    if (j.is_object() && j.contains("preset")) {
        const Json& pr = j["preset"];
        if (!pr.is_string() || !applyPreset(pr.get<std::string>(), &p)) {
            *error = (doc ? doc->where({"preset"}) : std::string()) + "footprint.preset must be wu2021 or yao2021";
            return false;
        }
    }
    if (!footprintSchema().fromJson(j, &p, error, doc)) return false;
    *out = p;
    return true;
}

Json footprintParamsToJson(const FootprintParams& p) { return footprintSchema().toJson(p); }

}  // namespace lwb::core::footprint
