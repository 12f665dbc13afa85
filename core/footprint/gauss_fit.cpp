#include "core/footprint/gauss_fit.hpp"
#include "core/common/select.hpp"

#include "core/common/text.hpp"
#include "core/footprint/gauss_kernel.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace lwb::core::footprint {

namespace {

struct DomainPixel {
    double u, v;   // position relative to the reference pixel
    double f;      // I − background (> 0)
    double lnfn;   // ln(f / S)
};

// A Gaussian in local coordinates, from the log-quadratic coefficients.
struct Quad {
    double lnScale = 0;  // ln(amplitude / S)
    double x0 = 0, y0 = 0, a = 0, b = 0, c = 0;
};

bool positiveDefinite(double a, double b, double c) { return a > 0 && c > 0 && a * c - b * b > 0; }

// Weighted log-quadratic least squares: rows w_i·[1 u v u² (uv) v²] = w_i·ln fn_i. With
// w_i = fn_i this is exactly paper 000's A = B·C (eq. 3–7), solved by QR as the paper does
// (qr = true). The Guo passes solve the same system through its 6×6 normal equations
// (qr = false), which is several times cheaper and well conditioned in peak-centred
// coordinates. Returns false when the quadratic form is not a peak.
// The weighted normal equations of the log fit (K columns: 1, u, v, u², then uv and v² or v²
// alone): every entry Σ w²·col_a·col_b is one of 15 weighted moments of degree ≤ 4 (Σ w²u² is
// both (1, u²) and (u, u)), taken in one vectorised pass (kernel::logMoments).
void normalEquations(const std::vector<DomainPixel>& px, const std::vector<double>& w, bool xy,
                     Eigen::Matrix<double, 6, 6>& N, Eigen::Matrix<double, 6, 1>& r) {
    static_assert(sizeof(DomainPixel) == 4 * sizeof(double) && offsetof(DomainPixel, v) == sizeof(double) &&
                      offsetof(DomainPixel, lnfn) == 3 * sizeof(double),
                  "logMoments reads (u, v, f, ln fn) quadruples");
    double m[15], rr[6];
    kernel::logMoments(&px[0].u, w.data(), static_cast<int>(px.size()), m, rr);
    // Moment index of u^i v^j (i + j ≤ 4), in logMoments' order.
    auto M = [&](int i, int j) {
        static const int first[5] = {0, 1, 3, 6, 10};  // first index of each degree
        return m[first[i + j] + j];
    };
    // The columns as exponents (i, j) of u^i v^j.
    const int cols6[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    const int cols5[5][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {0, 2}};
    const int k = xy ? 6 : 5;
    const int(*cols)[2] = xy ? cols6 : cols5;
    const int rhsIndex6[6] = {0, 1, 2, 3, 4, 5}, rhsIndex5[5] = {0, 1, 2, 3, 5};
    for (int a = 0; a < k; ++a) {
        r(a) = rr[xy ? rhsIndex6[a] : rhsIndex5[a]];
        for (int b = a; b < k; ++b) N(a, b) = M(cols[a][0] + cols[b][0], cols[a][1] + cols[b][1]);
    }
}

bool logFit(const std::vector<DomainPixel>& px, const std::vector<double>& w, bool xy, bool qr, Quad* q) {
    const int n = static_cast<int>(px.size());
    const int k = xy ? 6 : 5;
    if (n < k + 1) return false;
    Eigen::VectorXd C;
    if (qr) {
        Eigen::MatrixXd B(n, k);
        Eigen::VectorXd A(n);
        for (int i = 0; i < n; ++i) {
            const double u = px[i].u, v = px[i].v, wi = w[i];
            B(i, 0) = wi;
            B(i, 1) = wi * u;
            B(i, 2) = wi * v;
            B(i, 3) = wi * u * u;
            if (xy) {
                B(i, 4) = wi * u * v;
                B(i, 5) = wi * v * v;
            } else {
                B(i, 4) = wi * v * v;
            }
            A(i) = wi * px[i].lnfn;
        }
        C = B.householderQr().solve(A);
    } else {
        Eigen::Matrix<double, 6, 6> N = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> r = Eigen::Matrix<double, 6, 1>::Zero();
        normalEquations(px, w, xy, N, r);
        C = N.topLeftCorner(k, k).selfadjointView<Eigen::Upper>().ldlt().solve(r.head(k));
    }
    if (!C.allFinite()) return false;
    const double c3 = C(3), c4 = xy ? C(4) : 0.0, c5 = xy ? C(5) : C(4);
    // ln f = c0 + c1 u + c2 v + c3 u² + c4 uv + c5 v²  ⇒  precision M = [[−2c3, −c4], [−c4, −2c5]]
    const double a = -2 * c3, b = -c4, c = -2 * c5;
    if (!positiveDefinite(a, b, c)) return false;
    const double det = a * c - b * b;
    q->a = a;
    q->b = b;
    q->c = c;
    q->x0 = (c * C(1) - b * C(2)) / det;  // M p0 = [c1, c2]
    q->y0 = (a * C(2) - b * C(1)) / det;
    q->lnScale = C(0) + 0.5 * (a * q->x0 * q->x0 + 2 * b * q->x0 * q->y0 + c * q->y0 * q->y0);
    return std::isfinite(q->x0) && std::isfinite(q->y0) && std::isfinite(q->lnScale);
}

// A start from the intensity-weighted moments of the domain pixels above half the brightest:
// centroid, and a spread from the second moments (for a Gaussian cut at half its peak they are
// 0.61 of the full covariance), its σ clamped to 1–8 px.
bool momentStart(const std::vector<DomainPixel>& px, double S, Quad* q) {
    double fmax = 0;
    for (const auto& p : px) fmax = std::max(fmax, p.f);
    double sw = 0, su = 0, sv = 0;
    for (const auto& p : px)
        if (p.f >= 0.5 * fmax) {
            sw += p.f;
            su += p.f * p.u;
            sv += p.f * p.v;
        }
    if (!(sw > 0)) return false;
    const double mu = su / sw, mv = sv / sw;
    double suu = 0, suv = 0, svv = 0;
    for (const auto& p : px)
        if (p.f >= 0.5 * fmax) {
            const double du = p.u - mu, dv = p.v - mv;
            suu += p.f * du * du;
            suv += p.f * du * dv;
            svv += p.f * dv * dv;
        }
    const double k = 1 / 0.61;
    double sxx = std::clamp(k * suu / sw, 1.0, 64.0), syy = std::clamp(k * svv / sw, 1.0, 64.0);
    double sxy = std::clamp(k * suv / sw, -0.9 * std::sqrt(sxx * syy), 0.9 * std::sqrt(sxx * syy));
    const double det = sxx * syy - sxy * sxy;
    q->x0 = mu;
    q->y0 = mv;
    q->a = syy / det;
    q->b = -sxy / det;
    q->c = sxx / det;
    q->lnScale = std::log(fmax / S);
    return std::isfinite(q->x0) && std::isfinite(q->y0) && std::isfinite(q->lnScale);
}

// lnfn = ln(f / S) of every pixel, through the vectorised log of the kernel.
void logFractions(std::vector<DomainPixel>& px, double S) {
    thread_local std::vector<double> f, ln;
    f.resize(px.size());
    ln.resize(px.size());
    for (size_t i = 0; i < px.size(); ++i) f[i] = px[i].f;
    kernel::logOfRatio(f.data(), S, ln.data(), static_cast<int>(px.size()));
    for (size_t i = 0; i < px.size(); ++i) px[i].lnfn = ln[i];
}

// The domain pixels joined to the peak pixel (4-connected, within the domain) whose value is at
// least `fraction` of the domain's brightest pixel above the background, relative to
// (refX, refY); f > 0.
std::vector<DomainPixel> domainCore(const float* img, int w, int h, const SpotDomain& domain, double background,
                                    double fraction, double refX, double refY) {
    std::vector<DomainPixel> out;
    if (domain.peakX < 0 || domain.peakY < 0 || domain.peakX >= w || domain.peakY >= h ||
        domain.mask.size() != size_t(w) * size_t(h))
        return out;
    // The height of the domain's brightest pixel: the smoothed peak's lower value made a larger
    // core that turned an empty strong-ground ROI of the golden set into a doubtful "spot".
    double top = 0;
    for (int p : domain.pixels) top = std::max(top, double(img[p]) - background);
    const double level = fraction * top;
    std::vector<unsigned char> seen(size_t(w) * size_t(h), 0);
    std::vector<int> stack;
    const int start = domain.peakY * w + domain.peakX;
    if (!domain.mask[size_t(start)] || !(img[start] - background >= level)) return out;
    seen[size_t(start)] = 1;
    stack.push_back(start);
    while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        const double f = img[p] - background;
        if (f > 0) out.push_back({p % w - refX, p / w - refY, f, 0});
        const int x = p % w, y = p / w;
        const int next[4] = {x > 0 ? p - 1 : -1, x + 1 < w ? p + 1 : -1, y > 0 ? p - w : -1, y + 1 < h ? p + w : -1};
        for (int q : next) {
            if (q < 0 || seen[size_t(q)] || !domain.mask[size_t(q)] || !(img[q] - background >= level)) continue;
            seen[size_t(q)] = 1;
            stack.push_back(q);
        }
    }
    return out;
}

// Paper 000 eq. 8 residual at a given model: E_i = fn_i·ln(f_i / g_i), fn = f / Σf, with
// ln g_i = ln A − q_i/2 (q_i the model's quadratic form at pixel i), floored at ln 1e-300 so
// that a far pixel's model never counts as below 1e-300. At the log-fit's own solution this
// equals ‖A − B·C‖²/N of eq. 8 exactly.
// f holds the f_i (> 0), q the q_i.
double paperMse(const std::vector<double>& f, const std::vector<double>& q, double amplitude) {
    const int n = static_cast<int>(f.size());
    if (n == 0) return NAN;
    double s = 0;
    for (double v : f) s += v;
    thread_local std::vector<double> lnf;
    lnf.resize(f.size());
    kernel::logOfRatio(f.data(), 1.0, lnf.data(), n);
    const double lnA = std::log(amplitude), lnFloor = std::log(1e-300);
    double e2 = 0;
    for (int i = 0; i < n; ++i) {
        const double e = (f[i] / s) * (lnf[i] - std::max(lnA - 0.5 * q[i], lnFloor));
        e2 += e * e;
    }
    return e2 / n;
}

struct WinPixel {
    double dx, dy;  // relative to the window centre
    double value;
    double weight;
};

constexpr int kP = 9;  // amplitude, x0, y0, a, b, c, bg0, bgX, bgY
using Vec9 = Eigen::Matrix<double, kP, 1>;
using Mat9 = Eigen::Matrix<double, kP, kP>;

struct Cost {
    double value = 0;  // what LM minimises: Σ w r², or the Cauchy cost Σ c² ln(1 + w r²/c²)
    double chi2 = 0;   // Σ w_eff r² with the effective (IRLS) weights, for the covariance scale
};

// Evaluates the cost of the model at p over the window and, when jtj is given, the Gauss–Newton
// normal equations JᵀWJ and JᵀWr. cauchyC2 > 0 turns on the Cauchy loss: each pixel's weight is
// then multiplied by 1/(1 + w r²/c²) (iteratively re-weighted least squares), so ground features
// a Gaussian + plane cannot describe (roads, buildings, field edges) stop pulling the fit.
// The plane is referenced to the current centre (x0, y0). The weighted Jacobian rows go into a
// matrix and JᵀWJ is 45 column dot products: contiguous and vectorised.
struct FitWindow {
    std::vector<WinPixel> px;  // row-major over cols × rows
    int cols = 0, rows = 0;
    bool diff = false;         // fit neighbour differences (see accumulateDifferences)
    double diffVarX = 0, diffVarY = 0;  // ground variance of a neighbour difference along x, y (DN²)
    /// Inverse variance of each horizontal (w0[0]) and vertical (w0[1]) difference ending i+step:
    /// ground + the spot's photon noise at both pixels; 0 across a row end.
    std::vector<double> w0[2];
};

// The cost on the pixels (accumulate: the pixels or their differences).
Cost accumulatePixels(const FitWindow& fw, const Vec9& p, double cauchyC2, Mat9* jtj, Vec9* jtr) {
    const std::vector<WinPixel>& win = fw.px;
    const double A = p(0), x0 = p(1), y0 = p(2), a = p(3), b = p(4), c = p(5);
    const int n = static_cast<int>(win.size());
    thread_local std::vector<double> tq, te, tz;
    thread_local Eigen::Matrix<double, Eigen::Dynamic, kP> tJ;
    thread_local Eigen::VectorXd tR;
    auto& q = tq;
    auto& e = te;
    auto& z = tz;
    auto& J = tJ;
    auto& R = tR;
    q.resize(static_cast<size_t>(n));
    e.resize(static_cast<size_t>(n));
    z.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double dx = win[i].dx - x0, dy = win[i].dy - y0;
        q[i] = a * dx * dx + 2 * b * dx * dy + c * dy * dy;
    }
    kernel::halfNegExp(q.data(), e.data(), n);
    if (jtj) {
        J.resize(n, kP);
        R.resize(n);
    }
    Cost cost;
    for (int i = 0; i < n; ++i) {
        const WinPixel& w = win[static_cast<size_t>(i)];
        const double dx = w.dx - x0, dy = w.dy - y0;
        const double g = A * e[i];
        const double r = w.value - (g + p(6) + p(7) * dx + p(8) * dy);
        const double z2 = w.weight * r * r;
        z[i] = z2;
        double weight = w.weight;
        if (cauchyC2 > 0)
            weight /= 1.0 + z2 / cauchyC2;
        else
            cost.value += z2;
        cost.chi2 += weight * r * r;
        if (!jtj) continue;
        const double sw = std::sqrt(weight);
        J(i, 0) = sw * e[i];
        J(i, 1) = sw * (g * (a * dx + b * dy) - p(7));
        J(i, 2) = sw * (g * (b * dx + c * dy) - p(8));
        J(i, 3) = sw * (-0.5 * g * dx * dx);
        J(i, 4) = sw * (-g * dx * dy);
        J(i, 5) = sw * (-0.5 * g * dy * dy);
        J(i, 6) = sw;
        J(i, 7) = sw * dx;
        J(i, 8) = sw * dy;
        R(i) = sw * r;
    }
    // The Cauchy cost was never summed before issue 14 (value stayed 0, so LM took every step).
    if (cauchyC2 > 0) cost.value = kernel::cauchyCostSum(z.data(), n, cauchyC2);
    if (jtj) {
        for (int u = 0; u < kP; ++u) {
            for (int v = u; v < kP; ++v) (*jtj)(u, v) = (*jtj)(v, u) = J.col(u).dot(J.col(v));
            (*jtr)(u) = J.col(u).dot(R);
        }
        jtj->row(6).setZero();  // bg0 does not enter the differences
        jtj->col(6).setZero();
        (*jtj)(6, 6) = 1;
        (*jtr)(6) = 0;
    }
    return cost;
}

