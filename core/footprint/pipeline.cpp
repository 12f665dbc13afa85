#include "core/footprint/pipeline.hpp"

#include <cmath>

#include "core/common/text.hpp"
#include "core/footprint/crlb.hpp"

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

std::string validate(const FootprintParams& p) {
    for (const std::string& e : {validate(p.roi), validate(p.background), validate(p.segment), validate(p.tefm),
                                 validate(p.gauss), validate(p.verdict)})
        if (!e.empty()) return e;
    if (!(p.camera.gainEPerDn > 0 && p.camera.gainEPerDn < 1e4)) return "camera gain must be in (0, 1e4) e-/DN";
    if (!(p.camera.readNoiseE >= 0 && p.camera.readNoiseE < 1e5)) return "read noise must be in [0, 1e5) e-";
    if (!(p.camera.saturationDn > 0 && p.camera.saturationDn <= 1e9)) return "saturation level must be in (0, 1e9] DN";
    return {};
}

bool applyPreset(const std::string& name, FootprintParams* p) {
    if (!verdictPreset(name, &p->verdict)) return false;
    p->preset = name;
    return true;
}

namespace {
bool readRange(const Json& obj, const std::string& key, Range* r, std::string* error) {
    const Json* v = obj.find(key);
    if (!v) return true;
    if (v->isNull()) {
        r->enabled = false;
        return true;
    }
    if (!v->isArray() || v->items().size() != 2 || !v->items()[0].isNumber() || !v->items()[1].isNumber() ||
        !std::isfinite(v->items()[0].asNumber()) || !std::isfinite(v->items()[1].asNumber())) {
        *error = "\"" + key + "\" must be [low, high] with finite numbers, or null to switch it off";
        return false;
    }
    *r = {true, v->items()[0].asNumber(), v->items()[1].asNumber()};
    return true;
}
Json rangeJson(const Range& r) {
    if (!r.enabled) return Json();
    Json a = Json::array();
    a.push(r.lo);
    a.push(r.hi);
    return a;
}
bool section(const Json& j, const char* key, const Json** out, std::string* error) {
    *out = j.find(key);
    if (*out && !(*out)->isObject()) {
        *error = std::string("\"") + key + "\" must be an object";
        return false;
    }
    return true;
}
}  // namespace

