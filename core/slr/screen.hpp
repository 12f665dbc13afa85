#pragma once
// SLR signal extraction by binary-image analysis (paper 004, Li Xi et al. 2014), steps 3–6 on
// top of binary_image.hpp (steps 1–2):
//   3) area split: regions with area ≥ area limit are candidates, the others pending;
//   4) linearity: slopes between candidate centroids (eq. 2) — long regions represented by
//      pieces of a few rows, each piece to its k nearest pieces through a k-d tree, never all
//      pairs — a slope-angle histogram per time block gives the dominant slope range, and the
//      candidates whose slopes agree are signal; the others become pending;
//   5) recovery: a pending region A_n is signal when, with its two nearest signal anchors
//      A_{n−1}, A_{n+1} (k-d tree), C < |cos ∠A_{n−1} A_n A_{n+1}| ≤ 1 (eq. 3), with the
//      collinearity guard described at collinearAccept() and a gap limit;
//   6) inverse mapping: every point of a signal pixel is signal (the index matrix).
// The automatic mode (screen_auto.hpp) chooses mag_T, mag_OC and connectivity; the area limit
// comes from a null model (automaticAreaLimit).
//
// Departures from the literal paper, each because the literal step fails on simulated passes
// (see the functions): pieces instead of one centroid per long region (a track that is one
// region has no slopes to compare); signed slope angles; slope weights favouring short links;
// the same-side case of eq. 3 also requires collinearity and at most one step beyond the end;
// the anchor pair of eq. 3 must be close (gap limit). Setting pieceRows = 0,
// slopeBlockRegions = 0 and recoveryGapFactor = 0 comes back to the paper's region centroids,
// one histogram and no gap limit.
//
// Parameter ranges (paper §4.2, table 1): conventional ranging mag_T 10, mag_OC 1e10; diffuse
// (debris) ranging mag_T 1, mag_OC 1e7. A large magnification is a fine scale (dense data,
// high echo rate); the area limit scales inversely with the magnification; high echo rate →
// 4-connectivity, low → 8. C between 0.9 and 1 (smaller lets noise in).
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/binary_image.hpp"

