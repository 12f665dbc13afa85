#pragma once
// After screening (ILRS practice, the Herstmonceux normal-point recommendation): a polynomial
// trend fitted to the accepted O-C, iterative k·σ rejection (2.5σ single-photon, 3σ
// multi-photon), residual statistics, and normal points in bins aligned to 0h UTC whose length
// follows the satellite's altitude, with a minimum number of points (6 by day, 3 by night).
//
// The trend model is chosen for the pass (issue 13): gross outliers are first rejected against
// the local track (a leave-one-out quadratic through the neighbouring points, grossSigma robust
// σ), so a point metres off the track never enters the fit; the pass is split into segments at
// gaps longer than splitGapS (a polynomial across a gap bends to both sides); in each segment
// the model is chosen by the Bayesian information criterion n·ln(RSS/n) + k·ln n (k
// coefficients) among Legendre polynomials of degree 0..degree and cubic splines of 2, 4, …, 64
// equal intervals no shorter than a bin (a trend without a prediction — the O-C against a fitted
// TOF trend — bends at the ends of a pass more than a polynomial can follow); fixed degree, as
// before, with autoDegree = false. Day or night per bin from the Sun's
// elevation at the station (solar.hpp) when its position and the date are given.
// A normal point: the epoch of the point nearest the bin's mean epoch, the trend there plus the
// bin's mean residual (as O-C, and as a two-way TOF when the observed TOFs are given), bin RMS,
// skew, kurtosis, peak − mean, number of points and return rate — the fields of a CRD type-11
// record.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"

