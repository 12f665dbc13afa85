#pragma once
// The laserwb Python module (pybind11): what the binding files share. The module binds the core's
// tasks, readers and writers (core/common/task.hpp, docs/architecture.md "Tasks"); it computes
// nothing of its own. Failures of the core (its Result's `error`) become Python exceptions with
// the core's message: laserwb.ParameterError (also a ValueError) for a parameter the schema
// refuses, laserwb.Error for everything else (a bad file: "FILE:LINE: ...").
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/common/provenance.hpp"
#include "core/common/schema.hpp"

namespace lwb::py {

namespace py = pybind11;

/// A parameter the schema (or a family's rule) refuses: laserwb.ParameterError.
struct ParameterError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// Any other failure of the core (unreadable input, a failed run, an output not written): laserwb.Error.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Throws Error(message) when !ok.
inline void check(bool ok, const std::string& message) {
    if (!ok) throw Error(message);
}

/// A number argument `name` (a Python int or float, or a numpy scalar; bool refused): TypeError
/// naming it for anything else ("k must be a number, not str 'x'"; pybind11's own words were
/// "Unable to cast Python instance"), ValueError when it is not finite.
double numberArgument(const py::object& v, const char* name);
/// An argument (width, height) of two ints > 0: TypeError / ValueError naming it.
std::pair<int, int> sizeArgument(const py::object& v, const char* name);
/// A list of (x, y) number pairs: TypeError naming it.
std::vector<std::pair<double, double>> pointsArgument(const py::object& v, const char* name);

/// A Python value as the text `--set KEY=VALUE` takes: True/False, None ("null": a special, or a
/// range switched off), a number (its shortest round-trip repr), (lo, hi) for a range, a string.
std::string valueText(const py::handle& v);
/// A schema field's value of p as a Python object (a Choice as its name, a Range as (lo, hi) or None).
template <class P>
py::object fieldValue(const core::Schema<P>& s, const typename core::Schema<P>::Field& f, const P& p);

/// Binds P as a Python class NAME: p[key], p[key] = value (--set's rules and messages),
/// keys(), to_dict(), to_json(), update(dict), load(path) (a --config file), validate(),
/// describe(key); the class docstring is the schema's table (every key, unit, range, default
/// and doc). `defaults`: what P() gives (the CLI command's defaults); `familyCheck`: the
/// family's validate() (rules between fields); `fromJson`: how a config file is read.
template <class P>
struct ParamsBinding {
    const char* name;
    const char* summary;
    const core::Schema<P>& (*schema)();
    P (*defaults)();
    std::string (*familyCheck)(const P&);
    bool (*fromJson)(const core::JsonParseResult&, P*, std::string*) = nullptr;
    void (*afterSet)(P*, const std::string& key) = nullptr;
};
template <class P>
py::class_<P> bindParams(py::module_& m, const ParamsBinding<P>& b);

/// `params` as the family's P: None (defaults), a P, or a dict {key: value} over the defaults.
template <class P>
P paramsFrom(const py::object& params, const ParamsBinding<P>& b);

/// Applies a dict {key: value} over *p, as --set does, one key at a time: ParameterError with the
/// schema's message ("slr.screen.cosine_c = 1.2: must be in [0.5, 1)").
template <class P>
void applyDict(const core::Schema<P>& s, const py::dict& d, P* p, void (*afterSet)(P*, const std::string&) = nullptr);

/// `params` as a task's sources take them (core/*/..._run.hpp): a P becomes the config (its
/// JSON), a dict {key: value} the settings in order (as --set); None leaves both empty. The core
/// then resolves them in its one order. `typeName` names P in the TypeError.
template <class P>
void gatherParams(const py::object& params, const core::Schema<P>& schema, const char* typeName, core::Json* config,
                  std::vector<core::ParamSetting>* set) {
    if (py::isinstance<P>(params)) {
        *config = schema.toJson(params.cast<P>());
    } else if (py::isinstance<py::dict>(params)) {
        for (const auto& kv : params.cast<py::dict>()) {
            const std::string key = py::str(kv.first);
            set->push_back({key, valueText(kv.second), key});
        }
    } else if (!params.is_none()) {
        throw py::type_error(std::string("params must be None, a dict {key: value} or ") + typeName);
    }
}

/// A read-only numpy view of `v`'s data kept alive by `owner` (no copy). Read-only: a result
/// is what the run gave (a writable view let `r.kept[:] = 254` reach the files r.write made).
template <class T>
py::array_t<T> viewOf(const std::vector<T>& v, py::handle owner) {
    py::array_t<T> a({static_cast<py::ssize_t>(v.size())}, {static_cast<py::ssize_t>(sizeof(T))}, v.data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

/// A read-only numpy bool array of a 0/1 mask (a view of `v`'s bytes kept alive by `owner`;
/// a copy, value != 0, if any byte is not 0 or 1): `x[mask]` selects, where a uint8 array of
/// 0 and 1 took x[0] and x[1] over and over (fancy indexing).
py::array maskOf(const std::vector<uint8_t>& v, py::handle owner);

/// What a result records of its run for the provenance of the files written from it: the
/// command it stands for, its parameters (the schema's JSON) and the files it read.
struct Recorded {
    core::Provenance prov;
    void record(const std::string& command, core::Json parameters, std::vector<std::string> inputs) {
        prov.command = command;
        prov.parameters = std::move(parameters);
        prov.inputs = std::move(inputs);
    }
};

/// Writes `path` with `write(stagingPath, &error)` and, beside it, its provenance
/// (PATH.provenance.json: the run's command, parameters and inputs, the file's SHA-256), all or
/// nothing (core writeWithProvenance) as the CLI writes its outputs; standard output gets no sidecar.
void writeRecorded(const core::Provenance& prov, const std::string& path,
                   const std::function<bool(const std::string&, std::string*)>& write);

/// A path argument (str or os.PathLike) as os.fspath gives it.
std::string fsPath(const py::object& o);
/// The same for a file the call reads: requireReadable first (Python's OSError when it cannot be opened).
std::string inputPath(const py::object& o, bool folderOk = false);

/// Raises Python's own OSError subclass (FileNotFoundError, PermissionError, IsADirectoryError,
/// ...) with its errno and the file's name when `path` cannot be opened for reading (a folder
/// when `folderOk`); does nothing for "" and "-". The core's messages say the same in words; a
/// Python caller catches the class.
void requireReadable(const std::string& path, bool folderOk = false);

/// A float32 numpy array that owns `image` (CV_32FC1; no copy of its pixels).
py::array_t<float> ownedArray(cv::Mat image);

/// A numpy array that owns `image` (single channel, 8U, 16U, 32F or 64F; no copy of its pixels).
py::array ownedImage(cv::Mat image);

/// A result's image as a read-only numpy array sharing its pixels (no copy; read-only, as the
/// result's writers write the same pixels afterwards). np.array(...) gives a writable copy.
py::array resultImage(const cv::Mat& image);

/// An image argument: a path (read by `read`, as the CLI reads it, refused above maxPixels) or a
/// 2-D numpy array of uint8, uint16, float32 or float64 pixels, viewed without a copy (the array
/// is appended to *keep, which the caller holds while the Mat is used). Errors raise, naming `what`.
cv::Mat imageArgument(const py::object& image, const std::string& what, long long maxPixels, py::list* keep,
                      const std::function<bool(const std::string&, cv::Mat*, std::string*, long long)>& read);

/// The rows of a CSV text (header first) as {column: numpy array}: numbers as float64 (empty
/// cells NaN), columns in `textColumns` as arrays of str, `intColumns` as int64.
py::dict csvColumns(const std::string& csv, const std::vector<std::string>& textColumns,
                    const std::vector<std::string>& intColumns);

void bindFootprint(py::module_& m);
void bindSlr(py::module_& m);
void bindTrendCalibRadiometry(py::module_& m);

}  // namespace lwb::py

#include "bind_params.inl"