namespace lwb::core::slr {

/// Band: accepted by the post-fit's band where the screening said noise (a run's class,
/// PassRunResult::classes; the screening itself never gives it).
enum class PointClass : uint8_t { Noise = 0, Signal = 1, Recovered = 2, Band = 3 };
enum class RegionClass : uint8_t { Noise = 0, Signal = 1, Recovered = 2 };
const char* pointClassName(PointClass c);  ///< "noise", "signal", "recovered", "band"

struct ScreenParams {
    /// Automatic mode: every parameter left at 0 below is chosen from the data — mag_T, mag_OC
    /// and connectivity by the multi-scale search of screen_auto.hpp, the area limit by the null
    /// model of automaticAreaLimit(). Off: all four must be given. It chooses only these: the
    /// refinement, the track following and the floorless check have their own switches
    /// (refineRounds, followTrack, acceptFloorless); the paper's fixed procedure is automatic off
    /// with those three off too.
    bool automatic = true;
    double magT = 0;        ///< pixels per second of epoch; 0 = automatic. Sensible 1e-3..1e4 (paper: 1–10)
    double magOc = 0;       ///< pixels per second of O-C; 0 = automatic. Sensible 1e6..1e12 (paper: 1e7–1e10)
    int areaLimit = 0;      ///< px; regions with area ≥ limit are candidates (step 3); 0 = automatic; 1..1e6
    int connectivity = 0;   ///< 4 or 8; 0 = automatic
    double cosineC = 0.95;  ///< C of eq. 3; paper 0.9 < C < 1; accepted [0.5, 1)
    int slopeNeighbours = 8;       ///< step 4: slopes from each candidate piece to its k nearest pieces; 2..64
    double slopeBinDeg = 2.0;      ///< step 4: bin width of the line-angle histogram (degrees); 0.25..30
    double slopePeakFraction = 0.25;  ///< step 4: the dominant range is the run of bins around the peak
                                      ///< holding at least this fraction of the peak; (0, 1)
    double slopeAgreeFraction = 1.0 / 3;  ///< step 4: a candidate is on the line when at least this
                                          ///< (weighted) share of its slopes is in range (paper: 1/3); (0, 1]
    double maxSlopeRangeDeg = 40;  ///< step 4: the dominant range is at most this wide (degrees), so a flat
                                   ///< histogram (no line) keeps only candidates that happen to agree; 2..180
    int slopeBlockRegions = 200;   ///< step 4: pieces per time block with its own histogram (curved
                                   ///< tracks); 0 = one global histogram as in the paper; else ≥ 10
    int pieceRows = 8;             ///< steps 4–5: regions are cut into pieces of this many rows whose
                                   ///< centroids stand for them (a long track region is a line of pieces,
                                   ///< not one centroid); 0 = whole regions as in the paper; 0..1e6
    double recoveryGapFactor = 4;  ///< step 5: A_{n−1}, A_{n+1} at most this many typical anchor spacings
                                   ///< (median nearest-anchor distance) apart; 0 = no limit (paper); 0..1e6
    double areaTolerance = 2e-4;   ///< automatic area limit: share of pure-noise regions allowed to reach
                                   ///< it (automaticAreaLimit); (0, 0.5]
    int autoMaxPoints = 30000;     ///< automatic mode scores scales on at most this many points (three
                                   ///< time windows of the pass); 1000..1e7
    /// After the screening, a smooth trend (Legendre
    /// polynomial, 3σ-clipped, held constant outside the accepted time span) is fitted to the
    /// accepted points and subtracted, and the flattened O-C is screened again; the second
    /// result is kept when its extraction score (scoreExtraction over the whole pass) is at least
    /// the first one's; a trend within one O-C pixel of a straight line ends it (nothing
    /// to flatten). At a given scale the flattened O-C is screened at that scale, else the scale
    /// is searched again. Up to this many rounds; 0 = off (the paper's fixed procedure). Why: an O-C without a prediction (fitted TOF trend) leaves the
    /// track curved and broken (arches of tens of ns, segments at different levels), which the
    /// slope step and the area split handle badly; the track of the first round flattens it.
    int refineRounds = 2;          ///< 0..3
    /// Sparse passes — fewer returns per second than this over the pass (e.g. 10 Hz multi-photon
    /// passes with a few returns a second) — get the extra scale ladders of low noise occupancy
    /// and the refinement rounds; dense passes (kHz) do not need them and skip their cost.
    /// 0 = always use them.
    double sparseRateBelow = 50;
    /// Sparse passes (sparseRateBelow): follow the track from the accepted
    /// pieces through the pass afterwards (screen_follow.hpp): the sparse ends of the arc,
    /// stretches between pieces and pieces beyond gaps, with the density contrast along the
    /// track as the test. Off in the paper's fixed procedure.
    bool followTrack = true;
    /// A pass with no noise floor — the O-C about its robust piecewise trend
    /// has a robust σ of at most 1 ns, a peaked distribution ((q97.5 − q2.5)/(q75 − q25) ≥ 2.2;
    /// uniform noise gives 1.9, a Gaussian 2.9) and at most 2 % of the points (or 2 points)
    /// beyond 5σ — is
    /// a pass already filtered (station full-rate files often are): every point within 5σ of
    /// that trend is accepted (recovered) whatever the image made of it. Why: with no noise
    /// outside the track, the image's score cannot tell the track from a piece of it, and the
    /// screening kept 28 % of a clean 3577-point BLITS pass (checkNoiseFloor in screen_auto.hpp).
    bool acceptFloorless = true;
    /// Internal (no schema row; the refinement sets it): the O-C magnification of the round
    /// before, 0 = none. A search on an O-C flattened by that round's track starts its ladders
    /// at O-C pixels at most 4× that round's pixel (screen_auto.cpp says why).
    double previousMagOc = 0;
    /// Internal (no schema row: it never changes the answer): threads for the automatic scale
    /// search's independent trials, 0 = every core, 1 = none. A run setting carried with the run,
    /// not a process global: a batch that screens passes side by side gives each pass 1.
    int searchThreads = 0;
};

/// Empty when the parameters are valid, else what is wrong (names the parameter).
std::string validate(const ScreenParams& p);

/// One scale tried by the automatic mode, with its score (screen_auto.hpp explains the rule).
struct ScaleTrial {
    double magT = 0, magOc = 0;
    int areaLimit = 0, connectivity = 8;
    double score = 0;            ///< estimated true detections − 2 × false ones on the scoring windows
    double precisionEst = 0, recallEst = 0;  ///< the estimates the score is built from
    long long selected = 0;      ///< points the trial called signal (scoring windows only)
};

/// The extraction score of a selection (scoreExtraction, screen_auto.hpp), the automatic mode's
/// measure of a trial.
struct ExtractionScore {
    double score = 0;          ///< tp − 2·fp (estimated)
    double truePositives = 0;  ///< tp estimate
    double bandSignal = 0;     ///< N_in − E: estimated signal points in the band
    long long selected = 0;    ///< |S|
};

struct ScreenResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    // The parameters actually used, and which of them the automatic mode chose.
    double magT = 0, magOc = 0;
    int areaLimit = 0, connectivity = 0;
    bool autoMagT = false, autoMagOc = false, autoArea = false, autoConnectivity = false;
    std::vector<ScaleTrial> trials;  ///< automatic mode: every scale tried, in order (of the kept round)
    int refinedRounds = 0;           ///< screening rounds on a flattened O-C that were kept (refineRounds)
    /// The scale of the first round, on the O-C as given (magT ... above are the kept round's, on
    /// the flattened O-C when refinedRounds > 0): the scale that screening the same O-C again
    /// starts from (scaleChoice).
    double baseMagT = 0, baseMagOc = 0;
    int baseAreaLimit = 0, baseConnectivity = 0;
    long long followedAdded = 0;     ///< followTrack: points added as recovered
    long long followedDropped = 0;   ///< followTrack: accepted points returned to noise (off the followed track)
    /// Why the result cannot be trusted ("" when it can): automatic mode with no scale showing a
    /// clear track (the accepted points cannot be told from noise). The pass's run forms no
    /// normal points then.
    std::string doubt;
    bool floorless = false;          ///< acceptFloorless: the pass has no noise floor (filtered pass)
    double floorSigmaS = 0;          ///< acceptFloorless: robust σ of the O-C about its trend (s); 0 = not checked
    double floorBeyond = 0;          ///< acceptFloorless: share of points beyond 5σ of the trend
    long long floorlessAdded = 0;    ///< acceptFloorless: points within 5σ added as recovered
    std::vector<double> flattenS;    ///< when refinedRounds > 0: per point, the trend subtracted from the O-C
                                     ///< before the kept round (its image is of oc − flattenS); else empty
    /// Internal (the scale search): this result's extraction score on the O-C as given, when the
    /// refinement scored it and kept it (points in time order); the search's trial then uses it
    /// instead of scoring the same selection again.
    bool inputScoreKnown = false;
    ExtractionScore inputScore;
    // Per point (same order as the input).
    std::vector<PointClass> pointClass;
    std::vector<uint32_t> pointRegion;   ///< region id of each point (index into regionClass)
    // Per region (the regions themselves stay with the image: on a kHz pass they were 38
    // bytes an event held to the end of the run for their count).
    size_t regionCount = 0;
    std::vector<RegionClass> regionClass;
    // Counts.
    size_t pixels = 0, candidates = 0, linearRegions = 0, pendingRegions = 0, recoveredRegions = 0;
    size_t signalPoints = 0, recoveredPoints = 0, noisePoints = 0;
    double slopeLoDeg = 0, slopeHiDeg = 0;  ///< dominant line-angle range (widest over the blocks), degrees
    // Wall-clock timings (ms).
    double autoMs = 0, mapMs = 0, linearityMs = 0, recoveryMs = 0, totalMs = 0;

