#include "ui/image_view.hpp"

#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QRubberBand>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace lwb::ui {

namespace {
constexpr double kMinZoom = 0.05, kMaxZoom = 200;
}  // namespace

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
    // The keys (zoom steps, Home) by Tab; a click leaves the focus where it was, so that the
    // review keys of the shot table go on working after a pan or a zoom.
    setFocusPolicy(Qt::TabFocus);
    // Right-button presses and releases come here (box zoom, the menu) on every platform.
    setContextMenuPolicy(Qt::PreventContextMenu);
    setToolTip(tr("Wheel: zoom · drag: pan · right-drag or Shift+drag: zoom to the box · "
                  "2, 4, 8: zoom steps · 1, Home or double-click: fit · right-click: menu"));
}

void ImageView::setImage(const cv::Mat& data, const QImage& rendered, QPointF origin) {
    const bool sizeChanged = rendered.size() != m_image.size();
    m_data = data;
    m_image = rendered;
    m_message.clear();
    m_origin = origin;
    if (sizeChanged || m_fit) fitToWindow();
    update();
}

void ImageView::clear(const QString& message) {
    m_message = message;
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

double ImageView::fitZoom() const {
    if (m_image.isNull()) return 1;
    return std::max(kMinZoom, std::min(width() / double(m_image.width()), height() / double(m_image.height())));
}

void ImageView::fitToWindow() {
    m_fit = true;
    if (m_image.isNull()) return;
    m_zoom = fitZoom();
    m_offset = QPointF((width() - m_zoom * m_image.width()) / 2, (height() - m_zoom * m_image.height()) / 2);
    update();
}

void ImageView::zoomAbout(QPointF widgetPos, double zoom) {
    const QPointF at = toImage(widgetPos);
    m_zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    m_offset = widgetPos - (at + QPointF(0.5, 0.5)) * m_zoom;
    m_fit = false;
    update();
}

// The steps are relative to the fit rather than screen pixels per image pixel: a 32 px ROI
// fills a view at about 10 screen px per pixel, where fixed 1×…8× would all zoom out.
void ImageView::setZoomStep(double magnification) {
    if (m_image.isNull()) return;
    if (magnification <= 1) {
        fitToWindow();
        return;
    }
    zoomAbout(QPointF(width(), height()) / 2, fitZoom() * magnification);
}

void ImageView::zoomToBox(const QRectF& widgetBox) {
    const QRectF box = widgetBox.normalized();
    if (m_image.isNull() || box.width() < 1 || box.height() < 1) return;
    const QPointF centre = toImage(box.center());
    m_zoom = std::clamp(m_zoom * std::min(width() / box.width(), height() / box.height()), kMinZoom, kMaxZoom);
    m_offset = QPointF(width(), height()) / 2 - (centre + QPointF(0.5, 0.5)) * m_zoom;
    m_fit = false;
    update();
}

void ImageView::showMenu(const QPoint& globalPos) {
    if (m_image.isNull()) return;
    QMenu menu(this);
    menu.addAction(tr("1× (fit)\t1, Home, double-click"), this, &ImageView::fitToWindow);
    for (int step : {2, 4, 8}) menu.addAction(tr("%1×\t%1").arg(step), this, [this, step] { setZoomStep(step); });
    menu.addSeparator();
    menu.addAction(tr("Box zoom: right-drag or Shift+drag"))->setEnabled(false);
    menu.exec(globalPos);
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
        p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, placeholderText());
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
    if (hasFocus()) {  // reached by Tab: the zoom keys act here
        p.setPen(QPen(palette().color(QPalette::Highlight), 2));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(rect()).adjusted(1, 1, -1, -1));
    }
}

void ImageView::wheelEvent(QWheelEvent* e) {
    if (m_image.isNull()) return;
    zoomAbout(e->position(), m_zoom * std::pow(1.0015, e->angleDelta().y()));
}

void ImageView::mousePressEvent(QMouseEvent* e) {
    m_dragStart = e->position();
    m_rightPress = e->button() == Qt::RightButton;
    if (m_rightPress || (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier))) {
        m_drag = Drag::Box;
    } else if (e->button() == Qt::LeftButton) {
        m_drag = Drag::Pan;
        m_offsetStart = m_offset;
    }
}

void ImageView::mouseMoveEvent(QMouseEvent* e) {
    if (m_drag == Drag::Pan) {
        m_offset = m_offsetStart + (e->position() - m_dragStart);
        m_fit = false;
        update();
    } else if (m_drag == Drag::Box && (m_band || (e->position() - m_dragStart).manhattanLength() >= 5)) {
        if (!m_band) m_band = new QRubberBand(QRubberBand::Rectangle, this);
        m_band->setGeometry(QRectF(m_dragStart, e->position()).normalized().toRect());
        m_band->show();
    }
    if (m_data.empty()) return;
    const QPointF ip = toImage(e->position());
    const int x = static_cast<int>(std::lround(ip.x())), y = static_cast<int>(std::lround(ip.y()));
    if (x >= 0 && y >= 0 && x < m_data.cols && y < m_data.rows)
        emit pixelHovered(x + m_origin.x(), y + m_origin.y(), m_data.at<float>(y, x));
}

void ImageView::mouseReleaseEvent(QMouseEvent* e) {
    const Drag drag = m_drag;
    const bool rightClick = m_rightPress;
    m_drag = Drag::None;
    m_rightPress = false;
    if (drag != Drag::Box) return;
    const bool boxDrawn = m_band && m_band->isVisible();
    if (m_band) m_band->hide();
    if (boxDrawn || (e->position() - m_dragStart).manhattanLength() >= 5)
        zoomToBox(QRectF(m_dragStart, e->position()));
    else if (rightClick)
        showMenu(e->globalPosition().toPoint());
}

void ImageView::mouseDoubleClickEvent(QMouseEvent*) { fitToWindow(); }

void ImageView::keyPressEvent(QKeyEvent* e) {
    switch (e->key()) {
        case Qt::Key_Home:
        case Qt::Key_1: fitToWindow(); break;
        case Qt::Key_2: setZoomStep(2); break;
        case Qt::Key_4: setZoomStep(4); break;
        case Qt::Key_8: setZoomStep(8); break;
        default: QWidget::keyPressEvent(e);
    }
}

void ImageView::resizeEvent(QResizeEvent*) {
    if (m_fit) fitToWindow();
}

}  // namespace lwb::ui
