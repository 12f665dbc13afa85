#include "core/slr/slr_run.hpp"

#include "core/slr/pass_report.hpp"
#include "core/slr/slr_params.hpp"

#include <cmath>
#include <exception>
#include <fstream>

#include <sys/stat.h>

#include "core/common/atomic_file.hpp"
#include "core/common/memory.hpp"
#include "core/common/text.hpp"
#include "core/slr/np_compare.hpp"
#include "core/slr/pass_output.hpp"

namespace lwb::core::slr {

namespace {

// The config file and the config given directly, then the settings, over *p (the schema's
// messages, with FILE:LINE:COL for the file). `configDoc` null: the file is read here.
bool applyAnalystSettings(const SlrSources& src, const JsonParseResult* configDoc, SlrParams* p, SlrError* error) {
    std::string err;
    if (configDoc && !slrSchema().fromJson(configDoc->value, p, &err, configDoc)) {
        *error = {err, false};
        return false;
    }
    if (!src.config.is_null() && !slrSchema().fromJson(src.config, p, &err)) {
        *error = {err, true};
        return false;
    }
    for (const ParamSetting& s : src.set)
        if (!slrSchema().setFromText(p, s.key, s.value, &err)) {
            *error = {(s.label.empty() ? s.key + "=" + s.value : s.label) + ": " + err, true};
            return false;
        }
    return true;
}

bool readConfig(const SlrSources& src, JsonParseResult* doc, SlrError* error) {
    if (src.configFile.empty()) return true;
    *doc = readJsonFile(src.configFile);
    if (!doc->ok) {
        *error = {doc->error, false};
        return false;
    }
    return true;
}

std::string named(const std::string& path, const std::string& msg) {
    return msg.rfind(path, 0) == 0 ? msg : path + ": " + msg;
}

// Peak memory of a pass's run for each byte of its file, measured on simulated kHz passes of
// 10^5..10^7 events (docs/benchmarks.md, "A raw kHz pass end to end"): CRD 191-220 bytes an
// event for 55-byte lines at 10^6..10^7 (3.3-3.8; its type-10 lines read again from the file),
// 4.6 for a gzip file (its lines kept in memory; of the decompressed bytes), an O-C CSV 124-159
// for 35-byte lines (4.5); rounded up. Real CRD lines are longer (fewer events a byte), so the
// estimate errs high.
constexpr uint64_t kCrdBytesPerFileByte = 5, kCsvBytesPerFileByte = 5, kProcessBytes = 32u << 20;

// "" when the input's run fits the memory this process can take (core/common/memory.hpp), else
// why it is not read: issue 44's "limits said, not hit", before any of it is read. A gzip file
// counts by the size it decompresses to (its trailer's ISIZE). Standard input is not checked.
std::string inputMemoryProblem(const std::string& path, bool crd) {
    if (path.empty() || path == "-") return {};
    // Only a regular file is looked into (opening a FIFO would wait for its writer): anything
    // else, missing or unreadable, is the reader's to refuse with its own message.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size <= 0) return {};
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    const std::streamoff size = st.st_size;
    uint64_t bytes = static_cast<uint64_t>(size);
    unsigned char head[2] = {0, 0}, tail[4] = {0, 0, 0, 0};
    in.seekg(0);
    in.read(reinterpret_cast<char*>(head), 2);
    if (head[0] == 0x1f && head[1] == 0x8b && size > 18) {
        in.seekg(size - 4);
        in.read(reinterpret_cast<char*>(tail), 4);
        const uint64_t isize = tail[0] | tail[1] << 8 | tail[2] << 16 | static_cast<uint64_t>(tail[3]) << 24;
        bytes = std::max(bytes, isize);  // (ISIZE is modulo 4 GiB: never below the compressed size)
    }
    const uint64_t need = bytes * (crd ? kCrdBytesPerFileByte : kCsvBytesPerFileByte) + kProcessBytes;
    const std::string why = memoryShortfall(
        need, availableMemory(),
        "its " + formatFixed(static_cast<double>(bytes) / 1e6, 1) + " MB of " + (crd ? "CRD" : "O-C table") + " (" +
            std::to_string(crd ? kCrdBytesPerFileByte : kCsvBytesPerFileByte) + " bytes for each byte of it, measured)");
    return why.empty() ? why : path + ": " + why + ": not read";
}

}  // namespace

bool resolveBaseParams(const SlrSources& sources, SlrParams* out, SlrError* error) {
    JsonParseResult doc;
    if (!readConfig(sources, &doc, error)) return false;
    SlrParams p = commandDefaults();
    if (!applyAnalystSettings(sources, sources.configFile.empty() ? nullptr : &doc, &p, error)) return false;
    *out = p;
    return true;
}

bool setUpSlrRun(const SlrSources& sources, SlrSetup* out, SlrError* error) {
    SlrSetup s;
    s.sources = sources;
    if (!sources.cpf.empty() && sources.stations.empty() && !sources.listOnly) {
        *error = {"the prediction (CPF) and the station coordinates (SINEX) go together: O-C from the prediction needs both", true};
        return false;
    }
    if (!sources.satellite.empty() && sources.presets.empty()) {
        *error = {"a satellite name selects a preset entry: give the presets file with it", true};
        return false;
    }
    // The settings first: a bad option or config stops the run before any file is read.
    JsonParseResult doc;
    if (!readConfig(sources, &doc, error)) return false;
    s.base = commandDefaults();
    if (!applyAnalystSettings(sources, sources.configFile.empty() ? nullptr : &doc, &s.base, error)) return false;
    if (!sources.configFile.empty()) s.config = doc.value;
    if (!sources.presets.empty()) {
        const PresetsResult pr = loadPresets(sources.presets);
        if (!pr.ok) {
            *error = {named(sources.presets, pr.error), false};
            return false;
        }
        s.presets = pr.presets;
        s.havePresets = true;
    }
    auto predictions = std::make_shared<PassSources>();
    if (!sources.stations.empty() || (sources.listOnly && !sources.cpf.empty())) {  // (listed: a CPF checked alone)
        PassInputParams in;
        in.cpfPath = sources.cpf;
        in.sinexPath = sources.stations;
        std::string err;
        if (!readPassSources(in, predictions.get(), &err)) {
            *error = {err, false};
            return false;
        }
    }
    s.predictions = std::move(predictions);
    if (!setStationNormalPoints(&s, sources.stationNormalPoints, error)) return false;
    *out = std::move(s);
    return true;
}

bool setStationNormalPoints(SlrSetup* setup, const std::string& path, SlrError* error) {
    std::shared_ptr<const CrdFile> file;
    if (!path.empty()) {
        CrdFile f;
        std::string err;
        if (!loadStationNormalPoints(path, &f, &err)) {
            *error = {err, false};
            return false;
        }
        file = std::make_shared<const CrdFile>(std::move(f));
    }
    setup->sources.stationNormalPoints = path;
    setup->stationNormalPoints = std::move(file);
    return true;
}

bool resolvePassParams(const SlrSetup& setup, const PassData& pass, PassSettings* out, SlrError* error) {
    PassSettings s;
    s.params = commandDefaults();
    std::string err;
    if (setup.havePresets && !applyPreset(pass, setup.presets, setup.sources.satellite, &s.params, &s.presetName, &err)) {
        *error = {named(setup.sources.presets, err), false};
        return false;
    }
    // The config as read at set-up (its file's locations are gone: the keys name it).
    if (!setup.sources.configFile.empty() && !slrSchema().fromJson(setup.config, &s.params, &err)) {
        *error = {setup.sources.configFile + ": " + err, false};
        return false;
    }
    if (!applyAnalystSettings(setup.sources, nullptr, &s.params, error)) return false;
    // The O-C was computed when the pass was opened, with the oc.* rows of the set-up that opened
    // it: other values here (a preset's, or parameters given after the pass was loaded) would be
    // shown and never used.
    if (pass.ocComputed) {
        SlrParams opened = s.params;
        opened.oc = pass.ocParams;
        opened.ownTrend = pass.ownTrendParams;
        if (slrSchema().toJson(opened) != slrSchema().toJson(s.params)) {
            *error = {(s.presetName.empty() ? std::string("the parameters set") : "preset " + s.presetName + " sets") +
                          " oc.* rows other than the pass's O-C was computed with: the O-C is computed when the pass "
                          "is opened; give them in the config or with --set (Python: load_pass(params=...))",
                      true};
            return false;
        }
    }
    // What the pass tells, wherever the parameters leave it unknown (a printed config's 0 is not a value).
    s.notes = passNormalPointContext(pass, setup.stations(), &s.params.postfit);
    s.params.screen.searchThreads = setup.sources.searchThreads;
    if (const std::string e = slrSchema().validate(s.params); !e.empty()) {
        *error = {(s.presetName.empty() ? std::string() : "preset " + s.presetName + ": ") + e, true};
        return false;
    }
    *out = std::move(s);
    return true;
}

namespace {

// The pass of `loaded` (ok) resolved, or its error.
OpenedPass finishOpen(const SlrSetup& setup, PassInputResult loaded, std::shared_ptr<const CrdReadResult> crd) {
    OpenedPass o;
    o.crd = std::move(crd);
    o.warnings = std::move(loaded.warnings);
    o.notes = std::move(loaded.notes);
    o.passes = loaded.passes.empty() && o.crd ? summarisePasses(o.crd->file) : std::move(loaded.passes);
    if (!loaded.ok) {
        o.error = {named(setup.sources.input, loaded.error), loaded.notAPass};
        return o;
    }
    // A record of the pass that the reader had to skip ("FILE:LINE: ..."): the point is missing
    // from the screening and the damaged line would be written back as it is. Refused.
    if (!loaded.pass.damaged.empty() && !setup.sources.openDamaged) {
        o.error = {loaded.pass.damaged + "; nothing written", false};
        return o;
    }
    auto pass = std::make_shared<const PassData>(std::move(loaded.pass));
    if (!resolvePassParams(setup, *pass, &o.settings, &o.error)) return o;
    o.pass = std::move(pass);
    o.ok = true;
    return o;
}

PassInputParams inputParams(const SlrSetup& setup) {
    PassInputParams in;
    in.oc = setup.base.oc;  // (the O-C's rows: the config and the settings, before any preset)
    in.trend = setup.base.ownTrend;
    in.cpfPath = setup.sources.cpf;
    in.sinexPath = setup.sources.stations;
    in.cpfFallback = setup.sources.cpfFallback;
    return in;
}

}  // namespace

LoadedSlrPass loadSlrPass(const SlrSources& sources, const Feedback* fb) {
    LoadedSlrPass l;
    if (!setUpSlrRun(sources, &l.setup, &l.error)) return l;
    l.setUp = true;
    if (sources.listOnly) {  // (the input's blocks listed, none opened)
        if (!sources.input.empty()) {
            l.opened.crd = readSlrInput(sources, &l.error, fb);
            if (!l.opened.crd) return l;
            l.opened.passes = summarisePasses(l.opened.crd->file);
        }
        l.opened.ok = l.ok = true;
        return l;
    }
    l.opened = openPass(l.setup, fb);
    if (!l.opened.ok) {
        l.error = l.opened.error;
        return l;
    }
    l.ok = true;
    return l;
}

std::shared_ptr<const CrdReadResult> readSlrInput(const SlrSources& sources, SlrError* error, const Feedback* fb) {
    if (std::string why = inputMemoryProblem(sources.input, true); !why.empty()) {
        *error = {std::move(why), false};
        return nullptr;
    }
    auto crd = std::make_shared<const CrdReadResult>(readCrd(sources.input, {}, fb));
    if (!crd->ok) {
        *error = {named(sources.input, crd->error), false};
        for (size_t i = 0; i < crd->warnings.size() && i < 5; ++i) error->message += "\n  " + crd->warnings[i];
        return nullptr;
    }
    return crd;
}

OpenedPass openPassOf(const SlrSetup& setup, const std::shared_ptr<const CrdReadResult>& crd, int passIndex,
                      const Feedback* fb) {
    PassInputResult loaded = passFromCrd(crd, setup.sources.input, passIndex, inputParams(setup), *setup.predictions, fb);
    return finishOpen(setup, std::move(loaded), crd);
}

OpenedPass openPass(const SlrSetup& setup, const Feedback* fb) {
    const std::string& input = setup.sources.input;
    if (const OcArrays* a = setup.sources.arrays.get()) {  // (a pass given as its columns is an O-C table's pass)
        if (setup.sources.passNumber > 1 || !setup.sources.cpf.empty() || !input.empty()) {
            OpenedPass o;
            o.error = {a->name + ": a pass given as arrays is one O-C table's pass (no file, pass number or prediction)", true};
            return o;
        }
        return finishOpen(setup, passFromOc(a->t, a->oc, a->name), nullptr);
    }
    if (!isCrdFile(input)) {
        // (an O-C table is one pass: pass 1 of it is that pass)
        if (setup.sources.passNumber > 1 || !setup.sources.cpf.empty()) {
            OpenedPass o;
            o.error = {std::string(setup.sources.passNumber > 0 ? "a pass number" : "a prediction (CPF)") +
                           " applies to a CRD input; " + input + " is an O-C table",
                       true};
            return o;
        }
        if (std::string why = inputMemoryProblem(input, false); !why.empty()) {
            OpenedPass o;
            o.error = {std::move(why), false};
            return o;
        }
        return finishOpen(setup, passFromOcTable(input), nullptr);
    }
    SlrError readError;
    const std::shared_ptr<const CrdReadResult> crd = readSlrInput(setup.sources, &readError, fb);
    if (!crd) {
        OpenedPass o;
        o.error = readError;
        return o;
    }
    if (setup.sources.passNumber > static_cast<int>(crd->file.passes.size())) {
        OpenedPass o;
        o.crd = crd;
        o.passes = summarisePasses(crd->file);
        o.error = {input + ": pass " + std::to_string(setup.sources.passNumber) + " asked for, the file holds " +
                       std::to_string(crd->file.passes.size()) + " pass" + (crd->file.passes.size() == 1 ? "" : "es") +
                       " (numbered from 1)",
                   false};
        return o;
    }
    return openPassOf(setup, crd, setup.sources.passNumber - 1, fb);
}

PassRunResult runOpenedPass(const PassData& pass, const PassSettings& settings, const SlrSetup& setup, Feedback* fb) {
    SlrParams p = settings.params;
    p.screen.searchThreads = setup.sources.searchThreads;
    return runPass(pass, p, fb);
}

ResolvedRun resolveAndRunPass(const SlrSetup& setup, const PassData& pass, Feedback* fb) {
    ResolvedRun out;
    if (!resolvePassParams(setup, pass, &out.settings, &out.error)) return out;
    out.result = runOpenedPass(pass, out.settings, setup, fb);
    if (!out.result.ok) {
        out.error = {passName(pass) + ": " + out.result.error, false};
        return out;
    }
    out.ok = true;
    return out;
}

ResolvedRun resolveAndRunPass(const SlrSources& sources, const PassData& pass, Feedback* fb) {
    auto setup = std::make_shared<SlrSetup>();
    ResolvedRun out;
    if (!setUpSlrRun(sources, setup.get(), &out.error)) return out;
    out = resolveAndRunPass(*setup, pass, fb);
    out.setup = std::move(setup);
    return out;
}

const std::vector<uint8_t>& deliveredFlags(const PassRunResult& r) {
    return r.postOk && r.post.kept.size() == r.accepted.size() ? r.post.kept : r.accepted;
}

std::string productsProblem(const PassData& pass, const PassSettings& settings, const PassProductPaths& paths) {
    if ((!paths.crd.empty() || !paths.npt.empty()) && !pass.hasCrd)
        return std::string(!paths.crd.empty() ? "a flagged CRD" : "normal points as CRD") +
               " need a CRD input (its headers and records are written back); " + pass.source + " is an O-C table";
    if (!paths.npt.empty() && !(settings.params.postfit.binLengthS > 0) && !(settings.params.postfit.altitudeKm > 0))
        return "no normal points: the satellite's altitude is unknown (give the bin length, postfit.bin_length_s, or a "
               "preset with altitude_km)";
    return {};
}

bool stagePassProducts(const OutputSet& outs, const PassData& pass, const PassRunResult& r, const PassProductPaths& paths,
                       CrdPass* npBlock, std::string* error) {
    const PostfitResult* post = r.postOk ? &r.post : nullptr;
    if (!pass.damaged.empty()) {  // (every writer refuses a pass with records the reader skipped)
        *error = pass.damaged + "; nothing written";
        return false;
    }
    if (!paths.csv.empty() && !writeScreenCsv(outs.stagingPath(paths.csv), pass, r.screen, r.classes, post, error)) {
        *error = named(paths.csv, outs.unstaged(*error));
        return false;
    }
    if (!paths.crd.empty()) {
        // The pass alone (its own H9 and line ends, as passAlone gives it), or the whole file it
        // came from.
        if (!writeScreenedCrd(outs.stagingPath(paths.crd), pass, deliveredFlags(r), error, !paths.crdWholeFile)) {
            *error = named(paths.crd, outs.unstaged(*error));
            return false;
        }
    }
    if (!paths.npt.empty() || npBlock) {
        const DeliveredNormalPoints delivered = deliveredNormalPoints(r);
        CrdPass block;
        if (!normalPointPass(pass, delivered.points, normalPointProduct(post, &r.screen, delivered.noneReason), &block, error) ||
            (!paths.npt.empty() && !writeNormalPointFile(outs.stagingPath(paths.npt), {block}, error))) {
            *error = named(paths.npt.empty() ? pass.source : paths.npt, outs.unstaged(*error));
            return false;
        }
        if (npBlock) *npBlock = std::move(block);
    }
    if (!paths.report.empty()) {
        if (!paths.reportOf) {
            *error = named(paths.report, "no report contents given");
            return false;
        }
        if (!writePassReport(outs.stagingPath(paths.report), pass, r, *paths.reportOf, error)) {
            *error = named(paths.report, outs.unstaged(*error));
            return false;
        }
    }
    return true;
}

std::vector<std::string> passProductFiles(const PassProductPaths& paths) {
    std::vector<std::string> out;
    for (const std::string* p : {&paths.csv, &paths.crd, &paths.npt, &paths.report})
        if (!p->empty() && !isStandardStream(*p)) out.push_back(*p);
    return out;
}

std::vector<std::string> passOutputFiles(const PassProductPaths& paths) {
    std::vector<std::string> out;
    for (const std::string* p : {&paths.csv, &paths.crd, &paths.npt, &paths.report})
        if (!p->empty()) out.push_back(*p);
    for (const std::string& p : passProductFiles(paths)) out.push_back(provenancePathFor(p));
    return out;
}

Provenance passProvenance(const SlrSetup& setup, const PassSettings& settings, long long forcedByHand) {
    Provenance p = slrProvenance(setup, false);
    p.parameters = slrSchema().toJson(settings.params);
    if (forcedByHand > 0) p.settings["forced_by_hand"] = forcedByHand;
    return p;
}

bool stageScreenedPass(OutputSet& outs, const ScreenedPass& s, const PassProductPaths& given, const std::string& stationNp,
                       SlrError* error) {
    if (!s.setup || !s.pass || !s.settings || !s.result) {
        *error = {"a screened pass needs its set-up, pass, parameters and result", false};
        return false;
    }
    if (!stationNp.empty() && given.report.empty()) {
        *error = {"the station's normal points are compared in the report: give the report's file with them", true};
        return false;
    }
    if (isStandardStream(given.report)) {
        *error = {"the report needs a file (a PDF is not written to standard output)", true};
        return false;
    }
    if (const std::string why = productsProblem(*s.pass, *s.settings, given); !why.empty()) {
        *error = {why, true};
        return false;
    }
    // The report as every front end makes it: the run's set-up, the prediction the pass was
    // opened with, the station's normal points, and what opening it said.
    PassProductPaths paths = given;
    PassReport report;
    if (!paths.report.empty()) {
        std::vector<std::string> notes = s.notes;
        if (s.forcedByHand > 0)
            notes.push_back(std::to_string(s.forcedByHand) +
                            " point(s) forced in or out by hand in the workbench (not in the command below)");
        if (!passReportOfLoaded(*s.setup, s.openedWith ? *s.openedWith : s.setup->sources, *s.pass, *s.settings, std::move(notes),
                                stationNp, &report, error))
            return false;
        paths.reportOf = &report;
    }
    std::string err;
    if (!stagePassProducts(outs, *s.pass, *s.result, paths, nullptr, &err)) {
        *error = {err, false};
        return false;
    }
    const std::vector<std::string> products = passProductFiles(paths);
    const Provenance prov = passProvenance(*s.setup, *s.settings, s.forcedByHand);
    for (const std::string& p : products)
        if (!stageProvenance(outs, prov, products, provenancePathFor(p), &err)) {
            *error = {err, false};
            return false;
        }
    return true;
}

bool writeScreenedPass(const ScreenedPass& s, const PassProductPaths& paths, const std::string& stationNp, SlrError* error) {
    if (paths.csv.empty() && paths.crd.empty() && paths.npt.empty() && paths.report.empty()) {
        *error = {"no output: give a per-point CSV, a flagged CRD, normal points or a report", true};
        return false;
    }
    OutputSet outs;
    if (s.pass) outs.addInput(s.pass->source);
    outs.addInput(stationNp);
    for (const SlrSources* src : {s.setup ? &s.setup->sources : nullptr, s.openedWith})
        if (src)
            for (const std::string* in : {&src->input, &src->cpf, &src->stations, &src->presets, &src->configFile,
                                          &src->stationNormalPoints})
                outs.addInput(*in);
    for (const std::string& o : passOutputFiles(paths)) outs.addOutput(o);
    if (!outs.check()) {
        *error = {outs.error(), false};
        return false;
    }
    if (!stageScreenedPass(outs, s, paths, stationNp, error)) return false;
    if (!outs.commit()) {
        *error = {outs.error(), false};
        return false;
    }
    return true;
}

Provenance slrProvenance(const SlrSetup& setup, bool stationFile) {
    const SlrSources& s = setup.sources;
    Provenance p;
    p.command = stationFile ? "slr --all-passes" : "slr";
    p.parameters = slrSchema().toJson(setup.base);
    p.settings = {{"pass", s.passNumber}, {"cpf", s.cpf},           {"stations", s.stations},
                  {"preset", s.presets},  {"satellite", s.satellite}};
    p.inputs = {s.input, s.configFile, s.cpf, s.stations, s.presets, s.stationNormalPoints};
    return p;
}

std::string passName(const PassData& pass) {
    if (!pass.hasCrd) return pass.source;
    const size_t ordinal = pass.crd->passes[size_t(pass.passIndex)].ordinal;
    return pass.source + " pass " + std::to_string(ordinal ? ordinal : size_t(pass.passIndex) + 1);
}

std::vector<std::string> slrCommandArgs(const SlrSources& src, int passNumber, const SlrParams& params) {
    std::vector<std::string> out = {"slr", src.input};
    if (passNumber > 0) out.insert(out.end(), {"--pass", std::to_string(passNumber)});
    if (!src.cpf.empty()) out.insert(out.end(), {"--cpf", src.cpf});
    if (!src.cpf.empty() && src.cpfFallback) out.push_back("--cpf-fallback");
    if (!src.stations.empty()) out.insert(out.end(), {"--stations", src.stations});
    if (!src.stationNormalPoints.empty()) out.insert(out.end(), {"--station-np", src.stationNormalPoints});
    const Schema<SlrParams>& schema = slrSchema();
    const SlrParams defaults;
    for (const std::string& key : schema.changedKeys(defaults, params))
        if (const auto* f = schema.find(key)) out.insert(out.end(), {"--set", key + "=" + schema.valueText(*f, params)});
    return out;
}

SlrParams commandParams(const SlrSetup& setup, const PassData& pass, const SlrParams& resolved) {
    const SlrParams defaults = commandDefaults();
    SlrParams told = defaults;
    passNormalPointContext(pass, setup.stations(), &told.postfit);
    SlrParams out = resolved;
    for (const auto& f : slrSchema().fields()) {
        if (f.key.rfind("postfit.", 0) != 0 || !f.get || !f.set) continue;
        const double d = f.get(defaults), t = f.get(told), r = f.get(resolved);
        if (t != d && r == t) f.set(out, d);
    }
    return out;
}

std::string shellCommand(const std::vector<std::string>& args) {
    std::string s;
    for (const std::string& a : args) {
        const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                                             "_-+=.,/:@%") == std::string::npos;
        if (!s.empty()) s += ' ';
        if (plain) {
            s += a;
            continue;
        }
        s += '\'';
        for (char c : a) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
        s += '\'';
    }
    return s;
}

