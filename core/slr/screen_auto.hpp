#pragma once
// Automatic choice of the binary-image scale (mag_T, mag_OC), area limit and connectivity: the
// multi-scale version the paper names as its open problem (§5), done as a scored search.
//
// Rule. Let G be the robust O-C span (0.5–99.5 % quantiles) and r the points per second. A
// scale is written as an O-C pixel Δo = a·G and a time pixel Δt = c / (r·a), so c is the mean
// number of points per pixel if every point were noise spread over the gate: c fixes the
// noise occupancy, which must stay well below percolation (≈ 0.4 for 8-connectivity) for noise
// to stay in small regions, while a decides how fine the O-C scale is. The search runs the
// whole extraction (steps 1–6, area limit by automaticAreaLimit()) on scoring windows — up to
// autoMaxPoints points in three time windows of the pass
// (local density and slope unchanged), each screened on its own — for a = 2^-k, k = 2, 3, …
// (c = 0.1, and on sparse passes also 0.1/8, 0.1/64, 0.1/512, each ladder from the first k with
// c·2^k ≥ 1/16, i.e. at least 1/16 of a point per time pixel, and on an O-C flattened by a
// refinement round no coarser than 4× that round's O-C pixel; until the time pixel outgrows the
// windows or the score has fallen for 4 steps after a positive best; the ladders run side by
// side), then refines around
// the best (k ± ½, c ∈ {c/2, c, 2c}), then tries the other connectivity. A manual mag_OC fixes
// a (the ladder runs over c = 2^j); a manual mag_T fixes the time pixel.
//
// Score (no truth needed). From the trial's own output S in each window: a piecewise-linear
// trend of S (a robust line per time group of >= 8 points, joined; see scoreExtraction), the robust width σ_S = 1.4826·MAD of S's
// residuals, and the band |residual| ≤ h = 5σ_S. Noise density is measured outside the band
// (uniform over the O-C span), which predicts E noise points inside it. With N_in points in
// the band of which S_in selected: estimated true detections tp = S_in·(1 − E/N_in),
// false ones fp = |S| − tp, and the score is tp − 2·fp (a false detection costs two true
// ones: noise kept hurts the post-fit more than a few signal points lost). A too coarse scale
// merges noise into the track (wider band, more expected noise, selected points outside the
// band); a too fine one shatters the track into single pixels that the area split and
// linearity cannot keep (fewer true detections); a trial that keeps only a compact noise clump
// or a piece of the track scores only its few points. A band wider than half the span is no
// track: all of S counts as false. On simulated passes the estimated precision of the chosen
// scale is within about 0.01 of the true one.
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/screen.hpp"

namespace lwb::core::slr {

struct AutoScaleResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    std::string doubt;           ///< no scale shows a clear track ("" when one does)
    double magT = 0, magOc = 0;  ///< chosen (or the manual value when given)
    int connectivity = 8;        ///< chosen (or manual)
    std::vector<ScaleTrial> trials;
    double spanOcS = 0;          ///< robust O-C span G (s)
    double ratePerS = 0;         ///< points per second over the pass
};

/// Chooses the scale parameters left at 0 in params (manual ones are kept). t and oc in
/// seconds, finite, at least 3 points. Deterministic: the same choice and trial list whatever the
/// number of threads. Polls fb for cancel. Independent trials (the ladders of a sparse pass, the
/// refinement around the best) run side by side on params.searchThreads threads (0: every core).

AutoScaleResult chooseScale(const std::vector<double>& t, const std::vector<double>& oc, const ScreenParams& params,
                            const Feedback* fb = nullptr);

/// A robust piecewise-linear trend of points in time order: a line per time group of >= 8
/// points (at most 24 groups), joined straight between groups, constant beyond the ends.
struct PiecewiseTrend {
    struct Piece {
        double t0 = 0, t1 = 0, tm = 0, om = 0, slope = 0;
        double at(double x) const { return om + slope * (x - tm); }
    };
    std::vector<Piece> pieces;
    double at(double x) const;  ///< 0 when there are no pieces
    /// out[i] = at(x[i]) for x ascending, the same values, run by run of the points that share
    /// a piece or a gap between two (no search per point). Needs pieces in ascending t0 (as
    /// robustPiecewiseTrend makes them, from points in time order).
    void atMany(const double* x, size_t n, double* out) const;
};
/// The trend of the points sel (indices into t and oc, in ascending time).
PiecewiseTrend robustPiecewiseTrend(const double* t, const double* oc, const std::vector<size_t>& sel);

/// Is there a noise floor? The O-C about the robust piecewise trend of every point (in time
/// order): robust σ (1.4826·MAD), the peakedness (q97.5 − q2.5)/(q75 − q25), the share of
/// points within ±σ/4 (central) and beyond 5σ. Floorless when σ ≤ maxSigmaS, peakedness ≥ 2.2
/// (uniform noise: 1.9), central ≤ 0.34 (Gaussian 0.20; a track over noise in a gate a few ns
/// wide is a spike, 0.35) and the share beyond ≤ maxBeyond (or at most 2 points), with at
/// least kFloorShapePoints points; from 5 to 49 points, σ is the plain standard deviation, ≤
/// maxSigmaS, with at most one point in ten beyond 5σ. residualS holds each point's O-C minus the trend (input order).
/// Limits, measured on simulated passes: a track with an ns-level jitter (diffuse debris
/// ranging, σ ≈ 2 ns) is never called floorless (the paper's screening runs as before); noise
/// confined within about 3 ns of the track (a gate that narrow, with most points noise) cannot
/// be told from a filtered track's tails.
/// Below this many points the noise-floor check judges the spread and the outliers only (the
/// shape tests need more points than a short LEO pass has).
inline constexpr size_t kFloorShapePoints = 50;
struct NoiseFloorCheck {
    bool checked = false;  ///< false with fewer than 5 points
    bool floorless = false;
    double sigmaS = 0, peakedness = 0, centralFraction = 0, beyondFraction = 0;
    std::vector<double> residualS;
};
NoiseFloorCheck checkNoiseFloor(const std::vector<double>& t, const std::vector<double>& oc, double maxSigmaS = 1e-9,
                                double maxBeyond = 0.02);

/// The score of one time-sorted window (t ascending) given the selection mask (1 = the trial
/// called the point signal). Windows are scored separately and their parts summed.
ExtractionScore scoreExtraction(const double* t, const double* oc, const uint8_t* selected, size_t n);

}  // namespace lwb::core::slr
