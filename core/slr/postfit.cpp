#include "core/slr/postfit.hpp"

#include "core/slr/slr_params.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>

#include "core/common/text.hpp"
#include "core/slr/screen_follow.hpp"
#include "core/slr/solar.hpp"

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
    SlrParams sp;
    sp.postfit = p;
    if (std::string e = slrSchema().validate(sp, "postfit."); !e.empty()) return e;
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
    s.mean = mean;
    if (r.size() < 2) {
        s.peakMinusMean = 0;
        return s;
    }
    // ILRS: rms with n − 1, the third and fourth moments over n, scaled by that rms.
    const double var = m2 / (n - 1);
    s.rms = std::sqrt(var);
    if (var > 0) {
        s.skew = (m3 / n) / std::pow(var, 1.5);
        s.kurtosis = (m4 / n) / (var * var) - 3;
    }
    s.peakMinusMean = kernelPeak(r, mean, s.rms) - mean;
    return s;
}

double bestExpectedF1Band(double sigmaS, double signal, double density) {
    if (!(sigmaS > 0) || !(signal > 0) || !std::isfinite(sigmaS)) return NAN;
    if (!(density > 0)) return INFINITY;
    double best = NAN, bestF1 = -1;
    for (int k = 150; k <= 600; ++k) {
        const double w = sigmaS * k / 100.0;
        const double s = signal * std::erf(w / (sigmaS * std::sqrt(2.0)));
        const double f1 = 2 * s / (s + 2 * w * density + signal);
        if (f1 > bestF1) {
            bestF1 = f1;
            best = w;
        }
    }
    return best;
}

namespace {
const TrendSegment* segmentFor(const std::vector<TrendSegment>& segs, double t) {
    if (segs.empty()) return nullptr;
    const TrendSegment* best = &segs.front();
    double bestD = 1e308;
    for (const TrendSegment& g : segs) {
        const double d = t < g.tStart ? g.tStart - t : t > g.tEnd ? t - g.tEnd : 0;
        if (d < bestD) {
            bestD = d;
            best = &g;
        }
    }
    return best;
}
// Uniform cubic B-spline with K intervals over [a, b]: the index of the first of the four
// non-zero coefficients at t and their basis values.
inline int splineBasis(double a, double b, int K, double t, double* w) {
    const double h = (b - a) / K;
    const double x = h > 0 ? (t - a) / h : 0;
    const int i = std::clamp(static_cast<int>(std::floor(x)), 0, K - 1);
    const double u = x - i, u2 = u * u, u3 = u2 * u;
    w[0] = (1 - u) * (1 - u) * (1 - u) / 6;
    w[1] = (3 * u3 - 6 * u2 + 4) / 6;
    w[2] = (-3 * u3 + 3 * u2 + 3 * u + 1) / 6;
    w[3] = u3 / 6;
    return i;
}
double segmentAt(const TrendSegment& g, double t) {
    if (g.knots > 0) {
        double w[4];
        const int i = splineBasis(g.tStart, g.tEnd, g.knots, t, w);
        return g.coefficients[i] * w[0] + g.coefficients[i + 1] * w[1] + g.coefficients[i + 2] * w[2] +
               g.coefficients[i + 3] * w[3];
    }
    return trendAt(g.coefficients, (t - g.tCenter) / g.tHalfSpan);
}
}  // namespace

double evaluateTrend(const PostfitResult& r, double t) {
    if (const TrendSegment* g = segmentFor(r.segments, t)) return segmentAt(*g, t);
    if (r.coefficients.empty()) return NAN;
    return trendAt(r.coefficients, (t - r.tCenter) / r.tHalfSpan);
}

namespace {
// trendAt(c, (t[i] − centre) / halfSpan) for every i, eight points at a time: the same
// operations in the same order for each point (so the same values), but eight independent
// recurrences in flight instead of one chain of divisions.
void polynomialMany(const std::vector<double>& c, double centre, double halfSpan, const double* t, size_t n, double* out) {
    constexpr size_t B = 8;
    const int d = static_cast<int>(c.size()) - 1;
    double u[B], b0[B], b1[B], b2[B], s[B];
    for (size_t a = 0; a < n; a += B) {
        const size_t m = std::min(B, n - a);
        for (size_t j = 0; j < m; ++j) {
            u[j] = (t[a + j] - centre) / halfSpan;
            b0[j] = 1;
            s[j] = 0;
            s[j] += c[0] * b0[j];
        }
        if (d >= 1)
            for (size_t j = 0; j < m; ++j) {
                b1[j] = u[j];
                s[j] += c[1] * b1[j];
            }
        for (int k = 1; k < d; ++k) {
            for (size_t j = 0; j < m; ++j) {
                b2[j] = ((2 * k + 1) * u[j] * b1[j] - k * b0[j]) / (k + 1);
                s[j] += c[static_cast<size_t>(k + 1)] * b2[j];
                b0[j] = b1[j];
                b1[j] = b2[j];
            }
        }
        for (size_t j = 0; j < m; ++j) out[a + j] = s[j];
    }
}
}  // namespace

void evaluateTrendMany(const PostfitResult& r, const double* t, size_t n, double* out) {
    const bool onePolynomial = r.segments.size() == 1 && r.segments[0].knots == 0 && !r.segments[0].coefficients.empty();
    if (onePolynomial) {
        const TrendSegment& g = r.segments[0];
        polynomialMany(g.coefficients, g.tCenter, g.tHalfSpan, t, n, out);
    } else if (r.segments.empty() && !r.coefficients.empty()) {
        polynomialMany(r.coefficients, r.tCenter, r.tHalfSpan, t, n, out);
    } else {
        for (size_t i = 0; i < n; ++i) out[i] = evaluateTrend(r, t[i]);
    }
}

