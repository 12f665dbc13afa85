#include "core/footprint/background.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lwb::core::footprint {

const char* noiseClassName(NoiseClass c) {
    switch (c) {
        case NoiseClass::Night: return "night";
        case NoiseClass::Weak: return "weak";
        case NoiseClass::Moderate: return "moderate";
        case NoiseClass::Strong: return "strong";
    }
    return "?";
}

namespace {
// Histogram of the ROI (at most 4096 bins, 1 DN wide for 14-bit data) from which the clipped
// median and MAD are read in O(bins) per clipping pass: no sorting, no per-pass copies.
struct Histogram {
    float lo = 0, width = 1;
    std::vector<int> counts;
    float value(double bin) const { return static_cast<float>(lo + bin * width); }
};

Histogram buildHistogram(const cv::Mat& roi) {
    Histogram h;
    double mn = 0, mx = 0;
    cv::minMaxLoc(roi, &mn, &mx);
    h.lo = static_cast<float>(mn);
    const double span = mx - mn;
    // 1 DN per bin for integer data, at most 4096 bins; float data with a spread under a DN
    // still gets two bins or more (at least a bin per half of the spread).
    int bins = span > 0 ? static_cast<int>(std::clamp(std::floor(span) + 1, 2.0, 4096.0)) : 1;
    h.width = bins > 1 ? static_cast<float>(span / (bins - 1)) : 1.0f;
    if (!(h.width > 0) || !std::isfinite(h.width)) {  // a spread below the smallest float
        bins = 1;
        h.width = 1.0f;
    }
    h.counts.assign(static_cast<size_t>(bins), 0);
    const size_t last = static_cast<size_t>(bins - 1);
    // The bin index in double and clamped before the cast: float arithmetic over a spread near
    // FLT_MAX would give inf, and casting inf is undefined.
    const double invD = 1.0 / h.width, lastD = static_cast<double>(last);
    for (int y = 0; y < roi.rows; ++y) {
        const float* row = roi.ptr<float>(y);
        for (int x = 0; x < roi.cols; ++x) {
            const double b = (static_cast<double>(row[x]) - h.lo) * invD + 0.5;
            ++h.counts[static_cast<size_t>(std::clamp(b, 0.0, lastD))];
        }
    }
    return h;
}
}  // namespace

BackgroundResult estimateBackground(const cv::Mat& roi, const BackgroundParams& params) {
    BackgroundResult r;
    if (roi.empty() || roi.type() != CV_32FC1) {
        r.error = "background: ROI must be a non-empty CV_32FC1 image";
        return r;
    }
    const Histogram h = buildHistogram(roi);
    const int nb = static_cast<int>(h.counts.size());
    // cum[b] = pixels in bins 0..b-1, so any clipped median / MAD is a binary search.
    std::vector<long> cum(static_cast<size_t>(nb) + 1, 0);
    for (int b = 0; b < nb; ++b) cum[b + 1] = cum[b] + h.counts[b];
    auto countIn = [&](int lo, int hi) { return cum[std::max(hi, -1) + 1] - cum[std::max(lo, 0)]; };  // bins lo..hi
    int top = nb - 1;  // last bin kept by the clip
    int medianBin = 0, madBins = 0;
    for (int it = 0; it <= params.iterations; ++it) {
        const long m = cum[top + 1];
        if (m < 8) break;
        // Median: first bin where the cumulative count passes half.
        medianBin = static_cast<int>(std::upper_bound(cum.begin() + 1, cum.begin() + top + 2, m / 2) - cum.begin()) - 1;
        // MAD: smallest radius (in bins) around the median holding half of the kept pixels.
        int lo = 0, hi = std::max(medianBin, top - medianBin);
        while (lo < hi) {
            const int mid = (lo + hi) / 2;
            if (2 * countIn(medianBin - mid, std::min(medianBin + mid, top)) >= m) hi = mid;
            else lo = mid + 1;
        }
        madBins = lo;
        const double sigma = std::max(1.4826 * madBins * h.width, 0.5);
        // In double, clamped before the cast: with a bin width far below a DN (float data of
        // tiny values) the clip level is ~1e12 bins away and would overflow an int.
        const double nextBin = (h.value(medianBin) + params.clipSigma * sigma - h.lo) / h.width;
        const int next = nextBin >= top ? top : static_cast<int>(std::max(nextBin, 0.0));
        if (next >= top) break;
        top = next;
    }
    r.level = h.value(medianBin);
    r.noise = std::max(1.4826 * madBins * h.width, 0.5);  // never zero: quantisation alone gives ~0.3 DN
    if (r.level < params.nightBelow) r.noiseClass = NoiseClass::Night;
    else if (r.level < params.weakBelow) r.noiseClass = NoiseClass::Weak;
    else if (r.level <= params.strongAbove) r.noiseClass = NoiseClass::Moderate;
    else r.noiseClass = NoiseClass::Strong;
    r.ok = true;
    return r;
}

}  // namespace lwb::core::footprint
