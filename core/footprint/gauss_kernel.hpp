#pragma once
// The innermost loop of the Gaussian fit, in its own translation unit so that it alone is
// compiled with -ffast-math (which lets GCC call glibc's vectorised exp). Nothing here tests
// for NaN or relies on IEEE corner cases.

namespace lwb::core::footprint::kernel {

/// out[i] = exp(−½ q[i]) for i < n.
void halfNegExp(const double* q, double* out, int n);
/// Sum of the Cauchy costs c²·ln(1 + z2[i]/c²) for i < n.
double cauchyCostSum(const double* z2, int n, double c2);

}  // namespace lwb::core::footprint::kernel