namespace {
// A Python string literal (single quotes; backslashes, quotes and control characters escaped).
std::string pyString(const std::string& v) {
    std::string s = "'";
    for (char c : v) {
        if (c == '\\' || c == '\'') s += '\\';
        if (c == '\n') {
            s += "\\n";
            continue;
        }
        s += c;
    }
    return s + "'";
}
}  // namespace

std::string slrPythonScript(const SlrSources& src, int passNumber, const SlrParams& params, bool withCpf) {
    const Schema<SlrParams>& schema = slrSchema();
    std::string dict;
    for (const std::string& key : schema.changedKeys(SlrParams{}, params))
        if (const auto* f = schema.find(key)) {
            const std::string v = schema.valueText(*f, params);
            double number = 0;
            const bool bare = parseDouble(v, &number) && std::isfinite(number);
            dict += "    " + pyString(key) + ": " + (bare ? v : pyString(v)) + ",\n";
        }
    const std::string& sinex = src.stations;
    const bool cpf = withCpf && !src.cpf.empty();
    std::string s = "import laserwb\n\n";
    s += dict.empty() ? "params = {}\n" : "params = {\n" + dict + "}\n";
    s += "p = laserwb.slr.load_pass(" + pyString(src.input);
    if (passNumber > 0) s += ", pass_number=" + std::to_string(passNumber);
    if (cpf) s += ", cpf=" + pyString(src.cpf);
    if (!sinex.empty()) s += ", stations=" + pyString(sinex);
    s += ", params=params)\n";
    s += "r = laserwb.slr.run(p, params=params" + (sinex.empty() ? std::string() : ", stations=" + pyString(sinex)) + ")\n";
    s += "print(r.accepted_count, 'points accepted;', r.doubt or r.post_note or 'ok')\n";
    s += std::string("r.write(csv='screened.csv'") + (passNumber > 0 ? ", npt='pass.npt'" : "");
    if (!src.stationNormalPoints.empty())
        s += ", report='pass_report.pdf', station_np=" + pyString(src.stationNormalPoints);
    return s + ")\n";
}

}  // namespace lwb::core::slr