namespace {

// A stretch of the used points without a long gap: [a, b) in the time order, and its trend.
struct Seg {
    size_t a, b;
    TrendSegment trend;
};

// Stage 1: the inputs' lengths and values; *used the points to fit (all when `use` is empty).
bool checkPostfitInputs(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint8_t>& use,
                        const std::vector<double>& tof, const PostfitParams& p, std::vector<uint8_t>* used,
                        PostfitResult* res) {
    if (const std::string e = validate(p); !e.empty()) {
        res->error = e;
        return false;
    }
    const size_t n = t.size();
    if (oc.size() != n || (!use.empty() && use.size() != n) || (!tof.empty() && tof.size() != n)) {
        res->error = "epochs, O-C, mask and TOF differ in length";
        return false;
    }
    used->assign(n, 1);
    if (!use.empty()) *used = use;
    for (size_t i = 0; i < n; ++i) {
        if (!(*used)[i]) continue;
        if (!std::isfinite(t[i]) || !std::isfinite(oc[i]) || (!tof.empty() && !std::isfinite(tof[i]))) {
            res->error = "point " + std::to_string(i) + " has a non-finite epoch, O-C or TOF";
            return false;
        }
    }
    res->used = std::count(used->begin(), used->end(), uint8_t{1});
    if (res->used < 2) {
        res->error = "only " + std::to_string(res->used) + " accepted point(s): at least 2 are needed for a trend";
        return false;
    }
    return true;
}

// Stage 2: the used points (`ord`, in time order) split at gaps longer than `split` s, into
// segments of at least kMinSegmentPoints used points where the pass has them.
constexpr size_t kMinSegmentPoints = 20, kMinLonePoints = 3;
std::vector<Seg> splitAtGaps(const std::vector<double>& t, const std::vector<uint32_t>& ord, double split) {
    // The pieces between gaps longer than `split`, as [a, b) ranges of `ord`.
    std::vector<std::pair<size_t, size_t>> pieces;
    for (size_t k = 0; k < ord.size();) {
        size_t e = k + 1;
        while (e < ord.size() && !(split > 0 && t[ord[e]] - t[ord[e - 1]] > split)) ++e;
        pieces.emplace_back(k, e);
        k = e;
    }
    // A piece too small to fit its own trend joins its neighbour across the shorter gap (issue
    // 43: a short LEO pass in bursts of 3–8 returns, each fitted with its own line, gave normal
    // points 5–27 mm off where one trend through them all is within 2 mm). A piece of one or two
    // points stays alone, and nothing joins it: between bursts it may be a noise point on the
    // pass's own-TOF trend, which a trend through the bursts would bend to (a 785 km pass: one
    // such point, 5 ns off the true track, moved a normal point 150 mm).
    auto size = [&](size_t q) { return pieces[q].second - pieces[q].first; };
    for (bool merged = true; merged && pieces.size() > 1;) {
        merged = false;
        size_t small = pieces.size();
        double gapOfSmall = INFINITY;
        bool leftOfSmall = false;
        for (size_t q = 0; q < pieces.size(); ++q) {
            if (size(q) < kMinLonePoints || size(q) >= kMinSegmentPoints) continue;
            const double before = q > 0 && size(q - 1) >= kMinLonePoints ? t[ord[pieces[q].first]] - t[ord[pieces[q - 1].second - 1]] : INFINITY;
            const double after = q + 1 < pieces.size() && size(q + 1) >= kMinLonePoints
                                     ? t[ord[pieces[q + 1].first]] - t[ord[pieces[q].second - 1]]
                                     : INFINITY;
            if (!std::isfinite(std::min(before, after))) continue;
            if (small == pieces.size() || size(q) < size(small)) {
                small = q;
                gapOfSmall = std::min(before, after);
                leftOfSmall = before <= after;
            }
        }
        if (small == pieces.size() || !std::isfinite(gapOfSmall)) break;
        const size_t left = leftOfSmall ? small - 1 : small;
        pieces[left].second = pieces[left + 1].second;
        pieces.erase(pieces.begin() + static_cast<long>(left) + 1);
        merged = true;
    }
    std::vector<Seg> segs;
    for (const auto& [k, e] : pieces) {
        Seg g;
        g.a = k;
        g.b = e;
        g.trend.tStart = t[ord[k]];
        g.trend.tEnd = t[ord[e - 1]];
        g.trend.tCenter = 0.5 * (g.trend.tStart + g.trend.tEnd);
        g.trend.tHalfSpan = g.trend.tEnd > g.trend.tStart ? 0.5 * (g.trend.tEnd - g.trend.tStart) : 1.0;
        segs.push_back(g);
    }
    return segs;
}

// Stage 3: gross outliers against the local track (leave-one-out quadratic through 4 + 4
// neighbours of the same segment), with one robust σ for the pass. Only the worst point of a
// neighbourhood goes per round (an outlier also pulls its neighbours' fits), three rounds at
// most (the k·σ rejection takes what is left). Part of the rejection: off with rejectSigma = 0.
void rejectGrossOutliers(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint32_t>& ord,
                         const std::vector<Seg>& segs, const PostfitParams& p, PostfitResult* res) {
    if (!(p.grossSigma > 0 && p.rejectSigma > 0 && ord.size() >= 9)) return;
    double sig = -1;
    for (int round = 0; round < 3; ++round) {
        std::vector<uint32_t> live;
        std::vector<size_t> segOf;
        for (size_t gi = 0; gi < segs.size(); ++gi)
            for (size_t q = segs[gi].a; q < segs[gi].b; ++q)
                if (res->kept[ord[q]]) {
                    live.push_back(ord[q]);
                    segOf.push_back(gi);
                }
        std::vector<double> r(live.size(), NAN);
        for (size_t a0 = 0; a0 < live.size();) {
            size_t b0 = a0;
            while (b0 < live.size() && segOf[b0] == segOf[a0]) ++b0;
            if (b0 - a0 >= 5) {
                const std::vector<uint32_t> part(live.begin() + static_cast<long>(a0), live.begin() + static_cast<long>(b0));
                const std::vector<double> rp = localTrackResiduals(t, oc, part, 4);
                std::copy(rp.begin(), rp.end(), r.begin() + static_cast<long>(a0));
            }
            a0 = b0;
        }
        if (sig < 0) {  // σ from the first round (all points): robust to the outliers themselves
            std::vector<double> av;
            for (double v : r)
                if (std::isfinite(v)) av.push_back(std::fabs(v));
            if (av.size() < 5) break;
            std::nth_element(av.begin(), av.begin() + static_cast<long>(av.size() / 2), av.end());
            sig = 1.4826 * av[av.size() / 2];
            if (!(sig > 0)) break;
        }
        bool any = false;
        for (size_t q = 0; q < live.size(); ++q) {
            if (!std::isfinite(r[q]) || std::fabs(r[q]) <= p.grossSigma * sig) continue;
            bool worst = true;
            for (size_t e = q >= 4 ? q - 4 : 0; e < std::min(live.size(), q + 5) && worst; ++e)
                if (e != q && segOf[e] == segOf[q] && std::isfinite(r[e]) && std::fabs(r[e]) > std::fabs(r[q])) worst = false;
            if (!worst) continue;
            res->kept[live[q]] = 0;
            ++res->grossRejected;
            any = true;
        }
        if (!any) break;
    }
}

// Stage 4: the trend of every segment fitted to the kept points, then the k·σ rejection, until
// the kept points settle. The model of a segment is a Legendre polynomial of degree up to
// p.degree, or with p.autoDegree the degree or cubic spline of the lowest BIC.
class TrendIteration {
public:
    TrendIteration(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint32_t>& ord,
                   std::vector<Seg>& segs, const PostfitParams& p, PostfitResult* res)
        : t_(t), oc_(oc), ord_(ord), segs_(segs), p_(p), res_(res), mAll_(static_cast<size_t>(p.degree) + 1) {
        // P_0..P_degree of every used point at its segment's scaled epoch, once: the fit–reject
        // iterations take the normal equations and the Legendre residuals from them (the same
        // values as computing them again each time, a tenth of a sparse pass's scale search).
        // Not for passes so large that the table would pass 64 MB: those compute them as they go.
        if (ord.size() * mAll_ <= (size_t{8} << 20)) {
            pb_.resize(ord.size() * mAll_);
            for (const Seg& g : segs)
                for (size_t q = g.a; q < g.b; ++q)
                    legendre((t[ord[q]] - g.trend.tCenter) / g.trend.tHalfSpan, p.degree, &pb_[q * mAll_]);
        }
        frozen_.assign(segs.size(), INT32_MIN);
        // PostfitParams::trendOnly: normal equations updated point by point (inFit: in the sums).
        incremental_ = p.trendOnly && !p.autoDegree && !pb_.empty();
        inc_.resize(incremental_ ? segs.size() : 0);
        inFit_.assign(incremental_ ? ord.size() : 0, 0);
    }