bool footprintParamsFromJson(const Json& j, FootprintParams* out, std::string* error) {
    if (!j.isObject()) {
        *error = "config must be a JSON object";
        return false;
    }
    FootprintParams p = *out;
    std::string s;
    if (const Json* m = j.find("method")) {
        if (!m->isString() || !parseMethod(m->asString(), &p.method)) {
            *error = "\"method\" must be \"gauss\", \"tefm\" or \"gcm\"";
            return false;
        }
    }
    if (const Json* pr = j.find("preset")) {
        if (!pr->isString() || !applyPreset(pr->asString(), &p)) {
            *error = "\"preset\" must be one of: wu2021, yao2021";
            return false;
        }
    }
    const Json* sec = nullptr;
    auto fail = [&](const std::string& where) {
        *error = where + ": " + *error;
        return false;
    };
    if (!section(j, "roi", &sec, error)) return false;
    if (sec && !(jsonInt(*sec, "size", &p.roi.size, error) && jsonNumber(*sec, "blob_sigma", &p.roi.blobSigma, error)))
        return fail("roi");
    if (sec && sec->find("size")) p.roi.sizeExplicit = true;
    if (!section(j, "background", &sec, error)) return false;
    if (sec && !(jsonNumber(*sec, "night_below", &p.background.nightBelow, error) &&
                 jsonNumber(*sec, "weak_below", &p.background.weakBelow, error) &&
                 jsonNumber(*sec, "strong_above", &p.background.strongAbove, error) &&
                 jsonNumber(*sec, "clip_sigma", &p.background.clipSigma, error) &&
                 jsonInt(*sec, "iterations", &p.background.iterations, error)))
        return fail("background");
    if (!section(j, "segment", &sec, error)) return false;
    if (sec && !(jsonNumber(*sec, "threshold_factor", &p.segment.thresholdFactor, error) &&
                 jsonInt(*sec, "peak_smooth", &p.segment.peakSmooth, error) &&
                 jsonBool(*sec, "fill_holes", &p.segment.fillHoles, error) &&
                 jsonInt(*sec, "opening_radius", &p.segment.openingRadius, error) &&
                 jsonNumber(*sec, "min_peak_snr", &p.segment.minPeakSnr, error) &&
                 jsonNumber(*sec, "local_snr_floor", &p.segment.localSnrFloor, error) &&
                 jsonInt(*sec, "min_pixels", &p.segment.minPixels, error)))
        return fail("segment");
    if (!section(j, "gcm", &sec, error)) return false;
    if (sec && !jsonBool(*sec, "subtract_background", &p.gcm.subtractBackground, error)) return fail("gcm");
    if (!section(j, "tefm", &sec, error)) return false;
    if (sec) {
        if (const Json* off = sec->find("background_offset"); off && off->isNull())
            p.tefm.backgroundOffset = NAN;
        else if (!jsonNumber(*sec, "background_offset", &p.tefm.backgroundOffset, error))
            return fail("tefm");
        if (!(jsonNumber(*sec, "threshold_factor", &p.tefm.thresholdFactor, error) &&
              jsonInt(*sec, "erosion_size", &p.tefm.erosionSize, error) &&
              jsonBool(*sec, "centroid_on_eroded", &p.tefm.centroidOnEroded, error)))
            return fail("tefm");
    }
    if (!section(j, "gauss", &sec, error)) return false;
    if (sec && !(jsonBool(*sec, "xy_term", &p.gauss.xyTerm, error) &&
                 jsonInt(*sec, "guo_iterations", &p.gauss.guoIterations, error) &&
                 jsonBool(*sec, "lm", &p.gauss.lmRefine, error) &&
                 jsonInt(*sec, "lm_max_iterations", &p.gauss.lmMaxIterations, error) &&
                 jsonNumber(*sec, "lm_tolerance_px", &p.gauss.lmTolerancePx, error) &&
                 jsonNumber(*sec, "lm_max_move_px", &p.gauss.lmMaxMovePx, error) &&
                 jsonNumber(*sec, "lm_max_shape_change", &p.gauss.lmMaxShapeChange, error) &&
                 jsonNumber(*sec, "lm_window_sigmas", &p.gauss.lmWindowSigmas, error) &&
                 jsonNumber(*sec, "lm_window_sigmas_textured", &p.gauss.lmWindowSigmasTextured, error) &&
                 jsonBool(*sec, "difference_fit", &p.gauss.differenceFit, error) &&
                 jsonNumber(*sec, "lm_window_sigmas_difference", &p.gauss.lmWindowSigmasDifference, error) &&
                 jsonNumber(*sec, "textured_ratio", &p.gauss.texturedRatio, error) &&
                 jsonInt(*sec, "lm_min_half_width", &p.gauss.lmMinHalfWidth, error) &&
                 jsonBool(*sec, "noise_weights", &p.gauss.noiseWeights, error) &&
                 jsonBool(*sec, "robust_loss", &p.gauss.robustLoss, error) &&
                 jsonNumber(*sec, "robust_scale", &p.gauss.robustScale, error)))
        return fail("gauss");
    if (!section(j, "verdict", &sec, error)) return false;
    if (sec) {
        VerdictParams& v = p.verdict;
        if (!(readRange(*sec, "axis_ratio", &v.axisRatio, error) && readRange(*sec, "major_axis_px", &v.majorAxisPx, error) &&
              readRange(*sec, "tilt_deg", &v.tiltDeg, error) && readRange(*sec, "eccentricity", &v.eccentricity, error) &&
              jsonBool(*sec, "check_edge", &v.checkEdge, error) &&
              jsonNumber(*sec, "edge_extent", &v.edgeExtent, error) &&
              jsonBool(*sec, "check_saturation", &v.checkSaturation, error) &&
              jsonInt(*sec, "saturation_max_pixels", &v.saturationMaxPixels, error) &&
              jsonBool(*sec, "check_second_spot", &v.checkSecondSpot, error) &&
              jsonNumber(*sec, "second_spot_fraction", &v.secondSpotFraction, error)))
            return fail("verdict");
        if (const Json* mse = sec->find("mse_max"); mse && mse->isNull())
            v.mseEnabled = false;
        else if (mse && !jsonNumber(*sec, "mse_max", &v.mseMax, error))
            return fail("verdict");
        else if (mse)
            v.mseEnabled = true;
    }
    if (!section(j, "camera", &sec, error)) return false;
    if (sec && !(jsonNumber(*sec, "gain_e_per_dn", &p.camera.gainEPerDn, error) &&
                 jsonNumber(*sec, "read_noise_e", &p.camera.readNoiseE, error) &&
                 jsonNumber(*sec, "saturation_dn", &p.camera.saturationDn, error)))
        return fail("camera");
    if (const std::string e = validate(p); !e.empty()) {
        *error = e;
        return false;
    }
    *out = p;
    return true;
}

