#include "core/sim/footprint_sim.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/common/text.hpp"
#include "core/common/rng.hpp"
#include "core/sim/terrain_photo.hpp"

namespace lwb::core::sim {

const char* sceneName(Scene s) {
    switch (s) {
        case Scene::Weak: return "weak";
        case Scene::Moderate: return "moderate";
        case Scene::Strong: return "strong";
        case Scene::Night: return "night";
        case Scene::Flat: return "flat";
    }
    return "?";
}

const char* spotCaseName(SpotCase c) {
    switch (c) {
        case SpotCase::Normal: return "normal";
        case SpotCase::NoSpot: return "no_spot";
        case SpotCase::Saturated: return "saturated";
        case SpotCase::DoubleSpot: return "double_spot";
        case SpotCase::Edge: return "edge";
        case SpotCase::Elongated: return "elongated";
    }
    return "?";
}

bool parseScene(const std::string& s, Scene* out) {
    for (Scene c : {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night, Scene::Flat})
        if (toLower(s) == sceneName(c)) {
            *out = c;
            return true;
        }
    return false;
}

bool parseSpotCase(const std::string& s, SpotCase* out) {
    for (SpotCase c : {SpotCase::Normal, SpotCase::NoSpot, SpotCase::Saturated, SpotCase::DoubleSpot,
                       SpotCase::Edge, SpotCase::Elongated})
        if (toLower(s) == spotCaseName(c)) {
            *out = c;
            return true;
        }
    return false;
}

const char* groundSourceName(GroundSource g) {
    switch (g) {
        case GroundSource::Photo: return "photo";
        case GroundSource::Synthetic: return "synthetic";
        case GroundSource::Fractal: return "fractal";
        case GroundSource::PhotoCuts: return "photo-cuts";
    }
    return "?";
}

bool parseGroundSource(const std::string& s, GroundSource* out) {
    for (GroundSource g : {GroundSource::Photo, GroundSource::Synthetic, GroundSource::Fractal, GroundSource::PhotoCuts})
        if (toLower(s) == groundSourceName(g)) {
            *out = g;
            return true;
        }
    return false;
}

SceneLevels sceneLevels(Scene s, GroundSource g) {
    const bool photo = g != GroundSource::Synthetic;  // the held-out families take the photo levels
    switch (s) {
        case Scene::Weak: return {2500, 3900, 100, 220, !photo};
        case Scene::Moderate: return {4000, 4500, 150, 300, !photo};
        case Scene::Strong: return {4550, 5400, 220, 420, !photo};
        case Scene::Night: return {300, 500, photo ? 10.0 : 8.0, photo ? 40.0 : 25.0, false};
        case Scene::Flat: return {3000, 3000, 0, 0, false};
    }
    return {0, 0, 0, 0, false};
}

namespace {

// Smooth random field of unit RMS: octaves of bicubically interpolated white noise with a
// red (natural-image-like) spectrum.
cv::Mat textureField(int w, int h, Rng& rng) {
    cv::Mat sum = cv::Mat::zeros(h, w, CV_32F);
    for (int scale : {2, 4, 8, 16, 32, 64}) {
        if (scale > 2 * std::max(w, h)) break;
        const int cw = w / scale + 4, ch = h / scale + 4;
        cv::Mat coarse(ch, cw, CV_32F);
        for (int y = 0; y < ch; ++y)
            for (int x = 0; x < cw; ++x) coarse.at<float>(y, x) = static_cast<float>(rng.normal());
        cv::Mat fine;
        cv::resize(coarse, fine, cv::Size(cw * scale, ch * scale), 0, 0, cv::INTER_CUBIC);
        const int ox = static_cast<int>(rng.uniform() * scale) + scale, oy = static_cast<int>(rng.uniform() * scale) + scale;
        sum += fine(cv::Rect(ox, oy, w, h)) * std::pow(scale, 0.8);
    }
    cv::Scalar mean, sd;
    cv::meanStdDev(sum, mean, sd);
    sum = (sum - mean[0]) / std::max(sd[0], 1e-9);
    return sum;
}

float smoothStep(double d) {  // 1 inside (d < -0.5), 0 outside (d > 0.5), linear across one pixel
    return static_cast<float>(std::clamp(0.5 - d, 0.0, 1.0));
}

void addFeatures(cv::Mat& g, double rms, Rng& rng) {
    const int w = g.cols, h = g.rows;
    if (rng.uniform() < 0.5) {  // road: a straight band, bright concrete or dark asphalt
        const double ang = rng.uniform(0, M_PI), px = rng.uniform(0, w), py = rng.uniform(0, h);
        const double halfWidth = rng.uniform(0.75, 2.0);
        const double sign = rng.uniform() < 0.5 ? -1 : 1;
        const double contrast = sign * rng.uniform(1.5, 4.0) * rms;
        const double nx = -std::sin(ang), ny = std::cos(ang);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double d = std::fabs((x - px) * nx + (y - py) * ny) - halfWidth;
                g.at<float>(y, x) += static_cast<float>(contrast) * smoothStep(d);
            }
    }
    if (rng.uniform() < 0.5) {  // field edge: a step across a straight line
        const double ang = rng.uniform(0, 2 * M_PI), px = rng.uniform(0, w), py = rng.uniform(0, h);
        const double sign = rng.uniform() < 0.5 ? -1 : 1;
        const double contrast = sign * rng.uniform(0.5, 2.0) * rms;
        const double nx = std::cos(ang), ny = std::sin(ang);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                g.at<float>(y, x) += static_cast<float>(contrast) * smoothStep((x - px) * nx + (y - py) * ny);
    }
    if (rng.uniform() < 0.3) {  // building: a small bright rectangle
        const double bw = rng.uniform(2, 5), bh = rng.uniform(2, 5), px = rng.uniform(0, w), py = rng.uniform(0, h);
        const double contrast = rng.uniform(2.0, 5.0) * rms;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double d = std::max(std::fabs(x - px) - bw / 2, std::fabs(y - py) - bh / 2);
                g.at<float>(y, x) += static_cast<float>(contrast) * smoothStep(d);
            }
    }
}