    /// True when the point is signal or recovered.
    bool accepted(size_t i) const { return pointClass[i] != PointClass::Noise; }
};

/// Steps 1–6 on (t, O-C) in seconds (same length; any order). Automatic parameters per
/// `params`. Errors: fewer than 3 points, non-finite values (names the point), invalid params,
/// a scale that overflows the pixel coordinates; warnings for an empty or degenerate result.
/// Deterministic; polls fb for cancel and reports progress.
ScreenResult screenSignal(const std::vector<double>& t, const std::vector<double>& oc, const ScreenParams& params,
                          Feedback* fb = nullptr);

/// A mask (1 = accepted: signal or recovered) for postfit.
std::vector<uint8_t> acceptedMask(const ScreenResult& r);

/// The scale stage's result: the binary-image scale, area limit and connectivity a screening
/// used, and which of them the automatic mode chose. Passed back to screenSignal() to screen
/// the same pass again without searching (the workbench does so when only C or the post-fit
/// settings change).
struct ScaleChoice {
    double magT = 0, magOc = 0;
    int areaLimit = 0, connectivity = 0;
    bool autoMagT = false, autoMagOc = false, autoArea = false, autoConnectivity = false;
};
/// The scale a successful screening used on the O-C as given: its first round's when the
/// refinement kept rounds on a flattened O-C (that round's scale fits the flattened O-C only:
/// reused on the O-C as given, JASON1 accepted nothing after a move of C, and turning the
/// automatic mode off lost points).
ScaleChoice scaleChoice(const ScreenResult& r);
/// Steps 1–6 at a given scale: the parameters left at 0 (automatic) in `params` are taken from
/// `scale` instead of being searched; the result reports them as automatic choices, as the run
/// that chose them did.
ScreenResult screenSignal(const std::vector<double>& t, const std::vector<double>& oc, const ScreenParams& params,
                          const ScaleChoice& scale, Feedback* fb = nullptr);

