// laserwb.trend, laserwb.calib, laserwb.radiometry: the centroid trend (computeTrend,
// writeTrendCsv), the calibration task (CalibTask: detector fit, waveform and feature match,
// pointing, statistics) with its writers, and the radiometric steps (mosaicRow, the GCP map,
// measureRegionDn + fitReflectance, applyReflectance, relativeErrors) with theirs, as the CLI's
// `trend`, `calib detector|waveform|pointing|stats` and `radiometry mosaic|gcp|fit|apply|check`
// commands run them.
#include <functional>

#include "bind.hpp"
#include "core/calib/calib_csv.hpp"
#include "core/common/output_set.hpp"
#include "core/common/provenance.hpp"
#include "core/calib/calib_params.hpp"
#include "core/calib/calib_run.hpp"
#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/calib/waveform.hpp"
#include "core/footprint/trend.hpp"
#include "core/radiometry/gcp.hpp"
#include "core/radiometry/geotiff.hpp"
#include "core/radiometry/mosaic.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "core/radiometry/reflectance.hpp"

namespace lwb::py {

using namespace pybind11::literals;
namespace fp = core::footprint;
namespace cal = core::calib;
namespace rad = core::radiometry;

namespace {

template <class P>
P plain() {
    return {};
}
std::string trendCheck(const fp::TrendParams& p) { return fp::validate(p); }
std::string calibCheck(const cal::CalibParams& p) { return cal::validate(p); }
std::string radiometryCheck(const rad::RadiometryParams& p) { return rad::validate(p); }
const ParamsBinding<fp::TrendParams> kTrend{"TrendParams", "Parameters of the centroid trend (laserwb-cli trend).",
                                            fp::trendSchema, plain<fp::TrendParams>, trendCheck};
const ParamsBinding<cal::CalibParams> kCalib{"CalibParams",
                                             "Parameters of the altimeter calibration (laserwb-cli calib detector|waveform|pointing|stats).",
                                             cal::calibSchema, plain<cal::CalibParams>, calibCheck};
const ParamsBinding<rad::RadiometryParams> kRadiometry{
    "RadiometryParams", "Parameters of the radiometric calibration (laserwb-cli radiometry mosaic|gcp|fit|apply|check).",
    rad::radiometrySchema, plain<rad::RadiometryParams>, radiometryCheck};

// The path of an argument that may be a file's path or an array ("" for an array or None).
std::string pathOf(const py::object& o) {
    return !o.is_none() && (py::isinstance<py::str>(o) || py::hasattr(o, "__fspath__")) ? fsPath(o) : std::string();
}
std::vector<std::string> pathsOf(const py::list& items) {
    std::vector<std::string> out;
    for (const auto& o : items) out.push_back(pathOf(py::reinterpret_borrow<py::object>(o)));
    return out;
}

// A method that writes the object with a core writer (path, object, &error): the path as
// os.fspath gives it, the GIL released while it writes, a failure raised with the core's message,
// the file's provenance beside it.
template <class T, class W>
auto writer(W write) {
    return [write](const T& obj, const py::object& path) {
        const std::string p = fsPath(path);
        py::gil_scoped_release nogil;
        writeRecorded(obj.prov, p, [&](const std::string& to, std::string* e) { return write(to, obj, e); });
    };
}

// The same for a map image: the method takes plain_tiff too (a plain TIFF even with a georeference).
template <class T, class W>
auto mapWriter(W write) {
    return [write](const T& obj, const py::object& path, bool plain) {
        const std::string p = fsPath(path);
        py::gil_scoped_release nogil;
        writeRecorded(obj.prov, p, [&](const std::string& to, std::string* e) { return write(to, obj, plain, e); });
    };
}

struct Trend : Recorded {
    fp::TrendResult r;
};
struct Detector : Recorded {
    cal::DetectorArray array;
    cal::CalibRunResult run;
};
struct Pointing : Recorded {
    cal::CalibRunResult run;
};
struct Stats : Recorded {
    cal::CalibRunResult run;
};
struct RadiometryFit : Recorded {
    std::vector<rad::Region> regions;
    rad::ReflectanceFitResult r;
};
struct WaveformFit : Recorded {
    cal::CalibInputData in;
    cal::CalibRunResult run;
};
struct Mosaic : Recorded {
    rad::MosaicResult r;
};
struct GcpMap : Recorded {
    std::vector<rad::Gcp> gcps;
    rad::GcpFitResult fit;
    rad::MapGrid grid;
    rad::WarpResult warp;
    rad::GeoReference geo;
};
struct Applied : Recorded {
    rad::ApplyResult r;
    rad::GeoReference geo;
};
struct CheckTable : Recorded {
    rad::RelativeErrorResult r;
};

// The image readers of the radiometry commands (any depth kept), for imageArgument.
bool readAnyDepth(const std::string& path, cv::Mat* m, std::string* err, long long maxPixels) {
    return rad::readImageAnyDepth(path, m, err, maxPixels > 0 ? maxPixels : core::kMaxImagePixels);
}

py::dict relativeErrorDict(const rad::RelativeErrorResult& r) {
    py::list rows;
    for (const auto& row : r.rows)
        rows.append(py::dict("name"_a = row.name, "measured_pct"_a = row.measured, "image_pct"_a = row.simulated,
                             "relative_error_pct"_a = row.relativeErrorPct, "within_limit"_a = row.withinLimit));
    return py::dict("rows"_a = rows, "max_pct"_a = r.maxPct, "mean_pct"_a = r.meanPct, "all_within_limit"_a = r.allWithinLimit);
}

// A numpy image as the single-channel float32 Mat the radiometry steps read (viewed when float32
// and C-contiguous).
using Image = py::array_t<float, py::array::c_style | py::array::forcecast>;

// laserwb.trend: the monthly table (Trend) and compute().
void bindTrend(py::module_& top) {
    // ---- trend -------------------------------------------------------------------------------
    py::module_ t = top.def_submodule("trend", "Monthly spot-centroid means and pointing change (paper 001).");
    bindParams(t, kTrend);
    py::class_<Trend>(t, "Trend", "The monthly table of laserwb-cli trend.")
        .def_property_readonly("warnings", [](const Trend& x) { return x.r.warnings; })
        .def("__len__", [](const Trend& x) { return x.r.rows.size(); })
        .def("columns", [](const Trend& x) {
            const auto& rows = x.r.rows;
            auto col = [&](auto get) {
                py::array_t<double> a(static_cast<py::ssize_t>(rows.size()));
                auto w = a.mutable_unchecked<1>();
                for (size_t i = 0; i < rows.size(); ++i) w(static_cast<py::ssize_t>(i)) = get(rows[i]);
                return a;
            };
            auto text = [&](auto get) {
                py::list l;
                for (const auto& r : rows) l.append(get(r));
                return py::module_::import("numpy").attr("array")(l, "dtype"_a = "U");
            };
            return py::dict("camera"_a = text([](const auto& r) { return r.camera; }),
                            "beam"_a = text([](const auto& r) { return r.beam; }),
                            "month"_a = text([](const auto& r) { return r.month; }),
                            "n"_a = col([](const auto& r) { return double(r.n); }),
                            "rejected"_a = col([](const auto& r) { return double(r.rejected); }),
                            "x_mean"_a = col([](const auto& r) { return r.xMean; }), "y_mean"_a = col([](const auto& r) { return r.yMean; }),
                            "x_std"_a = col([](const auto& r) { return r.xStd; }), "y_std"_a = col([](const auto& r) { return r.yStd; }),
                            "dx_px"_a = col([](const auto& r) { return r.dx; }), "dy_px"_a = col([](const auto& r) { return r.dy; }),
                            "planar_change_px"_a = col([](const auto& r) { return r.planarPx; }),
                            "pointing_change_arcsec"_a = col([](const auto& r) { return r.pointingArcsec; }),
                            "beam_distance_px"_a = col([](const auto& r) { return r.beamDistancePx; }),
                            "distance_change_px"_a = col([](const auto& r) { return r.distanceChangePx; }));
        }, "{column: numpy array} of the monthly table (full precision)")
        .def("write_csv",
             writer<Trend>([](const std::string& p, const Trend& x, std::string* e) {
                 return fp::writeTrendCsv(p, x.r.rows, e);
             }),
             py::arg("path"), "Writes the table with the CLI's writer (writeTrendCsv).");
    t.def("compute", [](const py::object& path, const py::object& params) {
        const fp::TrendParams p = paramsFrom(params, kTrend);
        const std::string file = inputPath(path);
        Trend x;
        std::vector<fp::CentroidRecord> recs;
        std::string err;
        {
            py::gil_scoped_release nogil;
            check(fp::readCentroidCsv(file, &recs, &err), err);
            x.r = fp::computeTrend(recs, p);
        }
        check(x.r.ok, x.r.error);
        x.record("trend", fp::trendSchema().toJson(p), {file});
        return x;
    }, py::arg("path"), py::arg("params") = py::none(),
       "Reads a centroid table (time,beam,x,y[,camera]) and computes the monthly trend, as laserwb-cli trend.");
}

// laserwb.calib's detector step: DetectorFit and detector().
void bindCalibDetector(py::module_& c) {
    py::class_<Detector>(c, "DetectorFit", "The footprint centre from a ground detector array (CalibTask's detector step).")
        .def_property_readonly("centre", [](const Detector& d) {
            const auto& r = d.run.detector;
            return py::dict("e_m"_a = r.centreE, "n_m"_a = r.centreN, "lat_deg"_a = r.centreLatDeg, "lon_deg"_a = r.centreLonDeg,
                            "semi_major_m"_a = r.centreEllipse.semiMajor, "semi_minor_m"_a = r.centreEllipse.semiMinor,
                            "used"_a = r.used, "censored"_a = r.censored, "outliers"_a = r.outliers);
        })
        .def_property_readonly("doubts", [](const Detector& d) { return d.run.detector.doubts; })
        .def_property_readonly("warnings", [](const Detector& d) { return d.run.detector.warnings; })
        .def("write_centre",
             writer<Detector>([](const std::string& p, const Detector& d, std::string* e) {
                 return cal::writeDetectorCentreCsv(p, d.run.detector, e);
             }),
             py::arg("path"), "As laserwb-cli calib detector -o.")
        .def("write_report",
             writer<Detector>([](const std::string& p, const Detector& d, std::string* e) {
                 return cal::writeDetectorReportCsv(p, d.array, d.run.detector, e);
             }),
             py::arg("path"), "As laserwb-cli calib detector --detectors.");
    c.def("detector", [](const py::object& path, const py::object& params) {
        const cal::CalibParams p = paramsFrom(params, kCalib);
        const std::string file = inputPath(path);
        Detector d;
        {
            py::gil_scoped_release nogil;
            cal::CalibSources src;
            src.detectors = file;
            cal::CalibInputData in;
            std::string err;
            check(cal::loadCalibInputs(src, &in, &err), err);
            d.array = in.array;
            d.run = core::runTask<cal::CalibTask>(in, p);
        }
        check(d.run.detector.ok, file + ": " + d.run.detector.error);
        d.record("calib detector", cal::calibSchema().toJson(p), {file});
        return d;
    }, py::arg("path"), py::arg("params") = py::none(), "Fits the footprint centre of a detector CSV (CalibTask), as laserwb-cli calib detector.");
}

// laserwb.calib's pointing step: PointingFit and pointing().
void bindCalibPointing(py::module_& c) {
    py::class_<Pointing>(c, "PointingFit", "Pointing corrections and range biases from control points (CalibTask's pointing step).")
        .def_property_readonly("beams", [](const Pointing& x) {
            py::list out;
            for (const auto& b : x.run.pointing.beams)
                out.append(py::dict("id"_a = b.id, "solved"_a = b.solved, "d_alpha_rad"_a = b.dAlphaRad,
                                    "d_alpha_sd_rad"_a = b.dAlphaSdRad, "d_beta_rad"_a = b.dBetaRad, "d_beta_sd_rad"_a = b.dBetaSdRad,
                                    "d_rho_m"_a = b.dRhoM, "d_rho_sd_m"_a = b.dRhoSdM));
            return out;
        })
        .def_property_readonly("warnings", [](const Pointing& x) { return x.run.pointing.warnings; })
        .def("write_beams",
             writer<Pointing>([](const std::string& p, const Pointing& x, std::string* e) {
                 return cal::writeTextOutput(p, cal::pointingBeamsCsv(x.run.pointing), e);
             }),
             py::arg("path"), "As laserwb-cli calib pointing -o.")
        .def("write_params",
             writer<Pointing>([](const std::string& p, const Pointing& x, std::string* e) {
                 return cal::writeTextOutput(p, cal::pointingParamsCsv(x.run.pointing), e);
             }),
             py::arg("path"), "As --params.")
        .def("write_residuals",
             writer<Pointing>([](const std::string& p, const Pointing& x, std::string* e) {
                 return cal::writeTextOutput(p, cal::pointingResidualsCsv(x.run.pointing), e);
             }),
             py::arg("path"), "As --residuals.")
        .def("write_iterations",
             writer<Pointing>([](const std::string& p, const Pointing& x, std::string* e) {
                 return cal::writeTextOutput(p, cal::pointingIterationsCsv(x.run.pointing), e);
             }),
             py::arg("path"), "As --iterations.");
    c.def("pointing", [](const py::object& points, const py::object& beams, const py::object& params) {
        const cal::CalibParams p = paramsFrom(params, kCalib);
        const std::string file = inputPath(points), beamFile = inputPath(beams);
        Pointing x;
        {
            py::gil_scoped_release nogil;
            cal::CalibSources src;
            src.controlPoints = file;
            src.beams = beamFile;
            cal::CalibInputData in;
            std::string err;
            check(cal::loadCalibInputs(src, &in, &err), err);
            x.run = core::runTask<cal::CalibTask>(in, p);
        }
        check(x.run.pointing.ok, file + ": " + x.run.pointing.error);
        x.record("calib pointing", cal::calibSchema().toJson(p), {file, beamFile});
        return x;
    }, py::arg("points"), py::arg("beams"), py::arg("params") = py::none(),
       "Pointing calibration from a control-point CSV and the beam designs (JSON), as laserwb-cli calib pointing.");
}

// laserwb.calib's statistics: Stats and stats().
void bindCalibStats(py::module_& c) {
    py::class_<Stats>(c, "Stats", "Validation statistics of elevation differences (CalibTask's statistics).")
        .def("groups", [](const Stats& s) {
            py::dict out;
            for (const auto& g : s.run.stats) {
                check(g.stats.ok, g.stats.error);
                py::dict d;
                for (const auto& lv : cal::labelledStats(g.stats.stats)) d[py::str(lv.key)] = lv.value;
                out[py::str(g.name)] = d;
            }
            return out;
        }, "{group name: {statistic: value}}")
        .def("write_csv",
             writer<Stats>([](const std::string& p, const Stats& s, std::string* e) {
                 return cal::writeTextOutput(p, cal::statsCsv(cal::statsRows(s.run.stats)), e);
             }),
             py::arg("path"), "As laserwb-cli calib stats -o.");
    c.def("stats", [](const py::object& path, const std::string& group, const py::object& params) {
        const cal::CalibParams p = paramsFrom(params, kCalib);
        const std::string file = inputPath(path);
        Stats s;
        {
            py::gil_scoped_release nogil;
            cal::CalibSources src;
            src.differences = file;
            src.groupColumn = group;
            cal::CalibInputData in;
            std::string err;
            check(cal::loadCalibInputs(src, &in, &err), err);
            s.run = core::runTask<cal::CalibTask>(in, p);
        }
        for (const auto& g : s.run.stats) check(g.stats.ok, file + ": " + g.stats.error);
        s.record("calib stats", cal::calibSchema().toJson(p), {file});
        return s;
    }, py::arg("path"), py::arg("group") = "", py::arg("params") = py::none(),
       "Statistics of a CSV of elevation differences (per `group` column value), as laserwb-cli calib stats.");
}

// laserwb.calib's waveform step: WaveformFit and waveform().
void bindCalibWaveform(py::module_& c) {
    py::class_<WaveformFit>(c, "WaveformFit", "The feature height from a double-peak waveform and the feature it matches (CalibTask).")
        .def_property_readonly("waveform", [](const WaveformFit& x) -> py::object {
            if (!x.run.hasWaveform) return py::none();
            const auto& w = x.run.waveform;
            return py::dict("first_ns"_a = w.first.centreNs, "second_ns"_a = w.second.centreNs, "delta_t_ns"_a = w.deltaTNs,
                            "delta_t_sd_ns"_a = w.deltaTSdNs, "height_m"_a = w.heightM, "height_sd_m"_a = w.heightSdM,
                            "rms_residual"_a = w.rmsResidual, "iterations"_a = w.iterations);
        }, "The two returns and the height (None when a height was given).")
        .def_property_readonly("match", [](const WaveformFit& x) -> py::object {
            if (!x.run.hasMatch) return py::none();
            const auto& m = x.run.match;
            return py::dict("found"_a = m.found, "best"_a = x.in.features[m.best].id, "best_delta_h_m"_a = m.bestDeltaHM);
        }, "The candidate with the smallest height difference, and whether it is within thred_h (None without features).")
        .def_property_readonly("warnings", [](const WaveformFit& x) {
            std::vector<std::string> w = x.run.waveform.warnings;
            w.insert(w.end(), x.run.match.warnings.begin(), x.run.match.warnings.end());
            return w;
        })
        .def("write_ranking",
             writer<WaveformFit>([](const std::string& p, const WaveformFit& x, std::string* e) {
                 if (!x.run.hasMatch) {
                     *e = "no candidate features were given: no ranking";
                     return false;
                 }
                 return cal::writeTextOutput(p, cal::rankingCsv(x.in.features, x.run.match), e);
             }),
             py::arg("path"), "As laserwb-cli calib waveform -o.")
        .def("write_model",
             writer<WaveformFit>([](const std::string& p, const WaveformFit& x, std::string* e) {
                 if (!x.run.hasWaveform) {
                     *e = "a height was given, not a waveform: no model";
                     return false;
                 }
                 return cal::writeTextOutput(p, cal::waveformModelCsv(x.run.waveformRun, x.run.waveform), e);
             }),
             py::arg("path"), "As --model.");
    c.def("waveform", [](const py::object& path, const py::object& features, const py::object& height, const py::object& params) {
        const cal::CalibParams p = paramsFrom(params, kCalib);
        if (path.is_none() == height.is_none()) throw py::value_error("give a waveform file or height= (not both)");
        if (!height.is_none() && features.is_none()) throw py::value_error("height= needs features= to match against");
        const std::string file = path.is_none() ? std::string() : inputPath(path);
        const std::string featureFile = features.is_none() ? std::string() : inputPath(features);
        WaveformFit x;
        cal::CalibSources src;
        src.givenHeightM = height.is_none() ? NAN : numberArgument(height, "height");
        src.waveform = file;
        src.features = featureFile;
        {
            py::gil_scoped_release nogil;
            std::string err;
            check(cal::loadCalibInputs(src, &x.in, &err), err);
            x.run = core::runTask<cal::CalibTask>(x.in, p);
        }
        if (x.run.hasWaveform) check(x.run.waveform.ok, file + ": " + x.run.waveform.error);
        if (!featureFile.empty()) {
            check(x.run.hasMatch, featureFile + ": no candidate features");
            check(x.run.match.ok, x.run.match.error);
        }
        x.record("calib waveform", cal::calibSchema().toJson(p), {file, featureFile});
        return x;
    }, py::arg("path") = py::none(), py::arg("features") = py::none(), py::arg("height") = py::none(), py::arg("params") = py::none(),
       "The feature height from a waveform CSV (or a given height=) and its match among the candidate\n"
       "features (CSV), as laserwb-cli calib waveform. match['found'] False is the CLI's exit 3.");
}

// laserwb.calib: its parameters, then the detector, pointing, statistics and waveform steps.
void bindCalib(py::module_& top) {
    // ---- calibration -------------------------------------------------------------------------
    py::module_ c = top.def_submodule("calib", "Laser altimeter calibration (paper 002): detector arrays, waveforms, pointing, statistics.");
    bindParams(c, kCalib);
    bindCalibDetector(c);
    bindCalibPointing(c);
    bindCalibStats(c);
    bindCalibWaveform(c);
}

// laserwb.radiometry's fit: ReflectanceFit, read_image() and fit().
void bindRadiometryFit(py::module_& r) {
    py::class_<RadiometryFit>(r, "ReflectanceFit", "V_REF = K V_DN + B over the fit regions (fitReflectance).")
        .def_property_readonly("fit", [](const RadiometryFit& f) {
            const auto& x = f.r.fit;
            return py::dict("k"_a = x.k, "b"_a = x.b, "k_sd"_a = x.kSd, "b_sd"_a = x.bSd, "n"_a = x.n, "r2"_a = x.r2,
                            "residual_sd"_a = x.residualSd, "uncertainty_pct"_a = x.paperUncertaintyPct,
                            "uncertainty_at_mean_pct"_a = x.uncertaintyAtMeanPct);
        })
        .def_property_readonly("warnings", [](const RadiometryFit& f) { return f.r.warnings; })
        .def("write_csv",
             writer<RadiometryFit>([](const std::string& p, const RadiometryFit& f, std::string* e) {
                 return rad::writeFitCsv(p, f.r.fit, e);
             }),
             py::arg("path"), "As laserwb-cli radiometry fit -o.")
        .def("write_regions",
             writer<RadiometryFit>([](const std::string& p, const RadiometryFit& f, std::string* e) {
                 return rad::writeRegionFitCsv(p, f.regions, f.r, e);
             }),
             py::arg("path"), "As laserwb-cli radiometry fit --regions.");
    r.def("read_image", [](const py::object& path, long long maxPixels) {
        const std::string file = inputPath(path);
        cv::Mat img;
        std::string err;
        {
            py::gil_scoped_release nogil;
            check(rad::readImageAnyDepth(file, &img, &err, maxPixels > 0 ? maxPixels : core::kMaxImagePixels), err);
            if (img.type() != CV_32FC1) img.convertTo(img, CV_32F);
        }
        return ownedArray(std::move(img));
    }, py::arg("path"), py::arg("max_pixels") = 0, "An image as the radiometry commands read it, as float32.");
    r.def("fit", [](const py::object& regions, const py::object& image, const py::object& params) {
        const rad::RadiometryParams p = paramsFrom(params, kRadiometry);
        const std::string file = inputPath(regions);
        RadiometryFit f;
        std::string err;
        check(rad::readRegionCsv(file, &f.regions, &err), err);
        cv::Mat img;
        py::object keep;
        if (!image.is_none()) {
            if (py::isinstance<py::array>(image)) {
                Image a = Image::ensure(image);
                if (!a || a.ndim() != 2) throw py::value_error("image must be a 2-D array");
                keep = a;
                img = cv::Mat(static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)), CV_32FC1, const_cast<float*>(a.data()));
            } else {
                check(rad::readImageAnyDepth(inputPath(image), &img, &err, core::kMaxImagePixels), err);
            }
        }
        {
            py::gil_scoped_release nogil;
            // (the message after the call: the arguments of check() are evaluated in no set order)
            if (!img.empty() && !rad::measureRegionDn(img, p.fit, &f.regions, &err)) check(false, file + ": " + err);
            f.r = rad::fitReflectance(f.regions, p.fit);
        }
        check(f.r.ok, file + ": " + f.r.error);
        f.record("radiometry fit", rad::radiometrySchema().toJson(p), {file, pathOf(image)});
        return f;
    }, py::arg("regions"), py::arg("image") = py::none(), py::arg("params") = py::none(),
       "Fits DN to reflectance from a region CSV, measuring the regions' DN on `image` (a path, or a\n"
       "2-D array) when given, as laserwb-cli radiometry fit.");
}

