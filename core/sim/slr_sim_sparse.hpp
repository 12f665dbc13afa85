#pragma once
// Short sparse LEO passes with exact truth (issue 43): a satellite on a circular orbit of
// 500–1400 km seen from a station on the rotating Earth, ranged a few times over its pass as a
// sparse station ranges it (10–30 returns, 10 Hz shots, in bursts of a few seconds parted by
// gaps of 30 s – 3 min, or spread along one arc without a gap), with Gaussian jitter and
// optionally a few noise points in the range gate. Unlike slr_sim.hpp's straight-line flyby,
// the range is that of the real geometry: the satellite's inertial circular orbit (Kepler's
// rate for its radius) and the station turning with the Earth (ω_E), instantaneous range
// (no light time), TOF = 2ρ/c + jitter. Deterministic for (params, seed).
#include <cstdint>
#include <string>
#include <vector>

namespace lwb::core::sim {

struct SparseLeoParams {
    double altitudeKm = 800;         ///< circular orbit altitude above a 6371 km sphere (km), 300..3000
    int ranges = 18;                 ///< signal returns in the pass, 3..10000
    bool gaps = true;                ///< bursts parted by gaps of 30 s – 3 min over the pass; false: one arc
    double jitterS = 100e-12;        ///< Gaussian RMS of the returns about the true TOF (two-way s)
    int noisePoints = 0;             ///< noise points, uniform in the gate about the true TOF
    double gateS = 2e-6;             ///< range gate width for the noise (two-way s)
    double minElevationDeg = 15;     ///< the pass: the satellite above this elevation
    double maxElevationDeg = 0;      ///< 0: drawn in 25..85°; else the culmination wanted (approximate)
    double stationLatDeg = 30.68;    ///< station (spherical) latitude and east longitude (deg), on a
    double stationLonDeg = -104.02;  ///< 6371 km sphere, written as SIMU pad 9999 (not in the ILRS table)
    /// An ILRS station instead (a CDP pad id of resources/ilrs/stations.csv): the station at its
    /// WGS-84 position and height, written with its pad id; 0: the sphere's station above.
    int stationPad = 0;
    double fireRateHz = 10;          ///< epochs on the shot grid of this rate
    double dayStartSod = 36000;      ///< seconds of day of the pass's culmination (about)
};

struct SparseLeoPass {
    bool ok = false;
    std::string error;
    std::vector<double> epochS;      ///< s of day, ascending
    std::vector<double> tofS;        ///< observed two-way TOF (s)
    std::vector<double> trueTofS;    ///< 2ρ(t)/c without noise (s)
    std::vector<uint8_t> isSignal;   ///< 1 signal, 0 noise
    double maxElevationDeg = 0, passStartS = 0, passEndS = 0;  ///< geometry of the visible pass
    // The orbit and station, for trueTof at any epoch.
    double radiusM = 0, meanMotion = 0, tRefS = 0;
    double p[3] = {0, 0, 0}, q[3] = {0, 0, 0}, station[3] = {0, 0, 0};
    int stationPad = 9999;           ///< the CRD's H2 pad id
};

/// Simulates one pass. Deterministic for (params, seed).
SparseLeoPass simulateSparseLeoPass(const SparseLeoParams& params, uint64_t seed);

/// The true two-way TOF (s) of a simulated pass at epoch t (s of day): 2ρ(t)/c.
double sparseLeoTrueTof(const SparseLeoPass& pass, double t);

/// The pass as a CRD v2 full-rate file (as slrPassCrd: filter flag 2 signal, 1 noise), satellite
/// "simsat-sparse" (ILRS id 9999902, not in the missions table), station SIMU pad 9999 or the
/// ILRS station simulated.
std::string sparseLeoPassCrd(const SparseLeoPass& pass, int year = 2024, int month = 6, int day = 15);

}  // namespace lwb::core::sim
