#include "ui/kit/image_regions.hpp"

#include <QColor>
#include <QCoreApplication>
#include <QPainter>
#include <cmath>

#include "ui/kit/image_view.hpp"

namespace lwb::ui {

namespace {

QRectF boxRect(const core::RegionStatsParams& r) {
    return {r.centerX - r.width / 2, r.centerY - r.height / 2, r.width, r.height};
}

QString num(double v) {
    const double a = std::abs(v);
    return a != 0 && (a >= 1e6 || a < 1e-2) ? QString::number(v, 'g', 5) : QString::number(v, 'f', a >= 100 ? 1 : 2);
}
}  // namespace

QColor regionColor() { return QColor(0, 255, 0); }

void drawRegion(QPainter& p, const core::RegionStatsParams& r, double zoom, bool selected) {
    p.save();
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(regionColor(), (selected ? 2.4 : 1.5) / zoom));
    QRectF bounds;
    if (r.shape == core::RegionShape::Circle) {
        p.drawEllipse(QPointF(r.centerX, r.centerY), r.radius, r.radius);
        bounds = QRectF(r.centerX - r.radius, r.centerY - r.radius, 2 * r.radius, 2 * r.radius);
    } else {
        bounds = boxRect(r);
        p.drawRect(bounds);
    }
    if (selected) {  // DS9 marks the selected region with handles at its corners
        const double h = 4 / zoom;
        p.setBrush(regionColor());
        p.setPen(Qt::NoPen);
        for (QPointF c : {bounds.topLeft(), bounds.topRight(), bounds.bottomLeft(), bounds.bottomRight()})
            p.drawRect(QRectF(c - QPointF(h / 2, h / 2), QSizeF(h, h)));
    }
    p.restore();
}

void drawRegionLabel(QPainter& p, const core::RegionStatsParams& r, int index, const std::function<QPointF(QPointF)>& toWidget) {
    const QPointF corner = r.shape == core::RegionShape::Circle ? QPointF(r.centerX - r.radius * M_SQRT1_2, r.centerY - r.radius * M_SQRT1_2)
                                                                : boxRect(r).topLeft();
    const QPointF at = toWidget(corner) + QPointF(2, -3);
    p.save();
    p.setPen(Qt::black);
    p.drawText(at + QPointF(1, 1), QString::number(index + 1));
    p.setPen(regionColor());
    p.drawText(at, QString::number(index + 1));
    p.restore();
}

bool regionContains(const core::RegionStatsParams& r, QPointF q, double slack) {
    if (r.shape == core::RegionShape::Circle) return std::hypot(q.x() - r.centerX, q.y() - r.centerY) <= r.radius + slack;
    return boxRect(r).adjusted(-slack, -slack, slack, slack).contains(q);
}

QString regionStatsText(const core::RegionStatsParams& r, const core::RegionStatsResult& s, int index, QPointF origin) {
    const QString where =
        r.shape == core::RegionShape::Circle
            ? QCoreApplication::translate("lwb::ui::ImageRegions", "Circle %1 (r %2 px at %3, %4)").arg(index + 1).arg(num(r.radius)).arg(num(r.centerX + origin.x())).arg(num(r.centerY + origin.y()))
            : QCoreApplication::translate("lwb::ui::ImageRegions", "Box %1 (%2 × %3 px at %4, %5)")
                  .arg(index + 1)
                  .arg(num(r.width))
                  .arg(num(r.height))
                  .arg(num(r.centerX + origin.x()))
                  .arg(num(r.centerY + origin.y()));
    if (!s.ok) return where + ": " + QString::fromStdString(s.error);
    QString t = where + QCoreApplication::translate("lwb::ui::ImageRegions", ": n %1 · sum %2 · mean %3 · median %4 · σ %5 · min %6 · max %7")
                            .arg(s.count)
                            .arg(num(s.sum), num(s.mean), num(s.median), num(s.stddev), num(s.min), num(s.max));
    t += s.centroidOk ? QCoreApplication::translate("lwb::ui::ImageRegions", " · centroid (%1, %2)").arg(num(s.centroidX + origin.x()), num(s.centroidY + origin.y()))
                      : QCoreApplication::translate("lwb::ui::ImageRegions", " · no centroid (sum ≤ 0)");
    if (s.nonFinite) t += QCoreApplication::translate("lwb::ui::ImageRegions", " · %1 NaN left out").arg(s.nonFinite);
    if (s.outside) t += QCoreApplication::translate("lwb::ui::ImageRegions", " · %1 px outside the image").arg(s.outside);
    return t;
}

QString regionsSummary(const QList<QPair<QString, const ImageView*>>& views) {
    QStringList lines;
    for (const auto& [name, v] : views) {
        const QVector<core::RegionStatsResult> stats = v->regionStats();
        for (int i = 0; i < stats.size(); ++i)
            lines << name + " " + regionStatsText(v->regions()[i], stats[i], i, v->origin());
    }
    return lines.join('\n');
}

}  // namespace lwb::ui
