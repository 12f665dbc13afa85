#pragma once
// Float image → displayable QImage: colour maps and contrast stretches.
#include <QImage>
#include <QString>
#include <QStringList>
#include <opencv2/core.hpp>

namespace lwb::ui {

enum class ColorMap { Gray, Viridis, Inferno, Jet };
enum class Stretch { MinMax, Percentile, Sqrt };

QStringList colorMapNames();
QStringList stretchNames();
ColorMap colorMapFromIndex(int i);
Stretch stretchFromIndex(int i);

/// RGB colour of t in [0, 1] under the map.
QRgb mapColor(ColorMap map, double t);

struct DisplayRange {
    double lo = 0, hi = 1;
};
/// The display range of a CV_32FC1 image under a stretch (percentile: 1–99.5 %).
DisplayRange displayRange(const cv::Mat& img, Stretch stretch);

/// Renders a CV_32FC1 image to an ARGB32 QImage.
QImage renderImage(const cv::Mat& img, ColorMap map, Stretch stretch);

}  // namespace lwb::ui
