#pragma once
// O-C (observed minus computed two-way time of flight) of a full-rate CRD pass.
//
// With a prediction (computeOc): for every type-10 record, the computed two-way time of flight
// from the CPF satellite position (Lagrange-interpolated, body-fixed ITRF) and the station
// position (SINEX at the pass epoch): the up-leg and down-leg light times are iterated with the
// Earth's rotation during the flight (the station's inertial position at transmit and receive
// time, in the frame that coincides with ITRF at the bounce time). The record's epoch event
// says which instant its epoch is: 2 ground transmit, 0 ground receive, 1 spacecraft bounce
// (one-way events 3..6 are skipped with a warning). Optional: the Mendes-Pavlis tropospheric
// delay (both legs) from the pass's type-20 met records, the relativistic (Shapiro) delay of
// the Earth's field, a target centre-of-mass offset.
//
// Without a prediction (computeTrendOc): residuals against a robust trend of the time of flight
// itself over all returns (filter flags unused): sqrt of a polynomial fitted to the squared time
// of flight (a pass's range is nearly sqrt(d^2 + v^2 t^2)), a Huber M-estimate by iteratively
// reweighted least squares. Issue 43: or sqrt of the orbit arc, chosen by the data. A satellite
// on a circular orbit of radius R seen from a station at radius Re (non-rotating Earth) has
// rho^2 = Re^2 + R^2 - 2 Re R cos(gamma_min) cos(w (t - t0)), i.e. TOF^2 = A + B cos(w t) +
// C sin(w t): linear in A, B, C for a given angular rate w, which is searched (5e-5..1.4e-3
// rad/s: LEO to above LAGEOS). A Legendre polynomial of degree 0..2 (by BIC on the robust scale)
// on top takes up the Earth's rotation and the eccentricity. Taken when it leaves at most half
// the polynomial's robust scatter and a lower BIC: sparse LEO passes whose TOF no low-degree
// polynomial follows (an ERS-class pass of 18 ranges: 44 ns residuals on real returns); dense
// passes whose scatter is the gate's noise keep the polynomial. Huber (bounded influence, not redescending) follows the centre of the
// noise band, i.e. the station's own prediction, rather than locking onto part of the track. The range gate is centred on
// the station's own prediction, so noise spreads evenly about it and the trend follows the
// gate centre or the track; either way the O-C is relative to a fitted trend, not to an orbit:
// a range bias and a smooth drift are absorbed (the result says so in a warning).
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/cpf.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/sinex.hpp"

namespace lwb::core::slr {

constexpr double kSpeedOfLight = 299792458.0;       ///< m/s
constexpr double kEarthRotationRate = 7.292115e-5;  ///< rad/s (IERS)
constexpr double kEarthGm = 3.986004418e14;         ///< m^3/s^2

enum class RefractionModel {
    None,          ///< no tropospheric correction (the O-C then holds the whole delay, metres)
    MendesPavlis,  ///< Mendes & Pavlis (2004) zenith delay + FCULa mapping (IERS Conventions 2010 §9.2)
};

struct OcParams {
    RefractionModel refraction = RefractionModel::MendesPavlis;  ///< needs type-20 met records; off with a warning without
    CpfInterpParams interpolation;   ///< Lagrange nodes (default 10) and CPF direction flag (default 0)
    double wavelengthNm = NAN;       ///< laser wavelength (nm, 300..2000); NaN: from the record's C0, else 532 with a warning
    bool shapiro = true;             ///< add the relativistic light-time delay of the Earth's field (a few mm)
    double targetComOffsetM = NAN;   ///< centre of mass to reflector (m, one-way, 0..10); NaN: the CPF H5 value when the
                                     ///< CPF positions are of the centre of mass (H2 flag 0), else 0
    double convergenceS = 1e-13;     ///< light-time iteration stop (s, 1e-15..1e-9)
    int maxIterations = 10;          ///< light-time iterations per leg (2..50)
};
std::string validate(const OcParams& p);

enum class OcMethod { Prediction, FittedTrend };

struct OcResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    /// What the O-C is relative to, when that is not a prediction ("no prediction: O-C is
    /// relative to a robust degree-3 polynomial trend ..."): information, not a problem of the files.
    std::vector<std::string> notes;
    OcMethod method = OcMethod::Prediction;

