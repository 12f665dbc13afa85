#pragma once
// SLR pass simulator with exact truth, for tests, benchmarks and the demo. A straight-line
// flyby (closest slant distance d at t_TCA, relative speed v) gives ρ(t) and the range rate
// ρ'(t) = v²(t − t_TCA)/ρ(t); the O-C track follows paper 004 eq. 1 in two-way time of flight:
//   O-C(t) = b + (2/c)·ρ'(t)·τ      (b range bias in s of TOF, τ time bias in s)
// plus Gaussian jitter (and an optional exponential tail: a target signature); noise is
// uniform over the range gate, tied to random shots. Deterministic for a seed.
//
// Kinds (presets): kHz single-photon ranging to a LEO satellite (2 kHz, 2 % return probability,
// 25 ps jitter, 200 ns gate, 40 noise/s at night, 600 by day); conventional 10 Hz ranging to
// LAGEOS (60 % returns, 80 ps, 1 µs gate, 0.3 / 2 noise/s); diffuse (debris) ranging (20 Hz,
// 15 %, 2 ns, 10 µs gate, 3 / 20 noise/s); leo: 10 Hz multi-photon ranging to a low-orbit
// altimetry satellite (Jason class, 1336 km) on a low pass from a noisy station (50 % returns,
// 60 ps, 10 µs gate, 20 / 60 noise/s); daylight: low-SNR 20 Hz ranging to a LEO satellite by
// day (issue 43: 3 % returns, 150 ps, 400 ns gate, 2 / 20 noise/s, 15 min; by day about 3 % of
// the points are signal); dayspad (issue 45): low-SNR daylight single-photon ranging of another
// make than `daylight`, what a tuning must hold on without having been set on it: returns that
// fade with range (∝ (ρ_TCA/ρ)², 3 % on average, a fifth of the middle's at the pass's ends), a
// sky background that rises through the pass (3× from start to end), a detector's first-photon
// bias (noise 4× denser at the gate's start than at its end), a 40 ps target-signature tail and
// a poorer prediction (time bias up to 2 ms: a track sloped across a fifth of the gate), to a
// Starlette-class satellite (800 km) on a 10-minute pass. signalFraction overrides the noise
// rate so that signal / all = fraction (down to 3 % and below).
//
// Hard passes (issue 13): an extra O-C drift (a steep, curved track as against a poor
// prediction or a fitted TOF trend), and gaps in the track (clouds, a lost lock): no signal
// inside a gap (noise goes on unless told otherwise), and the track may resume at another level
// after a gap (a range-bias jump, e.g. a recalibration or a prediction update).
#include <cstdint>
#include <string>
#include <vector>

