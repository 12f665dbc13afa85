#include "core/slr/postfit.hpp"

#include "core/slr/slr_params.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>

#include "core/common/text.hpp"

namespace lwb::core::slr {

namespace {

// Legendre polynomials P_0..P_d at u, into b[0..d].
inline void legendre(double u, int d, double* b) {
    b[0] = 1;
    if (d >= 1) b[1] = u;
    for (int k = 1; k < d; ++k) b[k + 1] = ((2 * k + 1) * u * b[k] - k * b[k - 1]) / (k + 1);
}

double trendAt(const std::vector<double>& c, double u) {
    double b[32];
    const int d = static_cast<int>(c.size()) - 1;
    legendre(u, d, b);
    double s = 0;
    for (int k = 0; k <= d; ++k) s += c[static_cast<size_t>(k)] * b[k];
    return s;
}

// Maximum of a Gaussian kernel density (Silverman bandwidth) on a binned grid.
double kernelPeak(const std::vector<double>& v, double mean, double sd) {
    const size_t n = v.size();
    if (n == 0) return NAN;
    if (n == 1 || !(sd > 0)) return mean;
    std::vector<double> s(v);
    const size_t q1 = n / 4, q3 = (3 * n) / 4;
    std::nth_element(s.begin(), s.begin() + static_cast<long>(q1), s.end());
    const double a = s[q1];
    std::nth_element(s.begin(), s.begin() + static_cast<long>(q3), s.end());
    const double iqr = s[q3] - a;
    double spread = sd;
    if (iqr > 0) spread = std::min(sd, iqr / 1.34);
    const double h = 0.9 * spread * std::pow(static_cast<double>(n), -0.2);
    if (!(h > 0)) return mean;
    const auto mm = std::minmax_element(v.begin(), v.end());
    const double lo = *mm.first - 3 * h, hi = *mm.second + 3 * h;
    double step = h / 4;
    size_t g = static_cast<size_t>(std::ceil((hi - lo) / step)) + 1;
    if (g > 4096) {
        g = 4096;
        step = (hi - lo) / 4095;
    }
    std::vector<double> counts(g, 0.0), dens(g, 0.0);
    for (double x : v) {  // linear binning
        const double f = (x - lo) / step;
        const size_t i = std::min(g - 2, static_cast<size_t>(std::max(0.0, std::floor(f))));
        const double w = std::clamp(f - static_cast<double>(i), 0.0, 1.0);
        counts[i] += 1 - w;
        counts[i + 1] += w;
    }
    const double sb = h / step;
    const long r = std::min<long>(static_cast<long>(g), static_cast<long>(std::ceil(4 * sb)));
    std::vector<double> kern(static_cast<size_t>(r) + 1);
    for (long j = 0; j <= r; ++j) kern[static_cast<size_t>(j)] = std::exp(-0.5 * (j / sb) * (j / sb));
    for (size_t i = 0; i < g; ++i) {
        if (counts[i] == 0) continue;
        const long ii = static_cast<long>(i);
        for (long j = std::max(0L, ii - r); j <= std::min(static_cast<long>(g) - 1, ii + r); ++j)
            dens[static_cast<size_t>(j)] += counts[i] * kern[static_cast<size_t>(std::labs(j - ii))];
    }
    size_t best = 0;
    for (size_t i = 1; i < g; ++i)
        if (dens[i] > dens[best]) best = i;
    // Parabolic refinement of the maximum.
    double x = static_cast<double>(best);
    if (best > 0 && best + 1 < g) {
        const double y0 = dens[best - 1], y1 = dens[best], y2 = dens[best + 1];
        const double den = y0 - 2 * y1 + y2;
        if (den < 0) x += 0.5 * (y0 - y2) / den;
    }
    return lo + x * step;
}

}  // namespace

double normalPointBinS(double km) {
    if (!std::isfinite(km) || km < 0) return NAN;
    if (km < 500) return 5;
    if (km < 800) return 15;
    if (km < 2000) return 30;
    if (km < 5000) return 60;
    if (km < 8000) return 120;
    if (km < 15000) return 180;
    return 300;
}

std::string validate(const PostfitParams& p) {
    if (std::string e = slrSchema().validate({ScreenParams{}, p}, "postfit."); !e.empty()) return e;
    // Run-time conditions, not parameter ranges: the altitude may come with the pass.
    if (p.normalPoints && p.binLengthS == 0 && !(p.altitudeKm > 0))
        return "give the normal-point bin length or the satellite altitude (km)";
    if (!std::isfinite(p.dayStartS)) return "day start must be finite";
    return {};
}

ResidualStats residualStats(const std::vector<double>& r) {
    ResidualStats s;
    s.n = static_cast<long long>(r.size());
    if (r.empty()) return s;
    const double n = static_cast<double>(r.size());
    double mean = 0;
    for (double v : r) mean += v;
    mean /= n;
    double m2 = 0, m3 = 0, m4 = 0;
    for (double v : r) {
        const double d = v - mean, d2 = d * d;
        m2 += d2;
        m3 += d2 * d;
        m4 += d2 * d2;
    }
    m2 /= n;
    m3 /= n;
    m4 /= n;
    s.mean = mean;
    s.rms = std::sqrt(m2);
    if (m2 > 0) {
        s.skew = m3 / std::pow(m2, 1.5);
        s.kurtosis = m4 / (m2 * m2) - 3;
    }
    s.peakMinusMean = kernelPeak(r, mean, s.rms) - mean;
    return s;
}

double evaluateTrend(const PostfitResult& r, double t) {
    if (r.coefficients.empty()) return NAN;
    return trendAt(r.coefficients, (t - r.tCenter) / r.tHalfSpan);
}

PostfitResult postfit(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint8_t>& use,
                      const std::vector<double>& tof, const PostfitParams& p, const Feedback* fb) {
    PostfitResult res;
    if (const std::string e = validate(p); !e.empty()) {
        res.error = e;
        return res;
    }
    const size_t n = t.size();
    if (oc.size() != n || (!use.empty() && use.size() != n) || (!tof.empty() && tof.size() != n)) {
        res.error = "epochs, O-C, mask and TOF differ in length";
        return res;
    }
    std::vector<uint8_t> used(n, 1);
    if (!use.empty()) used = use;
    for (size_t i = 0; i < n; ++i) {
        if (!used[i]) continue;
        if (!std::isfinite(t[i]) || !std::isfinite(oc[i]) || (!tof.empty() && !std::isfinite(tof[i]))) {
            res.error = "point " + std::to_string(i) + " has a non-finite epoch, O-C or TOF";
            return res;
        }
    }
    res.used = std::count(used.begin(), used.end(), uint8_t{1});
    if (res.used < 2) {
        res.error = "only " + std::to_string(res.used) + " accepted point(s): at least 2 are needed for a trend";
        return res;
    }
    double tMin = 1e308, tMax = -1e308;
    for (size_t i = 0; i < n; ++i)
        if (used[i]) {
            tMin = std::min(tMin, t[i]);
            tMax = std::max(tMax, t[i]);
        }
    res.tCenter = 0.5 * (tMin + tMax);
    res.tHalfSpan = tMax > tMin ? 0.5 * (tMax - tMin) : 1.0;
    int degree = p.degree;
    if (tMax == tMin && degree > 0) {
        res.warnings.push_back("all accepted epochs are equal: the trend is a constant");
        degree = 0;
    }
    res.kept = used;
    res.residuals.assign(n, NAN);
    const double k = p.rejectSigma;
    std::vector<double> basis(32);
    const int blockCols = 256;
    bool warnedDegree = false;
    for (int it = 1; it <= p.maxIterations; ++it) {
        res.iterations = it;
        const long long nk = std::count(res.kept.begin(), res.kept.end(), uint8_t{1});
        int d = degree;
        if (nk < 2 * (d + 1)) {
            d = std::max(0, static_cast<int>(nk / 2) - 1);
            if (d < degree && !warnedDegree) {
                warnedDegree = true;
                res.warnings.push_back("only " + std::to_string(nk) + " points: trend degree lowered from " +
                                       std::to_string(degree) + " to " + std::to_string(d));
            }
        }
        if (nk < 1) {
            res.error = "the rejection removed every point";
            return res;
        }
        // Normal equations in blocks (M += B Bᵀ), Legendre basis: well conditioned.
        const int m = d + 1;
        Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m, m);
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
        Eigen::MatrixXd B(m, blockCols);
        Eigen::VectorXd y(blockCols);
        int fill = 0;
        auto flush = [&]() {
            if (fill == 0) return;
            M.selfadjointView<Eigen::Lower>().rankUpdate(B.leftCols(fill));
            rhs.noalias() += B.leftCols(fill) * y.head(fill);
            fill = 0;
        };
        for (size_t i = 0; i < n; ++i) {
            if (!res.kept[i]) continue;
            legendre((t[i] - res.tCenter) / res.tHalfSpan, d, basis.data());
            for (int j = 0; j < m; ++j) B(j, fill) = basis[static_cast<size_t>(j)];
            y(fill) = oc[i];
            if (++fill == blockCols) flush();
        }
        flush();
        const Eigen::MatrixXd Ms = M.selfadjointView<Eigen::Lower>();
        Eigen::VectorXd c = Ms.ldlt().solve(rhs);
        if (!c.allFinite()) c = Ms.completeOrthogonalDecomposition().solve(rhs);
        res.degree = d;
        res.coefficients.assign(c.data(), c.data() + m);
        double ss = 0;
        for (size_t i = 0; i < n; ++i) {
            if (!used[i]) continue;  // the others get their residual after the loop
            res.residuals[i] = oc[i] - trendAt(res.coefficients, (t[i] - res.tCenter) / res.tHalfSpan);
            if (res.kept[i]) ss += res.residuals[i] * res.residuals[i];
        }
        res.sigmaS = std::sqrt(ss / static_cast<double>(nk));
        if (cancelled(fb)) {
            res.error = "cancelled";
            return res;
        }
        if (k == 0) break;
        bool changed = false;
        const double lim = k * res.sigmaS;
        for (size_t i = 0; i < n; ++i) {
            if (!used[i]) continue;
            const uint8_t keep = std::fabs(res.residuals[i]) <= lim;
            if (keep != res.kept[i]) {
                res.kept[i] = keep;
                changed = true;
            }
        }
        if (!changed) break;
        if (it == p.maxIterations) {
            res.converged = false;
            res.warnings.push_back("the " + formatDouble(k, 3) + "-sigma rejection did not settle in " +
                                   std::to_string(p.maxIterations) + " iterations");
        }
    }
    for (size_t i = 0; i < n; ++i)
        if (!used[i]) res.residuals[i] = oc[i] - trendAt(res.coefficients, (t[i] - res.tCenter) / res.tHalfSpan);
    std::vector<double> kr;
    for (size_t i = 0; i < n; ++i)
        if (res.kept[i]) kr.push_back(res.residuals[i]);
    res.rejected = res.used - static_cast<long long>(kr.size());
    if (kr.empty()) {
        res.error = "the rejection removed every point";
        return res;
    }
    res.stats = residualStats(kr);

