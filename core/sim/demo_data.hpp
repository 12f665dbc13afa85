#pragma once
// The workbench's built-in demos (seeded, deterministic), generated here so the GUI only calls
// them: footprint shots, the calibration inputs and the radiometry field.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/calib/pointing.hpp"
#include "core/calib/waveform.hpp"
#include "core/sim/calib_sim.hpp"

namespace lwb::core::sim {

// ---- footprint ------------------------------------------------------------------------------
struct DemoShot {
    std::string name;    ///< "b1_2020-03_00"
    std::string time;    ///< ISO date/time
    int beam = 1;
    std::string camera;  ///< "LFI"
    cv::Mat roi;         ///< CV_32F, 32 x 32
    cv::Point origin;    ///< full-image position of the ROI's pixel (0, 0)
};
/// About 240 shots, 32x32 ROIs placed at paper 001's LFI beam positions with a slow drift over a
/// year of months, day and night, with doubtful cases.
std::vector<DemoShot> demoFootprintShots();

// ---- calibration (paper 002) -------------------------------------------------------------------
/// A GF-7-like footprint (1 sigma 3.75 m) over a 2.5 m grid of 61 x 41 detectors.
DetectorSimulation demoDetectorArray();
/// Four passes, both beams, the paper's error magnitudes.
CalibSimulation demoCalibrationPasses();
/// Independent check points (22 passes, as paper 002 validates on 22 and 24 points).
std::vector<calib::ControlPoint> demoCheckPoints();
/// A double-peak waveform over a feature of kDemoFeatureHeightM (paper 002's beam-1 case: a 2.9 m wood).
constexpr double kDemoFeatureHeightM = 2.93;
calib::Waveform demoWaveform();
/// Six surveyed candidate features around the footprint.
std::vector<calib::FeatureCandidate> demoFeatures();

// ---- radiometry (paper 003) ---------------------------------------------------------------------
struct DemoRegion {
    std::string name;
    bool check = false;      ///< a check surface (else a grey panel of the fit)
    cv::Rect rect;           ///< scene pixels
    double reflectance = 0;  ///< as measured by the spectrometer (%)
};
struct RadiometryDemoField {
    std::vector<cv::Mat> frames;      ///< six 16-bit frames of one row, in scan order
    cv::Point frame0;                 ///< scene position of frame 0's pixel (0, 0)
    std::vector<DemoRegion> regions;  ///< six grey panels, then four check surfaces
    double k = 0, b = 0;              ///< the simulated line V_REF = K * V_DN + B (%)
};
/// A textured ground with six grey panels of known reflectance for the fit and four check
/// surfaces, photographed as six overlapping frames of one row.
RadiometryDemoField demoRadiometryField();

}  // namespace lwb::core::sim
