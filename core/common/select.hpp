#pragma once
// The k-th smallest of a set of floats, exactly (the value std::nth_element puts at k), fast for
// what image statistics mostly see: pixel values and their differences, whole numbers in
// [0, 65535] (14- and 16-bit cameras). Those are counted in two 256-bin histograms (high byte,
// then the low bytes in the high byte holding rank k): two passes without a data-dependent
// branch, where nth_element's partitions mispredict about once a comparison (a median of 900
// pixel differences took 5 µs, a tenth of a footprint shot). Anything else (fractions,
// negatives, larger values, NaN) goes to std::nth_element; v is reordered only then.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

// The whole-number test below needs strict single-precision arithmetic.
#if defined(__FAST_MATH__)
#error "core/common/select.hpp must not be compiled with -ffast-math (kthSmallest's whole-number test)"
#endif
#include <cfloat>
static_assert(FLT_EVAL_METHOD == 0, "kthSmallest's whole-number test needs float arithmetic in float");

namespace lwb::core {

inline float kthSmallest(std::vector<float>& v, size_t k) {
    const size_t n = v.size();
    // Whole numbers in [0, 65535]: (x + 2²³) − 2²³ rounds x to a whole number (the float spacing
    // there is 1), so it equals x exactly when x is one. Comparisons only: vectorises; NaN fails. (Not
    // for -ffast-math translation units, which may fold the sum away.)
    int small = n > 0 && k < n;
    for (size_t i = 0; i < n; ++i) {
        const float x = v[i];
        small &= (x >= 0.0f) & (x <= 65535.0f) & ((x + 8388608.0f) - 8388608.0f == x);
    }
    if (!small) {
        std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
        return v[k];
    }
    // Four interleaved histograms per level: neighbouring values mostly share a bin, and one
    // histogram would make each count wait for the previous one's store.
    constexpr int kWays = 4;
    std::array<std::array<uint32_t, 256>, kWays> hi{}, lo{};
    for (size_t i = 0; i < n; ++i) ++hi[i % kWays][static_cast<uint32_t>(static_cast<int>(v[i])) >> 8];
    auto count = [&](const std::array<std::array<uint32_t, 256>, kWays>& c, uint32_t b) {
        uint32_t sum = 0;
        for (int w = 0; w < kWays; ++w) sum += c[w][b];
        return sum;
    };
    uint32_t h = 0;
    size_t below = 0;
    while (below + count(hi, h) <= k) below += count(hi, h++);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t u = static_cast<uint32_t>(static_cast<int>(v[i]));
        lo[i % kWays][u & 255] += (u >> 8) == h;
    }
    uint32_t l = 0;
    while (below + count(lo, l) <= k) below += count(lo, l++);
    return static_cast<float>((h << 8) | l);
}

/// The smallest and largest of v[0..n), n ≥ 1, finite values. Four running pairs: one chain
/// waited on each comparison (min and max give the same result in any order).
inline std::pair<double, double> minMaxOf(const double* v, size_t n) {
    double lo[4] = {v[0], v[0], v[0], v[0]}, hi[4] = {v[0], v[0], v[0], v[0]};
    size_t i = 1;
    for (; i + 4 <= n; i += 4)
        for (int k = 0; k < 4; ++k) {
            lo[k] = std::min(lo[k], v[i + k]);
            hi[k] = std::max(hi[k], v[i + k]);
        }
    for (; i < n; ++i) {
        lo[0] = std::min(lo[0], v[i]);
        hi[0] = std::max(hi[0], v[i]);
    }
    return {std::min(std::min(lo[0], lo[1]), std::min(lo[2], lo[3])), std::max(std::max(hi[0], hi[1]), std::max(hi[2], hi[3]))};
}

}  // namespace lwb::core