Json footprintParamsToJson(const FootprintParams& p) {
    Json j = Json::object();
    j.set("method", methodName(p.method));
    j.set("preset", p.preset);
    Json roi = Json::object();
    roi.set("size", p.roi.size);
    roi.set("blob_sigma", p.roi.blobSigma);
    j.set("roi", roi);
    Json bg = Json::object();
    bg.set("night_below", p.background.nightBelow);
    bg.set("weak_below", p.background.weakBelow);
    bg.set("strong_above", p.background.strongAbove);
    bg.set("clip_sigma", p.background.clipSigma);
    bg.set("iterations", p.background.iterations);
    j.set("background", bg);
    Json seg = Json::object();
    seg.set("threshold_factor", p.segment.thresholdFactor);
    seg.set("peak_smooth", p.segment.peakSmooth);
    seg.set("fill_holes", p.segment.fillHoles);
    seg.set("opening_radius", p.segment.openingRadius);
    seg.set("min_peak_snr", p.segment.minPeakSnr);
    seg.set("local_snr_floor", p.segment.localSnrFloor);
    seg.set("min_pixels", p.segment.minPixels);
    j.set("segment", seg);
    Json gcm = Json::object();
    gcm.set("subtract_background", p.gcm.subtractBackground);
    j.set("gcm", gcm);
    Json tefm = Json::object();
    tefm.set("background_offset", std::isnan(p.tefm.backgroundOffset) ? Json() : Json(p.tefm.backgroundOffset));
    tefm.set("threshold_factor", p.tefm.thresholdFactor);
    tefm.set("erosion_size", p.tefm.erosionSize);
    tefm.set("centroid_on_eroded", p.tefm.centroidOnEroded);
    j.set("tefm", tefm);
    Json g = Json::object();
    g.set("xy_term", p.gauss.xyTerm);
    g.set("guo_iterations", p.gauss.guoIterations);
    g.set("lm", p.gauss.lmRefine);
    g.set("lm_max_iterations", p.gauss.lmMaxIterations);
    g.set("lm_tolerance_px", p.gauss.lmTolerancePx);
    g.set("lm_max_move_px", p.gauss.lmMaxMovePx);
    g.set("lm_max_shape_change", p.gauss.lmMaxShapeChange);
    g.set("lm_window_sigmas", p.gauss.lmWindowSigmas);
    g.set("lm_window_sigmas_textured", p.gauss.lmWindowSigmasTextured);
    g.set("difference_fit", p.gauss.differenceFit);
    g.set("lm_window_sigmas_difference", p.gauss.lmWindowSigmasDifference);
    g.set("textured_ratio", p.gauss.texturedRatio);
    g.set("lm_min_half_width", p.gauss.lmMinHalfWidth);
    g.set("noise_weights", p.gauss.noiseWeights);
    g.set("robust_loss", p.gauss.robustLoss);
    g.set("robust_scale", p.gauss.robustScale);
    j.set("gauss", g);
    Json v = Json::object();
    v.set("axis_ratio", rangeJson(p.verdict.axisRatio));
    v.set("major_axis_px", rangeJson(p.verdict.majorAxisPx));
    v.set("tilt_deg", rangeJson(p.verdict.tiltDeg));
    v.set("eccentricity", rangeJson(p.verdict.eccentricity));
    v.set("mse_max", p.verdict.mseEnabled ? Json(p.verdict.mseMax) : Json());
    v.set("check_edge", p.verdict.checkEdge);
    v.set("edge_extent", p.verdict.edgeExtent);
    v.set("check_saturation", p.verdict.checkSaturation);
    v.set("saturation_max_pixels", p.verdict.saturationMaxPixels);
    v.set("check_second_spot", p.verdict.checkSecondSpot);
    v.set("second_spot_fraction", p.verdict.secondSpotFraction);
    j.set("verdict", v);
    Json cam = Json::object();
    cam.set("gain_e_per_dn", p.camera.gainEPerDn);
    cam.set("read_noise_e", p.camera.readNoiseE);
    cam.set("saturation_dn", p.camera.saturationDn);
    j.set("camera", cam);
    return j;
}

