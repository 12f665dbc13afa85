#include "core/footprint/gauss_kernel.hpp"

#include <cmath>

namespace lwb::core::footprint::kernel {

__attribute__((target_clones("avx2", "default")))
void halfNegExp(const double* q, double* out, int n) {
#pragma omp simd
    for (int i = 0; i < n; ++i) out[i] = std::exp(-0.5 * q[i]);
}

__attribute__((target_clones("avx2", "default")))
double differenceWeights(const double* res, int m, int step, const double* w0, double c2, double* w, double* dr,
                         double* chi2) {
    double cost = 0, x2 = 0;
    if (c2 > 0) {
        const double inv = 1.0 / c2;
        float lsum = 0;
#pragma omp simd reduction(+ : x2, lsum)
        for (int i = 0; i < m; ++i) {
            const double d = res[i + step] - res[i];
            const double z = w0[i] * d * d;
            const double wi = w0[i] / (1.0 + z * inv);
            w[i] = wi;
            dr[i] = d;
            x2 += wi * d * d;
            lsum += std::log(1.0f + static_cast<float>(z * inv));
        }
        cost = c2 * lsum;
    } else {
#pragma omp simd reduction(+ : x2)
        for (int i = 0; i < m; ++i) {
            const double d = res[i + step] - res[i];
            w[i] = w0[i];
            dr[i] = d;
            x2 += w0[i] * d * d;
        }
        cost = x2;
    }
    *chi2 = x2;
    return cost;
}

// Built for AVX2 as well as the baseline; the loader picks the one the processor runs.
__attribute__((target_clones("avx2", "default")))
void differenceGram(const double* P, int n, int k, int step, const double* w, const double* r, double* gram,
                    double* rhs, double* wd) {
    const int m = n - step;
    thread_local double dif[8][1024], wdif[8][1024];
    // Blocks of up to 1024 differences keep the columns in L1. Each column is kept plain and
    // weighted (w·d): a Gram entry is then one multiply–add of two loads per difference.
    for (int base = 0; base < m; base += 1024) {
        const int len = m - base < 1024 ? m - base : 1024;
        for (int u = 0; u < k; ++u) {
            const double* pu = P + static_cast<long>(u) * n + base;
            double* d = dif[u];
            double* wdu = wdif[u];
#pragma omp simd
            for (int i = 0; i < len; ++i) {
                d[i] = pu[i + step] - pu[i];
                wdu[i] = w[base + i] * d[i];
            }
        }
        for (int u = 0; u < k; ++u) {
            const double* wu = wdif[u];
            double acc = 0, acc1 = 0;
#pragma omp simd reduction(+ : acc, acc1)
            for (int i = 0; i < len; ++i) {
                acc += wu[i] * r[base + i];
                acc1 += wu[i];
            }
            rhs[u] = (base == 0 ? 0.0 : rhs[u]) + acc;
            wd[u] = (base == 0 ? 0.0 : wd[u]) + acc1;
            for (int v = 0; v <= u; ++v) {
                const double* dv = dif[v];
                double g = 0;
#pragma omp simd reduction(+ : g)
                for (int i = 0; i < len; ++i) g += wu[i] * dv[i];
                gram[u * k + v] = (base == 0 ? 0.0 : gram[u * k + v]) + g;
            }
        }
    }
    if (m <= 0)
        for (int u = 0; u < k; ++u) {
            rhs[u] = wd[u] = 0;
            for (int v = 0; v <= u; ++v) gram[u * k + v] = 0;
        }
}

__attribute__((target_clones("avx2", "default")))
double cauchyCostSum(const double* z2, int n, double c2) {
    const double inv = 1.0 / c2;
    double sum = 0;
#pragma omp simd reduction(+ : sum)
    for (int i = 0; i < n; ++i) sum += std::log(1.0 + z2[i] * inv);
    return c2 * sum;
}

}  // namespace lwb::core::footprint::kernel