// Adds a pixel-integrated rotated Gaussian.
void addSpot(cv::Mat& img, double x0, double y0, double amp, double sMaj, double sMin, double tilt, int ss) {
    const double c = std::cos(tilt), s = std::sin(tilt);
    const double ia = 1 / (sMaj * sMaj), ib = 1 / (sMin * sMin);
    const int reach = static_cast<int>(std::ceil(7 * sMaj));
    const int xa = std::max(0, static_cast<int>(x0) - reach), xb = std::min(img.cols - 1, static_cast<int>(x0) + reach);
    const int ya = std::max(0, static_cast<int>(y0) - reach), yb = std::min(img.rows - 1, static_cast<int>(y0) + reach);
    for (int y = ya; y <= yb; ++y)
        for (int x = xa; x <= xb; ++x) {
            double acc = 0;
            for (int j = 0; j < ss; ++j)
                for (int i = 0; i < ss; ++i) {
                    const double dx = x - 0.5 + (i + 0.5) / ss - x0, dy = y - 0.5 + (j + 0.5) / ss - y0;
                    const double u = dx * c + dy * s, v = -dx * s + dy * c;
                    acc += std::exp(-0.5 * (u * u * ia + v * v * ib));
                }
            img.at<float>(y, x) += static_cast<float>(amp * acc / (ss * ss));
        }
}

}  // namespace

cv::Mat simulateGround(int width, int height, double mean, double rms, bool features, uint64_t seed) {
    Rng rng(seed);
    cv::Mat g = textureField(width, height, rng) * rms + mean;
    if (features) addFeatures(g, rms, rng);
    return g;
}

namespace {
// Anti-aliased step: 1 on the far side of the line (x − px)·n > 0, 0 on the near side.
float stepAcross(double d) { return static_cast<float>(std::clamp(0.5 + d, 0.0, 1.0)); }
}  // namespace