namespace lwb::core::slr {

/// ILRS standard normal-point interval (s) for a satellite altitude (km): < 500 km 5 s;
/// 500–800 km 15 s (the list leaves 500–550 open; it goes with the 15 s LEOs); 800–2000 km 30 s;
/// 2000–5000 km 60 s; 5000–8000 km 120 s (LAGEOS); 8000–15000 km 180 s; > 15000 km 300 s (GNSS).
/// NaN for a non-finite or negative altitude.
double normalPointBinS(double altitudeKm);

struct PostfitParams {
    int degree = 10;              ///< trend polynomial degree (Legendre basis per segment), 0..30; the
                                  ///< largest degree tried when autoDegree
    bool autoDegree = true;       ///< choose the degree per segment (BIC); false = `degree` as given
    double splitGapS = 0;         ///< split the trend at gaps longer than this (s); 0 = automatic
                                  ///< (3 bin lengths, at least 20 s); < 0 = one trend for the pass
    double grossSigma = 10;      ///< reject points this many robust σ off the local track before the
                                  ///< fit; 0 = off, else 3..1000
    double rejectSigma = 3.0;     ///< k of the k·σ rejection: 2.5 single-photon, 3 multi-photon; 0 = off, else 1..10
    /// Narrow the k·σ band where the noise beside the track makes a narrower band lose fewer
    /// returns than it sheds noise (issue 43: low-SNR passes kept 8 % noise in a 3σ band whose σ
    /// the noise itself had widened). The noise density is measured beside the band; the signal's
    /// σ is the kept residuals' less that noise; the band becomes the one of the best expected F1,
    /// never wider than k·σ. No effect where fewer than kNoiseBandMinFlank points lie beside.
    bool noiseBand = true;
    /// Take the points the screening left out that lie within the final band about the trend,
    /// inside its segments' spans (PassTask: the post-fit is then run again with them): where the
    /// binary image stops (a sparse stretch, a return beside a gap in the image) the trend goes on.
    bool takeBand = true;
    int maxIterations = 30;       ///< fit–reject iterations, 1..1000
    double binLengthS = 0;        ///< normal-point bin length (s), 0 = from altitudeKm; else 0.1..86400
    double altitudeKm = 0;        ///< satellite altitude (km) when binLengthS = 0
    double dayStartS = 0;         ///< epoch of 0h UTC of the pass's day (s, same scale as the epochs)
    int minPointsPerBin = 0;      ///< 0 = ILRS minimum (6 by day, 3 by night); else 1..1e6
    /// Day or night for the ILRS minimum of points per bin (6 by day, 3 by night). Auto: from the
    /// Sun at the station, bin by bin, when the station is known (stationLatDeg ...), else day
    /// (the safer minimum). Day, Night: that minimum for every bin.
    enum class DayNight { Auto, Day, Night };
    DayNight dayNight = DayNight::Auto;
    double stationLatDeg = NAN;   ///< station geodetic latitude and east longitude (degrees) and the
    double stationLonDeg = NAN;   ///< MJD of dayStartS: with all three, day or night per bin from the
    double dayStartMjd = NAN;     ///< Sun's elevation at the bin's epoch (6 or 3 points minimum)
    double fireRateHz = 0;        ///< laser fire rate for the return rate; 0 = unknown (rate NaN)
    bool normalPoints = true;     ///< form normal points (off: trend and statistics only)
    /// Internal, no schema row (the screening's refinement sets it): the trend and `kept` only.
    /// Residuals of the points outside `use` stay NaN, `stats` and normal points are not formed,
    /// and the fit–reject iterations update the normal equations with the points that changed
    /// instead of summing them all again (the same sums in another order: a trend equal to the
    /// full sums' to rounding). Fixed degree only (autoDegree = false).
    bool trendOnly = false;
};

/// Empty when valid, else what is wrong.
std::string validate(const PostfitParams& p);

/// PostfitParams::noiseBand acts only with at least this many points beside the band.
inline constexpr long long kNoiseBandMinFlank = 20;

/// The band of the best expected F1 (half-width, s) for a Gaussian signal of σ `sigmaS` with
/// `signal` returns in all, over noise of `density` points per s of residual: the w that
/// maximises 2·S(w) / (S(w) + 2wλ + signal), S(w) = signal·erf(w / σ√2). Searched from 1.5 σ to
/// 6 σ in steps of σ/100. NaN for a non-positive σ or signal.
double bestExpectedF1Band(double sigmaS, double signal, double density);

/// Moments of a set of residuals (s), as the ILRS normal-point algorithm and CRD records take
/// them: d = residual − mean, rms = sqrt(Σd²/(n−1)), skew = (Σd³/n)/rms³, kurtosis =
/// (Σd⁴/n)/rms⁴ − 3 (0 for a Gaussian); peak = maximum of a Gaussian kernel density (Silverman
/// bandwidth). (The MLRS normal points of the shared data match these RMS and kurtosis values;
/// their skew is Σ|d|³/n/rms³, always positive — the signed third moment is kept here.) NaN
/// where undefined (n = 0; rms needs n ≥ 2; skew and kurtosis need rms > 0).
struct ResidualStats {
    long long n = 0;
    double mean = NAN;           ///< s
    double rms = NAN;            ///< s, about the mean, n − 1 in the denominator
    double skew = NAN;
    double kurtosis = NAN;       ///< excess
    double peakMinusMean = NAN;  ///< s
};
ResidualStats residualStats(const std::vector<double>& residuals);

/// One normal point, ready for a CRD type-11 record.
struct NormalPoint {
    double epochS = 0;          ///< epoch of the point nearest the bin's mean epoch (input time scale)
    double secondsOfDay = 0;    ///< epochS − dayStartS (CRD field 2)
    double tofS = NAN;          ///< two-way TOF (s): TOF_j − r_j + mean residual; NaN without TOFs (CRD field 3)
    double ocS = 0;             ///< O-C of the normal point: trend(epoch) + mean residual (s)
    double windowS = 0;         ///< bin length (s) (CRD field 6)
    double binStartS = 0;       ///< start of the bin (input time scale)
    int points = 0;             ///< ranges in the bin (CRD field 7)
    double meanResidualS = 0;   ///< mean residual of the bin (s)
    double rmsPs = NAN;         ///< bin RMS about the mean (ps) (CRD field 8)
    double skew = NAN;          ///< (CRD field 9)
    double kurtosis = NAN;      ///< excess (CRD field 10)
    double peakMinusMeanPs = NAN;  ///< (CRD field 11)
    double returnRatePct = NAN; ///< 100·points / (fire rate · bin length); NaN when unknown (CRD field 12)
    uint32_t pointIndex = 0;    ///< input index of the epoch point
    int minPoints = 0;          ///< the minimum this bin had to reach (6 day, 3 night, or as given)
    double sunElevationDeg = NAN;  ///< at the station at the epoch, when the station was given
};

/// One piece of the trend over [tStart, tEnd] (the used points of the segment): Legendre
/// coefficients in u = (t − tCenter) / tHalfSpan (knots = 0), or a cubic B-spline with `knots`
/// equal intervals over [tStart, tEnd] (knots + 3 coefficients; the end polynomials continue
/// beyond).
struct TrendSegment {
    double tStart = 0, tEnd = 0, tCenter = 0, tHalfSpan = 1;
    int degree = 0;     ///< Legendre degree, or 3 for a spline
    int knots = 0;      ///< spline intervals; 0 = Legendre polynomial
    std::vector<double> coefficients;
};

struct PostfitResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    int degree = 0;                     ///< highest degree fitted (over the segments)
    double tCenter = 0, tHalfSpan = 1;  ///< the longest segment's trend variable u = (t − tCenter) / tHalfSpan
    std::vector<double> coefficients;   ///< the longest segment's Legendre coefficients (s)
    std::vector<TrendSegment> segments; ///< the trend, in time order (one when the pass has no long gap)
    long long grossRejected = 0;        ///< of `rejected`: off the local track before the fit
    std::vector<uint8_t> kept;          ///< per input point: 1 when in the final fit
    std::vector<double> residuals;      ///< per input point: O-C − trend (s), every point
    ResidualStats stats;                ///< of the kept residuals
    double sigmaS = NAN;                ///< RMS of the kept residuals at the last rejection (s)
    /// The band the noise beside the track narrowed the rejection to (PostfitParams::noiseBand):
    /// its half-width (s), the signal's σ with the noise taken out (s), and the noise's density
    /// beside the band (points per s of residual); NaN where the band was not narrowed.
    double noiseBandS = NAN, signalSigmaS = NAN, noiseDensity = NAN;
    double limitS = NAN;                ///< the rejection's last limit: k·σ, or the noise band when narrower (s)
    int iterations = 0;
    long long used = 0;                 ///< points offered (the screening's accepted points)
    long long rejected = 0;             ///< of those, removed by the k·σ rejection
    bool converged = true;
    double binLengthS = 0;
    double dayStartS = 0;               ///< the bins' origin (PostfitParams::dayStartS)
    double splitGapS = 0;               ///< the gap the trend was split at (s; ≤ 0 none): splitGapS or its automatic value
    int minPointsPerBin = 0;            ///< the ILRS minimum used (the larger one when bins differ)
    int dayBins = 0, nightBins = 0;     ///< bins judged by the Sun's elevation (station given)
    std::vector<NormalPoint> normalPoints;
    int binsTooSmall = 0;               ///< bins with points but fewer than the minimum
};