    // False (res->error) when the rejection removed every point or on cancel.
    bool run(const Feedback* fb) {
        const double k = p_.rejectSigma;
        for (int it = 1; it <= p_.maxIterations; ++it) {
            res_->iterations = it;
            long long nkAll = 0;
            double ss = 0;
            for (size_t gi = 0; gi < segs_.size(); ++gi) nkAll += fitSegment(gi, it, &ss);
            if (nkAll < 1) {
                res_->error = "the rejection removed every point";
                return false;
            }
            res_->sigmaS = std::sqrt(ss / static_cast<double>(nkAll));
            if (cancelled(fb)) {
                res_->error = "cancelled";
                return false;
            }
            if (k == 0) break;
            if (!reject(std::min(k * res_->sigmaS, cap_))) break;
            if (it == p_.maxIterations) {
                res_->converged = false;
                res_->warnings.push_back("the " + formatDouble(k, 3) + "-sigma rejection did not settle in " +
                                         std::to_string(p_.maxIterations) + " iterations");
            }
        }
        return true;
    }

    /// The rejection's limit is at most this (s) from now on (PostfitParams::noiseBand).
    void capLimit(double limitS) { cap_ = limitS; }
    double limit() const { return std::min(p_.rejectSigma * res_->sigmaS, cap_); }

private:
    struct Incremental {
        Eigen::MatrixXd sums;  // lower triangle of Σ P Pᵀ (all mAll terms)
        Eigen::VectorXd rhs;   // Σ P·(oc − yRef)
        double yRef = 0;
    };
    // A segment's normal equations up to degree m − 1 on the O-C less the kept points' mean y0.
    struct Normal {
        Eigen::MatrixXd Ms;  // full (symmetric)
        Eigen::VectorXd rhs;
        double y0 = 0, yy = 0;
    };

