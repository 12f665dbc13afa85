#pragma once
// Row mosaic of overlapping frames (paper 003 §3.1: "stitch each row from frames that overlap
// by 1/5–1/4"). Consecutive frames of a row, in scan order, are registered by feature matching
// (ORB or AKAZE keypoints, ratio test, RANSAC for the chosen motion model); the transforms are
// chained to the first frame and the frames are blended into one image.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"

namespace lwb::core::radiometry {

/// The point (x, y) mapped by the homography h (pixel coordinates).
inline cv::Point2d applyHomography(const cv::Matx33d& h, double x, double y) {
    const double w = h(2, 0) * x + h(2, 1) * y + h(2, 2);
    return {(h(0, 0) * x + h(0, 1) * y + h(0, 2)) / w, (h(1, 0) * x + h(1, 1) * y + h(1, 2)) / w};
}


enum class FeatureType { Orb, Akaze };
enum class MotionModel {
    Translation,  ///< shift only (a rail-mounted, gimbal-held camera)
    Similarity,   ///< shift, rotation, scale (4 parameters)
    Affine,       ///< 6 parameters
    Homography,   ///< 8 parameters
};
enum class BlendMode {
    Feather,  ///< weights growing with the distance from each frame's edge (no seams)
    Average,  ///< plain mean where frames overlap
    First,    ///< the earliest frame wins (no resampling blur in overlaps)
};
const char* featureTypeName(FeatureType f);
const char* motionModelName(MotionModel m);
const char* blendModeName(BlendMode b);
bool parseFeatureType(const std::string& s, FeatureType* f);
bool parseMotionModel(const std::string& s, MotionModel* m);
bool parseBlendMode(const std::string& s, BlendMode* b);

struct MosaicParams {
    /// AKAZE localises keypoints to ~0.03 px on the synthetic rows of the tests, ORB (faster) to
    /// ~0.5 px; AKAZE is the default.
    FeatureType features = FeatureType::Akaze;
    int maxFeatures = 5000;            ///< ORB keypoints per frame (100..100000)
    double ratioTest = 0.75;           ///< Lowe's ratio for the two nearest descriptors (0..1)
    MotionModel model = MotionModel::Similarity;
    double ransacThresholdPx = 2.0;    ///< RANSAC inlier distance (px, > 0)
    int minInliers = 12;               ///< fewer consistent matches for a pair is an error (≥ 4)
    double maxRotationDeg = 10;        ///< warn above this rotation between neighbours (deg)
    double maxScaleChange = 0.1;       ///< warn above this relative scale change between neighbours
    BlendMode blend = BlendMode::Feather;
    double maxCanvasPixels = 4e8;      ///< larger mosaics are refused (memory)
};
std::string validate(const MosaicParams& p);

struct PairRegistration {
    size_t from = 0, to = 0;           ///< frame `to` registered onto frame `from` (= to − 1)
    int keypointsFrom = 0, keypointsTo = 0;
    int matches = 0;                   ///< after the ratio test
    int inliers = 0;                   ///< RANSAC-consistent
    double rmsPx = NAN;                ///< RMS transfer error of the inliers (px)
    cv::Matx33d transform = cv::Matx33d::eye();  ///< maps `to` pixels into `from` pixels
    double shiftX = 0, shiftY = 0;     ///< where `to`'s origin lands in `from` (px)
    double rotationDeg = 0, scale = 1;
};

struct MosaicResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    cv::Mat image;                     ///< same depth as the frames; 0 outside the coverage
    cv::Mat coverage;                  ///< CV_8U, 255 where a frame contributed
    std::vector<cv::Matx33d> frameToMosaic;  ///< per frame
    std::vector<PairRegistration> pairs;     ///< frames.size() − 1
};

/// Registers consecutive frames and blends the row. Frames: single-channel, same depth (8U,
/// 16U or 32F), any sizes. Errors: fewer than two frames, a pair without enough consistent
/// matches, a canvas too large; cancelled by fb.
MosaicResult mosaicRow(const std::vector<cv::Mat>& frames, const MosaicParams& params = {},
                       const Feedback* fb = nullptr);

/// Peak memory of mosaicRow (bytes) for frames of these pixel counts, measured on 16-bit frames
/// of 0.14–14 Mpx (docs/fuzzing.md, "Memory"): about 70 MB, plus 64 bytes per pixel of the
/// largest consecutive pair (both frames' features, matching, warps in float), plus 8 per pixel
/// of all frames (the frames themselves and the row).
double mosaicPeakBytes(const std::vector<long long>& framePixels);

/// The machine's memory budget for one run: three quarters of the physical memory (bytes).
double memoryBudgetBytes();

/// "" when the frames' headers announce a mosaic whose peak (mosaicPeakBytes) fits in
/// budgetBytes; else why not, with the figures. Reads each file's header only (the pixels are
/// not decoded); a file whose size cannot be read from its header is left to the decoder.
std::string mosaicMemoryProblem(const std::vector<std::string>& paths, double budgetBytes);

/// Writes the pair table (from, to, keypoints, matches, inliers, rms, shift, rotation, scale), atomically.
bool writePairCsv(const std::string& path, const MosaicResult& r, std::string* error);

}  // namespace lwb::core::radiometry
