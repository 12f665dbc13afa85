// laserwb.trend, laserwb.calib, laserwb.radiometry: the centroid trend (computeTrend,
// writeTrendCsv), the calibration task (CalibTask: detector fit, statistics) with its writers, and
// the radiometric fit's steps (measureRegionDn, fitReflectance, writeFitCsv), as the CLI's
// `trend`, `calib detector|stats` and `radiometry fit` commands run them.
#include "bind.hpp"
#include "core/calib/calib_csv.hpp"
#include "core/calib/calib_params.hpp"
#include "core/calib/calib_run.hpp"
#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/footprint/trend.hpp"
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

std::string fsPath(const py::object& o) { return py::str(py::module_::import("os").attr("fspath")(o)); }

// A method that writes the object with a core writer (path, object, &error): the path as
// os.fspath gives it, the GIL released while it writes, a failure raised with the core's message.
template <class T, class W>
auto writer(W write) {
    return [write](const T& obj, const py::object& path) {
        const std::string p = fsPath(path);
        std::string err;
        py::gil_scoped_release nogil;
        check(write(p, obj, &err), err);
    };
}

struct Trend {
    fp::TrendResult r;
};
struct Detector {
    cal::DetectorArray array;
    cal::CalibRunResult run;
};
struct Pointing {
    cal::CalibRunResult run;
};
struct Stats {
    cal::CalibRunResult run;
};
struct RadiometryFit {
    std::vector<rad::Region> regions;
    rad::ReflectanceFitResult r;
};

// A numpy image as the single-channel float32 Mat the radiometry steps read (viewed when float32
// and C-contiguous).
using Image = py::array_t<float, py::array::c_style | py::array::forcecast>;

}  // namespace

void bindTrendCalibRadiometry(py::module_& top) {
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
        const std::string file = fsPath(path);
        Trend x;
        std::vector<fp::CentroidRecord> recs;
        std::string err;
        {
            py::gil_scoped_release nogil;
            check(fp::readCentroidCsv(file, &recs, &err), err);
            x.r = fp::computeTrend(recs, p);
        }
        check(x.r.ok, x.r.error);
        return x;
    }, py::arg("path"), py::arg("params") = py::none(),
       "Reads a centroid table (time,beam,x,y[,camera]) and computes the monthly trend, as laserwb-cli trend.");

    // ---- calibration -------------------------------------------------------------------------
    py::module_ c = top.def_submodule("calib", "Laser altimeter calibration (paper 002): detector arrays, statistics.");
    bindParams(c, kCalib);
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
        const std::string file = fsPath(path);
        Detector d;
        {
            py::gil_scoped_release nogil;
            cal::CalibInputData in;
            std::string err;
            check(cal::readDetectorCsv(file, &in.array, &err), err);
            d.array = in.array;
            d.run = core::runTask<cal::CalibTask>(in, p);
        }
        check(d.run.detector.ok, file + ": " + d.run.detector.error);
        return d;
    }, py::arg("path"), py::arg("params") = py::none(), "Fits the footprint centre of a detector CSV (CalibTask), as laserwb-cli calib detector.");
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
        const std::string file = fsPath(points), beamFile = fsPath(beams);
        Pointing x;
        {
            py::gil_scoped_release nogil;
            cal::CalibInputData in;
            std::string err;
            check(cal::readBeamsJson(beamFile, &in.beams, &err), err);
            check(cal::readControlPointCsv(file, &in.points, &err), err);
            check(!in.points.empty(), file + ": no control points");
            x.run = core::runTask<cal::CalibTask>(in, p);
        }
        check(x.run.pointing.ok, file + ": " + x.run.pointing.error);
        return x;
    }, py::arg("points"), py::arg("beams"), py::arg("params") = py::none(),
       "Pointing calibration from a control-point CSV and the beam designs (JSON), as laserwb-cli calib pointing.");
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
        const std::string file = fsPath(path);
        Stats s;
        {
            py::gil_scoped_release nogil;
            cal::CalibInputData in;
            std::string err;
            check(cal::readDifferencesCsv(file, group, &in.differences, &err), err);
            in.differencesName = file;
            in.groupColumn = group;
            s.run = core::runTask<cal::CalibTask>(in, p);
        }
        for (const auto& g : s.run.stats) check(g.stats.ok, file + ": " + g.stats.error);
        return s;
    }, py::arg("path"), py::arg("group") = "", py::arg("params") = py::none(),
       "Statistics of a CSV of elevation differences (per `group` column value), as laserwb-cli calib stats.");

    // ---- radiometry --------------------------------------------------------------------------
    py::module_ r = top.def_submodule("radiometry", "Radiometric calibration (paper 003): DN to reflectance.");
    bindParams(r, kRadiometry);
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
        const std::string file = fsPath(path);
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
        const std::string file = fsPath(regions);
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
                check(rad::readImageAnyDepth(fsPath(image), &img, &err, core::kMaxImagePixels), err);
            }
        }
        {
            py::gil_scoped_release nogil;
            if (!img.empty()) check(rad::measureRegionDn(img, p.fit, &f.regions, &err), file + ": " + err);
            f.r = rad::fitReflectance(f.regions, p.fit);
        }
        check(f.r.ok, file + ": " + f.r.error);
        return f;
    }, py::arg("regions"), py::arg("image") = py::none(), py::arg("params") = py::none(),
       "Fits DN to reflectance from a region CSV, measuring the regions' DN on `image` (a path, or a\n"
       "2-D array) when given, as laserwb-cli radiometry fit.");
}

}  // namespace lwb::py
