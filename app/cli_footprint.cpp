// laserwb-cli footprint | simulate footprint | trend | eval footprint | bench footprint
#include <atomic>
#include <chrono>
#include <functional>
#include <thread>
#include <opencv2/imgcodecs.hpp>
#include <cstdio>
#include <iostream>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include "cli_batch.hpp"
#include "cli_common.hpp"
#include "cli_commands.hpp"
#include "core/common/parallel.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/row_filter.hpp"
#include "core/common/image_codecs.hpp"
#include "core/common/text.hpp"
#include "core/footprint/batch.hpp"
#include "core/footprint/crlb.hpp"
#include "core/footprint/footprint_run.hpp"
#include "core/footprint/report_columns.hpp"
#include "core/footprint/shot_list.hpp"
#include "core/footprint/trend.hpp"
#include "core/footprint/tune.hpp"
#include "core/sim/centroid_sim.hpp"
#include "core/sim/footprint_eval.hpp"
#include "core/common/rng.hpp"

namespace lwb::cli {

using namespace core::footprint;
namespace sim = core::sim;

namespace {
const std::string kFootprintUsage =
    std::string("usage: laserwb-cli footprint [options] INPUT... -o OUT.csv\n"
    "Finds the laser spot centre in footprint-camera frames or ROIs and judges each shot.\n"
    "INPUT: image files (16-bit PNG/TIFF/PGM, or raw little-endian 16-bit with --raw-size), folders\n"
    "(every image inside, sorted by name), or shot lists: a .csv with a header holding 'file' and\n"
    "optionally time, beam, camera, center_x, center_y (the workbench's shot list; one row per shot,\n"
    "a two-beam frame twice with each beam's centre; a relative file is relative to the list's\n"
    "folder; time as ISO date/date-time, YYYY-MM or Unix seconds). A list's time, beam and camera\n"
    "go into the report, so that `laserwb-cli trend OUT.csv` follows.\n"
    "Parameters (every one: --print-config; ranges and docs: --help-params):\n"
    "  --config FILE.json        parameters; the options below override it\n"
    "  --set KEY=VALUE           one parameter (repeatable), e.g. --set segment.threshold_factor=0.2\n"
    "  --print-config            print the effective parameters as JSON and exit\n"
    "  --help-params             every parameter with its unit, range, default and meaning\n"
    "  --help-columns            every column of the report with its unit and meaning\n"
    "  --method gauss|tefm|gcm   centre method (default {default:method}; gauss: Wu f.lnf QR + tilt + Guo + LM) = --set method=...\n"
    "  --preset wu2021|yao2021   verdict criteria (default {default:preset})\n"
    "  --roi N                   ROI side in px (default {default:roi.size}) = --set roi.size=N\n"
    "  --center X,Y              nominal spot centre in full-image px; repeat for the two beams of an\n"
    "                            LSI frame (one row per ROI). Without it, the brightest spot-like blob.\n"
    "                            A shot's own center_x,center_y (shot list, --metadata) replaces it\n"
    "  --metadata FILE.csv       frame metadata: a table in the shot-list format whose rows give the\n"
    "                            time, beam, camera (and centre) of frames chosen otherwise (folders,\n"
    "                            --files-from, a shard); a frame is found by its path (the table's\n"
    "                            relative to its folder) or else by its file name when only one row\n"
    "                            has it; a shot list's own values win. Frames no row describes are\n"
    "                            counted on stderr\n"
    "  --raw-size WxH            size of .raw/.bin frames\n"
    "  --max-pixels N            largest frame read, from its header (default 16777216 = 4096^2)\n"
    "  --threads N               worker threads (default: all cores)\n"
    "  --keep-going              write unreadable files as rejected rows instead of stopping\n"
    "  --where EXPR              only the report rows for which EXPR holds, e.g. 'snr < 10 and roi == 1'\n"
    "                            (the workbench's filter language over the report's columns)\n"
    "  -o, --output OUT.csv      report: file,x,y,verdict,reasons,method,noise_class,sigma_x,...,\n"
    "                            roi_y0,cov_xx_px2,...,radius95_px,time,beam,camera (every column:\n"
    "                            --help-columns); beside it OUT.csv.provenance.json\n"
    "                            (version, parameters, settings, SHA-256 of every input and output)\n"
    "  -q, --quiet               no progress line\n") +
    kBatchOptionsHelp +
    "Exit codes: 0 done, 1 bad input (nothing written), 2 usage error.\n";

// The footprint parameters: config file (a "preset" in it applied first), --preset, the
// aliases and --set, all through the footprint schema.
struct FootprintOptions : ParamOptions<FootprintParams> {
    FootprintOptions() : ParamOptions(footprintSchema(), {{"--method", "method"}, {"--roi", "roi.size"}}) {
        fromJson = [](const core::JsonParseResult& j, FootprintParams* p, std::string* err) {
            return footprintParamsFromJson(j.value, p, err, &j);
        };
    }
};
}  // namespace

namespace {
// The report, filtered by --where when given, staged at `path`: the expression sees each row's
// values as the column table gives them (core/footprint/report_columns.hpp), the numbers before
// the CSV rounds them, as the workbench's filter does. *rows and *kept count the rows.
bool writeReport(const std::string& path, const BatchResult& res, Method method, const core::RowFilter* where,
                 size_t* rows, size_t* kept, std::string* err) {
    if (!where) return writeFootprintCsv(path, res.items, method, err);
    core::AtomicFile f(path);
    if (!f.ok()) {
        *err = f.error();
        return false;
    }
    f.stream() << footprintCsvHeader();
    const auto& columns = footprintColumns();
    std::vector<core::FilterCell> cells;
    for (const BatchItem& it : res.items)
        for (const ReportRow& r : reportRows(it, method)) {
            ++*rows;
            cells.clear();
            for (const FootprintColumn& c : columns)
                if (!c.reviewOnly) cells.push_back(c.value(r));
            if (!where->matches(cells)) continue;
            ++*kept;
            bool first = true;
            for (const FootprintColumn& c : columns)
                if (!c.reviewOnly) {
                    f.stream() << (first ? "" : ",") << footprintCsvCell(c, r);
                    first = false;
                }
            f.stream() << "\n";
        }
    if (!f.commit()) {
        *err = f.error();
        return false;
    }
    return true;
}

// A shot's entry in the run summary.
core::Json shotEntry(const ShotSpec& shot, const BatchItem* item, const std::string& out, const char* status = nullptr) {
    core::Json e = core::Json::object();
    e["input"] = shot.file;
    if (!shot.source.empty()) e["listed_at"] = shot.source + ":" + std::to_string(shot.line);
    if (status) {
        e["status"] = status;
    } else if (!item->readError.empty()) {
        e["status"] = "unreadable";
        e["error"] = item->readError;
    } else {
        std::string v;
        for (const auto& r : item->rois) v += (v.empty() ? "" : ",") + std::string(verdictName(r.result.ok ? r.result.verdict : Verdict::Rejected));
        e["status"] = v.empty() ? "rejected" : v;
        e["rois"] = item->rois.size();
    }
    e["outputs"] = core::Json::array({out});
    if (item) e["seconds"] = item->seconds;
    return e;
}

// The run of cmdFootprint once the options are read: the shots, the share, the report.
int runFootprint(const Args& a, const FootprintSources& src, const BatchOptions& bo, RunSummary& summary) {
    const bool quiet = a.has("-q") || a.has("--quiet");
    std::string err;
    // --where: compiled before any work, against the report's columns.
    std::shared_ptr<const core::RowFilter> where;
    if (a.has("--where")) {
        core::RowFilterParams wp;
        wp.text = a.value("--where");
        wp.columns = footprintColumnNames();
        const core::RowFilterResult w = core::compileRowFilter(wp);
        if (!w.ok) return fail("footprint", "--where: " + w.error, kUsage);
        where = w.filter;
    }
    const std::string out = a.has("-o") ? a.value("-o") : a.value("--output");
    if (out.empty()) return fail("footprint", "no output file: give -o OUT.csv", kUsage);
    FootprintSetup setup;
    FootprintError fe;
    if (!setUpFootprintRun(src, &setup, &fe)) return fail("footprint", fe.message, fe.usage ? kUsage : kFailed);
    const BatchParams& bp = setup.params;
    const std::vector<ShotSpec>& all = setup.shots;
    if (setup.unmatched && !quiet)
        std::cerr << "laserwb-cli footprint: warning: " << setup.unmatched << " of " << all.size() << " shots have no row in "
                  << a.value("--metadata") << " (their time, beam and camera stay empty)\n";
    std::vector<std::string> inputs = a.positional();
    inputs.insert(inputs.end(), bo.listed.begin(), bo.listed.end());
    summary.setInputsTotal(all.size());
    const auto [first, last] = bo.shard.range(all.size());
    const std::vector<ShotSpec> shots(all.begin() + long(first), all.begin() + long(last));
    // ---- provenance: what the report is made of ----
    core::Provenance prov;
    prov.command = "footprint";
    prov.parameters = footprintSchema().toJson(bp.footprint);
    core::Json centres = core::Json::array();
    for (const auto& c : bp.centres) centres.push_back({c.x, c.y});
    prov.settings = {{"center", centres},
                     {"raw_size", a.value("--raw-size")},
                     {"max_pixels", bp.read.maxPixels},
                     {"keep_going", a.has("--keep-going")},
                     {"where", a.value("--where")},
                     {"metadata", a.value("--metadata")},
                     {"shard", bo.shard.text()},
                     {"shots_total", all.size()}};
    prov.inputs = {a.value("--config"), bo.filesFrom == "-" ? std::string() : bo.filesFrom, a.value("--metadata")};
    for (const auto& in : inputs)
        if (isShotListFile(in)) prov.inputs.push_back(in);
    for (const auto& s : shots) prov.inputs.push_back(s.file);
    const bool toStdout = core::isStandardStream(out);
    const std::string sidecar = core::provenancePathFor(out);
    summary.addOutput(out);
    if (!toStdout) summary.addOutput(sidecar);
    if (bo.skipExisting && !toStdout) {
        std::string why;
        if (outputsComplete(prov, {out}, sidecar, &why)) {
            for (const auto& s : shots) summary.addInput(shotEntry(s, nullptr, out, "skipped"));
            if (!quiet) std::cerr << "footprint: " << out << " is complete (" << sidecar << "): skipped\n";
            return kOk;
        }
        if (!quiet && ::access(out.c_str(), F_OK) == 0) std::cerr << "footprint: running again: " << why << "\n";
    }
    core::OutputSet outs;
    for (const auto& in : prov.inputs) outs.addInput(in);
    outs.addOutput(out);
    if (!toStdout) outs.addOutput(sidecar);
    if (int rc = checkOutputs("footprint", outs)) return rc;
    if (int rc = summary.checkTarget(toStdout ? std::vector<std::string>{} : std::vector<std::string>{out, sidecar})) return rc;
    // ---- the shots processed ----
    Progress progress("footprint", shots.size(), quiet);
    size_t done = 0;
    core::Feedback fb;
    const bool keepGoing = a.has("--keep-going");
    std::string firstError;
    const BatchResult res = runFootprintBatch(shots, bp, &fb, [&](size_t, const BatchItem& item) {
        progress.update(++done);
        if (!quiet)
            for (const auto& r : item.rois)
                for (const auto& w : r.warnings) std::cerr << "laserwb-cli footprint: warning: " << item.file << ": " << w << "\n";
        if (!keepGoing && firstError.empty()) {
            if (!item.readError.empty()) firstError = item.readError;
            for (const auto& r : item.rois)
                if (!r.result.ok && firstError.empty()) firstError = item.file + ": " + r.result.error;
            if (!firstError.empty()) fb.cancel();
        }
    });
    progress.finish();
    if (!firstError.empty()) return fail("footprint", firstError + " (nothing written; --keep-going reports it as a rejected row)");
    // ---- the report and its provenance, all or nothing ----
    size_t kept = 0, rows = 0;
    if (!writeReport(outs.stagingPath(out), res, bp.footprint.method, where.get(), &rows, &kept, &err))
        return fail("footprint", outs.unstaged(err));
    if (!toStdout && !stageProvenance(outs, prov, {out}, sidecar, &err)) return fail("footprint", err);
    if (int rc = commitOutputs("footprint", outs)) return rc;
    size_t good = 0, doubtful = 0, rejected = 0;
    for (size_t i = 0; i < res.items.size(); ++i) {
        const BatchItem& it = res.items[i];
        summary.addInput(shotEntry(shots[i], &it, out));
        if (!it.readError.empty()) ++rejected;
        for (const auto& r : it.rois) {
            const Verdict v = r.result.ok ? r.result.verdict : Verdict::Rejected;
            (v == Verdict::Good ? good : v == Verdict::Doubtful ? doubtful : rejected)++;
        }
    }
    bool fromLists = false;
    for (const auto& s : shots) fromLists |= !s.source.empty();
    if (!quiet)
        std::cerr << "footprint: " << shots.size() << (fromLists ? " shots" : " files")
                  << (bo.shard.given ? " (shard " + bo.shard.text() + " of " + std::to_string(all.size()) + ")" : "")
                  << " -> " << out << ": " << good << " good, " << doubtful << " doubtful, " << rejected << " rejected"
                  << (res.readErrors ? " (" + std::to_string(res.readErrors) + " unreadable)" : "")
                  << (where ? "; --where kept " + std::to_string(kept) + " of " + std::to_string(rows) + " rows" : "")
                  << "\n";
    return kOk;
}
}  // namespace

namespace {
// The options `footprint` and `footprint tune` gather their sources from.
void declareSourceOptions(Args& a, const FootprintOptions& params) {
    params.declare(a);
    for (const char* o : {"--preset", "--raw-size", "--threads", "--max-pixels", "--metadata"}) a.option(o, true);
    a.option("--center", true, true);
}

// The sources as given (the core resolves them: core/footprint/footprint_run.hpp), in two
// parts: the parameters (config, preset, settings), then the frames and how they are read.
// False with *err (a usage error).
bool gatherParams(const Args& a, const FootprintOptions& params, FootprintSources* src, std::string* err) {
    src->configFile = a.value("--config");
    src->preset = a.value("--preset");
    return params.settings(a, &src->set, err);
}
bool gatherFrames(const Args& a, FootprintSources* src, std::string* err) {
    for (const auto& c : a.values("--center")) {
        double x = 0, y = 0;
        if (!parsePoint(c, &x, &y)) {
            *err = "--center must be X,Y (numbers), not \"" + c + "\"";
            return false;
        }
        src->centres.emplace_back(x, y);
    }
    if (a.has("--raw-size") && !parseSize(a.value("--raw-size"), &src->read.rawWidth, &src->read.rawHeight)) {
        *err = "--raw-size must be WxH, e.g. 550x550";
        return false;
    }
    long long threads = 0;
    if (!a.getInt("--threads", 0, 256, &threads, err) || !a.getInt("--max-pixels", 1, 1LL << 40, &src->read.maxPixels, err))
        return false;
    src->threads = static_cast<int>(threads);
    src->inputs = a.positional();
    src->metadata = a.value("--metadata");
    return true;
}
}  // namespace

int cmdFootprint(int argc, char** argv) {
    if (argc > 2 && std::string(argv[2]) == "tune") return cmdFootprintTune(argc, argv);  // (a frame named tune: ./tune)
    Args a("footprint", kFootprintUsage);
    const FootprintOptions params;
    declareSourceOptions(a, params);
    declareBatchOptions(a);
    for (const char* o : {"-o", "--output", "--where"}) a.option(o, true);
    for (const char* o : {"--keep-going", "--help-params", "--help-columns", "-q", "--quiet", "--help", "-h"}) a.option(o, false);
    if (!a.parse(argc, argv, 2)) return fail("footprint", a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << a.usage();  // (its defaults filled from the schema by declare)
        return kOk;
    }
    if (a.has("--help-columns")) {  // (from the column table the report is written by)
        std::cout << "footprint report columns (name [unit]: meaning):\n";
        for (const FootprintColumn& c : footprintColumns())
            if (!c.reviewOnly)
                std::cout << "  " << c.name << (*c.unit ? std::string(" [") + c.unit + "]" : std::string()) << ": " << c.doc << "\n";
        return kOk;
    }
    if (a.has("--help-params")) {
        std::cout << "footprint parameters (key = default unit  valid range):\n" << footprintSchema().describe(FootprintParams{});
        return kOk;
    }
    FootprintSources src;
    std::string err;
    if (!gatherParams(a, params, &src, &err)) return fail("footprint", err, kUsage);
    if (params.printRequested(a)) {
        FootprintParams p;
        FootprintError fe;
        if (!resolveFootprintParams(src, &p, &fe)) return fail("footprint", fe.message, fe.usage ? kUsage : kFailed);
        std::cout << params.json(p);
        return kOk;
    }
    BatchOptions bo;
    const int loaded = loadBatchOptions("footprint", a, &bo);
    RunSummary summary("footprint", bo);
    if (loaded) return summary.finish(loaded);
    if (!gatherFrames(a, &src, &err)) return summary.finish(fail("footprint", err, kUsage));
    src.inputs.insert(src.inputs.end(), bo.listed.begin(), bo.listed.end());
    src.keepGoing = a.has("--keep-going");
    // The parameters' errors first (the shots are gathered once the options are known good).
    FootprintParams checked;
    FootprintError fe;
    if (!resolveFootprintParams(src, &checked, &fe)) return summary.finish(fail("footprint", fe.message, fe.usage ? kUsage : kFailed));
    return summary.finish(runFootprint(a, src, bo, summary));
}

namespace {
const std::string kTuneUsage =
    std::string("usage: laserwb-cli footprint tune [options] INPUT... --verdicts VERDICTS.csv --config-out FILE.json\n"
    "Tunes the verdict criteria from the analyst's own verdicts. Every shot of the inputs (frames,\n"
    "folders, shot lists, as for `footprint`) is fitted once under the starting parameters (the\n"
    "defaults, or --config / --preset / --set); the shots with a verdict in VERDICTS.csv are then\n"
    "judged under moved thresholds (each end of the axis-ratio, major-axis, tilt and eccentricity\n"
    "ranges, mse_max, max_uncertainty_px, edge_extent, saturation_max_pixels, second_spot_fraction;\n"
    "those switched on), one at a time, for the fewest disagreements between good and not good. No\n"
    "move lets more shots the analyst did not call good through as good than the starting point did,\n"
    "and a threshold moves only for a gain, a quarter into the values that give it. Cross-validation\n"
    "(the shots in folds by name; each fold judged by criteria tuned on the others) says how the\n"
    "choice holds on shots it was not tuned on. Prints the confusion table before, after and held out.\n"
    "VERDICTS.csv: 'file' and 'verdict' columns (good, doubtful, rejected; empty or unreadable rows\n"
    "are left out), and 'roi' for frames of several ROIs: the workbench's review export (only its rows\n"
    "with a manual verdict, marked in its override column) and a `footprint` report have them. A row\n"
    "is matched to a shot by the frame's path (relative to the\n"
    "table's folder, else to the working folder), else by its file name where one frame alone has it.\n"
    "  --verdicts FILE.csv       the analyst's verdicts (required)\n"
    "  --config-out FILE.json    the tuned parameters, a config for `footprint --config` (required);\n"
    "                            beside it FILE.json.provenance.json (the tuning's record, the inputs)\n"
    "  --folds K                 cross-validation folds, 2-20 (default 5; 0 = none)\n"
    "  --config, --set, --preset, --method, --roi, --center, --metadata, --raw-size, --max-pixels,\n"
    "  --threads                 the starting point and the shots, as for `footprint`\n"
    "  -q, --quiet               no progress line, no tables\n") +
    "Then: laserwb-cli footprint INPUT... --config FILE.json -o OUT.csv applies it.\n"
    "Exit codes: 0 written, 1 a file could not be read or written, 2 usage (no verdicts, no shot\n"
    "with a verdict, verdicts of one kind only).\n";
}  // namespace

int cmdFootprintTune(int argc, char** argv) {
    const std::string cmd = "footprint tune";
    Args a(cmd, kTuneUsage);
    const FootprintOptions params;
    declareSourceOptions(a, params);
    for (const char* o : {"--verdicts", "--config-out", "--folds"}) a.option(o, true);
    for (const char* o : {"-q", "--quiet", "--help", "-h"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << a.usage();
        return kOk;
    }
    const bool quiet = a.has("-q") || a.has("--quiet");
    FootprintTuneSources src;
    std::string err;
    if (!gatherParams(a, params, &src.run, &err) || !gatherFrames(a, &src.run, &err)) return fail(cmd, err, kUsage);
    src.verdicts = a.value("--verdicts");
    const std::string out = a.value("--config-out");
    long long folds = 5;
    if (!a.getInt("--folds", 0, 20, &folds, &err)) return fail(cmd, err, kUsage);
    src.folds = static_cast<int>(folds);
    if (src.run.inputs.empty()) return fail(cmd, "no shots given (frames, folders or shot lists)", kUsage);
    if (src.verdicts.empty()) return fail(cmd, "--verdicts FILE.csv is required (the analyst's verdicts)", kUsage);
    if (out.empty()) return fail(cmd, "--config-out FILE.json is required (where the tuned parameters go)", kUsage);
    Progress progress("footprint tune", 1000, quiet);
    core::Feedback fb([&](double f) { progress.update(static_cast<size_t>(f * 1000)); });
    const FootprintTuneResult r = tuneFootprint(src, &fb);
    progress.finish();
    if (!r.ok) return fail(cmd, r.error.message, r.error.usage ? kUsage : kFailed);
    for (const std::string& n : r.notes) std::cerr << "laserwb-cli footprint tune: note: " << n << "\n";
    if (!writeTunedFootprintConfig(r, src, out, &err)) return fail(cmd, err);
    if (!quiet) {
        const VerdictTuneResult& t = r.tuning;
        std::cout << r.labelled << " shot(s) with a verdict of " << r.rois << " (" << r.shots << " frame(s))\n";
        if (t.changes.empty()) std::cout << "no criterion moved: the starting point is already the best found\n";
        for (const VerdictChange& c : t.changes)
            std::cout << "  " << c.name() << ": " << core::formatDouble(c.before, 4) << " -> " << core::formatDouble(c.after, 4) << "\n";
        std::cout << "before (the starting point):\n" << t.confusionBefore.text() << "after (tuned on these shots):\n"
                  << t.confusionAfter.text();
        if (t.folds)
            std::cout << "held out (" << t.folds << "-fold cross-validation: each shot judged by criteria tuned without it):\n"
                      << t.heldOut.text();
        std::cout << "written: " << out << "\n";
    }
    return kOk;
}
namespace {
const char* kSimUsage =
    "usage: laserwb-cli simulate footprint --count N --seed S [options] OUTDIR\n"
    "Writes simulated footprint shots with exact truth (OUTDIR/truth.csv).\n"
    "  --count N            number of shots (default 100; at most 1000000, and what the disk holds:\n"
    "                       checked before the first shot, at 2 bytes a pixel)\n"
    "  -q, --quiet          no progress line\n"
    "  --seed S             random seed (default 1); the same seed gives the same files\n"
    "  --scene NAME         weak|moderate|strong|night|flat|mixed (default mixed: the first four in turn)\n"
    "  --case NAME          normal|no_spot|saturated|double_spot|edge|elongated|mixed (default normal;\n"
    "                       mixed: two normal shots, then one of each doubtful case in turn)\n"
    "  --size N             ROI side (default 32)\n"
    "  --full-frame         550x550 frames with the spot near --center (default 122,262: LFI beam 1)\n"
    "  --center X,Y         spot position in full frames (within 3 px); give it twice for a two-beam\n"
    "                       frame (e.g. 60,311 and 228,158: paper 001's LSI beams; truth in x2,y2)\n"
    "  --format png|tif|pgm|raw   image format (default png)\n"
    "  --ground photo|synthetic|fractal|photo-cuts   ground: real aerial photographs (default;\n"
    "                       OpenCV's sample aerial views, shipped with the workbench), the older\n"
    "                       synthetic texture with roads, field edges and buildings, or a family the\n"
    "                       fit was not tuned on: fractal 1/f^beta ground (beta 1.5-3.5) with sharp\n"
    "                       edges and water, or the photographs cut finer and coarser in mixed bands\n"
    "  --photo aero1|aero3  photo ground from one photograph only\n";

// --ground NAME and --photo NAME into *sp; false with *err when a value is unknown or photos are missing.
bool groundOption(const Args& a, sim::FootprintSimParams* out, std::string* err) {
    sim::GroundSource* g = &out->ground;
    if (a.has("--ground") && !sim::parseGroundSource(a.value("--ground"), g)) {
        *err = "--ground must be photo, synthetic, fractal or photo-cuts, not \"" + a.value("--ground") + "\"";
        return false;
    }
    if (a.has("--photo")) {
        const std::string ph = a.value("--photo");
        if (ph != "aero1" && ph != "aero3") {
            *err = "--photo must be aero1 or aero3, not \"" + ph + "\"";
            return false;
        }
        out->photo = ph == "aero1" ? 0 : 1;
    }
    sim::FootprintSimParams sp;
    sp.ground = *g;
    *err = sim::groundProblem(sp);
    return err->empty();
}
}

// A stated limit and the disk, before the first shot (10^7 shots ran past 120 s unrefused):
// at most kMaxSimulatedShots, and no more bytes than the folder's file system has free (2 bytes
// a pixel: the 16-bit images uncompressed, an upper bound for PNG and TIFF).
constexpr long long kMaxSimulatedShots = 1000000;
int checkSimulationSize(const std::string& dir, long long count, long long side) {
    if (count > kMaxSimulatedShots)
        return fail("simulate footprint", "--count " + std::to_string(count) + ": at most " + std::to_string(kMaxSimulatedShots) +
                                              " shots a folder (simulate several folders, or --shard the run that reads them)",
                    kUsage);
    std::string where = dir;  // the nearest folder that exists
    struct stat st {};
    while (::stat(where.c_str(), &st) != 0 && where.find('/') != std::string::npos) where = where.substr(0, where.find_last_of('/'));
    if (::stat(where.c_str(), &st) != 0) where = ".";
    struct statvfs fs {};
    if (::statvfs(where.c_str(), &fs) != 0) return kOk;  // (no figure: the writes will say)
    const double need = double(count) * double(side) * double(side) * 2 + double(count) * 200;
    const double free = double(fs.f_bavail) * double(fs.f_frsize);
    if (need > free)
        return fail("simulate footprint", dir + ": " + std::to_string(count) + " shots of " + std::to_string(side) + "x" +
                                              std::to_string(side) + " px need up to " + core::formatFixed(need / 1e9, 2) + " GB; " +
                                              where + " has " + core::formatFixed(free / 1e9, 2) + " GB free; nothing written",
                    kFailed);
    return kOk;
}

int cmdSimulateFootprint(int argc, char** argv) {
    Args a("simulate footprint", kSimUsage);
    for (const char* o : {"--count", "--seed", "--scene", "--case", "--size", "--center", "--format", "--ground", "--photo"})
        a.option(o, true, std::string(o) == "--center");
    for (const char* o : {"--full-frame", "--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail("simulate footprint", a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kSimUsage;
        return kOk;
    }
    std::string err;
    long long count = 100, seed = 1, size = 32;
    if (!a.getInt("--count", 1, 10000000, &count, &err) || !a.getInt("--seed", 0, (1LL << 62), &seed, &err) ||
        !a.getInt("--size", 8, 4096, &size, &err))
        return fail("simulate footprint", err, kUsage);
    if (a.positional().size() != 1) return fail("simulate footprint", "give exactly one output folder", kUsage);
    const std::string dir = a.positional()[0];
    if (int rc = checkSimulationSize(dir, count, a.has("--full-frame") ? 550 : size)) return rc;
    const std::string fmt = a.value("--format", "png");
    if (fmt != "png" && fmt != "tif" && fmt != "pgm" && fmt != "raw")
        return fail("simulate footprint", "--format must be png, tif, pgm or raw", kUsage);
    std::vector<sim::Scene> scenes;
    const std::string sceneArg = a.value("--scene", "mixed");
    if (sceneArg == "mixed") {
        scenes = {sim::Scene::Weak, sim::Scene::Moderate, sim::Scene::Strong, sim::Scene::Night};
    } else {
        sim::Scene s;
        if (!sim::parseScene(sceneArg, &s)) return fail("simulate footprint", "unknown --scene " + sceneArg, kUsage);
        scenes = {s};
    }
    std::vector<sim::SpotCase> cases;
    const std::string caseArg = a.value("--case", "normal");
    if (caseArg == "mixed") {
        cases = {sim::SpotCase::Normal, sim::SpotCase::Normal, sim::SpotCase::NoSpot, sim::SpotCase::Normal,
                 sim::SpotCase::Normal, sim::SpotCase::Saturated, sim::SpotCase::Normal, sim::SpotCase::Normal,
                 sim::SpotCase::DoubleSpot, sim::SpotCase::Normal, sim::SpotCase::Normal, sim::SpotCase::Edge,
                 sim::SpotCase::Normal, sim::SpotCase::Normal, sim::SpotCase::Elongated};
    } else {
        sim::SpotCase c;
        if (!sim::parseSpotCase(caseArg, &c)) return fail("simulate footprint", "unknown --case " + caseArg, kUsage);
        cases = {c};
    }
    sim::FootprintSimParams sp;
    if (!groundOption(a, &sp, &err)) return fail("simulate footprint", err);
    sp.width = sp.height = static_cast<int>(size);
    if (a.has("--full-frame")) {
        sp.width = sp.height = 550;
        sp.hasCenter = true;
        sp.centerX = 122;
        sp.centerY = 262;
    }
    if (a.has("--center")) {
        if (!a.has("--full-frame")) return fail("simulate footprint", "--center goes with --full-frame", kUsage);
        const std::vector<std::string> centres = a.values("--center");
        if (centres.size() > 2) return fail("simulate footprint", "--center: one or two (the two beams of a frame)", kUsage);
        double* xs[2] = {&sp.centerX, &sp.center2X};
        double* ys[2] = {&sp.centerY, &sp.center2Y};
        for (size_t k = 0; k < centres.size(); ++k)
            if (!parsePoint(centres[k], xs[k], ys[k]) || !(*xs[k] >= 0 && *xs[k] <= 549 && *ys[k] >= 0 && *ys[k] <= 549))
                return fail("simulate footprint", "--center must be X,Y inside the 550x550 frame, not \"" + centres[k] + "\"",
                            kUsage);
        sp.hasSecondBeam = centres.size() == 2;
        if (sp.hasSecondBeam && caseArg != "normal")
            return fail("simulate footprint", "a two-beam frame (--center twice) takes normal spots only (--case normal)",
                        kUsage);
    }
    const FolderForOutputs folder(dir);
    if (!folder.ok()) return fail("simulate footprint", dir + ": cannot create the folder");
    core::OutputSet outs;
    auto shotName = [&](long long i) {
        char name[64];
        std::snprintf(name, sizeof name, "shot_%06lld.%s", i, fmt.c_str());
        return std::string(name);
    };
    for (long long i = 0; i < count; ++i) outs.addOutput(dir + "/" + shotName(i));
    outs.addOutput(dir + "/truth.csv");
    // truth.csv lists the set: written last, and an earlier run's shots go (a run killed half-way
    // leaves no truth.csv beside a mix of old and new shots).
    outs.setManifest(dir + "/truth.csv", dir, {"shot_[0-9]*.png", "shot_[0-9]*.tif", "shot_[0-9]*.pgm", "shot_[0-9]*.raw"});
    if (int rc = checkOutputs("simulate footprint", outs)) return rc;
    std::string truth =
        "file,scene,case,x,y,sigma_major,sigma_minor,tilt_deg,amplitude_dn,ground_mean_dn,texture_rms_dn,expect_good,x2,y2,"
        "ground\n";
    Progress progress("simulate", static_cast<size_t>(count), a.has("-q") || a.has("--quiet"));
    auto f = [](double v, int d) { return std::isfinite(v) ? core::formatFixed(v, d) : std::string(); };
    for (long long i = 0; i < count; ++i) {
        sp.scene = scenes[i % scenes.size()];
        sp.spotCase = cases[(i / scenes.size()) % cases.size()];
        const sim::FootprintSimShot shot = sim::simulateFootprint(sp, sim::Rng::mix(static_cast<uint64_t>(seed), i));
        const std::string name = shotName(i);
        if (!writeFrame16(outs.stagingPath(dir + "/" + name), shot.image, &err))
            return fail("simulate footprint", outs.unstaged(err));
        const auto& t = shot.truth;
        truth += name + "," + sim::sceneName(t.scene) + "," + sim::spotCaseName(t.spotCase) + "," +
                 f(t.x, 5) + "," + f(t.y, 5) + "," + f(t.sigmaMajor, 4) + "," + f(t.sigmaMinor, 4) + "," +
                 f(t.tiltRad * 180 / M_PI, 3) + "," + f(t.amplitude, 1) + "," + f(t.groundMean, 1) + "," +
                 f(t.textureRms, 1) + "," + (t.expectGood ? "1" : "0") + "," + f(t.x2, 5) + "," + f(t.y2, 5) + "," +
                 (t.groundPhoto || t.groundNote.rfind("fractal", 0) == 0 ? t.groundNote : "synthetic") + "\n";
        progress.update(static_cast<size_t>(i + 1));
    }
    progress.finish();
    if (!core::writeFileAtomic(outs.stagingPath(dir + "/truth.csv"), truth, &err))
        return fail("simulate footprint", outs.unstaged(err));
    if (int rc = commitOutputs("simulate footprint", outs)) return rc;
    folder.keep();
    return kOk;
}

namespace {
const std::string kTrendUsage =
    "usage: laserwb-cli trend IN.csv -o OUT.csv [--arcsec-per-px A] [--reject-sigma K] [--min-shots N]\n"
    "Monthly mean spot centroid per camera and beam (paper 001 long-term monitoring).\n"
    "IN.csv: header time,beam,x,y[,camera]; time as ISO date/date-time, YYYY-MM, or Unix seconds.\n"
    "        A footprint report (laserwb-cli footprint -o report.csv, the workbench's review export) is\n"
    "        read directly: its shots judged good with a time and a beam (the others are counted).\n"
    "OUT.csv: camera,beam,month,n,rejected,x_mean,y_mean,x_std,y_std,dx_px,dy_px,planar_change_px,\n"
    "         pointing_change_arcsec,beam_distance_px,distance_change_px (changes from the first month).\n"
    "  --arcsec-per-px A    pointing change per pixel (default {default:arcsec_per_px}, paper 001's LFC) = --set arcsec_per_px=A\n"
    "  --reject-sigma K     k-sigma rejection of shots within a month (default {default:reject_sigma}; 0 = off) = --set reject_sigma=K\n"
    "  --min-shots N        leave out months with fewer shots (default {default:min_shots}) = --set min_shots=N\n"
    "  -o, --output OUT.csv the table; beside it OUT.csv.provenance.json (version, parameters, SHA-256\n"
    "                       of the input and the output)\n"
    "\n" + ParamOptions<TrendParams>::paramsHelp("trend", "reject_sigma=2.5");
}

namespace {
const char* kSimTrendUsage =
    "usage: laserwb-cli simulate trend OUT.csv [--months N] [--shots N] [--seed S] [--truth TRUTH.csv]\n"
    "Writes a simulated spot-centroid table (time,beam,x,y,camera) of both beams of the LFI footprint\n"
    "camera over N months, as `laserwb-cli trend` reads it: each beam's true centre drifts (a linear\n"
    "trend and an annual cycle drawn from the seed), shots scatter about it by 0.15 px and 2 % of them\n"
    "are outliers 1.5-4 px off. The exact monthly centres go to --truth.\n"
    "  --months N           consecutive months from 2020-03 (default 12)\n"
    "  --shots N            shots per beam and month (default 20)\n"
    "  --seed S             random seed (default 1); the same seed gives the same table\n"
    "  --truth TRUTH.csv    camera,beam,month,x_true,y_true\n"
    "  -q, --quiet          no summary\n";
}

int cmdSimulateTrend(int argc, char** argv) {
    const std::string cmd = "simulate trend";
    Args a(cmd, kSimTrendUsage);
    for (const char* o : {"--months", "--shots", "--seed", "--truth"}) a.option(o, true);
    if (int rc = a.parseWithHelp(argc, argv, 3); rc >= 0) return rc;
    sim::CentroidSimParams p;
    long long months = p.months, shots = p.shotsPerMonth, seed = 1;
    std::string err;
    if (!a.getInt("--months", 1, 600, &months, &err) || !a.getInt("--shots", 1, 100000, &shots, &err) ||
        !a.getInt("--seed", 0, 1LL << 62, &seed, &err))
        return fail(cmd, err, kUsage);
    if (a.positional().size() != 1) return fail(cmd, "give exactly one output file (OUT.csv)", kUsage);
    p.months = static_cast<int>(months);
    p.shotsPerMonth = static_cast<int>(shots);
    const std::string out = a.positional()[0], truthOut = a.value("--truth");
    core::OutputSet outs;
    outs.addOutput(out);
    if (a.has("--truth")) outs.addOutput(truthOut);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    const sim::CentroidSimulation s = sim::simulateCentroids(p, static_cast<uint64_t>(seed));
    if (!s.ok) return fail(cmd, s.error);
    std::string table = "time,beam,x,y,camera\n";
    size_t outliers = 0;
    for (const auto& shot : s.shots) {
        table += shot.time + "," + std::to_string(shot.beam) + "," + core::formatFixed(shot.x, 3) + "," +
                 core::formatFixed(shot.y, 3) + "," + p.camera + "\n";
        outliers += shot.outlier;
    }
    if (!core::writeFileAtomic(outs.stagingPath(out), table, &err)) return fail(cmd, outs.unstaged(err));
    if (a.has("--truth")) {
        std::string truth = "camera,beam,month,x_true,y_true\n";
        for (const auto& t : s.truth)
            truth += p.camera + "," + std::to_string(t.beam) + "," + t.month + "," + core::formatFixed(t.x, 4) + "," +
                     core::formatFixed(t.y, 4) + "\n";
        if (!core::writeFileAtomic(outs.stagingPath(truthOut), truth, &err)) return fail(cmd, outs.unstaged(err));
    }
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!a.quiet())
        std::cerr << cmd << ": " << s.shots.size() << " shots (" << outliers << " outliers), " << p.months
                  << " months, 2 beams -> " << out << "\n";
    return kOk;
}

int cmdTrend(int argc, char** argv) {
    Args a("trend", kTrendUsage);
    const ParamOptions<TrendParams> params(
        trendSchema(), {{"--arcsec-per-px", "arcsec_per_px"}, {"--reject-sigma", "reject_sigma"}, {"--min-shots", "min_shots"}});
    for (const char* o : {"-o", "--output"}) a.option(o, true);
    if (int rc = params.parseWithHelp(a, argc, argv, 2); rc >= 0) return rc;
    TrendParams tp;
    std::string err;
    if (int rc = params.apply("trend", a, &tp)) return rc;
    if (params.printRequested(a)) {
        std::cout << params.json(tp);
        return kOk;
    }
    const std::string out = a.has("-o") ? a.value("-o") : a.value("--output");
    if (out.empty()) return fail("trend", "no output file: give -o OUT.csv", kUsage);
    if (a.positional().size() != 1) return fail("trend", "give exactly one input CSV", kUsage);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    outs.addOutput(out);
    const bool toStdout = core::isStandardStream(out);
    const std::string sidecar = core::provenancePathFor(out);
    if (!toStdout) outs.addOutput(sidecar);
    if (int rc = checkOutputs("trend", outs)) return rc;
    std::vector<CentroidRecord> recs;
    std::string note;
    if (!readCentroidCsv(a.positional()[0], &recs, &err, &note)) return fail("trend", err);
    if (!note.empty() && !a.quiet()) std::cerr << "trend: " << a.positional()[0] << ": " << note << "\n";
    const TrendResult tr = computeTrend(recs, tp);
    if (!tr.ok) return fail("trend", tr.error);
    warnings("trend", tr.warnings, a.quiet());
    if (!writeTrendCsv(outs.stagingPath(out), tr.rows, &err)) return fail("trend", outs.unstaged(err));
    core::Provenance prov;
    prov.command = "trend";
    prov.parameters = trendSchema().toJson(tp);
    prov.inputs = {a.positional()[0], a.value("--config")};
    if (!toStdout && !stageProvenance(outs, prov, {out}, sidecar, &err)) return fail("trend", err);
    if (int rc = commitOutputs("trend", outs)) return rc;
    if (!(a.has("-q") || a.has("--quiet"))) {
        // Summary: first → last month change per camera/beam.
        for (size_t i = 0; i < tr.rows.size(); ++i) {
            const bool last = i + 1 == tr.rows.size() || tr.rows[i + 1].camera != tr.rows[i].camera ||
                              tr.rows[i + 1].beam != tr.rows[i].beam;
            if (!last) continue;
            const auto& r = tr.rows[i];
            std::cerr << "trend: " << (r.camera.empty() ? "" : r.camera + " ") << "beam " << r.beam << " to " << r.month
                      << ": planar change " << core::formatFixed(r.planarPx, 2) << " px = "
                      << core::formatFixed(r.pointingArcsec, 3) << " arcsec\n";
        }
    }
    return kOk;
}

namespace {
const char* kEvalUsage =
    "usage: laserwb-cli eval footprint [--count N] [--seed S] [--case NAME] [--variants a,b,...] [--threads N]\n"
    "Paper 000's accuracy experiment on the simulator: N shots per scene (weak, moderate, strong,\n"
    "night, flat), each processed by every method variant; prints a Markdown table of radial errors\n"
    "against the exact truth, verdict counts and the Cramer-Rao bound.\n"
    "Variants: gcm, tefm, gauss-paper, gauss-xy, gauss-guo, gauss (default: all).\n"
    "  --config FILE.json   add a variant \"config\": the defaults overridden by the file\n"
    "  -q, --quiet          no progress line\n"
    "  --scenes a,b         scenes to run (weak,moderate,strong,night,flat)\n"
    "  --ground photo|synthetic|fractal|photo-cuts   simulator ground (default photo: real aerial\n"
    "                       photographs; fractal and photo-cuts: families the fit was not tuned on)\n"
    "  --photo aero1|aero3  photo ground from one photograph only\n";
}

int cmdEvalFootprint(int argc, char** argv) {
    Args a("eval footprint", kEvalUsage);
    for (const char* o : {"--count", "--seed", "--case", "--variants", "--threads", "--scenes", "--config", "--ground", "--photo"})
        a.option(o, true);
    for (const char* o : {"--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail("eval footprint", a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kEvalUsage;
        return kOk;
    }
    sim::EvalParams ep;
    std::string err;
    long long count = ep.countPerScene, seed = static_cast<long long>(ep.seed), threads = 0;
    if (!a.getInt("--count", 1, 10000000, &count, &err) || !a.getInt("--seed", 0, 1LL << 62, &seed, &err) ||
        !a.getInt("--threads", 0, 256, &threads, &err))
        return fail("eval footprint", err, kUsage);
    ep.countPerScene = static_cast<int>(count);
    ep.seed = static_cast<uint64_t>(seed);
    ep.threads = static_cast<int>(threads);
    if (!groundOption(a, &ep.sim, &err)) return fail("eval footprint", err);
    if (a.has("--case") && !sim::parseSpotCase(a.value("--case"), &ep.spotCase))
        return fail("eval footprint", "unknown --case " + a.value("--case"), kUsage);
    if (a.has("--scenes")) {
        ep.scenes.clear();
        std::string list = a.value("--scenes");
        for (char& c : list)
            if (c == ',') c = ' ';
        for (auto s : core::splitBlanks(list)) {
            sim::Scene sc;
            if (!sim::parseScene(std::string(s), &sc)) return fail("eval footprint", "unknown scene " + std::string(s), kUsage);
            ep.scenes.push_back(sc);
        }
    }
    std::vector<sim::MethodVariant> variants;
    if (a.has("--variants")) {
        std::string list = a.value("--variants");
        for (char& c : list)
            if (c == ',') c = ' ';
        for (auto v : core::splitBlanks(list)) {
            sim::MethodVariant mv;
            if (!sim::findVariant(std::string(v), &mv)) return fail("eval footprint", "unknown variant " + std::string(v), kUsage);
            variants.push_back(mv);
        }
    } else {
        variants = sim::standardVariants();
    }
    if (a.has("--config")) {
        // A variant "config" with the default parameters overridden by the file.
        sim::MethodVariant mv{"config", {}};
        const core::JsonParseResult j = core::readJsonFile(a.value("--config"));
        if (!j.ok) return fail("eval footprint", j.error);
        if (!footprintParamsFromJson(j.value, &mv.params, &err, &j)) return fail("eval footprint", err);
        variants.push_back(mv);
    }
    const bool quiet = a.has("-q") || a.has("--quiet");
    Progress progress("eval", static_cast<size_t>(count) * ep.scenes.size(), quiet);
    core::Feedback fb([&](double f) { progress.update(static_cast<size_t>(f * count * ep.scenes.size())); });
    const auto stats = sim::evaluateFootprint(ep, variants, &fb, &err);
    progress.finish();
    if (stats.empty()) return fail("eval footprint", err.empty() ? "nothing evaluated" : err);
    std::cout << sim::evalTableMarkdown(stats);
    return kOk;
}

namespace {
const char* kBenchUsage =
    "usage: laserwb-cli bench footprint [--count N] [--seconds S] [--seed S] [--rounds R]\n"
    "ROIs per second on one core for each method variant, on N simulated 32x32 ROIs (weak, moderate,\n"
    "strong and night in turn, photo ground, decoded in memory), plus the default pipeline with 16-bit\n"
    "PNG decoding, the default pipeline with the quick uncertainty instead of the ground covariance,\n"
    "and the multi-threaded batch throughput, each with its ratio to gcm's ROIs per second; then\n"
    "the default pipeline's cost per stage.\n"
    "Every figure is the best of R rounds (default 3), the rows of a table taking their rounds in turn, so\n"
    "that load on a shared machine spreads over every row. Prints Markdown tables.\n";

// The bench's state across its tables: the simulated ROIs (as float images and as their 16-bit
// PNG encodings), the timing's settings, the default parameters and the checksum every timed
// call adds to.
struct FootprintBench {
    using clock = std::chrono::steady_clock;

    FootprintBench(long long roundCount, double secondsPerRow) : rounds(roundCount), seconds(secondsPerRow) {}

    long long rounds;
    double seconds;
    std::vector<cv::Mat> rois;
    std::vector<std::vector<uchar>> pngs;
    const FootprintParams def;
    size_t sink = 0;

    void simulateRois(long long count, long long seed);
    double timeOnce(const std::function<void(size_t)>& one) const;
    std::vector<double> bestOfInterleaved(const std::vector<std::function<void(size_t)>>& fns) const;
    void variantTable();
    void threadsRow();
    void stageTable();
};

// The ROIs: weak, moderate, strong and night in turn, photo ground.
void FootprintBench::simulateRois(long long count, long long seed) {
    const sim::Scene scenes[] = {sim::Scene::Weak, sim::Scene::Moderate, sim::Scene::Strong, sim::Scene::Night};
    for (long long i = 0; i < count; ++i) {
        sim::FootprintSimParams sp;
        sp.scene = scenes[i % 4];
        const auto shot = sim::simulateFootprint(sp, sim::Rng::mix(static_cast<uint64_t>(seed), i));
        cv::Mat f;
        shot.image.convertTo(f, CV_32F);
        rois.push_back(f);
        std::vector<uchar> buf;
        core::imageEncode(".png", shot.image, buf);
        pngs.push_back(std::move(buf));
    }
}

// Each row timed for `seconds` per round; the rounds go over every row of a table in turn
// (row 1, row 2, …, row 1, row 2, …), so that a burst of load on a shared machine falls on
// one round of every row rather than on all rounds of one, and each row keeps its best.
double FootprintBench::timeOnce(const std::function<void(size_t)>& one) const {
    size_t n = 0;
    const auto t0 = clock::now();
    double el = 0;
    do {
        one(n % rois.size());
        ++n;
        if (n % 64 == 0) el = std::chrono::duration<double>(clock::now() - t0).count();
    } while (el < seconds);
    el = std::chrono::duration<double>(clock::now() - t0).count();
    return n / el;
}

// Each row's best rate (ROIs per second) over the rounds.
std::vector<double> FootprintBench::bestOfInterleaved(const std::vector<std::function<void(size_t)>>& fns) const {
    std::vector<double> best(fns.size(), 0.0);
    for (long long r = 0; r < rounds; ++r)
        for (size_t k = 0; k < fns.size(); ++k) best[k] = std::max(best[k], timeOnce(fns[k]));
    return best;
}

// The table of the method variants, the quick uncertainty and the 16-bit PNG decoding, each row
// with its ratio to gcm.
void FootprintBench::variantTable() {
    // The ratio to gcm (the plain centroid, with the same background, segmentation and verdict)
    // is issue 32's speed figure: ROIs per second of the row over those of gcm, in this run.
    std::cout << "| pipeline | ROIs/s (1 core) | µs per ROI | ratio to gcm |\n|---|---|---|---|\n";
    double gcmRate = 0;
    auto row = [&](const std::string& name, double rate, double us) {
        std::cout << "| " << name << " | " << core::formatFixed(rate, 0) << " | " << core::formatFixed(us, 1) << " | "
                  << (gcmRate > 0 ? core::formatFixed(rate / gcmRate, 2) : std::string("-")) << " |\n";
    };
    FootprintParams quick = def;
    quick.gauss.uncertaintyFromGround = false;
    std::vector<std::string> names;
    std::vector<std::function<void(size_t)>> fns;
    const auto variants = sim::standardVariants();
    for (const auto& v : variants) {
        names.push_back(v.name + (v.name == "gauss" ? " (default)" : ""));
        fns.push_back([&](size_t i) { sink += processRoi(rois[i], v.params).verdict == Verdict::Good; });
    }
    names.push_back("gauss, quick uncertainty (gauss.uncertainty_from_ground off)");
    fns.push_back([&](size_t i) { sink += processRoi(rois[i], quick).verdict == Verdict::Good; });
    names.push_back("gauss + 16-bit PNG decode");
    fns.push_back([&](size_t i) {
        cv::Mat img = core::imageDecode(cv::Mat(pngs[i]), cv::IMREAD_UNCHANGED), f;
        img.convertTo(f, CV_32F);
        sink += processRoi(f, def).verdict == Verdict::Good;
    });
    const std::vector<double> rates = bestOfInterleaved(fns);
    for (size_t k = 0; k < variants.size(); ++k)
        if (variants[k].name == "gcm") gcmRate = rates[k];
    for (size_t k = 0; k < fns.size(); ++k) row(names[k], rates[k], 1e6 / rates[k]);
}

// The multi-threaded batch throughput row.
void FootprintBench::threadsRow() {
    // All cores: the same default pipeline over the ROIs on every hardware thread.
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    std::atomic<size_t> total{0};
    const auto t0 = clock::now();
    core::runOnThreads(hw, [&](size_t t) {
            size_t n = 0, s = 0;
            while (std::chrono::duration<double>(clock::now() - t0).count() < seconds)
                for (int k = 0; k < 32; ++k, ++n) s += processRoi(rois[(n * hw + t) % rois.size()], def).ok;
            total += n;
            (void)s;
        });
    const double el = std::chrono::duration<double>(clock::now() - t0).count();
    std::cout << "| gauss, " << hw << " threads | " << core::formatFixed(total / el, 0) << " (all cores) | "
              << core::formatFixed(1e6 * el * hw / total, 1) << " per thread | |\n";
}

// The table of the default pipeline's cost per stage.
void FootprintBench::stageTable() {
    // The default pipeline stage by stage: each stage alone over the ROIs, on the inputs the
    // earlier stages produced (computed once beforehand).
    std::vector<BackgroundResult> bgs;
    std::vector<SpotDomain> domains;
    for (const auto& r : rois) {
        bgs.push_back(estimateBackground(r, def.background));
        domains.push_back(segmentSpot(r, bgs.back().level, bgs.back().noise, def.camera.saturationDn, def.segment));
    }
    GaussParams logOnly = def.gauss;
    logOnly.lmRefine = false;
    std::vector<GaussResult> fits(rois.size());
    for (size_t i = 0; i < rois.size(); ++i)
        fits[i] = fitGauss(rois[i], domains[i], bgs[i].level, bgs[i].noise, def.gauss, def.camera);
    struct Stage {
        const char* name;
        std::function<void(size_t)> fn;
    };
    const std::vector<Stage> stages = {
        {"background (clipped median, noise class)",
         [&](size_t i) { sink += estimateBackground(rois[i], def.background).ok; }},
        {"segmentation (peak, domain, opening, holes, second spot, ring look)",
         [&](size_t i) {
             sink += segmentSpot(rois[i], bgs[i].level, bgs[i].noise, def.camera.saturationDn, def.segment).found;
         }},
        {"Gaussian without LM (Wu + Guo, ground differences, covariance, MSE)",
         [&](size_t i) { sink += fitGauss(rois[i], domains[i], bgs[i].level, bgs[i].noise, logOnly, def.camera).fit.ok; }},
        {"Gaussian with LM (the default fit)",
         [&](size_t i) { sink += fitGauss(rois[i], domains[i], bgs[i].level, bgs[i].noise, def.gauss, def.camera).fit.ok; }},
        {"verdict + closed-form CRLB",
         [&](size_t i) {
             const Judgement j = judge(fits[i].fit, domains[i], rois[i].cols, rois[i].rows, def.verdict);
             const CrlbResult c = crlbClosedForm(fits[i].fit.amplitude, fits[i].fit.sigmaX, fits[i].fit.sigmaY,
                                                 fits[i].fit.background, def.camera, false);
             sink += (j.verdict == Verdict::Good) + c.ok;
         }},
        {"whole default pipeline (processRoi)", [&](size_t i) { sink += processRoi(rois[i], def).ok; }},
    };
    std::cout << "\n| stage (default pipeline) | µs per ROI | ROIs/s (1 core) |\n|---|---|---|\n";
    std::vector<std::function<void(size_t)>> stageFns;
    for (const auto& st : stages) stageFns.push_back(st.fn);
    const std::vector<double> stageRates = bestOfInterleaved(stageFns);
    for (size_t k = 0; k < stages.size(); ++k)
        std::cout << "| " << stages[k].name << " | " << core::formatFixed(1e6 / stageRates[k], 1) << " | "
                  << core::formatFixed(stageRates[k], 0) << " |\n";
}

}

int cmdBenchFootprint(int argc, char** argv) {
    Args a("bench footprint", kBenchUsage);
    for (const char* o : {"--count", "--seconds", "--seed", "--rounds"}) a.option(o, true);
    for (const char* o : {"--help", "-h"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail("bench footprint", a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kBenchUsage;
        return kOk;
    }
    std::string err;
    long long count = 2000, seed = 7, rounds = 3;
    double seconds = 2.0;
    if (!a.getInt("--count", 10, 1000000, &count, &err) || !a.getDouble("--seconds", 0.05, 600, &seconds, &err) ||
        !a.getInt("--seed", 0, 1LL << 62, &seed, &err) || !a.getInt("--rounds", 1, 100, &rounds, &err))
        return fail("bench footprint", err, kUsage);
    FootprintBench b(rounds, seconds);
    b.simulateRois(count, seed);
    b.variantTable();
    b.threadsRow();
    b.stageTable();
    std::cerr << "(" << count << " distinct ROIs, best of " << rounds << " rounds of " << core::formatFixed(seconds, 1)
              << " s per row, the rows of a table taking their rounds in turn; checksum " << b.sink << ")\n";
    return kOk;
}

}  // namespace lwb::cli
