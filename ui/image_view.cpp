#include "ui/image_view.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace lwb::ui {

QRect placeBadge(const QRect& area, QSize size, int margin, const QVector<QPointF>& keepClear, double clearance) {
    const int left = area.left() + margin, right = area.right() + 1 - margin - size.width();
    const int top = area.top() + margin, bottom = area.bottom() + 1 - margin - size.height();
    for (const QPoint corner : {QPoint(left, top), QPoint(right, top), QPoint(left, bottom), QPoint(right, bottom)}) {
        const QRectF zone = QRectF(corner, size).adjusted(-clearance, -clearance, clearance, clearance);
        if (std::none_of(keepClear.begin(), keepClear.end(), [&](const QPointF& p) { return zone.contains(p); }))
            return QRect(corner, size);
    }
    return {};
}

ImageView::ImageView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setMinimumSize(160, 160);
    setBackgroundRole(QPalette::Dark);
    setAutoFillBackground(true);
}

void ImageView::setImage(const cv::Mat& data, const QImage& rendered, QPointF origin) {
    const bool sizeChanged = rendered.size() != m_image.size();
    m_data = data;
    m_image = rendered;
    m_origin = origin;
    if (sizeChanged || m_fit) fitToWindow();
    update();
}

void ImageView::clear() {
    m_data.release();
    m_image = QImage();
    m_badge.clear();
    m_keepClear.clear();
    update();
}

void ImageView::setOverlay(OverlayFn fn) {
    m_overlay = std::move(fn);
    update();
}

void ImageView::setBadge(const QString& text, const QColor& color) {
    m_badge = text;
    m_badgeColor = color;
    update();
}

void ImageView::setKeepClear(const QVector<QPointF>& points) {
    m_keepClear = points;
    update();
}

void ImageView::fitToWindow() {
    m_fit = true;
    if (m_image.isNull()) return;
    m_zoom = std::max(0.05, std::min(width() / double(m_image.width()), height() / double(m_image.height())));
    m_offset = QPointF((width() - m_zoom * m_image.width()) / 2, (height() - m_zoom * m_image.height()) / 2);
    update();
}

QPointF ImageView::toImage(QPointF w) const { return (w - m_offset) / m_zoom - QPointF(0.5, 0.5); }

QPointF ImageView::toWidget(QPointF image) const { return m_offset + (image + QPointF(0.5, 0.5)) * m_zoom; }

QRectF ImageView::visibleImageRect() const {
    return QRectF(toImage(QPointF(0, 0)), toImage(QPointF(width(), height()))) & QRectF(-0.5, -0.5, m_image.width(), m_image.height());
}

// The badge in the top left corner hid a spot near the ROI's top edge and its centre marker
// (issue 30): it goes to the first corner where it leaves the markers in view, and when the
// whole badge (the verdict and every failed criterion) fits in none, its first line does (the
// criteria are in the table's Reasons column). The layout follows the zoom and the pan.
ImageView::BadgeLayout ImageView::layoutBadge() const {
    if (m_badge.isEmpty() || m_image.isNull()) return {};
    QFont f = font();
    f.setBold(true);
    const QFontMetrics fm(f);
    QVector<QPointF> keep;
    for (const QPointF& p : m_keepClear) keep << toWidget(p);
    // The markers are drawn 0.6 image px about the centre (ui/footprint_workspace): their arms
    // are kept in view up to a size, and always the centre with a few pixels around it.
    const double clearance = std::min(0.6 * m_zoom, 24.0) + 4;
    const QString first = m_badge.section('\n', 0, 0);
    const QStringList texts = first == m_badge ? QStringList{m_badge} : QStringList{m_badge, first + QStringLiteral(" …")};
    QSize size;
    for (const QString& text : texts) {
        size = fm.boundingRect(QRect(0, 0, std::max(40, width() - 16), 2000), Qt::TextWordWrap, text).size() + QSize(12, 8);
        const QRect box = placeBadge(rect(), size, 8, keep, clearance);
        if (!box.isEmpty()) return {box, text};
    }
    return {QRect(QPoint(8, 8), size), texts.last()};  // a view too small for any clear corner
}

void ImageView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    if (m_image.isNull()) {
        p.setPen(palette().color(QPalette::BrightText));
        p.drawText(rect(), Qt::AlignCenter, tr("No image"));
        return;
    }
    p.save();
    p.translate(m_offset);
    p.scale(m_zoom, m_zoom);
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(QPointF(0, 0), m_image);
    p.translate(0.5, 0.5);  // now pixel centres are at integer coordinates
    p.setRenderHint(QPainter::Antialiasing, true);
    if (m_overlay) m_overlay(p, m_zoom);
    p.restore();
    const BadgeLayout badge = layoutBadge();
    if (!badge.box.isEmpty()) {
        QFont f = font();
        f.setBold(true);
        p.setFont(f);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(m_badgeColor.red(), m_badgeColor.green(), m_badgeColor.blue(), 215));
        p.drawRoundedRect(badge.box, 5, 5);
        p.setPen(Qt::white);
        p.drawText(badge.box.adjusted(6, 4, -6, -4), Qt::TextWordWrap, badge.text);
    }
}

void ImageView::wheelEvent(QWheelEvent* e) {
    if (m_image.isNull()) return;
    const QPointF pos = e->position();
    const QPointF before = toImage(pos);
    const double factor = std::pow(1.0015, e->angleDelta().y());
    m_zoom = std::clamp(m_zoom * factor, 0.05, 200.0);
    m_offset = pos - (before + QPointF(0.5, 0.5)) * m_zoom;
    m_fit = false;
    update();
}

void ImageView::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton) {
        m_dragging = true;
        m_dragStart = e->position();
        m_offsetStart = m_offset;
    }
}

void ImageView::mouseMoveEvent(QMouseEvent* e) {
    if (m_dragging) {
        m_offset = m_offsetStart + (e->position() - m_dragStart);
        m_fit = false;
        update();
    }
    if (m_data.empty()) return;
    const QPointF ip = toImage(e->position());
    const int x = static_cast<int>(std::lround(ip.x())), y = static_cast<int>(std::lround(ip.y()));
    if (x >= 0 && y >= 0 && x < m_data.cols && y < m_data.rows)
        emit pixelHovered(x + m_origin.x(), y + m_origin.y(), m_data.at<float>(y, x));
}

void ImageView::mouseReleaseEvent(QMouseEvent*) { m_dragging = false; }

void ImageView::mouseDoubleClickEvent(QMouseEvent*) { fitToWindow(); }

void ImageView::resizeEvent(QResizeEvent*) {
    if (m_fit) fitToWindow();
}

}  // namespace lwb::ui
