#include "ui/image_view.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>

namespace lwb::ui {

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

void ImageView::fitToWindow() {
    m_fit = true;
    if (m_image.isNull()) return;
    m_zoom = std::max(0.05, std::min(width() / double(m_image.width()), height() / double(m_image.height())));
    m_offset = QPointF((width() - m_zoom * m_image.width()) / 2, (height() - m_zoom * m_image.height()) / 2);
    update();
}

QPointF ImageView::toImage(QPointF w) const { return (w - m_offset) / m_zoom - QPointF(0.5, 0.5); }

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
    if (!m_badge.isEmpty()) {
        QFont f = font();
        f.setBold(true);
        p.setFont(f);
        const QRect text = p.fontMetrics().boundingRect(QRect(0, 0, width() - 16, 200), Qt::TextWordWrap, m_badge);
        const QRect box(8, 8, text.width() + 12, text.height() + 8);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(m_badgeColor.red(), m_badgeColor.green(), m_badgeColor.blue(), 215));
        p.drawRoundedRect(box, 5, 5);
        p.setPen(Qt::white);
        p.drawText(box.adjusted(6, 4, -6, -4), Qt::TextWordWrap, m_badge);
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
