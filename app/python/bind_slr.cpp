// laserwb.slr: an SLR pass from its files to its products, as `laserwb-cli slr` runs it: the
// readers (CRD, CPF, SINEX; core/slr/pass_input.hpp loadPass: O-C from the prediction or the
// pass's own TOF trend), the settings of a pass (passSettings: preset, normal-point context),
// the task (PassTask: screening, post-fit, normal points, judgeRun) and its writers
// (core/slr/pass_output.hpp). Nothing here computes: the CLI and the workbench call the same.
#include <memory>

#include "bind.hpp"
#include "core/common/output_set.hpp"
#include "core/slr/cpf.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_output.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/screen_auto.hpp"
#include "core/slr/sinex.hpp"
#include "core/slr/slr_params.hpp"

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

// Prefixes the input file to a message that does not name it already (as the CLI does).
std::string named(const std::string& path, const std::string& msg) {
    return msg.rfind(path, 0) == 0 ? msg : path + ": " + msg;
}

/// A loaded pass, shared with its results (the arrays are views of it).
struct Pass {
    std::shared_ptr<const slr::PassData> data;
    std::vector<std::string> warnings;
};

/// A pass's run: its settings and the task's outputs.
struct PassRun {
    std::shared_ptr<const slr::PassData> pass;
    slr::PassSettings settings;
    slr::PassRunResult r;
};

// A reader's result for `file`, read with the GIL released; raises with the core's message.
template <class R, class F>
R readReleased(const std::string& file, F read) {
    R r;
    {
        py::gil_scoped_release nogil;
        r = read(file);
    }
    check(r.ok, named(file, r.error));
    return r;
}

py::dict summaryDict(const slr::PassSummary& s) {
    return py::dict("pass_number"_a = s.index + 1, "satellite"_a = s.satellite, "ilrs_id"_a = s.ilrsId, "station"_a = s.station,
                    "start"_a = s.start, "end"_a = s.end, "ranges"_a = s.ranges, "normal_points"_a = s.normalPoints,
                    "data_type"_a = s.dataType, "problem"_a = s.problem);
}

std::string fsPath(const py::object& o) { return py::str(py::module_::import("os").attr("fspath")(o)); }

Pass loadPass(const py::object& path, const py::object& passNumber, const py::object& cpf, const py::object& stations) {
    slr::PassInputParams in;
    // (stations alone give no O-C: run() takes them for day or night, as the CLI's --stations)
    if (!cpf.is_none()) {
        if (stations.is_none()) throw ParameterError("cpf and stations go together (O-C from the prediction needs both)");
        in.cpfPath = fsPath(cpf);
        in.sinexPath = fsPath(stations);
    }
    const std::string input = fsPath(path);
    const int index = passNumber.is_none() ? -1 : passNumber.cast<int>() - 1;
    if (!passNumber.is_none() && index < 0) throw ParameterError("pass_number counts from 1");
    slr::PassInputResult loaded;
    {
        py::gil_scoped_release nogil;
        loaded = slr::loadPass(input, index, in);
    }
    check(loaded.ok, named(input, loaded.error));
    // A record of the pass the reader had to skip: its points are incomplete and every writer refuses it.
    check(loaded.pass.damaged.empty(), loaded.pass.damaged + "; nothing written");
    Pass p;
    p.data = std::make_shared<const slr::PassData>(std::move(loaded.pass));
    p.warnings = loaded.warnings;
    return p;
}

