// laserwb.footprint: the footprint shots (core/footprint/batch.hpp: runFootprintBatch for files,
// runFootprintFrames for frames already in numpy arrays — the same processFrame per frame) and
// the report's writer (writeFootprintCsv, footprintCsvRows), as `laserwb-cli footprint` runs them.
#include <cstring>

#include <cmath>
#include <map>

#include "bind.hpp"
#include "core/footprint/batch.hpp"
#include "core/footprint/footprint_run.hpp"
#include "core/footprint/tune.hpp"
#include "core/footprint/report_columns.hpp"
#include "core/footprint/image_io.hpp"

namespace lwb::py {

namespace fp = core::footprint;
using namespace pybind11::literals;

namespace {

fp::FootprintParams defaults() { return {}; }
std::string familyCheck(const fp::FootprintParams& p) { return fp::validate(p); }
bool fromJson(const core::JsonParseResult& j, fp::FootprintParams* p, std::string* err) {
    return fp::footprintParamsFromJson(j.value, p, err, &j);
}
// An ROI size set by the analyst: a frame smaller than it is an error (as --roi / --set roi.size).
void afterSet(fp::FootprintParams* p, const std::string& key) {
    if (key == "roi.size") p->roi.sizeExplicit = true;
}
const ParamsBinding<fp::FootprintParams> kParams{
    "FootprintParams", "Parameters of the footprint shots (laserwb-cli footprint; core/footprint/pipeline.hpp).",
    fp::footprintSchema, defaults, familyCheck, fromJson, afterSet};

/// A run's items and its method: the report's rows.
struct Report : Recorded {
    fp::BatchResult result;
    fp::Method method = fp::Method::Gauss;
    std::string rows() const {
        std::string s;
        for (const auto& it : result.items) s += fp::footprintCsvRows(it, method);
        return s;
    }
};

// The report's columns from the column table's getters (core/footprint/report_columns.hpp), as
// the core computed them: text as str, whole numbers as int64 (-1 empty), the rest float64 at
// full precision (NaN empty). The CSV's rounding is the CSV's only (x 14.8403 was 14.84031...).
py::dict reportColumns(const Report& rep) {
    std::vector<fp::ReportRow> rows;
    for (const auto& it : rep.result.items)
        for (fp::ReportRow& r : fp::reportRows(it, rep.method)) rows.push_back(r);
    const py::object numpy = py::module_::import("numpy");
    py::dict out;
    const auto n = static_cast<py::ssize_t>(rows.size());
    for (const fp::FootprintColumn& c : fp::footprintColumns()) {
        if (c.reviewOnly) continue;
        if (c.type == fp::ColumnType::Text) {
            py::list cells;
            for (const auto& r : rows) cells.append(c.value(r).text);
            out[c.name] = numpy.attr("array")(cells, "dtype"_a = "U");
        } else if (c.type == fp::ColumnType::Integer) {
            py::array_t<long long> a(n);
            long long* w = a.mutable_data();
            for (py::ssize_t i = 0; i < n; ++i) {
                const double v = c.value(rows[static_cast<size_t>(i)]).number;
                w[i] = std::isfinite(v) ? static_cast<long long>(v) : -1;
            }
            out[c.name] = a;
        } else {
            py::array_t<double> a(n);
            double* w = a.mutable_data();
            for (py::ssize_t i = 0; i < n; ++i) w[i] = c.value(rows[static_cast<size_t>(i)]).number;
            out[c.name] = a;
        }
    }
    return out;
}

// The sources as the CLI gathers them from its flags: a FootprintParams (its --config), the
// preset, the method (its alias), then a dict's keys (its --set options); the core resolves them.
fp::FootprintSources sourcesOf(const py::object& params, const py::object& preset, const py::object& method) {
    fp::FootprintSources src;
    gatherParams(params, fp::footprintSchema(), "laserwb.FootprintParams", &src.config, &src.set);
    if (!preset.is_none()) src.preset = py::str(preset);
    if (!method.is_none()) src.set.insert(src.set.begin(), {"method", py::str(method), "method"});
    return src;
}

[[noreturn]] void raise(const fp::FootprintError& e) {
    if (e.usage) throw ParameterError(e.message);
    throw Error(e.message);
}

// The first failure of a run in input order, as the CLI reports it without --keep-going.
std::string firstFailure(const fp::BatchResult& r) {
    for (const auto& it : r.items) {
        if (!it.readError.empty()) return it.readError;
        for (const auto& roi : it.rois)
            if (!roi.result.ok) return it.file + ": " + roi.result.error;
    }
    return {};
}

// tune: laserwb-cli footprint tune's task (core tuneFootprint, writeTunedFootprintConfig), its
// record as a dict.
py::dict tuneShots(const py::object& inputs, const py::object& verdicts, const py::object& configOut, const py::object& params,
                   const py::object& preset, const py::object& method, const py::object& centres, const py::object& rawSize,
                   long long maxPixels, int threads, int folds) {
    fp::FootprintTuneSources src;
    src.run = sourcesOf(params, preset, method);
    if (py::isinstance<py::str>(inputs) || py::hasattr(inputs, "__fspath__")) src.run.inputs.push_back(inputPath(inputs, true));
    else
        for (const py::handle f : inputs) src.run.inputs.push_back(inputPath(py::reinterpret_borrow<py::object>(f), true));
    src.run.threads = threads;
    if (maxPixels > 0) src.run.read.maxPixels = maxPixels;
    if (!rawSize.is_none()) {
        const auto wh = sizeArgument(rawSize, "raw_size");
        src.run.read.rawWidth = wh.first;
        src.run.read.rawHeight = wh.second;
    }
    if (!centres.is_none())
        for (const auto& c : pointsArgument(centres, "centres")) src.run.centres.emplace_back(c.first, c.second);
    src.verdicts = inputPath(verdicts);
    src.folds = folds;
    const std::string out = configOut.is_none() ? std::string() : fsPath(configOut);
    fp::FootprintTuneResult r;
    std::string err;
    bool written = true;
    {
        py::gil_scoped_release nogil;
        r = fp::tuneFootprint(src);
        if (r.ok && !out.empty()) written = fp::writeTunedFootprintConfig(r, src, out, &err);
    }
    if (!r.ok) raise(r.error);
    if (!written) throw Error(err);
    py::module_ json = py::module_::import("json");
    py::dict d = json.attr("loads")(core::dumpJson(fp::footprintTuneSummary(r)));
    d["params"] = json.attr("loads")(core::dumpJson(fp::footprintParamsToJson(r.tuning.after)));
    return d;
}

using Frame = py::array_t<float, py::array::c_style | py::array::forcecast>;

Report fitBatch(const py::object& inputs, const py::object& params, const py::object& preset, const py::object& method,
                const py::object& centres, const py::object& rawSize, long long maxPixels, int threads,
                const py::object& names, bool keepGoing) {
    fp::FootprintSources src = sourcesOf(params, preset, method);
    src.threads = threads;
    if (maxPixels > 0) src.read.maxPixels = maxPixels;
    if (!rawSize.is_none()) {
        const auto wh = sizeArgument(rawSize, "raw_size");
        src.read.rawWidth = wh.first;
        src.read.rawHeight = wh.second;
    }
    if (!centres.is_none())
        for (const auto& c : pointsArgument(centres, "centres")) src.centres.emplace_back(c.first, c.second);
    fp::FootprintSetup setup;
    fp::FootprintError fe;
    if (!fp::resolveBatchParams(src, &setup.params, &fe)) raise(fe);
    const fp::BatchParams& bp = setup.params;
    Report rep;
    bool fromFiles = false;  // (frames read from files, not arrays: the provenance lists them)
    rep.method = bp.footprint.method;
    // Frames in memory: float32 C-contiguous arrays are viewed in place (no copy); other dtypes are
    // converted once. A 3-D array is a stack of frames.
    std::vector<Frame> held;
    std::vector<cv::Mat> frames;
    const bool isArray = py::isinstance<py::array>(inputs);
    bool isFrames = isArray;
    if (!isArray && py::isinstance<py::sequence>(inputs) && !py::isinstance<py::str>(inputs)) {
        const py::sequence s = inputs.cast<py::sequence>();
        isFrames = s.size() > 0 && py::isinstance<py::array>(s[0]);
    }
    // A frame's size against the same limit as a frame read from a file (max_pixels, default
    // the reader's), before any copy or work: a 20000^2 array was processed until killed at 6 GB.
    const long long limit = src.read.maxPixels;
    auto sizeChecked = [&](const py::object& o, const std::string& what) {
        if (!py::isinstance<py::array>(o) || limit <= 0) return;
        const py::array a = py::reinterpret_borrow<py::array>(o);
        if (a.ndim() < 2) return;
        const long long h = static_cast<long long>(a.shape(a.ndim() - 2)), w = static_cast<long long>(a.shape(a.ndim() - 1));
        if (h > 0 && w > limit / h)
            throw ParameterError(what + ": a frame of " + std::to_string(w) + " x " + std::to_string(h) +
                                 " pixels is more than the limit of " + std::to_string(limit) +
                                 " pixels a frame (max_pixels=); a footprint frame is 550 x 550");
    };
    if (isFrames) {
        std::vector<py::object> parts;
        if (isArray) {
            sizeChecked(inputs, "frames");
            Frame a = Frame::ensure(inputs);
            if (!a) throw py::type_error("frames must be numbers");
            if (a.ndim() == 2) parts.push_back(a);
            else if (a.ndim() == 3) held.push_back(a);
            else throw py::value_error("frames must be a 2-D array (one frame) or a 3-D array (a stack of frames)");
        } else {
            for (const auto& o : inputs.cast<py::sequence>()) parts.push_back(py::reinterpret_borrow<py::object>(o));
        }
        for (size_t i = 0; i < parts.size(); ++i) {
            const py::object& o = parts[i];
            sizeChecked(o, "frame " + std::to_string(i));
            Frame a = Frame::ensure(o);
            if (!a || a.ndim() != 2) throw py::value_error("every frame must be a 2-D array of numbers");
            held.push_back(a);
        }
        for (const Frame& a : held) {
            if (a.ndim() == 3) {
                const int n = static_cast<int>(a.shape(0)), h = static_cast<int>(a.shape(1)), w = static_cast<int>(a.shape(2));
                for (int i = 0; i < n; ++i)
                    frames.emplace_back(h, w, CV_32FC1, const_cast<float*>(a.data()) + static_cast<size_t>(i) * h * w);
            } else {
                frames.emplace_back(static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)), CV_32FC1,
                                    const_cast<float*>(a.data()));
            }
        }
        std::vector<std::string> frameNames;
        if (!names.is_none()) {  // (pybind11's own words were "Unable to cast Python instance")
            try {
                frameNames = names.cast<std::vector<std::string>>();
            } catch (const py::cast_error&) {
                throw py::type_error("names must be a list of str, one per frame, not " +
                                     std::string(py::str(names).cast<std::string>()).substr(0, 80));
            }
        }
        else
            for (size_t i = 0; i < frames.size(); ++i) frameNames.push_back(std::to_string(i));
        if (frameNames.size() != frames.size())
            throw py::value_error("names: " + std::to_string(frameNames.size()) + " for " + std::to_string(frames.size()) + " frames");
        py::gil_scoped_release nogil;
        rep.result = fp::runFootprintFrames(frames, frameNames, bp);
    } else {
        std::vector<std::string> given;
        // (keep_going: a file that cannot be read is a rejected row, as --keep-going writes it)
        auto path = [&](const py::object& o) { return keepGoing ? fsPath(o) : inputPath(o, true); };
        if (py::isinstance<py::str>(inputs) || py::hasattr(inputs, "__fspath__"))
            given.push_back(path(inputs));
        else
            for (const auto& o : inputs.cast<py::sequence>()) given.push_back(path(py::reinterpret_borrow<py::object>(o)));
        src.inputs = given;
        src.keepGoing = keepGoing;
        fromFiles = true;
        bool ok;
        {
            py::gil_scoped_release nogil;  // (the set-up reads shot lists)
            ok = fp::setUpFootprintRun(src, &setup, &fe);
            if (ok) rep.result = fp::runFootprintBatch(setup.shots, setup.params);
        }
        if (!ok) raise(fe);
    }
    if (!keepGoing)
        if (const std::string e = firstFailure(rep.result); !e.empty())
            throw Error(e + " (keep_going=True reports it as a rejected row)");
    // (the provenance of the report written from it: the parameters, the frames read as files)
    std::vector<std::string> read;
    if (fromFiles)
        for (const auto& it : rep.result.items)
            if (it.readError.empty()) read.push_back(it.file);
    rep.record("footprint", fp::footprintSchema().toJson(setup.params.footprint), read);
    return rep;
}

}  // namespace

