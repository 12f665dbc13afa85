#pragma once
// Simulated spot-centroid tables for long-term pointing monitoring (paper 001 section 3), with
// exact truth: the spot centres one camera measured shot by shot over months, for each beam.
// Each beam's true monthly centre follows a slow drift (a linear trend plus an annual cycle,
// paper 001 reports changes of a pixel or two over a year); each shot scatters about it
// (Gaussian, scatterPx) and a few shots are outliers (a misplaced centre, 1.5–4 px off) that the
// trend's k-sigma rejection should remove. The table is what `laserwb-cli trend` reads:
// time,beam,x,y,camera.
#include <cstdint>
#include <string>
#include <vector>

namespace lwb::core::sim {

struct CentroidSimParams {
    int months = 12;             ///< consecutive months, [1, 600]
    int shotsPerMonth = 20;      ///< per beam, [1, 100000]
    int startYear = 2020, startMonth = 3;  ///< the first month (paper 001's series starts 2020-03)
    std::string camera = "LFI";
    /// Beam centres in the first month (full-image px): paper 001's LFI chips (102,242) and
    /// (198,143) with 40x40 px, so centres (122,262) and (218,163).
    double beam1X = 122, beam1Y = 262, beam2X = 218, beam2Y = 163;
    double driftMaxPxPerMonth = 0.12;  ///< |linear drift| per axis ≤ this, drawn per beam
    double annualAmplitudeMaxPx = 0.3; ///< annual cycle amplitude per axis ≤ this, drawn per beam
    double scatterPx = 0.15;     ///< Gaussian scatter of a shot about its month's centre (1σ per axis)
    double outlierFraction = 0.02;  ///< shots moved 1.5–4 px in a random direction, [0, 0.5]
};

struct CentroidSimShot {
    std::string time;  ///< ISO date-time in its month
    int beam = 1;
    double x = 0, y = 0;
    bool outlier = false;
};

struct CentroidSimMonth {
    std::string month;  ///< YYYY-MM
    int beam = 1;
    double x = 0, y = 0;  ///< the true centre that month
};

struct CentroidSimulation {
    bool ok = false;
    std::string error;
    std::vector<CentroidSimShot> shots;   ///< month by month, beam 1 then beam 2
    std::vector<CentroidSimMonth> truth;  ///< per month and beam
};

/// Empty when the params are usable, else what is wrong.
std::string validate(const CentroidSimParams& p);
/// Simulates the table. Deterministic for (params, seed).
CentroidSimulation simulateCentroids(const CentroidSimParams& p, uint64_t seed);

}  // namespace lwb::core::sim
