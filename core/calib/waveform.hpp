#pragma once
// Coarse single-beam calibration, footprint location (paper 002 §2.1.1, eq. 1): the height of
// a ground feature from a double-peak echo waveform, and the choice of the surveyed feature
// whose height matches it best.
//
// Height from the waveform: the echo is decomposed into two Gaussians plus a constant
// baseline (Levenberg–Marquardt on the 0.5 ns samples); the earlier peak comes from the top of
// the feature, the later one from the ground, and
//     h = Δt · c / 2 · 1/cos θ,   Δt = t_ground − t_top (two-way time),
// c/2 = 0.149896229 m/ns turning two-way time into one-way distance along the beam. θ is the
// beam's incidence angle from the vertical (parameter, default 0: GF-7 beams are 0.7° off nadir,
// which changes h by 0.007 %). Assumed: both surfaces are flat within the footprint (a slope
// widens each return and biases the peak positions; this is not modelled).
#include <cmath>
#include <string>
#include <vector>

namespace lwb::core::calib {

struct Waveform {
    std::vector<double> timeNs;     ///< sample times (ns), increasing
    std::vector<double> amplitude;  ///< samples (DN or volts)
    /// Read without a time column: timeNs is sample index x the sample interval given to the
    /// reader, and a run with another waveform.sample_interval_ns rescales it (withSampleInterval).
    bool timesFromInterval = false;
    double readIntervalNs = 0;      ///< the interval the times were made with (when timesFromInterval)
};

/// The waveform with its times made from `sampleIntervalNs` when they came from an interval (a
/// file without a time column); unchanged otherwise. The CLI and the workbench both read a
/// waveform through this, so waveform.sample_interval_ns means the same in both.
Waveform withSampleInterval(const Waveform& w, double sampleIntervalNs);

/// Reads a waveform CSV: columns time_ns and amplitude, or amplitude alone (times are then
/// i · sampleIntervalNs), or sample,amplitude (sample index · sampleIntervalNs). Errors name
/// the file and line.
bool readWaveformCsv(const std::string& path, double sampleIntervalNs, Waveform* out, std::string* error);

struct WaveformParams {
    double sampleIntervalNs = 0.5;    ///< used by readers without a time column (ns, > 0); GF-7: 0.5
    double smoothSigmaNs = 1.0;       ///< Gaussian smoothing for the peak search only (ns, ≥ 0)
    double minSeparationNs = 2.0;     ///< smallest peak distance to look for (ns, > 0)
    double minSecondPeak = 0.05;      ///< the weaker peak must reach this fraction of the stronger (0..1)
    double incidenceDeg = 0;          ///< beam incidence from the vertical (deg, 0..60)
    int maxIterations = 200;          ///< LM accepted steps
};
std::string validate(const WaveformParams& p);

struct GaussComponent {
    double amplitude = 0, centreNs = 0, sigmaNs = 0;
    double amplitudeSd = NAN, centreSdNs = NAN, sigmaSdNs = NAN;
};

struct WaveformResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    GaussComponent first, second;     ///< earlier (feature top) and later (ground) return
    double baseline = 0;
    double deltaTNs = NAN, deltaTSdNs = NAN;  ///< second − first centre (two-way ns)
    double heightM = NAN, heightSdM = NAN;    ///< feature height from eq. above (m)
    double rmsResidual = NAN;         ///< RMS of samples − model
    int iterations = 0;
    std::vector<double> model;        ///< fitted waveform at the sample times (for plots)
};

/// Two-Gaussian + baseline decomposition and h = Δt·c/2/cos θ.
WaveformResult decomposeWaveform(const Waveform& w, const WaveformParams& params = {});

/// Two-way time difference (ns) → one-way height (m) at incidence θ (rad).
double heightFromDelay(double deltaTNs, double incidenceRad = 0);

struct FeatureCandidate {
    std::string id;
    double e = NAN, n = NAN;          ///< position (m local, or lat/lon degrees as read)
    double heightM = NAN;             ///< surveyed feature height above the ground around it (m)
    long line = 0;
};

/// Reads candidates: header id, h (or height), and optional position columns (e,n or lat,lon
/// or x,y) passed through. Errors name the file and line.
bool readFeatureCsv(const std::string& path, std::vector<FeatureCandidate>* out, std::string* error);

struct FeatureMatchParams {
    double thresholdM = 0.1;          ///< thred_h (m, > 0); paper 002 uses 0.1 m
};

std::string validate(const FeatureMatchParams& p);

struct FeatureDelta {
    size_t index = 0;                 ///< into the candidate list
    double deltaHM = 0;               ///< |h_i − h_waveform| (m)
    bool belowThreshold = false;  ///< Δh ≤ thred_h
};

struct FeatureMatchResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    bool found = false;               ///< a candidate's Δh is within the threshold
    size_t best = 0;                  ///< index of the smallest Δh (valid when the list is non-empty)
    double bestDeltaHM = NAN;
    std::vector<FeatureDelta> ranking;  ///< every candidate, smallest Δh first (ties: input order)
};

/// Paper 002 eq. 1: Δh_i = |h_i − h_waveform|; the candidate with the smallest Δh within
/// thred_h is where the footprint fell; none when every Δh exceeds thred_h. The paper writes
/// Δh < thred_h but accepts its own beam-1 case, waveform 3.0 m against a 2.9 m wood with
/// thred_h = 0.1 m, so equality is accepted (within 1e-9 m of decimal rounding).
FeatureMatchResult matchFeature(const std::vector<FeatureCandidate>& candidates, double hWaveformM,
                                const FeatureMatchParams& params = {});

}  // namespace lwb::core::calib
