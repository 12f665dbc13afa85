// The laserwb Python module's entry: exceptions, the shared conversions, and the families'
// submodules (bind_footprint.cpp, bind_slr.cpp, bind_more.cpp). See bind.hpp.
#include <algorithm>
#include <climits>
#include <cmath>

#include "bind.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/output_set.hpp"
#include "core/common/csv.hpp"
#include "core/common/image_header.hpp"
#include "core/common/text.hpp"
#include "lwb_version.hpp"

namespace lwb::py {

using namespace pybind11::literals;

namespace {
std::string shown(const py::handle& v) {
    std::string r = py::repr(v);
    if (r.size() > 60) r = r.substr(0, 57) + "...";
    return std::string(py::str(py::type::handle_of(v).attr("__name__"))) + " " + r;
}
}  // namespace

double numberArgument(const py::object& v, const char* name) {
    const bool number = !py::isinstance<py::bool_>(v) &&
                        (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v) || py::hasattr(v, "__float__")) &&
                        !py::isinstance<py::str>(v);
    if (!number) throw py::type_error(std::string(name) + " must be a number, not " + shown(v));
    double d = 0;
    try {
        d = v.cast<double>();
    } catch (const py::cast_error&) {
        throw py::type_error(std::string(name) + " must be a number, not " + shown(v));
    }
    if (!std::isfinite(d)) throw py::value_error(std::string(name) + " must be finite, not " + core::formatShortest(d));
    return d;
}

std::pair<int, int> sizeArgument(const py::object& v, const char* name) {
    if (!py::isinstance<py::sequence>(v) || py::isinstance<py::str>(v) || py::len(v) != 2)
        throw py::type_error(std::string(name) + " must be (width, height), not " + shown(v));
    const py::sequence s = v.cast<py::sequence>();
    int wh[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
        const py::object e = s[static_cast<size_t>(i)];
        if (!py::isinstance<py::int_>(e) || py::isinstance<py::bool_>(e))
            throw py::type_error(std::string(name) + " must be (width, height) of ints, not " + shown(v));
        const long long n = e.cast<long long>();
        if (n < 1 || n > INT_MAX)
            throw py::value_error(std::string(name) + ": width and height must be in [1, " + std::to_string(INT_MAX) + "], not " +
                                  std::to_string(n));
        wh[i] = static_cast<int>(n);
    }
    return {wh[0], wh[1]};
}

std::vector<std::pair<double, double>> pointsArgument(const py::object& v, const char* name) {
    if (!py::isinstance<py::sequence>(v) || py::isinstance<py::str>(v))
        throw py::type_error(std::string(name) + " must be a list of (x, y), not " + shown(v));
    std::vector<std::pair<double, double>> out;
    for (const py::handle h : v.cast<py::sequence>()) {
        const py::object e = py::reinterpret_borrow<py::object>(h);
        if (!py::isinstance<py::sequence>(e) || py::isinstance<py::str>(e) || py::len(e) != 2)
            throw py::type_error(std::string(name) + " must be a list of (x, y), not one holding " + shown(e));
        const py::sequence s = e.cast<py::sequence>();
        for (const py::handle c : s)
            if (py::isinstance<py::str>(c) || py::isinstance<py::bool_>(c) || !py::hasattr(c, "__float__"))
                throw py::type_error(std::string(name) + " must be a list of (x, y) numbers, not one holding " + shown(e));
        out.emplace_back(numberArgument(s[0], name), numberArgument(s[1], name));
    }
    return out;
}

std::string valueText(const py::handle& v) {
    if (v.is_none()) return "null";
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::int_>(v)) return py::str(v);
    if (py::isinstance<py::float_>(v)) {
        const double d = v.cast<double>();
        return std::isnan(d) ? "null" : core::formatShortest(d);
    }
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::isinstance<py::tuple>(v) || py::isinstance<py::list>(v)) {
        const py::sequence s = v.cast<py::sequence>();
        if (s.size() != 2) throw ParameterError("a range must be (min, max) or None (off), not " + std::string(py::repr(v)));
        return valueText(s[0]) + "," + valueText(s[1]);
    }
    // numpy scalars and anything else with a number inside
    if (py::hasattr(v, "__float__")) return core::formatShortest(v.cast<double>());
    return py::str(v);
}

