#pragma once
// Accuracy experiment of paper 000 on the simulator: many shots per scene, each processed by
// several method variants, errors against the exact truth. Used by the CLI (docs table),
// the tests and the benchmark.
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/sim/footprint_sim.hpp"

namespace lwb::core::sim {

struct MethodVariant {
    std::string name;                    ///< e.g. "gauss", "gauss-paper"
    footprint::FootprintParams params;
};

/// gcm, tefm, gauss-paper (paper 000's exact 5-column f·ln f QR), gauss-xy (+ tilt term),
/// gauss-guo (+ Guo reweighting), gauss (+ LM, the default).
std::vector<MethodVariant> standardVariants();
/// The variant of that name from standardVariants(); false if unknown.
bool findVariant(const std::string& name, MethodVariant* out);

struct EvalParams {
    int countPerScene = 500;
    uint64_t seed = 1;
    std::vector<Scene> scenes{Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night, Scene::Flat};
    SpotCase spotCase = SpotCase::Normal;
    FootprintSimParams sim;              ///< scene and case are overwritten per run
    int threads = 0;                     ///< 0 = all cores
};

struct EvalStats {
    std::string variant;
    Scene scene = Scene::Weak;
    SpotCase spotCase = SpotCase::Normal;
    int n = 0;            ///< shots
    int fitted = 0;       ///< shots with a centre (not rejected)
    int good = 0, doubtful = 0, rejected = 0;
    int classCorrect = 0; ///< noise class equal to the class of the noise-free ground's median
    double meanErr = 0;   ///< mean radial error (px) over fitted shots
    double varErr = 0;    ///< variance of the radial error (px²)
    double rmsErr = 0;    ///< RMS radial error (px)
    double medianErr = 0, p99Err = 0, maxErr = 0;
    double meanCrlb = 0;  ///< RMS of the numerical CRLB (truth parameters, photon + read noise) (px):
                          ///< the floor of rmsErr
    double meanReportedCrlb = 0;  ///< mean of the pipeline's closed-form crlb_px
    int visible = 0;        ///< shots whose spot is plainly visible: amplitude ≥ 5× the ground RMS
    int visibleFitted = 0;  ///< of those, shots that got a centre (good or doubtful)
    int covered = 0;        ///< fitted shots with |error| < uncertainty_px (Rayleigh level: 63.2 %)
    int covered95 = 0;      ///< fitted shots with |error| < radius95_px (or, where none, 1.7308·uncertainty_px: 2.45 σ per axis)
};

/// Empty (with *error set when given) when the simulator cannot make the asked-for ground.
std::vector<EvalStats> evaluateFootprint(const EvalParams& params, const std::vector<MethodVariant>& variants,
                                         Feedback* fb = nullptr, std::string* error = nullptr);

/// Markdown table of the stats (one row per variant and scene).
std::string evalTableMarkdown(const std::vector<EvalStats>& stats);

}  // namespace lwb::core::sim
