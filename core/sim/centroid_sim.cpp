#include "core/sim/centroid_sim.hpp"

#include <cmath>
#include <cstdio>

#include "core/common/rng.hpp"

namespace lwb::core::sim {

std::string validate(const CentroidSimParams& p) {
    if (p.months < 1 || p.months > 600) return "months must be 1..600";
    if (p.shotsPerMonth < 1 || p.shotsPerMonth > 100000) return "shots per month must be 1..100000";
    if (p.startYear < 1970 || p.startYear > 2200 || p.startMonth < 1 || p.startMonth > 12) return "bad start month";
    if (!(p.scatterPx >= 0 && p.scatterPx <= 10)) return "scatter must be 0..10 px";
    if (!(p.outlierFraction >= 0 && p.outlierFraction <= 0.5)) return "outlier fraction must be 0..0.5";
    if (!(p.driftMaxPxPerMonth >= 0 && p.driftMaxPxPerMonth <= 5) || !(p.annualAmplitudeMaxPx >= 0 && p.annualAmplitudeMaxPx <= 10))
        return "drift must be 0..5 px a month and the annual amplitude 0..10 px";
    return {};
}

CentroidSimulation simulateCentroids(const CentroidSimParams& p, uint64_t seed) {
    CentroidSimulation sim;
    sim.error = validate(p);
    if (!sim.error.empty()) return sim;
    Rng rng(seed);
    struct Path {
        double x0, y0, dx, dy, ax, ay, phase;
    } beams[2];
    const double base[2][2] = {{p.beam1X, p.beam1Y}, {p.beam2X, p.beam2Y}};
    for (int b = 0; b < 2; ++b) {
        Path& q = beams[b];
        q.x0 = base[b][0];
        q.y0 = base[b][1];
        q.dx = rng.uniform(-p.driftMaxPxPerMonth, p.driftMaxPxPerMonth);
        q.dy = rng.uniform(-p.driftMaxPxPerMonth, p.driftMaxPxPerMonth);
        q.ax = rng.uniform(-p.annualAmplitudeMaxPx, p.annualAmplitudeMaxPx);
        q.ay = rng.uniform(-p.annualAmplitudeMaxPx, p.annualAmplitudeMaxPx);
        q.phase = rng.uniform(0, 2 * M_PI);
    }
    for (int m = 0; m < p.months; ++m) {
        const int idx = p.startMonth - 1 + m;
        const int year = p.startYear + idx / 12, month = idx % 12 + 1;
        char ym[16];
        std::snprintf(ym, sizeof ym, "%04d-%02d", year, month);
        for (int b = 0; b < 2; ++b) {
            const Path& q = beams[b];
            const double season = std::sin(2 * M_PI * m / 12.0 + q.phase);
            CentroidSimMonth t;
            t.month = ym;
            t.beam = b + 1;
            t.x = q.x0 + q.dx * m + q.ax * (season - std::sin(q.phase));
            t.y = q.y0 + q.dy * m + q.ay * (season - std::sin(q.phase));
            sim.truth.push_back(t);
            for (int k = 0; k < p.shotsPerMonth; ++k) {
                CentroidSimShot s;
                const int day = 1 + static_cast<int>(rng.uniform() * 28);
                const int sec = static_cast<int>(rng.uniform() * 86400);
                char when[40];
                std::snprintf(when, sizeof when, "%sT%02d:%02d:%02d", ym, sec / 3600, sec / 60 % 60, sec % 60);
                s.time = std::string(when).insert(7, "-" + std::string(day < 10 ? "0" : "") + std::to_string(day));
                s.beam = b + 1;
                s.x = t.x + p.scatterPx * rng.normal();
                s.y = t.y + p.scatterPx * rng.normal();
                if (rng.uniform() < p.outlierFraction) {
                    const double r = rng.uniform(1.5, 4.0), phi = rng.uniform(0, 2 * M_PI);
                    s.x += r * std::cos(phi);
                    s.y += r * std::sin(phi);
                    s.outlier = true;
                }
                sim.shots.push_back(s);
            }
        }
    }
    sim.ok = true;
    return sim;
}

}  // namespace lwb::core::sim
