#include "core/common/display_stretch.hpp"

#include <algorithm>
#include <cmath>

namespace lwb::core {

namespace {
std::vector<float> finiteSample(const float* v, size_t n, size_t maxSamples) {
    std::vector<float> out;
    if (!v || n == 0) return out;
    const size_t stride = std::max<size_t>(1, maxSamples ? n / maxSamples : 1);
    for (size_t i = 0; i < n && (maxSamples == 0 || out.size() < maxSamples); i += stride)
        if (std::isfinite(v[i])) out.push_back(v[i]);
    return out;
}

std::vector<float> finiteValues(const float* v, size_t n) {
    std::vector<float> out;
    out.reserve(n);
    for (size_t i = 0; i < n; ++i)
        if (std::isfinite(v[i])) out.push_back(v[i]);
    return out;
}
}  // namespace

ZScaleResult zscale(const float* values, size_t count, const ZScaleParams& p) {
    ZScaleResult r;
    std::vector<float> s = finiteSample(values, count, p.maxSamples);
    if (s.empty()) {
        r.error = "no finite values to scale";
        return r;
    }
    std::sort(s.begin(), s.end());
    const size_t n = s.size();
    r.samples = n;
    const double zmin = s.front(), zmax = s.back();
    const size_t centre = (n - 1) / 2;
    const double median = n % 2 ? s[centre] : 0.5 * (double(s[centre]) + s[centre + 1]);
    r.ok = true;
    const size_t minUsed = std::max(p.minSamples, static_cast<size_t>(n * p.maxReject));
    if (n < minUsed || n < 2) {
        r.z1 = zmin;
        r.z2 = zmax;
        r.used = n;
        r.fitFailed = true;
        return r;
    }
    // Line fit of value against rank with k-sigma rejection; rejections grown by ngrow ranks.
    const size_t ngrow = std::max<size_t>(1, static_cast<size_t>(n * 0.01));
    std::vector<char> good(n, 1);
    size_t used = n;
    double a = 0, b = 0;
    for (int it = 0; it < std::max(1, p.maxIterations); ++it) {
        double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (size_t i = 0; i < n; ++i) {
            if (!good[i]) continue;
            const double x = double(i), y = s[i];
            sw += 1;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
        const double det = sw * sxx - sx * sx;
        if (sw < 2 || det <= 0) break;
        b = (sw * sxy - sx * sy) / det;
        a = (sy - b * sx) / sw;
        double ss = 0;
        for (size_t i = 0; i < n; ++i)
            if (good[i]) ss += std::pow(s[i] - (a + b * double(i)), 2);
        const double sigma = std::sqrt(ss / sw);
        // A perfect line (e.g. a ramp): nothing to reject; rounding must not start a cascade.
        if (sigma <= 1e-9 * (std::fabs(zmax - zmin) + 1)) break;
        const double thr = p.rejectSigma * sigma;
        std::vector<char> bad(n, 0);
        for (size_t i = 0; i < n; ++i)
            if (std::fabs(s[i] - (a + b * double(i))) > thr) bad[i] = 1;
        std::vector<char> next(n, 1);
        for (size_t i = 0; i < n; ++i) {
            if (!bad[i]) continue;
            const size_t from = i >= ngrow ? i - ngrow : 0, to = std::min(n - 1, i + ngrow);
            for (size_t k = from; k <= to; ++k) next[k] = 0;
        }
        size_t nextUsed = 0;
        for (char g : next) nextUsed += g;
        if (nextUsed == used || nextUsed < minUsed) {
            if (nextUsed < minUsed) used = nextUsed;
            break;
        }
        good = next;
        used = nextUsed;
    }
    r.used = used;
    r.slope = b;
    if (used < minUsed) {
        r.z1 = zmin;
        r.z2 = zmax;
        r.fitFailed = true;
        return r;
    }
    const double slope = p.contrast > 0 ? b / p.contrast : b;
    r.z1 = std::max(zmin, median - double(centre) * slope);
    r.z2 = std::min(zmax, median + double(n - 1 - centre) * slope);
    return r;
}

const char* stretchKindName(StretchKind k) {
    switch (k) {
        case StretchKind::Linear: return "linear";
        case StretchKind::Sqrt: return "sqrt";
        case StretchKind::Log: return "log";
        case StretchKind::Asinh: return "asinh";
    }
    return "linear";
}

double applyStretch(StretchKind k, double x, const StretchParams& p) {
    x = std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0;
    switch (k) {
        case StretchKind::Linear: return x;
        case StretchKind::Sqrt: return std::sqrt(x);
        case StretchKind::Log: return std::log1p(p.logExponent * x) / std::log1p(p.logExponent);
        case StretchKind::Asinh: return std::asinh(p.asinhScale * x) / std::asinh(p.asinhScale);
    }
    return x;
}

double invertStretch(StretchKind k, double y, const StretchParams& p) {
    y = std::isfinite(y) ? std::clamp(y, 0.0, 1.0) : 0.0;
    switch (k) {
        case StretchKind::Linear: return y;
        case StretchKind::Sqrt: return y * y;
        case StretchKind::Log: return std::expm1(y * std::log1p(p.logExponent)) / p.logExponent;
        case StretchKind::Asinh: return std::sinh(y * std::asinh(p.asinhScale)) / p.asinhScale;
    }
    return y;
}

DisplayLimits minMaxLimits(const float* values, size_t count) {
    DisplayLimits l;
    for (size_t i = 0; i < count; ++i) {
        if (!std::isfinite(values[i])) continue;
        if (!l.ok) {
            l.lo = l.hi = values[i];
            l.ok = true;
        }
        l.lo = std::min<double>(l.lo, values[i]);
        l.hi = std::max<double>(l.hi, values[i]);
    }
    return l;
}

DisplayLimits percentileLimits(const float* values, size_t count, double loPercent, double hiPercent) {
    DisplayLimits l;
    std::vector<float> v = finiteValues(values, count);
    if (v.empty()) return l;
    auto at = [&](double pct) {
        const size_t k = static_cast<size_t>(std::clamp(pct, 0.0, 100.0) / 100.0 * double(v.size() - 1) + 0.5);
        std::nth_element(v.begin(), v.begin() + long(k), v.end());
        return double(v[k]);
    };
    l.lo = at(loPercent);
    l.hi = at(hiPercent);
    l.ok = true;
    return l;
}

std::vector<size_t> histogram(const float* values, size_t count, double lo, double hi, int bins) {
    std::vector<size_t> h(size_t(std::max(bins, 1)), 0);
    if (!(hi > lo)) return h;
    const double w = (hi - lo) / double(h.size());
    for (size_t i = 0; i < count; ++i) {
        const double v = values[i];
        if (!std::isfinite(v) || v < lo || v > hi) continue;
        const size_t k = std::min(h.size() - 1, static_cast<size_t>((v - lo) / w));
        ++h[k];
    }
    return h;
}

}  // namespace lwb::core