void bindFootprint(py::module_& top) {
    py::module_ m = top.def_submodule("footprint", "Footprint-camera shots: spot centre, verdict and the report (paper 000/001).");
    bindParams(m, kParams);

    m.def("read_frame", [](const std::string& path, const py::object& rawSize, long long maxPixels) {
        // The frame as a run reads a shot's (core resolveBatchParams + readShotFrame).
        fp::FootprintSources src;
        if (maxPixels > 0) src.read.maxPixels = maxPixels;
        if (!rawSize.is_none()) {
            const auto wh = sizeArgument(rawSize, "raw_size");
            src.read.rawWidth = wh.first;
            src.read.rawHeight = wh.second;
        }
        fp::BatchParams bp;
        fp::FootprintError fe;
        if (!fp::resolveBatchParams(src, &bp, &fe)) raise(fe);
        fp::ShotSpec shot;
        shot.file = path;
        requireReadable(path);
        fp::ImageReadResult r;
        {
            py::gil_scoped_release nogil;
            r = fp::readShotFrame(shot, bp);
        }
        check(r.ok, r.error);
        return ownedArray(r.image);  // (the array owns the decoded frame: no copy)
    }, py::arg("path"), py::arg("raw_size") = py::none(), py::arg("max_pixels") = 0,
       "One frame or ROI as the CLI reads it (16-bit PNG/TIFF/PGM, raw with raw_size=(w, h)): a float32 array of DN.");

    py::class_<Report>(m, "Report", "The footprint report of a run: one row per ROI, the columns of laserwb-cli footprint -o.")
        .def("__len__", [](const Report& r) {
            size_t n = 0;
            for (const auto& it : r.result.items) fp::footprintCsvRows(it, r.method, {}, &n);
            return n;
        })
        .def_property_readonly("files", [](const Report& r) {
            std::vector<std::string> f;
            for (const auto& it : r.result.items) f.push_back(it.file);
            return f;
        })
        .def_property_readonly("read_errors", [](const Report& r) {
            std::vector<std::string> e;
            for (const auto& it : r.result.items)
                if (!it.readError.empty()) e.push_back(it.readError);
            return e;
        })
        .def_property_readonly("warnings", [](const Report& r) {
            std::vector<std::string> w;
            for (const auto& it : r.result.items)
                for (const auto& roi : it.rois)
                    for (const auto& s : roi.warnings) w.push_back(it.file + ": " + s);
            return w;
        })
        .def("__repr__", [](const Report& r) {
            size_t rows = 0, errors = 0;
            std::map<std::string, size_t> verdicts;
            for (const auto& it : r.result.items) {
                size_t n = 0;
                fp::footprintCsvRows(it, r.method, {}, &n);
                rows += n;
                errors += !it.readError.empty();
                for (const auto& roi : it.rois) ++verdicts[roi.result.ok ? fp::verdictName(roi.result.verdict) : "failed"];
            }
            std::string s = "<laserwb.footprint.Report: " + std::to_string(rows) + " rows from " +
                            std::to_string(r.result.items.size()) + " frames";
            for (const auto& [v, n] : verdicts) s += ", " + std::to_string(n) + " " + v;
            if (errors) s += ", " + std::to_string(errors) + " not read";
            return s + ">";
        })
        .def("csv_rows", &Report::rows, "The report's data rows as text (what write_csv writes after the header).")
        .def("columns", &reportColumns,
             "{column: numpy array} of the report: the CSV's columns at the core's full precision (float64;\n"
             "empty cells NaN, whole-number columns int64 with -1 empty, text str).")
        .def("write_csv", [](const Report& r, const std::string& path) {
            py::gil_scoped_release nogil;
            writeRecorded(r.prov, path, [&](const std::string& to, std::string* e) {
                return fp::writeFootprintCsv(to, r.result.items, r.method, e);
            });
        }, py::arg("path"), "Writes the report with the CLI's writer (writeFootprintCsv): the same bytes as laserwb-cli footprint -o,\n"
           "its provenance beside it (PATH.provenance.json).");

    m.def("csv_header", [] { return fp::footprintCsvHeader(); }, "The report's header line.");
    m.def("tune", &tuneShots, py::arg("inputs"), py::arg("verdicts"), py::arg("config_out") = py::none(),
          py::arg("params") = py::none(), py::arg("preset") = py::none(), py::arg("method") = py::none(),
          py::arg("centres") = py::none(), py::arg("raw_size") = py::none(), py::arg("max_pixels") = 0,
          py::arg("threads") = 0, py::arg("folds") = 5,
          "The verdict criteria tuned from the analyst's verdicts, as laserwb-cli footprint tune: every shot\n"
          "of inputs (image files, folders, shot lists: a path or a list) fitted once under the starting\n"
          "parameters (params, preset, method as for fit_batch), the thresholds moved one at a time for the\n"
          "fewest disagreements with verdicts (a CSV with file and verdict columns, roi for frames of several\n"
          "ROIs), never letting more not-good shots through than the start; folds: cross-validation (0 none).\n"
          "config_out: the tuned parameters written as a config (the CLI's bytes) with its provenance.\n"
          "Returns the record: shots, labelled, changes, confusion_before/after/held_out, notes, params.");
    m.def("fit_batch", &fitBatch, py::arg("inputs"), py::arg("params") = py::none(), py::arg("preset") = py::none(),
          py::arg("method") = py::none(), py::arg("centres") = py::none(), py::arg("raw_size") = py::none(),
          py::arg("max_pixels") = 0, py::arg("threads") = 0, py::arg("names") = py::none(), py::arg("keep_going") = false,
          "Runs the footprint shots as `laserwb-cli footprint` does, on\n"
          "  inputs: image files and folders (a path or a list), or frames in memory: a 2-D array,\n"
          "          a 3-D array (a stack of frames, viewed without a copy when float32 and\n"
          "          C-contiguous) or a list of 2-D arrays; `names` fills their report's file column\n"
          "          (default '0', '1', ...);\n"
          "  params: None (the defaults), a FootprintParams (as --config) or {key: value} (as --set);\n"
          "  preset: 'wu2021' or 'yao2021' (--preset); method: 'gauss', 'tefm' or 'gcm' (--method);\n"
          "  centres: [(x, y), ...] nominal spot centres (--center), raw_size: (w, h) of raw frames,\n"
          "  threads: worker threads (0: every core). The GIL is released while it runs.\n"
          "A frame that cannot be read or fitted raises laserwb.Error unless keep_going=True (then it\n"
          "is a rejected row). Returns a Report (columns(), write_csv()).");
}

}  // namespace lwb::py
