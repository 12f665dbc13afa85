#pragma once
// An SLR run from its sources (docs/architecture.md, "Sources -> load -> resolve -> run ->
// write"). A front end — the CLI, the workbench, Python, Dask — only gathers SlrSources from its
// own world (flags, dialogs, keyword arguments); the core reads them once (setUpSlrRun), decides
// which block of a file is a pass and which one opens (isPassToScreen), resolves each pass's
// parameters in one order (resolvePassParams), runs it (PassTask) and writes its products with
// one writer (stagePassProducts). A station's file of passes is the batch over these steps
// (station_day.hpp). No front end calls a reader or a set-up helper itself: that is where front
// ends drifted apart (a printed config lost every normal point of --all-passes, issue 40).
#include <memory>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/common/json.hpp"
#include "core/common/output_set.hpp"
#include "core/common/provenance.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/slr_params.hpp"

namespace lwb::core::slr {

using core::ParamSetting;

/// What a front end gathers for an SLR run: names of files and the analyst's own settings,
/// nothing read yet.
/// A pass given as its columns instead of a file (Python's Pass.from_arrays): epochs and O-C
/// (s, two-way), as an O-C table's, named `name` in messages and products.
struct OcArrays {
    std::vector<double> t, oc;
    std::string name = "arrays";
};

struct SlrSources {
    std::string input;           ///< a CRD file (one pass of it, or all) or an O-C CSV
    /// The pass as arrays (instead of `input`): openPass makes it a pass as it makes an O-C table's.
    std::shared_ptr<const OcArrays> arrays;
    int passNumber = 0;          ///< 1-based; 0 = the file's first pass to screen (isPassToScreen)
    std::string cpf;             ///< CPF file or folder of CPF files; O-C from it needs `stations`
    std::string stations;        ///< SINEX station coordinates (alone: day or night per bin)
    /// The station's own normal points of the pass (a CRD normal-point file): compared with ours
    /// bin by bin in the pass report (np_compare.hpp; --station-np, the Station NP tab).
    std::string stationNormalPoints;
    std::string presets;         ///< per-satellite presets file ("" = none)
    std::string satellite;       ///< look the preset up under this name instead of the pass's
    std::string configFile;      ///< parameters as JSON (what --print-config writes); "" = none
    /// Parameters as JSON given directly, read after configFile: the workbench's panel, Python's
    /// SlrParams. Null = none. Keys the pass tells (altitude, fire rate, bin) left at 0 stay the pass's.
    Json config;
    std::vector<ParamSetting> set;  ///< after the config, in order (the last of one key wins)
    /// A CPF that does not fit a pass (another satellite, another day): a note and the pass's own
    /// TOF trend (the batch and the workbench) instead of an error (one pass on the CLI).
    bool cpfFallback = false;
    int searchThreads = 0;       ///< threads of the automatic scale search (0: every core); never changes the answer
    /// A pass with records the reader had to skip opens to be looked at (the workbench) instead
    /// of being refused; every writer still refuses it (PassData::damaged).
    bool openDamaged = false;
    /// Read and check the files, open no pass (Python's read_crd, read_cpf and read_sinex):
    /// loadSlrPass lists the input's blocks, and a prediction is checked without stations.
    bool listOnly = false;
};

/// A problem with a run: what and where; `usage` when it is the caller's choice (exit 2: an
/// option, a block that is not a pass), else the data's or the system's (exit 1).
struct SlrError {
    std::string message;
    bool usage = false;
    bool empty() const { return message.empty(); }
};

/// The sources read once and shared read-only by every pass of the run.
struct SlrSetup {
    SlrSources sources;
    std::vector<SatellitePreset> presets;
    bool havePresets = false;
    std::shared_ptr<const PassSources> predictions = std::make_shared<const PassSources>();  ///< CPFs (with stations), stations
    Json config = Json::object();  ///< configFile then `config`, merged (applied to every pass)
    /// The command's defaults with the config and the settings applied: what --print-config
    /// prints and the provenance records before a pass's own context.
    SlrParams base;
    /// sources.stationNormalPoints as read (null: none given).
    std::shared_ptr<const CrdFile> stationNormalPoints;
    const SinexFile* stations() const { return predictions && predictions->haveStations ? &predictions->stations : nullptr; }
};

/// Reads the presets, the station coordinates, the predictions and the config, and checks
/// every setting against the schema (before any pass is read). False with *error.
bool setUpSlrRun(const SlrSources& sources, SlrSetup* out, SlrError* error);
/// Reads `path` as the station's normal points of the run (setUpSlrRun does it for
/// sources.stationNormalPoints; the workbench when the analyst opens one): both of the setup's
/// fields set, or cleared for "". False with *error (FILE:LINE) and the setup as it was.
bool setStationNormalPoints(SlrSetup* setup, const std::string& path, SlrError* error);
/// setUpSlrRun without the files: the config and the settings checked over the defaults
/// (--print-config, and the usage checks before anything is read).
bool resolveBaseParams(const SlrSources& sources, SlrParams* out, SlrError* error);

/// The parameters of one pass, in the one order every front end and batch shares: the command's
/// defaults; the satellite's preset (when presets are given; none for the pass is an error);
/// the config; the settings; then what the pass tells wherever the parameters leave it unknown
/// (altitude 0, fire rate 0, bin length 0, the station's position: passNormalPointContext);
/// finally the whole schema's validation. Notes: the normal-point context.
bool resolvePassParams(const SlrSetup& setup, const PassData& pass, PassSettings* out, SlrError* error);

/// A pass opened: read, chosen, its O-C made and its parameters resolved.
struct OpenedPass {
    bool ok = false;
    SlrError error;
    std::vector<std::string> warnings;          ///< the readers'
    std::vector<std::string> notes;             ///< what the O-C is relative to (OcResult::notes)
    std::vector<PassSummary> passes;            ///< every block of the file (one for an O-C table)
    std::shared_ptr<const CrdReadResult> crd;   ///< the file as read (CRD input)
    std::shared_ptr<const PassData> pass;
    PassSettings settings;
};

/// Reads setup.sources.input and opens pass setup.sources.passNumber (0: the first pass to
/// screen). A block that is not a pass, a damaged pass, a pass number beyond the file: errors
/// that say what the file holds.
OpenedPass openPass(const SlrSetup& setup, const Feedback* fb = nullptr);
/// The CRD file of the sources as openPass reads it (gzip, limits, messages with the first
/// warnings): null with *error when it cannot be read. Python's read_crd lists its passes.
std::shared_ptr<const CrdReadResult> readSlrInput(const SlrSources& sources, SlrError* error, const Feedback* fb = nullptr);
/// The same for a file already read (the workbench switching passes): passIndex 0-based, -1 the first.
OpenedPass openPassOf(const SlrSetup& setup, const std::shared_ptr<const CrdReadResult>& crd, int passIndex,
                      const Feedback* fb = nullptr);

/// One pass loaded from its sources, the load every front end that opens a pass shares
/// (Python's load_pass, the workbench's open): setUpSlrRun, then openPass. ok false with
/// `error`; `setup` is set when the set-up succeeded, `opened` when the file was read (its
/// passes listed even when the one asked for cannot open). With sources.listOnly the input's
/// blocks are listed (opened.passes, opened.crd) and none is opened; the set-up's predictions
/// hold the CPF and stations as read.
struct LoadedSlrPass {
    bool ok = false;
    SlrError error;
    bool setUp = false;
    SlrSetup setup;
    OpenedPass opened;
};
LoadedSlrPass loadSlrPass(const SlrSources& sources, const Feedback* fb = nullptr);

/// PassTask on an opened pass with its resolved parameters (and the setup's search threads).
PassRunResult runOpenedPass(const PassData& pass, const PassSettings& settings, const SlrSetup& setup,
                            Feedback* fb = nullptr);

/// A pass opened earlier and run with the sources of `setup` (Python's load_pass, then run with
/// a preset, stations or parameters of its own): resolvePassParams, then runOpenedPass, so that
/// no front end strings the two together itself. ok false with `error` (a parameter refused is a
/// usage error; a failed screening names the pass).
struct ResolvedRun {
    bool ok = false;
    SlrError error;
    PassSettings settings;
    PassRunResult result;
    std::shared_ptr<const SlrSetup> setup;  ///< the set-up of the sources overload (its report needs it)
};
ResolvedRun resolveAndRunPass(const SlrSetup& setup, const PassData& pass, Feedback* fb = nullptr);
/// The same from the sources a front end gathered (Python's run): setUpSlrRun, then the above.
ResolvedRun resolveAndRunPass(const SlrSources& sources, const PassData& pass, Feedback* fb = nullptr);

/// The filter flags a screened pass is delivered with: what the post-fit kept (its rejects are
/// noise), else what the screening accepted. Every flagged-CRD product uses them.
const std::vector<uint8_t>& deliveredFlags(const PassRunResult& r);

struct PassReport;

/// Where a pass's products go ("" = not written).
struct PassProductPaths {
    std::string csv, crd, npt;
    /// crd: the whole file the pass came from, other passes unchanged (laserwb-cli slr --crd-out),
    /// or the pass alone (passAlone: a batch's passNNN.frd, the workbench's "this pass").
    bool crdWholeFile = false;
    /// The one-page PDF report (pass_report.hpp), drawn from `reportOf` (required with `report`).
    std::string report;
    const PassReport* reportOf = nullptr;
};

/// The products a run can write for these settings: "" or why not (a usage error: normal points
/// asked for when neither the bin length nor the altitude is known; a CRD product of an O-C table).
std::string productsProblem(const PassData& pass, const PassSettings& settings, const PassProductPaths& paths);

/// Writes the products of a pass into `outs`' staging files (the caller registered and checked
/// them and commits the set): the per-point CSV, the flagged CRD (deliveredFlags), the normal
/// points (or the reason there are none) and the PDF report. *npBlock (when given) gets the normal-point block for a
/// day's file. False with *error (naming the file).
bool stagePassProducts(const OutputSet& outs, const PassData& pass, const PassRunResult& r, const PassProductPaths& paths,
                       CrdPass* npBlock, std::string* error);

/// A screened pass as a front end holds it: what its products, its report and their provenance
/// are written from. Every pointer is required.
struct ScreenedPass {
    const SlrSetup* setup = nullptr;         ///< the run's set-up: the provenance's, the report's command
    /// The sources the pass was opened with when they are not the run's (Python's load_pass with a
    /// prediction, then run): the report names that prediction. Null: setup->sources.
    const SlrSources* openedWith = nullptr;
    const PassData* pass = nullptr;
    const PassSettings* settings = nullptr;  ///< the parameters it ran with
    const PassRunResult* result = nullptr;
    std::vector<std::string> notes;          ///< what opening it said, warnings first (the report's)
    /// Points forced in or out by hand (the workbench's edits): said in the report and recorded
    /// in the provenance, since the command it records does not make them.
    long long forcedByHand = 0;
};

/// The files a run of `paths` writes: each product, and beside each file its provenance sidecar
/// (F.provenance.json; a product to standard output has none). What a front end registers.
std::vector<std::string> passOutputFiles(const PassProductPaths& paths);
/// The products of `paths` that are files (not standard output): the ones a sidecar lists.
std::vector<std::string> passProductFiles(const PassProductPaths& paths);

/// The provenance of a one-pass run's products: slrProvenance with the pass's own parameters
/// (its preset and context applied) and, when there are any, the points forced by hand.
Provenance passProvenance(const SlrSetup& setup, const PassSettings& settings, long long forcedByHand = 0);

/// The whole writing of a screened pass, the one every front end uses (the CLI's outputs, the
/// workbench's exports, Python's write): the report built when asked for (passReportOfLoaded, with
/// the station's normal points `stationNp`, "" = the set-up's), the products checked
/// (productsProblem: a usage error), staged (stagePassProducts) and each file's provenance staged
/// beside it (passProvenance). The caller registered passOutputFiles(paths) in `outs` and commits.
/// False with *error.
bool stageScreenedPass(OutputSet& outs, const ScreenedPass& s, const PassProductPaths& paths, const std::string& stationNp,
                       SlrError* error);
/// stageScreenedPass into files of its own, all or nothing: the outputs and the run's inputs
/// registered and checked (none may replace an input or another output), staged, committed.
/// False with *error and nothing written (Python's write, the workbench's exports).
bool writeScreenedPass(const ScreenedPass& s, const PassProductPaths& paths, const std::string& stationNp, SlrError* error);

/// The provenance of a run's outputs (core/common/provenance.hpp): the command ("slr", or "slr
/// --all-passes" for a station's file), the parameters before any pass's preset and context
/// (setup.base; a one-pass run replaces them with the pass's own), the settings that shape the
/// outputs and the inputs. Every front end records the same.
Provenance slrProvenance(const SlrSetup& setup, bool stationFile);

/// "FILE pass K" (CRD) or "FILE" (O-C table): how messages name a pass.
std::string passName(const PassData& pass);

/// The laserwb-cli arguments that run pass `passNumber` (1-based; 0: none given) of the sources'
/// input with `params`: every field that differs from the schema's default as --set KEY=VALUE
/// (the value as --set reads it back exactly), the prediction (with --cpf-fallback when the
/// sources fall back, as the workbench reads it), the station file and the station's normal
/// points when given. Without the program's name and the outputs: the report's command and the
/// workbench's Edit ▸ Copy as command line (issue 42), from the one SlrSources.
std::vector<std::string> slrCommandArgs(const SlrSources& sources, int passNumber, const SlrParams& params);
/// The parameters a command that reruns `pass` needs to be given: `resolved` with every post-fit
/// field the pass tells itself (its altitude, the C1 fire rate, the ILRS bin, the station's
/// position: passNormalPointContext) put back to the default where it holds the value the pass
/// tells, so that the rerun says those notes again instead of taking them as the analyst's.
SlrParams commandParams(const SlrSetup& setup, const PassData& pass, const SlrParams& resolved);

/// Arguments as a POSIX shell reads them back: each single-quoted unless it is plain.
std::string shellCommand(const std::vector<std::string>& args);
/// The same run as a Python script of the laserwb module (Edit ▸ Copy as Python): load_pass with
/// the prediction and stations, run with every field that differs from the schema's default (the
/// value as --set reads it, a number bare, other values quoted), then writing the products to
/// screened.csv (and, for a CRD pass, passNumber > 0, its normal points to pass.npt) in the
/// working folder; with the station's normal points, the report (pass_report.pdf) that compares
/// them. The sources' cpf is left out when `withCpf` is false (a prediction the pass did not use).
std::string slrPythonScript(const SlrSources& sources, int passNumber, const SlrParams& params, bool withCpf = true);

}  // namespace lwb::core::slr
