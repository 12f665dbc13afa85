#pragma once
// The innermost loop of the Gaussian fit, in its own translation unit so that it alone is
// compiled with -ffast-math (which lets GCC call glibc's vectorised exp). Nothing here tests
// for NaN or relies on IEEE corner cases.

namespace lwb::core::footprint::kernel {

/// Lag sums of two width × height fields (row-major): out[(ly)·(2·lxMax + 1) + lx + lxMax] =
/// Σ u(x, y)·w(x + lx, y + ly) over the pairs inside the field, for 0 ≤ ly ≤ lyMax and
/// |lx| ≤ lxMax (both below the field's size). Single precision.
constexpr int kMaxLag = 31;  ///< lagSums' largest |lx|
void lagSums(const float* u, const float* w, int width, int height, int lxMax, int lyMax, float* out);
/// out[i] = exp(−½ q[i]) for i < n.
void halfNegExp(const double* q, double* out, int n);
/// out[i] = ln(f[i] / S) for i < n.
void logOfRatio(const double* f, double S, double* out, int n);
/// Sum of the Cauchy costs c²·ln(1 + z2[i]/c²) for i < n.
double cauchyCostSum(const double* z2, int n, double c2);
/// Difference-fit weights: for i < m, dr[i] = res[i + step] − res[i], z = w0[i]·dr², w[i] = w0[i]
/// (or w0[i]/(1 + z/c2) with the Cauchy loss, c2 > 0). Returns Σ w·dr² in *chi2 and the cost:
/// Σ z, or Σ c2·ln(1 + z/c2) (in single precision: it only ranks LM trial steps).
double differenceWeights(const double* res, int m, int step, const double* w0, double c2, double* w, double* dr,
                         double* chi2);
/// Weighted moments of the log fit's domain pixels, given as n quadruples (u, v, f, ln fn) at
/// pix[4i..4i+3] with weights w[i]: m[k] = Σ w²·u^i·v^j for the 15 monomials of degree ≤ 4 in
/// the order 1, u, v, u², uv, v², u³, u²v, uv², v³, u⁴, u³v, u²v², uv³, v⁴, and
/// r[k] = Σ w²·ln fn·(1, u, v, u², uv, v²)[k].
void logMoments(const double* pix, const double* w, int n, double* m, double* r);

/// Columns of the difference fit's Gram kernel: the spot's six parameters.
constexpr int kGramColumns = 6;
/// Weighted Gram matrix of neighbour differences for the difference fit: with
/// d_u[i] = P[u·n + i + step] − P[u·n + i], gram[u·6 + v] = Σ_i w[i]·d_u[i]·d_v[i] (v ≤ u, lower
/// triangle filled), rhs[u] = Σ_i w[i]·d_u[i]·r[i], wd[u] = Σ_i w[i]·d_u[i], *sw = Σ_i w[i] and
/// *swr = Σ_i w[i]·r[i], for i < n − step and u, v < 6.
void differenceGram(const double* P, int n, int step, const double* w, const double* r, double* gram, double* rhs,
                    double* wd, double* sw, double* swr);

}  // namespace lwb::core::footprint::kernel
