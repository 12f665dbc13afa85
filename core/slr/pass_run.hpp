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

struct PassSettings {
    SlrParams params;
    std::string presetName;          ///< the preset applied ("" when none)
    std::vector<std::string> notes;  ///< normal-point context: fire rate, day or night, station
};

/// The parameters for `pass` before the user's explicit options: `base`, then the satellite's
/// entry of `presets` (looked up under `satellite` when given, else the pass's H3 name / ILRS id;
/// no presets = none), then the normal-point context of a CRD pass (C1 fire rate; the station's
/// position from `stations` for day or night per bin; without a station and a preset, the day
/// minimum of 6 points). False with *error when presets are given and none is for the pass.
bool passSettings(const PassData& pass, const SlrParams& base, const std::vector<SatellitePreset>* presets,
                  const std::string& satellite, const SinexFile* stations, PassSettings* out, std::string* error);

/// The screening against the station's filter flags (2 data, 1 noise), when every point has one.
struct StationAgreement {
    bool available = false;
    long long data = 0, noise = 0;        ///< station flags 2 and 1
    double precision = NAN, recall = NAN; ///< of the screening
    double keptPrecision = NAN, keptRecall = NAN;  ///< after the post-fit (NaN without one)
};
StationAgreement stationAgreement(const PassData& pass, const std::vector<uint8_t>& accepted, const PostfitResult* post);

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
};

/// Two parallel tracks in a track's residuals: "" or what was found. The sorted residuals are
/// cut at their widest gap with at least 10 % (and 5) of them on each side; two tracks when the
/// gap is more than 8 times the larger of the two sides' standard deviations (one Gaussian track
/// of 50 points or more stays below 2: test parallelTracksAreFound).
std::string parallelTracks(const std::vector<double>& residuals);

/// Whether a pass's result can be trusted, judged the same way wherever it is run (the CLI's
/// runPass and the workbench's live run): the screening's doubt (when points were accepted), or
/// two parallel tracks in the post-fit's kept residuals. A doubtful result loses its normal
/// points (*postNote says why). Returns the doubt ("" when none).
std::string judgeRun(const ScreenResult& screen, size_t acceptedCount, PostfitResult* post, std::string* postNote);

/// The normal-point context of a CRD pass, as the CLI's passSettings gives it (the C1 fire rate,
/// the station's position and day start from SINEX when given), written over the fields of *pp
/// that the parameters leave unknown (fire rate 0, station position NaN). Notes for the summary.
std::vector<std::string> passNormalPointContext(const PassData& pass, const SinexFile* stations, PostfitParams* pp);

/// The post-fit's parameters for a pass: with neither a normal-point bin length nor the
/// satellite's altitude (an O-C table names none) no bins can be laid, so the trend fit and the
/// rejection run without normal points, and *note (when given) says why.
PostfitParams postfitForPass(PostfitParams pp, std::string* note);

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

/// PassTask from scratch on `pass` (no edits, nothing reused).
PassRunResult runPass(const PassData& pass, const SlrParams& params, Feedback* fb = nullptr);

}  // namespace lwb::core::slr