    /// Per point (one per usable type-10 record, in file order):
    std::vector<double> epoch_s;        ///< the record's epoch as seconds since 0h UTC of the pass's H4 start day
                                        ///< (may exceed 86 400 after midnight); add startMjd for an absolute time
    std::vector<double> oc_s;           ///< observed - computed two-way time of flight (s)
    std::vector<double> tof_s;          ///< observed two-way time of flight (s)
    std::vector<double> elevation_rad;  ///< elevation of the target at bounce (geometric; rad); NaN when unknown
                                        ///< (computeTrendOc: empty when the pass has no pointing records)
    std::vector<double> azimuth_rad;    ///< azimuth from north through east (rad); NaN when unknown (as elevation)
    std::vector<double> refraction_s;   ///< two-way tropospheric delay included in the computed value (s; 0 when off;
                                        ///< empty from computeTrendOc, which computes none)
    std::vector<uint32_t> range_index;  ///< index into CrdPass::ranges (the source type-10 record; a pass of 2^32
                                        ///< records is refused before it is read)
    std::vector<long> line;             ///< source line of the record
    std::vector<int8_t> filter_flag;    ///< the record's filter flag (0 unknown, 1 noise, 2 data)

    long startMjd = 0;                  ///< MJD of the pass's H4 start day (0h UTC)
    bool refractionApplied = false;
    double comOffsetM = 0;              ///< centre-of-mass offset used (m, one-way)
    double wavelengthNm = NAN;          ///< wavelength of the first point's configuration
    Eigen::Vector3d stationEcef{0, 0, 0};  ///< station position used (m, ITRF)
    std::string stationCode;            ///< SINEX site code (when looked up)
    int trendDegree = 0;                ///< FittedTrend: polynomial degree used (of the polynomial under the
                                        ///< orbit arc when trendArcRateRadS is finite)
    double trendScaleS = NAN;           ///< FittedTrend: robust scale of the residuals (s)
    double trendArcRateRadS = NAN;      ///< FittedTrend: the orbit arc's angular rate (rad/s) when the arc model
                                        ///< was chosen (computeTrendOc); NaN: the polynomial in TOF^2
    bool trendOrbit = false;            ///< FittedTrend: the circular orbit itself (orbit_fit.hpp) was chosen:
                                        ///< its residuals need at most a bias and a drift (postfitForPass)
    /// FittedTrend on a short pass (at most 49 records): the trend's hat matrix (row-major n×n,
    /// ∂trend_i/∂tof_k; orbit_fit.hpp leastSquaresHat), for the normal points' precision
    /// (postfit.hpp normalPointTrendFactors). Empty otherwise.
    std::vector<double> trendHat;
};

/// O-C of a pass against a prediction, station position given (ECEF, m). Never throws.
OcResult computeOc(const CrdPass& pass, const CpfFile& cpf, const Eigen::Vector3d& stationEcef, const OcParams& params,
                   const Feedback* feedback = nullptr);

/// Same with the station position looked up in SINEX by the pass's H2 CDP pad id at the
/// pass's first epoch.
OcResult computeOc(const CrdPass& pass, const CpfFile& cpf, const SinexFile& sinex, const OcParams& params,
                   const Feedback* feedback = nullptr);

struct TrendOcParams {
    int degree = 4;           ///< degree of the polynomial for the squared time of flight (normalised time; 1..20);
                              ///< lowered to max((records-1)/4, 2) for short passes (5 records: 2)
    double huberK = 1.345;    ///< Huber constant, in robust standard deviations (MAD x 1.4826) (0.5..10)
    int maxIterations = 50;   ///< reweighting iterations (1..500)
    int minPoints = 5;        ///< fewer usable records: error (>= 3; kMinPassPoints of pass_input.hpp)
    /// Internal, no schema row (tests compare with and without it): also fit the orbit-arc model
    /// (TOF^2 = A + B cos wt + C sin wt + a polynomial of degree 0..2, w searched) and take it when
    /// it leaves at most half the polynomial's robust scatter and a lower information criterion.
    bool orbitArc = true;
    /// Internal, no schema row (tests compare with and without it): with orbitArc, on a pass of
    /// 10–49 records from a station the ILRS table knows, also fit the circular orbit itself
    /// (orbit_fit.hpp) and take it when its BIC is the lower.
    bool circularOrbit = true;
    /// Internal, no schema row: the most records a trend's robust fit takes; a pass with more is
    /// fitted on every k-th (evenly taken) and its residuals computed for all. Each reweighting
    /// step is a QR of the design: on a 10^6-event kHz pass the whole-pass fit took 20 s.
    size_t fitMaxPoints = 20000;
};
std::string validate(const TrendOcParams& p);

/// O-C of a pass against a robust polynomial trend of its own time of flight (no prediction).
/// Elevation/azimuth are interpolated from the pass's type-30 records when present.
OcResult computeTrendOc(const CrdPass& pass, const TrendOcParams& params, const Feedback* feedback = nullptr);

}  // namespace lwb::core::slr
