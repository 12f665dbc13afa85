// laserwb-cli slr: screen one SLR pass (paper 004 binary image, automatic mode by default),
// post-fit with k-sigma rejection and ILRS normal points; per-point CSV, CRD full rate with
// filter flags and CRD normal points. The loading is core/slr/pass_input.hpp, the writing
// core/slr/pass_output.hpp: the layer the SLR workspace of the GUI uses too.
#include <algorithm>
#include <chrono>
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
#include "core/slr/pass_run.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/slr_params.hpp"
#include "core/slr/screen.hpp"
#include "core/slr/screen_auto.hpp"

namespace lwb::cli {

namespace slr = core::slr;

namespace {

const std::string kSlrUsage = std::string(
    "usage: laserwb-cli slr INPUT [options] [-o OUT.csv] [--crd-out FILE] [--npt-out FILE] (at least one)\n"
    "       laserwb-cli slr --all-passes --out-dir DIR [options] CRD...\n"
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
    "  --pass K              pass number in the CRD file, 1-based (1 = the first pass of the file);\n"
    "                        default: the first pass with full-rate (type 10) records\n"
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
    "Outputs (at least one; each written whole or not at all; nothing is written when the run fails):\n"
    "  -o, --output OUT.csv  one row per input point, in input order:\n"
    "                        index,epoch_s,oc_s,class,region,residual_s,kept,station_flag\n"
    "                        index: 0-based row of the O-C CSV, or type-10 record of the CRD pass;\n"
    "                        class: signal | recovered | noise; residual_s: O-C minus the post-fit\n"
    "                        trend; kept: 1 when in the final post-fit; station_flag: the CRD's own\n"
    "                        filter flag (0 unknown, 1 noise, 2 data), empty for a CSV\n"
    "  --crd-out FILE        the CRD file with this pass's filter flags set: 2 accepted by the\n"
    "                        screening (signal or recovered), 1 noise; other passes unchanged\n"
    "  --npt-out FILE        the normal points as a CRD normal-point file (the pass's headers); with\n"
    "                        none (no signal, no bin full enough, a doubtful pass) the file holds the\n"
    "                        reason as a comment record '00 no normal points: ...' in their place\n"
    "                        (--crd-out and --npt-out need a CRD input)\n"
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

// Prefixes the input file to a message that does not name it already.
std::string named(const std::string& path, const std::string& msg) {
    if (msg.rfind(path, 0) == 0) return msg;
    return path + ": " + msg;
}

// The command's defaults (the core's, with the multi-photon rejection of 3 sigma): Python's too.
slr::SlrParams cliDefaults() { return slr::commandDefaults(); }

std::string ps(double s) { return core::formatFixed(s * 1e12, 1) + " ps"; }
std::string f4(double v) { return std::isfinite(v) ? core::formatFixed(v, 4) : std::string(); }

// A precision of nothing accepted is 0/0: said so, not printed as 0 (summary.csv leaves it empty).
std::string precisionText(double v) { return std::isfinite(v) ? f4(v) : "undefined (nothing accepted)"; }

// What every pass of a run shares: the presets, the station file and the options.
struct RunInputs {
    const std::vector<slr::SatellitePreset>& presets;
    bool havePresets;
    std::string satellite;
    const slr::SinexFile* stations;
    const ParamOptions<slr::SlrParams>* options;
    const Args* args;
};

// The parameters of one pass: defaults, its preset and normal-point context, then the options.
int settingsFor(const std::string& cmd, const slr::PassData& pass, const RunInputs& ri, slr::PassSettings* out) {
    std::string err;
    if (!slr::passSettings(pass, cliDefaults(), ri.havePresets ? &ri.presets : nullptr, ri.satellite, ri.stations, out, &err))
        return fail(cmd, ri.args->value("--preset") + ": " + err);
    // What the pass tells (its altitude, fire rate, day or night) stays unless the options or a
    // config give a value for it: a config's "unknown" (the 0 that --print-config writes for
    // them) is not a value, so a printed config run again gives the same run.
    const slr::PostfitParams fromPass = out->params.postfit;
    if (int rc = ri.options->apply(cmd, *ri.args, &out->params)) return rc;
    slr::keepPassContext(fromPass, &out->params.postfit);
    if (const std::string e = slr::validate(out->params.screen); !e.empty())
        return fail(cmd, (out->presetName.empty() ? std::string() : "preset " + out->presetName + ": ") + e, kUsage);
    return kOk;
}

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
              << s.recoveredPoints << " recovered), noise " << s.noisePoints << "\n"
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

// --all-passes: a station's file of passes (a day's, say) in, the products a station delivers
// out, in `dir`: per pass passNNN.csv (as -o), passNNN.frd (the full-rate block with the filter
// flags: 2 kept by the post-fit, 1 noise or rejected) and passNNN.npt (its normal points, or the
// reason there are none); normal_points.npt (every pass's normal-point block, the file a
// station sends); summary.csv (one row per block, its status and reason). All are written
// together at the end. The blocks that are not passes to screen are rows too: the station's
// own normal points ("station normal points"), sampled engineering data and blocks with fewer
// than kMinPassPoints full-rate records ("skipped"). A pass that cannot be processed is
// "failed" with its reason; the others go on. The file is read pass by pass (slr::streamCrd):
// one pass is held at a time, whatever the size of the file.
// The scale search's threads set for a scope (every core again after it).
struct SearchThreads {
    explicit SearchThreads(int n) { slr::setScaleSearchThreads(n); }
    ~SearchThreads() { slr::setScaleSearchThreads(0); }
    SearchThreads(const SearchThreads&) = delete;
    SearchThreads& operator=(const SearchThreads&) = delete;
};

class AllPasses {
public:
    AllPasses(std::string cmd, std::string input, const slr::PassInputParams& in, const RunInputs& ri, std::string dir,
              int threads, bool quiet, const core::Provenance& prov)
        : m_cmd(std::move(cmd)), m_input(std::move(input)), m_in(in), m_ri(ri), m_dir(std::move(dir)), m_threads(threads),
          m_quiet(quiet), m_prov(prov) {
        m_in.cpfFallback = true;  // a pass the CPF does not fit is screened on its own TOF trend, with a note
    }

    int run() {
        std::string err;
        if (!m_in.cpfPath.empty() && !m_in.sinexPath.empty() && !slr::readPassSources(m_in, &m_sources, &err))
            return fail(m_cmd, err);
        const slr::CrdStreamResult crd = slr::streamCrd(
            m_input, {}, nullptr, [this](size_t count) { return begin(count); },
            [this](slr::CrdPass&& p) { return onPass(std::move(p)); });
        if (m_early != kOk) return m_early;
        if (!crd.ok) return fail(m_cmd, crd.error);
        if (m_unreadable == crd.passes)  // (as readCrd: a file none of whose blocks is a pass is an error)
            return fail(m_cmd, m_firstProblem + (m_unreadable > 1 ? " (and the file's " + std::to_string(m_unreadable - 1) +
                                                                       " other pass" + (m_unreadable > 2 ? "es cannot" : " cannot") +
                                                                       " be used either)"
                                                                 : std::string()));
        return finish();
    }

private:
    static constexpr const char* kHeader =
        "pass,station,satellite,ilrs_id,start_utc,duration_s,points,accepted,rms_ps,rms_mm,normal_points,"
        "station_precision,station_recall,oc_origin,status,reason,output,range_bias_mm,range_bias_sigma_mm,"
        "time_bias_us,time_bias_sigma_us\n";

    // The outputs' names, from the file's count of passes, so that every one is checked before any work.
    bool begin(size_t count) {
        m_n = count;
        m_folder = std::make_unique<FolderForOutputs>(m_dir);
        if (!m_folder->ok()) {
            m_early = fail(m_cmd, m_dir + ": cannot create the folder");
            return false;
        }
        m_outs.addInput(m_input);
        for (size_t i = 0; i < m_n; ++i) {
            char name[32];
            std::snprintf(name, sizeof name, "pass%03zu", i + 1);
            m_names.push_back(name);
            for (const char* ext : {".csv", ".frd", ".npt"}) m_outs.addOutput(m_dir + "/" + name + ext);
        }
        m_outs.addOutput(nptPath());
        m_outs.addOutput(provenancePath());
        m_outs.addOutput(summaryPath());
        // summary.csv lists the set: written last; an earlier run's pass files go.
        m_outs.setManifest(summaryPath(), m_dir,
                           {"pass[0-9][0-9][0-9]*.csv", "pass[0-9][0-9][0-9]*.frd", "pass[0-9][0-9][0-9]*.npt", "normal_points.npt"});
        m_early = checkOutputs(m_cmd, m_outs);
        m_written.assign(m_n, false);
        m_rows.assign(m_n, std::string());
        m_progress = std::make_unique<Progress>("slr", m_n, m_quiet);
        const size_t cores = core::coresFor(m_threads);
        // The passes fill the cores; each pass's scale search on one (the same trials and choice
        // on any number: test_slr_screen scaleSearchIsTheSameOnOneThreadAndMany).
        if (cores > 1 && m_n > 1) m_searchOnOne = std::make_unique<SearchThreads>(1);
        m_workers = std::make_unique<core::OrderedWorkers<Job>>(cores, 4 * cores, [this](Job& j) { work(j); });
        return m_early == kOk;
    }

    std::string summaryPath() const { return m_dir + "/summary.csv"; }
    std::string provenancePath() const { return m_dir + "/provenance.json"; }
    std::string nptPath() const { return m_dir + "/normal_points.npt"; }
    std::string out(size_t i, const char* ext) const { return m_dir + "/" + m_names[i] + ext; }

    // range_bias_mm .. time_bias_sigma_us: the station's check against the prediction (CPF O-C only).
    static std::string biasCells(const slr::PassBias& b) {
        if (!b.ok) return ",,,";
        const double mm = 0.5 * 299792458.0 * 1e3;
        return core::formatFixed(b.rangeBiasS * mm, 2) + "," + core::formatFixed(b.rangeBiasSigmaS * mm, 2) + "," +
               core::formatFixed(b.timeBiasS * 1e6, 3) + "," + core::formatFixed(b.timeBiasSigmaS * 1e6, 3);
    }

    void row(const slr::PassSummary& s, size_t i, const std::string& status, const std::string& reason) {
        // duration empty, the records, accepted .. oc_origin empty, status and reason, the rest empty.
        m_rows[i] = std::to_string(i + 1) + "," + core::csvEscape(s.station) + "," + core::csvEscape(s.satellite) + "," +
                     core::csvEscape(s.ilrsId) + "," + s.start + ",," + std::to_string(s.ranges ? s.ranges : s.normalPoints) +
                     ",,,,,,,," + status + "," + core::csvEscape(reason) + ",,,,,\n";
    }

    bool onPass(slr::CrdPass&& crdPass) {
        const size_t i = crdPass.ordinal - 1;
        if (i >= m_names.size()) {  // (the first read counted the passes: it cannot find fewer)
            m_early = fail(m_cmd, m_input + ": the file changed while it was read (more passes than counted)");
            return false;
        }
        if (!crdPass.problem.empty()) {
            if (m_firstProblem.empty()) m_firstProblem = crdPass.problem;
            ++m_unreadable;
        }
        auto one = std::make_shared<slr::CrdReadResult>();
        one->ok = true;
        one->file.path = m_input;
        one->file.passes.push_back(std::move(crdPass));
        // The block is written back as a file of its own (passNNN.frd, .npt): it ends with an H9.
        one->file.trailer.push_back(slr::CrdRecord{"H9", "h9", 0});
        const slr::PassSummary ps = slr::summarisePasses(one->file).front();
        if (const slr::BlockStatus b = slr::blockStatus(ps); !b.status.empty()) {
            m_progress->update(++m_done);
            row(ps, i, b.status, b.reason);
            ++(b.status == "skipped" ? m_skipped : m_stationNps);
            return true;
        }
        slr::PassInputResult p =
            slr::passFromCrd(std::shared_ptr<const slr::CrdReadResult>(std::move(one)), m_input, 0, m_in, m_sources);
        auto failed = [&](const std::string& why) {
            m_progress->update(++m_done);
            failedRow(ps, i, why);
            return true;
        };
        if (!p.ok) return failed(p.error);
        if (!p.pass.damaged.empty()) return failed(p.pass.damaged);
        slr::PassSettings settings;
        std::string err;
        if (!slr::passSettings(p.pass, cliDefaults(), m_ri.havePresets ? &m_ri.presets : nullptr, m_ri.satellite,
                               m_ri.stations, &settings, &err))
            return failed(err);
        if ((m_early = m_ri.options->apply(m_cmd, *m_ri.args, &settings.params)) != kOk) return false;
        Job job;
        job.i = i;
        job.ps = ps;
        job.pass = std::move(p.pass);
        job.params = std::move(settings.params);
        m_workers->submit(std::move(job));
        return gather(m_workers->takeReady());
    }

    void failedRow(const slr::PassSummary& ps, size_t i, const std::string& why) {
        row(ps, i, "failed", why.substr(0, why.find('\n')));
        ++m_failed;
    }

    // A pass read and set up, waiting for its screening; then its result and the error of
    // writing its files ("" when written).
    struct Job {
        size_t i;
        slr::PassSummary ps;
        slr::PassData pass;
        slr::SlrParams params;
        slr::PassRunResult r;
        std::string writeError;
        slr::CrdPass npBlock;  ///< its normal points as a CRD block
        bool npsFormed = false;
    };

    // Screening and writing a pass, on a worker thread. Nothing may leave it: a failure (memory
    // running out while a pass's files are written) is that pass's, as the CLI reports any other.
    void work(Job& j) const {
        try {
            j.r = slr::runPass(j.pass, j.params);
            if (j.r.ok) writePass(j);
        } catch (const std::exception& e) {
            j.r.ok = false;
            j.r.error = std::string("out of resources while screening the pass: ") + e.what();
        }
    }

    // The passes screened so far, in the file's order: their rows.
    bool gather(std::vector<Job> finished) {
        for (Job& j : finished) {
            m_progress->update(++m_done);
            if (!j.r.ok) {
                failedRow(j.ps, j.i, j.r.error);
                continue;
            }
            if (!j.writeError.empty()) {
                m_early = fail(m_cmd, m_outs.unstaged(j.writeError));
                return false;
            }
            m_written[j.i] = true;
            if (!m_like) m_like = j.pass.crd;
            if (j.npsFormed) m_dayNps.push_back(std::move(j.npBlock));
            screenedRow(j.i, j.ps, j.pass, j.r);
        }
        return true;
    }

    // The pass's CSV, flagged full-rate block and normal points (on a worker thread: it writes
    // only its own staging files and its own job); its normal-point block is kept for the file of
    // the day.
    void writePass(Job& j) const {
        const slr::PassData& pass = j.pass;
        const slr::PassRunResult& r = j.r;
        const slr::DeliveredNormalPoints delivered = slr::deliveredNormalPoints(r);
        const std::vector<slr::NormalPoint>& nps = delivered.points;
        const std::string& noneReason = delivered.noneReason;
        // The station's flags: what the post-fit kept (its rejects are excluded), else the screening's.
        const std::vector<uint8_t>& flags = r.postOk ? r.post.kept : r.accepted;
        std::string& err = j.writeError;
        const bool ok = slr::writeScreenCsv(m_outs.stagingPath(out(j.i, ".csv")), pass, r.screen, r.accepted,
                                            r.postOk ? &r.post : nullptr, &err) &&
                        slr::writeScreenedCrd(m_outs.stagingPath(out(j.i, ".frd")), pass, flags, &err) &&
                        slr::normalPointPass(pass, nps, slr::normalPointProduct(r.postOk ? &r.post : nullptr, &r.screen, noneReason),
                                             &j.npBlock, &err) &&
                        slr::writeNormalPointFile(m_outs.stagingPath(out(j.i, ".npt")), {j.npBlock}, *pass.crd, &err);
        j.npsFormed = ok && !nps.empty();  // (only passes with normal points go in the day's file)
        if (!ok && err.empty()) err = out(j.i, ".npt") + ": not written";
    }

    void screenedRow(size_t i, const slr::PassSummary& ps, const slr::PassData& pass, const slr::PassRunResult& r) {
        const bool doubtful = !r.doubt.empty();
        ++(doubtful ? m_doubtful : m_screened);
        const double duration = pass.t.empty() ? 0 : pass.t.back() - pass.t.front();
        const double rms = r.postOk ? r.post.stats.rms : NAN;
        const slr::BlockStatus st = slr::runStatus(pass, r);
        m_rows[i] = std::to_string(i + 1) + "," + core::csvEscape(ps.station) + "," + core::csvEscape(ps.satellite) + "," +
                     core::csvEscape(ps.ilrsId) + "," + ps.start + "," + core::formatFixed(duration, 1) + "," +
                     std::to_string(pass.t.size()) + "," + std::to_string(r.acceptedCount) + "," +
                     (std::isfinite(rms) ? core::formatFixed(rms * 1e12, 1) : "") + "," +
                     (std::isfinite(rms) ? core::formatFixed(rms * 0.5 * 299792458.0 * 1e3, 2) : "") + "," +
                     (r.postOk && !doubtful ? std::to_string(r.post.normalPoints.size()) : "0") + "," +
                     f4(r.agreement.precision) + "," + f4(r.agreement.recall) + "," + core::csvEscape(pass.ocOrigin) + "," +
                     st.status + "," + core::csvEscape(st.reason) + "," + m_names[i] +
                     ".csv," + biasCells(r.bias) + "\n";
    }

    int finish() {
        if (m_workers && !gather(m_workers->drain())) return m_early;
        if (m_progress) m_progress->finish();
        std::string err;
        for (size_t i = 0; i < m_n; ++i)  // passes with no result have no files
            if (!m_written[i])
                for (const char* ext : {".csv", ".frd", ".npt"}) m_outs.drop(out(i, ext));
        const bool dayNpt = m_like && !m_dayNps.empty();
        if (dayNpt) {
            if (!slr::writeNormalPointFile(m_outs.stagingPath(nptPath()), std::move(m_dayNps), *m_like, &err))
                return fail(m_cmd, m_outs.unstaged(err));
        } else {
            m_outs.drop(nptPath());  // (no pass formed a normal point: summary.csv says why)
        }
        std::string summary = kHeader;
        for (const std::string& r : m_rows) summary += r;
        if (!core::writeFileAtomic(m_outs.stagingPath(summaryPath()), summary, &err))
            return fail(m_cmd, m_outs.unstaged(err));
        // The folder's provenance: every file of the set with its checksum.
        std::vector<std::string> written;
        for (size_t i = 0; i < m_n; ++i)
            if (m_written[i])
                for (const char* ext : {".csv", ".frd", ".npt"}) written.push_back(out(i, ext));
        if (dayNpt) written.push_back(nptPath());
        written.push_back(summaryPath());
        if (!stageProvenance(m_outs, m_prov, written, provenancePath(), &err)) return fail(m_cmd, err);
        if (int rc = commitOutputs(m_cmd, m_outs)) return rc;
        m_folder->keep();
        if (!m_quiet)
            std::cerr << "slr: " << m_input << ": " << m_n << " blocks: " << m_screened << " screened, " << m_doubtful
                      << " doubtful, " << m_failed << " failed, " << m_stationNps << " station normal points, " << m_skipped
                      << " skipped -> " << m_dir << "/ (summary.csv"
                      << (dayNpt ? ", normal_points.npt" : "") << ")\n";
        if (m_failed == 0 && m_doubtful == 0) return kOk;
        // (said even with -q: a partial or doubtful result is not a success)
        std::cerr << "laserwb-cli slr: " << m_failed << " of " << m_n << " passes failed and " << m_doubtful
                  << " are doubtful (" << m_dir << "/summary.csv says why); exit "
                  << (m_failed ? kSomeFailed : kDoubtful) << "\n";
        return m_failed ? kSomeFailed : kDoubtful;
    }

    std::string m_cmd, m_input;
    slr::PassInputParams m_in;
    const RunInputs& m_ri;
    std::string m_dir;
    int m_threads;  ///< --threads, 0 = every core
    bool m_quiet;
    const core::Provenance& m_prov;
    slr::PassSources m_sources;
    std::unique_ptr<FolderForOutputs> m_folder;
    core::OutputSet m_outs;
    std::vector<std::string> m_names;
    std::vector<bool> m_written;
    std::unique_ptr<Progress> m_progress;
    std::vector<std::string> m_rows;  ///< summary.csv's rows, one per block in the file's order
    std::string m_firstProblem;
    std::vector<slr::CrdPass> m_dayNps;
    std::shared_ptr<const slr::CrdFile> m_like;
    size_t m_n = 0, m_done = 0, m_unreadable = 0;
    size_t m_screened = 0, m_doubtful = 0, m_failed = 0, m_skipped = 0, m_stationNps = 0;
    int m_early = kOk;
    // Passes screened side by side while the file is read (a station's day is many passes, most
    // too small to fill the cores alone); the products do not depend on the number of cores:
    // each pass is screened alone and what is gathered is gathered in the file's order. At most
    // four passes per core are held. (Last: its threads stop before the rest goes.)
    std::unique_ptr<SearchThreads> m_searchOnOne;
    std::unique_ptr<core::OrderedWorkers<Job>> m_workers;
};

int screenAllPasses(const std::string& cmd, const std::string& input, const slr::PassInputParams& in, const RunInputs& ri,
                    const std::string& dir, int threads, bool quiet, const core::Provenance& prov) {
    return AllPasses(cmd, input, in, ri, dir, threads, quiet, prov).run();
}

}  // namespace

// What one slr run reads and writes, from its options (cmdSlr's first stage).
struct SlrPlan {
    std::vector<std::string> inputs;  ///< the files named and listed (--files-from)
    std::string input, out, crdOut, nptOut, outDir;
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
        for (const char* o : {"-o", "--output", "--crd-out", "--npt-out", "--pass"})
            if (a.has(o)) return fail(cmd, std::string(o) + " is for one pass; --all-passes writes DIR/passNNN.csv and DIR/summary.csv", kUsage);
    } else if (!outDir.empty() || a.has("--threads")) {
        return fail(cmd, std::string(outDir.empty() ? "--threads" : "--out-dir") + " goes with --all-passes", kUsage);
    }

