#include "ui/kit/color_maps.hpp"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lwb::ui {

QStringList colorMapNames() {
    return {QCoreApplication::translate("lwb::ui::ColorMaps", "Gray"), "Viridis",
            "Inferno", "Jet"};
}
QStringList stretchNames() {
    return {QCoreApplication::translate("lwb::ui::ColorMaps", "Min–max"),
            QCoreApplication::translate("lwb::ui::ColorMaps", "Percentile 1–99.5"),
            QCoreApplication::translate("lwb::ui::ColorMaps", "Square root")};
}
ColorMap colorMapFromIndex(int i) { return static_cast<ColorMap>(std::clamp(i, 0, 3)); }
Stretch stretchFromIndex(int i) { return static_cast<Stretch>(std::clamp(i, 0, 2)); }

namespace {
struct Stop {
    double t;
    int r, g, b;
};
QRgb interpolate(const Stop* stops, int n, double t) {
    t = std::clamp(t, 0.0, 1.0);
    for (int i = 1; i < n; ++i)
        if (t <= stops[i].t) {
            const double f = (t - stops[i - 1].t) / (stops[i].t - stops[i - 1].t);
            auto lerp = [f](int a, int b) { return static_cast<int>(std::lround(a + f * (b - a))); };
            return qRgb(lerp(stops[i - 1].r, stops[i].r), lerp(stops[i - 1].g, stops[i].g), lerp(stops[i - 1].b, stops[i].b));
        }
    return qRgb(stops[n - 1].r, stops[n - 1].g, stops[n - 1].b);
}
// Key points of the matplotlib maps (perceptually uniform viridis / inferno) and a classic jet.
const Stop kViridis[] = {{0.0, 68, 1, 84},    {0.13, 71, 44, 122},  {0.25, 59, 81, 139}, {0.38, 44, 113, 142},
                         {0.5, 33, 144, 141}, {0.63, 39, 173, 129}, {0.75, 92, 200, 99}, {0.88, 170, 220, 50},
                         {1.0, 253, 231, 37}};
const Stop kInferno[] = {{0.0, 0, 0, 4},      {0.13, 31, 12, 72},   {0.25, 85, 15, 109}, {0.38, 136, 34, 106},
                         {0.5, 186, 54, 85},  {0.63, 227, 89, 51},  {0.75, 249, 140, 10}, {0.88, 249, 201, 50},
                         {1.0, 252, 255, 164}};
const Stop kJet[] = {{0.0, 0, 0, 131}, {0.125, 0, 0, 255}, {0.375, 0, 255, 255}, {0.625, 255, 255, 0},
                     {0.875, 255, 0, 0}, {1.0, 128, 0, 0}};
}  // namespace

QRgb mapColor(ColorMap map, double t) {
    switch (map) {
        case ColorMap::Gray: {
            const int v = static_cast<int>(std::lround(255 * std::clamp(t, 0.0, 1.0)));
            return qRgb(v, v, v);
        }
        case ColorMap::Viridis: return interpolate(kViridis, 9, t);
        case ColorMap::Inferno: return interpolate(kInferno, 9, t);
        case ColorMap::Jet: return interpolate(kJet, 6, t);
    }
    return qRgb(0, 0, 0);
}

DisplayRange displayRange(const cv::Mat& img, Stretch stretch) {
    DisplayRange r;
    if (img.empty()) return r;
    if (stretch == Stretch::Percentile) {
        std::vector<float> v(img.begin<float>(), img.end<float>());
        const size_t lo = static_cast<size_t>(0.01 * (v.size() - 1)), hi = static_cast<size_t>(0.995 * (v.size() - 1));
        std::nth_element(v.begin(), v.begin() + lo, v.end());
        r.lo = v[lo];
        std::nth_element(v.begin(), v.begin() + hi, v.end());
        r.hi = v[hi];
    } else {
        cv::minMaxLoc(img, &r.lo, &r.hi);
    }
    if (!(r.hi > r.lo)) r.hi = r.lo + 1;
    return r;
}

QImage renderImage(const cv::Mat& img, ColorMap map, Stretch stretch) {
    QImage out(img.cols, img.rows, QImage::Format_ARGB32);
    if (img.empty()) return out;
    const DisplayRange r = displayRange(img, stretch);
    QRgb lut[256];
    for (int i = 0; i < 256; ++i) lut[i] = mapColor(map, i / 255.0);
    for (int y = 0; y < img.rows; ++y) {
        const float* src = img.ptr<float>(y);
        auto* dst = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < img.cols; ++x) {
            double t = (src[x] - r.lo) / (r.hi - r.lo);
            t = std::clamp(t, 0.0, 1.0);
            if (stretch == Stretch::Sqrt) t = std::sqrt(t);
            dst[x] = lut[static_cast<int>(t * 255 + 0.5)];
        }
    }
    return out;
}

}  // namespace lwb::ui
