#pragma once
// Real terrain photographs as simulator ground. The photographs are the two aerial views of a
// town, forest, roads and water of OpenCV's sample data (samples/data/aero1.jpg and aero3.jpg,
// Apache-2.0 / BSD-3-Clause like the rest of OpenCV), shipped in resources/terrain/ (its
// README.md gives their source and licence) and installed to share/laserwb/terrain/. A patch is cut at a random
// zoom, rotation and flip, anti-aliased to the ROI's pixels, and scaled to a ground level and
// texture RMS. Structure at every scale and sharp edges come from the ground itself, not from a
// model of it.
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/rng.hpp"

namespace lwb::core::sim {

struct TerrainPhotos {
    bool ok = false;
    std::string error;                 ///< why none could be loaded (when !ok)
    std::string dir;                   ///< where they were found
    std::vector<std::string> names;    ///< file names
    std::vector<cv::Mat> bands;        ///< CV_32F grey bands: per photo luminance, red, green, blue
    std::vector<int> photoOfBand;      ///< index into names
};

/// Folders searched, in order: $LWB_TERRAIN_PHOTOS, the installed share/laserwb/terrain, then the
/// source tree's resources/terrain (programs and tests run from the build tree).
std::vector<std::string> terrainPhotoDirs();
/// The photographs, loaded once per process (thread-safe). ok=false names what is missing.
const TerrainPhotos& terrainPhotos();

struct TerrainPatchInfo {
    std::string photo;       ///< file name
    int band = 0;            ///< 0 luminance, 1 red, 2 green, 3 blue
    double zoom = 1;         ///< photo pixels per ROI pixel
    double angleDeg = 0;     ///< rotation
    bool flipped = false;
    double rawRms = 0;       ///< the patch's RMS before scaling (8-bit grey levels)
};

struct TerrainPatchParams {
    double zoomMin = 0.7, zoomMax = 2.5;  ///< photo px per ROI px, log-uniform
    /// Patches flatter than this (8-bit grey levels RMS: lakes, haze) are not stretched to the
    /// drawn RMS, only by the gain that would bring this RMS there: they stay flat ground, and
    /// JPEG blocks are not amplified into texture.
    double minRawRms = 4.0;
    int photo = -1;       ///< cut only from this photograph (index into names); -1 = any
    /// Grey level as a random positive mix of the red, green and blue bands (weights drawn per
    /// patch) instead of one of the luminance, red, green or blue bands
    bool bandMix = false;
    /// A second zoom range, drawn instead of [zoomMin, zoomMax] with probability altZoomShare
    /// (e.g. finer and coarser cuts than the simulator's own); 0 = never
    double altZoomMin = 0, altZoomMax = 0, altZoomShare = 0;
};

/// A w×h CV_32F patch with mean `mean` and RMS `rms` (DN; less on flat patches, see
/// minRawRms). photos must be ok.
cv::Mat terrainPatch(const TerrainPhotos& photos, int w, int h, double mean, double rms, Rng& rng,
                     const TerrainPatchParams& params = {}, TerrainPatchInfo* info = nullptr);

}  // namespace lwb::core::sim
