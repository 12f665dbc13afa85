#include "core/sim/demo_data.hpp"

#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "core/sim/footprint_sim.hpp"
#include "core/common/rng.hpp"
#include "core/sim/scene_sim.hpp"

namespace lwb::core::sim {

namespace {
// The calibration demo's fixed seeds.
constexpr uint64_t kDetectorSeed = 20230611, kPointingSeed = 20230612, kCheckSeed = 20230613, kWaveSeed = 20230614;
// Paper 003's line (cement 1 image): V_REF = 0.00126 V_DN - 4.32576, reflectance in %.
constexpr double kDemoK = 0.00126, kDemoB = -4.32576;
constexpr uint64_t kRadiometrySeed = 20230901;
}  // namespace

std::vector<DemoShot> demoFootprintShots() {
    std::vector<DemoShot> shots;
    Rng rng(20200315);
    // Paper 001 Table 2's first-month LFI means; the demo drifts by up to ~1 px over the year.
    const cv::Point2d nominal[2] = {{120.83, 263.71}, {216.32, 162.51}};
    const Scene scenes[] = {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night};
    const SpotCase doubtful[] = {SpotCase::NoSpot, SpotCase::Saturated, SpotCase::DoubleSpot, SpotCase::Edge, SpotCase::Elongated};
    int k = 0;
    for (int month = 0; month < 12; ++month) {
        const int year = 2020 + (2 + month) / 12, mon = (2 + month) % 12 + 1;  // from March 2020
        for (int beam = 0; beam < 2; ++beam) {
            const double drift = month / 11.0;
            const cv::Point2d c = nominal[beam] + cv::Point2d(-0.4 * drift, (beam ? -1.4 : -1.0) * drift + 0.15 * std::sin(month));
            for (int i = 0; i < 10; ++i, ++k) {
                FootprintSimParams p;
                p.scene = scenes[k % 4];
                p.spotCase = (k % 7 == 3) ? doubtful[(k / 7) % 5] : SpotCase::Normal;
                p.centreJitterPx = 0.25;
                const cv::Point origin(int(std::lround(c.x)) - 16, int(std::lround(c.y)) - 16);
                p.hasCenter = true;
                p.centerX = c.x - origin.x;
                p.centerY = c.y - origin.y;
                const auto shot = simulateFootprint(p, rng.next());
                DemoShot s;
                char buf[64];
                std::snprintf(buf, sizeof buf, "b%d_%04d-%02d_%02d", beam + 1, year, mon, i);
                s.name = buf;
                std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT03:14:00Z", year, mon, 1 + 2 * i);
                s.time = buf;
                s.beam = beam + 1;
                s.camera = "LFI";
                shot.image.convertTo(s.roi, CV_32F);
                s.origin = origin;
                shots.push_back(std::move(s));
            }
        }
    }
    return shots;
}

DetectorSimulation demoDetectorArray() {
    // The GF-7-like footprint of the simulator (1 sigma 3.75 m) over a 2.5 m grid, denser than
    // the simulator's 5 m default so the demo footprint covers a few dozen detectors.
    DetectorSimParams p;
    p.rows = 61;
    p.columns = 41;
    p.spacingM = 2.5;
    p.triggerThreshold = 20;
    DetectorSimulation s = simulateDetectorArray(p, kDetectorSeed);
    s.array.source = "demo detector array";
    return s;
}

CalibSimulation demoCalibrationPasses() {
    CalibSimParams p;  // 4 passes, both beams, the paper's error magnitudes
    return simulateCalibration(p, kPointingSeed);
}

std::vector<calib::ControlPoint> demoCheckPoints() {
    CalibSimParams p;
    p.passes = 22;  // paper 002 validates on 22 and 24 points
    return simulateCalibration(p, kCheckSeed).points;
}

calib::Waveform demoWaveform() {
    WaveformSimParams p;
    p.heightM = kDemoFeatureHeightM;
    return simulateWaveform(p, kWaveSeed).waveform;
}

std::vector<calib::FeatureCandidate> demoFeatures() {
    const struct {
        const char* id;
        double e, n, h;
    } f[] = {{"wood W1", -12.5, 8.0, 2.90}, {"shed S2", 6.0, -14.5, 2.45}, {"hedge H3", 15.2, 3.1, 3.35},
             {"wall M4", -3.4, -6.7, 1.60}, {"tree row T5", 21.0, 17.5, 4.20}, {"building B6", -25.0, -20.0, 6.40}};
    std::vector<calib::FeatureCandidate> out;
    for (const auto& x : f) {
        calib::FeatureCandidate c;
        c.id = x.id;
        c.e = x.e;
        c.n = x.n;
        c.heightM = x.h;
        out.push_back(c);
    }
    return out;
}

RadiometryDemoField demoRadiometryField() {
    RadiometryDemoField f;
    f.k = kDemoK;
    f.b = kDemoB;
    RowFramesParams rp;  // 6 frames of 400x360 px, 1/4 overlap (paper 003)
    const int step = int(std::lround(rp.frameWidth * (1 - rp.overlap)));
    const int margin = rp.jitterPx + 2;
    SceneSimParams sp;
    sp.width = (rp.frames - 1) * step + rp.frameWidth + 2 * margin;
    sp.height = rp.frameHeight + 2 * margin;
    cv::Mat scene = simulateScene(sp, kRadiometrySeed);
    Rng rng(Rng::mix(kRadiometrySeed, 7));
    auto dnOf = [](double reflectance) { return (reflectance - kDemoB) / kDemoK; };
    // Grey panels: uniform to 0.3 %, measured by the spectrometer to +-0.15 % reflectance.
    const double panels[] = {4.8, 10.3, 19.7, 30.4, 44.6, 62.1};
    for (int i = 0; i < 6; ++i) {
        // In the middle of frame i, away from the overlaps the mosaic registers on; small enough
        // (< 0.5 % of the pixels each) not to set the mosaic's 8-bit contrast stretch.
        const cv::Rect r(margin + i * step + 184, margin + 60, 32, 32);
        const double level = dnOf(panels[i]);
        for (int y = r.y; y < r.y + r.height; ++y)
            for (int x = r.x; x < r.x + r.width; ++x) scene.at<float>(y, x) = float(level * (1 + 0.003 * rng.normal()));
        DemoRegion d;
        char name[32];
        std::snprintf(name, sizeof name, "panel %.0f %%", panels[i]);
        d.name = name;
        d.rect = cv::Rect(r.x + 5, r.y + 5, r.width - 10, r.height - 10);
        d.reflectance = std::round((panels[i] + 0.15 * rng.normal()) * 1000) / 1000;
        f.regions.push_back(d);
    }
    // Check surfaces: textured (sigma 3 % of the level, 2 px grain), measured to +-1 %.
    const struct {
        const char* name;
        double r;
        int frame;
    } checks[] = {{"cement 1", 27.4, 1}, {"lawn", 8.6, 2}, {"cement 2", 31.2, 3}, {"asphalt", 11.9, 4}};
    for (const auto& c : checks) {
        const cv::Rect r(margin + c.frame * step + 140, margin + 200, 120, 90);
        cv::Mat tex(r.size(), CV_32F);
        for (int y = 0; y < tex.rows; ++y)
            for (int x = 0; x < tex.cols; ++x) tex.at<float>(y, x) = float(rng.normal());
        cv::GaussianBlur(tex, tex, cv::Size(0, 0), 2.0);
        cv::Scalar m, s;
        cv::meanStdDev(tex, m, s);
        const double level = dnOf(c.r);
        cv::Mat patch = scene(r);
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x)
                patch.at<float>(y, x) = float(level * (1 + 0.03 * (tex.at<float>(y, x) - m[0]) / std::max(s[0], 1e-9)));
        DemoRegion d;
        d.name = c.name;
        d.check = true;
        d.rect = cv::Rect(r.x + 10, r.y + 10, r.width - 20, r.height - 20);
        d.reflectance = std::round(c.r * (1 + 0.01 * rng.normal()) * 1000) / 1000;
        f.regions.push_back(d);
    }
    // The frames: jittered offsets along the row, 30 DN of noise each, 16-bit.
    for (int k = 0; k < rp.frames; ++k) {
        const int jx = int(std::lround(rng.uniform(-rp.jitterPx, rp.jitterPx)));
        const int jy = int(std::lround(rng.uniform(-rp.jitterPx, rp.jitterPx)));
        const cv::Point o(margin + k * step + jx, margin + jy);
        if (k == 0) f.frame0 = o;
        cv::Mat fr = scene(cv::Rect(o, cv::Size(rp.frameWidth, rp.frameHeight))).clone();
        for (int y = 0; y < fr.rows; ++y)
            for (int x = 0; x < fr.cols; ++x) fr.at<float>(y, x) += float(rng.normal(0, rp.noiseDn));
        cv::Mat g;
        fr.convertTo(g, CV_16U);
        f.frames.push_back(g);
    }
    return f;
}

}  // namespace lwb::core::sim