// The same cost on the differences of horizontally and vertically neighbouring pixels. Real
// ground has a red spectrum (photographs: power falling about as 1/f²), so neighbouring pixels'
// ground errors are strongly correlated and a pixel fit that treats them as independent lets
// smooth ground under the spot pull the centre. A first difference whitens such a spectrum: this
// is close to generalised least squares for the ground's correlation. On the issue-14 simulator it
// beat the pixel fit, a separable AR(1) prewhitening with the measured lag-1 correlation, partial
// differences (ρ = 0.5, 0.8) and second differences on every class. The constant background
// drops out (its row of JᵀWJ is pinned); the plane's slopes remain.
__attribute__((target_clones("avx2", "default")))
Cost accumulateDifferences(const FitWindow& fw, const Vec9& p, double cauchyC2, Mat9* jtj, Vec9* jtr) {
    // Structure-of-arrays: every Jacobian column, residual and weight is a contiguous array, and
    // a horizontal (vertical) difference is the array minus itself shifted by 1 (cols), so each
    // loop below is a plain vectorisable pass. bg0 (index 6) drops out of the differences.
    constexpr int kCols = 6;  // amplitude, x0, y0, a, b, c
    const std::vector<WinPixel>& win = fw.px;
    const double A = p(0), x0 = p(1), y0 = p(2), a = p(3), b = p(4), c = p(5), bx = p(7), by = p(8);
    const int n = static_cast<int>(win.size()), cols = fw.cols;
    thread_local std::vector<double> buf;
    buf.resize(size_t(n) * (kCols + 5));
    double* q = buf.data();
    double* e = q + n;
    double* res = e + n;
    double* W = res + n;    // weight of the difference ending at each pixel (horizontal, then vertical)
    double* DR = W + n;     // that difference of the residuals
    double* P = DR + n;     // kCols Jacobian columns of the pixels
    for (int i = 0; i < n; ++i) {
        const double dx = win[size_t(i)].dx - x0, dy = win[size_t(i)].dy - y0;
        q[i] = a * dx * dx + 2 * b * dx * dy + c * dy * dy;
    }
    kernel::halfNegExp(q, e, n);
    for (int i = 0; i < n; ++i) {
        const double dx = win[size_t(i)].dx - x0, dy = win[size_t(i)].dy - y0;
        const double g = A * e[i];
        res[i] = win[size_t(i)].value - (g + p(6) + bx * dx + by * dy);
        if (!jtj) continue;
        P[i] = e[i];
        P[n + i] = g * (a * dx + b * dy) - bx;
        P[2 * n + i] = g * (b * dx + c * dy) - by;
        P[3 * n + i] = -0.5 * g * dx * dx;
        P[4 * n + i] = -g * dx * dy;
        P[5 * n + i] = -0.5 * g * dy * dy;
    }
    Cost cost;
    double zsum = 0;
    if (jtj) {
        jtj->setZero();
        jtr->setZero();
    }
    for (int pass = 0; pass < 2; ++pass) {
        const int step = pass == 0 ? 1 : cols;
        const int m = n - step;  // differences (j = i + step) ending at pixels step..n-1
        double chi2 = 0;
        zsum += kernel::differenceWeights(res, m, step, fw.w0[pass].data(), cauchyC2, W, DR, &chi2);
        cost.chi2 += chi2;
        if (!jtj) continue;
        // JᵀWJ and JᵀWr of the differences: the six spot columns in a vectorised kernel; the
        // plane's slope columns differ by exactly 1 (along their own axis) or 0 between neighbours.
        constexpr int kSpot = kernel::kGramColumns;
        static_assert(kSpot == kCols, "the Gram kernel takes the six spot columns");
        double gram[kSpot * kSpot], rhs[kSpot], wd[kSpot], sw = 0, swr = 0;
        kernel::differenceGram(P, n, step, W, DR, gram, rhs, wd, &sw, &swr);
        const int slope = pass == 0 ? 7 : 8;  // bgX differs horizontally, bgY vertically
        for (int u = 0; u < kSpot; ++u) {
            (*jtr)(u) += rhs[u];
            for (int v = 0; v <= u; ++v) {
                (*jtj)(u, v) += gram[u * kSpot + v];
                if (v != u) (*jtj)(v, u) += gram[u * kSpot + v];
            }
            (*jtj)(u, slope) += wd[u];
            (*jtj)(slope, u) += wd[u];
        }
        (*jtj)(slope, slope) += sw;
        (*jtr)(slope) += swr;
    }
    cost.value = zsum;
    if (jtj) {
        (*jtj)(6, 6) = 1;  // bg0 does not enter the differences: pinned
        (*jtr)(6) = 0;
    }
    return cost;
}

