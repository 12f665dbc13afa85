#include "core/sim/slr_sim_lunar.hpp"
#include "core/sim/slr_sim.hpp"

#include <cmath>
#include <cstdio>

#include "core/common/rng.hpp"

namespace lwb::core::sim {

namespace {
constexpr double kMeanDistanceM = 384400e3;
constexpr double kDiurnalM = 4.5e6;         // the station's diurnal swing in range (m)
constexpr double kLunarDayS = 89428.3;      // one lunar day (s)
}  // namespace

std::string validate(const LunarSimParams& p) {
    auto bad = [](double v, double lo, double hi) { return !(v >= lo && v <= hi); };
    if (bad(p.durationS, 1, 86400)) return "duration must be in [1, 86400] s";
    if (bad(p.fireRateHz, 0.1, 1e4)) return "fire rate must be in [0.1, 1e4] Hz";
    if (p.durationS * p.fireRateHz > 2e7) return "more than 2e7 shots";
    if (bad(p.returnProbability, 0, 1) || bad(p.secondProbability, 0, 1) || bad(p.afterpulseProbability, 0, 1))
        return "probabilities must be in [0, 1]";
    if (bad(p.noisePerShot, 0, 100) || bad(p.edgeBandPerShot, 0, 100)) return "noise per shot must be in [0, 100]";
    if (bad(p.gateS, 1e-9, 1e-4)) return "gate must be in [1 ns, 100 µs]";
    if (bad(p.jitterS, 0, 1e-6)) return "jitter must be in [0, 1 µs]";
    if (bad(p.edgeBandS, 0, p.gateS)) return "edge band wider than the gate";
    if (p.burstCount < 0 || (p.burstCount > 0 && bad(p.burstLengthS, 0, p.durationS)) || bad(p.burstFactor, 0, 1e6))
        return "bad bursts";
    return {};
}

LunarSimPass simulateLunarPass(const LunarSimParams& p, uint64_t seed) {
    LunarSimPass out;
    out.error = validate(p);
    if (!out.error.empty()) return out;
    Rng rng(seed * 0x9E3779B97F4A7C15ull + 0x4C554E41ull);
    // The track against the gate's centre: e0 + e1 x + e2 x², x in [-1, 1] over the pass.
    double e0 = rng.uniform(-1, 1) * p.predictionErrorS;
    double e1 = rng.uniform(-0.5, 0.5) * p.predictionSlopeS, e2 = rng.uniform(-0.5, 0.5) * p.predictionSlopeS;
    const double room = 0.45 * p.gateS - 4 * p.jitterS - std::fabs(p.gateShiftS);
    const double reach = std::fabs(e0) + std::fabs(e1) + std::fabs(e2);
    if (reach > room) {
        const double f = room > 0 ? room / reach : 0;
        e0 *= f, e1 *= f, e2 *= f;
    }
    const double phase = rng.uniform(0.3, 1.2);  // where in the lunar day the pass is (rad from transit)
    std::vector<std::pair<double, double>> bursts;
    for (int b = 0; b < p.burstCount; ++b) {
        const double s = rng.uniform(0, p.durationS - p.burstLengthS);
        bursts.emplace_back(s, s + p.burstLengthS);
    }
    const long long shots = static_cast<long long>(std::floor(p.durationS * p.fireRateHz));
    out.shots = shots;
    const double half = 0.5 * p.durationS;
    std::vector<std::pair<double, LunarPointKind>> ev;
    for (long long k = 0; k < shots; ++k) {
        const double el = static_cast<double>(k) / p.fireRateHz;
        const double x = (el - half) / half;
        const double shift = p.gateShiftAtS >= 0 && el >= p.gateShiftAtS ? p.gateShiftS : 0;
        const double lo = shift - 0.5 * p.gateS, hi = shift + 0.5 * p.gateS;
        const double track = e0 + e1 * x + e2 * x * x;
        ev.clear();
        if (p.returnProbability > 0 && rng.uniform() < p.returnProbability)
            ev.emplace_back(track + p.jitterS * rng.normal(), LunarPointKind::Signal);
        if (p.secondProbability > 0 && rng.uniform() < p.secondProbability)
            ev.emplace_back(track + p.secondOffsetS + p.secondSlopeS * x + p.jitterS * rng.normal(), LunarPointKind::SecondTrack);
        double mult = 1;
        bool inBurst = false;
        for (const auto& [a, b] : bursts)
            if (el >= a && el < b) inBurst = true;
        if (inBurst) mult = p.burstFactor;
        const int nn = static_cast<int>(rng.poisson(p.noisePerShot * mult));
        for (int i = 0; i < nn; ++i) ev.emplace_back(rng.uniform(lo, hi), inBurst ? LunarPointKind::Burst : LunarPointKind::Noise);
        if (p.edgeBandS > 0 && p.edgeBandPerShot > 0) {
            const int nb = static_cast<int>(rng.poisson(p.edgeBandPerShot));
            for (int i = 0; i < nb; ++i) ev.emplace_back(rng.uniform(lo, lo + p.edgeBandS), LunarPointKind::EdgeBand);
        }
        if (p.afterpulseProbability > 0) {
            const size_t n0 = ev.size();
            for (size_t i = 0; i < n0; ++i)
                if (rng.uniform() < p.afterpulseProbability)
                    ev.emplace_back(ev[i].first - p.afterpulseDelayS * std::log(1 - rng.uniform()), LunarPointKind::Afterpulse);
        }
        if (ev.empty()) continue;
        const double t = p.startSod + el;
        const double rho = kMeanDistanceM + kDiurnalM * std::cos(phase + 2 * M_PI * el / kLunarDayS);
        const double truthTof = 2 * rho / kSpeedOfLight;
        const double predicted = truthTof - track;
        for (const auto& [oc, kind] : ev) {
            if (!(oc >= lo && oc <= hi)) continue;  // outside the gate: not recorded
            out.epochS.push_back(t);
            out.ocS.push_back(oc);
            out.tofS.push_back(predicted + oc);
            out.kind.push_back(kind);
            out.isSignal.push_back(kind == LunarPointKind::Signal);
            out.signalCount += kind == LunarPointKind::Signal;
        }
    }
    out.ok = true;
    return out;
}

std::string lunarPassCrd(const LunarSimParams& p, const LunarSimPass& pass, int year, int month, int day) {
    // (a TOF of 2.5 s: a tenth of a picosecond needs 13 decimals)
    return simulatedCrd("apollo15 103 103 na  0  2", pass.epochS, pass.tofS, pass.isSignal, p.startSod, year, month, day, 12, 13);
}

}  // namespace lwb::core::sim
