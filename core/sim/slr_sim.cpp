#include "core/sim/slr_sim.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "core/common/text.hpp"
#include "core/common/rng.hpp"

namespace lwb::core::sim {

namespace {

double rangeM(const SlrSimParams& p, double tcaSod, double t) {
    const double d = p.tcaDistanceKm * 1e3, v = p.velocityKmS * 1e3, x = v * (t - tcaSod);
    return std::sqrt(d * d + x * x);
}
double rangeRateMs(const SlrSimParams& p, double tcaSod, double t) {
    const double v = p.velocityKmS * 1e3;
    return v * v * (t - tcaSod) / rangeM(p, tcaSod, t);
}
}  // namespace

const char* slrKindName(SlrKind k) {
    switch (k) {
        case SlrKind::Khz: return "khz";
        case SlrKind::Conventional: return "conventional";
        case SlrKind::Diffuse: return "diffuse";
        case SlrKind::Leo: return "leo";
        case SlrKind::Daylight: return "daylight";
        case SlrKind::Dayspad: return "dayspad";
    }
    return "?";
}

namespace {
constexpr SlrKind kKinds[] = {SlrKind::Khz, SlrKind::Conventional, SlrKind::Diffuse, SlrKind::Leo, SlrKind::Daylight, SlrKind::Dayspad};
}

std::string slrKindList() {
    std::string s;
    const size_t n = sizeof kKinds / sizeof kKinds[0];
    for (size_t i = 0; i < n; ++i) s += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + slrKindName(kKinds[i]);
    return s;
}

bool parseSlrKind(const std::string& s, SlrKind* out) {
    for (SlrKind k : kKinds)
        if (toLower(s) == slrKindName(k)) {
            *out = k;
            return true;
        }
    return false;
}

SlrSimParams slrSimPreset(SlrKind kind) {
    SlrSimParams p;
    p.kind = kind;
    switch (kind) {
        case SlrKind::Khz:  // single-photon kHz ranging to a LEO satellite (Jason class)
            break;          // the struct defaults
        case SlrKind::Conventional:  // 10 Hz multi-photon ranging to LAGEOS
            p.fireRateHz = 10;
            p.returnProbability = 0.6;
            p.noiseRateNightHz = 0.3;
            p.noiseRateDayHz = 2;
            p.gateS = 1e-6;
            p.jitterS = 80e-12;
            p.tailS = 0;
            p.durationS = 2400;
            p.altitudeKm = 5900;
            p.tcaDistanceKm = 6500;
            p.velocityKmS = 4.5;
            p.rangeBiasMaxS = 20e-9;
            p.timeBiasMaxS = 2e-3;
            break;
        case SlrKind::Diffuse:  // diffuse-reflection ranging to space debris (ns laser)
            p.fireRateHz = 20;
            p.returnProbability = 0.15;
            p.noiseRateNightHz = 3;
            p.noiseRateDayHz = 20;
            p.gateS = 10e-6;
            p.jitterS = 2e-9;
            p.tailS = 0;
            p.durationS = 300;
            p.altitudeKm = 800;
            p.tcaDistanceKm = 1000;
            p.velocityKmS = 7.4;
            p.rangeBiasMaxS = 500e-9;
            p.timeBiasMaxS = 10e-3;
            break;
        case SlrKind::Leo:  // 10 Hz multi-photon ranging to a Jason-class satellite, low pass, noisy station
            p.fireRateHz = 10;
            p.returnProbability = 0.5;
            p.noiseRateNightHz = 20;
            p.noiseRateDayHz = 60;
            p.gateS = 10e-6;
            p.jitterS = 60e-12;
            p.tailS = 0;
            p.durationS = 600;
            p.altitudeKm = 1336;
            p.tcaDistanceKm = 2600;  // low pass: ~25° maximum elevation
            p.velocityKmS = 7.2;
            p.rangeBiasMaxS = 50e-9;
            p.timeBiasMaxS = 2e-3;
            break;
        case SlrKind::Daylight:  // low-SNR 20 Hz ranging to a LEO satellite by day (issue 43)
            p.fireRateHz = 20;
            p.returnProbability = 0.03;
            p.noiseRateNightHz = 2;
            p.noiseRateDayHz = 20;
            p.gateS = 400e-9;
            p.jitterS = 150e-12;
            p.tailS = 0;
            p.durationS = 900;
            p.altitudeKm = 1500;
            p.tcaDistanceKm = 2000;
            p.velocityKmS = 7.1;
            p.rangeBiasMaxS = 20e-9;
            p.timeBiasMaxS = 1e-3;
            break;
        case SlrKind::Dayspad:  // low-SNR daylight single-photon ranging of another make (issue 45)
            p = slrSimPreset(SlrKind::Daylight);  // the same rates, jitter and gate
            p.kind = kind;
            p.tailS = 40e-12;
            p.durationS = 600;
            p.altitudeKm = 800;
            p.tcaDistanceKm = 1100;
            p.velocityKmS = 7.4;
            p.rangeBiasMaxS = 20e-9;
            p.timeBiasMaxS = 2e-3;
            p.returnRangePower = 2;
            p.noiseRise = 3;
            p.noiseGateSkew = 4;
            break;
    }
    return p;
}

std::string validate(const SlrSimParams& p) {
    auto fin = [](double v) { return std::isfinite(v); };
    if (p.points < 0 || p.points > 50000000) return "points must be 0 (use the duration) or 1..50000000";
    if (!(fin(p.durationS) && p.durationS > 0 && p.durationS <= 172800)) return "duration must be in (0, 172800] s";
    if (!fin(p.signalFraction) || p.signalFraction < 0 || p.signalFraction > 1) return "signal fraction must be 0 (from the noise rate) or in (0, 1]";
    if (!fin(p.startSod) || p.startSod < 0 || p.startSod > 1e7) return "start epoch must be 0..1e7 s";
    if (!fin(p.fireRateHz) || p.fireRateHz <= 0 || p.fireRateHz > 1e5) return "fire rate must be in (0, 1e5] Hz";
    if (!fin(p.returnProbability) || p.returnProbability <= 0 || p.returnProbability > 1) return "return probability must be in (0, 1]";
    if (!fin(p.noiseRateNightHz) || !fin(p.noiseRateDayHz) || p.noiseRateNightHz < 0 || p.noiseRateDayHz < 0)
        return "noise rates must be finite and >= 0";
    if (!fin(p.gateS) || p.gateS <= 0 || p.gateS > 1) return "gate must be in (0, 1] s";
    if (!fin(p.jitterS) || p.jitterS < 0 || !fin(p.tailS) || p.tailS < 0) return "jitter and tail must be >= 0";
    if (!fin(p.tcaDistanceKm) || p.tcaDistanceKm <= 0 || !fin(p.velocityKmS) || p.velocityKmS <= 0)
        return "closest-approach distance and velocity must be > 0";
    if (!fin(p.rangeBiasMaxS) || p.rangeBiasMaxS < 0 || !fin(p.timeBiasMaxS) || p.timeBiasMaxS < 0)
        return "bias limits must be >= 0";
    if (!fin(p.altitudeKm) || p.altitudeKm < 0) return "altitude must be >= 0";
    if (!fin(p.driftSPerS) || !fin(p.driftSPerS2) || std::fabs(p.driftSPerS) > 1e-3 || std::fabs(p.driftSPerS2) > 1e-3)
        return "O-C drift terms must be finite and at most 1e-3 (s/s, s/s²)";
    if (!fin(p.returnRangePower) || p.returnRangePower < 0 || p.returnRangePower > 8)
        return "the return probability's range power must be in [0, 8]";
    if (p.returnRangePower > 0 && p.points > 0)
        return "returns that fade with range need the pass's length, not a number of points";
    if (!fin(p.noiseRise) || p.noiseRise < 0.1 || p.noiseRise > 10) return "the noise rise over the pass must be in [0.1, 10]";
    if (!fin(p.noiseGateSkew) || p.noiseGateSkew < 1 || p.noiseGateSkew > 100)
        return "the noise's skew across the gate must be in [1, 100]";
    for (size_t g = 0; g < p.gaps.size(); ++g) {
        const SlrSimGap& q = p.gaps[g];
        if (!fin(q.startS) || !fin(q.lengthS) || !fin(q.levelShiftS) || q.startS < 0 || q.lengthS <= 0 ||
            std::fabs(q.levelShiftS) > 1)
            return "gap " + std::to_string(g + 1) + ": start must be >= 0, length > 0 and the level shift at most 1 s";
    }
    return {};
}

namespace {
std::vector<std::string> splitOn(std::string_view s, char sep) {
    std::vector<std::string> out;
    size_t a = 0;
    for (size_t b = 0; b <= s.size(); ++b)
        if (b == s.size() || s[b] == sep) {
            out.emplace_back(s.substr(a, b - a));
            a = b + 1;
        }
    return out;
}
}  // namespace

bool parseSlrGaps(const std::string& text, std::vector<SlrSimGap>* out, std::string* error) {
    out->clear();
    for (const std::string& item : splitOn(text, ',')) {
        const std::vector<std::string> f = splitOn(trim(item), ':');
        SlrSimGap g;
        bool ok = f.size() >= 2 && f.size() <= 4 && parseDouble(trim(f[0]), &g.startS) && parseDouble(trim(f[1]), &g.lengthS);
        for (size_t k = 2; ok && k < f.size(); ++k) {
            const std::string v(trim(f[k]));
            double ns = 0;
            if (v == "nodata") g.noise = false;
            else if (k == 2 && parseDouble(v, &ns)) g.levelShiftS = ns * 1e-9;
            else ok = false;
        }
        if (!ok || !(g.lengthS > 0) || g.startS < 0) {
            *error = "gap \"" + item + "\" is not START:LENGTH[:SHIFT_NS][:nodata] (seconds from the first shot, length > 0)";
            return false;
        }
        out->push_back(g);
    }
    return true;
}

double slrTrackOc(const SlrSimParams& p, double rangeBiasS, double timeBiasS, double tcaSod, double t) {
    return rangeBiasS + 2.0 / kSpeedOfLight * rangeRateMs(p, tcaSod, t) * timeBiasS;
}

namespace {

// Gaps (seconds from the first shot): no signal inside; no noise either in a no-data gap.
bool inGap(const SlrSimParams& p, double x, bool* noiseOk) {
    for (const SlrSimGap& g : p.gaps)
        if (x >= g.startS && x < g.startS + g.lengthS) {
            *noiseOk = g.noise;
            return true;
        }
    *noiseOk = true;
    return false;
}

// How many shots, which of them return signal, how many noise points.
struct ShotPlan {
    long long shots = 0, ns = 0, nn = 0;
    std::vector<long long> sigShots;
};

// The shot plan: exactly p.points points (the kind's pass length kept, the return probability
// following), or the shots of the pass length with their return probability and the noise rate.
// False with *error for a pass too large.
// returnOf(k), where given, is shot k's return probability (returns that fade with range).
bool planShots(const SlrSimParams& p, Rng& rng, ShotPlan* plan, std::string* error,
               const std::function<double(long long)>& returnOf = {}) {
    auto gapAt = [&](double x, bool* noiseOk) { return inGap(p, x, noiseOk); };
    long long &shots = plan->shots, &ns = plan->ns, &nn = plan->nn;
    std::vector<long long>& sigShots = plan->sigShots;
    const double noiseRate = p.daylight ? p.noiseRateDayHz : p.noiseRateNightHz;
    const double sigRate = p.fireRateHz * p.returnProbability;
    if (p.points > 0) {
        const double f = p.signalFraction > 0 ? p.signalFraction : sigRate / (sigRate + noiseRate);
        ns = std::clamp<long long>(std::llround(f * static_cast<double>(p.points)), 1, p.points);
        nn = p.points - ns;
        // The kind's pass length is kept; the return probability follows (the pass is
        // lengthened only when even a return on every shot would not give ns signal points).
        shots = std::max<long long>(ns, std::llround(p.durationS * p.fireRateHz));
        if (shots > 1000000000LL) {
            *error = "too many shots (" + std::to_string(shots) + "): shorten the pass";
            return false;
        }
        // Exactly ns distinct signal shots among the shots outside the gaps (selection sampling,
        // ascending).
        long long open = shots;
        bool dummy = true;
        if (!p.gaps.empty()) {
            open = 0;
            for (long long k = 0; k < shots; ++k) open += !gapAt(static_cast<double>(k) / p.fireRateHz, &dummy);
        }
        ns = std::min(ns, open);
        sigShots.reserve(static_cast<size_t>(ns));
        long long need = ns, left = open;
        for (long long k = 0; k < shots && need > 0; ++k) {
            if (!p.gaps.empty() && gapAt(static_cast<double>(k) / p.fireRateHz, &dummy)) continue;
            if (rng.uniform() * static_cast<double>(left) < static_cast<double>(need)) {
                sigShots.push_back(k);
                --need;
            }
            --left;
        }
    } else {
        shots = std::max<long long>(1, std::llround(p.durationS * p.fireRateHz));
        if (shots > 1000000000LL) {
            *error = "too many shots (" + std::to_string(shots) + "): shorten the pass";
            return false;
        }
        bool dummy = true;
        for (long long k = 0; k < shots; ++k)
            if (rng.uniform() < (returnOf ? returnOf(k) : p.returnProbability) &&
                !(!p.gaps.empty() && gapAt(static_cast<double>(k) / p.fireRateHz, &dummy)))
                sigShots.push_back(k);
        ns = static_cast<long long>(sigShots.size());
        if (p.signalFraction > 0)
            nn = std::llround(static_cast<double>(ns) * (1 - p.signalFraction) / p.signalFraction);
        else
            nn = static_cast<long long>(rng.poisson(noiseRate * static_cast<double>(shots) / p.fireRateHz));
        if (ns + nn > 50000000LL) {
            *error = "the pass would hold " + std::to_string(ns + nn) + " points (more than 5e7)";
            return false;
        }
    }
    return true;
}

}  // namespace

SlrSimPass simulateSlrPass(const SlrSimParams& p, uint64_t seed) {
    SlrSimPass out;
    if (const std::string e = validate(p); !e.empty()) {
        out.error = e;
        return out;
    }
    Rng rng(seed);
    auto gapAt = [&](double x, bool* noiseOk) { return inGap(p, x, noiseOk); };
    // Counts and duration.
    // Track truth: biases, closest approach near the middle of the pass. Returns that fade with
    // range need the closest approach before the shots are drawn, so it is drawn first there;
    // the other passes keep their order of draws (the same pass for the same seed as before).
    auto drawTrack = [&](double duration) {
        out.rangeBiasS = rng.uniform(-p.rangeBiasMaxS, p.rangeBiasMaxS);
        out.timeBiasS = rng.uniform(-p.timeBiasMaxS, p.timeBiasMaxS);
        out.tcaSod = p.startSod + duration * rng.uniform(0.35, 0.65);
    };
    ShotPlan plan;
    std::function<double(long long)> returnOf;
    if (p.returnRangePower > 0) {  // (validate: points = 0, so the shots follow from the pass length)
        const long long n = std::max<long long>(1, std::llround(p.durationS * p.fireRateHz));
        if (n > 1000000000LL) {
            out.error = "too many shots (" + std::to_string(n) + "): shorten the pass";
            return out;
        }
        drawTrack(static_cast<double>(n) / p.fireRateHz);
        auto weight = [&p, tca = out.tcaSod](long long k) {
            return std::pow(p.tcaDistanceKm * 1e3 / rangeM(p, tca, p.startSod + static_cast<double>(k) / p.fireRateHz),
                            p.returnRangePower);
        };
        double sum = 0;
        for (long long k = 0; k < n; ++k) sum += weight(k);
        const double scale = p.returnProbability * static_cast<double>(n) / sum;
        if (!(sum > 0) || !std::isfinite(scale)) {
            out.error = "the returns' fade with range leaves no shot a return probability (closest approach too near)";
            return out;
        }
        returnOf = [weight, scale](long long k) { return std::min(1.0, scale * weight(k)); };
    }
    if (!planShots(p, rng, &plan, &out.error, returnOf)) return out;
    const long long shots = plan.shots, ns = plan.ns, nn = plan.nn;
    const std::vector<long long>& sigShots = plan.sigShots;
    const double duration = static_cast<double>(shots) / p.fireRateHz;
    if (!returnOf) drawTrack(duration);
    // The track: eq. 1, the extra drift about the pass middle and the level shifts after gaps.
    const double tMid = p.startSod + 0.5 * duration;
    auto track = [&](double t) {
        const double x = t - tMid;
        double v = slrTrackOc(p, out.rangeBiasS, out.timeBiasS, out.tcaSod, t) + p.driftSPerS * x + p.driftSPerS2 * x * x;
        for (const SlrSimGap& g : p.gaps)
            if (t - p.startSod >= g.startS + g.lengthS) v += g.levelShiftS;
        return v;
    };
    // Gate: the track (with 6σ of jitter) kept inside the middle 80 % of the gate.
    double tLo = 1e300, tHi = -1e300;
    for (int i = 0; i <= 400; ++i) {
        const double v = track(p.startSod + duration * i / 400.0);
        tLo = std::min(tLo, v);
        tHi = std::max(tHi, v);
    }
    const double mid = 0.5 * (tLo + tHi);
    const double room = std::max(0.0, 0.4 * p.gateS - 0.5 * (tHi - tLo) - 6 * p.jitterS - 10 * p.tailS);
    out.gateS = p.gateS;
    out.gateLoS = mid - 0.5 * p.gateS + rng.uniform(-room, room);
    // Points.
    struct Pt {
        double t, oc;
        uint8_t sig;
    };
    std::vector<Pt> pts;
    pts.reserve(static_cast<size_t>(ns + nn));
    for (long long k : sigShots) {
        const double t = p.startSod + static_cast<double>(k) / p.fireRateHz;
        double oc = track(t) + p.jitterS * rng.normal();
        if (p.tailS > 0) oc += -p.tailS * std::log(1.0 - rng.uniform());
        pts.push_back({t, oc, 1});
    }
    // Noise: over the shots with a rate rising linearly by noiseRise from start to end (density
    // ∝ 1 + b·x on x ∈ [0, 1], drawn by its inverse CDF), over the gate with a density falling
    // by noiseGateSkew from its start to its end (∝ e^(−a·u)); uniform where both are 1.
    const double rise = p.noiseRise - 1, skew = std::log(p.noiseGateSkew);
    auto noiseShot = [&](double u) {
        if (rise == 0) return u;
        return (std::sqrt(1 + 2 * rise * u * (1 + 0.5 * rise)) - 1) / rise;
    };
    auto noiseInGate = [&](double u) {
        if (skew == 0) return u;
        return -std::log(1 - u * (1 - std::exp(-skew))) / skew;
    };
    for (long long j = 0; j < nn; ++j) {
        const long long k =
            std::min<long long>(shots - 1, static_cast<long long>(noiseShot(rng.uniform()) * static_cast<double>(shots)));
        const double t = p.startSod + static_cast<double>(k) / p.fireRateHz;
        const double o = out.gateLoS + p.gateS * noiseInGate(rng.uniform());
        bool noiseOk = true;
        if (!p.gaps.empty() && gapAt(t - p.startSod, &noiseOk) && !noiseOk) continue;  // no data in the gap
        pts.push_back({t, o, 0});
    }
    std::sort(pts.begin(), pts.end(), [](const Pt& a, const Pt& b) {
        return a.t < b.t || (a.t == b.t && (a.oc < b.oc || (a.oc == b.oc && a.sig > b.sig)));
    });
    const size_t n = pts.size();
    out.epochS.resize(n);
    out.ocS.resize(n);
    out.isSignal.resize(n);
    out.trackOcS.resize(n);
    out.tofS.resize(n);
    for (size_t i = 0; i < n; ++i) {
        out.epochS[i] = pts[i].t;
        out.ocS[i] = pts[i].oc;
        out.isSignal[i] = pts[i].sig;
        out.trackOcS[i] = track(pts[i].t);
        out.tofS[i] = 2.0 * rangeM(p, out.tcaSod, pts[i].t) / kSpeedOfLight + pts[i].oc;
    }
    out.durationS = duration;
    out.shots = shots;
    out.signalCount = static_cast<long long>(sigShots.size());
    out.noiseCount = static_cast<long long>(n) - out.signalCount;
    out.signalFraction = n ? static_cast<double>(ns) / static_cast<double>(n) : 0;
    out.ok = true;
    return out;
}

std::string simulatedCrd(const std::string& h3, const std::vector<double>& epochS, const std::vector<double>& tofS,
                         const std::vector<uint8_t>& isSignal, double emptyStartSod, int year, int month, int day,
                         int epochDecimals, int tofDecimals, const std::string& h2) {
    auto hms = [](double sod, int* h, int* m, int* sec) {
        const long s = static_cast<long>(std::floor(sod)) % 86400;
        *h = int(s / 3600);
        *m = int(s / 60 % 60);
        *sec = int(s % 60);
    };
    const double first = epochS.empty() ? emptyStartSod : epochS.front();
    const double last = epochS.empty() ? emptyStartSod : epochS.back();
    int h0, m0, s0, h1, m1, s1;
    hms(first, &h0, &m0, &s0);
    hms(last, &h1, &m1, &s1);
    char line[256];
    std::string out;
    std::snprintf(line, sizeof line, "H1 CRD  2 %04d %02d %02d %02d\n", year, month, day, h0);
    out += line;
    out += "H2 " + h2 + "\n";
    out += "H3 " + h3 + "\n";
    // H4: full rate, session start and end, no corrections applied, two-way ranges.
    std::snprintf(line, sizeof line, "H4  0 %04d %02d %02d %02d %02d %02d %04d %02d %02d %02d %02d %02d  0  0  0  0  1  0  2  0\n",
                  year, month, day, h0, m0, s0, year, month, day, h1, m1, s1);
    out += line;
    out += "C0 0 532.000 std\n";
    out.reserve(out.size() + epochS.size() * 48 + 16);
    for (size_t i = 0; i < epochS.size() && i < tofS.size() && i < isSignal.size(); ++i) {
        // Seconds of day (of the H4 date; the CRD convention rolls past 86400 into the next day).
        // (v2: nine fields, the receive and transmit amplitudes not available)
        std::snprintf(line, sizeof line, "10 %.*f %.*f std 2 %d 0 0 na na\n", epochDecimals, epochS[i], tofDecimals, tofS[i],
                      isSignal[i] ? 2 : 1);
        out += line;
    }
    out += "H8\nH9\n";
    return out;
}

std::string slrPassCrd(const SlrSimParams& p, const SlrSimPass& pass, int year, int month, int day) {
    const bool lageos = p.kind == SlrKind::Conventional;
    const std::string name = lageos ? "lageos1" : std::string("simsat-") + slrKindName(p.kind);
    const std::string target = lageos ? "lageos1 7603901 1155 8820" : name + " 9999901 9999 99999";
    return simulatedCrd(target + "  0  1  1", pass.epochS, pass.tofS, pass.isSignal, p.startSod, year, month, day);
}

}  // namespace lwb::core::sim