// laserwb.radiometry's mosaic: Mosaic and mosaic().
void bindRadiometryMosaic(py::module_& r) {
    py::class_<Mosaic>(r, "Mosaic", "One row of frames stitched (mosaicRow).")
        .def_property_readonly("image", [](const Mosaic& m) { return resultImage(m.r.image); }, "The row (the frames' depth).")
        .def_property_readonly("coverage", [](const Mosaic& m) { return resultImage(m.r.coverage); }, "255 where a frame contributed.")
        .def_property_readonly("pairs", [](const Mosaic& m) {
            py::list out;
            for (const auto& pr : m.r.pairs)
                out.append(py::dict("from"_a = pr.from + 1, "to"_a = pr.to + 1, "matches"_a = pr.matches, "inliers"_a = pr.inliers,
                                    "rms_px"_a = pr.rmsPx, "shift_x"_a = pr.shiftX, "shift_y"_a = pr.shiftY,
                                    "rotation_deg"_a = pr.rotationDeg, "scale"_a = pr.scale));
            return out;
        }, "Each neighbour pair's registration (frames numbered from 1).")
        .def_property_readonly("warnings", [](const Mosaic& m) { return m.r.warnings; })
        .def("write", writer<Mosaic>([](const std::string& p, const Mosaic& m, std::string* e) { return rad::writeImage(p, m.r.image, e); }),
             py::arg("path"), "As laserwb-cli radiometry mosaic -o.")
        .def("write_coverage",
             writer<Mosaic>([](const std::string& p, const Mosaic& m, std::string* e) { return rad::writeImage(p, m.r.coverage, e); }),
             py::arg("path"), "As --coverage.")
        .def("write_pairs", writer<Mosaic>([](const std::string& p, const Mosaic& m, std::string* e) { return rad::writePairCsv(p, m.r, e); }),
             py::arg("path"), "As --pairs.");
    r.def("mosaic", [](const py::list& frames, const py::object& params, long long maxPixels) {
        const rad::RadiometryParams p = paramsFrom(params, kRadiometry);
        py::list keep;
        std::vector<cv::Mat> mats;
        for (size_t i = 0; i < frames.size(); ++i)
            mats.push_back(imageArgument(frames[i], "frame " + std::to_string(i + 1), maxPixels, &keep, readAnyDepth));
        Mosaic m;
        {
            py::gil_scoped_release nogil;
            m.r = rad::mosaicRow(mats, p.mosaic);
        }
        check(m.r.ok, m.r.error);
        m.record("radiometry mosaic", rad::radiometrySchema().toJson(p), pathsOf(frames));
        return m;
    }, py::arg("frames"), py::arg("params") = py::none(), py::arg("max_pixels") = 0,
       "Stitches the frames of one row (paths or 2-D arrays, in scan order), as laserwb-cli radiometry mosaic.");
}