PassRun runPass(const Pass& pass, const py::object& params, const py::object& preset, const py::object& satellite,
                const py::object& stations) {
    // The settings as the CLI makes them: its defaults, the preset and the normal-point context of
    // the pass (passSettings), then the analyst's own (a SlrParams as --config, a dict as --set).
    std::vector<slr::SatellitePreset> presets;
    if (!preset.is_none()) {
        const std::string file = fsPath(preset);
        const slr::PresetsResult pr = slr::loadPresets(file);
        check(pr.ok, named(file, pr.error));
        presets = pr.presets;
    }
    slr::SinexReadResult snx;
    if (!stations.is_none()) {
        const std::string file = fsPath(stations);
        snx = slr::readSinex(file);
        check(snx.ok, named(file, snx.error));
    }
    PassRun run;
    run.pass = pass.data;
    std::string err;
    const std::string sat = satellite.is_none() ? std::string() : std::string(py::str(satellite));
    if (!slr::passSettings(*pass.data, slr::commandDefaults(), preset.is_none() ? nullptr : &presets, sat,
                           snx.ok ? &snx.file : nullptr, &run.settings, &err))
        throw Error(fsPath(preset) + ": " + err);
    const slr::PostfitParams fromPass = run.settings.params.postfit;
    if (py::isinstance<slr::SlrParams>(params)) {
        std::string e;
        const slr::SlrParams given = params.cast<slr::SlrParams>();
        if (!slr::slrSchema().fromJson(slr::slrSchema().toJson(given), &run.settings.params, &e)) throw ParameterError(e);
    } else if (py::isinstance<py::dict>(params)) {
        applyDict(slr::slrSchema(), params.cast<py::dict>(), &run.settings.params);
    } else if (!params.is_none()) {
        throw py::type_error("params must be None, a dict {key: value} or laserwb.slr.SlrParams");
    }
    slr::keepPassContext(fromPass, &run.settings.params.postfit);
    if (const std::string e = slr::validate(run.settings.params.screen); !e.empty())
        throw ParameterError((run.settings.presetName.empty() ? std::string() : "preset " + run.settings.presetName + ": ") + e);
    {
        py::gil_scoped_release nogil;
        run.r = slr::runPass(*pass.data, run.settings.params);
    }
    const std::string what = pass.data->hasCrd ? pass.data->source + " pass " + std::to_string(pass.data->passIndex + 1)
                                               : pass.data->source;
    check(run.r.ok, what + ": " + run.r.error);
    return run;
}

// The products of a run as the one-pass CLI writes them, all or nothing (core::OutputSet).
void writeProducts(const PassRun& run, const std::string& csv, const std::string& crd, const std::string& npt) {
    const slr::PassData& pass = *run.pass;
    const slr::PassRunResult& r = run.r;
    core::OutputSet outs;
    outs.addInput(pass.source);
    for (const std::string* p : {&csv, &crd, &npt})
        if (!p->empty()) outs.addOutput(*p);
    if (csv.empty() && crd.empty() && npt.empty()) throw ParameterError("no output: give csv, crd or npt");
    if (!outs.check()) throw Error(outs.error());
    if ((!crd.empty() || !npt.empty()) && !pass.hasCrd)
        throw ParameterError(std::string(!crd.empty() ? "crd" : "npt") + " needs a CRD input (its headers and records are written back); " +
                             pass.source + " is an O-C table");
    if (!npt.empty() && !(run.settings.params.postfit.binLengthS > 0) && !(run.settings.params.postfit.altitudeKm > 0))
        throw ParameterError("no normal points: the satellite's altitude is unknown (give postfit.bin_length_s or a preset with altitude_km)");
    const slr::DeliveredNormalPoints nps = slr::deliveredNormalPoints(r);
    std::string err;
    if (!csv.empty() && !slr::writeScreenCsv(outs.stagingPath(csv), pass, r.screen, r.accepted, r.postOk ? &r.post : nullptr, &err))
        throw Error(named(csv, outs.unstaged(err)));
    if (!crd.empty() && !slr::writeScreenedCrd(outs.stagingPath(crd), pass, r.accepted, &err))
        throw Error(named(crd, outs.unstaged(err)));
    if (!npt.empty() &&
        !slr::writeNormalPointCrd(outs.stagingPath(npt), pass, nps.points, &err,
                                  slr::normalPointProduct(r.postOk ? &r.post : nullptr, &r.screen, nps.noneReason)))
        throw Error(named(npt, outs.unstaged(err)));
    check(outs.commit(), outs.error());
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

}  // namespace