    pl->out = a.has("-o") ? a.value("-o") : a.value("--output");
    const std::string& out = pl->out;
    pl->crdOut = a.value("--crd-out");
    pl->nptOut = a.value("--npt-out");
    if (out.empty() && pl->crdOut.empty() && pl->nptOut.empty() && !allPasses)
        return fail(cmd, "no output file: give -o OUT.csv, --crd-out FILE or --npt-out FILE", kUsage);
    const std::string &crdOut = pl->crdOut, &nptOut = pl->nptOut;
    // Every output is checked before anything is computed or written: none may replace an
    // input or another output (same device and inode, whatever the spelling), devices and
    // folders are refused, and all are renamed into place together at the end.
    for (const char* in : {"--cpf", "--stations", "--preset"}) outs->addInput(a.value(in));
    outs->addInput(input);
    for (const std::string* p : {&out, &crdOut, &nptOut})
        if (!p->empty()) outs->addOutput(*p);
    for (const std::string* p : {&out, &crdOut, &nptOut})  // each file's provenance beside it
        if (!p->empty() && !core::isStandardStream(*p)) outs->addOutput(core::provenancePathFor(*p));
    if (!allPasses)
        if (int rc = checkOutputs(cmd, *outs)) return rc;
    if (a.has("--cpf") && !a.has("--stations"))
        return fail(cmd, "--cpf and --stations go together (O-C from the prediction needs both)", kUsage);
    if (a.has("--satellite") && !a.has("--preset"))
        return fail(cmd, "--satellite selects a preset entry; give --preset FILE with it", kUsage);
    std::string err;
    if (!a.getInt("--pass", 1, 1000000, &pl->passK, &err) || !a.getInt("--threads", 0, 256, &pl->threads, &err))
        return fail(cmd, err, kUsage);
    {  // Bad options and config are usage errors before anything is read.
        slr::SlrParams probe = cliDefaults();
        if (int rc = params.apply(cmd, a, &probe)) return rc;
    }
    if (pl->inputs.size() > 1) return -1;  // (each file is looked at when its turn comes)
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
                          "--out-dir", "--threads"})
        a.option(o, true);
    declareBatchOptions(a);
    for (const char* o : {"--quiet", "-q", "--help", "-h", "--help-params", "--all-passes"}) a.option(o, false);
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
        slr::SlrParams p = cliDefaults();
        if (int rc = params.apply(cmd, a, &p)) return rc;
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
std::string stemOf(const std::string& path) {
    std::string n = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
    if (n.size() > 3 && n.compare(n.size() - 3, 3, ".gz") == 0) n.resize(n.size() - 3);
    if (const size_t dot = n.find_last_of('.'); dot != std::string::npos && dot > 0) n.resize(dot);
    return n;
}