// The cost and its normal equations: on the pixels, or on their neighbour differences. (Defined
// after both: a target_clones function declared ahead of its definition and called before it
// is refused by clang, and a declaration carrying the attribute miscompiled under it.)
Cost accumulate(const FitWindow& fw, const Vec9& p, double cauchyC2, Mat9* jtj, Vec9* jtr) {
    return fw.diff ? accumulateDifferences(fw, p, cauchyC2, jtj, jtr) : accumulatePixels(fw, p, cauchyC2, jtj, jtr);
}

// A step that changes nothing that matters: it moves the centre less than `tolerance` (px), and
// the amplitude and the shape (a, c, and b against √(ac)) by less than `shapeTolerance` of their
// values, so that what the verdict reads (axes, tilt, amplitude) has settled too.
bool smallStep(const Vec9& p, const Vec9& delta, double tolerance, double shapeTolerance) {
    if (!(std::max(std::fabs(delta(1)), std::fabs(delta(2))) < tolerance)) return false;
    const double scaleB = std::sqrt(std::fabs(p(3) * p(5)));
    return std::fabs(delta(0)) <= shapeTolerance * std::fabs(p(0)) && std::fabs(delta(3)) <= shapeTolerance * std::fabs(p(3)) &&
           std::fabs(delta(5)) <= shapeTolerance * std::fabs(p(5)) && std::fabs(delta(4)) <= shapeTolerance * scaleB;
}

// Levenberg–Marquardt from p on the (plain or Cauchy) cost; returns the iterations used.
// jtj/jtr/cost hold the state at p on entry; on return, that of the last evaluated point (the
// final small step, taken unevaluated, may have moved p from it by less than the tolerances).
int levenbergMarquardt(const FitWindow& win, Vec9& p, double cauchyC2, int maxIterations, double tolerance,
                       double shapeTolerance, Mat9& jtj, Vec9& jtr, Cost& cost) {
    double lambda = 1e-3;
    int it = 0;
    for (; it < maxIterations; ++it) {
        bool stepTaken = false, converged = false;
        bool first = true;
        while (lambda < 1e10) {
            Mat9 aug = jtj;
            aug.diagonal() *= (1.0 + lambda);
            const Vec9 delta = aug.ldlt().solve(jtr);
            // At the minimum within precision: the (hardly damped) step from here would move the
            // centre, amplitude and shape less than their tolerances (smallStep). It is taken
            // without evaluating its cost: one evaluation of the window less (jtj, jtr and cost
            // stay those of the previous point).
            if (first && lambda <= 1e-2 && delta.allFinite() && smallStep(p, delta, tolerance, shapeTolerance)) {
                const Vec9 last = p + delta;
                if (last(0) > 0 && positiveDefinite(last(3), last(4), last(5))) p = last;
                converged = true;
                break;
            }
            first = false;
            const Vec9 trial = p + delta;
            if (!delta.allFinite() || trial(0) <= 0 || !positiveDefinite(trial(3), trial(4), trial(5))) {
                lambda *= 10;
                continue;
            }
            Mat9 jtjTrial;
            Vec9 jtrTrial;
            const Cost costTrial = accumulate(win, trial, cauchyC2, &jtjTrial, &jtrTrial);
            if (costTrial.value <= cost.value) {
                converged = smallStep(p, delta, tolerance, shapeTolerance);
                p = trial;
                cost = costTrial;
                jtj = jtjTrial;
                jtr = jtrTrial;
                lambda = std::max(lambda * 0.1, 1e-9);
                stepTaken = true;
                break;
            }
            lambda *= 10;
        }
        if (converged || !stepTaken) break;  // at the minimum within precision
    }
    return it + 1;
}

