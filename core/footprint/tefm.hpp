#pragma once
// TEFM: threshold-constrained ellipse fitting method, paper 001 steps 1–6.
#include <cmath>
#include <opencv2/core.hpp>
#include <string>

#include "core/footprint/spot.hpp"

namespace lwb::core::footprint {

struct TefmParams {
    /// Step 1 ground offset subtracted from the chip (DN). NaN: use the estimated background
    /// (the paper uses a fixed 2000 DN from its histogram statistics).
    double backgroundOffset = NAN;
    double thresholdFactor = 0.1353352832;  ///< step 2: T = factor · max(I − offset); 1/e²
    int erosionSize = 3;                    ///< step 3: neighbourhood D1 (odd side, px); 1 = none
    /// Step 5 weights: true = the eroded image inside the ellipse (the paper's order of steps),
    /// false = the thresholded image inside the ellipse.
    bool centroidOnEroded = true;
};

struct TefmResult {
    SpotFit fit;
    double ellipseX = 0, ellipseY = 0;  ///< fitted ellipse centre (px)
    double ellipseA = 0, ellipseB = 0;  ///< semi-axes (px), A ≥ B
    double ellipseAngleRad = 0;         ///< angle of the A axis from +x
    cv::Mat constrained;                ///< step 4 result (the GCM input), CV_32FC1
};

/// Runs TEFM on a CV_32FC1 ROI. background/noise: the ROI's estimated background level and σ.
TefmResult fitTefm(const cv::Mat& roi, double background, double noise, const TefmParams& params = {});


}  // namespace lwb::core::footprint
