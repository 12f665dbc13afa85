// laserwb-cli slr: screen one SLR pass (paper 004 binary image, automatic mode by default),
// post-fit with k-sigma rejection and ILRS normal points; per-point CSV, CRD full rate with
// filter flags and CRD normal points. The loading is core/slr/pass_input.hpp, the writing
// core/slr/pass_output.hpp: the layer the SLR workspace of the GUI uses too.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <cerrno>
#include <cstring>
#include <exception>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_batch.hpp"
#include "cli_commands.hpp"
#include "cli_common.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/parallel.hpp"
#include "core/common/text.hpp"
#include "core/slr/np_context.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_output.hpp"
#include "core/slr/pass_report.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/slr_run.hpp"
#include "core/slr/station_day.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/slr_params.hpp"
#include "core/slr/screen.hpp"
#include "core/slr/screen_auto.hpp"

namespace lwb::cli {

namespace slr = core::slr;

namespace {

const std::string kSlrUsage = std::string(
    "usage: laserwb-cli slr INPUT [options] [-o OUT.csv] [--crd-out FILE] [--npt-out FILE] [--report-out FILE.pdf]\n"
    "                        (no output: the summary alone, nothing written)\n"
    "       laserwb-cli slr --all-passes --out-dir DIR [options] CRD...\n"
    "       laserwb-cli slr tune CRD... --preset-out FILE.json  (parameters from the station's flags: slr tune --help)\n"
    "Screens one SLR pass: signal extraction by binary image (paper 004; automatic scale by default),\n"
    "then a trend fit with k-sigma rejection and ILRS normal points. A summary goes to stderr.\n"
    "INPUT: a CRD file (v1 or v2; recognised by its H1 record, whatever the name) or an O-C CSV\n"
    "       (header with epoch_s,oc_s; epoch in s, O-C in s of two-way time of flight).\n"
    "  --cpf FILE --stations SINEX   O-C of a CRD pass from this CPF prediction and these station\n"
    "                        coordinates (--cpf needs --stations); without --cpf, O-C against a robust\n"
    "                        trend of the pass's own time of flight (a range bias and a smooth drift\n"
    "                        are absorbed). --stations alone: the station's position for day or night\n"
    "                        (the Sun's elevation per normal-point bin: at least 6 points by day, 3 by\n"
    "                        night); without it a CRD pass gets the day minimum of 6\n"
    "  --cpf-fallback        a CPF that does not fit the pass (another satellite, a span that misses\n"
    "                        it): O-C against the pass's own TOF trend with a warning, as the workbench\n"
    "                        and --all-passes do (default: an error)\n"
    "  --pass K              pass number in the CRD file, 1-based (1 = the first block of the file);\n"
    "                        default: the first pass to screen. The station's own normal points,\n"
    "                        sampled engineering data (H4 data type 2) and blocks of fewer than 5\n"
    "                        full-rate records are not passes: --pass K on one says so (exit 2)\n"
    "  --all-passes --out-dir DIR   a station's file of passes (a day's): every block of the CRD\n"
    "                        file with the same options. Per screened pass DIR/passNNN.csv (as -o),\n"
    "                        passNNN.frd (its full-rate block, flags 2 kept by the post-fit, 1 noise\n"
    "                        or rejected) and passNNN.npt (its normal points, or the reason there are\n"
    "                        none); DIR/normal_points.npt (every pass's normal points: the file a\n"
    "                        station sends) and DIR/summary.csv (one row per block: station,\n"
    "                        satellite, UTC start, duration, points, accepted, RMS, normal points,\n"
    "                        agreement with the station's flags, status and reason; with a CPF the\n"
    "                        range and time bias fitted to the kept O-C, with sigmas). Status: ok,\n"
    "                        no signal, doubtful, failed (the others go on), station normal points\n"
    "                        (the station's own type-11 block), skipped (sampled engineering data, or\n"
    "                        fewer than 5 records: the least a pass has, in every mode). --cpf may\n"
    "                        then be a folder: the CPF that fits each pass (satellite ids and time\n"
    "                        span) is picked; a pass no CPF fits is screened on its own TOF trend.\n"
    "                        Many CRD files (named, or --files-from): each file's products go to\n"
    "                        DIR/NAME/ (NAME: the file name without .gz and its extension); a file\n"
    "                        that fails does not stop the others\n"
"  --threads N           with --all-passes: passes screened side by side on N threads (default 0:\n"
"                        every core); the products are the same for any N\n"
    "Parameters (automatic screening by default; each option replaces only its own parameter; every\n"
    "parameter with its range and meaning: --help-params):\n"
    "  --config FILE.json    parameters (as --print-config writes them)\n"
    "  --set KEY=VALUE       one parameter (repeatable), e.g. --set screen.cosine_c=0.97\n"
    "  --print-config        print the effective parameters as JSON and exit\n"
    "  --help-params         every parameter with its unit, range, default and meaning\n"
    "  --mag-t X             pixels per second of epoch (paper table 1: 10 conventional, 1 diffuse)\n"
    "  --mag-oc Y            pixels per second of O-C (paper: 1e10 conventional, 1e7 diffuse)\n"
    "  --area-min N          area limit in pixels: regions at least this large are candidates\n"
    "  --connectivity 4|8    region connectivity (paper: 4 high echo rate, 8 low)\n"
    "  --cos-c C             cosine constant of the recovery step, 0.5..1 exclusive (default {default:screen.cosine_c})\n"
    "  --preset FILE         per-satellite presets (JSON, the workbench's format): the entry of the\n"
    "                        pass's satellite (CRD H3 name or ILRS id, or --satellite) is applied\n"
    "                        (screening and post-fit); options given here override it\n"
    "  --satellite NAME      look the preset up under NAME (a name or an ILRS id) instead of the\n"
    "                        pass's H3; needed for an O-C CSV, which names no satellite\n"
    "Post-fit:\n"
    "  --reject K            k of the k-sigma rejection: 2.5 (single-photon) or 3 (multi-photon);\n"
    "                        default {default:postfit.reject_sigma}; any value 1..10, 0 = off\n"
    "  --np-bin S            normal-point bin length in s (default: the ILRS length for the\n"
    "                        satellite's altitude; an O-C CSV has no altitude: no normal points\n"
    "                        unless --np-bin or a preset's altitude_km is given)\n"
    "Outputs (none: the summary alone; each written whole or not at all; nothing when the run fails):\n"
    "  -o, --output OUT.csv  one row per input point, in input order:\n"
    "                        index,epoch_s,oc_s,class,region,residual_s,kept,station_flag\n"
    "                        index: 0-based row of the O-C CSV, or type-10 record of the CRD pass;\n"
    "                        class: signal | recovered | noise; residual_s: O-C minus the post-fit\n"
    "                        trend; kept: 1 when in the final post-fit; station_flag: the CRD's own\n"
    "                        filter flag (0 unknown, 1 noise, 2 data), empty for a CSV\n"
    "  --crd-out FILE        the CRD file with this pass's filter flags set as delivered: 2 kept by\n"
    "                        the post-fit (without one: accepted by the screening), 1 noise or\n"
    "                        rejected; other passes unchanged (--all-passes: the same flags)\n"
    "  --npt-out FILE        the normal points as a CRD normal-point file (the pass's headers); with\n"
    "                        none (no signal, no bin full enough, a doubtful pass) the file holds the\n"
    "                        reason as a comment record '00 no normal points: ...' in their place\n"
    "                        (--crd-out and --npt-out need a CRD input)\n"
    "  --report-out FILE.pdf a one-page PDF report for the station log: O-C with the screening's\n"
    "                        classes, post-fit residuals and normal-point bins, binary image,\n"
    "                        histogram, parameters, normal points, provenance and this command\n"
    "                        (the workbench's File > Report... writes the same)\n"
    "  --station-np FILE     the station's own normal points of the pass (a CRD normal-point file):\n"
    "                        compared with ours bin by bin in the report and the summary, as the\n"
    "                        workbench's Station normal points tab compares them\n"
    "  Provenance: each output file F gets F.provenance.json beside it, and --out-dir DIR gets\n"
    "                        DIR/provenance.json: version, parameters, settings, SHA-256 of every\n"
    "                        input and output\n"
    "  -q, --quiet           no summary and no warnings on stderr (errors still)\n") +
    kBatchOptionsHelp + "  (--shard with --all-passes: a share of the files)\n"
    "Exit codes: 0 done (\"no signal found\" is a result), 1 bad input or failed run (nothing\n"
    "written), 2 usage error, 3 written but doubtful: the accepted points cannot be told from noise,\n"
    "no scale shows a track, or two parallel tracks were merged (the classes are written, no normal\n"
    "points; --all-passes: some pass is doubtful), 4 --all-passes wrote its outputs but some passes\n"
    "failed (summary.csv says why); with many files: 4 when some files failed or had passes that\n"
    "failed, 1 when all failed.\n";

std::string passList(const std::vector<slr::PassSummary>& passes) {
    std::string s;
    for (const auto& p : passes) {
        s += "\n  " + std::to_string(p.index + 1) + ": " + (p.satellite.empty() ? "?" : p.satellite) + " " + p.start +
             " .. " + p.end + ", " + std::to_string(p.ranges) + " full-rate, " + std::to_string(p.normalPoints) +
             " normal-point records";
    }
    return s;
}


// The command's defaults (the core's, with the multi-photon rejection of 3 sigma): Python's too.
slr::SlrParams cliDefaults() { return slr::commandDefaults(); }

std::string ps(double s) { return core::formatFixed(s * 1e12, 1) + " ps"; }
std::string f4(double v) { return std::isfinite(v) ? core::formatFixed(v, 4) : std::string(); }

// A precision of nothing accepted is 0/0: said so, not printed as 0 (summary.csv leaves it empty).
std::string precisionText(double v) { return std::isfinite(v) ? f4(v) : "undefined (nothing accepted)"; }

// The sources of a run of `input`, gathered from the options (the core reads and resolves
// them: core/slr/slr_run.hpp). kOk, or the exit code after saying why.
int gatherSources(const std::string& cmd, const Args& a, const ParamOptions<slr::SlrParams>& params,
                  const std::string& input, long long passK, slr::SlrSources* out) {
    slr::SlrSources s;
    s.input = input;
    s.passNumber = static_cast<int>(passK);
    s.cpf = a.value("--cpf");
    s.cpfFallback = a.has("--cpf-fallback");
    s.stations = a.value("--stations");
    s.stationNormalPoints = a.value("--station-np");
    s.presets = a.value("--preset");
    s.satellite = a.value("--satellite");
    s.configFile = a.value("--config");
    std::string err;
    if (!params.settings(a, &s.set, &err)) return fail(cmd, err, kUsage);
    *out = std::move(s);
    return kOk;
}

int failed(const std::string& cmd, const slr::SlrError& e) { return fail(cmd, e.message, e.usage ? kUsage : kFailed); }

void printSummary(const std::string& what, const slr::PassData& pass, const slr::PassSettings& settings,
                  const slr::PassRunResult& r) {
    const slr::ScreenResult& s = r.screen;
    const slr::PostfitResult& post = r.post;
    const slr::PostfitParams& pp = settings.params.postfit;
    for (const auto& w : s.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";
    if (!r.postOk && !r.postNote.empty()) std::cerr << "laserwb-cli slr: warning: " << r.postNote << "\n";
    if (r.postOk)
        for (const auto& w : post.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";
    auto mark = [](bool automatic) { return automatic ? " (auto)" : ""; };
    std::cerr << "slr: " << what;
    if (!pass.satellite.empty()) std::cerr << " (" << pass.satellite << (pass.station.empty() ? "" : " from " + pass.station) << ")";
    std::cerr << ": O-C from " << pass.ocOrigin << (settings.presetName.empty() ? "" : "; preset " + settings.presetName) << "\n"
              << "  points " << pass.t.size() << ", accepted " << r.acceptedCount << " (" << s.signalPoints << " signal + "
              << s.recoveredPoints << " recovered"
              << (r.bandTaken ? " + " + std::to_string(r.bandTaken) + " within the post-fit's band" : std::string())
              << "), noise " << pass.t.size() - r.acceptedCount << "\n"
              << "  scale: mag_T " << core::formatDouble(s.magT, 4) << mark(s.autoMagT) << ", mag_OC "
              << core::formatDouble(s.magOc, 4) << mark(s.autoMagOc) << ", area limit " << s.areaLimit << mark(s.autoArea)
              << ", connectivity " << s.connectivity << mark(s.autoConnectivity) << ", C "
              << core::formatDouble(settings.params.screen.cosineC, 4);
    if (!s.trials.empty()) std::cerr << "; " << s.trials.size() << " scales tried";
    std::cerr << "\n";
    if (s.floorless)
        std::cerr << "  no noise floor (robust sigma " << ps(s.floorSigmaS) << ", "
                  << core::formatFixed(100 * s.floorBeyond, 2) << " % beyond 5 sigma): a filtered pass; "
                  << s.floorlessAdded << " points within 5 sigma of its track accepted beyond the image's\n";
    if (r.postOk) {
        std::cerr << "  post-fit: degree " << post.degree << ", " << core::formatDouble(pp.rejectSigma, 3)
                  << "-sigma rejection removed " << post.rejected << " of " << post.used << ", RMS "
                  << ps(post.stats.rms) << " (" << core::formatFixed(post.stats.rms * 0.5 * 299792458.0 * 1e3, 1)
                  << " mm one-way)\n";
        if (std::isfinite(post.noiseBandS))
            std::cerr << "  band narrowed by the noise beside it (" << core::formatDouble(post.noiseDensity * 1e-9, 3)
                      << " points per ns): +-" << ps(post.noiseBandS) << " = "
                      << core::formatFixed(post.noiseBandS / post.signalSigmaS, 2) << " sigma of the signal's "
                      << ps(post.signalSigmaS) << ", the band of the best expected F1\n";
        if (post.normalPoints.empty() && !r.postNote.empty())
            std::cerr << "  " << r.postNote << "\n";
        else
            std::cerr << "  normal points: " << post.normalPoints.size() << " (bins of "
                      << core::formatDouble(post.binLengthS, 4) << " s, at least " << post.minPointsPerBin << " points"
                      << (post.dayBins + post.nightBins ? " (" + std::to_string(post.dayBins) + " day, " +
                                                              std::to_string(post.nightBins) + " night bins)"
                                                        : std::string(pp.dayNight == slr::PostfitParams::DayNight::Night
                                                                          ? " (night)"
                                                                          : pp.dayNight == slr::PostfitParams::DayNight::Day
                                                                                ? " (day)"
                                                                                : " (day: day or night unknown)"))
                      << (post.binsTooSmall ? ", " + std::to_string(post.binsTooSmall) + " bins too small" : "") << ")\n";
        if (!post.normalPoints.empty() && !r.postNote.empty()) std::cerr << "  " << r.postNote << "\n";
        for (const auto& note : settings.notes) std::cerr << "  " << note << "\n";
    }
    if (r.bias.ok) std::cerr << "  against the prediction: " << slr::describeBias(r.bias) << "\n";
    const slr::StationAgreement& g = r.agreement;
    if (g.available) {
        std::cerr << "  against the station's filter flags (" << g.data << " data, " << g.noise << " noise): screening precision "
                  << precisionText(g.precision) << ", recall " << f4(g.recall);
        if (r.postOk) std::cerr << "; after post-fit precision " << precisionText(g.keptPrecision) << ", recall " << f4(g.keptRecall);
        std::cerr << "\n";
    } else if (g.data > 0) {
        std::cerr << "  the station's filter flags are incomplete (some 0 = unknown): no comparison\n";
    }
}

}  // namespace

// What one slr run reads and writes, from its options (cmdSlr's first stage).
struct SlrPlan {
    std::vector<std::string> inputs;  ///< the files named and listed (--files-from)
    std::string input, out, crdOut, nptOut, reportOut, outDir;
    bool allPasses = false, csvInput = false;
    long long passK = 0;  ///< --pass K (1-based), 0 when not given
    long long threads = 0;  ///< --threads (--all-passes), 0 = every core
};

// The usage checks of cmdSlr (exit 2, nothing read or written): the input and outputs, the
// options that go together, the parameters; the outputs are registered in *outs and checked
// (single pass). -1 to go on, else the exit code.
int planSlrRun(const std::string& cmd, const Args& a, const ParamOptions<slr::SlrParams>& params, SlrPlan* pl,
               core::OutputSet* outs) {
    // ---- usage checks (exit 2, nothing read or written) ----
    pl->allPasses = a.has("--all-passes");
    const bool allPasses = pl->allPasses;
    if (pl->inputs.empty()) return fail(cmd, "no input file", kUsage);
    if (pl->inputs.size() != 1 && !allPasses)
        return fail(cmd, "give exactly one input file (many files: --all-passes --out-dir DIR)", kUsage);
    if (a.has("--shard") && !allPasses) return fail(cmd, "--shard goes with --all-passes (a share of many files)", kUsage);
    pl->input = pl->inputs[0];
    const std::string& input = pl->input;
    if (a.has("-o") && a.has("--output")) return fail(cmd, "give -o or --output, not both", kUsage);
    pl->outDir = a.value("--out-dir");
    const std::string& outDir = pl->outDir;
    if (allPasses) {
        if (outDir.empty()) return fail(cmd, "--all-passes needs --out-dir DIR (each pass's CSV and summary.csv go there)", kUsage);
        for (const char* o : {"-o", "--output", "--crd-out", "--npt-out", "--report-out", "--pass", "--station-np"})
            if (a.has(o)) return fail(cmd, std::string(o) + " is for one pass; --all-passes writes DIR/passNNN.csv and DIR/summary.csv", kUsage);
    } else if (!outDir.empty() || a.has("--threads")) {
        return fail(cmd, std::string(outDir.empty() ? "--threads" : "--out-dir") + " goes with --all-passes", kUsage);
    }

    pl->out = a.has("-o") ? a.value("-o") : a.value("--output");
    const std::string& out = pl->out;
    pl->crdOut = a.value("--crd-out");
    pl->nptOut = a.value("--npt-out");
    pl->reportOut = a.value("--report-out");
    // (no output asked for: the run prints its summary and writes nothing)
    if (core::isStandardStream(pl->reportOut))
        return fail(cmd, "--report-out needs a file (a PDF is not written to standard output)", kUsage);
    const std::string &crdOut = pl->crdOut, &nptOut = pl->nptOut, &reportOut = pl->reportOut;
    // Every output is checked before anything is computed or written: none may replace an
    // input or another output (same device and inode, whatever the spelling), devices and
    // folders are refused, and all are renamed into place together at the end.
    for (const char* in : {"--cpf", "--stations", "--preset", "--station-np"}) outs->addInput(a.value(in));
    outs->addInput(input);
    for (const std::string& o : slr::passOutputFiles({out, crdOut, nptOut, true, reportOut}))  // (each file's provenance beside it)
        outs->addOutput(o);
    if (!allPasses)
        if (int rc = checkOutputs(cmd, *outs)) return rc;
    if (a.has("--cpf") && !a.has("--stations"))
        return fail(cmd, "--cpf and --stations go together (O-C from the prediction needs both)", kUsage);
    if (a.has("--satellite") && !a.has("--preset"))
        return fail(cmd, "--satellite selects a preset entry; give --preset FILE with it", kUsage);
    std::string err;
    if (!a.getInt("--pass", 1, 1000000, &pl->passK, &err) || !a.getInt("--threads", 0, 256, &pl->threads, &err))
        return fail(cmd, err, kUsage);
    {  // Bad options and config are usage errors before anything is read (the core's check).
        slr::SlrSources sources;
        if (int rc = gatherSources(cmd, a, params, input, pl->passK, &sources)) return rc;
        slr::SlrParams probe;
        slr::SlrError e;
        if (!slr::resolveBaseParams(sources, &probe, &e)) return failed(cmd, e);
    }
    if (pl->inputs.size() > 1) return -1;  // (each file is looked at when its turn comes)
    // A folder or a missing path is neither a CRD file nor an O-C table (it was called "an O-C
    // table" when a CRD output or --all-passes was asked for).
    if (struct stat st {}; !core::isStandardStream(input) && (::stat(input.c_str(), &st) != 0 || S_ISDIR(st.st_mode)))
        return fail(cmd, input + (::stat(input.c_str(), &st) != 0
                                      ? ": no such file"
                                      : std::string(": is a folder, not a file") +
                                            (allPasses ? " (--all-passes takes several files: give them, or --files-from)" : "")),
                    kFailed);
    pl->csvInput = !slr::isCrdFile(input);
    const bool csvInput = pl->csvInput;
    if (csvInput && (!crdOut.empty() || !nptOut.empty()))
        return fail(cmd,
                    std::string(!crdOut.empty() ? "--crd-out" : "--npt-out") +
                        " needs a CRD input (its headers and records are written back); " + input +
                        " is an O-C table",
                    kUsage);
    if (csvInput && (a.has("--cpf") || a.has("--pass")))
        return fail(cmd, std::string(a.has("--cpf") ? "--cpf/--stations" : "--pass") + " apply to a CRD input; " +
                             input + " is an O-C table",
                    kUsage);
    if (csvInput && allPasses) return fail(cmd, "--all-passes needs a CRD input; " + input + " is an O-C table (one pass)", kUsage);

    return -1;
}

int runSlr(const std::string& cmd, const Args& a, const ParamOptions<slr::SlrParams>& params, const BatchOptions& bo,
           RunSummary& summary);

int cmdSlr(int argc, char** argv) {
    if (argc > 2 && std::string(argv[2]) == "tune") return cmdSlrTune(argc, argv);  // (a file named tune: ./tune)
    const std::string cmd = "slr";
    Args a(cmd, kSlrUsage);
    // Every screening and post-fit parameter: slr_params.hpp's schema; the named options are
    // aliases of --set with the schema's ranges.
    const ParamOptions<slr::SlrParams> params(slr::slrSchema(), {{"--mag-t", "screen.mag_t"},
                                                                 {"--mag-oc", "screen.mag_oc"},
                                                                 {"--area-min", "screen.area_limit"},
                                                                 {"--connectivity", "screen.connectivity"},
                                                                 {"--cos-c", "screen.cosine_c"},
                                                                 {"--reject", "postfit.reject_sigma"},
                                                                 {"--np-bin", "postfit.bin_length_s"}});
    params.declare(a);
    for (const char* o : {"--cpf", "--stations", "--satellite", "--preset", "--pass", "-o", "--output", "--crd-out", "--npt-out",
                          "--report-out", "--out-dir", "--threads", "--station-np"})
        a.option(o, true);
    declareBatchOptions(a);
    for (const char* o : {"--quiet", "-q", "--help", "-h", "--help-params", "--all-passes", "--cpf-fallback"}) a.option(o, false);
    if (!a.parse(argc, argv, 2)) return fail(cmd, a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << a.usage();  // (its defaults filled from the schema by declare)
        return kOk;
    }
    if (a.has("--help-params")) {
        std::cout << "slr parameters (key = default unit  valid range):\n" << slr::slrSchema().describe(cliDefaults());
        return kOk;
    }
    if (params.printRequested(a)) {  // the defaults with --config and the options applied (no preset: it needs the pass)
        slr::SlrSources sources;
        if (int rc = gatherSources(cmd, a, params, "", 0, &sources)) return rc;
        slr::SlrParams p;
        slr::SlrError e;
        if (!slr::resolveBaseParams(sources, &p, &e)) return failed(cmd, e);
        std::cout << params.json(p);
        return kOk;
    }
    BatchOptions bo;
    const int loaded = loadBatchOptions(cmd, a, &bo);
    RunSummary summary(cmd, bo);
    if (loaded) return summary.finish(loaded);
    return summary.finish(runSlr(cmd, a, params, bo, summary));
}

namespace {
// An --all-passes input's folder name when there are many: its file name without ".gz" and
// without its last extension ("7810_lageos1_crd_20240101_00_00.frd.gz" -> "..._00_00").
// True when `path` lies in `folder` (absolute, . and .. resolved, links of what exists followed).
bool isInside(const std::string& path, const std::string& folder) {
    std::error_code ec;
    auto norm = [&](const std::string& p) {
        return std::filesystem::weakly_canonical(std::filesystem::absolute(p, ec), ec).lexically_normal().string();
    };
    std::string f = norm(folder);
    if (f.empty() || f.back() != '/') f += '/';
    return norm(path).rfind(f, 0) == 0;
}

std::string stemOf(const std::string& path) {
    std::string n = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
    if (n.size() > 3 && n.compare(n.size() - 3, 3, ".gz") == 0) n.resize(n.size() - 3);
    if (const size_t dot = n.find_last_of('.'); dot != std::string::npos && dot > 0) n.resize(dot);
    return n;
}

// One file's --all-passes run (core runStationDay): progress on stderr, the summary line.
int screenAllPasses(const std::string& cmd, const slr::SlrSetup& setup, const std::string& dir, int threads, bool quiet) {
    slr::DayOptions opt;
    opt.outDir = dir;
    opt.threads = threads;
    std::unique_ptr<Progress> progress;
    size_t done = 0;
    slr::DayObserver obs;
    obs.begin = [&](size_t n) { progress = std::make_unique<Progress>("slr", n, quiet); };
    obs.row = [&](const slr::DayRow&) { progress->update(++done); };
    const slr::DayResult r = slr::runStationDay(setup, opt, obs);
    if (!r.ok) return failed(cmd, r.error);
    if (progress) progress->finish();
    const size_t n = r.rows.size();
    if (!quiet)
        std::cerr << "slr: " << setup.sources.input << ": " << n << " blocks: " << r.screened << " screened, " << r.doubtful
                  << " doubtful, " << r.failed << " failed, " << r.stationNormalPoints << " station normal points, "
                  << r.skipped << " skipped -> " << dir << "/ (summary.csv" << (r.dayNormalPoints ? ", normal_points.npt" : "")
                  << ")\n";
    if (r.failed == 0 && r.doubtful == 0) return kOk;
    // (said even with -q: a partial or doubtful result is not a success)
    std::cerr << "laserwb-cli slr: " << r.failed << " of " << n << " passes failed and " << r.doubtful << " are doubtful ("
              << dir << "/summary.csv says why); exit " << (r.failed ? kSomeFailed : kDoubtful) << "\n";
    return r.failed ? kSomeFailed : kDoubtful;
}

// --all-passes over the inputs of this shard: one file's products in --out-dir, or with many
// files each file's in DIR/<its name>/; a file that fails does not stop the others.
int allPassFiles(const std::string& cmd, const SlrPlan& plan, const slr::SlrSetup& setup,
                 const BatchOptions& bo, RunSummary& summary, bool quiet) {
    const std::vector<std::string>& inputs = plan.inputs;
    const bool many = inputs.size() > 1;
    std::vector<std::string> dirs;
    std::map<std::string, std::string> seen;
    for (const auto& f : inputs) {
        if (!many) {
            dirs.push_back(plan.outDir);
            continue;
        }
        // The file's name as a folder inside --out-dir: never ".", "..", or hidden ("...frd" named
        // "..", and the run wrote into the out-dir's parent).
        std::string name = stemOf(f);
        for (char& c : name)
            if (c != '.') break;
            else c = '_';
        if (name.empty()) name = "_";
        if (auto [it, fresh] = seen.emplace(name, f); !fresh)
            return fail(cmd, f + " and " + it->second + " would both write " + plan.outDir + "/" + name + "/ (rename one)", kUsage);
        dirs.push_back(plan.outDir + "/" + name);
    }
    // The whole plan before any work: no input inside a folder this run writes (the second file
    // of `--out-dir OUT day.frd OUT/day/pass001.frd` was overwritten by the first's flagged CRD),
    // and the summary's file none of the run's.
    for (const auto& in : inputs)
        for (size_t j = 0; many && j < dirs.size(); ++j)  // (one file: its outputs are checked by name)
            if (isInside(in, dirs[j]))
                return fail(cmd, in + " lies in " + dirs[j] + "/, which the products of " + inputs[j] +
                                     " are written into; nothing run (give another --out-dir)",
                            kUsage);
    // (a day's folder: summary.csv, normal_points.npt, provenance.json, passNNN.csv/.frd/.npt)
    std::vector<std::string> made = dirs;
    made.push_back(plan.outDir);
    if (int rc = summary.checkTarget({}, made, [](const std::string& n) {
            if (n == "summary.csv" || n == "normal_points.npt" || n == "provenance.json") return true;
            if (n.size() < 8 || n.rfind("pass", 0) != 0) return false;
            const size_t dot = n.find('.');
            if (dot == std::string::npos || dot == 4) return false;
            for (size_t i = 4; i < dot; ++i)
                if (!std::isdigit(static_cast<unsigned char>(n[i]))) return false;
            const std::string ext = n.substr(dot);
            return ext == ".csv" || ext == ".frd" || ext == ".npt";
        }))
        return rc;
    summary.setInputsTotal(inputs.size());
    const auto [first, last] = bo.shard.range(inputs.size());
    if (many && first < last) ::mkdir(plan.outDir.c_str(), 0777);  // (each file's folder is made by its run)
    size_t failedFiles = 0, partial = 0, doubtful = 0, run = 0;
    for (size_t i = first; i < last; ++i) {
        core::Json e = core::Json::object();
        e["input"] = inputs[i];
        e["outputs"] = core::Json::array({dirs[i]});
        slr::SlrSetup one = setup;
        one.sources.input = inputs[i];
        const core::Provenance p = slr::slrProvenance(one, true);  // (what its run records)
        std::string why;
        if (bo.skipExisting && outputsComplete(p, {}, dirs[i] + "/provenance.json", &why)) {
            e["status"] = "skipped";
            summary.addInput(e);
            if (!quiet) std::cerr << "slr: " << inputs[i] << ": " << dirs[i] << "/ is complete: skipped\n";
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const int rc = screenAllPasses(cmd, one, dirs[i], static_cast<int>(plan.threads), quiet);
        ++run;
        e["status"] = rc == kOk ? "ok" : rc == kDoubtful ? "doubtful" : rc == kSomeFailed ? "some passes failed" : "failed";
        e["exit_code"] = rc;
        if (rc != kOk && rc != kDoubtful) e["error"] = lastFailure();
        e["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        summary.addInput(e);
        if (!many) return rc;
        (rc == kDoubtful ? doubtful : rc == kSomeFailed ? partial : rc != kOk ? failedFiles : run)++;
    }
    if (!many) return kOk;  // (the one file is another shard's)
    if (failedFiles || partial) {
        std::cerr << "laserwb-cli slr: " << failedFiles << " of " << (last - first) << " files failed, " << partial
                  << " had passes that failed (--summary-json, each folder's summary.csv say why)\n";
        return failedFiles == last - first ? kFailed : kSomeFailed;
    }
    return doubtful ? kDoubtful : kOk;
}
}  // namespace

int runSlr(const std::string& cmd, const Args& a, const ParamOptions<slr::SlrParams>& params, const BatchOptions& bo,
           RunSummary& summary) {
    const bool quiet = a.has("--quiet") || a.has("-q");
    SlrPlan plan;
    plan.inputs = a.positional();
    plan.inputs.insert(plan.inputs.end(), bo.listed.begin(), bo.listed.end());
    core::OutputSet outs;
    if (int rc = planSlrRun(cmd, a, params, &plan, &outs); rc >= 0) return rc;
    const std::string &input = plan.input, &out = plan.out, &crdOut = plan.crdOut, &nptOut = plan.nptOut,
                      &reportOut = plan.reportOut;
    const bool allPasses = plan.allPasses;

    // ---- the sources, read once by the core (presets, stations, predictions, config) ----
    slr::SlrSources sources;
    if (int rc = gatherSources(cmd, a, params, input, plan.passK, &sources)) return rc;
    slr::SlrSetup setup;
    slr::SlrError e;
    if (!slr::setUpSlrRun(sources, &setup, &e)) return failed(cmd, e);
    // (--all-passes: the set-up read once for every file; each file's run records its provenance)
    if (allPasses) return allPassFiles(cmd, plan, setup, bo, summary, quiet);

    // ---- the pass: read, chosen (the first pass to screen unless --pass), resolved ----
    const slr::OpenedPass opened = slr::openPass(setup);
    if (!opened.ok) {
        std::string msg = opened.error.message;
        if (opened.passes.size() > 1) msg += "\nThe passes of the file (--pass K):" + passList(opened.passes);
        return fail(cmd, msg, opened.error.usage ? kUsage : kFailed);
    }
    const slr::PassData& pass = *opened.pass;
    const slr::PassSettings& settings = opened.settings;
    if (!quiet) {
        for (const auto& w : opened.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";
        for (const auto& n : opened.notes) std::cerr << "laserwb-cli slr: note: " << n << "\n";
    }
    const slr::PassProductPaths paths{out, crdOut, nptOut, true, reportOut};
    if (const std::string why = slr::productsProblem(pass, settings, paths); !why.empty()) return fail(cmd, why, kUsage);
    // The provenance the products will record (the pass's own parameters): with
    // --skip-existing, outputs whose sidecars say they are complete are not made again.
    const core::Provenance prov = slr::passProvenance(setup, settings);
    const std::vector<std::string> products = slr::passProductFiles(paths);
    core::Json entry = core::Json::object();
    entry["input"] = input;
    entry["outputs"] = products;
    for (const auto& n : products) summary.addOutput(n), summary.addOutput(core::provenancePathFor(n));
    {  // the summary's file is checked with the run's other outputs, before the run
        std::vector<std::string> planned;
        for (const auto& n : products) planned.push_back(n), planned.push_back(core::provenancePathFor(n));
        if (int rc = summary.checkTarget(planned)) return rc;
    }
    summary.setInputsTotal(1);
    if (bo.skipExisting && !products.empty()) {
        bool complete = true;
        for (const auto& n : products) complete = complete && outputsComplete(prov, products, core::provenancePathFor(n));
        if (complete) {
            entry["status"] = "skipped";
            summary.addInput(entry);
            if (!quiet) std::cerr << "slr: " << products.front() << " is complete: skipped\n";
            return kOk;
        }
    }
    const auto t0 = std::chrono::steady_clock::now();

    // ---- screening and post-fit ----
    const slr::PassRunResult r = slr::runOpenedPass(pass, settings, setup);
    const std::string what = slr::passName(pass);
    if (!r.ok) return fail(cmd, what + ": " + r.error);
    // A result that cannot be trusted (noise that no scale tells from a track, two tracks merged):
    // the points' classes are written, no normal points, exit 3 with the reason. No normal point
    // is a result, not a failure: every requested output is written, the NPT with the reason in
    // place of its records.
    const bool doubtful = !r.doubt.empty();
    const slr::DeliveredNormalPoints delivered = slr::deliveredNormalPoints(r);

    // ---- outputs: all or nothing (the writer every front end and batch uses) ----
    slr::ScreenedPass screened{&setup, nullptr, &pass, &settings, &r, opened.warnings};
    screened.notes.insert(screened.notes.end(), opened.notes.begin(), opened.notes.end());
    if (!slr::stageScreenedPass(outs, screened, paths, "", &e)) return failed(cmd, e);
    if (int rc = commitOutputs(cmd, outs)) return rc;
    entry["status"] = doubtful ? "doubtful" : "ok";
    entry["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    summary.addInput(entry);
    if (!quiet) {
        printSummary(what, pass, settings, r);
        if (setup.stationNormalPoints) {  // (the comparison the report and the Station NP tab make)
            const slr::NpComparison cmp =
                r.postOk ? slr::compareWithStation(pass, r.post, *setup.stationNormalPoints, setup.sources.stationNormalPoints)
                         : slr::NpComparison{};
            std::cerr << "  station normal points: "
                      << (cmp.ok ? cmp.describe() : cmp.error.empty() ? std::string("no post-fit: nothing to compare") : cmp.error)
                      << "\n";
        }
        std::string written;
        for (const std::string* o : {&out, &crdOut, &nptOut, &reportOut})
            if (!o->empty()) written += (written.empty() ? "" : ", ") + *o;
        std::cerr << "  -> " << (written.empty() ? "nothing written (-o, --crd-out, --npt-out, --report-out write the products)" : written)
                  << (nptOut.empty() || !delivered.points.empty() ? "" : " (" + nptOut + ": no normal points: " + delivered.noneReason + ")")
                  << "\n";
    }
    if (doubtful) {
        std::cerr << "laserwb-cli slr: doubtful: " << r.doubt << " (exit 3)\n";
        return kDoubtful;
    }
    return kOk;
}

}  // namespace lwb::cli
