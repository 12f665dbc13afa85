#pragma once
// Footprint-camera shot simulator with exact truth: a pixel-integrated, elliptical, tilted
// Gaussian laser spot on ground cut from real aerial photographs (core/sim/terrain_photo; or,
// asked for explicitly, the older synthetic ground: multi-scale noise, roads, field edges),
// clouds, photon + read noise, 14-bit quantisation; day and night scenes and the doubtful
// cases the verdict must catch. Deterministic for a seed.
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "core/footprint/gauss_fit.hpp"
#include "core/footprint/spot.hpp"
#include "core/common/rng.hpp"

namespace lwb::core::sim {

enum class Scene { Weak, Moderate, Strong, Night, Flat };
enum class SpotCase { Normal, NoSpot, Saturated, DoubleSpot, Edge, Elongated };
/// Photo: real aerial photographs (the default); Synthetic: red-spectrum noise + roads, field
/// edges and buildings (the simulator before issue 14, easier than real ground). Two families
/// the fit and its uncertainty were never tuned on (issue 32's held-out ground):
/// Fractal: a Gaussian field with power spectrum 1/f^β, β drawn in 1.5-3.5 per shot, with
/// strong sharp edges (fields, shores) and water-flat patches; PhotoCuts: the same photographs
/// cut finer (zoom 0.35-0.7) and coarser (2.5-6) than the simulator's 0.7-2.5, as random
/// positive mixes of their red, green and blue.
enum class GroundSource { Photo, Synthetic, Fractal, PhotoCuts };
const char* sceneName(Scene s);
const char* spotCaseName(SpotCase c);
bool parseScene(const std::string& s, Scene* out);
bool parseSpotCase(const std::string& s, SpotCase* out);
const char* groundSourceName(GroundSource g);
bool parseGroundSource(const std::string& s, GroundSource* out);

/// Ground level and texture per scene (DN). Day classes follow paper 000's histogram bands
/// (weak < 4000, moderate 4000–4500, strong > 4500); night 300–500 DN.
struct SceneLevels {
    double meanMin, meanMax;        ///< ground mean level (DN)
    double textureMin, textureMax;  ///< ground texture RMS (DN), before features
    bool features;                  ///< roads, field edges and buildings (synthetic ground only)
};
/// Night texture: 10–40 DN RMS on photo ground (real night ground varies more than the 8–25 DN
/// the synthetic ground had); synthetic ground keeps its old ranges.
SceneLevels sceneLevels(Scene s, GroundSource g = GroundSource::Photo);

struct FootprintSimParams {
    int width = 32, height = 32;   ///< image size (a ROI, or 550×550 for a full frame)
    Scene scene = Scene::Weak;
    SpotCase spotCase = SpotCase::Normal;
    footprint::CameraParams camera;  ///< gain, read noise, full scale
    GroundSource ground = GroundSource::Photo;
    int photo = -1;                ///< Photo / PhotoCuts: cut only from this photograph (0 aero1, 1 aero3); -1 = both
    double sigmaMajorMin = 2.5, sigmaMajorMax = 4.2;  ///< px: L_A = 4σ of 10–17 px (paper 000: 10–18)
    double axisRatioMin = 1.1, axisRatioMax = 1.4;    ///< paper 000: ≈ 1.25
    double tiltMaxDeg = 25;        ///< |tilt| of the long axis from x
    double centreJitterPx = 3;     ///< spot centre spread around the image (or given) centre
    /// DN above the ground by day. As in paper 000's experiment (one spot image added to ground
    /// patches of every class) the amplitude does not depend on the ground class; with ground
    /// at 2500–5400 DN the spot peaks land at 6000–12400 DN (paper: "generally above 7000").
    double dayAmplitudeMin = 3500, dayAmplitudeMax = 7000;
    double nightAmplitudeMin = 1100, nightAmplitudeMax = 1600;  ///< DN above the ground at night
    bool hasCenter = false;        ///< place the spot around (centerX, centerY) instead of the middle
    double centerX = 0, centerY = 0;
    /// A second beam's spot around (center2X, center2Y) as well (a two-beam frame, e.g. paper 001's
    /// LSI); its own shape and amplitude, the truth in x2, y2. Normal spots only.
    bool hasSecondBeam = false;
    double center2X = 0, center2Y = 0;
    int supersample = 5;           ///< sub-samples per pixel side for the pixel integral
};

struct FootprintSimTruth {
    bool hasSpot = true;
    double x = 0, y = 0;           ///< exact spot centre (px, image coordinates)
    double sigmaMajor = 0, sigmaMinor = 0, tiltRad = 0;  ///< of the continuous Gaussian
    double amplitude = 0;          ///< DN above the ground at the centre (continuous peak)
    double groundMean = 0;         ///< DN, the texture's mean level (before features and clouds)
    double groundMedian = 0;       ///< DN, median of the noise-free ground under the spot's ROI: where
                                   ///< its histogram concentrates, which is what the noise class means
    double textureRms = 0;         ///< DN, RMS of the ground texture (photo: after scaling)
    bool groundPhoto = false;      ///< the ground is a terrain photograph
    std::string groundNote;        ///< photo, band, zoom, angle, flip; or why no photo was used
    double x2 = NAN, y2 = NAN;     ///< second spot centre (DoubleSpot, or the second beam's spot)
    Scene scene = Scene::Weak;
    SpotCase spotCase = SpotCase::Normal;
    bool expectGood = false;       ///< a normal spot inside the wu2021 criteria
};

struct FootprintSimShot {
    cv::Mat image;                 ///< CV_16UC1, 0..saturation
    FootprintSimTruth truth;
};

/// The truth's spot as a rotated Gaussian on its ground's mean level (no plane).
footprint::GaussModel truthModel(const FootprintSimTruth& truth);

/// Photo ground falls back to synthetic ground when no photographs are installed (the truth
/// says so); callers that need photos check groundProblem() first.
FootprintSimShot simulateFootprint(const FootprintSimParams& params, uint64_t seed);

/// Empty when the asked-for ground can be simulated, else why not (photographs missing).
std::string groundProblem(const FootprintSimParams& params);

/// The ground alone (no noise): multi-scale texture of unit RMS scaled to `rms`, plus mean,
/// plus features when asked. Exposed for tests of the texture statistics.
cv::Mat simulateGround(int width, int height, double mean, double rms, bool features, uint64_t seed);

struct FractalGroundInfo {
    double beta = 0;        ///< spectral slope: power ∝ 1/f^β
    int edges = 0;          ///< sharp steps drawn
    bool water = false;     ///< a water-flat patch
};
/// Fractal ground (GroundSource::Fractal): mean `mean`, RMS `rms` over the frame.
cv::Mat fractalGround(int width, int height, double mean, double rms, Rng& rng, FractalGroundInfo* info = nullptr);

}  // namespace lwb::core::sim