// --all-passes over the inputs of this shard: one file's products in --out-dir, or with many
// files each file's in DIR/<its name>/; a file that fails does not stop the others.
int allPassFiles(const std::string& cmd, const SlrPlan& plan, const slr::PassInputParams& in, const RunInputs& ri,
                 const core::Provenance& prov, const BatchOptions& bo, RunSummary& summary, bool quiet) {
    const std::vector<std::string>& inputs = plan.inputs;
    const bool many = inputs.size() > 1;
    std::vector<std::string> dirs;
    std::map<std::string, std::string> seen;
    for (const auto& f : inputs) {
        if (!many) {
            dirs.push_back(plan.outDir);
            continue;
        }
        const std::string name = stemOf(f);
        if (auto [it, fresh] = seen.emplace(name, f); !fresh)
            return fail(cmd, f + " and " + it->second + " would both write " + plan.outDir + "/" + name + "/ (rename one)", kUsage);
        dirs.push_back(plan.outDir + "/" + name);
    }
    summary.setInputsTotal(inputs.size());
    const auto [first, last] = bo.shard.range(inputs.size());
    if (many && first < last) ::mkdir(plan.outDir.c_str(), 0777);  // (each file's folder is made by its run)
    size_t failed = 0, partial = 0, doubtful = 0, run = 0;
    for (size_t i = first; i < last; ++i) {
        core::Json e = core::Json::object();
        e["input"] = inputs[i];
        e["outputs"] = core::Json::array({dirs[i]});
        core::Provenance p = prov;
        p.inputs.front() = inputs[i];
        std::string why;
        if (bo.skipExisting && outputsComplete(p, {}, dirs[i] + "/provenance.json", &why)) {
            e["status"] = "skipped";
            summary.addInput(e);
            if (!quiet) std::cerr << "slr: " << inputs[i] << ": " << dirs[i] << "/ is complete: skipped\n";
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const int rc = !slr::isCrdFile(inputs[i])
                           ? fail(cmd, inputs[i] + ": cannot be read or is not a CRD file (--all-passes reads CRD files)")
                           : screenAllPasses(cmd, inputs[i], in, ri, dirs[i], static_cast<int>(plan.threads), quiet, p);
        ++run;
        e["status"] = rc == kOk ? "ok" : rc == kDoubtful ? "doubtful" : rc == kSomeFailed ? "some passes failed" : "failed";
        e["exit_code"] = rc;
        if (rc != kOk && rc != kDoubtful) e["error"] = lastFailure();
        e["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        summary.addInput(e);
        if (!many) return rc;
        (rc == kDoubtful ? doubtful : rc == kSomeFailed ? partial : rc != kOk ? failed : run)++;
    }
    if (!many) return kOk;  // (the one file is another shard's)
    if (failed || partial) {
        std::cerr << "laserwb-cli slr: " << failed << " of " << (last - first) << " files failed, " << partial
                  << " had passes that failed (--summary-json, each folder's summary.csv say why)\n";
        return failed == last - first ? kFailed : kSomeFailed;
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
    const std::string &input = plan.input, &out = plan.out, &crdOut = plan.crdOut, &nptOut = plan.nptOut;
    const bool allPasses = plan.allPasses, csvInput = plan.csvInput;
    const long long passK = plan.passK;
    std::string err;

    // ---- presets (read before the pass so that a bad file stops early) ----
    std::vector<slr::SatellitePreset> presets;
    if (a.has("--preset")) {
        const slr::PresetsResult pr = slr::loadPresets(a.value("--preset"));
        if (!pr.ok) return fail(cmd, named(a.value("--preset"), pr.error));
        presets = pr.presets;
    }

    // ---- the station file (day or night per normal-point bin), read once ----
    slr::PassInputParams in;
    in.cpfPath = a.value("--cpf");
    if (a.has("--cpf")) in.sinexPath = a.value("--stations");
    slr::SinexReadResult snx;
    if (a.has("--stations")) {
        snx = slr::readSinex(a.value("--stations"));
        if (!snx.ok) return fail(cmd, named(a.value("--stations"), snx.error));
    }
    const RunInputs ri{presets, a.has("--preset"), a.value("--satellite"), snx.ok ? &snx.file : nullptr, &params, &a};
    // Provenance: the parameters (--all-passes: before each pass's preset; the presets file is
    // an input), what else shapes the outputs, and the inputs.
    core::Provenance prov;
    prov.command = allPasses ? "slr --all-passes" : "slr";
    {
        slr::SlrParams base = cliDefaults();
        if (int rc = params.apply(cmd, a, &base)) return rc;
        prov.parameters = slr::slrSchema().toJson(base);
    }
    prov.settings = {{"pass", passK},          {"cpf", a.value("--cpf")}, {"stations", a.value("--stations")},
                     {"preset", a.value("--preset")}, {"satellite", a.value("--satellite")}};
    prov.inputs = {input, a.value("--config"), a.value("--cpf"), a.value("--stations"), a.value("--preset")};
    if (allPasses) return allPassFiles(cmd, plan, in, ri, prov, bo, summary, quiet);

    // ---- the pass ----
    const int passIndex = a.has("--pass") ? static_cast<int>(passK - 1) : -1;
    const slr::PassInputResult loaded = slr::loadPass(input, passIndex, in);
    if (!loaded.ok) {
        std::string msg = named(input, loaded.error);
        if (!csvInput && passIndex >= 0 && !loaded.passes.empty() && passIndex >= static_cast<int>(loaded.passes.size()))
            msg = input + ": --pass " + std::to_string(passK) + " asked for, the file holds " +
                  std::to_string(loaded.passes.size()) + " pass" + (loaded.passes.size() == 1 ? "" : "es") +
                  " (numbered from 1):" + passList(loaded.passes);
        else if (!csvInput && loaded.passes.size() > 1)
            msg += "\nThe passes of the file (--pass K):" + passList(loaded.passes);
        return fail(cmd, msg);
    }
    const slr::PassData& pass = loaded.pass;
    // A record of the pass to screen that the reader had to skip ("FILE:LINE: ..."): the point is
    // missing from the screening and the damaged line would be written back as it is. Refused.
    if (!pass.damaged.empty()) return fail(cmd, pass.damaged + "; nothing written");
    if (!quiet)
        for (const auto& w : loaded.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";

    // ---- parameters: defaults (automatic), preset, normal-point context, config file, options ----
    slr::PassSettings settings;
    if (int rc = settingsFor(cmd, pass, ri, &settings)) return rc;
    const slr::SlrParams& run = settings.params;
    if (!nptOut.empty() && !(run.postfit.binLengthS > 0) && !(run.postfit.altitudeKm > 0))
        return fail(cmd, "no normal points: the satellite's altitude is unknown (give --np-bin S or a preset with altitude_km)",
                    kUsage);
    // The pass's own parameters (its preset and context applied) in the provenance; with
    // --skip-existing, outputs whose sidecars say they are complete are not made again.
    prov.parameters = slr::slrSchema().toJson(run);
    std::vector<std::string> products;
    for (const std::string* o : {&out, &crdOut, &nptOut})
        if (!o->empty() && !core::isStandardStream(*o)) products.push_back(*o);
    core::Json entry = core::Json::object();
    entry["input"] = input;
    entry["outputs"] = products;
    for (const auto& n : products) summary.addOutput(n), summary.addOutput(core::provenancePathFor(n));
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
    const slr::PassRunResult r = slr::runPass(pass, run);
    const std::string what = csvInput ? input : input + " pass " + std::to_string(pass.passIndex + 1);
    if (!r.ok) return fail(cmd, what + ": " + r.error);
    // A result that cannot be trusted (noise that no scale tells from a track, two tracks merged):
    // the points' classes are written, no normal points, exit 3 with the reason.
    const bool doubtful = !r.doubt.empty();
    // No normal point is a result, not a failure (no signal found, no bin full enough, a
    // doubtful pass): every requested output is written, the NPT with the reason in place of
    // its records, and the exit code says which (0, or 3 when doubtful).
    const slr::DeliveredNormalPoints delivered = slr::deliveredNormalPoints(r);
    const std::vector<slr::NormalPoint>& nps = delivered.points;
    const std::string& noneReason = delivered.noneReason;

    // ---- outputs: all or nothing ----
    if (!out.empty() &&
        !slr::writeScreenCsv(outs.stagingPath(out), pass, r.screen, r.accepted, r.postOk ? &r.post : nullptr, &err))
        return fail(cmd, named(out, outs.unstaged(err)));
    if (!crdOut.empty() && !slr::writeScreenedCrd(outs.stagingPath(crdOut), pass, r.accepted, &err))
        return fail(cmd, named(crdOut, outs.unstaged(err)));
    if (!nptOut.empty() && !slr::writeNormalPointCrd(outs.stagingPath(nptOut), pass, nps, &err,
                                                     slr::normalPointProduct(r.postOk ? &r.post : nullptr, &r.screen, noneReason)))
        return fail(cmd, named(nptOut, outs.unstaged(err)));
    for (const auto& n : products)
        if (!stageProvenance(outs, prov, products, core::provenancePathFor(n), &err)) return fail(cmd, err);
    if (int rc = commitOutputs(cmd, outs)) return rc;
    entry["status"] = doubtful ? "doubtful" : "ok";
    entry["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    summary.addInput(entry);
    if (!quiet) {
        printSummary(what, pass, settings, r);
        std::string written;
        for (const std::string* o : {&out, &crdOut, &nptOut})
            if (!o->empty()) written += (written.empty() ? "" : ", ") + *o;
        std::cerr << "  -> " << written
                  << (nptOut.empty() || !nps.empty() ? "" : " (" + nptOut + ": no normal points: " + noneReason + ")")
                  << "\n";
    }
    if (doubtful) {
        std::cerr << "laserwb-cli slr: doubtful: " << r.doubt << " (exit 3)\n";
        return kDoubtful;
    }
    return kOk;
}

}  // namespace lwb::cli
