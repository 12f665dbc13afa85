#pragma once
// Pixel statistics inside a box or circle region of an image, as SAOImage DS9's region
// statistics: count, sum, mean, median, standard deviation, min, max and the value-weighted
// centroid. Image coordinates: x = column, y = row, pixel centres at integers, the origin at the
// centre of the top-left pixel. Pure math, no Qt; no exceptions.
#include <cstddef>
#include <string>

#include <opencv2/core.hpp>

namespace lwb::core {

enum class RegionShape { Box, Circle };

/// A region. A pixel belongs to it when its centre does: a box takes the centres x with
/// centerX − width/2 ≤ x < centerX + width/2 (the same in y), so a box of integer size takes
/// width × height pixels wherever it sits; a circle takes the centres at a distance ≤ radius.
struct RegionStatsParams {
    RegionShape shape = RegionShape::Box;
    double centerX = 0, centerY = 0;
    double width = 0, height = 0;  ///< box (px)
    double radius = 0;             ///< circle (px)
};

struct RegionStatsResult {
    bool ok = false;      ///< false: bad input, or no finite pixel of the image in the region (error says which)
    std::string error;
    size_t count = 0;     ///< finite pixels inside (the statistics are of these)
    size_t nonFinite = 0; ///< NaN / infinite pixels inside, left out
    size_t outside = 0;   ///< pixel centres of the region that fall outside the image
    double sum = 0, mean = 0, median = 0;
    double stddev = 0;    ///< sample standard deviation (n − 1); 0 for one pixel
    double min = 0, max = 0;
    bool centroidOk = false;           ///< the sum is positive (a value-weighted mean needs it)
    double centroidX = 0, centroidY = 0;  ///< Σ v·x / Σ v, Σ v·y / Σ v over the finite pixels
};

/// `image`: one channel (8U, 16U, 16S, 32S, 32F or 64F). Parts of the region outside the image
/// are counted in `outside` and otherwise ignored.
RegionStatsResult regionStats(const cv::Mat& image, const RegionStatsParams& p);

}  // namespace lwb::core