// Ground variance of a horizontal and of a vertical neighbour difference (texture, photon and
// read noise together): robust (MAD) spread of the ROI's differences away from the spot (outside
// 3σ of the start model), so a building or a road edge does not inflate it.
struct DifferenceVariances {
    double x = 0, y = 0;
    bool ok = false;
};

__attribute__((target_clones("avx2", "default")))
DifferenceVariances groundDifferenceVariances(const cv::Mat& roi, const GaussModel& m) {
    DifferenceVariances dv;
    const int w = roi.cols, h = roi.rows;
    const float* img = roi.ptr<float>();
    // The start model's quadratic form at each pixel (a plain loop that vectorises); a pixel is
    // away from the spot where it exceeds 9.
    thread_local std::vector<double> quad;
    thread_local std::vector<float> d;
    quad.resize(size_t(w) * h);
    for (int y = 0; y < h; ++y) {
        double* q = quad.data() + size_t(y) * w;
        const double dy = y - m.y0;
        for (int x = 0; x < w; ++x) {
            const double dx = x - m.x0;
            q[x] = m.a * dx * dx + 2 * m.b * dx * dy + m.c * dy * dy;
        }
    }
    auto robustVar = [&](int step) {
        // Every difference is written, the count advanced only for those away from the spot.
        d.resize(size_t(w) * h);
        size_t k = 0;
        const int xEnd = step == 1 ? w - 1 : w, yEnd = step == 1 ? h : h - 1;
        for (int y = 0; y < yEnd; ++y)
            for (int x = 0; x < xEnd; ++x) {
                const size_t i = size_t(y) * w + x;
                d[k] = std::fabs(img[i + step] - img[i]);
                k += (quad[i] > 9.0) & (quad[i + step] > 9.0);
            }
        d.resize(k);
        if (d.size() < 16) return 0.0;
        const double s = 1.4826 * kthSmallest(d, d.size() / 2);
        return s * s;
    };
    dv.x = robustVar(1);
    dv.y = robustVar(w);
    dv.ok = dv.x > 0 && dv.y > 0;
    return dv;
}

// The centre's covariance from the shot's own ground (issue 32). The fit's centre is, to first
// order, δθ = (JᵀWJ)⁻¹JᵀW·n (pixel fit) or (J_dᵀWJ_d)⁻¹J_dᵀW·D·n (difference fit: D the
// neighbour differences, J_d = D·J), with W the final (Cauchy re-weighted) weights: a template
// s_x, s_y over the window's pixels gives x̂ − x = s_x·n. Its covariance under pixel noise of
// covariance C is s C sᵀ: a sandwich. C = the ground's texture (stationary over the ROI, its
// autocovariance R(l) measured on the residual field img − model of this ROI, each lag's sum
// divided by the pairs it has) + the photon and read noise of each pixel (diagonal, from the
// model). s C sᵀ = Σ_l A_s(l)·R(l) with A_s the template's autocorrelation, over every lag the
// template reaches. The templates sum to zero and are orthogonal to the plane, so a constant
// or a plane left in the residuals cancels. The texture part is scaled by textureScale²
// (GaussParams::uncertaintyScale, for the robust fits: see there).
struct CentreCovariance {
    bool ok = false;
    double xx = NAN, xy = NAN, yy = NAN;
};

// The window's per-pixel arrays of the covariance, in one thread-local buffer: the model's
// quadratic form and its exponential, the gradients of x0 and y0, the residual, the photon +
// read variance and the templates s_x, s_y.
struct CovarianceArrays {
    double *q, *e, *gx, *gy, *res, *v, *sx, *sy;
};

// The three sums of a sandwich s C sᵀ (or its parts).
struct CovarianceSums {
    double xx = 0, xy = 0, yy = 0;
};

// The ROI's residual field (mean removed) and its mean photon + read variance.
struct ResidualField {
    const double* rho;
    double vbar;
};

// Carves the window's arrays out of the thread's buffer (n pixels each).
__attribute__((always_inline)) inline CovarianceArrays covarianceArrays(int n) {
    thread_local std::vector<double> buf;
    buf.resize(size_t(n) * 8);
    double *q = buf.data(), *e = q + n, *gx = e + n, *gy = gx + n, *res = gy + n, *v = res + n, *sx = v + n, *sy = sx + n;
    return {q, e, gx, gy, res, v, sx, sy};
}

// At each window pixel: the gradients of x0 and y0, the residual and the photon + read variance.
__attribute__((always_inline)) inline void windowGradients(const FitWindow& fw, const Vec9& p,
                                                           const Eigen::Matrix<double, kP, 2>& hc, double gain, double rn2,
                                                           const CovarianceArrays& t) {
    const std::vector<WinPixel>& win = fw.px;
    const int n = static_cast<int>(win.size());
    const double A = p(0), x0 = p(1), y0 = p(2), a = p(3), b = p(4), c = p(5), bx = p(7), by = p(8);
    double *q = t.q, *e = t.e, *gx = t.gx, *gy = t.gy, *res = t.res, *v = t.v;
    for (int i = 0; i < n; ++i) {
        const double dx = win[size_t(i)].dx - x0, dy = win[size_t(i)].dy - y0;
        q[i] = a * dx * dx + 2 * b * dx * dy + c * dy * dy;
    }
    kernel::halfNegExp(q, e, n);
    // The gradients of x0 and y0 at each pixel: J (the model's Jacobian row) times those columns,
    // the terms in J's order (the plane's three columns 1, dx, dy last).
    double h[2][kP];
    for (int k = 0; k < kP; ++k) h[0][k] = hc(k, 0), h[1][k] = hc(k, 1);
    for (int i = 0; i < n; ++i) {
        const double dx = win[size_t(i)].dx - x0, dy = win[size_t(i)].dy - y0, g = A * e[i];
        const double j1 = g * (a * dx + b * dy) - bx, j2 = g * (b * dx + c * dy) - by, j3 = -0.5 * g * dx * dx,
                     j4 = -g * dx * dy, j5 = -0.5 * g * dy * dy;
        gx[i] = e[i] * h[0][0] + j1 * h[0][1] + j2 * h[0][2] + j3 * h[0][3] + j4 * h[0][4] + j5 * h[0][5] + h[0][6] +
                dx * h[0][7] + dy * h[0][8];
        gy[i] = e[i] * h[1][0] + j1 * h[1][1] + j2 * h[1][2] + j3 * h[1][3] + j4 * h[1][4] + j5 * h[1][5] + h[1][6] +
                dx * h[1][7] + dy * h[1][8];
        const double model = g + p(6) + bx * dx + by * dy;
        res[i] = win[size_t(i)].value - model;
        v[i] = std::max(model, 0.0) / gain + rn2;
    }
}

