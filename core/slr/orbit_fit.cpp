#include "core/slr/orbit_fit.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "core/common/golden.hpp"
#include "core/slr/oc.hpp"

namespace lwb::core::slr {

namespace {

double keplerRadius(double n) { return std::cbrt(kEarthGm / (n * n)); }
double keplerMotion(double r) { return std::sqrt(kEarthGm / (r * r * r)); }

// The model's state: the orbit's radius and mean motion, its frame (columns: the satellite's
// direction at the pass's middle epoch, its direction of motion there, the orbit's normal), the
// range bias. The station is given (its ECEF position stands for its position in the inertial
// frame of the pass's middle epoch: the frame's longitude is free).
struct Orbit {
    double radius = 0, motion = 0, bias = 0;
    Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
};

// Parameter ids: 0 radius (Kepler's rate following it), 1–3 rotations of the frame about the
// axes, 4 bias.
class Model {
public:
    Model(const CircularOrbitParams& p, std::vector<int> ids) : p_(p), ids_(std::move(ids)) {}

    int count() const { return static_cast<int>(ids_.size()); }

    // The central-difference step of parameter j (m, rad, s).
    double stepSize(int j) const {
        static constexpr double kSteps[5] = {1.0, 1e-7, 1e-7, 1e-7, 1e-12};
        return kSteps[ids_[static_cast<size_t>(j)]];
    }

    Orbit step(const Orbit& o, const Eigen::VectorXd& d) const {
        Orbit q = o;
        Eigen::Vector3d rv = Eigen::Vector3d::Zero();
        for (size_t j = 0; j < ids_.size(); ++j) {
            const double v = d(static_cast<Eigen::Index>(j));
            switch (ids_[j]) {
                case 0:
                    q.radius += v;
                    q.motion = keplerMotion(q.radius);
                    break;
                case 4: q.bias += v; break;
                default: rv(ids_[j] - 1) = v; break;
            }
        }
        if (rv.norm() > 0) q.frame = Eigen::AngleAxisd(rv.norm(), rv.normalized()).toRotationMatrix() * o.frame;
        return q;
    }