namespace lwb::core::sim {

constexpr double kSpeedOfLight = 299792458.0;  ///< m/s


enum class SlrKind { Khz, Conventional, Diffuse, Leo, Daylight, Dayspad };
const char* slrKindName(SlrKind k);  ///< "khz", "conventional", "diffuse", "leo", "daylight", "dayspad"
/// Every kind's name, for messages: "khz, conventional, ..., daylight or dayspad".
std::string slrKindList();
bool parseSlrKind(const std::string& s, SlrKind* out);

/// A gap in the track: no signal from startS to startS + lengthS (seconds from the first shot).
struct SlrSimGap {
    double startS = 0, lengthS = 0;
    bool noise = true;         ///< noise goes on in the gap (signal lost); false: no data at all (no tracking)
    double levelShiftS = 0;    ///< the track is shifted by this (two-way s) from the end of the gap on
};

struct SlrSimParams {
    SlrKind kind = SlrKind::Khz;
    bool daylight = false;          ///< day noise rate instead of night
    long long points = 0;           ///< > 0: exactly this many points in durationS (the return probability
                                    ///< follows; the pass grows only past one return per shot); ≤ 5e7
    double durationS = 600;         ///< pass length (s); (0, 172800]
    double signalFraction = 0;      ///< 0: from the noise rate; else signal / all points, (0, 1]
    double startSod = 36007.25;     ///< epoch of the first shot, seconds of day (bins align to 0h)
    double fireRateHz = 2000;       ///< laser fire rate, (0, 1e5]
    double returnProbability = 0.02;  ///< chance a shot gives a signal detection, (0, 1]
    double noiseRateNightHz = 40;   ///< noise detections per second in the gate (night), ≥ 0
    double noiseRateDayHz = 600;    ///< same, by day
    double gateS = 200e-9;          ///< range gate width (two-way s), > 0
    double jitterS = 25e-12;        ///< Gaussian RMS of the signal about the track (s), ≥ 0
    double tailS = 10e-12;          ///< mean of an added exponential tail (target signature, s), ≥ 0
    double altitudeKm = 1336;       ///< satellite altitude (for the normal-point bin length)
    double tcaDistanceKm = 1700;    ///< slant distance at closest approach, > 0
    double velocityKmS = 7.2;       ///< relative speed at closest approach, > 0
    double rangeBiasMaxS = 5e-9;    ///< |b| ≤ this (two-way s), drawn uniformly
    double timeBiasMaxS = 0.3e-3;   ///< |τ| ≤ this (s), drawn uniformly
    double driftSPerS = 0;          ///< extra O-C drift: driftSPerS·x + driftSPerS2·x², x = t − pass middle (s)
    double driftSPerS2 = 0;
    std::vector<SlrSimGap> gaps;    ///< gaps in the track (each inside the pass, lengths > 0)
    double returnRangePower = 0;    ///< > 0: a shot's return probability ∝ (ρ_TCA/ρ)^power, scaled so that
                                    ///< its mean over the pass is returnProbability (each capped at 1);
                                    ///< 0: the same on every shot. [0, 8]; needs points = 0
    double noiseRise = 1;           ///< noise rate at the pass's end over its start (a linear ramp about the
                                    ///< mean rate: a sky that brightens); 1: steady. [0.1, 10]
    double noiseGateSkew = 1;       ///< noise density at the gate's start over at its end (exponential
                                    ///< across the gate: a detector's first-photon bias); 1: uniform. [1, 100]
};

/// The preset physics for a kind (day/night only picks which noise rate is used later).
SlrSimParams slrSimPreset(SlrKind kind);
/// Empty when the params are usable, else what is wrong.
std::string validate(const SlrSimParams& p);

struct SlrSimPass {
    bool ok = false;
    std::string error;
    std::vector<double> epochS;      ///< fire epochs (s of day), ascending
    std::vector<double> ocS;         ///< observed minus computed two-way TOF (s)
    std::vector<uint8_t> isSignal;   ///< truth: 1 signal, 0 noise
    std::vector<double> trackOcS;    ///< exact model O-C at each epoch (no jitter, no tail)
    std::vector<double> tofS;        ///< observed two-way TOF = 2ρ(t)/c + O-C (s)
    double rangeBiasS = 0, timeBiasS = 0, tcaSod = 0;  ///< truth of the track
    double gateLoS = 0, gateS = 0;   ///< the gate [gateLo, gateLo + gate] (O-C, s)
    double durationS = 0, signalFraction = 0;  ///< as generated
    long long shots = 0, signalCount = 0, noiseCount = 0;
};

/// Simulates one pass. Deterministic for (params, seed).
SlrSimPass simulateSlrPass(const SlrSimParams& params, uint64_t seed);

/// The pass as a CRD v2 full-rate file (type-10 records: epoch, two-way time of flight, filter
/// flag) of a simulated station ranging a simulated satellite on `date` (YYYY, MM, DD): the
/// filter flag is the truth (2 signal, 1 noise), as a station's own screening would mark it.
/// The satellite is named after the kind ("lageos1", ILRS id 7603901, for the conventional
/// kind, whose physics is LAGEOS's; "simsat-KIND", id 9999901, for the others); the station is
/// "SIMU", pad 9999. An epoch past midnight rolls the date.
std::string slrPassCrd(const SlrSimParams& p, const SlrSimPass& pass, int year = 2024, int month = 6, int day = 15);
/// Every simulator's CRD writer: the events as a CRD v2 full-rate file of one pass (H1, H2 of a
/// simulated station, H3 `h3` (the fields after "H3 ": target name, ids, class), an H4 over the
/// epochs (full rate, two-way; `emptyStartSod` when there are none), one configuration, a type-10
/// record per event with the truth as its filter flag (2 signal, 1 noise), H8, H9), with
/// `epochDecimals` and `tofDecimals` digits; `h2` the fields after "H2 " (the station).
std::string simulatedCrd(const std::string& h3, const std::vector<double>& epochS, const std::vector<double>& tofS,
                         const std::vector<uint8_t>& isSignal, double emptyStartSod, int year, int month, int day,
                         int epochDecimals = 12, int tofDecimals = 12, const std::string& h2 = "SIMU 9999 99 99  7 ILRS");

/// The model O-C (s) of a pass at epoch t (for truth comparisons): eq. 1 only, without the
/// drift and the level shifts of the gaps (those are in SlrSimPass::trackOcS).
double slrTrackOc(const SlrSimParams& p, double rangeBiasS, double timeBiasS, double tcaSod, double t);

/// Parses gaps written as START:LENGTH[:SHIFT_NS][:nodata], comma-separated (s, s, ns of
/// two-way O-C). False with *error naming the bad item.
bool parseSlrGaps(const std::string& text, std::vector<SlrSimGap>* out, std::string* error);

}  // namespace lwb::core::sim
