#include "core/footprint/gauss_kernel.hpp"

#include <cstring>
#include <vector>

#include <cmath>

namespace lwb::core::footprint::kernel {

__attribute__((target_clones("avx2", "default")))
void halfNegExp(const double* q, double* out, int n) {
#pragma omp simd
    for (int i = 0; i < n; ++i) out[i] = std::exp(-0.5 * q[i]);
}

__attribute__((target_clones("avx2", "default")))
void logOfRatio(const double* f, double S, double* out, int n) {
#pragma omp simd
    for (int i = 0; i < n; ++i) out[i] = std::log(f[i] / S);
}

// For each row pair (y, y + ly) and each pixel of row y, the 2·lxMax + 1 products with the
// other row's pixels around it are one contiguous multiply-add into the lag accumulators (the
// other row zero-padded on both sides), which vectorises across the lags. The accumulators are
// V vectors of eight lanes held in registers for a whole ly (V fixed per instantiation: the
// lags rounded up to a multiple of eight; the spare lanes sum zeros and products past the
// field's edge, never read). With U = 2 sets of them, even and odd pixels of a row go to
// different sets, added at the end of the ly: one set waited on each addition's latency (three
// cycles a pixel whatever V), two keep the multiply and add units busy (issue 32: the lag sums
// 1.6 times faster). In single precision: the sums feed a variance estimate good to a few per
// cent at best.
namespace {
typedef float v8f __attribute__((vector_size(32)));

template <int V, int U>
__attribute__((always_inline)) inline void lagSumsV(const float* u, const float* w, int width, int height, int lxMax,
                                                    int lyMax, float* row, float* out) {
    const int stride = 2 * lxMax + 1;
    for (int ly = 0; ly <= lyMax; ++ly) {
        v8f acc[U][V];
        for (int s = 0; s < U; ++s)
            for (int v = 0; v < V; ++v) acc[s][v] = v8f{};
        for (int y = 0; y + ly < height; ++y) {
            const float* ur = u + static_cast<long>(y) * width;
            std::memcpy(row + lxMax, w + static_cast<long>(y + ly) * width, sizeof(float) * static_cast<size_t>(width));
            int x = 0;
            for (; x + U <= width; x += U)
                for (int s = 0; s < U; ++s) {
                    const v8f a = v8f{} + ur[x + s];
                    for (int v = 0; v < V; ++v) {
                        v8f b;
                        std::memcpy(&b, row + x + s + 8 * v, sizeof b);  // row[x + k] = w(x + k − lxMax, y + ly)
                        acc[s][v] += a * b;
                    }
                }
            for (; x < width; ++x) {
                const v8f a = v8f{} + ur[x];
                for (int v = 0; v < V; ++v) {
                    v8f b;
                    std::memcpy(&b, row + x + 8 * v, sizeof b);
                    acc[0][v] += a * b;
                }
            }
        }
        for (int s = 1; s < U; ++s)
            for (int v = 0; v < V; ++v) acc[0][v] += acc[s][v];
        float lanes[8 * V];
        std::memcpy(lanes, acc[0], sizeof lanes);
        for (int k = 0; k < stride; ++k) out[ly * stride + k] = lanes[k];
    }
}
}  // namespace

__attribute__((target_clones("avx2", "default")))
void lagSums(const float* u, const float* w, int width, int height, int lxMax, int lyMax, float* out) {
    const int vectors = (2 * lxMax + 1 + 7) / 8;  // ≤ 8 (lxMax ≤ kMaxLag)
    thread_local std::vector<float> rowBuf;
    rowBuf.assign(static_cast<size_t>(width) + 8 * static_cast<size_t>(vectors) + 8, 0.0f);
    float* row = rowBuf.data();
    // Two accumulator sets while they and a product fit the sixteen vector registers.
    switch (vectors) {
        case 1: lagSumsV<1, 2>(u, w, width, height, lxMax, lyMax, row, out); break;
        case 2: lagSumsV<2, 2>(u, w, width, height, lxMax, lyMax, row, out); break;
        case 3: lagSumsV<3, 2>(u, w, width, height, lxMax, lyMax, row, out); break;
        case 4: lagSumsV<4, 2>(u, w, width, height, lxMax, lyMax, row, out); break;
        case 5: lagSumsV<5, 2>(u, w, width, height, lxMax, lyMax, row, out); break;
        case 6: lagSumsV<6, 2>(u, w, width, height, lxMax, lyMax, row, out); break;
        case 7: lagSumsV<7, 1>(u, w, width, height, lxMax, lyMax, row, out); break;
        default: lagSumsV<8, 1>(u, w, width, height, lxMax, lyMax, row, out); break;
    }
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
// The differences of the six columns are formed once per block of up to 1024 (kept in L1), and
// the 33 sums are taken in three register-blocked passes over them (11, 11 and 11 running sums):
// each loaded difference feeds several multiply–adds, where one dot product per entry loaded
// two numbers for each.
__attribute__((target_clones("avx2", "default")))
void differenceGram(const double* P, int n, int step, const double* w, const double* r, double* gram, double* rhs,
                    double* wd, double* sw, double* swr) {
    constexpr int K = kGramColumns;
    const int m = n - step;
    thread_local double dif[K][1024];
    double g[K][K] = {}, rh[K] = {}, ws[K] = {}, s0 = 0, s1 = 0;
    for (int base = 0; base < m; base += 1024) {
        const int len = m - base < 1024 ? m - base : 1024;
        for (int u = 0; u < K; ++u) {
            const double* pu = P + static_cast<long>(u) * n + base;
            double* d = dif[u];
#pragma omp simd
            for (int i = 0; i < len; ++i) d[i] = pu[i + step] - pu[i];
        }
        const double* d0 = dif[0];
        const double* d1 = dif[1];
        const double* d2 = dif[2];
        const double* d3 = dif[3];
        const double* d4 = dif[4];
        const double* d5 = dif[5];
        const double* wb = w + base;
        const double* rb = r + base;
        {  // columns 0 and 1 of the Gram matrix
            double a00 = 0, a10 = 0, a20 = 0, a30 = 0, a40 = 0, a50 = 0, a11 = 0, a21 = 0, a31 = 0, a41 = 0, a51 = 0;
#pragma omp simd reduction(+ : a00, a10, a20, a30, a40, a50, a11, a21, a31, a41, a51)
            for (int i = 0; i < len; ++i) {
                const double x0 = wb[i] * d0[i], x1 = wb[i] * d1[i];
                a00 += x0 * d0[i];
                a10 += x0 * d1[i];
                a20 += x0 * d2[i];
                a30 += x0 * d3[i];
                a40 += x0 * d4[i];
                a50 += x0 * d5[i];
                a11 += x1 * d1[i];
                a21 += x1 * d2[i];
                a31 += x1 * d3[i];
                a41 += x1 * d4[i];
                a51 += x1 * d5[i];
            }
            g[0][0] += a00, g[1][0] += a10, g[2][0] += a20, g[3][0] += a30, g[4][0] += a40, g[5][0] += a50;
            g[1][1] += a11, g[2][1] += a21, g[3][1] += a31, g[4][1] += a41, g[5][1] += a51;
        }
        {  // columns 2 and 3, and the right-hand side w·d·r
            double a22 = 0, a32 = 0, a42 = 0, a52 = 0, a33 = 0, a43 = 0, a53 = 0;
            double r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
#pragma omp simd reduction(+ : a22, a32, a42, a52, a33, a43, a53, r0, r1, r2, r3, r4, r5)
            for (int i = 0; i < len; ++i) {
                const double x2 = wb[i] * d2[i], x3 = wb[i] * d3[i], wr = wb[i] * rb[i];
                a22 += x2 * d2[i];
                a32 += x2 * d3[i];
                a42 += x2 * d4[i];
                a52 += x2 * d5[i];
                a33 += x3 * d3[i];
                a43 += x3 * d4[i];
                a53 += x3 * d5[i];
                r0 += wr * d0[i];
                r1 += wr * d1[i];
                r2 += wr * d2[i];
                r3 += wr * d3[i];
                r4 += wr * d4[i];
                r5 += wr * d5[i];
            }
            g[2][2] += a22, g[3][2] += a32, g[4][2] += a42, g[5][2] += a52, g[3][3] += a33, g[4][3] += a43;
            g[5][3] += a53;
            rh[0] += r0, rh[1] += r1, rh[2] += r2, rh[3] += r3, rh[4] += r4, rh[5] += r5;
        }
        {  // columns 4 and 5, the sums w·d, and Σw, Σw·r
            double a44 = 0, a54 = 0, a55 = 0, c0 = 0, c1 = 0, c2 = 0, c3 = 0, c4 = 0, c5 = 0, t0 = 0, t1 = 0;
#pragma omp simd reduction(+ : a44, a54, a55, c0, c1, c2, c3, c4, c5, t0, t1)
            for (int i = 0; i < len; ++i) {
                const double x4 = wb[i] * d4[i], x5 = wb[i] * d5[i];
                a44 += x4 * d4[i];
                a54 += x4 * d5[i];
                a55 += x5 * d5[i];
                c0 += wb[i] * d0[i];
                c1 += wb[i] * d1[i];
                c2 += wb[i] * d2[i];
                c3 += wb[i] * d3[i];
                c4 += x4;
                c5 += x5;
                t0 += wb[i];
                t1 += wb[i] * rb[i];
            }
            g[4][4] += a44, g[5][4] += a54, g[5][5] += a55;
            ws[0] += c0, ws[1] += c1, ws[2] += c2, ws[3] += c3, ws[4] += c4, ws[5] += c5;
            s0 += t0, s1 += t1;
        }
    }
    for (int u = 0; u < K; ++u) {
        rhs[u] = rh[u];
        wd[u] = ws[u];
        for (int v = 0; v <= u; ++v) gram[u * K + v] = g[u][v];
    }
    *sw = s0;
    *swr = s1;
}

// Two passes of up to 15 and 6 running sums, so each stays in registers.
__attribute__((target_clones("avx2", "default")))
void logMoments(const double* pix, const double* w, int n, double* m, double* r) {
    double s00 = 0, s10 = 0, s01 = 0, s20 = 0, s11 = 0, s02 = 0, s30 = 0, s21 = 0, s12 = 0, s03 = 0, s40 = 0,
           s31 = 0, s22 = 0, s13 = 0, s04 = 0;
#pragma omp simd reduction(+ : s00, s10, s01, s20, s11, s02, s30, s21, s12, s03, s40, s31, s22, s13, s04)
    for (int i = 0; i < n; ++i) {
        const double u = pix[4 * i], v = pix[4 * i + 1], w2 = w[i] * w[i];
        const double wu = w2 * u, wv = w2 * v, wuu = wu * u, wuv = wu * v, wvv = wv * v;
        s00 += w2;
        s10 += wu;
        s01 += wv;
        s20 += wuu;
        s11 += wuv;
        s02 += wvv;
        s30 += wuu * u;
        s21 += wuu * v;
        s12 += wuv * v;
        s03 += wvv * v;
        s40 += wuu * u * u;
        s31 += wuu * u * v;
        s22 += wuu * v * v;
        s13 += wuv * v * v;
        s04 += wvv * v * v;
    }
    const double out[15] = {s00, s10, s01, s20, s11, s02, s30, s21, s12, s03, s40, s31, s22, s13, s04};
    for (int k = 0; k < 15; ++k) m[k] = out[k];
    double r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
#pragma omp simd reduction(+ : r0, r1, r2, r3, r4, r5)
    for (int i = 0; i < n; ++i) {
        const double u = pix[4 * i], v = pix[4 * i + 1], y = w[i] * w[i] * pix[4 * i + 3];
        r0 += y;
        r1 += y * u;
        r2 += y * v;
        r3 += y * u * u;
        r4 += y * u * v;
        r5 += y * v * v;
    }
    r[0] = r0, r[1] = r1, r[2] = r2, r[3] = r3, r[4] = r4, r[5] = r5;
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
