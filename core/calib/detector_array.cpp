#include "core/calib/detector_array.hpp"
#include "core/calib/calib_params.hpp"

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
        // The origin: the mean latitude and the circular mean of the longitudes (an array across
        // the antimeridian, at 179.9999 and -179.9999, averaged to 0: the local frame on the other
        // side of the Earth, a centre 3 900 km off with a sigma of 0.14 m).
        double la = 0, ls = 0, lc = 0, hs = 0;
        int nh = 0;
        for (size_t i = 0; i < lats.size(); ++i) {
            la += lats[i];
            ls += std::sin(lons[i] * kDeg);
            lc += std::cos(lons[i] * kDeg);
            if (std::isfinite(arr.detectors[i].h)) {
                hs += arr.detectors[i].h;
                ++nh;
            }
        }
        arr.originLatDeg = la / lats.size();
        arr.originLonDeg = std::atan2(ls, lc) / kDeg;
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
    // The ranges of the schema's rows and the rules between them (calib_params.cpp).
    CalibParams c;
    c.detector = p;
    return calibSchema().validate(c, "detector.");
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

const char* surfaceModelName(SurfaceModel m) {
    switch (m) {
        case SurfaceModel::Auto: return "auto";
        case SurfaceModel::Elliptical: return "elliptical";
        case SurfaceModel::Circular: return "circular";
    }
    return "?";
}

