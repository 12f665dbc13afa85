#include "core/calib/detector_array.hpp"

#include <algorithm>
#include <cmath>

#include "core/calib/geodesy.hpp"
#include "core/calib/least_squares.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::calib {

namespace {

// "1", "0", "true", "false", "yes", "no" → 1 / 0; −1 when unreadable.
int parseFlag(const std::string& s) {
    const std::string t = toLower(trim(s));
    if (t == "1" || t == "true" || t == "yes" || t == "y") return 1;
    if (t == "0" || t == "false" || t == "no" || t == "n") return 0;
    return -1;
}

}  // namespace

bool readDetectorCsv(const std::string& path, DetectorArray* out, std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int cid = t.firstColumn({"id", "detector", "name"});
    int ce = t.firstColumn({"e", "east", "x"}), cn = t.firstColumn({"n", "north", "y"});
    const int clat = t.firstColumn({"lat", "latitude", "lat_deg"}), clon = t.firstColumn({"lon", "longitude", "lon_deg"});
    const int ch = t.firstColumn({"h", "height", "height_m"});
    const int cen = t.firstColumn({"energy", "e_energy", "signal"});
    const int ctr = t.firstColumn({"triggered", "trigger"}), csat = t.firstColumn({"saturated", "saturation"});
    const bool geographic = ce < 0 || cn < 0;
    if (geographic && (clat < 0 || clon < 0)) {
        *error = path + ":1: header needs the position columns e,n (metres) or lat,lon (degrees)";
        return false;
    }
    if (cen < 0) {
        *error = path + ":1: header needs an energy column";
        return false;
    }
    DetectorArray arr;
    arr.source = path;
    arr.geographic = geographic;
    std::vector<double> lats, lons;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        const std::string where = whereInFile(path, t.lines[i]);
        Detector d;
        d.line = t.lines[i];
        d.id = cid >= 0 ? std::string(trim(row[cid])) : std::to_string(i + 1);
        double x = 0, y = 0;
        const int cx = geographic ? clat : ce, cy = geographic ? clon : cn;
        if (!parseDouble(row[cx], &x) || !parseDouble(row[cy], &y)) {
            *error = where + (geographic ? "lat and lon" : "e and n") + " must be finite numbers, not \"" + printableExcerpt(row[cx]) +
                     "\", \"" + printableExcerpt(row[cy]) + "\"";
            return false;
        }
        if (geographic && (std::fabs(x) > 90 || std::fabs(y) > 360)) {
            *error = where + "latitude/longitude out of range";
            return false;
        }
        if (ch >= 0 && !trim(row[ch]).empty() && !parseDouble(row[ch], &d.h)) {
            *error = where + "height must be a finite number, not \"" + printableExcerpt(row[ch]) + "\"";
            return false;
        }
        if (ctr >= 0 && !trim(row[ctr]).empty()) {
            d.triggered = parseFlag(row[ctr]);
            if (d.triggered < 0) {
                *error = where + "triggered must be 0 or 1, not \"" + printableExcerpt(row[ctr]) + "\"";
                return false;
            }
        }
        if (csat >= 0 && !trim(row[csat]).empty()) {
            d.saturated = parseFlag(row[csat]);
            if (d.saturated < 0) {
                *error = where + "saturated must be 0 or 1, not \"" + printableExcerpt(row[csat]) + "\"";
                return false;
            }
        }
        if (trim(row[cen]).empty()) {
            if (d.triggered != 0) {
                *error = where + "empty energy for a detector not marked triggered=0";
                return false;
            }
        } else if (!parseDouble(row[cen], &d.energy)) {
            *error = where + "energy must be a finite number, not \"" + printableExcerpt(row[cen]) + "\"";
            return false;
        }
        if (geographic) {
            lats.push_back(x);
            lons.push_back(y);
        } else {
            d.e = x;
            d.n = y;
        }
        arr.detectors.push_back(std::move(d));
    }
    if (arr.detectors.empty()) {
        *error = path + ": no detector rows";
        return false;
    }
    if (geographic) {
        double la = 0, lo = 0, hs = 0;
        int nh = 0;
        for (size_t i = 0; i < lats.size(); ++i) {
            la += lats[i];
            lo += lons[i];
            if (std::isfinite(arr.detectors[i].h)) {
                hs += arr.detectors[i].h;
                ++nh;
            }
        }
        arr.originLatDeg = la / lats.size();
        arr.originLonDeg = lo / lons.size();
        arr.originH = nh ? hs / nh : 0;
        const LocalFrame frame(arr.originLatDeg * kDeg, arr.originLonDeg * kDeg, arr.originH);
        for (size_t i = 0; i < lats.size(); ++i) {
            Detector& d = arr.detectors[i];
            const double h = std::isfinite(d.h) ? d.h : arr.originH;
            const Eigen::Vector3d enu = frame.toEnu(geodeticToEcef(lats[i] * kDeg, lons[i] * kDeg, h));
            d.e = enu.x();
            d.n = enu.y();
        }
    }
    *out = std::move(arr);
    return true;
}