    // One segment fitted (its trend and the residuals of its points); the kept count, *ss += the
    // kept points' squared residuals.
    long long fitSegment(size_t gi, int it, double* ss) {
        Seg& g = segs_[gi];
        long long nk = 0;
        for (size_t q = g.a; q < g.b; ++q) nk += res_->kept[ord_[q]];
        int dMax = g.trend.tEnd > g.trend.tStart ? p_.degree : 0;
        if (nk < 2 * (dMax + 1)) {
            const int d = std::max(0, static_cast<int>(nk / 2) - 1);
            if (d < dMax && !warnedDegree_ && (!p_.autoDegree || segs_.size() == 1)) {
                warnedDegree_ = true;
                res_->warnings.push_back("only " + std::to_string(nk) + " points: trend degree lowered from " +
                                         std::to_string(p_.degree) + " to at most " + std::to_string(d));
            }
            dMax = std::min(dMax, d);
        }
        if (nk < 1) {  // every point of the segment rejected: keep its previous trend
            if (g.trend.coefficients.empty()) g.trend.coefficients.assign(1, 0.0);
            return 0;
        }
        const Normal ne = normalEquations(gi, nk, dMax + 1);
        const int code = chooseModel(gi, it, nk, dMax, ne);
        Eigen::VectorXd c;
        if (code >= 0) {
            c = solve(ne, code);
            c(0) += ne.y0;  // P_0 = 1: the mean goes back into the constant term
            g.trend.degree = code;
            g.trend.knots = 0;
        } else {
            double rss = 0;
            c = splineFit(g, ne, -code, &rss);
            c.array() += ne.y0;  // the B-spline basis sums to 1
            g.trend.degree = 3;
            g.trend.knots = -code;
        }
        g.trend.coefficients.assign(c.data(), c.data() + c.size());
        const bool table = !pb_.empty() && g.trend.knots == 0;  // trendAt from the table
        const size_t terms = g.trend.coefficients.size();
        for (size_t q = g.a; q < g.b; ++q) {
            const uint32_t i = ord_[q];
            if (table) {
                const double* bq = &pb_[q * mAll_];
                double v = 0;
                for (size_t j = 0; j < terms; ++j) v += g.trend.coefficients[j] * bq[j];
                res_->residuals[i] = oc_[i] - v;
            } else {
                res_->residuals[i] = oc_[i] - segmentAt(g.trend, t_[i]);
            }
            if (res_->kept[i]) *ss += res_->residuals[i] * res_->residuals[i];
        }
        return nk;
    }

    // Normal equations up to degree m − 1 (Legendre basis: the lower degrees are leading
    // blocks), on the O-C less the segment's mean (so that yᵀy − cᵀ·rhs gives the residual sum
    // exactly enough for the criterion).
    Normal normalEquations(size_t gi, long long nk, int m) {
        const Seg& g = segs_[gi];
        Normal ne;
        for (size_t q = g.a; q < g.b; ++q)
            if (res_->kept[ord_[q]]) ne.y0 += oc_[ord_[q]];
        ne.y0 /= static_cast<double>(nk);
        const double y0 = ne.y0;
        Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m, m);
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
        if (incremental_) {
            // The sums of the points in the fit so far, on the O-C less the first round's mean,
            // brought up to date with the points whose `kept` changed; then centred on this
            // round's mean y0 (P_0 = 1, so column 0 holds Σ P_j): Σ P_j·(oc − y0) =
            // Σ P_j·(oc − yRef) − (y0 − yRef)·Σ P_j.
            Incremental& s = inc_[gi];
            if (s.sums.size() == 0) {
                s.yRef = y0;
                s.sums = Eigen::MatrixXd::Zero(static_cast<long>(mAll_), static_cast<long>(mAll_));
                s.rhs = Eigen::VectorXd::Zero(static_cast<long>(mAll_));
            }
            for (size_t q = g.a; q < g.b; ++q) {
                const uint32_t i = ord_[q];
                if (res_->kept[i] == inFit_[q]) continue;
                inFit_[q] = res_->kept[i];
                const double sign = res_->kept[i] ? 1.0 : -1.0, d = sign * (oc_[i] - s.yRef);
                const double* bq = &pb_[q * mAll_];
                for (size_t a = 0; a < mAll_; ++a) {
                    s.rhs(static_cast<long>(a)) += bq[a] * d;
                    const double sa = sign * bq[a];
                    for (size_t c = 0; c <= a; ++c) s.sums(static_cast<long>(a), static_cast<long>(c)) += sa * bq[c];
                }
            }
            M = s.sums.topLeftCorner(m, m);
            rhs = s.rhs.head(m) - (y0 - s.yRef) * M.col(0);
        } else {
            const int blockCols = 256;
            Eigen::MatrixXd B(m, blockCols);
            Eigen::VectorXd y(blockCols);
            int fill = 0;
            auto flush = [&]() {
                if (fill == 0) return;
                M.selfadjointView<Eigen::Lower>().rankUpdate(B.leftCols(fill));
                rhs.noalias() += B.leftCols(fill) * y.head(fill);
                fill = 0;
            };
            for (size_t q = g.a; q < g.b; ++q) {
                const uint32_t i = ord_[q];
                if (!res_->kept[i]) continue;
                const double* bq = basis_.data();
                if (pb_.empty()) legendre((t_[i] - g.trend.tCenter) / g.trend.tHalfSpan, m - 1, basis_.data());
                else bq = &pb_[q * mAll_];
                for (int j = 0; j < m; ++j) B(j, fill) = bq[j];
                y(fill) = oc_[i] - y0;
                ne.yy += (oc_[i] - y0) * (oc_[i] - y0);
                if (++fill == blockCols) flush();
            }
            flush();
        }
        ne.Ms = M.selfadjointView<Eigen::Lower>();
        ne.rhs = rhs;
        return ne;
    }

    static Eigen::VectorXd solve(const Normal& ne, int d) {
        const Eigen::MatrixXd Md = ne.Ms.topLeftCorner(d + 1, d + 1);
        Eigen::VectorXd c = Md.ldlt().solve(ne.rhs.head(d + 1));
        if (!c.allFinite()) c = Md.completeOrthogonalDecomposition().solve(ne.rhs.head(d + 1));
        return c;
    }

