#include "core/common/region_stats.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lwb::core {

namespace {
constexpr double kEdge = 1e-9;  // a centre on an edge, up to rounding, is on that edge

// The columns [x0, x1] of row y whose centres are in the region (x1 < x0: none).
struct Span {
    long long x0 = 0, x1 = -1;
};

bool rowsOf(const RegionStatsParams& p, long long* y0, long long* y1) {
    if (p.shape == RegionShape::Box) {
        *y0 = static_cast<long long>(std::ceil(p.centerY - p.height / 2 - kEdge));
        *y1 = static_cast<long long>(std::ceil(p.centerY + p.height / 2 - kEdge)) - 1;
    } else {
        *y0 = static_cast<long long>(std::ceil(p.centerY - p.radius - kEdge));
        *y1 = static_cast<long long>(std::floor(p.centerY + p.radius + kEdge));
    }
    return *y1 >= *y0;
}

Span spanOf(const RegionStatsParams& p, long long y) {
    Span s;
    if (p.shape == RegionShape::Box) {
        s.x0 = static_cast<long long>(std::ceil(p.centerX - p.width / 2 - kEdge));
        s.x1 = static_cast<long long>(std::ceil(p.centerX + p.width / 2 - kEdge)) - 1;
        return s;
    }
    const double dy = double(y) - p.centerY;
    const double h2 = p.radius * p.radius - dy * dy;
    if (h2 < -kEdge) return s;
    const double h = std::sqrt(std::max(0.0, h2));
    s.x0 = static_cast<long long>(std::ceil(p.centerX - h - kEdge));
    s.x1 = static_cast<long long>(std::floor(p.centerX + h + kEdge));
    return s;
}

std::string checkInput(const cv::Mat& image, const RegionStatsParams& p) {
    if (image.empty()) return "empty image";
    if (image.channels() != 1) return "the image must have one channel";
    const int d = image.depth();
    if (d != CV_8U && d != CV_16U && d != CV_16S && d != CV_32S && d != CV_32F && d != CV_64F)
        return "unsupported pixel type";
    if (!std::isfinite(p.centerX) || !std::isfinite(p.centerY)) return "the region's centre is not finite";
    if (p.shape == RegionShape::Box && !(p.width >= 0 && p.height >= 0 && std::isfinite(p.width) && std::isfinite(p.height)))
        return "the box's size must be finite and not negative";
    if (p.shape == RegionShape::Circle && !(p.radius >= 0 && std::isfinite(p.radius)))
        return "the circle's radius must be finite and not negative";
    // Bounded work: the region's rows are walked one by one.
    const double extent = p.shape == RegionShape::Box ? std::max(p.width, p.height) : 2 * p.radius;
    if (extent > 1e8 || std::abs(p.centerX) > 1e12 || std::abs(p.centerY) > 1e12) return "the region is too large";
    return {};
}

struct Accumulated {
    std::vector<double> values;
    double sum = 0, sx = 0, sy = 0;
};

// Walks the region's rows: values inside the image, NaNs and the centres outside it.
void collect(const cv::Mat& img, const RegionStatsParams& p, Accumulated* a, RegionStatsResult* r) {
    long long y0 = 0, y1 = -1;
    if (!rowsOf(p, &y0, &y1)) return;
    for (long long y = y0; y <= y1; ++y) {
        const Span s = spanOf(p, y);
        if (s.x1 < s.x0) continue;
        const long long n = s.x1 - s.x0 + 1;
        if (y < 0 || y >= img.rows) {
            r->outside += size_t(n);
            continue;
        }
        const long long c0 = std::max<long long>(s.x0, 0), c1 = std::min<long long>(s.x1, img.cols - 1);
        const long long inside = c1 >= c0 ? c1 - c0 + 1 : 0;
        r->outside += size_t(n - inside);
        for (long long x = c0; x <= c1; ++x) {
            double v = 0;
            switch (img.depth()) {
                case CV_8U: v = img.at<uchar>(int(y), int(x)); break;
                case CV_16U: v = img.at<ushort>(int(y), int(x)); break;
                case CV_16S: v = img.at<short>(int(y), int(x)); break;
                case CV_32S: v = img.at<int>(int(y), int(x)); break;
                case CV_32F: v = img.at<float>(int(y), int(x)); break;
                default: v = img.at<double>(int(y), int(x)); break;
            }
            if (!std::isfinite(v)) {
                ++r->nonFinite;
                continue;
            }
            a->values.push_back(v);
            a->sum += v;
            a->sx += v * double(x);
            a->sy += v * double(y);
        }
    }
}

void summarise(Accumulated& a, RegionStatsResult* r) {
    const size_t n = a.values.size();
    r->count = n;
    r->sum = a.sum;
    r->mean = a.sum / double(n);
    double ss = 0;
    for (double v : a.values) ss += (v - r->mean) * (v - r->mean);
    r->stddev = n > 1 ? std::sqrt(ss / double(n - 1)) : 0;
    const auto [lo, hi] = std::minmax_element(a.values.begin(), a.values.end());
    r->min = *lo;
    r->max = *hi;
    auto mid = a.values.begin() + long(n / 2);
    std::nth_element(a.values.begin(), mid, a.values.end());
    r->median = *mid;
    if (n % 2 == 0) r->median = (r->median + *std::max_element(a.values.begin(), mid)) / 2;
    if (a.sum > 0) {
        r->centroidOk = true;
        r->centroidX = a.sx / a.sum;
        r->centroidY = a.sy / a.sum;
    }
}
}  // namespace

RegionStatsResult regionStats(const cv::Mat& image, const RegionStatsParams& p) {
    RegionStatsResult r;
    r.error = checkInput(image, p);
    if (!r.error.empty()) return r;
    Accumulated a;
    collect(image, p, &a, &r);
    if (a.values.empty()) {
        r.error = r.nonFinite ? "every pixel of the region is NaN or infinite" : "no pixel of the image is in the region";
        return r;
    }
    summarise(a, &r);
    r.ok = true;
    return r;
}

}  // namespace lwb::core