// laserwb.radiometry's GCP map: GcpMap and gcp().
void bindRadiometryGcp(py::module_& r) {
    py::class_<GcpMap>(r, "GcpMap", "An image resampled onto the map grid its control points give (fitGcpTransform, warpToMap).")
        .def_property_readonly("image", [](const GcpMap& g) { return resultImage(g.warp.image); })
        .def_property_readonly("valid", [](const GcpMap& g) { return resultImage(g.warp.valid); }, "255 where the map pixel came from inside the image.")
        .def_property_readonly("fit", [](const GcpMap& g) {
            return py::dict("model"_a = std::string(rad::geoModelName(g.fit.model)), "rms_map_m"_a = g.fit.rmsMap,
                            "rms_px"_a = g.fit.rmsPx, "metres_per_pixel"_a = g.fit.metresPerPixel,
                            "outliers"_a = [&] {
                                std::vector<std::string> ids;
                                for (size_t k : g.fit.outliers) ids.push_back(g.gcps[k].id);
                                return ids;
                            }(),
                            "grid"_a = py::dict("width"_a = g.grid.width, "height"_a = g.grid.height, "pixel_size_m"_a = g.grid.pixelSize,
                                                "origin_x"_a = g.grid.originX, "origin_y"_a = g.grid.originY));
        }, "The transform's fit; outliers (GCP ids) make the map doubtful (the CLI's exit 3).")
        .def_property_readonly("warnings", [](const GcpMap& g) { return g.fit.warnings; })
        .def("write",
             mapWriter<GcpMap>([](const std::string& p, const GcpMap& g, bool plain, std::string* e) {
                 return rad::writeMapImage(p, g.warp.image, g.geo, plain, e, g.warp.image.depth() == CV_32F);
             }),
             py::arg("path"), py::arg("plain_tiff") = false, "As laserwb-cli radiometry gcp -o (a GeoTIFF for .tif unless plain_tiff).")
        .def("write_valid",
             mapWriter<GcpMap>([](const std::string& p, const GcpMap& g, bool plain, std::string* e) {
                 return rad::writeMapImage(p, g.warp.valid, g.geo, plain, e);
             }),
             py::arg("path"), py::arg("plain_tiff") = false, "As --valid.")
        .def("write_residuals",
             writer<GcpMap>([](const std::string& p, const GcpMap& g, std::string* e) { return rad::writeGcpResidualCsv(p, g.gcps, g.fit, e); }),
             py::arg("path"), "As --residuals.");
    r.def("gcp", [](const py::object& image, const py::object& gcps, const py::object& params, const py::object& crs, long long maxPixels) {
        const rad::RadiometryParams p = paramsFrom(params, kRadiometry);
        GcpMap g;
        std::string err, crsWkt;
        const std::string gcpFile = inputPath(gcps);
        if (!crs.is_none() && !rad::crsFromUserInput(py::str(crs), &crsWkt, &err)) check(false, "crs: " + err);
        check(rad::readGcpCsv(gcpFile, &g.gcps, &err), err);
        py::list keep;
        const cv::Mat img = imageArgument(image, "image", maxPixels, &keep, readAnyDepth);
        {
            py::gil_scoped_release nogil;
            g.fit = rad::fitGcpTransform(g.gcps, p.gcp);
            if (g.fit.ok) {
                g.grid = rad::gridCovering(g.fit, img.size(), p.mapPixelSizeM > 0 ? p.mapPixelSizeM : g.fit.metresPerPixel);
                g.warp = rad::warpToMap(img, g.fit, g.grid);
                g.geo = rad::geoReferenceOf(g.grid, crsWkt);
            }
        }
        check(g.fit.ok, gcpFile + ": " + g.fit.error);
        check(g.warp.ok, g.warp.error);
        g.record("radiometry gcp", rad::radiometrySchema().toJson(p), {pathOf(image), gcpFile});
        return g;
    }, py::arg("image"), py::arg("gcps"), py::arg("params") = py::none(), py::arg("crs") = py::none(), py::arg("max_pixels") = 0,
       "Fits the image-to-map transform of a GCP CSV and resamples the image (a path or 2-D array) onto\n"
       "the map grid, as laserwb-cli radiometry gcp; crs: 'EPSG:32650', a PROJ string or WKT.");
}