    // Cubic splines of K intervals (K + 3 coefficients) on the same centred O-C.
    Eigen::VectorXd splineFit(const Seg& g, const Normal& ne, int K, double* rss) const {
        const int mk = K + 3;
        Eigen::MatrixXd S = Eigen::MatrixXd::Zero(mk, mk);
        Eigen::VectorXd sr = Eigen::VectorXd::Zero(mk);
        std::vector<int> perInterval(static_cast<size_t>(K), 0);
        // The normal matrix is symmetric with 4 diagonals: S(a, a + o) summed in band[4a + o]
        // (o = 0..3) and mirrored below. Each entry gets the same products in the same point
        // order as summing every S(j + r, j + c) (w[r]·w[c] = w[c]·w[r]). The points come in
        // time order, so a run of them shares an interval j: its 16 band entries and 4
        // right-hand sides are held in locals over the run (loaded at its start, stored at its
        // end), the same sums in the same order.
        std::vector<double> band(static_cast<size_t>(4 * mk + 16), 0.0), rs(static_cast<size_t>(mk + 4), 0.0);
        double w[4], lb[16], lr[4];
        int cur = -1;
        auto store = [&] {
            if (cur < 0) return;
            std::copy(lb, lb + 16, &band[static_cast<size_t>(4 * cur)]);
            std::copy(lr, lr + 4, &rs[static_cast<size_t>(cur)]);
        };
        for (size_t q = g.a; q < g.b; ++q) {
            const uint32_t i = ord_[q];
            if (!res_->kept[i]) continue;
            const int j = splineBasis(g.trend.tStart, g.trend.tEnd, K, t_[i], w);
            ++perInterval[static_cast<size_t>(j)];
            if (j != cur) {
                store();
                cur = j;
                std::copy(&band[static_cast<size_t>(4 * j)], &band[static_cast<size_t>(4 * j)] + 16, lb);
                std::copy(&rs[static_cast<size_t>(j)], &rs[static_cast<size_t>(j)] + 4, lr);
            }
            const double d = oc_[i] - ne.y0;
            for (int r = 0; r < 4; ++r) {
                lr[r] += w[r] * d;
                for (int c2 = r; c2 < 4; ++c2) lb[4 * r + (c2 - r)] += w[r] * w[c2];
            }
        }
        store();
        for (int a = 0; a < mk; ++a) sr(a) = rs[static_cast<size_t>(a)];
        for (int a = 0; a < mk; ++a)
            for (int o = 0; o < 4 && a + o < mk; ++o) S(a, a + o) = S(a + o, a) = band[static_cast<size_t>(4 * a + o)];
        // Every interval must hold points (else coefficients are free); a tiny ridge keeps the
        // solution bounded.
        const bool covered = std::all_of(perInterval.begin(), perInterval.end(), [](int c) { return c >= 2; });
        S.diagonal().array() += 1e-12 * S.trace() / mk;
        Eigen::VectorXd c = S.ldlt().solve(sr);
        if (!c.allFinite()) c = S.completeOrthogonalDecomposition().solve(sr);
        *rss = covered ? std::max(ne.yy - c.dot(sr), 1e-300 + 1e-15 * ne.yy) : 1e308;
        return c;
    }

    // The model: code ≥ 0 a Legendre degree, < 0 a spline of −code intervals. With autoDegree
    // the lowest BIC, settled from the third iteration on (the rejection then converges).
    int chooseModel(size_t gi, int it, long long nk, int dMax, const Normal& ne) {
        if (!p_.autoDegree) return dMax;
        if (frozen_[gi] != INT32_MIN) return frozen_[gi] >= 0 ? std::min(frozen_[gi], dMax) : frozen_[gi];
        const Seg& g = segs_[gi];
        int code = dMax;
        double bestBic = 1e308;
        const double nd = static_cast<double>(nk);
        for (int d = 0; d <= dMax; ++d) {
            const Eigen::VectorXd c = solve(ne, d);
            const double rss = std::max(ne.yy - c.dot(ne.rhs.head(d + 1)), 1e-300 + 1e-15 * ne.yy);
            const double bic = nd * std::log(rss / nd) + (d + 1) * std::log(nd);
            if (bic < bestBic - 1e-9) {
                bestBic = bic;
                code = d;
            }
        }
        const double span = g.trend.tEnd - g.trend.tStart, L = std::isfinite(res_->binLengthS) ? res_->binLengthS : 0;
        for (int K = 2; L > 0 && K * L <= span && nk >= 2 * (K + 3) && K <= 64; K *= 2) {
            double rss = 0;
            splineFit(g, ne, K, &rss);
            if (!(rss < 1e307)) continue;
            const double bic = nd * std::log(rss / nd) + (K + 3) * std::log(nd);
            if (bic < bestBic - 1e-9) {
                bestBic = bic;
                code = -K;
            }
        }
        if (it >= 3) frozen_[gi] = code;
        return code;
    }

    // The k·σ rejection over every used point; true when a point changed side.
    bool reject(double lim) {
        bool changed = false;
        for (const uint32_t i : ord_) {
            // A gross outlier stays out (its residual is against the trend it never entered).
            if (!res_->kept[i] && std::fabs(res_->residuals[i]) > p_.grossSigma * res_->sigmaS && p_.grossSigma > 0) continue;
            const uint8_t keep = std::fabs(res_->residuals[i]) <= lim;
            if (keep != res_->kept[i]) {
                res_->kept[i] = keep;
                changed = true;
            }
        }
        return changed;
    }

    const std::vector<double>& t_;
    const std::vector<double>& oc_;
    const std::vector<uint32_t>& ord_;
    std::vector<Seg>& segs_;
    const PostfitParams& p_;
    PostfitResult* res_;
    const size_t mAll_;
    std::vector<double> pb_, basis_ = std::vector<double>(32);
    std::vector<int> frozen_;
    bool warnedDegree_ = false, incremental_ = false;
    double cap_ = INFINITY;
    std::vector<Incremental> inc_;
    std::vector<uint8_t> inFit_;
};

// Stage 5: the segments' trends into the result; the longest segment's as the pass's trend.
void collectTrend(const std::vector<Seg>& segs, PostfitResult* res) {
    res->degree = 0;
    res->segments.clear();
    size_t longest = 0;
    for (size_t gi = 0; gi < segs.size(); ++gi) {
        res->degree = std::max(res->degree, segs[gi].trend.degree);
        if (segs[gi].b - segs[gi].a > segs[longest].b - segs[longest].a) longest = gi;
        res->segments.push_back(segs[gi].trend);
    }
    res->tCenter = segs[longest].trend.tCenter;
    res->tHalfSpan = segs[longest].trend.tHalfSpan;
    res->coefficients = segs[longest].trend.coefficients;
}