FootprintResult processRoi(const cv::Mat& roi, const FootprintParams& params) {
    FootprintResult r;
    r.method = params.method;
    if (roi.empty() || roi.type() != CV_32FC1) {
        r.error = "ROI must be a non-empty single-channel float image";
        return r;
    }
    if (roi.cols < 5 || roi.rows < 5) {
        r.error = "ROI is only " + std::to_string(roi.cols) + "x" + std::to_string(roi.rows) + " px";
        return r;
    }
    if (const std::string e = validate(params); !e.empty()) {
        r.error = e;
        return r;
    }
    if (!cv::checkRange(roi)) {
        r.error = "ROI holds NaN or infinite pixels";
        return r;
    }
    r.background = estimateBackground(roi, params.background);
    if (!r.background.ok) {
        r.error = r.background.error;
        return r;
    }
    const double bg = r.background.level, noise = r.background.noise;
    r.domain = segmentSpot(roi, bg, noise, params.camera.saturationDn, params.segment);
    r.ok = true;
    std::string fallbackNote;  // the Gaussian fit had to start from moments: doubtful
    if (r.domain.found) {
        switch (params.method) {
            case Method::Gcm: r.fit = fitGcm(roi, bg, noise, params.gcm); break;
            case Method::Tefm:
                r.tefm = fitTefm(roi, bg, noise, params.tefm);
                r.fit = r.tefm.fit;
                break;
            case Method::Gauss: {
                GaussResult g = fitGauss(roi, r.domain, bg, noise, params.gauss, params.camera);
                r.fit = g.fit;
                r.gaussModel = g.model;
                r.gaussStage = g.stage;
                fallbackNote = g.fallbackStart ? g.note : std::string();
                break;
            }
        }
        if (r.fit.ok) {
            r.fit.areaPx = params.method == Method::Gauss ? r.domain.pixels.size() : r.fit.areaPx;
            const double big = std::max(r.fit.sigmaX, r.fit.sigmaY), small = std::min(r.fit.sigmaX, r.fit.sigmaY);
            // For TEFM/GCM the "σ" are ellipse semi-axes / moments: scale to Gaussian σ.
            const double toSigma = params.method == Method::Tefm ? 0.5 : 1.0;
            const CrlbResult c = crlbClosedForm(r.fit.amplitude, big * toSigma, small * toSigma,
                                                r.fit.background, params.camera, false);
            if (c.ok) r.crlbPx = c.radialPx;
        }
    }
    const Judgement j = judge(r.fit, r.domain, roi.cols, roi.rows, params.verdict);
    r.verdict = j.verdict;
    r.reasons = j.reasons;
    if (!fallbackNote.empty() && r.verdict == Verdict::Good) r.verdict = Verdict::Doubtful;
    if (!fallbackNote.empty() && r.verdict == Verdict::Doubtful) r.reasons.push_back(fallbackNote);
    return r;
}

std::vector<FrameRoiResult> processFrame(const cv::Mat& image, const FootprintParams& params,
                                         const std::vector<cv::Point2d>& centres) {
    std::vector<FrameRoiResult> out;
    std::vector<RoiParams> rois;
    if (centres.empty()) {
        rois.push_back(params.roi);
    } else {
        for (const auto& c : centres) {
            RoiParams rp = params.roi;
            rp.hasCenter = true;
            rp.centerX = c.x;
            rp.centerY = c.y;
            rois.push_back(rp);
        }
    }
    for (const RoiParams& rp : rois) {
        FrameRoiResult fr;
        const RoiResult roi = extractRoi(image, rp);
        if (!roi.ok) {
            fr.result.error = roi.error;
            out.push_back(std::move(fr));
            continue;
        }
        fr.originX = roi.originX;
        fr.originY = roi.originY;
        fr.warnings = roi.warnings;
        fr.result = processRoi(roi.roi, params);
        out.push_back(std::move(fr));
    }
    return out;
}

}  // namespace lwb::core::footprint