std::string validate(const DetectorFitParams& p) {
    if (!std::isfinite(p.background)) return "background must be finite";
    if (!(p.triggerThreshold >= 0 && std::isfinite(p.triggerThreshold))) return "trigger threshold must be >= 0";
    if (!(p.saturationLevel >= 0 && std::isfinite(p.saturationLevel))) return "saturation level must be >= 0 (0 = none)";
    if (p.saturationLevel > 0 && p.saturationLevel <= p.triggerThreshold)
        return "saturation level must exceed the trigger threshold";
    if (!(p.relativeNoise >= 0 && p.relativeNoise <= 1)) return "relative noise must be within 0..1";
    if (!(p.noiseFloor >= 0 && std::isfinite(p.noiseFloor))) return "noise floor must be >= 0";
    if (p.recommendedDetectors < 0 || p.recommendedDetectors > 100000) return "recommended detectors must be 0..100000";
    if (p.maxIterations < 1 || p.maxIterations > 10000) return "LM iterations must be within 1..10000";
    return {};
}

double evalSurface(const GaussSurface& s, double e, double n) {
    const double de = e - s.e0, dn = n - s.n0;
    return s.amplitude * std::exp(-0.5 * (s.a * de * de + 2 * s.b * de * dn + s.c * dn * dn)) + s.background;
}

UncertaintyEllipse ellipseFromCovariance(double varE, double varN, double covEN) {
    UncertaintyEllipse u;
    u.sigmaE = sqrtVariance(varE);
    u.sigmaN = sqrtVariance(varN);
    u.covEN = covEN;
    const double m = 0.5 * (varE + varN), d = std::sqrt(0.25 * (varE - varN) * (varE - varN) + covEN * covEN);
    u.semiMajor = sqrtVariance(m + d);
    u.semiMinor = sqrtVariance(m - d);
    u.orientationRad = 0.5 * std::atan2(2 * covEN, varE - varN);
    return u;
}

const char* detectorStatusName(DetectorStatus s) {
    switch (s) {
        case DetectorStatus::Used: return "used";
        case DetectorStatus::Untriggered: return "untriggered";
        case DetectorStatus::Saturated: return "saturated";
        case DetectorStatus::NoEnergy: return "no_energy";
    }
    return "?";
}

namespace {

struct Shape {
    double sigmaMajor, sigmaMinor, orientation;
};

// Widths of the surface exp(−½ dᵀ M d), M = [a b; b c]: the ellipse of its covariance M⁻¹.
Shape shapeOf(double a, double b, double c) {
    const double det = a * c - b * b;
    const UncertaintyEllipse u = ellipseFromCovariance(c / det, a / det, -b / det);
    return {u.semiMajor, u.semiMinor, u.orientationRad};
}

struct Point {
    double de, dn, energy;
};

// Parameter layout: [A, de0, dn0, a, (b, c,) (B)] with de0, dn0 relative to the reference point.
struct Layout {
    bool elliptical = true, background = true;
    int count() const { return (elliptical ? 6 : 4) + (background ? 1 : 0); }
};

void unpack(const Layout& L, const Eigen::VectorXd& p, double fixedBg, double* A, double* x0, double* y0, double* a,
            double* b, double* c, double* bg) {
    *A = p(0);
    *x0 = p(1);
    *y0 = p(2);
    *a = p(3);
    *b = L.elliptical ? p(4) : 0.0;
    *c = L.elliptical ? p(5) : p(3);
    *bg = L.background ? p(L.count() - 1) : fixedBg;
}

}  // namespace

