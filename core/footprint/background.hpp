#pragma once
// Background level, background noise and the noise class of a footprint ROI (paper 000 §3.2:
// the class is where the ground histogram concentrates).
#include <opencv2/core.hpp>
#include <string>

namespace lwb::core::footprint {

enum class NoiseClass { Night, Weak, Moderate, Strong };
const char* noiseClassName(NoiseClass c);

struct BackgroundParams {
    double nightBelow = 1000;   ///< DN; background below this is a night shot (paper: 300–500 DN)
    double weakBelow = 4000;    ///< DN; day background below this is weak noise (paper 000)
    double strongAbove = 4500;  ///< DN; day background above this is strong noise (paper 000)
    double clipSigma = 2.5;     ///< upper clip (in robust σ) that removes spot pixels
    int iterations = 4;         ///< clipping passes
};

struct BackgroundResult {
    bool ok = false;
    std::string error;
    double level = 0;   ///< DN: sigma-clipped median of the ROI (where the ground histogram concentrates)
    double noise = 0;   ///< DN: robust σ (1.4826 MAD) of the clipped pixels: texture + photon noise
    NoiseClass noiseClass = NoiseClass::Weak;
};

/// Estimates the background of a CV_32FC1 ROI. Bright (spot) pixels are clipped iteratively.
BackgroundResult estimateBackground(const cv::Mat& roi, const BackgroundParams& params = {});

}  // namespace lwb::core::footprint
