#include "core/footprint/gauss_kernel.hpp"

#include <cmath>

namespace lwb::core::footprint::kernel {

void halfNegExp(const double* q, double* out, int n) {
#pragma omp simd
    for (int i = 0; i < n; ++i) out[i] = std::exp(-0.5 * q[i]);
}

double cauchyCostSum(const double* z2, int n, double c2) {
    const double inv = 1.0 / c2;
    double sum = 0;
#pragma omp simd reduction(+ : sum)
    for (int i = 0; i < n; ++i) sum += std::log(1.0 + z2[i] * inv);
    return c2 * sum;
}

}  // namespace lwb::core::footprint::kernel
