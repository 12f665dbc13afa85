#include "core/sim/terrain_photo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <unistd.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/image_codecs.hpp"
#include "core/common/install_paths.hpp"

#ifndef LWB_SOURCE_TERRAIN
#define LWB_SOURCE_TERRAIN ""
#endif

namespace lwb::core::sim {

std::vector<std::string> terrainPhotoDirs() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("LWB_TERRAIN_PHOTOS"); env && *env) dirs.emplace_back(env);
    for (const std::string& d : installedDataCandidates("terrain")) dirs.push_back(d);
    if (*LWB_SOURCE_TERRAIN) dirs.emplace_back(LWB_SOURCE_TERRAIN);  // the build tree's programs and tests
    return dirs;
}

namespace {
// The photograph, or empty (absent or unreadable); *why says so when no decoder could be used at
// all (the codec module not loaded), which the error must name instead of a missing package.
cv::Mat readPhoto(const std::string& path, std::string* why) {
    if (::access(path.c_str(), R_OK) != 0) return {};  // (a candidate folder without it: no decoder warning)
    try {
        return imageRead(path, cv::IMREAD_COLOR);
    } catch (const cv::Exception& e) {
        *why = e.what();
        return {};
    }
}

TerrainPhotos loadPhotos() {
    TerrainPhotos t;
    std::string decoderProblem;
    const char* files[] = {"aero1.jpg", "aero3.jpg"};
    for (const std::string& dir : terrainPhotoDirs()) {
        TerrainPhotos cand;
        cand.dir = dir;
        for (const char* f : files) {
            const cv::Mat bgr = readPhoto(dir + "/" + f, &decoderProblem);
            if (bgr.empty() || bgr.cols < 200 || bgr.rows < 200) continue;
            const int photo = static_cast<int>(cand.names.size());
            cand.names.emplace_back(f);
            cv::Mat grey, ch[3];
            cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
            cv::split(bgr, ch);
            for (const cv::Mat* band : {&grey, &ch[2], &ch[1], &ch[0]}) {
                cv::Mat f32;
                band->convertTo(f32, CV_32F);
                cand.bands.push_back(f32);
                cand.photoOfBand.push_back(photo);
            }
        }
        if (!cand.bands.empty()) {
            cand.ok = true;
            return cand;
        }
    }
    if (!decoderProblem.empty()) {
        t.error = "the terrain photographs cannot be decoded: " + decoderProblem;
        return t;
    }
    t.error = "no terrain photographs (aero1.jpg, aero3.jpg) in";
    for (const std::string& dir : terrainPhotoDirs()) t.error += " " + dir;
    t.error += ": the photographs ship in resources/terrain/ and install to share/laserwb/terrain/; set LWB_TERRAIN_PHOTOS "
               "to a folder holding them";
    return t;
}
}  // namespace

const TerrainPhotos& terrainPhotos() {
    static const TerrainPhotos photos = loadPhotos();
    return photos;
}

cv::Mat terrainPatch(const TerrainPhotos& photos, int w, int h, double mean, double rms, Rng& rng,
                     const TerrainPatchParams& params, TerrainPatchInfo* info) {
    // The band: any of every photograph's four, or (params.photo) one photograph's.
    const int perPhoto = 4, nBands = static_cast<int>(photos.bands.size());
    const bool onePhoto = params.photo >= 0 && (params.photo + 1) * perPhoto <= nBands;
    const int firstBand = onePhoto ? params.photo * perPhoto : 0, bandCount = onePhoto ? perPhoto : nBands;
    const int bandIndex = firstBand + std::min(static_cast<int>(rng.uniform() * bandCount), bandCount - 1);
    cv::Mat mixed;
    if (params.bandMix) {
        // A positive mix of the photograph's red, green and blue (bands 1-3 after luminance).
        const int base = bandIndex - bandIndex % perPhoto;
        double wgt[3], sum = 0;
        for (double& v : wgt) sum += (v = -std::log(std::max(rng.uniform(), 1e-12)));
        mixed = photos.bands[size_t(base + 1)] * (wgt[0] / sum) + photos.bands[size_t(base + 2)] * (wgt[1] / sum) +
                photos.bands[size_t(base + 3)] * (wgt[2] / sum);
    }
    const cv::Mat& src = params.bandMix ? mixed : photos.bands[static_cast<size_t>(bandIndex)];
    // Zoom: photo pixels per ROI pixel, log-uniform; a large frame must still fit in the photo.
    const double half = (std::max(w, h) / 2.0 + 2) * std::sqrt(2.0);
    const double zoomFit = (std::min(src.cols, src.rows) / 2.0 - 8) / half;
    const bool alt = params.altZoomShare > 0 && rng.uniform() < params.altZoomShare;
    const double zHi = std::min(alt ? params.altZoomMax : params.zoomMax, zoomFit),
                 zLo = std::min(alt ? params.altZoomMin : params.zoomMin, zHi);
    const double zoom = std::exp(rng.uniform(std::log(zLo), std::log(zHi)));
    const double angle = rng.uniform(0, 2 * M_PI);
    const bool flip = rng.uniform() < 0.5;
    // Each ROI pixel integrates zoom×zoom photo pixels: a Gaussian of the box's extra spread
    // stands in for the integral before the bilinear resampling.
    const double blur = zoom > 1 ? std::sqrt((zoom * zoom - 1) / 12.0) : 0.0;
    const double reach = zoom * half;
    const int margin = static_cast<int>(std::ceil(3 * blur)) + 3;
    const double lo = reach + margin;
    const double cx = rng.uniform(lo, std::max(lo, src.cols - lo)), cy = rng.uniform(lo, std::max(lo, src.rows - lo));
    cv::Rect box(static_cast<int>(std::floor(cx - reach - margin)), static_cast<int>(std::floor(cy - reach - margin)), 0, 0);
    box.width = static_cast<int>(std::ceil(2 * (reach + margin))) + 2;
    box.height = box.width;
    box &= cv::Rect(0, 0, src.cols, src.rows);
    cv::Mat crop = src(box).clone();
    if (blur > 0.2) cv::GaussianBlur(crop, crop, cv::Size(0, 0), blur, blur, cv::BORDER_REFLECT);
    const double c = std::cos(angle), s = std::sin(angle), fx = flip ? -1.0 : 1.0;
    const double x0 = (w - 1) / 2.0, y0 = (h - 1) / 2.0, u0 = cx - box.x, v0 = cy - box.y;
    // ROI (x, y) → crop (u, v) = centre + zoom·R(angle)·diag(fx, 1)·(x − x0, y − y0).
    cv::Mat M = (cv::Mat_<double>(2, 3) << zoom * c * fx, -zoom * s, u0 - zoom * c * fx * x0 + zoom * s * y0,
                 zoom * s * fx, zoom * c, v0 - zoom * s * fx * x0 - zoom * c * y0);
    cv::Mat patch;
    cv::warpAffine(crop, patch, M, cv::Size(w, h), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REFLECT);
    cv::Scalar m, sd;
    cv::meanStdDev(patch, m, sd);
    const double gain = rms / std::max(sd[0], params.minRawRms);
    patch = (patch - m[0]) * gain + mean;
    if (info) {
        info->photo = photos.names[static_cast<size_t>(photos.photoOfBand[static_cast<size_t>(bandIndex)])];
        info->band = bandIndex % 4;
        info->zoom = zoom;
        info->angleDeg = angle * 180 / M_PI;
        info->flipped = flip;
        info->rawRms = sd[0];
    }
    return patch;
}

}  // namespace lwb::core::sim