cv::Mat fractalGround(int width, int height, double mean, double rms, Rng& rng, FractalGroundInfo* info) {
    // A Gaussian field with power ∝ 1/f^β on a grid twice the frame (its periodicity out of sight).
    const int n = cv::getOptimalDFTSize(2 * std::max(width, height));
    const double beta = rng.uniform(1.5, 3.5);
    cv::Mat spec(n, n, CV_64FC2);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double fx = (x <= n / 2 ? x : x - n) / double(n), fy = (y <= n / 2 ? y : y - n) / double(n);
            const double f = std::max(std::hypot(fx, fy), 0.5 / n);
            const double amp = std::pow(f, -beta / 2);
            spec.at<cv::Vec2d>(y, x) = {amp * rng.normal(), amp * rng.normal()};
        }
    spec.at<cv::Vec2d>(0, 0) = {0, 0};
    cv::Mat field;
    cv::dft(spec, field, cv::DFT_INVERSE | cv::DFT_REAL_OUTPUT);
    const int ox = static_cast<int>(rng.uniform() * (n - width)), oy = static_cast<int>(rng.uniform() * (n - height));
    cv::Mat g;
    field(cv::Rect(ox, oy, width, height)).convertTo(g, CV_32F);
    cv::Scalar m0, sd0;
    cv::meanStdDev(g, m0, sd0);
    g = (g - m0[0]) / std::max(sd0[0], 1e-12);
    // Strong sharp edges: 0-3 steps of 1-4 texture σ (field boundaries, shores, roofs), straight or
    // bent (two half-lines meeting at a corner).
    const int edges = static_cast<int>(rng.uniform() * 4);
    for (int e = 0; e < edges; ++e) {
        const double px = rng.uniform(0, width), py = rng.uniform(0, height), a1 = rng.uniform(0, 2 * M_PI);
        const double a2 = rng.uniform() < 0.5 ? a1 : a1 + rng.uniform(-1.2, 1.2);
        const double contrast = (rng.uniform() < 0.5 ? -1 : 1) * rng.uniform(1.0, 4.0);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const double d1 = (x - px) * std::cos(a1) + (y - py) * std::sin(a1);
                const double d2 = (x - px) * std::cos(a2) + (y - py) * std::sin(a2);
                g.at<float>(y, x) += static_cast<float>(contrast) * stepAcross(std::min(d1, d2));
            }
    }
    // Water: a disc or half-plane that is flat (a level of its own, ripples of 3 % of the texture).
    const bool water = rng.uniform() < 0.35;
    if (water) {
        const bool disc = rng.uniform() < 0.5;
        const double px = rng.uniform(0, width), py = rng.uniform(0, height), ang = rng.uniform(0, 2 * M_PI);
        const double radius = rng.uniform(5, 14), level = rng.uniform(-2.0, 1.0);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const double d = disc ? radius - std::hypot(x - px, y - py)
                                      : (x - px) * std::cos(ang) + (y - py) * std::sin(ang);
                const float k = stepAcross(d);
                float& v = g.at<float>(y, x);
                v = (1 - k) * v + k * static_cast<float>(level + 0.03 * rng.normal());
            }
    }
    cv::Scalar m, sd;
    cv::meanStdDev(g, m, sd);
    g = (g - m[0]) * (rms / std::max(sd[0], 1e-12)) + mean;
    if (info) {
        info->beta = beta;
        info->edges = edges;
        info->water = water;
    }
    return g;
}

std::string groundProblem(const FootprintSimParams& p) {
    if ((p.ground != GroundSource::Photo && p.ground != GroundSource::PhotoCuts) || p.scene == Scene::Flat) return {};
    return terrainPhotos().ok ? std::string() : terrainPhotos().error;
}

footprint::GaussModel truthModel(const FootprintSimTruth& t) {
    footprint::GaussModel gm;
    gm.amplitude = t.amplitude;
    gm.x0 = t.x;
    gm.y0 = t.y;
    const double c = std::cos(t.tiltRad), s = std::sin(t.tiltRad);
    const double i1 = 1 / (t.sigmaMajor * t.sigmaMajor), i2 = 1 / (t.sigmaMinor * t.sigmaMinor);
    gm.a = i1 * c * c + i2 * s * s;
    gm.b = (i1 - i2) * c * s;
    gm.c = i1 * s * s + i2 * c * c;
    gm.bg0 = t.groundMean;
    return gm;
}

