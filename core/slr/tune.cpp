#include "core/slr/tune.hpp"

#include <cmath>
#include <sys/stat.h>

#include "core/common/atomic_file.hpp"
#include "core/common/folder.hpp"
#include "core/common/provenance.hpp"
#include "core/common/text.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/presets.hpp"

namespace lwb::core::slr {

namespace {

// The grid: the parameters that decide which points are delivered once the track is found.
constexpr double kCosines[] = {0.90, 0.93, 0.95, 0.97, 0.98, 0.99};
constexpr double kRejects[] = {2.5, 3.0, 3.5};
constexpr bool kTakeBand[] = {true, false};
// The mean F1 by which a candidate must beat the starting point to be chosen over it: where the
// automatic mode is at its ceiling, a candidate better by less is a pass's chance, not a gain.
constexpr double kMinGain = 0.001;
// ... and it may lose to the starting point on no pass by more than this.
constexpr double kMaxLoss = 0.002;

std::string candidateLabel(const SlrParams& p) {
    return "cosine_c=" + formatFixed(p.screen.cosineC, 2) + " reject_sigma=" + formatFixed(p.postfit.rejectSigma, 1) +
           " take_band=" + (p.postfit.takeBand ? "true" : "false");
}

bool sameChoice(const SlrParams& a, const SlrParams& b) {
    return a.screen.cosineC == b.screen.cosineC && a.postfit.rejectSigma == b.postfit.rejectSigma &&
           a.postfit.takeBand == b.postfit.takeBand;
}

// A pass opened for tuning: the pass, its resolved starting settings and the set-up it ran with.
struct OpenTuned {
    std::shared_ptr<const SlrSetup> setup;
    std::shared_ptr<const PassData> pass;
    PassSettings settings;
    std::vector<uint8_t> labels;  ///< 1 where the station flagged data
};

TuneResult failed(std::string message, bool usage) {
    TuneResult r;
    r.error = {std::move(message), usage};
    return r;
}

}  // namespace

TuneResult tuneSlr(const TuneSources& sources, const Feedback* fb) {
    if (sources.files.empty() && sources.sessions.empty())
        return failed("no passes to tune on: give one or more CRD files with the station's filter flags, or sessions", true);
    std::vector<SatellitePreset> entries;
    if (!sources.presets.empty()) {
        const PresetsResult pr = loadPresets(sources.presets);
        if (!pr.ok) return failed(pr.error, false);
        entries = pr.presets;
    }
    const std::vector<SatellitePreset> wanted = {SatellitePreset{sources.satellite, {}, {}, {}}};
    TuneResult out;
    {  // The settings, checked once (a bad one is no file's reason to be left out).
        SlrSources check;
        check.set = sources.set;
        SlrParams base;
        if (!resolveBaseParams(check, &base, &out.error)) return out;
    }
    // The files: each one named, and the CRD files of each folder named (a station's archive).
    // What cannot be tuned on in a folder (a file that does not read, a pass without labels, a
    // normal-point file) is left out with its reason; a file named is refused for it.
    struct Input {
        std::string path;
        bool inFolder = false;
    };
    std::vector<Input> inputs;
    for (const std::string& file : sources.files) {
        if (!isFolder(file)) {
            inputs.push_back({file, false});
            continue;
        }
        std::vector<std::string> listed;
        std::string err;
        if (!listFolder(file, &listed, &err)) return failed(err, false);
        size_t crd = 0;
        for (const std::string& f : listed)
            if (isCrdFile(f)) inputs.push_back({f, true}), ++crd;
        if (crd == 0) out.notes.push_back(file + ": no CRD file in the folder");
    }
    std::vector<OpenTuned> open;
    for (const Input& input : inputs) out.filesRead.push_back(input.path);
    for (const Input& input : inputs) {
        const std::string& file = input.path;
        // A folder's file that cannot be tuned on: its reason noted, the next one read.
        auto leaveOut = [&](const std::string& why) {
            out.notes.push_back(why.rfind(file, 0) == 0 ? why + " (left out)" : file + ": left out: " + why);
            out.error = {};
        };
        SlrSources src;
        src.input = file;
        src.set = sources.set;
        src.searchThreads = sources.threads;
        if (isCrdFile(file)) {
            src.cpf = sources.cpf;
            src.stations = sources.stations;
            src.cpfFallback = sources.cpfFallback;
        }
        auto plain = std::make_shared<SlrSetup>();
        if (!setUpSlrRun(src, plain.get(), &out.error)) {
            if (!input.inFolder) return out;
            leaveOut(out.error.message);
            continue;
        }
        // (the existing entry of the pass's satellite is the starting point, where there is one)
        std::shared_ptr<SlrSetup> withEntry;
        if (!entries.empty()) {
            src.presets = sources.presets;
            // (an O-C table names no satellite: its entry is --satellite's)
            if (!isCrdFile(file)) src.satellite = sources.satellite;
            withEntry = std::make_shared<SlrSetup>();
            if (!setUpSlrRun(src, withEntry.get(), &out.error)) return out;
        }
        // A pass opened: its labels (the station's flags: 2 data, 1 noise) or why it has none
        // (a folder's pass without labels is left out with it).
        auto take = [&](const std::string& name, std::shared_ptr<const SlrSetup> setup, const OpenedPass& o) -> bool {
            const PassData& d = *o.pass;
            size_t data = 0, noise = 0;
            for (int f : d.stationFlag) data += f == 2, noise += f == 1;
            if (data == 0) {
                const std::string why =
                    name + ": no labels to tune on: " +
                    (d.stationFlag.empty() && !isCrdFile(file)
                         ? std::string("the O-C table has no station_flag column, or only 0 or blank in it "
                                       "(laserwb-cli slr -o writes one from a CRD pass's filter flags)")
                     : noise == 0 ? std::string("every filter flag is 0 (unknown)")
                                  : "no point is flagged data (2), " + std::to_string(noise) + " noise (1)") +
                    "; tuning learns from the station's own decisions (2 data, 1 noise)";
                if (input.inFolder) {
                    out.notes.push_back(why + " (left out)");
                    return true;
                }
                out = failed(why, false);
                return false;
            }
            OpenTuned t{std::move(setup), o.pass, o.settings, {}};
            t.labels.resize(d.stationFlag.size());
            for (size_t i = 0; i < d.stationFlag.size(); ++i) t.labels[i] = d.stationFlag[i] == 2;
            open.push_back(std::move(t));
            return true;
        };
        if (!isCrdFile(file)) {
            // An O-C table (the CLI's -o): one pass, its station_flag column the labels. It does
            // not name its satellite: --satellite does (the entry written, the entry started from).
            if (sources.satellite.empty())
                return failed(file + ": an O-C table does not name its satellite: give --satellite NAME (the preset "
                                     "entry the tuning writes)",
                              true);
            const bool entry = withEntry && findPreset(entries, sources.satellite);
            const OpenedPass o = openPass(entry ? *withEntry : *plain);
            if (!o.ok) return failed(o.error.message, o.error.usage);
            if (!take(file, entry ? std::shared_ptr<const SlrSetup>(withEntry) : plain, o)) return out;
            continue;
        }
        const std::shared_ptr<const CrdReadResult> crd = readSlrInput(src, &out.error);
        if (!crd) {
            if (!input.inFolder) return out;
            leaveOut(out.error.message);
            continue;
        }
        const std::vector<PassSummary> summaries = summarisePasses(crd->file);
        for (const PassSummary& s : summaries) {
            const std::string name = file + " pass " + std::to_string(s.index + 1);
            if (!isPassToScreen(s)) {
                out.notes.push_back(name + ": left out: " + (s.problem.empty() ? blockStatus(s).reason : s.problem));
                continue;
            }
            if (!sources.satellite.empty() && !findPreset(wanted, s.satellite)) {
                out.notes.push_back(name + ": left out: satellite " + s.satellite + ", not " + sources.satellite);
                continue;
            }
            const bool entry = withEntry && findPreset(entries, s.satellite, s.ilrsId);
            std::shared_ptr<const SlrSetup> setup = entry ? std::shared_ptr<const SlrSetup>(withEntry) : plain;
            OpenedPass o = openPassOf(*setup, crd, s.index);
            if (!o.ok && input.inFolder) {
                out.notes.push_back(name + ": left out: " + o.error.message);
                continue;
            }
            if (!o.ok) return failed(o.error.message, o.error.usage);
            if (!take(name, setup, o)) return out;
        }
    }
    // The workbench sessions: the analyst's decisions on their passes.
    for (const std::string& session : sources.sessions) try {
        const JsonParseResult doc = readJsonFile(session);
        if (!doc.ok) return failed(doc.error, false);
        const Json& root = doc.value;
        if (!root.is_object() || root.value("format", "") != "laserwb-session")
            return failed(session + ": not a Laser Workbench session (no \"format\": \"laserwb-session\")", false);
        const Json slr = root.value("slr", Json::object());
        const std::string path = slr.is_object() ? slr.value("path", "") : "";
        if (path.empty()) return failed(session + ": the session has no SLR pass from a file (slr.path)", false);
        // The session's parameters: the schema's sections it saved.
        Json params = Json::object();
        for (const auto& f : slrSchema().fields()) {
            const std::string section = f.key.substr(0, f.key.find('.'));
            if (slr.contains(section)) params[section] = slr[section];
        }
        SlrSources labelled;
        labelled.input = path;
        labelled.passNumber = slr.value("pass", -1) + 1;
        labelled.cpf = slr.value("cpf", "");
        labelled.stations = slr.value("sinex", "");
        labelled.cpfFallback = true;
        labelled.config = params;
        labelled.searchThreads = sources.threads;
        const LoadedSlrPass l = loadSlrPass(labelled);
        if (!l.ok) return failed(session + ": " + l.error.message, l.error.usage);
        const PassData& d = *l.opened.pass;
        std::vector<int8_t> forced(d.t.size(), 0);
        size_t edits = 0;
        for (const Json& e : slr.value("forced", Json::array())) {
            const long long i = e.is_array() && e.size() == 2 && e[0].is_number_integer() ? e[0].get<long long>() : -1;
            if (i < 0 || static_cast<size_t>(i) >= forced.size() || !e[1].is_number_integer())
                return failed(session + ": slr.forced: " + e.dump() + " is not a point of the pass ([index, +1 or -1], " +
                                  std::to_string(forced.size()) + " points)",
                              false);
            forced[static_cast<size_t>(i)] = e[1].get<int>() > 0 ? 1 : -1;
            ++edits;
        }
        const std::string name = session + ": " + passName(d);
        if (!sources.satellite.empty() && !findPreset(wanted, d.satellite)) {
            out.notes.push_back(name + ": left out: satellite " + d.satellite + ", not " + sources.satellite);
            continue;
        }
        if (edits == 0)
            return failed(name + ": no labels to tune on: no point was forced in or out by hand (a session's labels are "
                                 "the analyst's decisions: the screening with the edits made on it)",
                          false);
        // The labels: the session's run with its edits, as the workbench delivered it.
        const PassRunResult run = runTask<PassTask>({l.opened.pass, forced}, l.opened.settings.params);
        if (!run.ok) return failed(name + ": " + run.error, false);
        // The starting point of the tuning: the command's (defaults, the satellite's entry), on
        // the same O-C (the session's prediction and station file).
        SlrSources start = labelled;
        start.config = Json();
        start.set = sources.set;
        if (findPreset(entries, d.satellite, d.ilrsId)) start.presets = sources.presets;
        auto setup = std::make_shared<SlrSetup>();
        if (!setUpSlrRun(start, setup.get(), &out.error)) return out;
        PassSettings settings;
        if (!resolvePassParams(*setup, d, &settings, &out.error)) return out;
        OpenTuned t{setup, l.opened.pass, settings, deliveredFlags(run)};
        size_t data = 0;
        for (uint8_t f : t.labels) data += f;
        if (data == 0) return failed(name + ": no labels to tune on: the analyst's decisions keep no point", false);
        out.notes.push_back(name + ": labels from the session (" + std::to_string(edits) + " point(s) forced by hand, " +
                            std::to_string(data) + " kept of " + std::to_string(t.labels.size()) + ")");
        open.push_back(std::move(t));
    } catch (const Json::exception& e) {  // a value of the wrong type (a pass number as text, say)
        return failed(session + ": slr: a value of the wrong type (" + e.what() + ")", false);
    }
    if (open.empty()) {
        // Why each file or pass was left out (a folder's own reasons are the answer here).
        std::string why;
        for (size_t k = 0; k < out.notes.size() && k < 5; ++k) why += "\n  " + out.notes[k];
        if (out.notes.size() > 5) why += "\n  ... and " + std::to_string(out.notes.size() - 5) + " more";
        return failed("no pass to tune on in the files given" + (why.empty() ? std::string() : ":" + why), out.notes.empty());
    }
    // One satellite: its preset entry is what the tuning writes.
    out.satellite = sources.satellite.empty() ? open.front().pass->satellite : sources.satellite;
    out.ilrsId = open.front().pass->ilrsId;
    if (sources.satellite.empty()) {
        const std::vector<SatellitePreset> first = {SatellitePreset{open.front().pass->satellite, {}, {}, {}}};
        for (const OpenTuned& t : open)
            if (!findPreset(first, t.pass->satellite))
                return failed("passes of several satellites (" + open.front().pass->satellite + ", " + t.pass->satellite +
                                  "): give --satellite NAME to tune one",
                              true);
    }
    // The candidates: the starting point first, then the grid (the pass's context left to each pass).
    const SlrParams start = commandParams(*open.front().setup, *open.front().pass, open.front().settings.params);
    out.candidates.push_back({candidateLabel(start) + " (the starting point)", start, 0});
    for (double c : kCosines)
        for (double k : kRejects)
            for (bool band : kTakeBand) {
                SlrParams p = start;
                p.screen.cosineC = c;
                p.postfit.rejectSigma = k;
                p.postfit.takeBand = band;
                if (!sameChoice(p, start)) out.candidates.push_back({candidateLabel(p), p, 0});
            }
    const size_t total = open.size() * out.candidates.size();
    size_t done = 0;
    for (const OpenTuned& t : open) {
        TunedPass tp;
        tp.name = passName(*t.pass);
        tp.points = t.labels.size();
        for (uint8_t l : t.labels) tp.labelledSignal += l;
        for (const TuneCandidate& c : out.candidates) {
            if (fb && fb->isCancelled()) return failed("cancelled", false);
            PassSettings s = t.settings;
            s.params.screen.cosineC = c.params.screen.cosineC;
            s.params.postfit.rejectSigma = c.params.postfit.rejectSigma;
            s.params.postfit.takeBand = c.params.postfit.takeBand;
            const PassRunResult r = runOpenedPass(*t.pass, s, *t.setup);
            tp.scores.push_back(r.ok ? sim::scoreDetection(deliveredFlags(r), t.labels) : sim::DetectionScore{});
            if (fb) fb->setProgress(double(++done) / double(total));
        }
        out.passes.push_back(std::move(tp));
    }
    // The choice: the best mean F1 among the candidates that beat the starting point by more
    // than kMinGain and lose to it on no pass by more than kMaxLoss (the starting point on a tie).
    auto bestOver = [&](size_t leftOut) {
        auto mean = [&](size_t c) {
            double sum = 0;
            size_t n = 0;
            for (size_t p = 0; p < out.passes.size(); ++p)
                if (p != leftOut) sum += out.passes[p].scores[c].f1, ++n;
            return n ? sum / double(n) : 0.0;
        };
        const double startMean = mean(0);
        size_t best = 0;
        double bestF1 = startMean;
        for (size_t c = 1; c < out.candidates.size(); ++c) {
            const double m = mean(c);
            if (!(m > startMean + kMinGain) || !(m > bestF1 + 1e-12)) continue;
            bool holds = true;
            for (size_t p = 0; p < out.passes.size(); ++p)
                if (p != leftOut) holds = holds && out.passes[p].scores[c].f1 >= out.passes[p].scores[0].f1 - kMaxLoss;
            if (holds) bestF1 = m, best = c;
        }
        return best;
    };
    for (size_t c = 0; c < out.candidates.size(); ++c) {
        double sum = 0;
        for (const TunedPass& p : out.passes) sum += p.scores[c].f1;
        out.candidates[c].meanF1 = sum / double(out.passes.size());
    }
    out.best = bestOver(out.passes.size());
    double held = 0;
    for (size_t p = 0; p < out.passes.size(); ++p) {
        // (one pass alone: nothing to choose on without it; its held-out figure is the starting point's)
        const size_t choice = out.passes.size() > 1 ? bestOver(p) : 0;
        out.passes[p].heldOutF1 = out.passes[p].scores[choice].f1;
        held += out.passes[p].heldOutF1;
    }
    out.heldOutMeanF1 = held / double(out.passes.size());
    // A choice that does not hold out is not made: where leaving each pass out and choosing on
    // the others scores no better on the passes left out than the starting point does, the gain
    // on all of them is theirs, not the kind's (dayspad seeds 1-3: 0.9421 -> 0.9588 on them,
    // 0.9310 held out, and the choice lost 0.0095 on six passes never tuned on).
    out.startMeanF1 = out.candidates[0].meanF1;
    if (out.best != 0 && out.passes.size() > 1 && !(out.heldOutMeanF1 > out.startMeanF1)) {
        out.notes.push_back("the best candidate (" + candidateLabel(out.candidates[out.best].params) + ", mean F1 " +
                            formatFixed(out.candidates[out.best].meanF1, 4) +
                            ") does not hold out: the choices made without each pass in turn score " +
                            formatFixed(out.heldOutMeanF1, 4) + " on the passes left out, the starting point " +
                            formatFixed(out.startMeanF1, 4) + "; the starting point is kept");
        out.notHeldOut = out.best;
        out.best = 0;
    }
    if (out.passes.size() == 1)
        out.notes.push_back("one pass: the choice is not cross-validated (leave-one-pass-out needs two or more)");
    out.ok = true;
    return out;
}

Json tuneSummary(const TuneResult& r) {
    Json j = Json::object();
    j["satellite"] = r.satellite;
    j["chosen"] = r.candidates[r.best].label;
    j["f1_before"] = r.candidates[0].meanF1;
    j["f1_after"] = r.candidates[r.best].meanF1;
    j["f1_held_out"] = r.heldOutMeanF1;
    if (r.notHeldOut != 0) {  // (the choice on all the passes, not made: it did not hold out)
        j["not_held_out"] = r.candidates[r.notHeldOut].label;
        j["not_held_out_f1"] = r.candidates[r.notHeldOut].meanF1;
    }
    j["candidates"] = r.candidates.size();
    Json passes = Json::array();
    for (const TunedPass& p : r.passes) {
        Json e = Json::object();
        e["pass"] = p.name;
        e["points"] = p.points;
        e["labelled_data"] = p.labelledSignal;
        e["f1_before"] = p.scores[0].f1;
        e["f1_after"] = p.scores[r.best].f1;
        e["f1_held_out"] = p.heldOutF1;
        passes.push_back(std::move(e));
    }
    j["passes"] = std::move(passes);
    return j;
}

bool writeTunedPreset(const TuneResult& r, const TuneSources& sources, const std::string& path, std::string* error,
                      std::string* note) {
    if (!r.ok || r.candidates.empty()) {
        *error = "no tuning to write";
        return false;
    }
    // The file's entries kept, the satellite's replaced (or added).
    std::vector<SatellitePreset> presets;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        const PresetsResult pr = loadPresets(path);
        if (!pr.ok) {
            *error = pr.error + " (the tuned entry is written into an existing presets file: it must read)";
            return false;
        }
        presets = pr.presets;
    }
    const SlrParams& chosen = r.candidates[r.best].params;
    SatellitePreset entry{r.satellite, r.ilrsId, chosen.screen, chosen.postfit};
    bool replaced = false;
    for (SatellitePreset& p : presets)
        if (findPreset({p}, r.satellite, r.ilrsId)) {
            if (note)
                *note = "the entry \"" + p.name + "\"" + (p.ilrsId.empty() ? std::string() : " (ILRS id " + p.ilrsId + ")") +
                        " replaced" + (p.name == r.satellite ? std::string() : " (the same satellite by its ILRS id)");
            p = entry, replaced = true;
        }
    if (!replaced) {
        presets.push_back(entry);
        if (note) *note = "the entry \"" + r.satellite + "\" added";
    }
    const Json doc = presetsToJson(presets);
    if (const PresetsResult check = presetsFromJson(doc, path); !check.ok) {
        *error = check.error + " (nothing written)";
        return false;
    }
    Provenance prov;
    prov.command = "slr tune";
    prov.parameters = slrSchema().toJson(chosen);
    prov.settings = tuneSummary(r);
    prov.inputs = r.filesRead;  // (a folder's files, each with its checksum)
    prov.inputs.insert(prov.inputs.end(), sources.sessions.begin(), sources.sessions.end());
    prov.inputs.push_back(sources.presets);
    prov.inputs.push_back(sources.cpf);
    prov.inputs.push_back(sources.stations);
    // The file and its provenance all or nothing; an existing presets file is read above and
    // replaced on purpose (update), every other input stays protected.
    const std::string text = dumpJson(doc);
    return writeWithProvenance(prov, path, [&](const std::string& to, std::string* e) { return writeFileAtomic(to, text, e); },
                               error, !presets.empty() || ::stat(path.c_str(), &st) == 0);
}