// The templates s_x, s_y: each pixel's final weight times its gradients (pixel fit), or the
// sums over the differences each pixel is in (difference fit).
__attribute__((always_inline)) inline void centreTemplates(const FitWindow& fw, double cauchyC2, const CovarianceArrays& t) {
    const std::vector<WinPixel>& win = fw.px;
    const int n = static_cast<int>(win.size()), cols = fw.cols;
    const double *gx = t.gx, *gy = t.gy, *res = t.res;
    double *sx = t.sx, *sy = t.sy;
    if (!fw.diff) {
        for (int i = 0; i < n; ++i) {
            double w = win[size_t(i)].weight;
            if (cauchyC2 > 0) w /= 1.0 + w * res[i] * res[i] / cauchyC2;
            sx[i] = w * gx[i];
            sy[i] = w * gy[i];
        }
    } else {
        std::fill(sx, sx + 2 * n, 0.0);  // sx and sy: sums over the differences each pixel is in
        for (int pass = 0; pass < 2; ++pass) {
            const int step = pass == 0 ? 1 : cols;
            const std::vector<double>& w0 = fw.w0[pass];
            const int m = std::min(n - step, static_cast<int>(w0.size()));
            for (int i = 0; i < m; ++i) {
                if (!(w0[size_t(i)] > 0)) continue;
                const double d = res[i + step] - res[i];
                double w = w0[size_t(i)];
                if (cauchyC2 > 0) w /= 1.0 + w * d * d / cauchyC2;
                const double hx = w * (gx[i + step] - gx[i]), hy = w * (gy[i + step] - gy[i]);
                sx[i + step] += hx;
                sx[i] -= hx;
                sy[i + step] += hy;
                sy[i] -= hy;
            }
        }
    }
}

// The ROI's residual field img − model (mean removed) and its mean photon + read variance.
__attribute__((always_inline)) inline ResidualField roiResidualField(const cv::Mat& roi, const Vec9& p, int cx, int cy,
                                                                     double gain, double rn2) {
    const double A = p(0), x0 = p(1), y0 = p(2), a = p(3), b = p(4), c = p(5), bx = p(7), by = p(8);
    const int W = roi.cols, H = roi.rows, N = W * H;
    const float* img = roi.ptr<float>();
    thread_local std::vector<double> rq, re;
    rq.resize(size_t(N));
    re.resize(size_t(N));
    const double ox = cx + x0, oy = cy + y0;  // the centre in ROI coordinates
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double dx = x - ox, dy = y - oy;
            rq[size_t(y) * W + x] = a * dx * dx + 2 * b * dx * dy + c * dy * dy;
        }
    kernel::halfNegExp(rq.data(), re.data(), N);
    double* rho = rq.data();  // reused: the residual field
    double mean = 0, vbar = 0;
    for (int y = 0; y < H; ++y) {
        const double dy = y - oy;
        for (int x = 0; x < W; ++x) {
            const int i = y * W + x;
            const double model = A * re[size_t(i)] + p(6) + bx * (x - ox) + by * dy;
            rho[i] = img[i] - model;
            mean += rho[i];
            vbar += std::max(model, 0.0) / gain + rn2;
        }
    }
    mean /= N;
    vbar /= N;
    for (int i = 0; i < N; ++i) rho[i] -= mean;
    return {rho, vbar};
}

// The texture part Σ_l A_s(l)·R(l) of the templates' sandwich, photon and read noise included
// in R(0) (taken out by the caller).
__attribute__((always_inline)) inline CovarianceSums textureSums(const cv::Mat& roi, const double* rho, const FitWindow& fw,
                                                                 const CovarianceArrays& t) {
    const int W = roi.cols, H = roi.rows, N = W * H;
    const int n = static_cast<int>(fw.px.size()), cols = fw.cols, rows = fw.rows;
    const double *sx = t.sx, *sy = t.sy;
    // Σ over the template's lags l of A_s(l)·R(l), R(l) = the lag's sum of products over its pairs,
    // taken directly (kernel::lagSums, vectorised). Lags l and −l are the same pairs: the
    // half-plane ly > 0 or (ly = 0, lx ≥ 0), the others counted twice. (By FFT on a 64² grid this
    // took 4-5 times the fit's instructions; every lag directly, 8 times.)
    // Lags up to half the template's reach (a quarter of the products; the coverage of aero1's
    // shots moved by less than 1 point against every lag), R flat beyond at its edge level.
    constexpr double kLagFraction = 0.5;
    // (At most kernel::kMaxLag either way: a spot of σ 25 px and more.)
    const int lxMax = std::clamp(static_cast<int>(std::lround(kLagFraction * (cols - 1))), 1, kernel::kMaxLag),
              lyMax = std::clamp(static_cast<int>(std::lround(kLagFraction * (rows - 1))), 1, kernel::kMaxLag);
    const int stride = 2 * lxMax + 1, lags = stride * (lyMax + 1);
    // In single precision; the templates as s_x, s_y and s_x + s_y, whose autocorrelations give
    // the symmetrised cross term as (A_x+y − A_xx − A_yy)/2.
    thread_local std::vector<float> lagBuf, fr, fx, fy, fs;
    lagBuf.resize(size_t(lags) * 4);
    fr.assign(rho, rho + N);
    fx.assign(sx, sx + n);
    fy.assign(sy, sy + n);
    fs.resize(size_t(n));
    for (int i = 0; i < n; ++i) fs[size_t(i)] = static_cast<float>(sx[i] + sy[i]);
    float *rr = lagBuf.data(), *axx = rr + lags, *ayy = axx + lags, *asum = ayy + lags;
    kernel::lagSums(fr.data(), fr.data(), W, H, lxMax, lyMax, rr);
    kernel::lagSums(fx.data(), fx.data(), cols, rows, lxMax, lyMax, axx);
    kernel::lagSums(fy.data(), fy.data(), cols, rows, lxMax, lyMax, ayy);
    kernel::lagSums(fs.data(), fs.data(), cols, rows, lxMax, lyMax, asum);
    // Beyond the lags summed, R is taken flat at its mean on the box's edge: the templates sum to
    // zero over all lags, so the lags left out carry −(the sum of A_s inside) times that level.
    double edge = 0;
    int edgeN = 0;
    for (int ly = 0; ly <= lyMax; ++ly)
        for (int lx = -lxMax; lx <= lxMax; ++lx)
            if (ly == lyMax || std::abs(lx) == lxMax) {
                edge += rr[ly * stride + lx + lxMax] / (double(H - ly) * (W - std::abs(lx)));
                ++edgeN;
            }
    edge /= edgeN;
    double txx = 0, txy = 0, tyy = 0;
    for (int ly = 0; ly <= lyMax; ++ly)
        for (int lx = ly == 0 ? 0 : -lxMax; lx <= lxMax; ++lx) {
            const int k = ly * stride + lx + lxMax;
            const double twice = ly == 0 && lx == 0 ? 1.0 : 2.0;
            const double r = twice * (rr[k] / (double(H - ly) * (W - std::abs(lx))) - edge);
            txx += axx[k] * r;
            tyy += ayy[k] * r;
            txy += 0.5 * (double(asum[k]) - axx[k] - ayy[k]) * r;
        }
    return {txx, txy, tyy};
}