namespace {

// The ground frame: a terrain photo patch, a fractal field or the synthetic ground, each from its
// own generator seeded with groundSeed. Sets t's ground note (and on a photo patch rescales t's
// texture RMS by the patch's raw RMS).
cv::Mat groundImage(const FootprintSimParams& p, const SceneLevels& lv, const TerrainPhotos& photos, bool photo,
                    bool fractal, uint64_t groundSeed, FootprintSimTruth& t) {
    cv::Mat img;
    if (photo) {
        Rng groundRng(groundSeed);
        TerrainPatchInfo info;
        TerrainPatchParams tp;
        tp.photo = p.photo;
        if (p.ground == GroundSource::PhotoCuts) {
            // Finer and coarser cuts than the simulator's 0.7-2.5, half each; mixed colour bands.
            tp.zoomMin = 0.35;
            tp.zoomMax = 0.7;
            tp.altZoomMin = 2.5;
            tp.altZoomMax = 6.0;
            tp.altZoomShare = 0.5;
            tp.bandMix = true;
        }
        img = terrainPatch(photos, p.width, p.height, t.groundMean, t.textureRms, groundRng, tp, &info);
        t.textureRms = t.textureRms * std::min(1.0, info.rawRms / tp.minRawRms);
        t.groundPhoto = true;
        t.groundNote = info.photo + (tp.bandMix ? " band mix" : " band " + std::to_string(info.band)) + " zoom " +
                       formatFixed(info.zoom, 2) + " angle " + formatFixed(info.angleDeg, 1) + (info.flipped ? " flipped" : "");
    } else if (fractal) {
        Rng groundRng(groundSeed);
        FractalGroundInfo info;
        img = fractalGround(p.width, p.height, t.groundMean, t.textureRms, groundRng, &info);
        t.groundNote = "fractal beta " + formatFixed(info.beta, 2) + " edges " + std::to_string(info.edges) +
                       (info.water ? " water" : "");
    } else {
        img = simulateGround(p.width, p.height, t.groundMean, t.textureRms, lv.features, groundSeed);
        if (p.ground == GroundSource::Photo && p.scene != Scene::Flat) t.groundNote = "synthetic: " + photos.error;
    }
    return img;
}

// The spot's shape and centre (near a border for SpotCase::Edge).
void spotGeometry(const FootprintSimParams& p, Rng& rng, FootprintSimTruth& t) {
    // Spot shape.
    t.sigmaMajor = rng.uniform(p.sigmaMajorMin, p.sigmaMajorMax);
    double ratio = rng.uniform(p.axisRatioMin, p.axisRatioMax);
    if (p.spotCase == SpotCase::Elongated) {
        t.sigmaMajor = rng.uniform(3.6, 4.4);
        ratio = rng.uniform(1.7, 2.6);
    }
    t.sigmaMinor = t.sigmaMajor / ratio;
    t.tiltRad = rng.uniform(-p.tiltMaxDeg, p.tiltMaxDeg) * M_PI / 180;
    const double cx = p.hasCenter ? p.centerX : (p.width - 1) / 2.0;
    const double cy = p.hasCenter ? p.centerY : (p.height - 1) / 2.0;
    t.x = cx + rng.uniform(-p.centreJitterPx, p.centreJitterPx);
    t.y = cy + rng.uniform(-p.centreJitterPx, p.centreJitterPx);
    if (p.spotCase == SpotCase::Edge) {
        const int side = static_cast<int>(rng.uniform() * 4);
        const double d = rng.uniform(1.0, 4.0);
        if (side == 0) t.x = d;
        else if (side == 1) t.x = p.width - 1 - d;
        else if (side == 2) t.y = d;
        else t.y = p.height - 1 - d;
    }
}

// The ground level under the spot; for SpotCase::Saturated a cloud added around it, lifting that level.
double groundUnderSpot(const FootprintSimParams& p, Rng& rng, const FootprintSimTruth& t, cv::Mat& img) {
    double groundAtSpot = img.at<float>(std::clamp(static_cast<int>(std::lround(t.y)), 0, p.height - 1),
                                        std::clamp(static_cast<int>(std::lround(t.x)), 0, p.width - 1));
    if (p.spotCase == SpotCase::Saturated) {
        // A cloud lifts the ground under the spot so that spot + cloud exceed full scale.
        const double cloudSigma = rng.uniform(6, 14);
        const double cloudX = t.x + rng.uniform(-4, 4), cloudY = t.y + rng.uniform(-4, 4);
        const double cloudAmp = rng.uniform(4000, 7000);
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) {
                const double r2 = (x - cloudX) * (x - cloudX) + (y - cloudY) * (y - cloudY);
                img.at<float>(y, x) += static_cast<float>(cloudAmp * std::exp(-0.5 * r2 / (cloudSigma * cloudSigma)));
            }
        groundAtSpot += cloudAmp * 0.7;
    }
    return groundAtSpot;
}