// f(i, oc[i] − trend(t[i])) for every point i, in order, that pick(i) takes; the trend evaluated
// in blocks (the points' epochs and indices are not gathered beside the pass: 16 bytes a point,
// 160 MB at 10^7 events).
template <class Pick, class F>
void trendResiduals(const PostfitResult& res, const std::vector<double>& t, const std::vector<double>& oc, Pick pick, F f) {
    constexpr size_t kBlock = 8192;
    std::vector<double> tb(kBlock), yb(kBlock);
    std::vector<size_t> ib(kBlock);
    size_t m = 0;
    auto flush = [&] {
        evaluateTrendMany(res, tb.data(), m, yb.data());
        for (size_t k = 0; k < m; ++k) f(ib[k], oc[ib[k]] - yb[k]);
        m = 0;
    };
    for (size_t i = 0; i < t.size(); ++i) {
        if (!pick(i)) continue;
        tb[m] = t[i];
        ib[m] = i;
        if (++m == kBlock) flush();
    }
    if (m) flush();
}

// Stage 4b (PostfitParams::noiseBand): the band of the best expected F1 when the noise beside
// the kept band is measurable, else INFINITY. `limit` is the band the rejection last used.
// Every point of the pass within the kept points' time span is set against the trend; the
// noise's density is counted beside the band, from twice its half-width out to 40 kept-point
// RMS beyond that on each side, each side clipped to where the pass has points (the gate as the
// data show it). The kept
// points hold the signal within ±limit plus the noise's 2·limit·λ: taking that noise out of
// their count and of their sum of squares (uniform: limit²/3 each), and the truncation of a
// Gaussian at ±limit, gives the signal's σ and count.
double noiseBandLimit(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint8_t>& used,
                      double limit, PostfitResult* res) {
    const size_t n = t.size();
    double t0 = INFINITY, t1 = -INFINITY, ss = 0;
    long long nk = 0;
    for (size_t i = 0; i < n; ++i)
        if (res->kept[i]) {
            t0 = std::min(t0, t[i]);
            t1 = std::max(t1, t[i]);
            ss += res->residuals[i] * res->residuals[i];
            ++nk;
        }
    if (nk < 10 || !(limit > 0) || !std::isfinite(limit)) return INFINITY;
    const double rms = std::sqrt(ss / static_cast<double>(nk));
    auto within = [&](size_t i) { return !used[i] && std::isfinite(t[i]) && std::isfinite(oc[i]) && t[i] >= t0 && t[i] <= t1; };
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) count += used[i] || within(i);
    std::vector<double> r;
    r.reserve(count);
    for (size_t i = 0; i < n; ++i)
        if (used[i]) r.push_back(res->residuals[i]);
    trendResiduals(*res, t, oc, within, [&](size_t, double v) { r.push_back(v); });
    const double a = 2 * limit, b = a + 40 * rms;
    double hi = -INFINITY, lo = INFINITY;
    for (double x : r) {
        hi = std::max(hi, x);
        lo = std::min(lo, x);
    }
    const double upTo = std::min(b, hi), downTo = std::min(b, -lo);
    const double width = std::max(0.0, upTo - a) + std::max(0.0, downTo - a);
    long long flank = 0;
    for (double x : r) flank += (x >= a && x <= upTo) || (-x >= a && -x <= downTo);
    if (flank < kNoiseBandMinFlank || !(width > 0)) return INFINITY;
    const double lambda = static_cast<double>(flank) / width;
    const double noiseIn = std::min(0.8 * static_cast<double>(nk), lambda * 2 * limit);
    const double nsIn = static_cast<double>(nk) - noiseIn;
    const double ssSignal = ss - noiseIn * limit * limit / 3;
    if (!(ssSignal > 0) || nsIn < 5) return INFINITY;
    // σ² of the untruncated Gaussian from the truncated second moment, by fixed point.
    const double m2 = ssSignal / nsIn;
    double sigma = std::sqrt(m2);
    for (int k = 0; k < 20; ++k) {
        const double z = limit / sigma, mass = std::erf(z / std::sqrt(2.0));
        const double shrink = 1 - 2 * z * std::exp(-z * z / 2) / std::sqrt(2 * M_PI) / std::max(mass, 1e-12);
        if (!(shrink > 0.05)) break;
        sigma = std::sqrt(m2 / shrink);
    }
    const double signal = nsIn / std::max(1e-12, std::erf(limit / sigma / std::sqrt(2.0)));
    const double w = bestExpectedF1Band(sigma, signal, lambda);
    if (!std::isfinite(w)) return INFINITY;
    res->signalSigmaS = sigma;
    res->noiseDensity = lambda;
    return w;
}

// Stage 6: the residuals of the points not fitted (against the trend), the statistics of the
// kept ones. False (res->error) when none is kept.
bool finalResiduals(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint8_t>& used,
                    PostfitResult* res) {
    const size_t n = t.size();
    trendResiduals(*res, t, oc, [&](size_t i) { return !used[i]; }, [&](size_t i, double v) { res->residuals[i] = v; });
    std::vector<double> kr;
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i) kept += res->kept[i] != 0;
    kr.reserve(kept);
    for (size_t i = 0; i < n; ++i)
        if (res->kept[i]) kr.push_back(res->residuals[i]);
    res->rejected = res->used - static_cast<long long>(kr.size());
    if (kr.empty()) {
        res->error = "the rejection removed every point";
        return false;
    }
    res->stats = residualStats(kr);
    return true;
}