__attribute__((target_clones("avx2", "default")))
CentreCovariance groundCentreCovariance(const cv::Mat& roi, const FitWindow& fw, const Vec9& p, const Mat9& jtj,
                                        double cauchyC2, int cx, int cy, const CameraParams& camera, double textureScale) {
    CentreCovariance out;
    Eigen::Matrix<double, kP, 2> unit = Eigen::Matrix<double, kP, 2>::Zero();
    unit(1, 0) = unit(2, 1) = 1;
    const Eigen::LDLT<Mat9> ldlt(jtj);
    if (ldlt.info() != Eigen::Success) return out;
    const Eigen::Matrix<double, kP, 2> hc = ldlt.solve(unit);  // the x0 and y0 columns of (JᵀWJ)⁻¹
    if (!hc.allFinite()) return out;
    const std::vector<WinPixel>& win = fw.px;
    const int n = static_cast<int>(win.size()), cols = fw.cols, rows = fw.rows;
    if (n < 4 || cols < 2 || rows < 2) return out;
    const double gain = camera.gainEPerDn, rn = camera.readNoiseE / camera.gainEPerDn, rn2 = rn * rn;
    const CovarianceArrays t = covarianceArrays(n);
    windowGradients(fw, p, hc, gain, rn2, t);
    centreTemplates(fw, cauchyC2, t);
    const double *sx = t.sx, *sy = t.sy, *v = t.v;
    // Photon and read noise: diagonal.
    double pxx = 0, pxy = 0, pyy = 0;
    for (int i = 0; i < n; ++i) {
        pxx += sx[i] * sx[i] * v[i];
        pxy += sx[i] * sy[i] * v[i];
        pyy += sy[i] * sy[i] * v[i];
    }
    const ResidualField field = roiResidualField(roi, p, cx, cy, gain, rn2);
    const double vbar = field.vbar;
    const CovarianceSums tex = textureSums(roi, field.rho, fw, t);
    double txx = tex.xx, txy = tex.xy, tyy = tex.yy;
    // The photon + read part of R(0) is counted exactly above (pixel by pixel): take its mean out.
    double sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < n; ++i) {
        sxx += sx[i] * sx[i];
        syy += sy[i] * sy[i];
        sxy += sx[i] * sy[i];
    }
    txx -= vbar * sxx;
    tyy -= vbar * syy;
    txy -= vbar * sxy;
    const double k2 = textureScale * textureScale;
    // A texture variance below zero is the estimate's noise: no texture part then.
    const double texX = std::max(txx, 0.0), texY = std::max(tyy, 0.0);
    const double texXY = std::clamp(txy, -std::sqrt(texX * texY), std::sqrt(texX * texY));
    out.xx = pxx + k2 * texX;
    out.yy = pyy + k2 * texY;
    out.xy = pxy + k2 * texXY;
    out.ok = std::isfinite(out.xx) && std::isfinite(out.yy) && std::isfinite(out.xy) && out.xx > 0 && out.yy > 0;
    return out;
}

void fillFit(const GaussModel& m, double noise, SpotFit* f) {
    const double det = m.a * m.c - m.b * m.b;
    const double sxx = m.c / det, syy = m.a / det, sxy = -m.b / det;  // covariance = M⁻¹
    f->x = m.x0;
    f->y = m.y0;
    setShapeFromCovariance(sxx, sxy, syy, 4.0, f);
    f->amplitude = m.amplitude;
    f->background = m.bg0;
    f->snr = m.amplitude / std::max(noise, 1e-9);
}

// Stage 1 (Wu): the domain's pixels above the background, their log-intensity fitted by a
// quadratic with weights f (unit-sum normalised); when it is not peaked, the spot's core, then
// (for LM) the moments of the bright core. False (r->fit.error) when no start is found.
struct LogStart {
    std::vector<DomainPixel> px;
    std::vector<double> wts;
    double S = 0;
    Quad q;
};

bool logFitStart(const float* img, int w, int h, const SpotDomain& domain, double background, const GaussParams& params,
                 LogStart* st, GaussResult* r) {
    const double refX = domain.peakX, refY = domain.peakY;
    std::vector<DomainPixel>& px = st->px;
    px.reserve(domain.pixels.size());
    double S = 0;
    for (int p : domain.pixels) {
        const double f = img[p] - background;
        if (f <= 0) continue;
        px.push_back({p % w - refX, p / w - refY, f, 0});
        S += f;
    }
    if (px.size() < 7) {
        r->fit.error = "Gaussian fit: only " + std::to_string(px.size()) + " domain pixels above the background";
        return false;
    }
    logFractions(px, S);
    std::vector<double>& wts = st->wts;
    wts.resize(px.size());
    for (size_t i = 0; i < px.size(); ++i) wts[i] = px[i].f / S;
    Quad& q = st->q;
    // Paper 000 solves by QR; when Guo passes refine the result anyway, the 6×6 normal
    // equations give the same start for a fraction of the cost.
    const bool qr = params.guoIterations == 0;
    bool peaked = logFit(px, wts, params.xyTerm, qr, &q);
    if (!peaked && params.coreFraction > 0) {
        // Ground brighter than the threshold next to the spot joins the domain through a neck
        // and makes its log-intensity a saddle. The spot's own core — the domain pixels joined
        // to the peak at or above coreFraction of the brightest's height — leaves that ground beyond the
        // dip between them: its log fit is the spot's (the verdict keeps it doubtful).
        std::vector<DomainPixel> core = domainCore(img, w, h, domain, background, params.coreFraction, refX, refY);
        double coreS = 0;
        for (const auto& c : core) coreS += c.f;
        if (core.size() >= 7 && core.size() < px.size()) {
            std::vector<double> coreW(core.size());
            logFractions(core, coreS);
            for (size_t i = 0; i < core.size(); ++i) coreW[i] = core[i].f / coreS;
            if (logFit(core, coreW, params.xyTerm, qr, &q)) {
                px = std::move(core);
                wts = std::move(coreW);
                S = coreS;
                peaked = true;
                r->coreStart = true;
                r->note = "the domain's log-intensity is not peaked (brighter ground joined it): fitted from the spot's "
                          "core";
            }
        }
    }
    st->S = S;
    if (!peaked) {
        // Ground brighter than the threshold around the spot can make the domain's log-intensity
        // a saddle. The spot is still there: start LM from the moments of the domain's bright
        // core (pixels above half the brightest), and say so (the verdict marks it doubtful).
        if (!params.lmRefine || !momentStart(px, S, &q)) {
            r->fit.error = "Gaussian fit failed: the domain's log-intensity is not peaked (no closed spot)";
            return false;
        }
        r->fallbackStart = true;
        r->note = "log fit not peaked: LM started from the moments of the spot's bright core";
    }
    r->stage = r->fallbackStart ? "moments" : "wu";
    return true;
}

// Stage 2 (Guo): the log fit again with weights from the model; a pass that loses the peak
// keeps the one before. The iterations done are added to *iterations.
void guoIterations(const GaussParams& params, LogStart* st, GaussResult* r, int* iterations) {
    std::vector<DomainPixel>& px = st->px;
    std::vector<double>& wts = st->wts;
    Quad& q = st->q;
    std::vector<double> quad(px.size());
    for (int it = 0; it < (r->fallbackStart ? 0 : params.guoIterations); ++it) {
        for (size_t i = 0; i < px.size(); ++i) {
            const double dx = px[i].u - q.x0, dy = px[i].v - q.y0;
            quad[i] = q.a * dx * dx + 2 * q.b * dx * dy + q.c * dy * dy;
        }
        kernel::halfNegExp(quad.data(), wts.data(), static_cast<int>(px.size()));
        const double scale = std::exp(q.lnScale);
        for (double& wt : wts) wt *= scale;
        Quad next;
        if (!logFit(px, wts, params.xyTerm, false, &next)) {
            r->note = "Guo iteration " + std::to_string(it + 1) + " lost the peak; kept the previous pass";
            break;
        }
        q = next;
        r->stage = "guo";
        ++*iterations;
    }
}

