#pragma once
// ROI extraction: an N×N window around a nominal centre, or around the brightest
// spot-like blob when no centre is given (paper 000 uses 32×32, paper 001 40×40 chips).
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace lwb::core::footprint {

struct RoiParams {
    int size = 32;              ///< ROI side N (px), 4..1024
    bool sizeExplicit = false;  ///< the user asked for `size`: an image smaller than it is an error
    bool hasCenter = false;     ///< use (centerX, centerY) instead of searching
    double centerX = 0;         ///< nominal centre, full-image x (column), px
    double centerY = 0;         ///< nominal centre, full-image y (row), px
    double blobSigma = 2.5;     ///< spot scale (px) of the blob search's matched filter
};

struct RoiResult {
    bool ok = false;
    std::string error;
    cv::Mat roi;              ///< CV_32FC1 copy, continuous
    int originX = 0;          ///< full-image x of the ROI's pixel (0,0)
    int originY = 0;          ///< full-image y of the ROI's pixel (0,0)
    bool wholeImage = false;  ///< the input already was the ROI
    bool searched = false;    ///< the centre came from the blob search
    std::vector<std::string> warnings;
};

/// Cuts the ROI from a CV_32FC1 frame. An image no larger than N (when N was not asked for
/// explicitly) is taken whole as a ready ROI. A ROI that would cross the frame edge is shifted
/// inside (with a warning); a ROI larger than the frame is an error.
RoiResult extractRoi(const cv::Mat& image, const RoiParams& params);

/// Position (full-image px) of the strongest spot-like blob: maximum of a difference-of-
/// Gaussians matched filter, so broad bright ground (clouds, fields) does not win over the spot.
cv::Point findBrightestBlob(const cv::Mat& image, double sigma);

std::string validate(const RoiParams& p);

}  // namespace lwb::core::footprint
