#include "core/sim/slr_sim_sparse.hpp"

#include "core/slr/ilrs_tables.hpp"
#include "core/slr/refraction.hpp"
#include "core/sim/slr_sim.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "core/common/rng.hpp"

namespace lwb::core::sim {

namespace {
constexpr double kGm = 3.986004418e14;
constexpr double kOmegaE = 7.292115e-5;
constexpr double kRe = 6371000.0;
constexpr double kDeg = M_PI / 180;

struct V3 {
    double x, y, z;
};
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double norm(V3 a) { return std::sqrt(dot(a, a)); }
V3 unit(V3 a) { return (1.0 / norm(a)) * a; }

V3 satAt(const SparseLeoPass& s, double t) {
    const double a = s.meanMotion * (t - s.tRefS);
    const V3 p{s.p[0], s.p[1], s.p[2]}, q{s.q[0], s.q[1], s.q[2]};
    return s.radiusM * (std::cos(a) * p + std::sin(a) * q);
}
V3 stationAt(const SparseLeoPass& s, double t) {
    const double a = kOmegaE * (t - s.tRefS), c = std::cos(a), sn = std::sin(a);
    return {c * s.station[0] - sn * s.station[1], sn * s.station[0] + c * s.station[1], s.station[2]};
}
double elevationDeg(const SparseLeoPass& s, double t) {
    const V3 st = stationAt(s, t), d = satAt(s, t) - st;
    return std::asin(dot(d, unit(st)) / norm(d)) / kDeg;
}
}  // namespace

double sparseLeoTrueTof(const SparseLeoPass& pass, double t) { return 2.0 * norm(satAt(pass, t) - stationAt(pass, t)) / kSpeedOfLight; }

SparseLeoPass simulateSparseLeoPass(const SparseLeoParams& p, uint64_t seed) {
    SparseLeoPass s;
    if (!(p.altitudeKm >= 300 && p.altitudeKm <= 3000) || p.ranges < 3 || p.ranges > 10000 || p.noisePoints < 0 ||
        !(p.jitterS >= 0) || !(p.gateS > 0) || !(p.fireRateHz > 0)) {
        s.error = "sparse LEO pass: altitude 300..3000 km, 3..10000 ranges, jitter >= 0, gate > 0, fire rate > 0";
        return s;
    }
    Rng rng(seed);
    const double R = kRe + p.altitudeKm * 1e3;
    s.radiusM = R;
    s.meanMotion = std::sqrt(kGm / (R * R * R));
    s.tRefS = p.dayStartSod;
    double lat = p.stationLatDeg * kDeg, lon = p.stationLonDeg * kDeg;
    V3 st = kRe * V3{std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
    if (p.stationPad != 0) {
        const slr::IlrsStation* is = slr::findStation(p.stationPad);
        if (!is) {
            s.error = "sparse LEO pass: station " + std::to_string(p.stationPad) + " is not in the ILRS stations table";
            return s;
        }
        // The station where the table puts it (its geocentric direction is "up" below).
        const Eigen::Vector3d e = slr::ecefFromGeodetic(is->latDeg, is->lonDeg, is->heightM);
        st = V3{e.x(), e.y(), e.z()};
        const double lo = is->lonDeg * kDeg;
        lat = std::atan2(st.z, std::hypot(st.x, st.y));
        lon = lo;
        s.stationPad = p.stationPad;
    }
    const V3 sHat = unit(st);
    s.station[0] = st.x, s.station[1] = st.y, s.station[2] = st.z;
    // Culmination wanted: the central angle gamma of elevation e, tan e = (cos g - Re/R) / sin g.
    const double eWant = (p.maxElevationDeg > 0 ? p.maxElevationDeg : rng.uniform(25, 85)) * kDeg;
    double lo = 0, hi = std::acos(kRe / R);
    for (int i = 0; i < 60; ++i) {
        const double g = 0.5 * (lo + hi);
        (std::atan2(std::cos(g) - kRe / R, std::sin(g)) > eWant ? lo : hi) = g;
    }
    const double gamma = 0.5 * (lo + hi);
    // The sub-satellite point at closest approach: gamma from the station towards a random azimuth.
    const V3 north = unit(V3{-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)});
    const V3 east = cross(north, sHat);
    const double az = rng.uniform(0, 2 * M_PI);
    const V3 dir = std::cos(az) * north + std::sin(az) * east;
    const V3 g = std::cos(gamma) * sHat + std::sin(gamma) * dir;
    V3 q = unit(cross(g, sHat));
    if (rng.uniform() < 0.5) q = -1.0 * q;
    s.p[0] = g.x, s.p[1] = g.y, s.p[2] = g.z;
    s.q[0] = q.x, s.q[1] = q.y, s.q[2] = q.z;
    // The visible pass about the culmination (1 s steps).
    double best = -90, tBest = s.tRefS;
    for (double t = s.tRefS - 1500; t <= s.tRefS + 1500; t += 1) {
        const double e = elevationDeg(s, t);
        if (e > best) best = e, tBest = t;
    }
    s.maxElevationDeg = best;
    if (best <= p.minElevationDeg + 1) {
        s.error = "sparse LEO pass: the satellite does not rise above the minimum elevation";
        return s;
    }
    double a = tBest, b = tBest;
    while (elevationDeg(s, a - 1) > p.minElevationDeg) a -= 1;
    while (elevationDeg(s, b + 1) > p.minElevationDeg) b += 1;
    s.passStartS = a, s.passEndS = b;
    const double W = b - a, dt = 1.0 / p.fireRateHz;
    // Epochs of the returns on the shot grid.
    std::set<long long> shots;
    auto shotOf = [&](double t) { return std::llround(t / dt); };
    auto fill = [&](double t0, double len, int count) {
        int tries = 0;
        const size_t want = shots.size() + size_t(count);
        while (shots.size() < want && tries++ < 100000) shots.insert(shotOf(t0 + len * rng.uniform()));
    };
    if (p.gaps) {
        // Bursts of 2–8 returns over 1–2 s a return, parted by gaps of 30 s – 3 min (shrunk to fit).
        std::vector<int> sizes;
        for (int left = p.ranges; left > 0;) {
            const int k = std::min(left, 2 + int(rng.uniform() * 7));
            sizes.push_back(k);
            left -= k;
        }
        std::vector<double> dur, gap;
        double sd = 0, sg = 0;
        for (size_t i = 0; i < sizes.size(); ++i) {
            dur.push_back(sizes[i] * rng.uniform(0.5, 2.0));
            sd += dur.back();
            if (i + 1 < sizes.size()) {
                gap.push_back(rng.uniform(30, 180));
                sg += gap.back();
            }
        }
        if (sd + sg > W && sg > 0) {
            const double f = std::max(0.05, (W - sd) / sg);
            for (double& x : gap) x *= f;
            sg *= f;
        }
        double t = a + std::max(0.0, W - sd - sg) * rng.uniform();
        for (size_t i = 0; i < sizes.size(); ++i) {
            fill(t, dur[i], sizes[i]);
            t += dur[i] + (i < gap.size() ? gap[i] : 0);
        }
    } else {
        const double len = std::min(W, rng.uniform(60, 300));
        fill(a + (W - len) * rng.uniform(), len, p.ranges);
    }
    std::vector<std::pair<double, uint8_t>> ev;
    for (long long k : shots) ev.emplace_back(double(k) * dt, 1);
    const double first = ev.front().first, last = ev.back().first;
    for (int i = 0; i < p.noisePoints; ++i) ev.emplace_back(double(shotOf(rng.uniform(first, last))) * dt, 0);
    std::stable_sort(ev.begin(), ev.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [t, sig] : ev) {
        const double tt = sparseLeoTrueTof(s, t);
        s.epochS.push_back(t);
        s.trueTofS.push_back(tt);
        s.isSignal.push_back(sig);
        s.tofS.push_back(sig ? tt + p.jitterS * rng.normal() : tt + p.gateS * (rng.uniform() - 0.5));
    }
    s.ok = true;
    return s;
}

std::string sparseLeoPassCrd(const SparseLeoPass& pass, int year, int month, int day) {
    char h2[64];
    std::snprintf(h2, sizeof h2, "%s %04d 99 99  7 ILRS", pass.stationPad == 9999 ? "SIMU" : "SIMSTA", pass.stationPad);
    return simulatedCrd("simsat-sparse 9999902 9998 99998  0  1  1", pass.epochS, pass.tofS, pass.isSignal, 0, year, month, day, 7,
                        12, h2);
}

}  // namespace lwb::core::sim