// Stage 7: the normal points: the kept points binned from the start of the day, a bin with at
// least the ILRS minimum of points gives one (at the kept epoch nearest the bin's mean epoch).
void formNormalPoints(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<double>& tof,
                      const PostfitParams& p, PostfitResult* res) {
    const size_t n = t.size();
    const bool stationKnown = std::isfinite(p.stationLatDeg) && std::isfinite(p.stationLonDeg) && std::isfinite(p.dayStartMjd);
    // The ILRS minimum: day or night as given, else bin by bin from the Sun at a known station,
    // else the day minimum (the safer one).
    using DN = PostfitParams::DayNight;
    const bool perBin = p.dayNight == DN::Auto && stationKnown;
    const int fixedMinimum = p.dayNight == DN::Night ? 3 : 6;
    res->minPointsPerBin = p.minPointsPerBin > 0 ? p.minPointsPerBin : fixedMinimum;
    if (!p.normalPoints) return;
    if (perBin && p.minPointsPerBin == 0) res->minPointsPerBin = 3;
    const double L = res->binLengthS;
    std::vector<uint32_t> idx;
    for (size_t i = 0; i < n; ++i)
        if (res->kept[i]) idx.push_back(static_cast<uint32_t>(i));
    std::stable_sort(idx.begin(), idx.end(), [&](uint32_t a, uint32_t b) { return t[a] < t[b]; });
    auto binOf = [&](double x) { return static_cast<long long>(std::floor((x - p.dayStartS) / L)); };
    std::vector<double> br;
    for (size_t a = 0; a < idx.size();) {
        const long long bin = binOf(t[idx[a]]);
        size_t b = a;
        while (b < idx.size() && binOf(t[idx[b]]) == bin) ++b;
        const int cnt = static_cast<int>(b - a);
        // The ILRS minimum: 6 by day, 3 by night (the Sun at the station at the bin's middle).
        int minPts = p.minPointsPerBin > 0 ? p.minPointsPerBin : fixedMinimum;
        double sunEl = NAN;
        if (stationKnown) {
            const double mid = p.dayStartS + (static_cast<double>(bin) + 0.5) * L;
            sunEl = sunElevationDeg(p.dayStartMjd + (mid - p.dayStartS) / 86400.0, p.stationLatDeg, p.stationLonDeg);
            const bool day = isDaylight(sunEl);
            (day ? res->dayBins : res->nightBins)++;
            if (p.minPointsPerBin == 0 && perBin) {
                minPts = day ? 6 : 3;
                res->minPointsPerBin = std::max(res->minPointsPerBin, minPts);
            }
        }
        if (cnt < minPts) {
            ++res->binsTooSmall;
            a = b;
            continue;
        }
        double meanT = 0;
        br.clear();
        for (size_t j = a; j < b; ++j) {
            meanT += t[idx[j]];
            br.push_back(res->residuals[idx[j]]);
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
        np.ocS = oc[ep] - res->residuals[ep] + bs.mean;  // trend(t_j) + mean residual
        if (!tof.empty()) np.tofS = tof[ep] - res->residuals[ep] + bs.mean;
        np.rmsPs = bs.rms * 1e12;
        np.skew = bs.skew;
        np.kurtosis = bs.kurtosis;
        np.peakMinusMeanPs = bs.peakMinusMean * 1e12;
        np.returnRatePct = p.fireRateHz > 0 ? 100.0 * cnt / (p.fireRateHz * L) : NAN;
        np.pointIndex = ep;
        np.minPoints = minPts;
        np.sunElevationDeg = sunEl;
        res->normalPoints.push_back(np);
        a = b;
    }
    if (res->normalPoints.empty())
        res->warnings.push_back("no bin reaches " + std::to_string(res->minPointsPerBin) + " points: no normal point");
}

// A segment's basis at t: Legendre P_0..P_d in u, or its spline's knots + 3 B-splines.
Eigen::VectorXd segmentBasis(const TrendSegment& g, double t) {
    if (g.knots > 0) {
        Eigen::VectorXd b = Eigen::VectorXd::Zero(g.knots + 3);
        double w[4];
        const int i = splineBasis(g.tStart, g.tEnd, g.knots, t, w);
        for (int q = 0; q < 4; ++q) b(i + q) = w[q];
        return b;
    }
    double v[32];
    legendre((t - g.tCenter) / g.tHalfSpan, g.degree, v);
    return Eigen::Map<const Eigen::VectorXd>(v, g.degree + 1);
}

}  // namespace