void bindSlr(py::module_& top) {
    py::module_ m = top.def_submodule("slr", "SLR passes: CRD/CPF/SINEX, O-C, screening (paper 004), post-fit, normal points.");
    bindParams(m, kParams);

    m.def("read_crd", [](const py::object& path) {
        const std::string file = fsPath(path);
        const auto r = readReleased<slr::CrdReadResult>(file, [](const std::string& f) { return slr::readCrd(f); });
        py::list out;
        for (const auto& s : slr::summarisePasses(r.file)) out.append(summaryDict(s));
        return out;
    }, py::arg("path"), "The passes of a CRD file (v1 or v2, gzip too): one dict per pass (pass_number from 1, satellite, station, start, end, ranges, ...).");
    m.def("read_cpf", [](const py::object& path) {
        const std::string file = fsPath(path);
        const auto r = readReleased<slr::CpfReadResult>(file, [](const std::string& f) { return slr::readCpf(f); });
        return py::dict("path"_a = file, "warnings"_a = r.warnings);
    }, py::arg("path"), "Reads and checks a CPF prediction (raises laserwb.Error with FILE:LINE when it is not one).");
    m.def("read_sinex", [](const py::object& path) {
        const std::string file = fsPath(path);
        const auto r = readReleased<slr::SinexReadResult>(file, [](const std::string& f) { return slr::readSinex(f); });
        std::vector<std::string> codes;
        for (const auto& s : r.file.sites) codes.push_back(s.code);
        return py::dict("path"_a = file, "sites"_a = codes, "solutions"_a = r.file.solutions.size(), "warnings"_a = r.warnings);
    }, py::arg("path"), "Reads a SINEX file of station coordinates: its site codes and solutions.");

    py::class_<Pass>(m, "Pass", "One pass ready to screen: epochs and O-C (numpy views, no copy) and where the O-C came from.")
        .def_property_readonly("t", [](py::object self) { return viewOf(self.cast<const Pass&>().data->t, self); },
                               "epoch (s since 0h UTC of the pass day for CRD)")
        .def_property_readonly("oc", [](py::object self) { return viewOf(self.cast<const Pass&>().data->oc, self); }, "O-C (s, two-way)")
        .def_property_readonly("tof", [](py::object self) { return viewOf(self.cast<const Pass&>().data->tof, self); },
                               "observed two-way time of flight (s); empty for an O-C table")
        .def_property_readonly("station_flag", [](py::object self) { return viewOf(self.cast<const Pass&>().data->stationFlag, self); })
        .def_property_readonly("source", [](const Pass& p) { return p.data->source; })
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
            std::vector<double> tv(t.data(), t.data() + t.size()), ov(oc.data(), oc.data() + oc.size());
            slr::PassInputResult r;
            {
                py::gil_scoped_release nogil;
                r = slr::passFromOc(std::move(tv), std::move(ov), name);
            }
            check(r.ok, r.error);
            Pass p;
            p.data = std::make_shared<const slr::PassData>(std::move(r.pass));
            p.warnings = r.warnings;
            return p;
        }, py::arg("t"), py::arg("oc"), py::arg("name") = "arrays",
           "A pass from epochs and O-C (s, two-way), as an O-C table's columns: run() screens it, write(csv=) writes its table.")
        .def("__len__", [](const Pass& p) { return p.data->t.size(); })
        .def("__repr__", [](const Pass& p) {
            return "<laserwb.slr.Pass " + p.data->source + " pass " + std::to_string(p.data->passIndex + 1) + ": " +
                   std::to_string(p.data->t.size()) + " points, O-C from " + p.data->ocOrigin + ">";
        });

    py::class_<PassRun>(m, "PassResult",
                        "A screened pass (PassTask): classes, post-fit, normal points, and its writers (the CLI's).")
        .def_property_readonly("params", [](const PassRun& r) { return r.settings.params; }, "the parameters the pass ran with")
        .def_property_readonly("preset", [](const PassRun& r) { return r.settings.presetName; })
        .def_property_readonly("notes", [](const PassRun& r) { return r.settings.notes; }, "the normal-point context")
        .def_property_readonly("doubt", [](const PassRun& r) { return r.r.doubt; }, "why the result cannot be trusted ('' when it can)")
        .def_property_readonly("accepted", [](py::object self) { return viewOf(self.cast<const PassRun&>().r.accepted, self); },
                               "per point: 1 signal or recovered")
        .def_property_readonly("accepted_count", [](const PassRun& r) { return r.r.acceptedCount; })
        .def_property_readonly("classes", [](const PassRun& r) {
            py::list c;
            for (const auto pc : r.r.screen.pointClass) c.append(slr::pointClassName(pc));
            return py::module_::import("numpy").attr("array")(c, "dtype"_a = "U");
        }, "per point: 'signal', 'recovered' or 'noise'")
        .def_property_readonly("scale", [](const PassRun& r) {
            const auto& s = r.r.screen;
            return py::dict("mag_t"_a = s.magT, "mag_oc"_a = s.magOc, "area_limit"_a = s.areaLimit, "connectivity"_a = s.connectivity,
                            "trials"_a = s.trials.size());
        })
        .def_property_readonly("post_ok", [](const PassRun& r) { return r.r.postOk; })
        .def_property_readonly("post_note", [](const PassRun& r) { return r.r.postNote; })
        .def_property_readonly("residuals", [](py::object self) { return viewOf(self.cast<const PassRun&>().r.post.residuals, self); },
                               "per point: O-C minus the post-fit trend (s); empty without a post-fit")
        .def_property_readonly("kept", [](py::object self) { return viewOf(self.cast<const PassRun&>().r.post.kept, self); },
                               "per point: 1 when in the final post-fit")
        .def_property_readonly("rms_s", [](const PassRun& r) { return r.r.postOk ? r.r.post.stats.rms : NAN; })
        .def_property_readonly("normal_points", [](const PassRun& r) { return normalPointColumns(slr::deliveredNormalPoints(r.r).points); },
                               "the normal points delivered (none when doubtful): {column: numpy array}")
        .def_property_readonly("no_normal_points_reason", [](const PassRun& r) { return slr::deliveredNormalPoints(r.r).noneReason; })
        .def_property_readonly("range_bias_s", [](const PassRun& r) { return r.r.bias.ok ? r.r.bias.rangeBiasS : NAN; })
        .def_property_readonly("time_bias_s", [](const PassRun& r) { return r.r.bias.ok ? r.r.bias.timeBiasS : NAN; })
        .def("write", [](const PassRun& r, const py::object& csv, const py::object& crd, const py::object& npt) {
            const std::string c = csv.is_none() ? "" : fsPath(csv), f = crd.is_none() ? "" : fsPath(crd), n = npt.is_none() ? "" : fsPath(npt);
            py::gil_scoped_release nogil;
            writeProducts(r, c, f, n);
        }, py::arg("csv") = py::none(), py::arg("crd") = py::none(), py::arg("npt") = py::none(),
           "Writes the products with the CLI's writers, all or nothing: csv (as -o), crd (as --crd-out: the\n"
           "CRD with this pass's filter flags), npt (as --npt-out: the normal points, or why there are none).");

    m.def("load_pass", &loadPass, py::arg("path"), py::arg("pass_number") = py::none(), py::arg("cpf") = py::none(),
          py::arg("stations") = py::none(),
          "Loads one pass of a CRD file (pass_number from 1; default the first with full-rate records) or an\n"
          "O-C CSV. With cpf (a file or a folder) and stations (SINEX), O-C from the prediction; without,\n"
          "O-C against the pass's own TOF trend. Bad files raise laserwb.Error with FILE:LINE.");
    m.def("run", &runPass, py::arg("pass_"), py::arg("params") = py::none(), py::arg("preset") = py::none(),
          py::arg("satellite") = py::none(), py::arg("stations") = py::none(),
          "Screens a Pass, fits the trend and forms the normal points (PassTask), with the settings\n"
          "laserwb-cli slr makes: its defaults, the preset file's entry for the satellite (preset,\n"
          "satellite), the normal-point context (stations: SINEX for day or night), then params (a\n"
          "SlrParams as --config, or {key: value} as --set). The GIL is released while it runs.");
    m.def("set_search_threads", [](int n) { slr::setScaleSearchThreads(n); }, py::arg("n"),
          "Threads of the automatic scale search (0: every core, the default). The answer is the same\n"
          "for any number; a Dask worker running one pass per task sets 1 (as slr --all-passes does).");
    m.def("default_params", [] { return slr::commandDefaults(); }, "The defaults of laserwb-cli slr.");
}

}  // namespace lwb::py