DetectorFitResult fitDetectorArray(const DetectorArray& array, const DetectorFitParams& params) {
    DetectorFitResult res;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    const auto& det = array.detectors;
    res.detectors.resize(det.size());
    int untriggered = 0, saturated = 0, noEnergy = 0;
    std::vector<size_t> used;
    for (size_t i = 0; i < det.size(); ++i) {
        const Detector& d = det[i];
        DetectorOutcome& o = res.detectors[i];
        const std::string en = formatDouble(d.energy, 6);
        if (!std::isfinite(d.e) || !std::isfinite(d.n)) {
            res.error = (array.source.empty() ? "detector " + d.id : array.source + ":" + std::to_string(d.line)) +
                        ": non-finite position";
            return res;
        }
        if (d.triggered == 0) {
            o.status = DetectorStatus::Untriggered;
            o.reason = "marked untriggered in the input";
        } else if (!std::isfinite(d.energy)) {
            o.status = DetectorStatus::NoEnergy;
            o.reason = "no finite energy recorded";
        } else if (d.saturated == 1) {
            o.status = DetectorStatus::Saturated;
            o.reason = "marked saturated in the input";
        } else if (params.saturationLevel > 0 && d.energy >= params.saturationLevel) {
            o.status = DetectorStatus::Saturated;
            o.reason = "energy " + en + " >= saturation level " + formatDouble(params.saturationLevel, 6);
        } else if (d.energy <= params.triggerThreshold) {
            o.status = DetectorStatus::Untriggered;
            o.reason = "energy " + en + " <= trigger threshold " + formatDouble(params.triggerThreshold, 6);
        } else {
            o.status = DetectorStatus::Used;
            used.push_back(i);
        }
        if (o.status == DetectorStatus::Untriggered) ++untriggered;
        if (o.status == DetectorStatus::Saturated) ++saturated;
        if (o.status == DetectorStatus::NoEnergy) ++noEnergy;
    }
    Layout L;
    L.elliptical = params.model == SurfaceModel::Elliptical;
    L.background = params.fitBackground;
    const int np = L.count();
    res.used = static_cast<int>(used.size());
    if (res.used < np) {
        res.error = "only " + std::to_string(res.used) + " usable detector" + (res.used == 1 ? "" : "s") + " (" +
                    std::to_string(untriggered) + " untriggered, " + std::to_string(saturated) + " saturated, " +
                    std::to_string(noEnergy) + " without energy, of " + std::to_string(det.size()) + ") for the " +
                    std::to_string(np) + "-parameter Gaussian surface: at least " + std::to_string(np) + " are needed";
        return res;
    }
    // Reference point and geometry check on the used detectors.
    double maxE = -INFINITY, minE = INFINITY;
    for (size_t i : used) {
        maxE = std::max(maxE, det[i].energy);
        minE = std::min(minE, det[i].energy);
    }
    const double bg0 = L.background ? std::min(0.0, minE) : params.background;
    double sw = 0, re = 0, rn = 0;
    for (size_t i : used) {
        const double w = std::pow(std::max(det[i].energy - bg0, 0.0), 2);
        sw += w;
        re += w * det[i].e;
        rn += w * det[i].n;
    }
    if (!(sw > 0)) {
        res.error = "no usable detector has energy above the background";
        return res;
    }
    re /= sw;
    rn /= sw;
    {
        Eigen::Matrix2d s = Eigen::Matrix2d::Zero();
        double me = 0, mn = 0;
        for (size_t i : used) {
            me += det[i].e;
            mn += det[i].n;
        }
        me /= used.size();
        mn /= used.size();
        for (size_t i : used) {
            const Eigen::Vector2d d(det[i].e - me, det[i].n - mn);
            s += d * d.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(s);
        if (!(es.eigenvalues()(0) > 1e-9 * std::max(1.0, es.eigenvalues()(1)))) {
            res.error = "the " + std::to_string(res.used) +
                        " usable detectors lie on one line: a 2D Gaussian surface is not determined across it";
            return res;
        }
    }
    std::vector<Point> pts;
    pts.reserve(used.size());
    for (size_t i : used) pts.push_back({det[i].e - re, det[i].n - rn, det[i].energy});
    // Starting width: from log ratios of mid-level detectors (robust on a truncated footprint).
    const double A0 = std::max(maxE - bg0, 1e-300);
    std::vector<double> s2;
    for (const auto& p : pts) {
        const double f = (p.energy - bg0) / A0;
        const double r2 = p.de * p.de + p.dn * p.dn;
        if (f > 0.05 && f < 0.9 && r2 > 0) s2.push_back(r2 / (2 * std::log(1 / f)));
    }
    double sigma0 = 1.0;
    if (s2.empty()) {
        // Fallback width: the smallest detector spacing (sweep over points sorted by east, so a
        // large array is not a quadratic scan).
        std::vector<std::pair<double, double>> byE;
        byE.reserve(pts.size());
        for (const auto& p : pts) byE.emplace_back(p.de, p.dn);
        std::sort(byE.begin(), byE.end());
        double nn = INFINITY;
        for (size_t i = 0; i < byE.size(); ++i)
            for (size_t j = i + 1; j < byE.size() && byE[j].first - byE[i].first < nn; ++j) {
                const double d = std::hypot(byE[j].first - byE[i].first, byE[j].second - byE[i].second);
                if (d > 0) nn = std::min(nn, d);
            }
        if (std::isfinite(nn)) sigma0 = nn;
    } else {
        std::nth_element(s2.begin(), s2.begin() + s2.size() / 2, s2.end());
        sigma0 = std::sqrt(s2[s2.size() / 2]);
    }
    const double floorAbs = params.noiseFloor > 0 ? params.noiseFloor : 1e-3 * params.relativeNoise * A0;
    const bool weighted = params.relativeNoise > 0 || params.noiseFloor > 0;
    std::vector<double> sigma(pts.size(), 1.0);
    auto setWeights = [&](const std::function<double(size_t)>& level) {
        if (!weighted) return;
        for (size_t k = 0; k < pts.size(); ++k) {
            const double m = params.relativeNoise * std::max(level(k), 0.0);
            sigma[k] = std::sqrt(floorAbs * floorAbs + m * m);
        }
    };
    auto modelAt = [&](const Eigen::VectorXd& p, size_t k) {
        double A, x0, y0, a, b, c, bg;
        unpack(L, p, params.background, &A, &x0, &y0, &a, &b, &c, &bg);
        const double dx = pts[k].de - x0, dy = pts[k].dn - y0;
        return A * std::exp(-0.5 * (a * dx * dx + 2 * b * dx * dy + c * dy * dy)) + bg;
    };
    LmProblem prob;
    prob.parameters = np;
    prob.evaluate = [&](const Eigen::VectorXd& p, Eigen::VectorXd* r, Eigen::MatrixXd* J) {
        double A, x0, y0, a, b, c, bg;
        unpack(L, p, params.background, &A, &x0, &y0, &a, &b, &c, &bg);
        if (!(A > 0) || !(a > 0) || !(c > 0) || !(a * c - b * b > 0)) return false;
        r->resize(static_cast<int>(pts.size()));
        if (J) J->resize(static_cast<int>(pts.size()), np);
        for (size_t k = 0; k < pts.size(); ++k) {
            const int i = static_cast<int>(k);
            const double dx = pts[k].de - x0, dy = pts[k].dn - y0;
            const double g = std::exp(-0.5 * (a * dx * dx + 2 * b * dx * dy + c * dy * dy));
            const double m = A * g + bg;
            const double w = 1.0 / sigma[k];
            (*r)(i) = (m - pts[k].energy) * w;
            if (!J) continue;
            (*J)(i, 0) = g * w;
            (*J)(i, 1) = A * g * (a * dx + b * dy) * w;
            (*J)(i, 2) = A * g * (b * dx + c * dy) * w;
            if (L.elliptical) {
                (*J)(i, 3) = -0.5 * A * g * dx * dx * w;
                (*J)(i, 4) = -A * g * dx * dy * w;
                (*J)(i, 5) = -0.5 * A * g * dy * dy * w;
            } else {
                (*J)(i, 3) = -0.5 * A * g * (dx * dx + dy * dy) * w;
            }
            if (L.background) (*J)(i, np - 1) = w;
        }
        return true;
    };
    LmOptions opt;
    opt.maxIterations = params.maxIterations;
    LmOutcome best;
    std::string lastFailure;  // why the starts failed, when none succeeds
    // Multi-start over the width (a truncated footprint can mislead one start).
    for (double f : {1.0, 0.5, 2.0}) {
        Eigen::VectorXd p0(np);
        const double s0 = sigma0 * f, a0 = 1.0 / (s0 * s0);
        if (L.elliptical)
            p0.head(6) << A0, 0, 0, a0, 0, a0;
        else
            p0.head(4) << A0, 0, 0, a0;
        if (L.background) p0(np - 1) = bg0;
        setWeights([&](size_t k) { return pts[k].energy; });
        LmOutcome o = levenbergMarquardt(prob, p0, opt);
        // Two re-weighting passes with the model instead of the noisy data.
        for (int pass = 0; o.ok && weighted && pass < 2; ++pass) {
            const Eigen::VectorXd pk = o.params;
            setWeights([&](size_t k) { return modelAt(pk, k); });
            LmOutcome o2 = levenbergMarquardt(prob, pk, opt);
            if (!o2.ok) break;
            o2.history.insert(o2.history.begin(), o.history.begin(), o.history.end() - 1);
            o = o2;
        }
        if (!o.ok) lastFailure = o.error;
        if (o.ok && (!best.ok || o.cost < best.cost)) best = o;
    }
    if (!best.ok) {
        res.error = "Gaussian surface fit failed from every start (widths 0.5, 1 and 2 times the energy-weighted "
                    "spread): " + (lastFailure.empty() ? std::string("the solver did not converge") : lastFailure);
        return res;
    }
    // Keep the weights of the winning fit for the covariance.
    if (weighted) {
        const Eigen::VectorXd pk = best.params;
        setWeights([&](size_t k) { return modelAt(pk, k); });
        Eigen::VectorXd r;
        Eigen::MatrixXd J;
        prob.evaluate(pk, &r, &J);
        best.residuals = r;
        best.jacobian = J;
        best.cost = r.squaredNorm();
    }
    if (!best.converged) res.warnings.push_back("the surface fit stopped at the iteration limit before converging");
    const Eigen::VectorXd& p = best.params;
    GaussSurface& s = res.surface;
    double A, x0, y0, a, b, c, bg;
    unpack(L, p, params.background, &A, &x0, &y0, &a, &b, &c, &bg);
    s.amplitude = A;
    s.e0 = x0 + re;
    s.n0 = y0 + rn;
    s.a = a;
    s.b = b;
    s.c = c;
    s.background = bg;
    const Shape sh = shapeOf(a, b, c);
    s.sigmaMajor = sh.sigmaMajor;
    s.sigmaMinor = sh.sigmaMinor;
    s.orientationRad = sh.orientation;
    res.centreE = s.e0;
    res.centreN = s.n0;
    res.iterations = static_cast<int>(best.history.size()) - 1;
    for (const auto& h : best.history) res.costPerIteration.push_back(h.cost);
    res.dof = res.used - np;
    res.chi2 = best.cost;
    res.paramNames = L.elliptical ? std::vector<std::string>{"amplitude", "e0_m", "n0_m", "a_per_m2", "b_per_m2", "c_per_m2"}
                                  : std::vector<std::string>{"amplitude", "e0_m", "n0_m", "a_per_m2"};
    if (L.background) res.paramNames.push_back("background");
    Eigen::MatrixXd cov;
    double rcond = 0;
    if (!covarianceFromJacobian(best.jacobian, 1e-12, &cov, &rcond)) {
        res.error = "the detector geometry does not determine the Gaussian surface (reciprocal condition " +
                    formatDouble(rcond, 3) + "): too few detectors around the footprint";
        return res;
    }
    double scale = 1;
    if (!weighted || params.scaleByChi2) {
        if (res.dof > 0) {
            scale = res.chi2 / res.dof;
        } else {
            scale = NAN;
            res.warnings.push_back("as many parameters as detectors: the fit passes through every detector and its "
                                   "uncertainty cannot be estimated");
        }
    }
    res.covariance = cov * scale;
    const Eigen::MatrixXd& C = res.covariance;
    res.centreEllipse = ellipseFromCovariance(C(1, 1), C(2, 2), C(1, 2));
    res.amplitudeSd = std::sqrt(C(0, 0));
    {  // σ of the widths by the delta method over (a, b, c)
        const int ia = 3, ib = L.elliptical ? 4 : -1, ic = L.elliptical ? 5 : 3;
        Eigen::MatrixXd G(2, np);
        G.setZero();
        const double h = 1e-6 * std::max(std::fabs(a), std::fabs(c));
        auto widths = [&](double aa, double bb, double cc) {
            const Shape t = shapeOf(aa, bb, cc);
            return Eigen::Vector2d(t.sigmaMajor, t.sigmaMinor);
        };
        if (L.elliptical) {
            G.col(ia) = (widths(a + h, b, c) - widths(a - h, b, c)) / (2 * h);
            G.col(ib) = (widths(a, b + h, c) - widths(a, b - h, c)) / (2 * h);
            G.col(ic) = (widths(a, b, c + h) - widths(a, b, c - h)) / (2 * h);
        } else {
            G.col(ia) = (widths(a + h, 0, a + h) - widths(a - h, 0, a - h)) / (2 * h);
        }
        const Eigen::Matrix2d cw = G * C * G.transpose();
        res.sigmaMajorSd = sqrtVariance(cw(0, 0));
        res.sigmaMinorSd = sqrtVariance(cw(1, 1));
    }
    // Per-detector model and residual; consistency of the set-aside detectors.
    double ss = 0;
    for (size_t i = 0; i < det.size(); ++i) {
        DetectorOutcome& o = res.detectors[i];
        o.model = evalSurface(s, det[i].e, det[i].n);
        if (o.status == DetectorStatus::Used) {
            o.residual = det[i].energy - o.model;
            ss += o.residual * o.residual;
        } else if (o.status == DetectorStatus::Untriggered && params.triggerThreshold > 0 &&
                   o.model > 2 * params.triggerThreshold) {
            res.warnings.push_back("detector " + det[i].id + " is untriggered but the fit predicts " +
                                   formatDouble(o.model, 4) + ", twice the trigger threshold");
        } else if (o.status == DetectorStatus::Saturated && params.saturationLevel > 0 &&
                   o.model < 0.8 * params.saturationLevel) {
            res.warnings.push_back("detector " + det[i].id + " is saturated but the fit predicts only " +
                                   formatDouble(o.model, 4));
        }
    }
    res.rmsResidual = std::sqrt(ss / res.used);
    if (res.used < params.recommendedDetectors)
        res.warnings.push_back("only " + std::to_string(res.used) + " usable detectors (paper 002 asks for at least " +
                               std::to_string(params.recommendedDetectors) + ")");
    double emin = INFINITY, emax = -INFINITY, nmin = INFINITY, nmax = -INFINITY;
    for (size_t i : used) {
        emin = std::min(emin, det[i].e);
        emax = std::max(emax, det[i].e);
        nmin = std::min(nmin, det[i].n);
        nmax = std::max(nmax, det[i].n);
    }
    if (s.e0 < emin || s.e0 > emax || s.n0 < nmin || s.n0 > nmax)
        res.warnings.push_back("the fitted centre lies outside the usable detectors (extrapolated)");
    // Height at the centre: plane through the detector heights (all surveyed detectors).
    {
        std::vector<const Detector*> hs;
        for (const auto& d : det)
            if (std::isfinite(d.h)) hs.push_back(&d);
        if (hs.size() >= 3) {
            Eigen::MatrixXd M(hs.size(), 3);
            Eigen::VectorXd y(hs.size());
            for (size_t k = 0; k < hs.size(); ++k) {
                M(k, 0) = 1;
                M(k, 1) = hs[k]->e - s.e0;
                M(k, 2) = hs[k]->n - s.n0;
                y(k) = hs[k]->h;
            }
            Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(M);
            if (qr.rank() == 3)
                res.centreH = qr.solve(y)(0);
            else
                res.centreH = y.mean();
        } else if (!hs.empty()) {
            double m = 0;
            for (auto* d : hs) m += d->h;
            res.centreH = m / hs.size();
        }
    }
    if (array.geographic) {
        const LocalFrame frame(array.originLatDeg * kDeg, array.originLonDeg * kDeg, array.originH);
        const Geodetic g = ecefToGeodetic(frame.toEcef(Eigen::Vector3d(s.e0, s.n0, 0)));
        res.centreLatDeg = g.latRad / kDeg;
        res.centreLonDeg = g.lonRad / kDeg;
    }
    res.ok = std::isfinite(res.centreE) && std::isfinite(res.centreN);
    if (!res.ok) res.error = "the surface fit produced a non-finite centre";
    return res;
}

bool writeDetectorCsv(const std::string& path, const DetectorArray& array, std::string* error) {
    std::string s = array.geographic ? "id,lat,lon,h,energy,triggered,saturated\n" : "id,e,n,h,energy,triggered,saturated\n";
    const LocalFrame frame(array.originLatDeg * kDeg, array.originLonDeg * kDeg, array.originH);
    auto f = [](double v, int d) { return std::isfinite(v) ? formatFixed(v, d) : std::string(); };
    for (const auto& d : array.detectors) {
        std::string pos;
        if (array.geographic) {
            const Geodetic g = ecefToGeodetic(frame.toEcef(Eigen::Vector3d(d.e, d.n, 0)));
            pos = formatFixed(g.latRad / kDeg, 9) + "," + formatFixed(g.lonRad / kDeg, 9);
        } else {
            pos = f(d.e, 4) + "," + f(d.n, 4);
        }
        s += csvEscape(d.id) + "," + pos + "," + f(d.h, 4) + "," + (std::isfinite(d.energy) ? formatDouble(d.energy, 10) : "") +
             "," + (d.triggered < 0 ? "" : std::to_string(d.triggered)) + "," +
             (d.saturated < 0 ? "" : std::to_string(d.saturated)) + "\n";
    }
    return writeFileAtomic(path, s, error);
}

bool writeDetectorReportCsv(const std::string& path, const DetectorArray& array, const DetectorFitResult& r,
                            std::string* error) {
    std::string s = "id,e_m,n_m,h_m,energy,status,reason,model,residual\n";
    auto f = [](double v, int d) { return std::isfinite(v) ? formatFixed(v, d) : std::string(); };
    auto g = [](double v) { return std::isfinite(v) ? formatDouble(v, 8) : std::string(); };
    for (size_t i = 0; i < array.detectors.size() && i < r.detectors.size(); ++i) {
        const Detector& d = array.detectors[i];
        const DetectorOutcome& o = r.detectors[i];
        s += csvEscape(d.id) + "," + f(d.e, 3) + "," + f(d.n, 3) + "," + f(d.h, 3) + "," + g(d.energy) + "," +
             detectorStatusName(o.status) + "," + csvEscape(o.reason) + "," + g(o.model) + "," + g(o.residual) + "\n";
    }
    return writeFileAtomic(path, s, error);
}

}  // namespace lwb::core::calib