// laserwb.radiometry's apply: Reflectance and apply().
void bindRadiometryApply(py::module_& r) {
    py::class_<Applied>(r, "Reflectance", "A DN image converted to reflectance (applyReflectance).")
        .def_property_readonly("reflectance", [](const Applied& a) { return resultImage(a.r.reflectance); }, "%, float32.")
        .def_property_readonly("uncertainty", [](const Applied& a) -> py::object {
            return a.r.uncertainty.empty() ? py::object(py::none()) : py::object(resultImage(a.r.uncertainty));
        }, "% (float32), when a fit file with K's and B's errors was given.")
        .def_property_readonly("out_of_range", [](const Applied& a) {
            return py::dict("below"_a = a.r.belowRange, "above"_a = a.r.aboveRange);
        })
        .def_property_readonly("warnings", [](const Applied& a) { return a.r.warnings; })
        .def("write",
             mapWriter<Applied>([](const std::string& p, const Applied& a, bool plain, std::string* e) {
                 return rad::writeFloatMapImage(p, a.r.reflectance, a.geo, plain, e);
             }),
             py::arg("path"), py::arg("plain_tiff") = false,
             "As laserwb-cli radiometry apply -o (georeferenced as the input when it was a GeoTIFF path).")
        .def("write_uncertainty",
             mapWriter<Applied>([](const std::string& p, const Applied& a, bool plain, std::string* e) {
                 if (a.r.uncertainty.empty()) {
                     *e = "no uncertainty image: give fit= (a fit file with the errors of K and B)";
                     return false;
                 }
                 return rad::writeFloatMapImage(p, a.r.uncertainty, a.geo, plain, e);
             }),
             py::arg("path"), py::arg("plain_tiff") = false, "As --uncertainty.");
    r.def("apply", [](const py::object& image, const py::object& fit, const py::object& k, const py::object& b,
                      const py::object& params, long long maxPixels) {
        rad::RadiometryParams p = paramsFrom(params, kRadiometry);
        if (fit.is_none() == (k.is_none() && b.is_none()) || k.is_none() != b.is_none())
            throw py::value_error("give fit= (a fit CSV), or k= and b=");
        rad::ReflectanceFit f;
        std::string err;
        p.uncertaintyImage = !fit.is_none();  // (the errors of K and B come with a fit file)
        if (!fit.is_none()) {
            check(rad::readFitCsv(inputPath(fit), &f, &err), err);
        } else {
            f.k = numberArgument(k, "k");
            f.b = numberArgument(b, "b");
        }
        Applied a;
        py::list keep;
        const cv::Mat img = imageArgument(image, "image", maxPixels, &keep, readAnyDepth);
        if (!py::isinstance<py::array>(image)) {
            std::string gerr;
            if (!rad::readGeoReference(inputPath(image), &a.geo, &gerr)) a.geo = rad::GeoReference{};
        }
        {
            py::gil_scoped_release nogil;
            a.r = rad::applyReflectance(img, f, rad::applyParamsOf(p));
        }
        check(a.r.ok, a.r.error);
        a.record("radiometry apply", rad::radiometrySchema().toJson(p), {pathOf(image), pathOf(fit)});
        return a;
    }, py::arg("image"), py::arg("fit") = py::none(), py::arg("k") = py::none(), py::arg("b") = py::none(),
       py::arg("params") = py::none(), py::arg("max_pixels") = 0,
       "Converts a DN image (a path or 2-D array) to reflectance with a fit file (fit=, as written by\n"
       "radiometry fit: the uncertainty image comes with it) or k= and b=, as laserwb-cli radiometry apply.");
}