    void tofs(const Orbit& o, const std::vector<double>& s, std::vector<double>* out) const {
        const Eigen::Vector3d& st = p_.stationEcef;
        out->resize(s.size());
        for (size_t i = 0; i < s.size(); ++i) {
            const double a = o.motion * s[i], e = kEarthRotationRate * s[i], ce = std::cos(e), se = std::sin(e);
            const Eigen::Vector3d sat = o.radius * (std::cos(a) * o.frame.col(0) + std::sin(a) * o.frame.col(1));
            const Eigen::Vector3d sta(ce * st.x() - se * st.y(), se * st.x() + ce * st.y(), st.z());
            (*out)[i] = 2.0 * (sat - sta).norm() / kSpeedOfLight + o.bias;
        }
    }

private:
    const CircularOrbitParams& p_;
    std::vector<int> ids_;
};

struct Data {
    std::vector<double> s, tof, w;
};

double weightedSsr(const Model& m, const Orbit& o, const Data& d) {
    std::vector<double> f;
    m.tofs(o, d.s, &f);
    double ss = 0;
    for (size_t i = 0; i < d.s.size(); ++i)
        if (d.w[i] > 0) ss += d.w[i] * (d.tof[i] - f[i]) * (d.tof[i] - f[i]);
    return ss;
}

// The model's Jacobian at `o` (central differences), each row times sw (none: 1).
Eigen::MatrixXd jacobian(const Model& m, const Orbit& o, const std::vector<double>& s, const Eigen::VectorXd* sw = nullptr) {
    const int k = m.count();
    Eigen::MatrixXd J(static_cast<Eigen::Index>(s.size()), k);
    std::vector<double> fu, fd;
    for (int j = 0; j < k; ++j) {
        const double h = m.stepSize(j);
        Eigen::VectorXd dv = Eigen::VectorXd::Zero(k);
        dv(j) = h;
        m.tofs(m.step(o, dv), s, &fu);
        dv(j) = -h;
        m.tofs(m.step(o, dv), s, &fd);
        for (size_t i = 0; i < s.size(); ++i) {
            const Eigen::Index r = static_cast<Eigen::Index>(i);
            J(r, j) = (sw ? (*sw)(r) : 1.0) * (fu[i] - fd[i]) / (2 * h);
        }
    }
    return J;
}

// Levenberg–Marquardt from `o`: central-difference Jacobian, columns scaled to unit norm, the
// damped step solved as the least-squares problem [J; sqrt(lambda) I] dz = [r; 0] by an
// orthogonal factorisation (the normal equations would square a condition number of 1e8).
Orbit levenbergMarquardt(const Model& m, Orbit o, const Data& d, int iterations, double* ssrOut) {
    const int k = m.count();
    const Eigen::Index n = static_cast<Eigen::Index>(d.s.size());
    double ssr = weightedSsr(m, o, d), lambda = 1e-3;
    std::vector<double> f;
    for (int it = 0; it < iterations; ++it) {
        Eigen::VectorXd r(n), sw(n);
        m.tofs(o, d.s, &f);
        for (Eigen::Index i = 0; i < n; ++i) {
            sw(i) = std::sqrt(std::max(0.0, d.w[static_cast<size_t>(i)]));
            r(i) = sw(i) * (d.tof[static_cast<size_t>(i)] - f[static_cast<size_t>(i)]);
        }
        const Eigen::MatrixXd J = jacobian(m, o, d.s, &sw);
        Eigen::VectorXd scale = J.colwise().norm().transpose();
        for (int j = 0; j < k; ++j)
            if (!(scale(j) > 0)) scale(j) = 1;
        Eigen::MatrixXd aug(n + k, k);
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + k);
        aug.topRows(n) = J * scale.cwiseInverse().asDiagonal();
        rhs.head(n) = r;
        bool improved = false, converged = false;
        for (int tries = 0; tries < 12 && !improved; ++tries) {
            aug.bottomRows(k) = std::sqrt(lambda) * Eigen::MatrixXd::Identity(k, k);
            const Eigen::VectorXd step = aug.colPivHouseholderQr().solve(rhs).cwiseQuotient(scale);
            if (!step.allFinite()) break;
            const Orbit q = m.step(o, step);
            const double qs = q.radius > 0 ? weightedSsr(m, q, d) : INFINITY;
            if (qs < ssr) {
                converged = ssr - qs <= 1e-10 * ssr;
                o = q;
                ssr = qs;
                lambda = std::max(lambda / 4, 1e-16);
                improved = true;
            } else {
                lambda *= 8;
            }
        }
        if (!improved || converged) break;
    }
    *ssrOut = ssr;
    return o;
}

// The start for a mean motion n (the radius Kepler's for it): rho^2 = R^2 + |S|^2
// − 2 sat . S(s) is linear in the in-plane vectors A = R a and B = R b once the station S is
// placed; their least-squares values (weights making it least squares in the range) projected
// onto the nearest orthonormal pair.
Orbit linearStart(const Eigen::Vector3d& st, double n, const Data& d) {
    Orbit o;
    o.radius = keplerRadius(n);
    o.motion = n;
    const double c0 = o.radius * o.radius + st.squaredNorm();
    const Eigen::Index rows = static_cast<Eigen::Index>(d.s.size());
    Eigen::MatrixXd X(rows, 6);
    Eigen::VectorXd y(rows);
    for (Eigen::Index i = 0; i < rows; ++i) {
        const size_t u = static_cast<size_t>(i);
        const double rho = 0.5 * kSpeedOfLight * d.tof[u], sw = d.w[u] > 0 ? std::sqrt(d.w[u]) / (2 * rho) : 0.0;
        const double e = kEarthRotationRate * d.s[u], ce = std::cos(e), se = std::sin(e);
        const Eigen::Vector3d S(ce * st.x() - se * st.y(), se * st.x() + ce * st.y(), st.z());
        const double c = std::cos(n * d.s[u]), sn = std::sin(n * d.s[u]);
        X.row(i) << S.x() * c, S.y() * c, S.z() * c, S.x() * sn, S.y() * sn, S.z() * sn;
        X.row(i) *= -2 * sw;
        y(i) = sw * (rho * rho - c0);
    }
    const Eigen::VectorXd th = X.completeOrthogonalDecomposition().solve(y);
    Eigen::MatrixXd ab(3, 2);
    ab.col(0) = th.segment<3>(0);
    ab.col(1) = th.segment<3>(3);
    if (!ab.allFinite() || ab.norm() == 0) ab << 1, 0, 0, 1, 0, 0;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(ab, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::MatrixXd q = svd.matrixU() * svd.matrixV().transpose();
    const Eigen::Vector3d a = q.col(0), b = q.col(1);
    o.frame.col(0) = a;
    o.frame.col(1) = b;
    o.frame.col(2) = a.cross(b);
    return o;
}

double madAboutZero(const std::vector<double>& r, const std::vector<double>& w) {
    std::vector<double> a;
    for (size_t i = 0; i < r.size(); ++i)
        if (w.empty() || w[i] > 0) a.push_back(std::fabs(r[i]));
    if (a.empty()) return NAN;
    const size_t mid = a.size() / 2;
    std::nth_element(a.begin(), a.begin() + static_cast<long>(mid), a.end());
    double med = a[mid];
    if (a.size() % 2 == 0) med = 0.5 * (med + *std::max_element(a.begin(), a.begin() + static_cast<long>(mid)));
    return 1.4826 * med;
}

// The search: the orientation and bias fitted at every n of a grid within 20 % of the pass's
// apparent rate (the Earth's turning makes it differ from the orbit's by up to 7 %, and a noisy
// arc's rate is itself a few per cent off), 0.4 % apart; the three best local minima in n
// refined by golden section, 20 steps (each trial's orientation and bias from its linear start
// and from the best so far, the lower kept).
Orbit searchOrbit(const CircularOrbitParams& p, const Data& d, double* ssrOut) {
    const Model inner(p, {1, 2, 3, 4});
    Orbit best;
    double bestSsr = INFINITY;
    constexpr int kHalf = 50;
    constexpr double kStep = 0.004;  // (0.8 % steps: 15 NPs beyond the bound tolerance instead of 11)
    std::vector<std::pair<double, double>> row;  // (n, ssr)
    for (int k = -kHalf; k <= kHalf; ++k) {
        const double n = p.arcRate * (1 + kStep * k);
        double ssr = INFINITY;
        const Orbit f = levenbergMarquardt(inner, linearStart(p.stationEcef, n, d), d, 100, &ssr);
        row.emplace_back(n, ssr);
        if (ssr < bestSsr) bestSsr = ssr, best = f;
    }
    std::vector<std::pair<double, double>> minima;
    for (size_t i = 0; i < row.size(); ++i)
        if ((i == 0 || row[i].second <= row[i - 1].second) && (i + 1 == row.size() || row[i].second <= row[i + 1].second))
            minima.push_back(row[i]);
    std::sort(minima.begin(), minima.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    if (minima.size() > 3) minima.resize(3);
    for (const auto& m : minima) {
        Orbit warm = best;
        auto trial = [&](double n) {
            double r1 = INFINITY, r2 = INFINITY;
            const Orbit f1 = levenbergMarquardt(inner, linearStart(p.stationEcef, n, d), d, 100, &r1);
            Orbit w0 = warm;
            w0.motion = n;
            w0.radius = keplerRadius(n);
            const Orbit f2 = levenbergMarquardt(inner, w0, d, 100, &r2);
            const double r = std::min(r1, r2);
            if (r < bestSsr) bestSsr = r, best = r1 <= r2 ? f1 : f2, warm = best;
            return r;
        };
        goldenSection(m.first - p.arcRate * kStep, m.first + p.arcRate * kStep, 20, 0.0, trial);
    }
    *ssrOut = bestSsr;
    return best;
}

// The model refined on every point from `best` (and the robust reweighting), as a result.
CircularOrbitResult finish(const CircularOrbitParams& p, const Model& model, Orbit best, const Data& all) {
    CircularOrbitResult res;
    const size_t n = all.s.size();
    const int k = model.count();
    double ssr = INFINITY;
    best = levenbergMarquardt(model, best, all, p.maxIterations, &ssr);
    std::vector<double> r(n), f;
    auto residuals = [&] {
        model.tofs(best, all.s, &f);
        for (size_t i = 0; i < n; ++i) r[i] = all.tof[i] - f[i];
    };
    residuals();
    // Tukey bisquare reweighting (c = 4.685 robust sigma) of the prior weights.
    Data robust = all;
    for (int step = 0; step < p.robustSteps; ++step) {
        const double sc = madAboutZero(r, robust.w);
        if (!(sc > 0)) break;
        size_t left = 0;
        std::vector<double> w(n);
        for (size_t i = 0; i < n; ++i) {
            const double u = r[i] / (4.685 * sc);
            w[i] = all.w[i] > 0 && std::fabs(u) < 1 ? all.w[i] * (1 - u * u) * (1 - u * u) : 0.0;
            left += w[i] > 0;
        }
        if (static_cast<int>(left) < k + 3) break;
        robust.w = std::move(w);  // (the weights of the fit the residuals come from: the hat's below)
        best = levenbergMarquardt(model, best, robust, p.maxIterations, &ssr);
        residuals();
    }
    const double rs = p.stationEcef.norm();
    if (!(best.radius > rs + 150e3 && best.radius < 5 * rs) || !(best.motion > 0)) {
        res.error = "the fitted orbit is not a satellite's (radius " + std::to_string(best.radius / 1e3) + " km)";
        return res;
    }
    res.radiusM = best.radius;
    res.meanMotion = best.motion;
    res.biasS = best.bias;
    res.parameters = k;
    res.residualS = r;
    if (n <= kMaxOrbitHatPoints)
        res.hat = leastSquaresHat(jacobian(model, best, all.s), Eigen::Map<const Eigen::VectorXd>(robust.w.data(), robust.w.size()));
    res.scaleS = madAboutZero(r, {});
    res.ok = std::isfinite(res.scaleS);
    if (!res.ok) res.error = "the circular orbit's residuals are not finite";
    return res;
}

}  // namespace

std::vector<double> leastSquaresHat(const Eigen::MatrixXd& J, const Eigen::VectorXd& w) {
    const Eigen::Index n = J.rows();
    std::vector<double> out(static_cast<size_t>(n * n), 0.0);
    if (w.size() != n || n == 0) return out;
    const Eigen::VectorXd sw = w.cwiseMax(0.0).cwiseSqrt();
    // S = J D pinv(√W J D) √W, D scaling the columns to one norm (parameters in metres, radians
    // and seconds); a rank-deficient J, a sloppy model's, gives its pseudo-inverse's hat.
    Eigen::MatrixXd M = sw.asDiagonal() * J;
    Eigen::VectorXd d = M.colwise().norm().transpose();
    for (Eigen::Index j = 0; j < d.size(); ++j) d(j) = d(j) > 0 ? 1.0 / d(j) : 0.0;
    M = M * d.asDiagonal();
    const Eigen::MatrixXd S = J * d.asDiagonal() * M.completeOrthogonalDecomposition().pseudoInverse() * sw.asDiagonal();
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(out.data(), n, n) = S;
    return out;
}

CircularOrbitResult fitCircularOrbit(const std::vector<double>& s, const std::vector<double>& tofS,
                                     const std::vector<double>& wIn, const CircularOrbitParams& p) {
    auto fail = [](const std::string& why) {
        CircularOrbitResult r;
        r.error = why;
        return r;
    };
    try {
        const size_t n = s.size();
        const Data all{s, tofS, wIn.empty() ? std::vector<double>(n, 1.0) : wIn};
        if (tofS.size() != n || all.w.size() != n) return fail("epochs, times of flight and weights differ in length");
        const Model model(p, {0, 1, 2, 3, 4});
        size_t used = 0;
        for (double v : all.w) used += v > 0;
        if (static_cast<int>(used) < model.count() + 3)
            return fail("too few points for a circular orbit (" + std::to_string(used) + ")");
        if (!(p.arcRate > 0) || !std::isfinite(p.arcRate)) return fail("no rate to start from");
        if (!(p.stationEcef.norm() > 6.3e6 && p.stationEcef.norm() < 6.4e6)) return fail("no station position");
        // The search on at most 300 points (evenly taken), then the whole model on every point.
        Data sub;
        const size_t stride = std::max<size_t>(1, (n + 299) / 300);
        for (size_t i = 0; i < n; i += stride) {
            sub.s.push_back(s[i]);
            sub.tof.push_back(tofS[i]);
            sub.w.push_back(all.w[i]);
        }
        double ssr = INFINITY;
        const Orbit found = searchOrbit(p, sub, &ssr);
        if (!std::isfinite(ssr)) return fail("the circular orbit did not fit");
        return finish(p, model, found, all);
    } catch (const std::exception& e) {
        return fail(std::string("internal error: ") + e.what());
    }
}

}  // namespace lwb::core::slr
