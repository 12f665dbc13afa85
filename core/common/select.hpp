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
#include <vector>

namespace lwb::core {

inline float kthSmallest(std::vector<float>& v, size_t k) {
    const size_t n = v.size();
    bool small = n > 0 && k < n;
    for (float x : v) small &= x >= 0.0f && x <= 65535.0f && x == static_cast<float>(static_cast<int>(x));
    if (!small) {
        std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
        return v[k];
    }
    std::array<uint32_t, 256> hi{}, lo{};
    for (float x : v) ++hi[static_cast<uint32_t>(x) >> 8];
    uint32_t h = 0;
    size_t below = 0;
    while (below + hi[h] <= k) below += hi[h++];
    for (float x : v) {
        const uint32_t u = static_cast<uint32_t>(x);
        lo[u & 255] += (u >> 8) == h;
    }
    uint32_t l = 0;
    while (below + lo[l] <= k) below += lo[l++];
    return static_cast<float>((h << 8) | l);
}

}  // namespace lwb::core