/// The whole post-screening step on epochs t and O-C (s). `use`: the screening's mask (1 =
/// accepted), empty = every point. `tof`: observed two-way TOF per point (s), empty = none.
/// Errors name the problem (lengths, non-finite values, fewer than 2 usable points, params);
/// the degree is lowered with a warning when too few points or too short a span.
PostfitResult postfit(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint8_t>& use,
                      const std::vector<double>& tof, const PostfitParams& params, const Feedback* fb = nullptr);

/// How much of each normal point's error its fitted trends carry (issue 43: on sparse passes
/// without a prediction, normal points 5-73 mm off where the stations' 100-200 ps allow a few).
/// A normal point is the trend at its epoch point j plus the mean residual of its bin's kept
/// points B; the trends are fitted to the same points, so its error against the mean of B's
/// true errors is, to first order, a combination d·ε of the points' errors with
/// d = g − (I − S)ᵀ(I − H)ᵀg, g = e_j − 1_B/|B|, H the post-fit's hat matrix (its segments' bases
/// at their kept points) and S the O-C trend's (∂trend_i/∂tof_k: PassData::trendHat, row-major
/// n×n; empty for a prediction, which is not fitted to the pass). Per normal point of r, ‖d‖:
/// its trend error's standard deviation in units of a single shot's. *dof (when given): what
/// the kept residuals' sum of squares is in units of a single shot's variance, the sum over the
/// kept points of the squared rows of (I − H)(I − S) (without S, the kept points less the
/// segments' ranks). NaN everywhere for a pass of more than kMaxTrendFactorPoints points (the
/// cost grows as n²; such a pass's bins hold tens of points or more, over which a trend of a
/// dozen coefficients moves a normal point little), or where r or trendHat do not fit t.
inline constexpr size_t kMaxTrendFactorPoints = 5000;
std::vector<double> normalPointTrendFactors(const std::vector<double>& t, const PostfitResult& r,
                                            const std::vector<double>& trendHat, double* dof = nullptr);

/// The fitted trend at epoch t (s of O-C): the segment holding t, else the nearest one.
double evaluateTrend(const PostfitResult& r, double t);
/// evaluateTrend(r, t[i]) into out[i] for i < n (the same values, several points at a time).
void evaluateTrendMany(const PostfitResult& r, const double* t, size_t n, double* out);

}  // namespace lwb::core::slr