// ---- The steps, public for tests and for a step-by-step view. ----

/// Step 3: indices of the regions with area ≥ areaLimit (candidates), in region order.
std::vector<uint32_t> splitByArea(const RegionList& regions, int64_t areaLimit);

/// The automatic area limit (step 3) from a null model: the same epochs with O-C drawn
/// uniformly over the O-C span (fixed seed), mapped and labelled at the same scale; the limit is
/// the smallest area a ≥ 2 that at most max(1, tolerance × #regions) null regions reach, i.e.
/// pure noise of this density seldom makes a candidate. At most maxPoints points (a central
/// time window: same density) are used. Returns 2..64.
int automaticAreaLimit(const std::vector<double>& t, const std::vector<double>& oc, const MappingParams& mapping,
                       double tolerance = 2e-4, size_t maxPoints = 200000);

struct LinearityResult {
    std::vector<uint32_t> onLine;    ///< candidates whose slopes agree with the dominant range
    std::vector<uint32_t> offLine;   ///< candidates that do not (they become pending)
    double loDeg = 0, hiDeg = 0;     ///< widest dominant line-angle range over the blocks (degrees, (−90, 90])
    std::vector<std::string> warnings;
};

/// A point standing for (part of) a region in steps 4–5: the pixel centroid of a piece of
/// pieceRows rows of the region (or of the whole region), with its pixel count.
struct Anchor {
    double row = 0, col = 0;
    double weight = 0;     ///< pixels in the piece
    uint32_t region = 0;
};

/// The pieces of the selected regions: each region's pixels cut into bands of pieceRows rows
/// (counted from the region's first row), one anchor per band at its pixel centroid, in order
/// of first pixel. pieceRows = 0: one anchor per region at its centroid (the paper).
std::vector<Anchor> regionPieces(const BinaryImage& img, const std::vector<uint8_t>& selected, int pieceRows);

/// Step 4 on the candidate regions, represented by their pieces (or, when `pieces` is empty,
/// by their centroids as in the paper). The line angle of two pieces is atan(ΔY/ΔX) (X = row =
/// time, Y = col = O-C), kept signed (the paper's |K| of eq. 2 would fold a rising and a falling
/// track together) and taken modulo 180°. Each piece contributes the angles to its k nearest
/// pieces, weighted by the smaller pixel count of the pair over their distance (short links
/// along a track count most); per time block (slopeBlockRegions
/// pieces) the weighted histogram is smoothed, its peak found and the range grown over the
/// neighbouring bins holding ≥ slopePeakFraction of the peak (at most maxSlopeRangeDeg, plus one
/// bin of margin). A candidate region is on the line when ≥ slopeAgreeFraction of the weight of
/// its pieces' angles is in range. With ≤ 2 pieces in all, every candidate is on the line (a
/// warning says so).
LinearityResult findLinearRegions(const RegionList& regions, const std::vector<uint32_t>& candidates,
                                  const std::vector<Anchor>& pieces, const ScreenParams& params,
                                  const Feedback* fb = nullptr);

/// Eq. 3 for one pending centroid X with its nearest signal anchor P and second nearest Q:
/// accepted when |cos ∠P X Q| > C and the three are collinear. Between (cos < −C): the paper's
/// case (a). Same side (cos > C): the paper's case (b) — there |cos ∠PXQ| alone is not enough,
/// since any region far from a compact pair sees it under a small angle (|cos| → 1); so the
/// nearer anchor P must also lie between X and Q (cos ∠XPQ < −C) and X be no farther beyond P
/// than Q is (|XP| ≤ |PQ|: one step past the end of the track). X on P accepts.
bool collinearAccept(double pRow, double pCol, double xRow, double xCol, double qRow, double qCol, double C);

struct RecoveryResult {
    std::vector<uint32_t> recovered;  ///< pending regions accepted, ascending
    double maxPairDistance = 0;       ///< the gap limit used for |PQ| (pixels; 0 = none)
};

/// Step 5: tests every pending region against its two nearest signal anchors (k-d tree; one
/// pass: recovered regions do not become anchors). With gapFactor > 0, anchor pairs P, Q
/// farther apart than gapFactor × the median nearest-anchor distance are no line to recover on
/// (else an isolated anchor and the track would accept a whole lens of noise between them).
/// Fewer than 2 anchors: nothing is recovered.
RecoveryResult recoverPending(const RegionList& regions, const std::vector<uint32_t>& pending,
                              const std::vector<Anchor>& anchors, double cosineC, double gapFactor,
                              const Feedback* fb = nullptr);

}  // namespace lwb::core::slr