// The spot's amplitude and the spots added: the spot, the second spot of SpotCase::DoubleSpot and
// the second beam's.
void addSpots(const FootprintSimParams& p, double groundAtSpot, Rng& rng, cv::Mat& img, FootprintSimTruth& t) {
    const bool night = p.scene == Scene::Night;
    if (night)
        t.amplitude = rng.uniform(p.nightAmplitudeMin, p.nightAmplitudeMax);
    else
        t.amplitude = rng.uniform(p.dayAmplitudeMin, p.dayAmplitudeMax);
    if (p.spotCase == SpotCase::Saturated)
        t.amplitude = std::max(t.amplitude, 1.15 * p.camera.saturationDn - groundAtSpot);
    t.hasSpot = p.spotCase != SpotCase::NoSpot;
    if (t.hasSpot) addSpot(img, t.x, t.y, t.amplitude, t.sigmaMajor, t.sigmaMinor, t.tiltRad, p.supersample);
    if (p.spotCase == SpotCase::DoubleSpot) {
        for (int attempt = 0; attempt < 50; ++attempt) {
            const double d = rng.uniform(9, 13), phi = rng.uniform(0, 2 * M_PI);
            const double x2 = t.x + d * std::cos(phi), y2 = t.y + d * std::sin(phi);
            if (x2 > 2 && y2 > 2 && x2 < p.width - 3 && y2 < p.height - 3) {
                t.x2 = x2;
                t.y2 = y2;
                break;
            }
        }
        if (!std::isnan(t.x2))
            addSpot(img, t.x2, t.y2, t.amplitude * rng.uniform(0.5, 1.0), t.sigmaMajor, t.sigmaMinor, t.tiltRad,
                    p.supersample);
    }
    if (p.hasSecondBeam && p.spotCase == SpotCase::Normal) {
        // (drawn after everything above, so a one-beam frame is the same with and without it)
        t.x2 = p.center2X + rng.uniform(-p.centreJitterPx, p.centreJitterPx);
        t.y2 = p.center2Y + rng.uniform(-p.centreJitterPx, p.centreJitterPx);
        const double major = rng.uniform(p.sigmaMajorMin, p.sigmaMajorMax);
        const double minor = major / rng.uniform(p.axisRatioMin, p.axisRatioMax);
        const double tilt = rng.uniform(-p.tiltMaxDeg, p.tiltMaxDeg) * M_PI / 180;
        const double amp = night ? rng.uniform(p.nightAmplitudeMin, p.nightAmplitudeMax)
                                 : rng.uniform(p.dayAmplitudeMin, p.dayAmplitudeMax);
        addSpot(img, t.x2, t.y2, amp, major, minor, tilt, p.supersample);
    }
}

// Photon + read noise, quantisation, full-scale clipping: the camera's 16-bit frame of img.
void addCameraNoise(const FootprintSimParams& p, const cv::Mat& img, Rng& rng, cv::Mat& image) {
    const double g = p.camera.gainEPerDn, rn = p.camera.readNoiseE;
    image.create(p.height, p.width, CV_16UC1);
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            const double photons = rng.poisson(std::max(0.0, static_cast<double>(img.at<float>(y, x))) * g);
            const double e = photons + rn * rng.normal();
            const double dn = std::clamp(std::round(e / g), 0.0, p.camera.saturationDn);
            image.at<uint16_t>(y, x) = static_cast<uint16_t>(dn);
        }
}

}  // namespace

FootprintSimShot simulateFootprint(const FootprintSimParams& p, uint64_t seed) {
    Rng rng(seed);
    FootprintSimShot shot;
    FootprintSimTruth& t = shot.truth;
    t.scene = p.scene;
    t.spotCase = p.spotCase;
    const TerrainPhotos& photos = terrainPhotos();
    const bool photo = (p.ground == GroundSource::Photo || p.ground == GroundSource::PhotoCuts) && p.scene != Scene::Flat &&
                       photos.ok;
    const bool fractal = p.ground == GroundSource::Fractal && p.scene != Scene::Flat;
    const SceneLevels lv = sceneLevels(p.scene, photo || fractal ? GroundSource::Photo : GroundSource::Synthetic);
    t.groundMean = rng.uniform(lv.meanMin, lv.meanMax);
    t.textureRms = rng.uniform(lv.textureMin, lv.textureMax);
    const uint64_t groundSeed = rng.next();
    cv::Mat img = groundImage(p, lv, photos, photo, fractal, groundSeed, t);
    spotGeometry(p, rng, t);
    const double groundAtSpot = groundUnderSpot(p, rng, t, img);
    {
        std::vector<float> g(img.begin<float>(), img.end<float>());
        std::nth_element(g.begin(), g.begin() + g.size() / 2, g.end());
        t.groundMedian = g[g.size() / 2];
    }
    addSpots(p, groundAtSpot, rng, img, t);
    if (!t.hasSpot) t.x = t.y = NAN;
    t.expectGood = p.spotCase == SpotCase::Normal;
    addCameraNoise(p, img, rng, shot.image);
    return shot;
}

}  // namespace lwb::core::sim