    // Normal points.
    res.binLengthS = p.binLengthS > 0 ? p.binLengthS : normalPointBinS(p.altitudeKm);
    res.minPointsPerBin = p.minPointsPerBin > 0 ? p.minPointsPerBin : (p.daylight ? 6 : 3);
    if (p.normalPoints) {
        const double L = res.binLengthS;
        std::vector<uint32_t> idx;
        for (size_t i = 0; i < n; ++i)
            if (res.kept[i]) idx.push_back(static_cast<uint32_t>(i));
        std::stable_sort(idx.begin(), idx.end(), [&](uint32_t a, uint32_t b) { return t[a] < t[b]; });
        auto binOf = [&](double x) { return static_cast<long long>(std::floor((x - p.dayStartS) / L)); };
        std::vector<double> br;
        for (size_t a = 0; a < idx.size();) {
            const long long bin = binOf(t[idx[a]]);
            size_t b = a;
            while (b < idx.size() && binOf(t[idx[b]]) == bin) ++b;
            const int cnt = static_cast<int>(b - a);
            if (cnt < res.minPointsPerBin) {
                ++res.binsTooSmall;
                a = b;
                continue;
            }
            double meanT = 0;
            br.clear();
            for (size_t j = a; j < b; ++j) {
                meanT += t[idx[j]];
                br.push_back(res.residuals[idx[j]]);
            }
            meanT /= cnt;
            uint32_t ep = idx[a];
            for (size_t j = a; j < b; ++j)
                if (std::fabs(t[idx[j]] - meanT) < std::fabs(t[ep] - meanT)) ep = idx[j];
            const ResidualStats bs = residualStats(br);
            NormalPoint np;
            np.epochS = t[ep];
            np.secondsOfDay = t[ep] - p.dayStartS;
            np.binStartS = p.dayStartS + static_cast<double>(bin) * L;
            np.windowS = L;
            np.points = cnt;
            np.meanResidualS = bs.mean;
            np.ocS = oc[ep] - res.residuals[ep] + bs.mean;  // trend(t_j) + mean residual
            if (!tof.empty()) np.tofS = tof[ep] - res.residuals[ep] + bs.mean;
            np.rmsPs = bs.rms * 1e12;
            np.skew = bs.skew;
            np.kurtosis = bs.kurtosis;
            np.peakMinusMeanPs = bs.peakMinusMean * 1e12;
            np.returnRatePct = p.fireRateHz > 0 ? 100.0 * cnt / (p.fireRateHz * L) : NAN;
            np.pointIndex = ep;
            res.normalPoints.push_back(np);
            a = b;
        }
        if (res.normalPoints.empty())
            res.warnings.push_back("no bin reaches " + std::to_string(res.minPointsPerBin) + " points: no normal point");
    }
    res.ok = true;
    return res;
}

}  // namespace lwb::core::slr