// Stage 3: the window and the weights of the LM fit and of every stage's covariance, from the
// start model: the ground's texture (its σ against the photon and read noise), the window's
// pixels (or, on textured ground, their neighbour differences), their variances, the χ² and
// the centre's uncertainty with the texture term.
class LmProblem {
public:
    LmProblem(const cv::Mat& roi, const GaussModel& m, double background, double noise, const GaussParams& params,
              const CameraParams& camera) {
        const int w = roi.cols, h = roi.rows;
        const float* img = roi.ptr<float>();
        det0 = m.a * m.c - m.b * m.b;
        sigmaMajor = std::sqrt(0.5 * (m.a + m.c + std::sqrt((m.a - m.c) * (m.a - m.c) + 4 * m.b * m.b)) / det0);
        // Is the ground textured (background σ well above the photon + read σ)?
        const double g = camera.gainEPerDn, rn = camera.readNoiseE / camera.gainEPerDn;
        const double photonVar = std::max(background, 0.0) / g + rn * rn;
        textured = noise * noise > params.texturedRatio * params.texturedRatio * photonVar;
        const double texVar = std::max(0.0, noise * noise - photonVar);
        // Window for LM (and for the covariance of every stage).
        // Textured ground: fit neighbour differences (see accumulateDifferences).
        // The ground's difference variances also size the texture term of the uncertainty.
        dv_ = groundDifferenceVariances(roi, m);
        diff = textured && params.differenceFit && dv_.ok;
        const double windowSigmas = textured ? (diff ? params.lmWindowSigmasDifference : params.lmWindowSigmasTextured)
                                             : params.lmWindowSigmas;
        const int hw = std::max(params.lmMinHalfWidth, static_cast<int>(std::ceil(windowSigmas * sigmaMajor)));
        cx = static_cast<int>(std::lround(m.x0));
        cy = static_cast<int>(std::lround(m.y0));
        xa = std::max(0, cx - hw);
        xb = std::min(w - 1, cx + hw);
        ya = std::max(0, cy - hw);
        yb = std::min(h - 1, cy + hw);
        fw.cols = xb - xa + 1;
        fw.rows = yb - ya + 1;
        fw.diff = diff;
        fw.diffVarX = dv_.x;
        fw.diffVarY = dv_.y;
        std::vector<WinPixel>& win = fw.px;
        win.reserve(size_t(fw.cols) * fw.rows);
        for (int y = ya; y <= yb; ++y)
            for (int x = xa; x <= xb; ++x) win.push_back({double(x - cx), double(y - cy), img[y * w + x], 1.0});
        if (params.noiseWeights || diff) {
            // 1/variance of each pixel under the start model: photon + read + ground texture; for
            // the difference fit, the spot's own photon variance (the ground's is in fw.diffVar).
            std::vector<double> qw(win.size()), ew(win.size());
            const double ox = m.x0 - cx, oy = m.y0 - cy;
            for (size_t i = 0; i < win.size(); ++i) {
                const double ddx = win[i].dx - ox, ddy = win[i].dy - oy;
                qw[i] = m.a * ddx * ddx + 2 * m.b * ddx * ddy + m.c * ddy * ddy;
            }
            kernel::halfNegExp(qw.data(), ew.data(), static_cast<int>(win.size()));
            for (size_t i = 0; i < win.size(); ++i) {
                if (diff) {
                    win[i].weight = std::max(m.amplitude * ew[i], 0.0) / g;  // the spot's photon variance
                } else {
                    const double model = background + m.amplitude * ew[i];
                    win[i].weight = 1.0 / (std::max(model, 0.0) / g + rn * rn + texVar);
                }
            }
        }
        if (diff) differenceWeights();
        // Textured ground: Cauchy loss (robustScale in residual σ); photon-limited: least squares.
        cauchyC2 = textured && params.robustLoss ? params.robustScale * params.robustScale : 0.0;
        // Covariance of the parameters at p: (JᵀWJ)⁻¹ scaled by the reduced χ².
        const int nres = diff ? fw.rows * (fw.cols - 1) + (fw.rows - 1) * fw.cols : static_cast<int>(win.size());
        dof_ = nres - (diff ? kP - 1 : kP);
        // The covariance treats the residuals as independent; ground texture is not, and moves
        // the centre by about (texture difference σ)·σ_spot/A. That term, calibrated on the photo
        // simulator (tuning seed 11; the tests check the coverage on seed 1), is added in
        // quadrature: texture beyond (1 + deadband) of the photon + read part of a difference counts.
        texDiffVar_ = std::max(0.0, 0.5 * (dv_.x + dv_.y) - 2 * photonVar * (1 + params.uncertaintyDeadband));
        texScale_ = diff ? params.uncertaintyTextureScale : params.uncertaintyTextureScalePixelFit;
        setStart(m, background);
    }

    // p at the start model, and its cost.
    void setStart(const GaussModel& m, double background) {
        p << m.amplitude, m.x0 - cx, m.y0 - cy, m.a, m.b, m.c, background, 0, 0;
        cost = accumulate(fw, p, cauchyC2, &jtj, &jtr);
    }

    // Only the centre's variances are read: the two columns of (JᵀWJ)⁻¹ for x0 and y0.
    double centreVariance() const {
        Eigen::Matrix<double, kP, 2> unit = Eigen::Matrix<double, kP, 2>::Zero();
        unit(1, 0) = unit(2, 1) = 1;
        const Eigen::Matrix<double, kP, 2> cols = jtj.ldlt().solve(unit);
        return (cols(1, 0) + cols(2, 1)) * (dof_ > 0 ? cost.chi2 / dof_ : 1.0);
    }

    double uncertainty(double centreVar, double amplitude) const {
        const double texShift = std::sqrt(texDiffVar_) * sigmaMajor / std::max(amplitude, 1e-9);
        return sqrtVariance(centreVar + (dv_.ok ? texScale_ * texScale_ * texShift * texShift : 0.0));
    }

    FitWindow fw;
    Vec9 p;
    Mat9 jtj;
    Vec9 jtr;
    Cost cost;
    double cauchyC2 = 0, det0 = 0, sigmaMajor = 0;
    bool textured = false, diff = false;
    int cx = 0, cy = 0, xa = 0, xb = 0, ya = 0, yb = 0;

private:
    void differenceWeights() {
        const std::vector<WinPixel>& win = fw.px;
        const int n = static_cast<int>(win.size());
        for (int pass = 0; pass < 2; ++pass) {
            const int step = pass == 0 ? 1 : fw.cols;
            const double groundVar = pass == 0 ? fw.diffVarX : fw.diffVarY;
            std::vector<double>& w0 = fw.w0[pass];
            w0.assign(size_t(std::max(0, n - step)), 0.0);
            // Along a row (a horizontal difference stops at the row's end), row by row.
            const int rowEnd = step == 1 ? fw.cols - 1 : fw.cols;
            for (int row = 0; row * fw.cols + step < n; ++row)
                for (int i = row * fw.cols; i < row * fw.cols + rowEnd && i + step < n; ++i)
                    w0[size_t(i)] = 1.0 / (groundVar + win[size_t(i)].weight + win[size_t(i + step)].weight);
        }
    }

