#pragma once
// Parameters tuned from a station's own decisions (issue 45): labelled passes (the station's
// filter flags in its CRD files, 2 data / 1 noise) are screened with each candidate of a small
// grid over the parameters that decide which points are kept (the screening's cosine constant,
// the post-fit's rejection k and whether its band takes the image's leftovers), the command's
// own settings first; the candidate with the best mean F1 of the delivered flags against the
// labels is chosen, and leave-one-pass-out says how well that choice holds on a pass it was not
// chosen on (a choice that holds out no better than the starting point is not made). `laserwb-cli slr tune` writes it as the satellite's preset entry, with provenance.
#include <cmath>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/common/json.hpp"
#include "core/sim/slr_eval.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/slr_run.hpp"

namespace lwb::core::slr {

/// What a front end gathers for a tuning: the files, the analyst's settings (as for a run) and
/// the satellite whose passes count ("" = the passes' one satellite).
struct TuneSources {
    std::vector<std::string> files;  ///< CRD files: every pass to screen of each (isPassToScreen); O-C tables
                                     ///< with a station_flag column (the CLI's -o): one pass each, of `satellite`;
                                     ///< folders: their CRD files (isCrdFile), where a file that does not read
                                     ///< or a pass without labels is left out with its reason (notes)
    /// Workbench sessions: the SLR pass of each with the analyst's decisions as labels — what the
    /// session's run delivered (its own parameters, prediction and station file) with the points
    /// forced in or out by hand. A session without edits has no decision of the analyst's.
    std::vector<std::string> sessions;
    /// The prediction and the station coordinates the files' O-C is made from (as the run's
    /// SlrSources: a CPF needs the stations; not applied to O-C tables, whose O-C is given, nor to
    /// sessions, which carry their own). Tuned on the O-C the passes are screened on in production.
    std::string cpf, stations;
    bool cpfFallback = false;        ///< a CPF that does not fit a pass: its own TOF trend, with a note
    std::string satellite;           ///< only passes of this satellite (matched as presets match)
    std::string presets;             ///< an existing presets file: its entry is the starting point
    std::vector<ParamSetting> set;   ///< over the defaults (or the entry), as --set
    int threads = 0;                 ///< the scale search's threads (0: every core)
};

/// One pass of the tuning: its name, its labels and each candidate's score on it.
struct TunedPass {
    std::string name;                         ///< "FILE pass K"
    size_t points = 0, labelledSignal = 0;    ///< points, and those the station flagged data
    std::vector<sim::DetectionScore> scores;  ///< per candidate (same order as TuneResult::candidates)
    double heldOutF1 = 0;                     ///< leave-one-pass-out: the choice made without this pass, scored on it
};

struct TuneCandidate {
    std::string label;  ///< "cosine_c=0.95 reject_sigma=3 take_band=true"
    SlrParams params;   ///< the parameters as a preset holds them (the pass's context left to the pass)
    double meanF1 = 0;  ///< over the passes
};

struct TuneResult {
    bool ok = false;
    SlrError error;
    std::string satellite, ilrsId;
    std::vector<TuneCandidate> candidates;  ///< [0]: the starting point (defaults, the entry, --set)
    std::vector<TunedPass> passes;
    size_t best = 0;                        ///< index of the chosen candidate
    double heldOutMeanF1 = 0;               ///< mean of TunedPass::heldOutF1
    /// The candidate the choice on all the passes took when it did not hold out (leave-one-pass-out
    /// F1 no better than the starting point's): best is then 0; 0 when it held out or was the start.
    size_t notHeldOut = 0;
    double startMeanF1 = 0;                 ///< the starting point's mean F1 (candidate 0's)
    std::vector<std::string> notes;         ///< passes left out (another satellite, not a pass) and why; a choice
                                            ///< that did not hold out (leave-one-pass-out), kept as the start
    std::vector<std::string> filesRead;     ///< the files the passes came from (a folder's CRD files by name)
};

/// Reads the files, keeps the passes of one satellite, refuses a pass without labels (every flag
/// 0, or no point flagged data) with its reason, screens every pass with every candidate and
/// chooses. ok false with `error` (a usage error when the choice is the caller's: passes of
/// several satellites without `satellite`, too few labelled passes).
TuneResult tuneSlr(const TuneSources& sources, const Feedback* fb = nullptr);

/// The tuning's record for the preset's provenance: the passes, their labels, F1 before (the
/// starting point) and after, and leave-one-pass-out.
Json tuneSummary(const TuneResult& r);

/// Writes `r`'s chosen parameters as the satellite's entry of the presets file `path` (the
/// entries already there kept, that satellite's replaced) and its provenance beside it
/// (PATH.provenance.json), all or nothing. An entry is the satellite's by its ILRS id, else by
/// its name (as a pass finds its preset). *note (when given): which entry was added or replaced.
/// False with *error.
bool writeTunedPreset(const TuneResult& r, const TuneSources& sources, const std::string& path, std::string* error,
                      std::string* note = nullptr);

/// What one value of a parameter gives on a pass (the SLR sliders' strips, issue 45).
struct SweepOutcome {
    bool ok = false;           ///< the run succeeded (a value the schema refuses, a failed screening: false)
    long long delivered = 0;   ///< points the run delivers (the post-fit's kept ones, else the accepted)
    double rmsS = NAN;         ///< the post-fit's RMS of the kept residuals (s); NaN without a post-fit
    double f1 = NAN;           ///< of the delivered flags against the labels; NaN without labels
};

/// A parameter swept over a pass as the workbench would run it with the slider moved there:
/// for each of `values`, `key` set to it over `panel` (the analyst's parameters), resolved for
/// the pass as every front end resolves them (resolvePassParams on `setup`), and the pass task
/// run with the analyst's edits (`in`). What the live rerun reuses for a change of that key
/// alone is reused: `reuse.screen` (the last run's screening) for a post-fit row, `reuse.scale`
/// (the automatic mode's last choice, where the workbench keeps it while C moves) for a
/// recovery row; nothing for the rows before. `labels` (1 data, per point; empty = none): the
/// station's flags or a simulation's truth, scored as F1. Cancelled through `fb` (within a run
/// too): the outcomes so far, the rest not ok.
std::vector<SweepOutcome> sweepSlrParam(const SlrSetup& setup, const PassTask::Inputs& in, const SlrParams& panel,
                                        const std::string& key, const std::vector<double>& values,
                                        const std::vector<uint8_t>& labels, const PassTask::Reuse& reuse,
                                        Feedback* fb = nullptr);

}  // namespace lwb::core::slr