std::vector<double> normalPointTrendFactors(const std::vector<double>& t, const PostfitResult& r,
                                            const std::vector<double>& trendHat, double* dof) {
    const size_t n = t.size();
    std::vector<double> out(r.normalPoints.size(), NAN);
    if (dof) *dof = NAN;
    const bool hasS = trendHat.size() == n * n && n > 0;
    if (n > kMaxTrendFactorPoints || r.kept.size() != n || r.segments.empty() || !(r.binLengthS > 0) ||
        (!trendHat.empty() && !hasS))
        return out;
    // Each segment's kept points, their basis rows and normal matrix.
    const size_t segs = r.segments.size();
    auto segmentIndex = [&](double x) { return static_cast<size_t>(segmentFor(r.segments, x) - r.segments.data()); };
    std::vector<std::vector<size_t>> members(segs);
    for (size_t i = 0; i < n; ++i)
        if (r.kept[i]) members[segmentIndex(t[i])].push_back(i);
    std::vector<Eigen::MatrixXd> rows(segs);
    std::vector<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>> solve(segs);
    for (size_t k = 0; k < segs; ++k) {
        const TrendSegment& g = r.segments[k];
        rows[k].resize(static_cast<Eigen::Index>(members[k].size()), g.knots > 0 ? g.knots + 3 : g.degree + 1);
        for (size_t m = 0; m < members[k].size(); ++m) rows[k].row(static_cast<Eigen::Index>(m)) = segmentBasis(g, t[members[k][m]]);
        solve[k].compute(rows[k].transpose() * rows[k]);
    }
    // Hᵀx for a sparse x: Hᵀ = B_K G⁺ B_allᵀ per segment (each point evaluated in its segment).
    auto hatT = [&](const std::vector<std::pair<size_t, double>>& x, Eigen::VectorXd* y) {
        y->setZero(static_cast<Eigen::Index>(n));
        std::vector<Eigen::VectorXd> z(segs);
        for (const auto& [i, v] : x) {
            const size_t k = segmentIndex(t[i]);
            if (z[k].size() == 0) z[k] = Eigen::VectorXd::Zero(rows[k].cols());
            z[k] += v * segmentBasis(r.segments[k], t[i]);
        }
        for (size_t k = 0; k < segs; ++k) {
            if (z[k].size() == 0 || members[k].empty()) continue;
            const Eigen::VectorXd h = rows[k] * solve[k].solve(z[k]);
            for (size_t m = 0; m < members[k].size(); ++m) (*y)(static_cast<Eigen::Index>(members[k][m])) = h(static_cast<Eigen::Index>(m));
        }
    };
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const Eigen::Map<const RowMajor> S(hasS ? trendHat.data() : nullptr, hasS ? static_cast<Eigen::Index>(n) : 0,
                                       hasS ? static_cast<Eigen::Index>(n) : 0);
    const double L = r.binLengthS;
    auto binOf = [&](double x) { return static_cast<long long>(std::floor((x - r.dayStartS) / L)); };
    for (size_t q = 0; q < r.normalPoints.size(); ++q) {
        const NormalPoint& np = r.normalPoints[q];
        if (np.pointIndex >= n) continue;
        const long long bin = binOf(np.epochS);
        std::vector<std::pair<size_t, double>> g;
        for (const std::vector<size_t>& seg : members)
            for (size_t i : seg)
                if (binOf(t[i]) == bin) g.emplace_back(i, 1.0);
        if (g.empty()) continue;
        for (auto& e : g) e.second = -1.0 / static_cast<double>(g.size());
        g.emplace_back(np.pointIndex, 1.0);
        Eigen::VectorXd hg;
        hatT(g, &hg);  // Hᵀg
        Eigen::VectorXd d = hg;
        if (hasS) {
            Eigen::VectorXd v = -hg;  // v = (I − H)ᵀg
            for (const auto& [i, x] : g) v(static_cast<Eigen::Index>(i)) += x;
            d += S.transpose() * v;  // d = g − (I − S)ᵀv = Hᵀg + Sᵀv
        }
        out[q] = d.norm();
    }
    if (dof) {
        // Σ over the kept points i of ‖row i of (I − H)(I − S)‖²; without S, (I − H) is a
        // projector over each segment's kept points and that is their count less its rank.
        double sum = 0;
        if (!hasS) {
            for (size_t k = 0; k < segs; ++k) sum += static_cast<double>(members[k].size()) - static_cast<double>(solve[k].rank());
        } else {
            Eigen::VectorXd hi;
            for (const std::vector<size_t>& seg : members)
                for (size_t i : seg) {
                    hatT({{i, 1.0}}, &hi);  // row i of H
                    Eigen::VectorXd row = -hi;
                    row(static_cast<Eigen::Index>(i)) += 1;  // row i of I − H
                    sum += (row - S.transpose() * row).squaredNorm();
                }
        }
        *dof = sum;
    }
    return out;
}

PostfitResult postfit(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint8_t>& use,
                      const std::vector<double>& tof, const PostfitParams& p, const Feedback* fb) {
    PostfitResult res;
    std::vector<uint8_t> used;
    if (!checkPostfitInputs(t, oc, use, tof, p, &used, &res)) return res;
    const size_t n = t.size();
    res.binLengthS = p.binLengthS > 0 ? p.binLengthS : normalPointBinS(p.altitudeKm);
    res.dayStartS = p.dayStartS;
    // Used points in time order.
    std::vector<uint32_t> ord;
    for (size_t i = 0; i < n; ++i)
        if (used[i]) ord.push_back(static_cast<uint32_t>(i));
    std::stable_sort(ord.begin(), ord.end(), [&](uint32_t a, uint32_t b) { return t[a] < t[b]; });
    res.kept = used;
    // Segments: split at gaps longer than splitGapS (automatic: 3 bins, at least 20 s).
    double split = p.splitGapS;
    if (split == 0) split = std::max(20.0, 3 * (std::isfinite(res.binLengthS) ? res.binLengthS : 0.0));
    res.splitGapS = split;
    std::vector<Seg> segs = splitAtGaps(t, ord, split);
    rejectGrossOutliers(t, oc, ord, segs, p, &res);
    if (res.used > 0 && t[ord.front()] == t[ord.back()] && p.degree > 0)
        res.warnings.push_back("all accepted epochs are equal: the trend is a constant");
    res.residuals.assign(n, NAN);
    TrendIteration iteration(t, oc, ord, segs, p, &res);
    if (!iteration.run(fb)) return res;
    collectTrend(segs, &res);
    // The noise beside the band may call for a narrower one (at most twice: the trend moves
    // little once the band is set).
    for (int round = 0; round < 2 && p.noiseBand && !p.trendOnly && p.rejectSigma > 0; ++round) {
        const double lim = iteration.limit();
        const double w = noiseBandLimit(t, oc, used, lim, &res);
        if (!(w < 0.99 * lim)) break;
        res.noiseBandS = w;
        iteration.capLimit(w);
        if (!iteration.run(fb)) return res;
        collectTrend(segs, &res);
    }
    res.limitS = p.rejectSigma > 0 ? iteration.limit() : NAN;
    if (p.trendOnly) {
        res.rejected = res.used - std::count(res.kept.begin(), res.kept.end(), uint8_t{1});
        if (res.rejected == res.used) {
            res.error = "the rejection removed every point";
            return res;
        }
        res.ok = true;
        return res;
    }
    if (!finalResiduals(t, oc, used, &res)) return res;
    formNormalPoints(t, oc, tof, p, &res);
    res.ok = true;
    return res;
}

}  // namespace lwb::core::slr
