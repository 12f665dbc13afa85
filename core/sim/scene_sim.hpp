#pragma once
// Synthetic ground scenes with exact truth for the radiometry tests (paper 003): a textured
// field (slabs, joints, blobs, fine grain) and the overlapping frames a rail-mounted camera
// takes along one row, with their exact offsets. Deterministic for a seed.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace lwb::core::sim {

struct SceneSimParams {
    int width = 2000, height = 500;  ///< scene size (px)
    double meanDn = 20000;           ///< mean level (DN)
    double contrastDn = 8000;        ///< spread of the features' levels (DN)
    int features = 400;              ///< slabs, blobs and joints drawn
    double grainDn = 1500;           ///< fine texture amplitude (DN)
    double grainSigmaPx = 1.2;       ///< its correlation length (px)
};

/// A textured scene as CV_32F DN.
cv::Mat simulateScene(const SceneSimParams& p, uint64_t seed);

struct RowFramesParams {
    int frames = 6;
    int frameWidth = 400, frameHeight = 360;  ///< px
    double overlap = 0.25;           ///< fraction of a frame shared with the next (paper 003: 1/5–1/4)
    int jitterPx = 4;                ///< ± integer jitter of each frame's offset (x and y)
    double noiseDn = 30;             ///< independent noise added to each frame (DN σ)
    int depth = CV_16U;              ///< frame depth: CV_8U, CV_16U or CV_32F
};

struct RowFrames {
    cv::Mat scene;                   ///< CV_32F DN (noise-free)
    std::vector<cv::Mat> frames;     ///< in scan order
    std::vector<cv::Point> offsets;  ///< top-left of each frame in the scene (px, exact)
};

/// Cuts overlapping frames along a row of a scene made for them (8U frames are scaled by 1/256).
RowFrames simulateRowFrames(const RowFramesParams& p, const SceneSimParams& scene, uint64_t seed);

}  // namespace lwb::core::sim
