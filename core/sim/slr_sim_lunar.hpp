#pragma once
// Lunar laser ranging passes with exact truth, made adversarial (issue 43): sparse returns
// among Poisson noise over a wide range gate, and the structures real LLR noise has that a
// uniform floor has not. A station fires at fireRateHz for durationS; each shot returns a
// photon from the reflector with returnProbability (Gaussian jitter about the true TOF), and
// noise detections arrive at noisePerShot per shot, uniform over the gate. The gate is centred
// on the prediction, which is off the truth by a slow quadratic (the O-C track seen against the
// pass's own TOF trend). Adversarial variants, each optional:
//  - afterpulses: after any detection, a second one with afterpulseProbability, delayed by an
//    exponential of mean afterpulseDelayS (a single-photon detector's afterpulsing);
//  - an edge band: extra noise (edgeBandPerShot) in the first edgeBandS of the gate (the
//    gate-opening transient): a horizontal band of noise in the O-C;
//  - bursts: burstCount intervals of burstLengthS where the noise is burstFactor times denser
//    (a bright limb in the field, a thin cloud lit by the Moon);
//  - a second, weak track (secondProbability per shot) offset by secondOffsetS with another slope
//    (secondSlopeS over the half pass): a spurious return (a ghost, an internal reflection);
//  - a gate that moves: from gateShiftAtS on, the gate is shifted by gateShiftS (the operator
//    re-centres it), so that the noise's edges step mid-pass.
// returnProbability 0 is a pass with no signal at all. Deterministic for (params, seed).
#include <cstdint>
#include <string>
#include <vector>

namespace lwb::core::sim {

struct LunarSimParams {
    double durationS = 1800;          ///< (0, 86400]
    double startSod = 7200.5;         ///< first shot, seconds of day
    double fireRateHz = 10;           ///< (0, 1e4]
    double returnProbability = 0.02;  ///< signal photons per shot, [0, 1]
    double noisePerShot = 0.05;       ///< noise detections per shot over the whole gate, ≥ 0
    double gateS = 200e-9;            ///< gate width (two-way s), > 0
    double jitterS = 150e-12;         ///< RMS of a return about the true TOF (reflector tilt, laser, detector)
    double predictionErrorS = 40e-9;  ///< |offset| of the track from the gate centre ≤ this (≤ gate/2 − margin)
    double predictionSlopeS = 10e-9;  ///< |change| of the offset over the half pass (linear and quadratic) ≤ this
    // Adversarial variants.
    double afterpulseProbability = 0;
    double afterpulseDelayS = 30e-9;
    double edgeBandS = 0;             ///< width of the band at the gate's opening edge
    double edgeBandPerShot = 0;       ///< its extra noise, detections per shot
    int burstCount = 0;
    double burstLengthS = 60;
    double burstFactor = 20;
    double secondProbability = 0;     ///< the spurious track's detections per shot
    double secondOffsetS = 25e-9;
    double secondSlopeS = 15e-9;
    double gateShiftAtS = -1;         ///< < 0: the gate never moves
    double gateShiftS = 0;
};

/// What each point is (the truth).
enum class LunarPointKind : uint8_t { Noise = 0, Signal = 1, SecondTrack = 2, Afterpulse = 3, EdgeBand = 4, Burst = 5 };

struct LunarSimPass {
    bool ok = false;
    std::string error;
    std::vector<double> epochS;   ///< fire epochs (s of day), ascending
    std::vector<double> tofS;     ///< two-way TOF (s)
    std::vector<double> ocS;      ///< TOF − the prediction (s): the O-C against the gate's prediction
    std::vector<LunarPointKind> kind;
    std::vector<uint8_t> isSignal;  ///< 1: a return from the reflector (kind Signal); everything else is noise
    long long shots = 0, signalCount = 0;
};

std::string validate(const LunarSimParams& p);
LunarSimPass simulateLunarPass(const LunarSimParams& p, uint64_t seed);

/// The pass as a CRD v2 full-rate file of station SIMU ranging Apollo 15 (H3 "apollo15 103":
/// the ILRS missions table's lunar bin applies), filter flag 2 for a return, 1 for the rest.
std::string lunarPassCrd(const LunarSimParams& p, const LunarSimPass& pass, int year = 2024, int month = 6, int day = 15);

}  // namespace lwb::core::sim