    DifferenceVariances dv_;
    int dof_ = 0;
    double texDiffVar_ = 0, texScale_ = 0;
};

// Stage 4: LM from the start model. It refines; it must not run off: a large move, a shape far
// from the log fit's (a Gaussian stretched along a road) or a centre outside the window means it
// followed the ground, and the log fit is kept (*m unchanged, lp back at the start).
void refineLm(const GaussParams& params, double background, LmProblem* lp, GaussModel* m, GaussResult* r, int* iterations) {
    // A step smaller than a fraction of the centre's uncertainty changes nothing that matters.
    // Not from a moment start (its χ², and so its uncertainty, is inflated by the poor start),
    // and never looser than kMaxTolerancePx (a near-singular start could give any value).
    constexpr double kMaxTolerancePx = 0.05;
    double tolerance = params.lmTolerancePx;
    if (params.lmToleranceFraction > 0 && !r->fallbackStart) {
        const double u0 = lp->uncertainty(lp->centreVariance(), m->amplitude);
        if (std::isfinite(u0)) tolerance = std::max(tolerance, std::min(params.lmToleranceFraction * u0, kMaxTolerancePx));
    }
    Vec9& p = lp->p;
    *iterations += levenbergMarquardt(lp->fw, p, lp->cauchyC2, params.lmMaxIterations, tolerance, params.lmToleranceShape,
                                      lp->jtj, lp->jtr, lp->cost);
    const double moved = std::hypot(p(1) + lp->cx - m->x0, p(2) + lp->cy - m->y0);
    const double pcx = p(1) + lp->cx, pcy = p(2) + lp->cy;
    const double detLm = p(3) * p(5) - p(4) * p(4);
    const double sigmaMajorLm = std::sqrt(0.5 * (p(3) + p(5) + std::sqrt((p(3) - p(5)) * (p(3) - p(5)) + 4 * p(4) * p(4))) / detLm);
    const double areaRatio = std::sqrt(lp->det0 / detLm);  // σ1σ2 of LM over that of the log fit
    // (A moment start's shape is rough: there only the spot-likeness check of finishFit applies.)
    const bool shapeRunOff = !r->fallbackStart && (sigmaMajorLm > params.lmMaxShapeChange * lp->sigmaMajor ||
                                                   areaRatio > params.lmMaxShapeChange || areaRatio < 1 / params.lmMaxShapeChange);
    if (moved > params.lmMaxMovePx || shapeRunOff || pcx < lp->xa - 0.5 || pcx > lp->xb + 0.5 || pcy < lp->ya - 0.5 ||
        pcy > lp->yb + 0.5) {
        r->note = "LM moved the centre by " + std::to_string(moved).substr(0, 5) +
                  " px or changed the shape too much; kept the log-fit result";
        lp->setStart(*m, background);
        return;
    }
    r->stage = "lm";
    m->amplitude = p(0);
    m->x0 = pcx;
    m->y0 = pcy;
    m->a = p(3);
    m->b = p(4);
    m->c = p(5);
    m->bg0 = p(6);
    m->bgX = p(7);
    m->bgY = p(8);
}

// Stage 5: the result: a moment start kept only when LM made a spot of it; the centre's
// uncertainty; paper 000's MSE at the reported model over the domain pixels above the fitted
// background. False (r->fit.error) when refused.
bool finishFit(const cv::Mat& roi, const SpotDomain& domain, double noise, const LmProblem& lp, const GaussModel& m,
               int iterations, const GaussParams& params, const CameraParams& camera, GaussResult* r) {
    fillFit(m, noise, &r->fit);
    if (r->fallbackStart) {
        // A moment start is only a spot when LM made a spot of it: kept, spot-sized (σ 1.5–6 px,
        // axes within 1:2.5) and standing minPeakSnr-like above the ground (6 background σ).
        const double big = std::max(r->fit.sigmaX, r->fit.sigmaY), small = std::min(r->fit.sigmaX, r->fit.sigmaY);
        if (r->stage != "lm" || !(big >= 1.2 && big <= 6 && small * 2.5 >= big) || !(r->fit.snr >= 4.8)) {
            r->fit = SpotFit{};
            r->fit.error = "Gaussian fit failed: the domain's log-intensity is not peaked, and LM from its moments "
                           "found no spot-like Gaussian";
            return false;
        }
    }
    r->fit.uncertaintyPx = lp.uncertainty(lp.centreVariance(), m.amplitude);
    if (params.uncertaintyFromGround) {
        const CentreCovariance cc = groundCentreCovariance(roi, lp.fw, lp.p, lp.jtj, lp.cauchyC2, lp.cx, lp.cy, camera,
                                                           lp.cauchyC2 > 0 ? params.uncertaintyScale : 1.0);
        if (cc.ok) {
            r->fit.covXX = cc.xx;
            r->fit.covXY = cc.xy;
            r->fit.covYY = cc.yy;
            r->fit.uncertaintyPx = std::sqrt(cc.xx + cc.yy);
            r->fit.radius95Px = params.radius95Factor * r->fit.uncertaintyPx;
        }
    }
    const int w = roi.cols;
    const float* img = roi.ptr<float>();
    thread_local std::vector<double> mseF, mseQ;
    mseF.clear();
    mseQ.clear();
    for (int pi : domain.pixels) {
        const double x = pi % w, y = pi / w, dx = x - m.x0, dy = y - m.y0;
        const double f = img[pi] - (m.bg0 + m.bgX * dx + m.bgY * dy);
        if (f <= 0) continue;
        mseF.push_back(f);
        mseQ.push_back(m.a * dx * dx + 2 * m.b * dx * dy + m.c * dy * dy);
    }
    r->fit.mse = paperMse(mseF, mseQ, m.amplitude);
    r->fit.areaPx = static_cast<double>(domain.pixels.size());
    r->fit.iterations = iterations;
    r->model = m;
    r->fit.ok = std::isfinite(r->fit.x) && std::isfinite(r->fit.y);
    if (!r->fit.ok) r->fit.error = "Gaussian fit produced a non-finite centre";
    return true;
}

}  // namespace

GaussResult fitGauss(const cv::Mat& roi, const SpotDomain& domain, double background, double noise,
                     const GaussParams& params, const CameraParams& camera) {
    GaussResult r;
    if (!domain.found) {
        r.fit.error = domain.why.empty() ? "no spot domain" : domain.why;
        return r;
    }
    const int w = roi.cols, h = roi.rows;
    LogStart st;
    if (!logFitStart(roi.ptr<float>(), w, h, domain, background, params, &st, &r)) return r;
    int iterations = 1;
    guoIterations(params, &st, &r, &iterations);
    const Quad& q = st.q;
    GaussModel m;
    m.amplitude = st.S * std::exp(q.lnScale);
    m.x0 = q.x0 + domain.peakX;
    m.y0 = q.y0 + domain.peakY;
    m.a = q.a;
    m.b = q.b;
    m.c = q.c;
    m.bg0 = background;
    if (!(m.x0 > -0.5 && m.y0 > -0.5 && m.x0 < w - 0.5 && m.y0 < h - 0.5)) {
        r.fit.error = "Gaussian fit failed: centre (" + std::to_string(m.x0) + ", " + std::to_string(m.y0) +
                      ") outside the ROI";
        return r;
    }
    LmProblem lp(roi, m, background, noise, params, camera);
    if (params.lmRefine) refineLm(params, background, &lp, &m, &r, &iterations);
    finishFit(roi, domain, noise, lp, m, iterations, params, camera, &r);
    return r;
}

}  // namespace lwb::core::footprint