// laserwb.radiometry's check: Check and check().
void bindRadiometryCheck(py::module_& r) {
    py::class_<CheckTable>(r, "Check", "Relative errors of check regions against their measured reflectance (relativeErrors).")
        .def_property_readonly("table", [](const CheckTable& c) { return relativeErrorDict(c.r); })
        .def_property_readonly("warnings", [](const CheckTable& c) { return c.r.warnings; })
        .def("write_csv",
             writer<CheckTable>([](const std::string& p, const CheckTable& c, std::string* e) { return rad::writeRelativeErrorCsv(p, c.r, e); }),
             py::arg("path"), "As laserwb-cli radiometry check -o (and apply --table).");
    r.def("check", [](const py::object& regions, const py::object& image, const py::object& params, long long maxPixels) {
        const rad::RadiometryParams p = paramsFrom(params, kRadiometry);
        const std::string file = inputPath(regions);
        std::vector<rad::Region> regs;
        std::string err;
        check(rad::readRegionCsv(file, &regs, &err), err);
        py::list keep;
        cv::Mat img;
        if (!image.is_none()) img = imageArgument(image, "image", maxPixels, &keep, readAnyDepth);
        CheckTable c;
        {
            py::gil_scoped_release nogil;
            c.r = rad::relativeErrors(regs, image.is_none() ? nullptr : &img, p.limitPct);
        }
        check(c.r.ok, file + ": " + c.r.error);
        c.record("radiometry check", rad::radiometrySchema().toJson(p), {file, pathOf(image)});
        return c;
    }, py::arg("regions"), py::arg("image") = py::none(), py::arg("params") = py::none(), py::arg("max_pixels") = 0,
       "The relative errors of a check-region CSV, measured on a reflectance image (a path or 2-D\n"
       "array) when given, as laserwb-cli radiometry check; table['all_within_limit'] False is exit 3.");
}

// laserwb.radiometry: its parameters, then the fit, mosaic, GCP map, apply and check steps.
void bindRadiometry(py::module_& top) {
    // ---- radiometry --------------------------------------------------------------------------
    py::module_ r = top.def_submodule("radiometry", "Radiometric calibration (paper 003): mosaic, GCP map, DN to reflectance, check.");
    bindParams(r, kRadiometry);
    bindRadiometryFit(r);
    bindRadiometryMosaic(r);
    bindRadiometryGcp(r);
    bindRadiometryApply(r);
    bindRadiometryCheck(r);
}

}  // namespace

void bindTrendCalibRadiometry(py::module_& top) {
    bindTrend(top);
    bindCalib(top);
    bindRadiometry(top);
}

}  // namespace lwb::py