py::array maskOf(const std::vector<uint8_t>& v, py::handle owner) {
    const bool binary = std::all_of(v.begin(), v.end(), [](uint8_t b) { return b <= 1; });
    if (!binary || v.empty()) {  // (a copy; an empty vector has no data to view)
        py::array_t<bool> a(static_cast<py::ssize_t>(v.size()));
        bool* out = a.mutable_data();
        for (size_t i = 0; i < v.size(); ++i) out[i] = v[i] != 0;
        py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
        return std::move(a);
    }
    py::array a(py::dtype::of<bool>(), {static_cast<py::ssize_t>(v.size())}, {py::ssize_t{1}}, v.data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

void writeRecorded(const core::Provenance& prov, const std::string& path,
                   const std::function<bool(const std::string&, std::string*)>& write) {
    std::string err;
    const bool written = core::writeWithProvenance(prov, path, write, &err);
    check(written, err);
}

std::string fsPath(const py::object& o) { return py::str(py::module_::import("os").attr("fspath")(o)); }

std::string inputPath(const py::object& o, bool folderOk) {
    std::string p = fsPath(o);
    requireReadable(p, folderOk);
    return p;
}

void requireReadable(const std::string& path, bool folderOk) {
    if (path.empty() || path == "-") return;
    const py::module_ os = py::module_::import("os");
    // os.stat and open raise FileNotFoundError, PermissionError, ... with errno and filename.
    const py::object st = os.attr("stat")(path);
    if (folderOk && py::module_::import("stat").attr("S_ISDIR")(st.attr("st_mode")).cast<bool>()) {
        os.attr("listdir")(path);
        return;
    }
    py::module_::import("builtins").attr("open")(path, "rb").attr("close")();  // (a folder: IsADirectoryError)
}

py::array_t<float> ownedArray(cv::Mat image) {
    auto* keep = new cv::Mat(std::move(image));
    py::capsule owner(keep, [](void* p) { delete static_cast<cv::Mat*>(p); });
    return py::array_t<float>({keep->rows, keep->cols},
                              {static_cast<py::ssize_t>(keep->step[0]), static_cast<py::ssize_t>(sizeof(float))},
                              keep->ptr<float>(), owner);
}

py::array ownedImage(cv::Mat image) {
    if (image.empty()) return py::array_t<float>(std::vector<py::ssize_t>{0, 0});
    check(image.channels() == 1, "a multi-channel image cannot be returned as a 2-D array");
    py::dtype dt = image.depth() == CV_8U    ? py::dtype::of<uint8_t>()
                   : image.depth() == CV_16U ? py::dtype::of<uint16_t>()
                   : image.depth() == CV_32F ? py::dtype::of<float>()
                   : image.depth() == CV_64F ? py::dtype::of<double>()
                                             : py::dtype();
    check(image.depth() == CV_8U || image.depth() == CV_16U || image.depth() == CV_32F || image.depth() == CV_64F,
          "an image of an unsupported depth");
    auto* keep = new cv::Mat(std::move(image));
    py::capsule owner(keep, [](void* p) { delete static_cast<cv::Mat*>(p); });
    return py::array(dt, {keep->rows, keep->cols},
                     {static_cast<py::ssize_t>(keep->step[0]), static_cast<py::ssize_t>(keep->elemSize())}, keep->data, owner);
}

py::array resultImage(const cv::Mat& image) {
    py::array a = ownedImage(image);  // (a second header on the same pixels: cv::Mat counts the owners)
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

cv::Mat imageArgument(const py::object& image, const std::string& what, long long maxPixels, py::list* keep,
                      const std::function<bool(const std::string&, cv::Mat*, std::string*, long long)>& read) {
    if (!py::isinstance<py::array>(image)) {
        const std::string path = inputPath(image);
        cv::Mat m;
        std::string err;
        check(read(path, &m, &err, maxPixels), err);
        return m;
    }
    py::array a = py::reinterpret_borrow<py::array>(image);
    if (a.ndim() != 2) throw py::value_error(what + ": a 2-D array (rows, columns), not " + std::to_string(a.ndim()) + "-D");
    // The limit of an image read from a file applies to an array too (checked before any copy).
    const long long limit = maxPixels > 0 ? maxPixels : core::kMaxImagePixels;
    const long long rows = static_cast<long long>(a.shape(0)), cols = static_cast<long long>(a.shape(1));
    if (rows > INT_MAX || cols > INT_MAX || (rows > 0 && cols > limit / rows))
        throw ParameterError(what + ": " + std::to_string(cols) + " x " + std::to_string(rows) +
                             " pixels is more than the limit of " + std::to_string(limit) + " pixels (max_pixels=)");
    a = py::module_::import("numpy").attr("ascontiguousarray")(image);
    const char kind = a.dtype().kind();
    const size_t size = static_cast<size_t>(a.dtype().itemsize());
    const int type = kind == 'u' && size == 1   ? CV_8UC1
                     : kind == 'u' && size == 2 ? CV_16UC1
                     : kind == 'f' && size == 4 ? CV_32FC1
                     : kind == 'f' && size == 8 ? CV_64FC1
                                                : -1;
    if (type < 0) throw py::value_error(what + ": uint8, uint16, float32 or float64 pixels, not " + std::string(py::str(a.dtype())));
    keep->append(a);  // (the Mat views the array's pixels: no copy)
    return cv::Mat(static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)), type, const_cast<void*>(a.data()),
                   static_cast<size_t>(a.strides(0)));
}

py::dict csvColumns(const std::string& csv, const std::vector<std::string>& textColumns,
                    const std::vector<std::string>& intColumns) {
    const core::CsvReadResult r = core::parseCsv(csv, "report");
    check(r.ok, r.error);
    py::dict out;
    const auto& t = r.table;
    const size_t n = t.rows.size();
    for (size_t c = 0; c < t.header.size(); ++c) {
        const std::string& name = t.header[c];
        const bool text = std::find(textColumns.begin(), textColumns.end(), name) != textColumns.end();
        const bool whole = std::find(intColumns.begin(), intColumns.end(), name) != intColumns.end();
        if (text) {
            py::list cells;
            for (const auto& row : t.rows) cells.append(row[c]);
            out[py::str(name)] = py::module_::import("numpy").attr("array")(cells, "dtype"_a = "U");
        } else if (whole) {
            py::array_t<long long> a(static_cast<py::ssize_t>(n));
            auto w = a.mutable_unchecked<1>();
            for (size_t i = 0; i < n; ++i) {
                double d = 0;
                w(static_cast<py::ssize_t>(i)) = core::parseDouble(t.rows[i][c], &d) ? static_cast<long long>(d) : -1;
            }
            out[py::str(name)] = a;
        } else {
            py::array_t<double> a(static_cast<py::ssize_t>(n));
            auto w = a.mutable_unchecked<1>();
            for (size_t i = 0; i < n; ++i) {
                double d = NAN;
                if (!core::parseDouble(t.rows[i][c], &d)) d = NAN;
                w(static_cast<py::ssize_t>(i)) = d;
            }
            out[py::str(name)] = a;
        }
    }
    return out;
}

}  // namespace lwb::py