std::vector<SweepOutcome> sweepSlrParam(const SlrSetup& setup, const PassTask::Inputs& in, const SlrParams& panel,
                                        const std::string& key, const std::vector<double>& values,
                                        const std::vector<uint8_t>& labels, const PassTask::Reuse& reuse,
                                        Feedback* fb) {
    std::vector<SweepOutcome> out(values.size());
    const auto* field = slrSchema().find(key);
    if (!field || !field->set || !in.pass) return out;
    // What the live rerun would reuse for a change of this row alone.
    PassTask::Reuse use;
    if (field->stage >= kStagePostfit) use.screen = reuse.screen;
    if (field->stage >= kStageRecovery && !use.screen) use.scale = reuse.scale;
    SlrSetup at = setup;
    for (size_t k = 0; k < values.size(); ++k) {
        if (fb && fb->isCancelled()) break;
        SlrParams p = panel;
        field->set(p, values[k]);
        if (!slrSchema().validate(p).empty()) continue;
        at.sources.config = slrSchema().toJson(p);
        PassSettings settings;
        SlrError e;
        if (!resolvePassParams(at, *in.pass, &settings, &e)) continue;
        const PassRunResult r = PassTask::run(in, settings.params, use, fb);
        if (!r.ok || (fb && fb->isCancelled())) continue;
        SweepOutcome& o = out[k];
        o.ok = true;
        const std::vector<uint8_t>& delivered = deliveredFlags(r);
        for (uint8_t d : delivered) o.delivered += d != 0;
        if (r.postOk) o.rmsS = r.post.stats.rms;
        if (!labels.empty()) o.f1 = sim::scoreDetection(delivered, labels).f1;
    }
    return out;
}

}  // namespace lwb::core::slr
