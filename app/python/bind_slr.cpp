// laserwb.slr: an SLR pass from its files to its products, as `laserwb-cli slr` runs it. The
// binding gathers sources (SlrSources: files, parameters, preset, threads) and hands them to the
// core's tasks: loadSlrPass loads them (read, checked, the pass opened), resolveAndRunPass
// resolves a pass's settings and runs it, writeScreenedPass writes its products, runStationDay
// and tuneSlr do a file of passes. Nothing here reads, resolves or computes: the CLI and the
// workbench call the same tasks.
#include <atomic>
#include <memory>

#include "bind.hpp"
#include "core/common/atomic_file.hpp"
#include "core/slr/slr_params.hpp"
#include "core/slr/slr_run.hpp"
#include "core/slr/station_day.hpp"
#include "core/slr/tune.hpp"
#include "core/common/text.hpp"

namespace lwb::py {

namespace slr = core::slr;
using namespace pybind11::literals;

namespace {

std::string familyCheck(const slr::SlrParams& p) { return slr::validate(p.screen); }
const ParamsBinding<slr::SlrParams> kParams{
    "SlrParams",
    "Parameters of the SLR pass (laserwb-cli slr; core/slr/slr_params.cpp). SlrParams() holds the\n"
    "command's defaults (automatic screening, 3-sigma rejection).",
    slr::slrSchema, slr::commandDefaults, familyCheck};

/// A loaded pass, shared with its results (the arrays are views of it).
struct Pass {
    std::shared_ptr<const slr::PassData> data;
    std::vector<std::string> warnings;
    std::vector<std::string> notes;  ///< what the O-C is relative to (when not a prediction)
    slr::SlrSources sources;         ///< what load_pass was given (the pass's file, prediction, stations)
};

/// A pass's run: its settings, the task's outputs, the set-up it ran with and the sources the
/// pass was loaded with (the report names both: core passReportOfLoaded).
struct PassRun {
    std::shared_ptr<const slr::PassData> pass;
    std::shared_ptr<const slr::SlrSetup> setup;
    slr::SlrSources opened;
    std::vector<std::string> openingNotes;  ///< load_pass's warnings, then its notes
    slr::PassSettings settings;
    slr::PassRunResult r;
};

// The core's error as Python's: a usage error (an option, a block that is not a pass) is a
// ParameterError, anything else laserwb.Error.
[[noreturn]] void raise(const slr::SlrError& e) {
    if (e.usage) throw ParameterError(e.message);
    throw Error(e.message);
}

// The MJD of a CRD pass's day (its epochs are seconds of that day), None for an O-C table.
py::object startMjd(const slr::PassData& d) { return d.hasCrd ? py::object(py::int_(d.startMjd)) : py::none(); }

py::dict summaryDict(const slr::PassSummary& s) {
    return py::dict("pass_number"_a = s.index + 1, "satellite"_a = s.satellite, "ilrs_id"_a = s.ilrsId, "station"_a = s.station,
                    "start"_a = s.start, "end"_a = s.end, "ranges"_a = s.ranges, "normal_points"_a = s.normalPoints,
                    "data_type"_a = s.dataType, "problem"_a = s.problem, "status"_a = slr::blockStatus(s).status);
}

// The default of run(threads=None): set_search_threads.
std::atomic<int> gDefaultSearchThreads{0};

int threadCount(const py::object& threads) {
    if (threads.is_none()) return gDefaultSearchThreads.load();
    if (!py::isinstance<py::int_>(threads)) throw py::type_error("threads must be an int (0: every core)");
    const long long n = threads.cast<long long>();
    if (n < 0 || n > 256) throw py::value_error("threads must be in [0, 256] (0: every core), not " + std::to_string(n));
    return static_cast<int>(n);
}

// The analyst's own parameters as sources: a SlrParams as --config, a dict {key: value} as --set.
void gatherParams(const py::object& params, slr::SlrSources* src) {
    lwb::py::gatherParams(params, slr::slrSchema(), "laserwb.slr.SlrParams", &src->config, &src->set);
}

// The sources loaded by the core (loadSlrPass: read, resolved, the pass opened) without the GIL,
// as a Pass; the load's error raised.
slr::LoadedSlrPass loadSources(const slr::SlrSources& src) {
    slr::LoadedSlrPass loaded;
    {
        py::gil_scoped_release nogil;
        loaded = slr::loadSlrPass(src);
    }
    if (!loaded.ok) raise(loaded.error);
    return loaded;
}

Pass passOf(const slr::LoadedSlrPass& loaded) {
    return Pass{loaded.opened.pass, loaded.opened.warnings, loaded.opened.notes, loaded.setup.sources};
}

Pass pyLoadPass(const py::object& path, const py::object& passNumber, const py::object& cpf, const py::object& stations,
                const py::object& params) {
    // The sources as the CLI gathers them from its flags; the core reads, chooses and loads.
    slr::SlrSources src;
    src.input = fsPath(path);
    requireReadable(src.input);
    gatherParams(params, &src);  // (their oc.* rows make the O-C; the rest are run()'s)
    // (stations alone give no O-C: run() takes them for day or night, as the CLI's --stations)
    if (!cpf.is_none()) {
        if (stations.is_none()) throw ParameterError("cpf and stations go together (O-C from the prediction needs both)");
        src.cpf = fsPath(cpf);
        src.stations = fsPath(stations);
        requireReadable(src.cpf, true);
        requireReadable(src.stations);
    }
    if (!passNumber.is_none()) {
        if (!py::isinstance<py::int_>(passNumber)) throw py::type_error("pass_number must be an int (from 1)");
        // (compared as Python ints: 10**20 does not fit a C++ integer, and its cast said only "Unable to cast")
        if (passNumber < py::int_(1) || passNumber > py::int_(1000000))
            throw ParameterError("pass_number counts from 1 (at most 1000000), not " + std::string(py::str(passNumber)));
        const long long k = passNumber.cast<long long>();
        src.passNumber = static_cast<int>(k);
    }
    return passOf(loadSources(src));
}

PassRun pyRun(const py::object& given, const py::object& params, const py::object& preset, const py::object& satellite,
                const py::object& stations, const py::object& threads) {
    // A Pass, or a file's path loaded here as load_pass(path, params=params) loads it.
    Pass loaded;
    if (py::isinstance<py::str>(given) || py::hasattr(given, "__fspath__"))
        loaded = pyLoadPass(given, py::none(), py::none(), py::none(), params);
    else if (!py::isinstance<Pass>(given))
        throw py::type_error("run() takes a Pass (laserwb.slr.load_pass(PATH)) or a CRD or O-C file's path, not " +
                             std::string(py::str(py::type::of(given).attr("__name__"))));
    const Pass& pass = loaded.data ? loaded : given.cast<const Pass&>();
    // The sources of the run as the CLI gathers them: the preset file and its satellite, the
    // station file, the analyst's own parameters (a SlrParams as --config, a dict as --set); the
    // core resolves them over the pass in the one order and runs it (core resolveAndRunPass).
    slr::SlrSources src;
    src.input = pass.sources.input;  // ("" for a pass given as arrays: no file to record)
    if (!preset.is_none()) src.presets = fsPath(preset);
    if (!satellite.is_none()) src.satellite = std::string(py::str(satellite));
    if (!stations.is_none()) src.stations = fsPath(stations);
    requireReadable(src.presets);
    requireReadable(src.stations);
    gatherParams(params, &src);
    src.searchThreads = threadCount(threads);
    slr::ResolvedRun done;
    {
        py::gil_scoped_release nogil;
        done = slr::resolveAndRunPass(src, *pass.data);
    }
    if (!done.ok) raise(done.error);
    PassRun run;
    run.pass = pass.data;
    run.openingNotes = pass.warnings;
    run.openingNotes.insert(run.openingNotes.end(), pass.notes.begin(), pass.notes.end());
    run.opened = pass.sources;
    run.setup = std::move(done.setup);
    run.settings = std::move(done.settings);
    run.r = std::move(done.result);
    return run;
}

// A station's file of passes into `outDir` (core runStationDay), as laserwb-cli slr --all-passes
// writes it: one dict per block (summary.csv's columns, as text).
py::list processFile(const py::object& path, const py::object& outDir, const py::object& params, const py::object& preset,
                     const py::object& satellite, const py::object& cpf, const py::object& stations, const py::object& threads) {
    slr::SlrSources src;
    src.input = fsPath(path);
    if (!preset.is_none()) src.presets = fsPath(preset);
    if (!satellite.is_none()) src.satellite = std::string(py::str(satellite));
    if (!cpf.is_none()) src.cpf = fsPath(cpf);
    if (!stations.is_none()) src.stations = fsPath(stations);
    for (const std::string* f : {&src.input, &src.presets, &src.stations}) requireReadable(*f);
    requireReadable(src.cpf, true);
    gatherParams(params, &src);
    slr::DayOptions opt;
    opt.outDir = fsPath(outDir);
    opt.threads = threadCount(threads);
    slr::DayResult r;
    {
        py::gil_scoped_release nogil;
        r = slr::runStationDay(src, opt);
    }
    if (!r.ok) raise(r.error);
    py::list rows;
    for (const slr::DayRow& row : r.rows) {
        py::dict d;
        for (const slr::DayColumn& c : slr::dayColumns()) d[py::str(c.name)] = c.cell(row);
        rows.append(d);
    }
    return rows;
}

// The products of a run as the one-pass CLI writes them, all or nothing, each file's provenance
// beside it (core writeScreenedPass: the CLI's writer, report and sidecars).
void writeProducts(const PassRun& run, const std::string& csv, const std::string& crd, const std::string& npt,
                   const std::string& report, const std::string& stationNp) {
    // (the checks in this front end's own words: its keywords)
    if (csv.empty() && crd.empty() && npt.empty() && report.empty()) throw ParameterError("no output: give csv, crd, npt or report");
    if (!stationNp.empty() && report.empty())
        throw ParameterError("station_np is compared in the report: give report='FILE.pdf' with it");
    if (core::isStandardStream(report)) throw ParameterError("report needs a file (a PDF is not written to standard output)");
    const slr::ScreenedPass screened{run.setup.get(), &run.opened, run.pass.get(), &run.settings, &run.r, run.openingNotes};
    slr::SlrError e;
    if (!slr::writeScreenedPass(screened, {csv, crd, npt, true, report}, stationNp, &e)) raise(e);
}

py::dict normalPointColumns(const std::vector<slr::NormalPoint>& nps) {
    auto col = [&](auto get) {
        py::array_t<double> a(static_cast<py::ssize_t>(nps.size()));
        auto w = a.mutable_unchecked<1>();
        for (size_t i = 0; i < nps.size(); ++i) w(static_cast<py::ssize_t>(i)) = get(nps[i]);
        return a;
    };
    return py::dict("epoch_s"_a = col([](const auto& n) { return n.epochS; }),
                    "seconds_of_day"_a = col([](const auto& n) { return n.secondsOfDay; }),
                    "tof_s"_a = col([](const auto& n) { return n.tofS; }), "oc_s"_a = col([](const auto& n) { return n.ocS; }),
                    "window_s"_a = col([](const auto& n) { return n.windowS; }),
                    "points"_a = col([](const auto& n) { return double(n.points); }),
                    "mean_residual_s"_a = col([](const auto& n) { return n.meanResidualS; }),
                    "rms_ps"_a = col([](const auto& n) { return n.rmsPs; }), "skew"_a = col([](const auto& n) { return n.skew; }),
                    "kurtosis"_a = col([](const auto& n) { return n.kurtosis; }),
                    "peak_minus_mean_ps"_a = col([](const auto& n) { return n.peakMinusMeanPs; }),
                    "return_rate_pct"_a = col([](const auto& n) { return n.returnRatePct; }));
}

// The readers: read_crd, read_cpf and read_sinex, as a run's load reads those files (core
// loadSlrPass with listOnly: a damaged prediction is refused as before any pass is screened).
slr::LoadedSlrPass contentsOf(slr::SlrSources src) {
    requireReadable(src.input);
    requireReadable(src.cpf);
    requireReadable(src.stations);
    src.listOnly = true;
    return loadSources(src);
}

void bindReaders(py::module_& m) {
    m.def("read_crd", [](const py::object& path) {
        slr::SlrSources src;
        src.input = fsPath(path);
        py::list out;
        for (const auto& s : contentsOf(src).opened.passes) out.append(summaryDict(s));
        return out;
    }, py::arg("path"), "The passes of a CRD file (v1 or v2, gzip too): one dict per pass (pass_number from 1, satellite, station, start, end, ranges, ...).");
    m.def("read_cpf", [](const py::object& path) {
        slr::SlrSources src;
        src.cpf = fsPath(path);
        const slr::LoadedSlrPass l = contentsOf(src);
        const slr::PassSources& c = *l.setup.predictions;
        check(!c.cpfFolder, src.cpf + ": a folder; read_cpf reads one CPF file");
        return py::dict("path"_a = src.cpf, "warnings"_a = c.cpfs.front().warnings);
    }, py::arg("path"), "Reads and checks a CPF prediction (raises laserwb.Error with FILE:LINE when it is not one).");
    m.def("read_sinex", [](const py::object& path) {
        slr::SlrSources src;
        src.stations = fsPath(path);
        const slr::LoadedSlrPass l = contentsOf(src);
        const slr::PassSources& c = *l.setup.predictions;
        std::vector<std::string> codes;
        for (const auto& s : c.stations.sites) codes.push_back(s.code);
        return py::dict("path"_a = src.stations, "sites"_a = codes, "solutions"_a = c.stations.solutions.size(),
                        "warnings"_a = c.stationWarnings);
    }, py::arg("path"), "Reads a SINEX file of station coordinates: its site codes and solutions.");
}

// Pass: one pass ready to screen.
void bindPass(py::module_& m) {
    py::class_<Pass>(m, "Pass", "One pass ready to screen: epochs and O-C (numpy views, no copy) and where the O-C came from.")
        .def_property_readonly("t", [](py::object self) { return viewOf(self.cast<const Pass&>().data->t, self); },
                               "epoch (s since 0h UTC of the pass day for CRD)")
        .def_property_readonly("oc", [](py::object self) { return viewOf(self.cast<const Pass&>().data->oc, self); }, "O-C (s, two-way)")
        .def_property_readonly("tof", [](py::object self) { return viewOf(self.cast<const Pass&>().data->tof, self); },
                               "observed two-way time of flight (s); empty for an O-C table")
        .def_property_readonly("station_flag", [](py::object self) { return viewOf(self.cast<const Pass&>().data->stationFlag, self); })
        .def_property_readonly("source", [](const Pass& p) { return p.data->source; })
        .def_property_readonly("start_mjd", [](const Pass& p) { return startMjd(*p.data); },
                               "MJD of the day the epochs count from (a CRD pass's H4 start day); None for an O-C table")
        .def_property_readonly("pass_number", [](const Pass& p) { return p.data->passIndex + 1; })
        .def_property_readonly("satellite", [](const Pass& p) { return p.data->satellite; })
        .def_property_readonly("ilrs_id", [](const Pass& p) { return p.data->ilrsId; })
        .def_property_readonly("station", [](const Pass& p) { return p.data->station; })
        .def_property_readonly("oc_origin", [](const Pass& p) { return p.data->ocOrigin; })
        .def_property_readonly("oc_note", [](const Pass& p) { return p.data->ocNote; })
        .def_property_readonly("warnings", [](const Pass& p) { return p.warnings; })
        .def_static("from_arrays", [](const py::array_t<double, py::array::c_style | py::array::forcecast>& t,
                                      const py::array_t<double, py::array::c_style | py::array::forcecast>& oc,
                                      const std::string& name) {
            if (t.ndim() != 1 || oc.ndim() != 1) throw py::value_error("t and oc must be 1-D arrays");
            // A source of its own (core openPass makes it an O-C table's pass), loaded as load_pass loads a file.
            auto arrays = std::make_shared<slr::OcArrays>();
            arrays->t.assign(t.data(), t.data() + t.size());
            arrays->oc.assign(oc.data(), oc.data() + oc.size());
            arrays->name = name;
            slr::SlrSources src;
            src.arrays = std::move(arrays);
            slr::LoadedSlrPass loaded = loadSources(src);
            loaded.setup.sources.arrays.reset();  // (the pass holds its columns; no file names it)
            return passOf(loaded);
        }, py::arg("t"), py::arg("oc"), py::arg("name") = "arrays",
           "A pass from epochs and O-C (s, two-way), as an O-C table's columns: run() screens it, write(csv=) writes its table.")
        .def("__len__", [](const Pass& p) { return p.data->t.size(); })
        .def("__repr__", [](const Pass& p) {
            return "<laserwb.slr.Pass " + p.data->source + " pass " + std::to_string(p.data->passIndex + 1) + ": " +
                   std::to_string(p.data->t.size()) + " points, O-C from " + p.data->ocOrigin + ">";
        });
}

// PassResult: a screened pass and its writers.
void bindPassResult(py::module_& m) {
    py::class_<PassRun>(m, "PassResult",
                        "A screened pass (PassTask): classes, post-fit, normal points, and its writers (the CLI's).")
        .def_property_readonly("params", [](const PassRun& r) { return r.settings.params; }, "the parameters the pass ran with")
        .def_property_readonly("t", [](py::object self) { return viewOf(self.cast<const PassRun&>().pass->t, self); },
                               "the pass's epochs (s), as Pass.t")
        .def_property_readonly("oc", [](py::object self) { return viewOf(self.cast<const PassRun&>().pass->oc, self); },
                               "the pass's O-C (s, two-way), as Pass.oc")
        .def_property_readonly("start_mjd", [](const PassRun& r) { return startMjd(*r.pass); }, "as Pass.start_mjd")
        .def_property_readonly("preset", [](const PassRun& r) { return r.settings.presetName; })
        .def_property_readonly("notes", [](const PassRun& r) { return r.settings.notes; }, "the normal-point context")
        .def_property_readonly("doubt", [](const PassRun& r) { return r.r.doubt; }, "why the result cannot be trusted ('' when it can)")
        .def_property_readonly("accepted", [](py::object self) { return maskOf(self.cast<const PassRun&>().r.accepted, self); },
                               "per point: True when signal or recovered (a bool mask: pass_.t[r.accepted])")
        .def_property_readonly("accepted_count", [](const PassRun& r) { return r.r.acceptedCount; })
        .def_property_readonly("classes", [](const PassRun& r) {
            py::list c;
            for (const auto pc : r.r.classes) c.append(slr::pointClassName(pc));
            return py::module_::import("numpy").attr("array")(c, "dtype"_a = "U");
        }, "per point, the run's class (the CSV's): 'signal', 'recovered', 'band' (taken by the post-fit's band) or 'noise'")
        .def_property_readonly("scale", [](const PassRun& r) {
            const auto& s = r.r.screen;
            return py::dict("mag_t"_a = s.magT, "mag_oc"_a = s.magOc, "area_limit"_a = s.areaLimit, "connectivity"_a = s.connectivity,
                            "trials"_a = s.trials.size());
        })
        .def_property_readonly("post_ok", [](const PassRun& r) { return r.r.postOk; })
        .def_property_readonly("post_note", [](const PassRun& r) { return r.r.postNote; })
        .def_property_readonly("residuals", [](py::object self) { return viewOf(self.cast<const PassRun&>().r.post.residuals, self); },
                               "per point: O-C minus the post-fit trend (s); empty without a post-fit")
        .def_property_readonly("kept", [](py::object self) { return maskOf(self.cast<const PassRun&>().r.post.kept, self); },
                               "per point: True when in the final post-fit (a bool mask)")
        .def_property_readonly("rms_s", [](const PassRun& r) { return r.r.postOk ? r.r.post.stats.rms : NAN; })
        .def_property_readonly("normal_points", [](const PassRun& r) { return normalPointColumns(slr::deliveredNormalPoints(r.r).points); },
                               "the normal points delivered (none when doubtful): {column: numpy array}")
        .def_property_readonly("no_normal_points_reason", [](const PassRun& r) { return slr::deliveredNormalPoints(r.r).noneReason; })
        .def_property_readonly("range_bias_s", [](const PassRun& r) { return r.r.bias.ok ? r.r.bias.rangeBiasS : NAN; })
        .def_property_readonly("time_bias_s", [](const PassRun& r) { return r.r.bias.ok ? r.r.bias.timeBiasS : NAN; })
        .def("__len__", [](const PassRun& r) { return r.r.accepted.size(); })
        .def("__repr__", [](const PassRun& r) {
            const slr::PassData& d = *r.pass;
            std::string s = "<laserwb.slr.PassResult " + d.source + " pass " + std::to_string(d.passIndex + 1) + ": " +
                            std::to_string(r.r.accepted.size()) + " points, " + std::to_string(r.r.acceptedCount) + " accepted";
            if (r.r.postOk) s += ", post-fit RMS " + core::formatFixed(r.r.post.stats.rms * 1e12, 1) + " ps";
            s += ", " + std::to_string(slr::deliveredNormalPoints(r.r).points.size()) + " normal points";
            if (!r.r.doubt.empty()) s += "; doubtful: " + r.r.doubt.substr(0, 120) + (r.r.doubt.size() > 120 ? "..." : "");
            return s + ">";
        })
        .def("write", [](const PassRun& r, const py::object& csv, const py::object& crd, const py::object& npt,
                         const py::object& report, const py::object& stationNp) {
            auto path = [](const py::object& o) { return o.is_none() ? std::string() : fsPath(o); };
            const std::string c = path(csv), f = path(crd), n = path(npt), rep = path(report), snp = path(stationNp);
            py::gil_scoped_release nogil;
            writeProducts(r, c, f, n, rep, snp);
        }, py::arg("csv") = py::none(), py::arg("crd") = py::none(), py::arg("npt") = py::none(),
           py::arg("report") = py::none(), py::arg("station_np") = py::none(),
           "Writes the products with the CLI's writers, all or nothing: csv (as -o), crd (as --crd-out: the\n"
           "CRD with this pass's filter flags), npt (as --npt-out: the normal points, or why there are none),\n"
           "report (as --report-out: the one-page PDF), with station_np (as --station-np: the station's\n"
           "normal points compared in it).");
}

// tune: laserwb-cli slr tune's task (core tuneSlr, writeTunedPreset), its record as a dict.
py::dict tunePasses(const py::object& files, const py::object& satellite, const py::object& preset, const py::object& presetOut,
                    const py::object& threads, const py::object& sessions, const py::object& cpf, const py::object& stations,
                    bool cpfFallback) {
    slr::TuneSources src;
    // (a folder among the files: a station's archive, as for the CLI)
    auto paths = [](const py::object& o, std::vector<std::string>* out) {
        if (o.is_none()) return;
        if (py::isinstance<py::str>(o) || py::hasattr(o, "__fspath__")) out->push_back(inputPath(o, true));
        else
            for (const py::handle f : o) out->push_back(inputPath(py::reinterpret_borrow<py::object>(f), true));
    };
    if (!cpf.is_none()) {
        if (stations.is_none()) throw ParameterError("cpf and stations go together (O-C from the prediction needs both)");
        src.cpf = fsPath(cpf);
        requireReadable(src.cpf, true);
    }
    if (!stations.is_none()) src.stations = inputPath(stations);
    src.cpfFallback = cpfFallback;
    paths(files, &src.files);
    paths(sessions, &src.sessions);
    if (!satellite.is_none()) src.satellite = std::string(py::str(satellite));
    if (!preset.is_none()) src.presets = inputPath(preset);
    src.threads = threadCount(threads);
    const std::string out = presetOut.is_none() ? std::string() : fsPath(presetOut);
    slr::TuneResult r;
    std::string err, note;
    bool written = true;
    {
        py::gil_scoped_release nogil;
        r = slr::tuneSlr(src);
        if (r.ok && !out.empty()) written = slr::writeTunedPreset(r, src, out, &err, &note);
    }
    if (!r.ok) raise(r.error);
    check(written, err);
    py::dict d = py::module_::import("json").attr("loads")(core::dumpJson(slr::tuneSummary(r)));
    d["notes"] = r.notes;
    d["written"] = note;
    return d;
}

// The runs: load_pass, run, set_search_threads, process_file, tune and default_params.
void bindRuns(py::module_& m) {
    m.def("load_pass", &pyLoadPass, py::arg("path"), py::arg("pass_number") = py::none(), py::arg("cpf") = py::none(),
          py::arg("stations") = py::none(), py::arg("params") = py::none(),
          "Loads one pass of a CRD file (pass_number from 1; default the first with full-rate records) or an\n"
          "O-C CSV. With cpf (a file or a folder) and stations (SINEX), O-C from the prediction; without,\n"
          "O-C against the pass's own TOF trend. params (SlrParams or {key: value}): their oc.* rows make\n"
          "the O-C (run() refuses other oc.* values). Bad files raise laserwb.Error with FILE:LINE.");
    m.def("run", &pyRun, py::arg("pass_"), py::arg("params") = py::none(), py::arg("preset") = py::none(),
          py::arg("satellite") = py::none(), py::arg("stations") = py::none(), py::arg("threads") = py::none(),
          "Screens a Pass (or the first pass of a file's path, loaded as load_pass(path, params=params)),\n"
          "fits the trend and forms the normal points (PassTask), with the settings\n"
          "laserwb-cli slr makes: its defaults, the preset file's entry for the satellite (preset,\n"
          "satellite), the normal-point context (stations: SINEX for day or night), then params (a\n"
          "SlrParams as --config, or {key: value} as --set). threads: the scale search's threads (0: every\n"
          "core; None: set_search_threads's default); the answer is the same for any number. The GIL is\n"
          "released while it runs.");
    m.def("set_search_threads", [](const py::object& n) { gDefaultSearchThreads.store(threadCount(n)); }, py::arg("n"),
          "The default of run(threads=None): threads of the automatic scale search, 0..256 (0: every core,\n"
          "the default). The answer is the same for any number; a Dask worker running one pass per task\n"
          "sets 1 (as slr --all-passes does).");
    m.def("process_file", &processFile, py::arg("path"), py::arg("out_dir"), py::arg("params") = py::none(),
          py::arg("preset") = py::none(), py::arg("satellite") = py::none(), py::arg("cpf") = py::none(),
          py::arg("stations") = py::none(), py::arg("threads") = 0,
          "A station's file of passes, every block, into out_dir: the products of laserwb-cli slr --all-passes\n"
          "--out-dir OUT_DIR, byte for byte (passNNN.csv/.frd/.npt, normal_points.npt, summary.csv,\n"
          "provenance.json). Returns one dict per block with summary.csv's columns (text).");
    m.def("tune", &tunePasses, py::arg("files"), py::arg("satellite") = py::none(), py::arg("preset") = py::none(),
          py::arg("preset_out") = py::none(), py::arg("threads") = py::none(), py::arg("sessions") = py::none(),
          py::arg("cpf") = py::none(), py::arg("stations") = py::none(), py::arg("cpf_fallback") = false,
          "A satellite's parameters from the station's own filter flags, as laserwb-cli slr tune: every pass\n"
          "of the CRD files (one path or a list; a folder: its CRD files, what cannot be tuned on there left\n"
          "out with the reason in notes; an O-C table with a station_flag column, as slr -o writes it, with\n"
          "satellite=; sessions: workbench sessions whose pass is labelled by the analyst's edits, as\n"
          "--session; cpf and stations: the O-C from the prediction, as --cpf, --stations, cpf_fallback as\n"
          "--cpf-fallback) screened with each candidate, the best mean F1 against the\n"
          "flags chosen (another than the starting point only for a gain beyond 0.001 that loses on no pass\n"
          "more than 0.002, and only when it holds out, leave one pass out, better than the starting point). preset: start from the satellite's entry of this presets\n"
          "file; preset_out: write the entry there (its other entries kept) with its provenance, the CLI's\n"
          "bytes. Returns the record: satellite, chosen, f1_before, f1_after, f1_held_out, passes, notes.");
    m.def("default_params", [] { return slr::commandDefaults(); }, "The defaults of laserwb-cli slr.");
}

}  // namespace

void bindSlr(py::module_& top) {
    py::module_ m = top.def_submodule("slr", "SLR passes: CRD/CPF/SINEX, O-C, screening (paper 004), post-fit, normal points.");
    bindParams(m, kParams);

    bindReaders(m);
    bindPass(m);
    bindPassResult(m);
    bindRuns(m);
}

}  // namespace lwb::py