using namespace pybind11::literals;

PYBIND11_MODULE(_laserwb, m) {
    namespace py = pybind11;
    m.doc() = "Laser Workbench core (C++), bound with pybind11: the tasks of laserwb-cli and the workbench.";
    m.attr("__version__") = LWB_VERSION;

    // laserwb.Error, and laserwb.ParameterError(Error, ValueError) for refused parameters.
    static PyObject* error = PyErr_NewException("laserwb.Error", PyExc_Exception, nullptr);
    static PyObject* paramError = [] {
        PyObject* bases = PyTuple_Pack(2, error, PyExc_ValueError);
        PyObject* e = PyErr_NewException("laserwb.ParameterError", bases, nullptr);
        Py_DECREF(bases);
        return e;
    }();
    m.add_object("Error", py::handle(error));
    m.add_object("ParameterError", py::handle(paramError));
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const lwb::py::ParameterError& e) {
            PyErr_SetString(paramError, e.what());
        } catch (const lwb::py::Error& e) {
            PyErr_SetString(error, e.what());
        }
    });

    m.def("write_text", [](const std::string& path, const std::string& text) {
        std::string err;
        py::gil_scoped_release nogil;
        lwb::py::check(lwb::core::writeFileAtomic(path, text, &err), err);
    }, py::arg("path"), py::arg("text"),
       "Writes text to path atomically (a temporary beside it, renamed into place), as every writer of the core does.");

    lwb::py::bindFootprint(m);
    lwb::py::bindSlr(m);
    lwb::py::bindTrendCalibRadiometry(m);
}
