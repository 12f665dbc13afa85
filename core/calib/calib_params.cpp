#include "core/calib/calib_params.hpp"

namespace lwb::core::calib {

const Schema<CalibParams>& calibSchema() {
    static const Schema<CalibParams> schema = [] {
        using C = CalibParams;
        Schema<C> s("calib");
        const double big = 1e300;
        // ---- detector array (calib detector) ---------------------------------------------------
        s.choice("detector.model", LWB_FIELD(C, detector.model), {"auto", "elliptical", "circular"},
                 "fitted surface: elliptical (7 parameters), circular (5), or auto (elliptical from 10 measurements)");
        s.choice("detector.noise", LWB_FIELD(C, detector.noise), {"data", "given"},
                 "energy noise: estimated from the array (data) or rel_noise and noise_floor as given");
        s.boolean("detector.fit_background", LWB_FIELD(C, detector.fitBackground),
                  "fit the background; false holds it at detector.background");
        s.real("detector.background", LWB_FIELD(C, detector.background), "energy", {-big, big}, {0, 100},
               "the background held fixed when fit_background is false");
        s.real("detector.trigger", LWB_FIELD(C, detector.triggerThreshold), "energy", {0, big}, {0, 200},
               "energies at or below this count as untriggered; 0 = no threshold");
        s.real("detector.saturation", LWB_FIELD(C, detector.saturationLevel), "energy", {0, big}, {0, 10000},
               "energies at or above this count as saturated; 0 = from the flags or a clipped maximum");
        s.real("detector.rel_noise", LWB_FIELD(C, detector.relativeNoise), "", {0, 1}, {0, 0.1},
               "given noise: sigma as a fraction of the energy");
        s.real("detector.noise_floor", LWB_FIELD(C, detector.noiseFloor), "energy", {0, big}, {0, 50},
               "given noise: additive sigma");
        s.boolean("detector.censor", LWB_FIELD(C, detector.censor),
                  "saturated and untriggered detectors enter the fit as bounds (false: set aside)");
        s.real("detector.outlier_sigma", LWB_FIELD(C, detector.outlierSigma), "sigma", {3, 1e6}, {3, 10},
               "set aside detectors more than this many robust sigma off; 0 = off (plain least squares)")
            .specials = {{0, "off"}};
        s.boolean("detector.scale_chi2", LWB_FIELD(C, detector.scaleByChi2),
                  "given noise: scale the covariance by the reduced chi-square");
        s.integer("detector.recommended_detectors", LWB_FIELD(C, detector.recommendedDetectors), "", {0, 100000}, {3, 30},
                  "warn below this many detectors seeing the footprint (paper 002: 9)");
        s.integer("detector.max_iterations", LWB_FIELD(C, detector.maxIterations), "", {1, 10000}, {20, 1000},
                  "Levenberg-Marquardt accepted steps");
        s.real("detector.chi2_probability", LWB_FIELD(C, detector.chi2Probability), "", {0, 0.5}, {1e-6, 0.05},
               "given noise: doubtful when chi-square is this improbable (either tail)")
            .uiLog = true;
        s.real("detector.max_axis_ratio", LWB_FIELD(C, detector.maxAxisRatio), "", {1, 1e6}, {1, 5},
               "doubtful when the fitted footprint's axis ratio exceeds this");
        // ---- pointing calibration (calib pointing) -------------------------------------------------
        s.choice("pointing.model", LWB_FIELD(C, pointing.model), {"single", "dual"},
                 "each beam on its own (single), or beam 2 = beam 1 rotated by dR(r, a, b) (dual)");
        s.boolean("pointing.solve_range", LWB_FIELD(C, pointing.solveRange), "solve the range biases (false: pointing only)");
        s.boolean("pointing.fix_relative", LWB_FIELD(C, pointing.fixRelativeRotation),
                  "dual model: hold the relative rotation at its design");
        s.real("pointing.sigma_h", LWB_FIELD(C, pointing.sigmaHorizontalM), "m", {0, 1e6, true, true}, {0.01, 2},
               "default control-point sigma per horizontal axis");
        s.real("pointing.sigma_v", LWB_FIELD(C, pointing.sigmaVerticalM), "m", {0, 1e6, true, true}, {0.005, 0.5},
               "default control-point height sigma (RTK: 0.05 or less)");
        s.real("pointing.sigma_range", LWB_FIELD(C, pointing.sigmaRangeM), "m", {0, 1e6, false, true}, {0, 1},
               "range noise per shot");
        s.real("pointing.sigma_attitude_urad", [](const C& p) { return p.pointing.sigmaAttitudeRad * 1e6; },
               [](C& p, double v) { p.pointing.sigmaAttitudeRad = v / 1e6; }, "urad", {0, 1e5, false, true}, {0, 20},
               "attitude noise per axis per shot");
        s.real("pointing.sigma_orbit", LWB_FIELD(C, pointing.sigmaOrbitM), "m", {0, 1e6, false, true}, {0, 1},
               "orbit position noise per axis");
        s.boolean("pointing.scale_chi2", LWB_FIELD(C, pointing.scaleByChi2), "scale the covariance by the reduced chi-square");
        s.integer("pointing.max_iterations", LWB_FIELD(C, pointing.maxIterations), "", {1, 1000}, {5, 100},
                  "accepted Levenberg-Marquardt steps");
        s.real("pointing.min_rcond", LWB_FIELD(C, pointing.minRcond), "", {0, 1, true, true}, {1e-12, 1e-6},
               "below this reciprocal condition the geometry is singular")
            .uiLog = true;
        // ---- waveform and feature match (calib waveform) ----------------------------------------
        s.real("waveform.sample_interval_ns", LWB_FIELD(C, waveform.sampleIntervalNs), "ns", {0, 1e6, true, true}, {0.1, 5},
               "sample interval of waveform files without a time column (GF-7: 0.5)");
        s.real("waveform.smooth_ns", LWB_FIELD(C, waveform.smoothSigmaNs), "ns", {0, 1e6, false, true}, {0, 5},
               "Gaussian smoothing for the peak search only");
        s.real("waveform.min_separation_ns", LWB_FIELD(C, waveform.minSeparationNs), "ns", {0, 1e6, true, true}, {0.5, 20},
               "smallest peak distance looked for");
        s.real("waveform.min_second_peak", LWB_FIELD(C, waveform.minSecondPeak), "", {0, 1, true, false}, {0.01, 0.5},
               "the weaker peak must reach this fraction of the stronger");
        s.real("waveform.incidence_deg", LWB_FIELD(C, waveform.incidenceDeg), "deg", {0, 60}, {0, 30},
               "beam incidence from the vertical");
        s.integer("waveform.max_iterations", LWB_FIELD(C, waveform.maxIterations), "", {1, 10000}, {20, 1000},
                  "Levenberg-Marquardt accepted steps");
        s.real("waveform.thred_h", LWB_FIELD(C, match.thresholdM), "m", {0, 1e300, true, false}, {0.01, 1},
               "height threshold thred_h of the feature match (paper 002: 0.1)");
        // ---- the rules between rows (every front end's check: validate(CalibParams)) ----
        s.rule(
            [](const C& p) -> std::string {
                const DetectorFitParams& d = p.detector;
                if (d.saturationLevel > 0 && d.saturationLevel <= d.triggerThreshold)
                    return "detector fit: saturation level must exceed the trigger threshold";
                if (d.scaleByChi2 && d.noise != NoiseSource::Given)
                    return "detector fit: scale_chi2 (--scale-chi2) applies to a given noise model (detector.noise = given: "
                           "--rel-noise / --noise-floor)";
                return {};
            },
            "detector.", false);
        s.rule(
            [](const C& p) -> std::string {
                if (p.pointing.fixRelativeRotation && p.pointing.model != CalibModel::DualBeam)
                    return "pointing calibration: fix_relative (--fix-relative) goes with pointing.model = dual (--model dual)";
                return {};
            },
            "pointing.", false);
        return s;
    }();
    return schema;
}

std::string validate(const CalibParams& p) {
    // The rows' ranges and the rules between them (declared with the rows above), checked once
    // every setting is applied, so the order of --set options does not matter.
    return calibSchema().validate(p);
}

}  // namespace lwb::core::calib