const char* detectorStatusName(DetectorStatus s) {
    switch (s) {
        case DetectorStatus::Used: return "used";
        case DetectorStatus::Untriggered: return "untriggered";
        case DetectorStatus::Saturated: return "saturated";
        case DetectorStatus::NoEnergy: return "no_energy";
        case DetectorStatus::AtLeast: return "at_least";
        case DetectorStatus::AtMost: return "at_most";
        case DetectorStatus::Outlier: return "outlier";
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

// One detector in the fit: a measurement, or a bound (censored: "at least" / "at most" value).
enum class Kind { Exact, AtLeast, AtMost };
struct Obs {
    double de, dn, value;
    Kind kind;
    size_t index;      // into the array
    double sigma = 1;  // noise σ (energy unit) of this pass
    double count = 1;  // detectors this term stands for (identical far "at most" bounds merged)
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

// −2 ln Φ(z) and the inverse Mills ratio φ(z)/Φ(z), accurate in both tails.
void censoredTerm(double z, double* q, double* millsRatio) {
    constexpr double kInvSqrt2Pi = 0.3989422804014327, kSqrtHalf = 0.7071067811865476;
    if (z > 0) {
        const double tail = 0.5 * std::erfc(z * kSqrtHalf);  // 1 − Φ(z)
        *q = -2 * std::log1p(-tail);
        *millsRatio = kInvSqrt2Pi * std::exp(-0.5 * z * z) / (1 - tail);
    } else if (z > -30) {
        const double cdf = 0.5 * std::erfc(-z * kSqrtHalf);
        *q = -2 * std::log(cdf);
        *millsRatio = kInvSqrt2Pi * std::exp(-0.5 * z * z) / cdf;
    } else {  // asymptotic series of Φ(z) for z → −∞
        const double z2 = z * z, series = 1 - 1 / z2 + 3 / (z2 * z2);
        *q = z2 + std::log(2 * M_PI) + 2 * std::log(-z) - 2 * std::log(series);
        *millsRatio = -z / series;
    }
}

// Whitened residuals of the Gaussian surface: (model − energy)/σ for a measurement, and
// √(−2 ln P(bound statement)) for a censored detector (its normal likelihood as a square).
struct SurfaceProblem {
    const std::vector<Obs>* obs = nullptr;
    Layout L;
    double fixedBg = 0;
    double robustC = 0;  // > 0: Cauchy loss c²·ln(1 + q/c²) on each term's q = r² (c in σ units)

    double model(const Eigen::VectorXd& p, double de, double dn) const {
        double A, x0, y0, a, b, c, bg;
        unpack(L, p, fixedBg, &A, &x0, &y0, &a, &b, &c, &bg);
        const double dx = de - x0, dy = dn - y0;
        return A * std::exp(-0.5 * (a * dx * dx + 2 * b * dx * dy + c * dy * dy)) + bg;
    }

    bool evaluate(const Eigen::VectorXd& p, Eigen::VectorXd* r, Eigen::MatrixXd* J) const {
        double A, x0, y0, a, b, c, bg;
        unpack(L, p, fixedBg, &A, &x0, &y0, &a, &b, &c, &bg);
        if (!(A > 0) || !(a > 0) || !(c > 0) || !(a * c - b * b > 0)) return false;
        const int np = L.count();
        const auto& o = *obs;
        r->resize(static_cast<int>(o.size()));
        if (J) J->resize(static_cast<int>(o.size()), np);
        Eigen::RowVectorXd grad(np);
        for (size_t k = 0; k < o.size(); ++k) {
            const int i = static_cast<int>(k);
            const double dx = o[k].de - x0, dy = o[k].dn - y0;
            const double g = std::exp(-0.5 * (a * dx * dx + 2 * b * dx * dy + c * dy * dy));
            const double m = A * g + bg, s = o[k].sigma;
            grad(0) = g;
            grad(1) = A * g * (a * dx + b * dy);
            grad(2) = A * g * (b * dx + c * dy);
            if (L.elliptical) {
                grad(3) = -0.5 * A * g * dx * dx;
                grad(4) = -A * g * dx * dy;
                grad(5) = -0.5 * A * g * dy * dy;
            } else {
                grad(3) = -0.5 * A * g * (dx * dx + dy * dy);
            }
            if (L.background) grad(np - 1) = 1;
            if (o[k].kind == Kind::Exact) {
                (*r)(i) = (m - o[k].value) / s;
                if (J) J->row(i) = grad / s;
            } else {
                // At least v: P = Φ((m − v)/σ); at most v: P = Φ((v − m)/σ).
                const double sign = o[k].kind == Kind::AtLeast ? 1.0 : -1.0;
                double q, lambda;
                censoredTerm(sign * (m - o[k].value) / s, &q, &lambda);
                const double rr = std::sqrt(std::max(q, 0.0));
                (*r)(i) = rr;
                if (J) J->row(i) = rr > 1e-150 ? Eigen::RowVectorXd(-lambda * sign / (s * rr) * grad) : Eigen::RowVectorXd::Zero(np);
                if (o[k].count != 1) {
                    const double w = std::sqrt(o[k].count);
                    (*r)(i) *= w;
                    if (J) J->row(i) *= w;
                }
            }
            if (robustC > 0) {  // r' = ±√ρ(r²), dr'/dr = r / (r'·(1 + r²/c²))
                const double rv = (*r)(i), q = rv * rv, c2 = robustC * robustC;
                const double rp = std::copysign(std::sqrt(c2 * std::log1p(q / c2)), rv);
                if (J && std::fabs(rv) > 1e-150) J->row(i) *= rv / (rp * (1 + q / c2));
                (*r)(i) = rp;
            }
        }
        return true;
    }
};

LmOutcome solveSurface(const SurfaceProblem& sp, const Eigen::VectorXd& start, int maxIterations) {
    LmProblem prob;
    prob.parameters = sp.L.count();
    prob.evaluate = [&sp](const Eigen::VectorXd& p, Eigen::VectorXd* r, Eigen::MatrixXd* J) { return sp.evaluate(p, r, J); };
    LmOptions opt;
    opt.maxIterations = maxIterations;
    return levenbergMarquardt(prob, start, opt);
}

// Noise σ² = floor² + (rel·level)² from squared residuals u (leverage corrected, so E[u] = σ²)
// at the model levels: maximum likelihood of the scale for each share t of the relative term,
// t on a grid; the relative term is kept only when it raises the log-likelihood by more than
// BIC's ½ ln n for its parameter.
void estimateNoise(const std::vector<double>& u, const std::vector<double>& level, bool allowRelative, double* floor,
                   double* rel) {
    const size_t n = u.size();
    double top = 0;
    for (double l : level) top = std::max(top, l);
    double uMax = 0;
    for (double x : u) uMax = std::max(uMax, x);
    const double tiny = 1e-30 * std::max({top * top, uMax, 1e-300});
    auto profile = [&](double t, double* s2) {
        double acc = 0, logw = 0;
        for (size_t k = 0; k < n; ++k) {
            const double f = top > 0 ? level[k] / top : 0;
            const double w = (1 - t) + t * f * f;
            acc += u[k] / w;
            logw += std::log(w);
        }
        *s2 = std::max(acc / n, tiny);
        return -0.5 * (logw + n * std::log(*s2));
    };
    double s2 = 0, bestT = 0;
    const double l0 = profile(0, &s2);
    double best = l0, bestS2 = s2;
    if (allowRelative && top > 0 && n >= 4)
        for (int i = 1; i <= 49; ++i) {
            const double t = i / 50.0;
            const double l = profile(t, &s2);
            if (l > best) {
                best = l;
                bestT = t;
                bestS2 = s2;
            }
        }
    if (bestT > 0 && 2 * (best - l0) <= std::log(static_cast<double>(n))) {
        bestT = 0;
        profile(0, &bestS2);
    }
    *floor = std::sqrt(bestS2 * (1 - bestT));
    *rel = top > 0 ? std::sqrt(bestS2 * bestT) / top : 0;
}

// ln(1 − Φ(z)), accurate in both tails.
double logUpperTail(double z) {
    constexpr double kSqrtHalf = 0.7071067811865476;
    if (z > 0) return z < 37 ? std::log(0.5 * std::erfc(z * kSqrtHalf)) : -0.5 * z * z - std::log(z * 2.5066282746310002);
    return std::log1p(-0.5 * std::erfc(-z * kSqrtHalf));
}

// The normal score of a probability given by its upper tail: w with 1 − Φ(w) = exp(logTail), by
// bisection (monotone, 80 halvings of [−40, 40] reach the double's resolution).
double normalScoreOfUpperTail(double logTail) {
    double lo = -40, hi = 40;
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        (logUpperTail(mid) > logTail ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Upper tail P(χ²_ν ≥ x) by the Wilson–Hilferty cube-root normal approximation.
double chi2UpperTail(double x, int nu) {
    if (nu <= 0 || !(x >= 0)) return NAN;
    const double v = nu, h = 2.0 / (9 * v);
    const double z = (std::cbrt(x / v) - (1 - h)) / std::sqrt(h);
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

using P2 = Eigen::Vector2d;

// Convex hull (Andrew's monotone chain), counter-clockwise, no repeated points.
std::vector<P2> convexHull(std::vector<P2> pts) {
    std::sort(pts.begin(), pts.end(), [](const P2& a, const P2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return pts;
    auto cross = [](const P2& o, const P2& a, const P2& b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    std::vector<P2> h(2 * pts.size());
    size_t k = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
        h[k++] = pts[i];
    }
    for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1);
    return h;
}

// Distance of p outside the convex hull of pts (0 inside or on it; NaN without points).
double distanceOutsideHull(const std::vector<P2>& pts, const P2& p) {
    const std::vector<P2> h = convexHull(pts);
    if (h.empty()) return NAN;
    if (h.size() == 1) return (p - h[0]).norm();
    bool inside = h.size() >= 3;
    double best = INFINITY;
    for (size_t i = 0; i < h.size(); ++i) {
        const P2& a = h[i];
        const P2& b = h[(i + 1) % h.size()];
        const P2 ab = b - a;
        if ((ab.x() * (p.y() - a.y()) - ab.y() * (p.x() - a.x())) < 0) inside = false;
        const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
        best = std::min(best, (p - (a + t * ab)).norm());
        if (h.size() == 2) break;
    }
    return inside ? 0.0 : best;
}

// Distance of every point to its nearest other point (∞ when alone), by a sweep over east.
std::vector<double> nearestNeighbourDistances(const std::vector<P2>& pts) {
    std::vector<size_t> order(pts.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return pts[a].x() < pts[b].x(); });
    std::vector<double> nn(pts.size(), INFINITY);
    for (size_t i = 0; i < order.size(); ++i)
        for (size_t j = i + 1; j < order.size(); ++j) {
            const P2& a = pts[order[i]];
            const P2& b = pts[order[j]];
            if (b.x() - a.x() >= std::max(nn[order[i]], 0.0) && std::isfinite(nn[order[i]])) break;
            const double d = (a - b).norm();
            if (d <= 0) continue;
            nn[order[i]] = std::min(nn[order[i]], d);
            nn[order[j]] = std::min(nn[order[j]], d);
        }
    std::vector<double> finite;
    for (double d : nn)
        if (std::isfinite(d)) finite.push_back(d);
    return finite;
}

// Median of a copy.
double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    const size_t m = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + m, v.end());
    return v[m];
}

}  // namespace

// fitDetectorArray in named stages: judge the detectors, choose the surface, start it robustly,
// refine noise and outliers, then the figures, the uncertainty, the per-detector report, the
// doubts and the centre's height. The stages share one SurfaceFit (observations, problem, best
// solution, reference point and noise model).
namespace {

double sigmaOf(double floor, double rel, double level) {
    const double m = rel * std::max(level, 0.0);
    return std::sqrt(floor * floor + m * m);
}

bool givenNoise(const DetectorFitParams& p) { return p.noise == NoiseSource::Given; }
bool givenWeights(const DetectorFitParams& p) { return givenNoise(p) && (p.relativeNoise > 0 || p.noiseFloor > 0); }

// Stage 1a. What each detector says on its own: untriggered, saturated, no energy, or used.
std::string judgeDetectors(const DetectorArray& array, const DetectorFitParams& params, std::vector<DetectorOutcome>* out) {
    const auto& det = array.detectors;
    for (size_t i = 0; i < det.size(); ++i) {
        const Detector& d = det[i];
        DetectorOutcome& o = (*out)[i];
        const std::string en = formatDouble(d.energy, 6);
        if (!std::isfinite(d.e) || !std::isfinite(d.n))
            return (array.source.empty() ? "detector " + d.id : array.source + ":" + std::to_string(d.line)) +
                   ": non-finite position";
        if (d.triggered == 0) {
            o.status = DetectorStatus::Untriggered;
            o.reason = "marked untriggered in the input";
        } else if (d.saturated == 1) {
            o.status = DetectorStatus::Saturated;
            o.reason = "marked saturated in the input";
            o.bound = std::isfinite(d.energy) ? d.energy : params.saturationLevel > 0 ? params.saturationLevel : NAN;
        } else if (!std::isfinite(d.energy)) {
            o.status = DetectorStatus::NoEnergy;
            o.reason = "no finite energy recorded";
        } else if (params.saturationLevel > 0 && d.energy >= params.saturationLevel) {
            o.status = DetectorStatus::Saturated;
            o.reason = "energy " + en + " >= saturation level " + formatDouble(params.saturationLevel, 6);
            o.bound = params.saturationLevel;
        } else if (params.triggerThreshold > 0 && d.energy <= params.triggerThreshold) {
            o.status = DetectorStatus::Untriggered;
            o.reason = "energy " + en + " <= trigger threshold " + formatDouble(params.triggerThreshold, 6);
        } else {
            o.status = DetectorStatus::Used;
        }
    }
    return {};
}

// The range of the used detectors' energies (±∞ when none is used).
struct UsedEnergies {
    double max = -INFINITY, min = INFINITY, minTriggered = INFINITY;
};
UsedEnergies usedEnergies(const std::vector<Detector>& det, const std::vector<DetectorOutcome>& out) {
    UsedEnergies u;
    for (size_t i = 0; i < det.size(); ++i)
        if (out[i].status == DetectorStatus::Used) {
            u.max = std::max(u.max, det[i].energy);
            u.min = std::min(u.min, det[i].energy);
            if (det[i].triggered == 1) u.minTriggered = std::min(u.minTriggered, det[i].energy);
        }
    return u;
}

// Stage 1b. A clip level nobody declared: when the input says nothing of saturation, the highest
// energy shared exactly by two or more detectors is taken as saturation. True when it was.
bool markUndeclaredClip(const DetectorArray& array, const DetectorFitParams& params, double maxUsed, DetectorFitResult* res) {
    const auto& det = array.detectors;
    bool anySatColumn = false;
    for (const Detector& d : det) anySatColumn = anySatColumn || d.saturated >= 0;
    if (anySatColumn || params.saturationLevel > 0 || !std::isfinite(maxUsed) || !(maxUsed > 0)) return false;
    int atMax = 0;
    for (size_t i = 0; i < det.size(); ++i) atMax += res->detectors[i].status == DetectorStatus::Used && det[i].energy == maxUsed;
    if (atMax < 2) return false;
    for (size_t i = 0; i < det.size(); ++i)
        if (res->detectors[i].status == DetectorStatus::Used && det[i].energy == maxUsed) {
            res->detectors[i].status = DetectorStatus::Saturated;
            res->detectors[i].reason = "shares the highest energy " + formatDouble(maxUsed, 6) + " (clipped)";
            res->detectors[i].bound = maxUsed;
        }
    res->warnings.push_back(std::to_string(atMax) + " detectors share the highest energy " + formatDouble(maxUsed, 6) +
                            ": taken as saturated at that level (give the saturation level to decide otherwise)");
    return true;
}

// Stage 1c. The fit's observations: measurements, and (censoring on) saturated detectors as
// "at least" their bound, untriggered ones as "at most" the trigger level.
struct Observations {
    std::vector<Obs> obs;
    int untriggered = 0, saturated = 0, noEnergy = 0, exact = 0, atLeast = 0;
    int informative() const { return exact + atLeast; }
};
Observations observationsOf(const std::vector<Detector>& det, const DetectorFitParams& params, double maxUsed, double upperBound,
                            std::vector<DetectorOutcome>* out) {
    Observations r;
    for (size_t i = 0; i < det.size(); ++i) {
        DetectorOutcome& o = (*out)[i];
        if (o.status == DetectorStatus::Saturated) {
            ++r.saturated;
            if (!std::isfinite(o.bound)) o.bound = maxUsed;  // at least the brightest measurement
            if (params.censor && std::isfinite(o.bound)) {
                o.status = DetectorStatus::AtLeast;
                o.reason += "; in the fit as at least " + formatDouble(o.bound, 6);
            }
        } else if (o.status == DetectorStatus::Untriggered) {
            ++r.untriggered;
            if (params.censor && std::isfinite(upperBound)) {
                o.status = DetectorStatus::AtMost;
                o.bound = upperBound;
                o.reason += "; in the fit as at most " + formatDouble(upperBound, 6);
            }
        } else if (o.status == DetectorStatus::NoEnergy) {
            ++r.noEnergy;
        }
        if (o.status == DetectorStatus::Used) r.obs.push_back({det[i].e, det[i].n, det[i].energy, Kind::Exact, i});
        else if (o.status == DetectorStatus::AtLeast) r.obs.push_back({det[i].e, det[i].n, o.bound, Kind::AtLeast, i});
        else if (o.status == DetectorStatus::AtMost) r.obs.push_back({det[i].e, det[i].n, o.bound, Kind::AtMost, i});
    }
    for (const Obs& ob : r.obs) {
        r.exact += ob.kind == Kind::Exact;
        r.atLeast += ob.kind == Kind::AtLeast;
    }
    return r;
}

// Stage 2a. The surface: Auto takes the elliptical one from 10 measurements (3 degrees of freedom
// left), else the circular one, without background below 7.
Layout chooseSurface(const DetectorFitParams& params, int informative, SurfaceModel* model) {
    Layout L;
    L.background = params.fitBackground;
    *model = params.model;
    if (*model == SurfaceModel::Auto) {
        *model = informative >= 10 ? SurfaceModel::Elliptical : SurfaceModel::Circular;
        if (informative < 7) L.background = false;
    }
    L.elliptical = *model == SurfaceModel::Elliptical;
    return L;
}

// Stage 2b. Enough measurements for the parameters (Auto leaves one degree of freedom for the
// noise), spanning two dimensions. Returns the error, empty when the surface is determined.
std::string checkDetermined(const Observations& ob, size_t detectors, const DetectorFitParams& params, int np) {
    const int informative = ob.informative();
    const int needed = params.model == SurfaceModel::Auto ? np + 1 : np;
    if (informative < needed)
        return "only " + std::to_string(informative) + " detector" + (informative == 1 ? "" : "s") + " with a measurement (" +
               std::to_string(ob.untriggered) + " untriggered, " + std::to_string(ob.saturated) + " saturated, " +
               std::to_string(ob.noEnergy) + " without energy, of " + std::to_string(detectors) + ") for the " +
               std::to_string(np) + "-parameter Gaussian surface: at least " + std::to_string(needed) + " are needed";
    Eigen::Matrix2d s = Eigen::Matrix2d::Zero();
    P2 mean = P2::Zero();
    int n = 0;
    for (const Obs& o : ob.obs)
        if (o.kind != Kind::AtMost) {
            mean += P2(o.de, o.dn);
            ++n;
        }
    mean /= n;
    for (const Obs& o : ob.obs)
        if (o.kind != Kind::AtMost) {
            const P2 d = P2(o.de, o.dn) - mean;
            s += d * d.transpose();
        }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(s);
    if (!(es.eigenvalues()(0) > 1e-9 * std::max(1.0, es.eigenvalues()(1))))
        return "the " + std::to_string(informative) +
               " measured detectors lie on one line: a 2D Gaussian surface is not determined across it";
    return {};
}

// The fit as the stages pass it on. `sp` points at `obs`: not copyable.
struct SurfaceFit {
    std::vector<Obs> obs;  // positions relative to (re, rn)
    SurfaceProblem sp;
    LmOutcome best;
    double re = 0, rn = 0;        // reference point: centroid of the brightest half (m)
    double vmax = 0, refBg = 0;   // brightest measurement and the background start it is judged against
    double floorN = 0, relN = 0;  // noise model: σ² = floor² + (rel·level)²
    int noiseDof = 0;
    int maxIterations = 0;
    explicit SurfaceFit(std::vector<Obs> o) : obs(std::move(o)) { sp.obs = &obs; }
    SurfaceFit(const SurfaceFit&) = delete;
    SurfaceFit& operator=(const SurfaceFit&) = delete;

    // Refits from the best solution; keeps the refit (with the whole history) when it evaluates.
    bool refit() {
        LmOutcome o = solveSurface(sp, best.params, maxIterations);
        if (!o.ok) return false;
        o.history.insert(o.history.begin(), best.history.begin(), best.history.end() - 1);
        best = std::move(o);
        return true;
    }
};

// Width start from log ratios of mid-level detectors; else the smallest detector spacing.
double startWidth(const std::vector<Obs>& obs, double bg0, double vmax) {
    const double A0 = vmax - bg0;
    std::vector<double> s2;
    for (const Obs& ob : obs) {
        if (ob.kind == Kind::AtMost) continue;
        const double f = (ob.value - bg0) / A0, r2 = ob.de * ob.de + ob.dn * ob.dn;
        if (f > 0.05 && f < 0.9 && r2 > 0) s2.push_back(r2 / (2 * std::log(1 / f)));
    }
    if (!s2.empty()) return std::sqrt(median(s2));
    std::vector<P2> pts;
    for (const Obs& ob : obs) pts.emplace_back(ob.de, ob.dn);
    const std::vector<double> nn = nearestNeighbourDistances(pts);
    return nn.empty() ? 1.0 : *std::min_element(nn.begin(), nn.end());
}

// Stage 3a. Background starts (0 or the lowest energy, and the lower quartile when it stands out)
// and the brightest measurement; positions re-centred on the centroid of the brightest half.
std::vector<double> backgroundStarts(const Layout& L, double fixedBg, SurfaceFit* f) {
    std::vector<double> vals;
    f->vmax = -INFINITY;
    for (const Obs& ob : f->obs)
        if (ob.kind != Kind::AtMost) {
            vals.push_back(ob.value);
            f->vmax = std::max(f->vmax, ob.value);
        }
    if (!L.background) return {fixedBg};
    std::sort(vals.begin(), vals.end());
    std::vector<double> starts = {std::min(0.0, vals.front())};
    const double q1 = vals[vals.size() / 4];
    if (vals.size() >= 20 && q1 - starts[0] > 0.02 * (f->vmax - starts[0])) starts.push_back(q1);
    return starts;
}

void centreOnBrightHalf(SurfaceFit* f) {
    double re = 0, rn = 0, sw = 0;
    const double half = f->refBg + 0.5 * (f->vmax - f->refBg);
    for (const Obs& ob : f->obs)
        if (ob.kind != Kind::AtMost && ob.value >= half) {
            const double w = ob.value - half + 1e-12 * (f->vmax - f->refBg);
            sw += w;
            re += w * ob.de;
            rn += w * ob.dn;
        }
    f->re = re / sw;
    f->rn = rn / sw;
    for (Obs& ob : f->obs) {
        ob.de -= f->re;
        ob.dn -= f->rn;
    }
}

// Stage 3b. Robust fits from every background start and widths 1, 0.5 and 2 times the start
// width, with a Cauchy loss so that a few dead or faulty detectors cannot bend the surface; the
// best is refitted once with σ scaled to the robust spread of its residuals. Returns the error.
std::string robustStart(const DetectorFitParams& params, const std::vector<double>& bgStarts, SurfaceFit* f) {
    const Layout& L = f->sp.L;
    const int np = L.count();
    const bool weighted = givenWeights(params);
    // First pass: a common σ of 5 % of the peak (only the censored terms feel its size); given
    // weights when the noise model is given.
    for (Obs& ob : f->obs) ob.sigma = 0.05 * (f->vmax - f->refBg);
    if (weighted)
        for (Obs& ob : f->obs) ob.sigma = std::max(sigmaOf(f->floorN, params.relativeNoise, ob.value), 1e-300);
    f->sp.robustC = params.outlierSigma > 0 ? 3.0 : 0.0;
    std::string lastFailure;
    for (double bg0 : bgStarts)
        for (double w : {1.0, 0.5, 2.0}) {
            Eigen::VectorXd p0(np);
            const double s0 = startWidth(f->obs, bg0, f->vmax) * w, a0 = 1.0 / (s0 * s0);
            if (L.elliptical)
                p0.head(6) << f->vmax - bg0, 0, 0, a0, 0, a0;
            else
                p0.head(4) << f->vmax - bg0, 0, 0, a0;
            if (L.background) p0(np - 1) = bg0;
            LmOutcome o = solveSurface(f->sp, p0, f->maxIterations);
            if (!o.ok) lastFailure = o.error;
            if (o.ok && (!f->best.ok || o.cost < f->best.cost)) f->best = std::move(o);
        }
    if (!f->best.ok)
        return "Gaussian surface fit failed from every start (widths 0.5, 1 and 2 times the spread of the bright "
               "detectors): " + (lastFailure.empty() ? std::string("the solver did not converge") : lastFailure);
    if (f->sp.robustC > 0) {
        std::vector<double> z;
        for (const Obs& ob : f->obs)
            if (ob.kind == Kind::Exact) z.push_back(std::fabs(ob.value - f->sp.model(f->best.params, ob.de, ob.dn)) / ob.sigma);
        const double scale = 1.4826 * median(z);
        if (scale > 0 && std::isfinite(scale) && !weighted) {
            for (Obs& ob : f->obs) ob.sigma *= scale;
            f->refit();
        }
    }
    return {};
}

// Stage 3c. Untriggered detectors far from the footprint (the surface below 1e-12 of its peak
// there) all say the same about the background: one term standing for all of them keeps large
// arrays fast.
void mergeFarBounds(double fixedBg, SurfaceFit* f) {
    double A, x0, y0, a, b, c, bg;
    unpack(f->sp.L, f->best.params, fixedBg, &A, &x0, &y0, &a, &b, &c, &bg);
    std::vector<Obs> kept;
    Obs far{0, 0, 0, Kind::AtMost, 0};
    far.count = 0;
    double farG = INFINITY;
    for (const Obs& ob : f->obs) {
        const double g = (f->sp.model(f->best.params, ob.de, ob.dn) - bg) / A;
        if (ob.kind != Kind::AtMost || g > 1e-12 || (far.count > 0 && ob.value != far.value)) {
            kept.push_back(ob);
            continue;
        }
        if (g < farG) {
            const double n = far.count;
            far = ob;
            far.count = n;
            farG = g;
        }
        far.count += 1;
    }
    if (far.count > 1) {
        kept.push_back(far);
        f->obs.swap(kept);
        f->refit();
    }
}

// Diagonal of the hat matrix J (JᵀJ)⁻¹ Jᵀ (zeros when JᵀJ is singular).
Eigen::VectorXd leverage(const Eigen::MatrixXd& J) {
    Eigen::VectorXd h = Eigen::VectorXd::Zero(J.rows());
    Eigen::MatrixXd cov;
    double rc = 0;
    if (covarianceFromJacobian(J, 1e-14, &cov, &rc))
        for (int i = 0; i < J.rows(); ++i) h(i) = J.row(i) * cov * J.row(i).transpose();
    return h;
}

// Stage 4a. Detectors inconsistent with the fit at p beyond outlierSigma robust σ are set aside:
// all of them in the first pass (on the robust fit), then one per pass. Keeps `h` in step with
// the observations. True when any was set aside.
bool setAsideOutliers(const DetectorFitParams& params, int pass, int maxOutliers, int informative, const Eigen::VectorXd& p,
                      SurfaceFit* f, Eigen::VectorXd* h, DetectorFitResult* res) {
    const std::vector<Obs>& obs = f->obs;
    const int np = f->sp.L.count();
    std::vector<double> z(obs.size(), 0.0), zExact;
    for (size_t k = 0; k < obs.size(); ++k) {
        const double m = f->sp.model(p, obs[k].de, obs[k].dn);
        const double lev = std::sqrt(1 - std::min((*h)(static_cast<int>(k)), 0.99));
        if (obs[k].kind == Kind::Exact) {
            z[k] = std::fabs(obs[k].value - m) / (obs[k].sigma * lev);
            zExact.push_back(z[k]);
        } else if (obs[k].kind == Kind::AtLeast) {
            z[k] = (obs[k].value - m) / obs[k].sigma;
        } else {
            z[k] = (m - obs[k].value) / obs[k].sigma;
        }
    }
    const double scale = std::max(1.4826 * median(zExact), 1.0);
    std::vector<size_t> order;
    for (size_t k = 0; k < obs.size(); ++k)
        if (z[k] / scale > params.outlierSigma) order.push_back(k);
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return z[i] > z[j]; });
    if (pass > 0 && order.size() > 1) order.erase(order.begin() + 1, order.end());
    std::vector<bool> drop(obs.size(), false);
    bool removed = false;
    for (size_t k : order) {
        if (res->outliers >= maxOutliers || informative - res->outliers - 1 < np + 2) break;
        const Obs& ob = obs[k];
        DetectorOutcome& o = res->detectors[ob.index];
        o.status = DetectorStatus::Outlier;
        o.reason = (ob.kind == Kind::Exact     ? "energy " + formatDouble(ob.value, 6)
                    : ob.kind == Kind::AtLeast ? "saturated at " + formatDouble(ob.value, 6)
                                               : "untriggered (at most " + formatDouble(ob.value, 6) + ")") +
                   " against " + formatDouble(f->sp.model(p, ob.de, ob.dn), 6) + " from the fit: " +
                   formatFixed(z[k] / scale, 1) + " robust sigma off, set aside (dead or faulty detector?)";
        ++res->outliers;
        drop[k] = true;
        removed = true;
    }
    if (removed) {
        std::vector<Obs> kept;
        std::vector<double> hk;
        for (size_t k = 0; k < obs.size(); ++k)
            if (!drop[k]) {
                kept.push_back(obs[k]);
                hk.push_back((*h)(static_cast<int>(k)));
            }
        f->obs.swap(kept);
        *h = Eigen::Map<Eigen::VectorXd>(hk.data(), static_cast<int>(hk.size()));
    }
    return removed;
}

// The noise scale k (σ → k·σ) that maximizes the whole likelihood at the model p: the
// measurements' normal densities (their leverage-corrected squared residuals u, in the order of
// the exact observations) and the censored detectors' probabilities Φ(±(m − bound)/kσ). The
// measurements alone give k = 1 (the estimate above); untriggered detectors listed as "at most
// the trigger level" hold σ down where the measurements alone would let it grow without bound
// (a broad surface on a negative background that every bound is content with). 1 without bounds.
double jointNoiseScale(const SurfaceFit& f, const Eigen::VectorXd& p, const std::vector<double>& u, double floor, double rel) {
    bool anyBound = false;
    for (const Obs& ob : f.obs) anyBound = anyBound || ob.kind != Kind::Exact;
    if (!anyBound) return 1;
    std::vector<double> sig, model;
    for (const Obs& ob : f.obs) {
        model.push_back(f.sp.model(p, ob.de, ob.dn));
        sig.push_back(std::max(sigmaOf(floor, rel, model.back()), 1e-300));
    }
    // The score: the derivative of the log-likelihood in t = ln k. A measurement contributes
    // u/s² − 1 (s = kσ); a censored detector, count·ln Φ(z) with z = ±(m − v)/s and dz/dt = −z,
    // contributes −count·z·φ(z)/Φ(z) (the ratio from logs: Φ underflows far in the tail).
    auto score = [&](double logk) {
        const double k = std::exp(logk);
        double d = 0;
        size_t e = 0;
        for (size_t i = 0; i < f.obs.size(); ++i) {
            const Obs& ob = f.obs[i];
            const double s = k * sig[i];
            if (ob.kind == Kind::Exact) {
                d += u[e++] / (s * s) - 1;
            } else {
                const double sign = ob.kind == Kind::AtLeast ? 1.0 : -1.0;
                const double z = sign * (model[i] - ob.value) / s;
                const double mills = std::exp(-0.5 * z * z - 0.9189385332046728 - logUpperTail(-z));  // φ(z)/Φ(z)
                d -= ob.count * z * mills;
            }
        }
        return d;
    };
    // The maximum over ln k in [ln 0.02, ln 50] (the likelihood is unimodal in k) where the score
    // changes sign, by bisection on its sign. The root of the score is found to the double's
    // resolution; a search on the likelihood's values (golden section) stops at about √ε ≈ 1e-8
    // relative, where those values stop differing, and its answer moved in the 8th digit between
    // CPUs (issue 26's golden file: the covariance, ∝ k², by 2.8e-8 with the dispatch held to SSE4).
    double a = std::log(0.02), b = std::log(50.0);
    if (score(a) <= 0) return std::exp(a);
    if (score(b) >= 0) return std::exp(b);
    for (int i = 0; i < 64 && b - a > 1e-15; ++i) {
        const double mid = 0.5 * (a + b);
        (score(mid) > 0 ? a : b) = mid;
    }
    return std::exp(0.5 * (a + b));
}

// Stage 4. Noise model and outliers, iterated with refits: residuals → (floor, relative) →
// weights, plain least squares from here on.
void refineNoiseAndOutliers(const DetectorFitParams& params, int informative, SurfaceFit* f, DetectorFitResult* res) {
    const bool given = givenNoise(params), weighted = givenWeights(params);
    const int np = f->sp.L.count();
    const int maxOutliers = params.outlierSigma > 0 ? std::max(1, informative / 5) : 0;
    for (int pass = 0; pass < 12; ++pass) {
        const Eigen::VectorXd p = f->best.params;
        Eigen::VectorXd h = leverage(f->best.jacobian);
        f->sp.robustC = 0;
        const bool removed =
            params.outlierSigma > 0 && setAsideOutliers(params, pass, maxOutliers, informative, p, f, &h, res);
        // Noise from the remaining measurements' residuals (leverage corrected).
        std::vector<double> u, level;
        for (size_t k = 0; k < f->obs.size(); ++k) {
            const Obs& ob = f->obs[k];
            if (ob.kind != Kind::Exact) continue;
            const double m = f->sp.model(p, ob.de, ob.dn), e = ob.value - m;
            u.push_back(e * e / (1 - std::min(h(static_cast<int>(k)), 0.99)));
            level.push_back(std::max(m, 0.0));
        }
        f->noiseDof = static_cast<int>(u.size()) - np;
        double newFloor = f->floorN, newRel = f->relN;
        if (!weighted && f->noiseDof >= 1) estimateNoise(u, level, !given, &newFloor, &newRel);
        if (!weighted && f->noiseDof < 1) {  // nothing to estimate from: keep the first pass's σ
            newFloor = f->obs.front().sigma;
            newRel = 0;
        }
        const double A = std::max(p(0), 1e-300);
        newFloor = std::max(newFloor, 1e-9 * A);
        const bool noiseSettled = pass > 0 && std::fabs(newFloor - f->floorN) <= 0.01 * f->floorN + 1e-12 * A &&
                                  std::fabs(newRel - f->relN) <= 0.01 * f->relN + 1e-6;
        if (!weighted && f->noiseDof >= 1) {
            const double k = jointNoiseScale(*f, p, u, newFloor, newRel);
            newFloor *= k;
            newRel *= k;
        }
        f->floorN = newFloor;
        f->relN = newRel;
        for (Obs& ob : f->obs) ob.sigma = std::max(sigmaOf(f->floorN, f->relN, f->sp.model(p, ob.de, ob.dn)), 1e-300);
        if (!f->refit()) break;
        if (noiseSettled && !removed && pass >= 2) break;
    }
}

// Stage 5. The final weights at the final model, the surface and the fit's figures.
void finalFigures(const DetectorFitParams& params, double fixedBg, SurfaceFit* f, DetectorFitResult* res) {
    const Layout& L = f->sp.L;
    for (Obs& ob : f->obs) ob.sigma = std::max(sigmaOf(f->floorN, f->relN, f->sp.model(f->best.params, ob.de, ob.dn)), 1e-300);
    {
        Eigen::VectorXd r;
        Eigen::MatrixXd J;
        if (f->sp.evaluate(f->best.params, &r, &J)) {
            f->best.residuals = r;
            f->best.jacobian = J;
            f->best.cost = r.squaredNorm();
        }
    }
    if (!f->best.converged) res->warnings.push_back("the surface fit stopped at the iteration limit before converging");
    GaussSurface& s = res->surface;
    double A, x0, y0, a, b, c, bg;
    unpack(L, f->best.params, fixedBg, &A, &x0, &y0, &a, &b, &c, &bg);
    s.amplitude = A;
    s.e0 = x0 + f->re;
    s.n0 = y0 + f->rn;
    s.a = a;
    s.b = b;
    s.c = c;
    s.background = bg;
    const Shape sh = shapeOf(a, b, c);
    s.sigmaMajor = sh.sigmaMajor;
    s.sigmaMinor = sh.sigmaMinor;
    s.orientationRad = sh.orientation;
    res->centreE = s.e0;
    res->centreN = s.n0;
    res->iterations = static_cast<int>(f->best.history.size()) - 1;
    for (const auto& hst : f->best.history) res->costPerIteration.push_back(hst.cost);
    res->used = 0;
    res->chi2 = f->best.cost;
    res->chi2Exact = 0;
    res->censored = 0;
    for (size_t k = 0; k < f->obs.size(); ++k) {
        if (f->obs[k].kind == Kind::Exact) {
            ++res->used;
            res->chi2Exact += f->best.residuals(static_cast<int>(k)) * f->best.residuals(static_cast<int>(k));
        } else {
            res->censored += static_cast<int>(f->obs[k].count);
        }
    }
    res->dof = res->used - L.count();
    const bool given = givenNoise(params), weighted = givenWeights(params);
    NoiseModelUsed& nm = res->noise;
    nm.source = params.noise;
    nm.floor = f->floorN;
    nm.relative = f->relN;
    nm.dof = weighted ? 0 : std::max(f->noiseDof, 0);
    if (weighted)
        nm.description = "given: floor " + formatDouble(f->floorN, 4) + ", relative " + formatDouble(f->relN, 4);
    else if (f->noiseDof >= 1)
        nm.description = std::string(given ? "unweighted, scale from the residuals" : "estimated from the residuals") + " of " +
                         std::to_string(res->used) + " measurements (" + std::to_string(f->noiseDof) +
                         " dof): floor " + formatDouble(f->floorN, 4) + ", relative " + formatDouble(f->relN, 4);
    else
        nm.description = "no degrees of freedom to estimate the noise: floor taken as 5 % of the peak, " + formatDouble(f->floorN, 4);
    res->paramNames = L.elliptical ? std::vector<std::string>{"amplitude", "e0_m", "n0_m", "a_per_m2", "b_per_m2", "c_per_m2"}
                                   : std::vector<std::string>{"amplitude", "e0_m", "n0_m", "a_per_m2"};
    if (L.background) res->paramNames.push_back("background");
}

// Stage 5b. Goodness of fit that knows the trigger: a detector that recorded its energy only
// because it exceeded the trigger level T holds a value drawn from the normal law above T, not
// from the whole law; near T its plain residual is biased upward (a false trigger from the
// background always stands ≥ T above it). Its normal score w = Φ⁻¹(P(y' ≤ y | y' > T)) is
// standard normal under the model; Σw² over the measurements is the χ² judged against χ²_ν,
// ν = scored measurements − parameters. Untruncated measurements (full reports) keep w = their
// residual. With T estimated as the lowest triggered energy, the detector that defines it is
// not scored.
void truncationAwareFit(const DetectorArray& array, const DetectorFitParams& params, double triggerLevel, const SurfaceFit& f,
                        DetectorFitResult* res) {
    res->chi2Gof = 0;
    int scored = 0;
    for (size_t k = 0; k < f.obs.size(); ++k) {
        const Obs& ob = f.obs[k];
        if (ob.kind != Kind::Exact) continue;
        const double z = -f.best.residuals(static_cast<int>(k));
        const bool truncated =
            std::isfinite(triggerLevel) && (params.triggerThreshold > 0 || array.detectors[ob.index].triggered == 1);
        double w = z;
        if (truncated) {
            if (!(ob.value > triggerLevel)) continue;
            const double m = ob.value + f.best.residuals(static_cast<int>(k)) * ob.sigma;
            w = normalScoreOfUpperTail(logUpperTail(z) - logUpperTail((triggerLevel - m) / ob.sigma));
        }
        res->chi2Gof += w * w;
        ++scored;
    }
    res->gofDof = scored - f.sp.L.count();
}

// σ of the noise model at the fitted background.
double backgroundSigma(const DetectorFitResult& res) {
    return sigmaOf(res.noise.floor, res.noise.relative, res.surface.background);
}

// Stage 6. Detectors that see the footprint: above the background by 3 noise σ and 1 % of the
// peak, or saturated (their positions).
std::vector<P2> seeingDetectors(const DetectorArray& array, DetectorFitResult* res) {
    const double sigmaBg = backgroundSigma(*res), bg = res->surface.background, A = res->surface.amplitude;
    std::vector<P2> pts;
    for (size_t i = 0; i < array.detectors.size(); ++i) {
        const Detector& d = array.detectors[i];
        const DetectorOutcome& o = res->detectors[i];
        if ((o.status == DetectorStatus::Used && d.energy - bg > std::max(3 * sigmaBg, 0.01 * A)) ||
            o.status == DetectorStatus::AtLeast)
            pts.emplace_back(d.e, d.n);
    }
    res->seeing = static_cast<int>(pts.size());
    return pts;
}

// Stage 7. Covariance of the parameters (scaled by χ²/dof when the given weights are only
// relative), the centre's 1σ and 95 % ellipses and the widths' σ. Returns the error.
std::string covarianceAndEllipses(const DetectorFitParams& params, const SurfaceFit& f, DetectorFitResult* res) {
    const Layout& L = f.sp.L;
    const int np = L.count();
    const bool given = givenNoise(params), weighted = givenWeights(params);
    Eigen::MatrixXd cov;
    double rcond = 0;
    if (!covarianceFromJacobian(f.best.jacobian, 1e-12, &cov, &rcond)) {
        std::string e = "the detectors do not determine the Gaussian surface (reciprocal condition " + formatDouble(rcond, 3) + ")";
        if (res->seeing <= 9) e += ": only " + std::to_string(res->seeing) + " detectors see the footprint";
        return e;
    }
    double scale = 1;
    const bool scaled = given && (!weighted || params.scaleByChi2);
    if (scaled && weighted) {
        if (res->dof > 0) {
            scale = res->chi2Exact / res->dof;
        } else {
            scale = NAN;
            res->warnings.push_back("as many parameters as measurements: the fit passes through every detector and its "
                                    "uncertainty cannot be estimated");
        }
    }
    res->covariance = cov * scale;
    // 95 % scale: χ²₂ with a known noise; with a noise scale estimated from ν dof, 2·F(2, ν).
    const bool estimatedScale = !weighted || params.scaleByChi2;
    const int nu = estimatedScale ? std::max(res->dof, 0) : 0;
    if (!estimatedScale)
        res->centreEllipse95Scale = std::sqrt(-2 * std::log(0.05));
    else if (nu >= 1)
        res->centreEllipse95Scale = std::sqrt(nu * (std::pow(0.05, -2.0 / nu) - 1));
    else
        res->centreEllipse95Scale = NAN;
    const Eigen::MatrixXd& C = res->covariance;
    res->centreEllipse = ellipseFromCovariance(C(1, 1), C(2, 2), C(1, 2));
    res->amplitudeSd = std::sqrt(C(0, 0));
    // σ of the widths by the delta method over (a, b, c).
    const double a = res->surface.a, b = res->surface.b, c = res->surface.c;
    const int ia = 3, ib = L.elliptical ? 4 : -1, ic = L.elliptical ? 5 : 3;
    Eigen::MatrixXd G(2, np);
    G.setZero();
    const double hh = 1e-6 * std::max(std::fabs(a), std::fabs(c));
    auto widths = [](double aa, double bb, double cc) {
        const Shape t = shapeOf(aa, bb, cc);
        return Eigen::Vector2d(t.sigmaMajor, t.sigmaMinor);
    };
    if (L.elliptical) {
        G.col(ia) = (widths(a + hh, b, c) - widths(a - hh, b, c)) / (2 * hh);
        G.col(ib) = (widths(a, b + hh, c) - widths(a, b - hh, c)) / (2 * hh);
        G.col(ic) = (widths(a, b, c + hh) - widths(a, b, c - hh)) / (2 * hh);
    } else {
        G.col(ia) = (widths(a + hh, 0, a + hh) - widths(a - hh, 0, a - hh)) / (2 * hh);
    }
    const Eigen::Matrix2d cw = G * C * G.transpose();
    res->sigmaMajorSd = sqrtVariance(cw(0, 0));
    res->sigmaMinorSd = sqrtVariance(cw(1, 1));
    return {};
}

// Stage 8. Per-detector model, residual and σ; warnings where a set-aside detector contradicts
// the fit; the warnings on outliers and on too few seeing detectors.
void detectorReport(const DetectorArray& array, const DetectorFitParams& params, DetectorFitResult* res) {
    const auto& det = array.detectors;
    double ss = 0;
    int nss = 0;
    for (size_t i = 0; i < det.size(); ++i) {
        DetectorOutcome& o = res->detectors[i];
        o.model = evalSurface(res->surface, det[i].e, det[i].n);
        if (o.status == DetectorStatus::Used || o.status == DetectorStatus::AtLeast || o.status == DetectorStatus::AtMost)
            o.sigma = sigmaOf(res->noise.floor, res->noise.relative, o.model);
        if (o.status == DetectorStatus::Used) {
            o.residual = det[i].energy - o.model;
            ss += o.residual * o.residual;
            ++nss;
        } else if (o.status == DetectorStatus::Untriggered && params.triggerThreshold > 0 &&
                   o.model > 2 * params.triggerThreshold) {
            res->warnings.push_back("detector " + det[i].id + " is untriggered but the fit predicts " +
                                    formatDouble(o.model, 4) + ", twice the trigger threshold");
        } else if (o.status == DetectorStatus::Saturated && std::isfinite(o.bound) && o.model < 0.8 * o.bound) {
            res->warnings.push_back("detector " + det[i].id + " is saturated but the fit predicts only " +
                                    formatDouble(o.model, 4));
        }
    }
    res->rmsResidual = nss ? std::sqrt(ss / nss) : NAN;
    if (res->outliers > 0)
        res->warnings.push_back(std::to_string(res->outliers) + " detector" + (res->outliers == 1 ? "" : "s") +
                                " inconsistent with the fit by more than " + formatDouble(params.outlierSigma, 3) +
                                " robust sigma set aside (see the detector report)");
    if (res->seeing < params.recommendedDetectors)
        res->warnings.push_back("only " + std::to_string(res->seeing) + " detectors see the footprint (paper 002 asks for at least " +
                                std::to_string(params.recommendedDetectors) + ")");
}

// Stage 9. Doubts: a centre was found, but is it to be trusted?
void judgeDoubts(const DetectorArray& array, const DetectorFitParams& params, const std::vector<P2>& seeingPts,
                 DetectorFitResult* res) {
    auto doubt = [res](const std::string& why) {
        res->doubtful = true;
        res->doubts.push_back(why);
    };
    const GaussSurface& s = res->surface;
    const double radius = 2 * s.sigmaMajor;  // 1/e² radius along the major axis
    // The array's extent (bounding-box diagonal) and its typical spacing (median nearest neighbour).
    std::vector<P2> arrayPts;
    double e0 = INFINITY, e1 = -INFINITY, n0 = INFINITY, n1 = -INFINITY;
    for (const auto& d : array.detectors) {
        arrayPts.emplace_back(d.e, d.n);
        e0 = std::min(e0, d.e);
        e1 = std::max(e1, d.e);
        n0 = std::min(n0, d.n);
        n1 = std::max(n1, d.n);
    }
    const double extent = std::hypot(e1 - e0, n1 - n0);
    const double spacing = median(nearestNeighbourDistances(arrayPts));
    const P2 centre(s.e0, s.n0);
    res->centreOutsideSeeingM = distanceOutsideHull(seeingPts, centre);
    res->centreOutsideArrayM = distanceOutsideHull(arrayPts, centre);
    if (givenWeights(params) && res->gofDof >= 1) {
        res->chi2Probability = chi2UpperTail(res->chi2Gof, res->gofDof);
        if (res->chi2Probability < 0.5 * params.chi2Probability || res->chi2Probability > 1 - 0.5 * params.chi2Probability)
            doubt("chi2/dof " + formatDouble(res->chi2Gof / res->gofDof, 4) + " on " + std::to_string(res->gofDof) +
                  " dof is far from 1 (P = " + formatDouble(res->chi2Probability, 3) +
                  "): the given noise model does not describe these detectors");
    }
    if (res->seeing == 0)
        doubt("no detector sees the footprint (none rises 3 noise sigma above the background)");
    else if (res->centreOutsideSeeingM > radius)
        doubt("the centre lies " + formatFixed(res->centreOutsideSeeingM, 2) + " m outside the detectors that see the footprint "
              "(more than its 1/e2 radius " + formatFixed(radius, 2) + " m)");
    if (res->centreOutsideArrayM > radius)
        doubt("the centre lies " + formatFixed(res->centreOutsideArrayM, 2) + " m outside the array (more than the footprint's "
              "1/e2 radius " + formatFixed(radius, 2) + " m)");
    const double k95 = res->centreEllipse95Scale;
    if (!std::isfinite(k95) || !std::isfinite(res->centreEllipse.semiMajor))
        doubt("the centre's uncertainty cannot be estimated (no degrees of freedom left)");
    else if (2 * k95 * res->centreEllipse.semiMajor > extent)
        doubt("the 95 % ellipse (" + formatFixed(2 * k95 * res->centreEllipse.semiMajor, 2) + " m across) is larger than the array (" +
              formatFixed(extent, 2) + " m)");
    if (4 * s.sigmaMajor > 2 * extent)
        doubt("the fitted footprint (1/e2 diameter " + formatFixed(4 * s.sigmaMajor, 2) + " m) is more than twice as wide "
              "as the array (" + formatFixed(extent, 2) + " m): its width is not determined");
    if (std::isfinite(spacing) && 4 * s.sigmaMinor < spacing)
        doubt("the fitted footprint (1/e2 diameter " + formatFixed(4 * s.sigmaMinor, 2) +
              " m across its minor axis) is narrower than the detector spacing (" + formatFixed(spacing, 2) + " m)");
    if (s.sigmaMajor > params.maxAxisRatio * s.sigmaMinor)
        doubt("the fitted footprint's axis ratio " + formatFixed(s.sigmaMajor / s.sigmaMinor, 2) + " exceeds " +
              formatDouble(params.maxAxisRatio, 3) + ": not a laser footprint's shape (a dead detector under the peak?)");
    const double sigmaBg = backgroundSigma(*res);
    if (!(s.amplitude > 3 * sigmaBg))
        doubt("the footprint's peak " + formatDouble(s.amplitude, 4) + " is less than 3 noise sigma (" + formatDouble(sigmaBg, 4) +
              ") above the background");
}

// Stage 10. Height at the centre from a plane through the surveyed detectors' heights, and the
// centre's latitude and longitude when the array was geographic.
void placeCentre(const DetectorArray& array, DetectorFitResult* res) {
    const GaussSurface& s = res->surface;
    std::vector<const Detector*> hs;
    for (const auto& d : array.detectors)
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
        res->centreH = qr.rank() == 3 ? qr.solve(y)(0) : y.mean();
    } else if (!hs.empty()) {
        double m = 0;
        for (auto* d : hs) m += d->h;
        res->centreH = m / hs.size();
    }
    if (array.geographic) {
        const LocalFrame frame(array.originLatDeg * kDeg, array.originLonDeg * kDeg, array.originH);
        const Geodetic g = ecefToGeodetic(frame.toEcef(Eigen::Vector3d(s.e0, s.n0, 0)));
        res->centreLatDeg = g.latRad / kDeg;
        res->centreLonDeg = g.lonRad / kDeg;
    }
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
    // 1. What each detector says: a measurement, "at least" (saturated), "at most" (untriggered), nothing.
    if (std::string e = judgeDetectors(array, params, &res.detectors); !e.empty()) {
        res.error = std::move(e);
        return res;
    }
    const UsedEnergies energies = usedEnergies(det, res.detectors);
    const double maxUsed =
        markUndeclaredClip(array, params, energies.max, &res) ? usedEnergies(det, res.detectors).max : energies.max;
    const double upperBound = params.triggerThreshold > 0 ? params.triggerThreshold
                              : std::isfinite(energies.minTriggered) ? energies.minTriggered
                                                                     : energies.min;
    Observations ob = observationsOf(det, params, maxUsed, upperBound, &res.detectors);
    // 2. The surface, and whether the measurements determine it.
    const int informative = ob.informative();
    const Layout L = chooseSurface(params, informative, &res.modelUsed);
    res.used = static_cast<int>(ob.obs.size());
    if (std::string e = checkDetermined(ob, det.size(), params, L.count()); !e.empty()) {
        res.error = std::move(e);
        return res;
    }
    // 3. Start: robust fits from several starts, far untriggered detectors merged into one term.
    SurfaceFit f(std::move(ob.obs));
    f.sp.L = L;
    f.sp.fixedBg = params.background;
    f.maxIterations = params.maxIterations;
    const std::vector<double> bgStarts = backgroundStarts(L, params.background, &f);
    f.refBg = bgStarts.back();
    if (!(f.vmax > f.refBg)) {
        res.error = "no detector has energy above the background";
        return res;
    }
    centreOnBrightHalf(&f);
    // A given relative noise without a floor: 0.1 % of it at the peak keeps zero and negative
    // energies (background detectors) finite in the fit.
    f.floorN = params.noiseFloor > 0 ? params.noiseFloor : 1e-3 * params.relativeNoise * (f.vmax - f.refBg);
    f.relN = params.relativeNoise;
    if (std::string e = robustStart(params, bgStarts, &f); !e.empty()) {
        res.error = std::move(e);
        return res;
    }
    mergeFarBounds(params.background, &f);
    // 4. Noise model and outliers, iterated with refits.
    refineNoiseAndOutliers(params, informative, &f, &res);
    // 5.–10. Figures, uncertainty, per-detector report, doubts, the centre's height and position.
    finalFigures(params, params.background, &f, &res);
    truncationAwareFit(array, params, upperBound, f, &res);
    const std::vector<P2> seeingPts = seeingDetectors(array, &res);
    if (std::string e = covarianceAndEllipses(params, f, &res); !e.empty()) {
        res.error = std::move(e);
        return res;
    }
    detectorReport(array, params, &res);
    judgeDoubts(array, params, seeingPts, &res);
    placeCentre(array, &res);
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

bool writeDetectorCentreCsv(const std::string& path, const DetectorFitResult& r, std::string* error) {
    auto fx = [](double v, int d) { return std::isfinite(v) ? formatFixed(v, d) : std::string(); };
    auto gx = [](double v) { return std::isfinite(v) ? formatDouble(v, 10) : std::string(); };
    const auto& s = r.surface;
    const auto& e = r.centreEllipse;
    const double k = r.centreEllipse95Scale;
    std::string doubts;
    for (const auto& d : r.doubts) doubts += (doubts.empty() ? "" : "; ") + d;
    const std::string csv =
        "centre_e_m,centre_n_m,sigma_e_m,sigma_n_m,cov_en_m2,ellipse_major_m,ellipse_minor_m,ellipse_deg,ellipse95_scale,"
        "ellipse95_major_m,ellipse95_minor_m,lat_deg,lon_deg,h_m,amplitude,amplitude_sd,sigma_major_m,sigma_major_sd_m,"
        "sigma_minor_m,sigma_minor_sd_m,orientation_deg,background,model,used,censored,outliers,seeing,dof,chi2,chi2_exact,"
        "chi2_gof,gof_dof,rms_residual,iterations,noise_source,noise_floor,noise_relative,noise_dof,doubtful,doubts\n" +
        fx(r.centreE, 4) + "," + fx(r.centreN, 4) + "," + fx(e.sigmaE, 4) + "," + fx(e.sigmaN, 4) + "," + gx(e.covEN) + "," +
        fx(e.semiMajor, 4) + "," + fx(e.semiMinor, 4) + "," + fx(e.orientationRad / kDeg, 3) + "," + fx(k, 4) + "," +
        fx(k * e.semiMajor, 4) + "," + fx(k * e.semiMinor, 4) + "," + fx(r.centreLatDeg, 9) + "," + fx(r.centreLonDeg, 9) + "," +
        fx(r.centreH, 3) + "," + gx(s.amplitude) + "," + gx(r.amplitudeSd) + "," + fx(s.sigmaMajor, 4) + "," +
        fx(r.sigmaMajorSd, 4) + "," + fx(s.sigmaMinor, 4) + "," + fx(r.sigmaMinorSd, 4) + "," +
        fx(s.orientationRad / kDeg, 3) + "," + gx(s.background) + "," + surfaceModelName(r.modelUsed) + "," +
        std::to_string(r.used) + "," + std::to_string(r.censored) + "," + std::to_string(r.outliers) + "," +
        std::to_string(r.seeing) + "," + std::to_string(r.dof) + "," + gx(r.chi2) + "," + gx(r.chi2Exact) + "," +
        gx(r.chi2Gof) + "," + std::to_string(r.gofDof) + "," + gx(r.rmsResidual) + "," + std::to_string(r.iterations) + "," +
        (r.noise.source == NoiseSource::Given ? "given" : "data") + "," + gx(r.noise.floor) + "," + gx(r.noise.relative) + "," +
        std::to_string(r.noise.dof) + "," + (r.doubtful ? "1" : "0") + "," + csvEscape(doubts) + "\n";
    return writeFileAtomic(path, csv, error);
}

bool writeDetectorReportCsv(const std::string& path, const DetectorArray& array, const DetectorFitResult& r,
                            std::string* error) {
    std::string s = "id,e_m,n_m,h_m,energy,status,reason,model,residual,bound,sigma\n";
    auto f = [](double v, int d) { return std::isfinite(v) ? formatFixed(v, d) : std::string(); };
    auto g = [](double v) { return std::isfinite(v) ? formatDouble(v, 8) : std::string(); };
    for (size_t i = 0; i < array.detectors.size() && i < r.detectors.size(); ++i) {
        const Detector& d = array.detectors[i];
        const DetectorOutcome& o = r.detectors[i];
        s += csvEscape(d.id) + "," + f(d.e, 3) + "," + f(d.n, 3) + "," + f(d.h, 3) + "," + g(d.energy) + "," +
             detectorStatusName(o.status) + "," + csvEscape(o.reason) + "," + g(o.model) + "," + g(o.residual) + "," +
             g(o.bound) + "," + g(o.sigma) + "\n";
    }
    return writeFileAtomic(path, s, error);
}

}  // namespace lwb::core::calib
