#pragma once
// Regions on an image view (ui/image_view): how a box or circle region is drawn, hit and
// described with its pixel statistics (core/common/region_stats). Region and statistics are in
// data coordinates; the text adds the view's origin, so that it reads in full-image
// coordinates (x = column, y = row, pixel centres at integers, as the readout and the report).
#include <QColor>
#include <QPointF>
#include <QString>
#include <functional>

#include "core/common/region_stats.hpp"

class QPainter;
class QLabel;

namespace lwb::ui {

class ImageView;

/// DS9's default region colour.
QColor regionColor();
/// Draws the outline in image coordinates (pixel centres at integers); `zoom`: screen px per image px.
void drawRegion(QPainter& p, const core::RegionStatsParams& r, double zoom, bool selected);
/// The region's number (1-based) beside its top-left corner, in widget coordinates.
void drawRegionLabel(QPainter& p, const core::RegionStatsParams& r, int index, const std::function<QPointF(QPointF)>& toWidget);
/// Inside the region or within `slack` image px of its outline.
bool regionContains(const core::RegionStatsParams& r, QPointF imagePoint, double slack);
/// "Box 1 (8 × 6 px at 12.5, 10.0): n 48 · sum … · mean … · median … · σ … · min … · max …
/// · centroid (x, y)", coordinates plus `origin`.
QString regionStatsText(const core::RegionStatsParams& r, const core::RegionStatsResult& s, int index, QPointF origin);
/// Every region of the views, one line each, prefixed with the view's name ("ROI", "Frame").
QString regionsSummary(const QList<QPair<QString, const ImageView*>>& views);

}  // namespace lwb::ui
