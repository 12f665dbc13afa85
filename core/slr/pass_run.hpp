#pragma once
// One pass from its data to its results — the parameters for the pass (preset, normal-point
// context), the screening (paper 004), the post-fit with normal points, and the agreement with
// the station's own filter flags — shared by `laserwb-cli slr` (one pass or --all-passes) and
// the workbench's SLR workspace.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/common/task.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/screen.hpp"
#include "core/slr/slr_params.hpp"

namespace lwb::core::slr {

/// Below this many points, a pass without a prediction (O-C against its own TOF trend) that
/// screens to nothing is doubtful, not "no signal": a quadratic over a minute of a LEO pass
/// misses its range by tens of ns (hy2c_202109 pass 1: 5 points, ±36 ns, all data).
inline constexpr size_t kMinOwnTrendPoints = 10;

struct PassSettings {
    SlrParams params;
    std::string presetName;          ///< the preset applied ("" when none)
    std::vector<std::string> notes;  ///< normal-point context: fire rate, day or night, station
};

/// The parameters for `pass` from `base`: the satellite's entry of `presets` (looked up under
/// `satellite` when given, else the pass's H3 name / ILRS id; no presets = none), then what the
/// pass tells where the parameters leave it unknown (passNormalPointContext). False with *error
/// when presets are given and none is for the pass. Front ends do not call it: they go through
/// core/slr/slr_run.hpp (resolvePassParams), which adds the analyst's config and settings in
/// the same order for every one of them.
bool passSettings(const PassData& pass, const SlrParams& base, const std::vector<SatellitePreset>* presets,
                  const std::string& satellite, const SinexFile* stations, PassSettings* out, std::string* error);
/// The satellite's preset of `presets` over *params (the preset's screening and post-fit replace
/// them whole), its name in *presetName; false with *error (what the file holds) when none is for the pass.
bool applyPreset(const PassData& pass, const std::vector<SatellitePreset>& presets, const std::string& satellite,
                 SlrParams* params, std::string* presetName, std::string* error);

/// The parameters `laserwb-cli slr` and Python's laserwb.slr start from: the core's, with the
/// multi-photon rejection of 3 sigma.
SlrParams commandDefaults();

/// The screening against the station's filter flags (2 data, 1 noise), when every point has one.
struct StationAgreement {
    bool available = false;
    long long data = 0, noise = 0;        ///< station flags 2 and 1
    double precision = NAN, recall = NAN; ///< of the screening; precision NaN (0/0) when nothing is accepted
    double keptPrecision = NAN, keptRecall = NAN;  ///< after the post-fit (NaN without one)
};
StationAgreement stationAgreement(const PassData& pass, const std::vector<uint8_t>& accepted, const PostfitResult* post);

/// The station's quality check against a prediction: a range bias b and a time bias τ fitted to
/// the kept points' O-C by least squares, O-C = b + τ · d(TOF_predicted)/dt (TOF_predicted =
/// TOF − O-C, its rate by central differences in time), with 1-sigma errors from the residual
/// scatter. Only when the O-C comes from a CPF prediction (ok false otherwise, with why).
struct PassBias {
    bool ok = false;
    std::string why;                       ///< why there is none
    double rangeBiasS = NAN, rangeBiasSigmaS = NAN;  ///< two-way
    double timeBiasS = NAN, timeBiasSigmaS = NAN;
    long long points = 0;
};
PassBias passBias(const PassData& pass, const std::vector<uint8_t>& kept);
/// "range bias 12.3 ± 0.4 mm (one-way), time bias 5.1 ± 0.8 µs (150 points)", or why none.
std::string describeBias(const PassBias& b);

/// The evidence for one normal point's bin (issue 43: real lunar passes published normal points
/// from points 40-67 % noise). The track's window is ±3σ of the trend (σ the kept residuals'
/// RMS): `onPoints` of the bin's points fall in it. The noise beside it is counted in the flanks
/// out to 20 windows each side, clipped to the gate as the bin's points show it, slice by slice
/// (about 20 points a slice: a burst of noise or a gate that moves is measured where it is):
/// `expectedNoise` is the number the flanks' density puts in the window. `pValue`: the chance
/// that noise alone puts onPoints of the window's and flanks' points in the window (the binomial
/// on/off test, the track given). The whole track (every bin's counts together) must pass the
/// same test times `trials` = (gate / window)², the tracks of that width one could draw across
/// the gate (the largest of the bins'); a pass that fails it fails in every bin. `edgeRoom`: the room between the window and the nearer edge of the gate, in
/// windows (median over the track's points of the room left by the 16 points off the window nearest
/// in time). Judged by kMaxBinFalseAlarm, kMaxBinNoiseShare and
/// kMinEdgeRoom.
struct BinEvidence {
    double binStartS = 0;
    long long onPoints = 0, offPoints = 0;
    long long bandPoints = 0;   ///< points within the fit's own band (min(window, PostfitResult::limitS))
    long long keptOnPoints = 0; ///< of bandPoints, those the fit kept
    double expectedNoise = 0;   ///< noise in the window, from the flanks
    double noiseShare = 0;      ///< (offPoints + 1)-based estimate of the window's noise share
    double pValue = 1;          ///< with the trials factor
    double trials = 1;
    double edgeRoom = 0;        ///< windows
    std::string why;            ///< "" when the bin's normal point stands
};
/// A bin's normal point stands when noise alone would give it less than once in 1000 bins, when
/// the window's estimated noise share is at most 10 %, and when the window is at least 2 windows
/// from the gate's edge (a band of noise at the gate's opening is dense and flat; a track there
/// cannot be told from it) — the last judged only where the noise shows the gate (the flanks'
/// density puts at least 3 points in 10 windows; sparse noise leaves a side empty by chance). A
/// bin with fewer than 16 points off the window is judged by the pass-wide test alone (too few
/// to measure its noise by: the MLRS Beacon-C passes' 15 s bins).
inline constexpr double kMaxBinFalseAlarm = 1e-3;
inline constexpr double kMaxBinNoiseShare = 0.10;
/// On a short pass without a prediction (its own fitted TOF trend, PassData::trendHat), a
/// normal point whose fitted trends' share of its error (normalPointTrendErrors, one sigma,
/// one-way) exceeds this many mm is dropped (PassTask): 2.5 sigma within the 5 mm a LEO normal
/// point is held to. Measured on 120 simulated sparse LEO passes (tests/test_slr_sparse_leo.cpp,
/// docs/slr-detection.md): every normal point beyond max(5 mm, 4 Cramér–Rao bounds) is withheld.
inline constexpr double kMaxNpTrendErrorMm = 2.0;
inline constexpr double kMinEdgeRoom = 2;
/// A bin's track must be kept, not a part of it: the points within the fit's own band (its
/// rejection's last limit, or the window where that is wider) that the fit left out (the
/// screening called them noise) may be at most 10 % of the band's points plus the noise the
/// flanks put there (λ scaled to the band, + 3√(λ + 1)). (The band, not the window: a
/// rejection at 2σ settles at 1.45σ, and a window of 3 RMS would leave 12 % of a clean track out.) A scale finer than the track (O-C pixels of 1 ps
/// on a 25 ps track) keeps a sliver of it: 37 of the 141 points within ±10 ps, λ 9.7, and a
/// normal point 1.8 mm from the whole track's with a precision of 0.1 mm; a scale that splits the
/// gate's noise keeps half the window. The shared real passes leave 0–2 % of it out.
inline constexpr double kMaxWindowLeftOut = 0.10;
/// The kept residuals' shape judges every pass too (windowShapeDoubt; residuals of 0 to a
/// femtosecond, points their own segment's fit passes through, left out): where the window spans
/// the gate (a scale that kept the gate's noise), the flanks beside it measure nothing, or only
/// the few points a misfit put there. Two shapes are not one track:
/// - a narrow track on a wide floor (the window, ±3 RMS, spans the floor): the share of kept
///   points in the densest interval a fiftieth of their RMS wide is above kCentralShareBase +
///   4·√(base·(1 − base) / n), n ≥ kMinCentralPoints. One Gaussian track puts 0.8 % there; the
///   shared real passes' kept points 1–8 % (BLITS and Beacon-C, 50 points: the most); a track of
///   60 ps on a floor of µs puts its own share there. The densest interval, not the median's: a
///   trend fitted through the floor leaves the track aside. The project's draws
///   (windowShapeTellsOneTrackFromNoise, docs/slr-detection.md) give the shares refused;
/// - noise that fills the window, judged where no bin has 16 points off its window or where the
///   fit's band is the whole window (a rejection below 3σ, or the noise band, clips a real
///   track's shoulders and flattens it): peakedness (q97.5 − q2.5)/(q75 − q25) of 300 3σ-clipped points
///   (3 000 draws each, docs/slr-detection.md): a Gaussian median 2.85, 0.1 % quantile 2.28; with
///   an exponential tail 3.02 (2.40); half Gaussian half flat 2.75 (2.26); flat 1.90 (99 %
///   quantile 2.19); the shared real passes of 300 kept points or more 2.56 at the least. Below
///   300 points the sample cannot tell (a Gaussian of 100 falls under 2.2 one time in 50): not
///   judged.
inline constexpr double kCentralShareBase = 0.08;
inline constexpr size_t kMinCentralPoints = 50;
inline constexpr double kMinTrackPeakedness = 2.2;
inline constexpr size_t kMinFlatWindowPoints = 300;
/// "" when the kept residuals can be one track (or are too few to tell), else why not.
/// judgePeakedness: no bin has 16 points off its window, or the fit's band is its whole window
/// (PassTask judges the peakedness only then).
std::string windowShapeDoubt(const PostfitResult& post, bool judgePeakedness = true);
/// One BinEvidence per normal point of `post` (t: the pass's epochs).
std::vector<BinEvidence> normalPointEvidence(const std::vector<double>& t, const PostfitResult& post);

struct PassRunResult {
    bool ok = false;
    std::string error;                 ///< the screening failed
    ScreenResult screen;
    std::vector<uint8_t> accepted;     ///< per point: signal or recovered
    size_t acceptedCount = 0;
    bool postOk = false;
    std::string postNote;              ///< why there is no post-fit, or no normal points
    /// Why the result cannot be trusted ("" when it can): the screening's doubt, or two parallel
    /// tracks in the post-fit residuals (a second target or a double-pulse echo merged into one
    /// track). No normal points are formed then (postNote says so).
    std::string doubt;
    PostfitResult post;
    StationAgreement agreement;
    double seconds = 0;                ///< wall time of screening + post-fit
    bool screenReused = false;         ///< the earlier run's screening was reused (only post-fit or edits changed)
    bool scaleReused = false;          ///< screened at the scales an earlier run chose (only C changed)
    PassBias bias;                     ///< range and time bias against the prediction (CPF O-C only)
    /// Points the screening left out that the post-fit's band took (PostfitParams::takeBand);
    /// they are in `accepted`, not in `screen`.
    long long bandTaken = 0;
    /// Per point, the run's class for every product (the CSV, Python, the workbench, the
    /// report): the screening's, Signal or Noise where an edit overrode it, Band where the
    /// post-fit's band took it. Accepted exactly where it is not Noise.
    std::vector<PointClass> classes;
    /// One per normal point the post-fit formed (before any was dropped), on a pass with a noise
    /// floor and no other doubt: why each stands or not (normalPointEvidence).
    std::vector<BinEvidence> binEvidence;
};

/// Two parallel tracks in a track's residuals: "" or what was found. The sorted residuals are
/// cut at their widest gap with at least 10 % (and 5) of them on each side; two tracks when the
/// gap is more than 8 times the larger of the two sides' standard deviations (one Gaussian track
/// of 50 points or more stays below 2: test parallelTracksAreFound). With noise between the
/// tracks (no empty gap), a second dense window of the main track's width beside it, parted
/// from it by a sparse valley and standing 5 times above the noise (see pass_run.cpp).
std::string parallelTracks(const std::vector<double>& residuals);

/// The fewest points the binary image must find on a track, unless the track stands
/// kMinTrackSeparation times above the noise (judgeRun).
inline constexpr size_t kMinImagePoints = 10;
inline constexpr double kMinTrackSeparation = 20;

/// How far a post-fit track stands above the noise: the points within ±3σ of the trend (σ the
/// kept residuals' RMS), divided by the number the noise beside the band would put there if it
/// were as dense inside (uniform over the residuals' range). Infinite with no point beside the
/// band; NaN without residuals. Measured: true tracks of 2 %-signal lunar-like passes 49–82,
/// 5 % 110–125; a track the recovery followed through noise 8.4 (docs/slr-detection.md).
double trackSeparation(const PostfitResult& post);

/// Whether a pass's result can be trusted, judged the same way wherever it is run (PassTask):
/// - points accepted: the screening's doubt (no scale showed a clear track), or a track resting
///   on fewer than kMinImagePoints image points (recovered around them or not) that does not
///   stand kMinTrackSeparation above the noise (not on a filtered pass), or two parallel tracks
///   in the post-fit's kept residuals;
/// - nothing accepted: doubtful when no scale showed a clear track (a signal too sparse for the
///   method), else "no signal found" is the answer and not a doubt.
/// A doubtful result loses its normal points (*postNote says why). Returns the doubt ("" when none).
std::string judgeRun(const ScreenResult& screen, size_t acceptedCount, PostfitResult* post, std::string* postNote);

/// What a pass tells, written over the fields of *pp that the parameters leave unknown: the
/// satellite's altitude (0), the C1 fire rate (0), the ILRS missions table's bin length (0), and
/// the station's position and day start (from SINEX when given, else the ILRS stations table).
/// Notes for the summary.
std::vector<std::string> passNormalPointContext(const PassData& pass, const SinexFile* stations, PostfitParams* pp);

/// The post-fit's parameters for a pass: with neither a normal-point bin length nor the
/// satellite's altitude (an O-C table names none) no bins can be laid, so the trend fit and the
/// rejection run without normal points, and *note (when given) says why. A pass whose O-C is
/// relative to a circular orbit fitted to it (PassData::orbitTrend) has residuals that need at
/// most a bias and a drift: with the automatic degree and split gap, its trend is then one line
/// over the pass (per-burst polynomials or splines through a few returns would carry their noise
/// into the normal points).
PostfitParams postfitForPass(PostfitParams pp, std::string* note, const PassData* pass = nullptr);

/// The SLR pass task (core/common/task.hpp), run by `laserwb-cli slr` (one pass and
/// --all-passes) and by the workbench's SLR workspace (TaskJob<PassTask>): screens the pass,
/// applies the analyst's edits, and with at least two accepted points fits the trend and forms
/// the normal points, judged by judgeRun. Normal points are switched off (with a note) when
/// neither a bin length nor the satellite's altitude is known. The parameters come from
/// passSettings (preset, normal-point context) before the user's own.
struct PassTask {
    static constexpr const char* kName = "slr pass";
    using Params = SlrParams;
    static const Schema<SlrParams>& schema() { return slrSchema(); }
    struct Inputs {
        std::shared_ptr<const PassData> pass;
        /// Manual edits per point (+1 accepted, -1 rejected, 0 as screened); empty = none.
        std::vector<int8_t> forced;
    };
    /// What an earlier run of the same pass gives: its screening, when only kStagePostfit rows
    /// or the edits changed; or the scales its automatic mode chose, when only kStageRecovery
    /// rows changed (the workbench's opt-in: a screening at a kept scale is not the one the CLI
    /// makes at that C).
    struct Reuse {
        std::shared_ptr<const ScreenResult> screen;
        std::optional<ScaleChoice> scale;
    };
    using Outputs = PassRunResult;
    static PassRunResult run(const Inputs& in, const SlrParams& params, const Reuse& reuse, Feedback* fb);
};

/// The points outside `accepted` within the post-fit's final band (|residual| ≤ post.limitS)
/// and inside one of its trend segments' spans, less those an edit forced out (forced < 0).
std::vector<uint32_t> pointsInBand(const std::vector<double>& t, const PostfitResult& post,
                                   const std::vector<uint8_t>& accepted, const std::vector<int8_t>& forced);

/// Per normal point of `post` (a post-fit of `pass`): the fitted trends' share of its error, one
/// sigma (two-way s): postfit.hpp normalPointTrendFactors with the pass's own trend hat matrix
/// (PassData::trendHat; none for a prediction), times the kept residuals' scale, their sum of
/// squares over its `dof` (infinite with less than one left). NaN where not computed (more than
/// kMaxTrendFactorPoints points).
std::vector<double> normalPointTrendErrors(const PassData& pass, const PostfitResult& post);

/// PassTask from scratch on `pass` (no edits, nothing reused).
PassRunResult runPass(const PassData& pass, const SlrParams& params, Feedback* fb = nullptr);

/// The normal points a run delivers (none when it is doubtful or has no post-fit) and, when there
/// are none, why: what the normal-point file says in their place (the CLI and Python write it).
struct DeliveredNormalPoints {
    std::vector<NormalPoint> points;
    std::string noneReason;  ///< "" when there are points
};
DeliveredNormalPoints deliveredNormalPoints(const PassRunResult& r);


/// After screening: "doubtful" (r.doubt), "no signal" (nothing accepted) or "ok" (the O-C note
/// or the post-fit's note as the reason).
BlockStatus runStatus(const PassData& pass, const PassRunResult& r);

}  // namespace lwb::core::slr
