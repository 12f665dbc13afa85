#pragma once
// Verdict criteria tuned from an analyst's own verdicts (issue 45). The shots are fitted once
// under the starting parameters; their verdict measures (core/footprint/verdict.hpp) are then
// judged under many criteria without fitting again. The search moves one threshold at a time
// (each end of the axis-ratio, major-axis, tilt and eccentricity ranges, the MSE and
// uncertainty limits, the edge extent, the saturated-pixel allowance, the second-spot fraction;
// only criteria the starting point has switched on) to where it leaves the fewest disagreements
// between good and not good, never letting more shots the analyst did not call good through as
// good than the starting point did; a threshold moves only for a gain, and then a quarter of the
// way from the values it lets through towards those it holds back (tune.cpp, kGoodSide). Cross-validation (shots
// parted into folds by their names, each fold judged by criteria tuned on the others) says how
// the choice holds on shots it was not tuned on. The segmentation and the fit are not tuned:
// they would need every shot fitted again per candidate.
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/common/json.hpp"
#include "core/common/task.hpp"
#include "core/footprint/footprint_run.hpp"
#include "core/footprint/verdict.hpp"

namespace lwb::core::footprint {

/// Counts by the analyst's verdict (row) and the computed one (column): good, doubtful, rejected.
struct VerdictConfusion {
    int count[3][3] = {};
    void add(Verdict analyst, Verdict computed) { ++count[static_cast<int>(analyst)][static_cast<int>(computed)]; }
    int total() const;
    int analystGood() const;     ///< shots the analyst called good
    int analystNotGood() const;  ///< doubtful or rejected by the analyst
    int falseDoubts() const;     ///< the analyst's good ones computed doubtful or rejected
    int misses() const;          ///< the analyst's doubtful or rejected ones computed good
    int disagreements() const;   ///< off the diagonal
    Json toJson() const;
    /// A printable table, rows the analyst's verdict, columns the computed one.
    std::string text(const std::string& indent = "  ") const;
};

/// One ROI the analyst judged: what its verdict stage reads (measureResult) and the verdict.
struct LabelledShot {
    std::string name;            ///< the frame's file, with " roi K" for a frame of several ROIs
    VerdictMeasures measures;
    Verdict label = Verdict::Good;
};

/// One criterion the tuning moved.
struct VerdictChange {
    std::string key;             ///< the schema row: "verdict.tilt_deg", "verdict.mse_max"
    std::string end;             ///< a range row's end moved: "lo", "hi", "±" (both, about 0); "" a value row
    double before = 0, after = 0;
    std::string name() const { return end.empty() ? key : key + " (" + end + ")"; }
};

struct VerdictTuneResult {
    bool ok = false;
    std::string error;
    FootprintParams before, after;     ///< the starting point, and it with the tuned criteria
    std::vector<VerdictChange> changes;
    VerdictConfusion confusionBefore;  ///< every labelled shot under `before`
    VerdictConfusion confusionAfter;   ///< under `after` (the shots it was tuned on)
    VerdictConfusion heldOut;          ///< each shot under criteria tuned without its fold
    int folds = 0;                     ///< cross-validation folds (0: too few shots for any)
};

/// Tunes `start`'s verdict criteria on the labelled shots (every other parameter kept); `folds`
/// (2..20; 0 = none) for the cross-validation. Refuses (ok false, error) too few labelled shots
/// or labels of one kind only. Cancel through fb.
VerdictTuneResult tuneVerdict(const std::vector<LabelledShot>& shots, const FootprintParams& start, int folds = 5,
                              Feedback* fb = nullptr);

/// One criterion swept over values (the workbench's strip beside its slider): per value, the
/// shots judged good, those whose verdict (good or not good) differs from theirs under `p`, and
/// those that disagree with their label (labels: one per shot, -1 none; empty: no labels).
struct CriterionSweep {
    std::vector<int> good, changed, disagree;
    int labelled = 0;                  ///< shots with a label
};

/// The row `key` ("verdict.mse_max"; a range row's end `end`, "lo" or "hi") set to each of
/// `values` in turn, every shot judged (checkVerdict) under it, the rest of `p` kept. Empty when
/// the key is not a verdict threshold. Cancel through fb (then partial, empty).
CriterionSweep sweepCriterion(const std::vector<VerdictMeasures>& shots, const std::vector<int>& labels,
                              const FootprintParams& p, const std::string& key, const std::string& end,
                              const std::vector<double>& values, Feedback* fb = nullptr);

/// The tuning as a task (core/common/task.hpp) on shots already fitted: the workbench's "Suggest
/// thresholds from my verdicts" runs it (TaskJob) on the shots the analyst gave a manual verdict,
/// tuneFootprint on the shots of files with a verdicts table.
struct VerdictTuneTask {
    static constexpr const char* kName = "footprint verdict tuning";
    using Params = FootprintParams;  ///< the starting point
    static const Schema<FootprintParams>& schema() { return footprintSchema(); }
    struct Inputs {
        std::vector<LabelledShot> shots;
        int folds = 5;
    };
    using Reuse = NoReuse;
    using Outputs = VerdictTuneResult;
    static Outputs run(const Inputs& in, const Params& start, const Reuse&, Feedback* fb) {
        return tuneVerdict(in.shots, start, in.folds, fb);
    }
};

/// What a front end gathers for `footprint tune`: the shots and the starting parameters as for
/// a run, and the analyst's verdicts.
struct FootprintTuneSources {
    FootprintSources run;
    /// A CSV with `file` and `verdict` columns (good, doubtful, rejected; the workbench's review
    /// export and the CLI's report have them) and optionally `roi` (a frame of several ROIs). A
    /// shot's row is found by the frame's path (a relative one relative to the table's folder,
    /// else to the working folder), else by its file name when one frame alone has that name.
    std::string verdicts;
    int folds = 5;
};

struct FootprintTuneResult {
    bool ok = false;
    FootprintError error;
    VerdictTuneResult tuning;
    size_t shots = 0, rois = 0;        ///< shots run, and their ROIs
    size_t labelled = 0;               ///< ROIs with a verdict (those tuned on)
    size_t unreadable = 0;             ///< frames that could not be read (left out)
    size_t unmatchedRows = 0;          ///< verdict rows no shot has
    std::vector<std::string> notes;    ///< what was left out and why
    std::vector<std::string> inputs;   ///< the frames read (for the provenance)
};

/// Resolves the sources (setUpFootprintRun), reads the verdicts, fits every shot once and tunes.
/// ok false with `error` (FILE:LINE for a bad verdicts table; usage when no shot has a verdict).
FootprintTuneResult tuneFootprint(const FootprintTuneSources& sources, Feedback* fb = nullptr);

/// The tuning's record: shots, labels, changes, confusion before, after and held out.
Json footprintTuneSummary(const FootprintTuneResult& r);

/// Writes the tuned parameters as a footprint config (`footprint --config FILE.json` applies it)
/// with its provenance beside it (FILE.json.provenance.json: the summary, every input), all or
/// nothing. False with *error.
bool writeTunedFootprintConfig(const FootprintTuneResult& r, const FootprintTuneSources& sources, const std::string& path,
                               std::string* error);

}  // namespace lwb::core::footprint
