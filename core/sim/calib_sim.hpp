#pragma once
// Simulators with exact truth for the altimeter calibration (paper 002): orbits, attitudes,
// beam pointings and control points with known pointing / range errors and measurement noise;
// ground detector arrays capturing a Gaussian footprint; double-peak echo waveforms.
// Deterministic for a seed. Consistent with the model in core/calib/pointing.hpp.
#include <cstdint>
#include <vector>

#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/waveform.hpp"

namespace lwb::core::sim {

struct CalibSimParams {
    int passes = 4;                  ///< calibration passes; each gives one control point per firing beam
    bool dualBeam = true;            ///< both beams fire on every pass (false: beam 1 only)
    double altitudeM = 500e3;        ///< orbit height above the ellipsoid (m); GF-7 ranges 450–550 km
    double inclinationDeg = 97.4;    ///< orbit inclination (deg), sun-synchronous
    double siteLatDeg = 42.7, siteLonDeg = 112.6;  ///< calibration field (Inner Mongolia, paper 002)
    double siteHeightM = 1000;       ///< ground height (m)
    double terrainSpreadM = 30;      ///< ± uniform ground height variation between points (m)
    double crossTrackSpreadM = 20e3; ///< ± uniform offset of each pass's ground track from the site (m)
    double attitudeBiasMaxDeg = 0.3; ///< ± uniform roll / pitch / yaw of each pass (deg): geometric diversity
    /// The errors to recover: beam 1 then beam 2 (rad, rad, m).
    double dAlpha[2] = {40e-6, -30e-6};
    double dBeta[2] = {2.0e-3, -1.5e-3};
    double dRho[2] = {-1.011, -1.256};
    double sigmaHorizontalM = 0.5;   ///< control-point horizontal noise per axis (m)
    double sigmaVerticalM = 0.05;    ///< control-point height noise (m)
    double sigmaRangeM = 0.1;        ///< range noise (m)
    double sigmaAttitudeRad = 1e-6;  ///< attitude knowledge noise per axis (rad); shared by a pass's beams
    double sigmaOrbitM = 0.05;       ///< orbit knowledge noise per axis (m); shared by a pass's beams
};

struct CalibSimulation {
    std::vector<calib::BeamDesign> beams;       ///< design (what the solver is told)
    std::vector<calib::ControlPoint> points;    ///< with noisy attitude, orbit, range and survey
    std::vector<Eigen::Vector3d> trueGround;    ///< exact footprint centres (ECEF)
    double dAlpha[2] = {0, 0}, dBeta[2] = {0, 0}, dRho[2] = {0, 0};  ///< truth (rad, rad, m)
    calib::PointingCalibParams matchingParams;  ///< solver noise model equal to the simulated one
};

/// GF-7-like design: beam 1 at α = 0.7°, β = 90° (right of track), beam 2 at α = 0.7°, β = −90°.
std::vector<calib::BeamDesign> gf7Beams();

/// Simulates the passes. Exact truth; noise from the seed.
CalibSimulation simulateCalibration(const CalibSimParams& p, uint64_t seed);

struct DetectorSimParams {
    int rows = 81, columns = 33;     ///< along × across detectors (paper 002: ≈ 400 × 160 m at 5 m)
    double spacingM = 5;             ///< grid spacing (m)
    double sigmaM = 3.75;            ///< footprint 1σ radius (m): 1/e² diameter 15 m (GF-7 footprint)
    double axisRatioMax = 1.2;       ///< major/minor axis ratio drawn in 1..this
    double amplitude = 1000;         ///< peak energy (energy unit)
    double background = 0;           ///< energy unit
    double relativeNoise = 0.05;     ///< energy noise σ as a fraction of the true energy
    double noiseFloor = 2;           ///< additive energy noise σ (energy unit)
    double triggerThreshold = 50;    ///< detectors at or below record nothing (triggered = 0)
    double saturationLevel = 0;      ///< > 0: energies at or above are clipped and flagged saturated
    double centreSpreadM = 10;       ///< footprint centre uniform within ± this of the array centre (m)
    double centreE = NAN, centreN = NAN;  ///< when finite: the footprint centre (m), instead of a random one
    bool geographic = false;         ///< give positions as lat/lon around (originLatDeg, originLonDeg)
    double originLatDeg = 42.7, originLonDeg = 112.6, heightM = 1000;
    /// Every detector reports its energy, background and noise included (negative values too),
    /// with no triggered column; else only detectors above triggerThreshold record an energy.
    bool fullReport = false;
    /// Trigger-style arrays: list the untriggered detectors (triggered = 0, no energy); false
    /// leaves them out of the array, as a field file that holds only the triggered ones.
    bool listUntriggered = true;
    double deadFraction = 0;         ///< each detector is dead with this probability (0..1): it records
                                     ///< 0 in a full report and never triggers otherwise
    bool flagSaturated = true;       ///< the file has the saturated column (false: clipped values unflagged)
};

/// One array of the field population of issue 12, drawn from the seed: 17 × 9 detectors on a
/// 5 m grid, a Gaussian footprint of 13–17 m 1/e² diameter with axis ratio 1–1.3 at any
/// orientation, centre anywhere at least 5 m inside the array's edge, additive noise 2–5 % of the
/// peak; half the arrays report every detector (background 0–3 % of the peak, negative values
/// too), half only the detectors above a trigger level 3 noise σ above the background (untriggered
/// ones listed with triggered = 0 in half of those); 2 % dead detectors; in 30 % of the arrays the
/// peak saturates at 60–95 % of the amplitude (flagged in half of those).
DetectorSimParams drawDetectorFieldCase(uint64_t seed);

struct DetectorSimulation {
    calib::DetectorArray array;
    calib::GaussSurface truth;       ///< exact surface (centre in the array's e, n)
};

DetectorSimulation simulateDetectorArray(const DetectorSimParams& p, uint64_t seed);

struct WaveformSimParams {
    double heightM = 3.0;            ///< feature height: top-to-ground distance (m)
    double incidenceDeg = 0;         ///< beam incidence (deg)
    double sigmaNs = 2.0;            ///< each return's 1σ width (ns): 4–8 ns pulses
    double amplitudeTop = 300, amplitudeGround = 500;
    double baseline = 20;
    double noise = 5;                ///< Gaussian sample noise σ
    int samples = 240;
    double sampleIntervalNs = 0.5;
    double firstReturnNs = 40;       ///< time of the top return (ns)
};

struct WaveformSimulation {
    calib::Waveform waveform;
    double deltaTNs = 0;             ///< exact two-way delay between the returns
};

WaveformSimulation simulateWaveform(const WaveformSimParams& p, uint64_t seed);

}  // namespace lwb::core::sim
