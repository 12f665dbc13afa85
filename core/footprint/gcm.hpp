#pragma once
// GCM: gray centroid method, paper 001 eq. 1–2 — the baseline every method is compared with.
#include <opencv2/core.hpp>

#include "core/footprint/spot.hpp"

namespace lwb::core::footprint {

struct GcmParams {
    /// Subtract the background before weighting (not in the paper, whose GCM weights raw DN
    /// over the whole chip and is therefore pulled towards the chip centre by the ground).
    bool subtractBackground = false;
};

/// X = Σ x·I / Σ I, Y = Σ y·I / Σ I over the whole CV_32FC1 ROI. Shape from the weighted
/// second moments (majorAxisPx = 4·σ_major). noise (DN) gives the uncertainty.
SpotFit fitGcm(const cv::Mat& roi, double background, double noise, const GcmParams& params = {});

/// Weighted centroid of w (CV_32FC1, values ≥ 0) with second moments and the propagated
/// uncertainty for independent pixel noise of σ = noise. Shared by GCM and TEFM step 5.
SpotFit weightedCentroid(const cv::Mat& w, double noise);

}  // namespace lwb::core::footprint
