#include "ui/kit/image_view.hpp"

#include <QActionGroup>
#include <QFileInfo>
#include <QInputDialog>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPdfWriter>
#include <QRubberBand>
#include <QSaveFile>
#include <QSvgGenerator>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "ui/kit/image_regions.hpp"
#include "ui/kit/save_path.hpp"

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
                  "middle-drag or Ctrl+drag: contrast (up/down) and bias (left/right) · "
                  "2, 4, 8: zoom steps · 1, Home or double-click: fit · right-click: menu (regions, export)"));
}

void ImageView::setImage(const cv::Mat& data, const QImage& rendered, QPointF origin) {
    const bool sizeChanged = rendered.size() != m_image.size();
    m_data = data;
    m_image = rendered;
    m_message.clear();
    m_origin = origin;
    if (sizeChanged || m_fit) fitToWindow();
    update();
    if (!m_regions.isEmpty()) emit regionsChanged();  // their statistics are of the new data
}

void ImageView::clear(const QString& message) {
    m_message = message;
    m_data.release();
    m_image = QImage();
    m_badge.clear();
    m_keepClear.clear();
    update();
    if (!m_regions.isEmpty()) emit regionsChanged();
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
    emitViewChanged();
}

void ImageView::emitViewChanged() {
    if (!m_applyingState) emit viewChanged();
}

ImageView::ViewState ImageView::viewState() const {
    ViewState s;
    s.fit = m_fit;
    s.magnification = m_zoom / fitZoom();
    s.centre = toImage(QPointF(width(), height()) / 2);
    return s;
}

void ImageView::setViewState(const ViewState& s) {
    m_applyingState = true;
    if (s.fit || m_image.isNull()) {
        fitToWindow();
    } else {
        m_zoom = std::clamp(fitZoom() * s.magnification, kMinZoom, kMaxZoom);
        m_offset = QPointF(width(), height()) / 2 - (s.centre + QPointF(0.5, 0.5)) * m_zoom;
        m_fit = false;
        update();
    }
    m_applyingState = false;
}

void ImageView::zoomAbout(QPointF widgetPos, double zoom) {
    const QPointF at = toImage(widgetPos);
    m_zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    m_offset = widgetPos - (at + QPointF(0.5, 0.5)) * m_zoom;
    m_fit = false;
    update();
    emitViewChanged();
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
    emitViewChanged();
}

void ImageView::showMenu(const QPoint& globalPos) {
    if (m_image.isNull()) return;
    QMenu menu(this);
    menu.addAction(tr("1× (fit)\t1, Home, double-click"), this, &ImageView::fitToWindow);
    for (int step : {2, 4, 8}) menu.addAction(tr("%1×\t%1").arg(step), this, [this, step] { setZoomStep(step); });
    menu.addSeparator();
    menu.addAction(tr("Box zoom: right-drag or Shift+drag"))->setEnabled(false);
    menu.addSeparator();
    auto* modes = new QActionGroup(&menu);
    const std::pair<MouseMode, QString> choices[] = {{MouseMode::Pan, tr("Mouse: pan")},
                                                     {MouseMode::BoxRegion, tr("Mouse: box regions")},
                                                     {MouseMode::CircleRegion, tr("Mouse: circle regions")}};
    for (const auto& [mode, text] : choices) {
        QAction* a = menu.addAction(text, this, [this, m = mode] { setMouseMode(m); });
        a->setCheckable(true);
        a->setChecked(m_mode == mode);
        modes->addAction(a);
    }
    const int under = regionAt(mapFromGlobal(globalPos));
    const int target = under >= 0 ? under : m_selected;
    menu.addAction(tr("Delete region\tDelete"), this, [this, target] { deleteRegion(target); })->setEnabled(target >= 0);
    menu.addAction(tr("Delete all regions"), this, [this] { setRegions({}); })->setEnabled(!m_regions.isEmpty());
    menu.addSeparator();
    menu.addAction(tr("Reset contrast and bias"), this, &ImageView::contrastBiasResetRequested);
    menu.addAction(tr("Contrast / bias: middle-drag or Ctrl+drag"))->setEnabled(false);
    menu.addSeparator();
    menu.addAction(tr("Export view (PNG, SVG, PDF)…"), this, [this] { exportDialog(); });
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
ImageView::BadgeLayout ImageView::layoutBadge(const QRect& area) const {
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
        size = fm.boundingRect(QRect(0, 0, std::max(40, area.width() - 16), 2000), Qt::TextWordWrap, text).size() + QSize(12, 8);
        const QRect box = placeBadge(area, size, 8, keep, clearance);
        if (!box.isEmpty()) return {box, text};
    }
    return {QRect(area.topLeft() + QPoint(8, 8), size), texts.last()};  // a view too small for any clear corner
}

void ImageView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    if (m_image.isNull()) {
        p.setPen(palette().color(QPalette::BrightText));
        p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, placeholderText());
        return;
    }
    paintContent(p, rect());
    if (hasFocus()) {  // reached by Tab: the zoom keys act here
        p.setPen(QPen(palette().color(QPalette::Highlight), 2));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(rect()).adjusted(1, 1, -1, -1));
    }
}

void ImageView::paintContent(QPainter& p, const QRect& area) const {
    p.save();
    p.translate(m_offset);
    p.scale(m_zoom, m_zoom);
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(QPointF(0, 0), m_image);
    p.translate(0.5, 0.5);  // now pixel centres are at integer coordinates
    p.setRenderHint(QPainter::Antialiasing, true);
    if (m_overlay) m_overlay(p, m_zoom);
    paintRegions(p);
    p.restore();
    for (int i = 0; i < m_regions.size(); ++i) drawRegionLabel(p, m_regions[i], i, [this](QPointF q) { return toWidget(q); });
    const BadgeLayout badge = layoutBadge(area);
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

void ImageView::paintRegions(QPainter& p) const {
    for (int i = 0; i < m_regions.size(); ++i) drawRegion(p, m_regions[i], m_zoom, i == m_selected);
}

void ImageView::wheelEvent(QWheelEvent* e) {
    if (m_image.isNull()) return;
    zoomAbout(e->position(), m_zoom * std::pow(1.0015, e->angleDelta().y()));
}

void ImageView::mousePressEvent(QMouseEvent* e) {
    m_dragStart = e->position();
    m_rightPress = false;
    const bool ctrl = e->modifiers() & Qt::ControlModifier;
    if (e->button() == Qt::MiddleButton || (ctrl && (e->button() == Qt::LeftButton || e->button() == Qt::RightButton))) {
        if (m_image.isNull()) return;
        m_drag = Drag::Contrast;  // DS9: x sets the bias, y the contrast
        emit contrastBiasStarted();
        return;
    }
    m_rightPress = e->button() == Qt::RightButton;
    if (m_rightPress || (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier))) {
        m_drag = Drag::Box;
    } else if (e->button() == Qt::LeftButton && m_mode != MouseMode::Pan && !m_image.isNull()) {
        regionPress(e->position());
    } else if (e->button() == Qt::LeftButton) {
        m_drag = Drag::Pan;
        m_offsetStart = m_offset;
    }
}

void ImageView::regionPress(QPointF pos) {
    const int hit = regionAt(pos);
    if (hit >= 0) {
        m_drag = Drag::MoveRegion;
        m_selected = hit;
        m_regionStart = m_regions[hit];
    } else {
        m_drag = Drag::DrawRegion;
        core::RegionStatsParams r;
        r.shape = m_mode == MouseMode::CircleRegion ? core::RegionShape::Circle : core::RegionShape::Box;
        const QPointF at = toImage(pos);
        r.centerX = at.x();
        r.centerY = at.y();
        m_regions << r;
        m_selected = int(m_regions.size()) - 1;
    }
    update();
}

void ImageView::regionMove(QPointF pos) {
    if (m_selected < 0 || m_selected >= m_regions.size()) return;
    core::RegionStatsParams& r = m_regions[m_selected];
    const QPointF a = toImage(m_dragStart), b = toImage(pos);
    if (m_drag == Drag::MoveRegion) {
        r.centerX = m_regionStart.centerX + (b.x() - a.x());
        r.centerY = m_regionStart.centerY + (b.y() - a.y());
    } else if (r.shape == core::RegionShape::Circle) {  // from the centre out, as DS9 draws
        r.centerX = a.x();
        r.centerY = a.y();
        r.radius = std::hypot(b.x() - a.x(), b.y() - a.y());
    } else {  // corner to corner
        r.centerX = (a.x() + b.x()) / 2;
        r.centerY = (a.y() + b.y()) / 2;
        r.width = std::abs(b.x() - a.x());
        r.height = std::abs(b.y() - a.y());
    }
    update();
    emit regionsChanged();
}

void ImageView::mouseMoveEvent(QMouseEvent* e) {
    if (m_drag == Drag::Pan) {
        m_offset = m_offsetStart + (e->position() - m_dragStart);
        m_fit = false;
        update();
        emitViewChanged();
    } else if (m_drag == Drag::Contrast) {
        const QPointF d = e->position() - m_dragStart;
        emit contrastBiasDragged(d.x() / std::max(1, width()), d.y() / std::max(1, height()));
    } else if (m_drag == Drag::DrawRegion || m_drag == Drag::MoveRegion) {
        regionMove(e->position());
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
    if (drag == Drag::DrawRegion) {
        // A click (no drag) draws nothing: it selects the region under it, if any.
        if ((e->position() - m_dragStart).manhattanLength() < 4 && m_selected >= 0) {
            m_regions.remove(m_selected);
            m_selected = regionAt(e->position());
            update();
            return;
        }
        emit regionsChanged();
        return;
    }
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
        case Qt::Key_Delete:
        case Qt::Key_Backspace:
            if (m_selected >= 0) deleteRegion(m_selected);
            else QWidget::keyPressEvent(e);
            break;
        default: QWidget::keyPressEvent(e);
    }
}

// A zoomed view keeps its magnification of the fit (as the zoom steps are) and the image point
// at its centre: a blink tile shown alone, or a window made larger, shows the same part.
void ImageView::resizeEvent(QResizeEvent* e) {
    if (m_fit) {
        fitToWindow();
        return;
    }
    const QSize old = e->oldSize();
    if (!old.isValid() || m_image.isNull() || old.isEmpty()) return;
    const QPointF centre = toImage(QPointF(old.width(), old.height()) / 2);
    const double oldFit = std::max(kMinZoom, std::min(old.width() / double(m_image.width()), old.height() / double(m_image.height())));
    m_zoom = std::clamp(m_zoom / oldFit * fitZoom(), kMinZoom, kMaxZoom);
    m_offset = QPointF(width(), height()) / 2 - (centre + QPointF(0.5, 0.5)) * m_zoom;
}

void ImageView::setMouseMode(MouseMode m) {
    m_mode = m;
    setCursor(m == MouseMode::Pan ? Qt::ArrowCursor : Qt::CrossCursor);
}

void ImageView::setRegions(const QVector<core::RegionStatsParams>& regions) {
    m_regions = regions;
    m_selected = -1;
    update();
    emit regionsChanged();
}

void ImageView::deleteRegion(int index) {
    if (index < 0 || index >= m_regions.size()) return;
    m_regions.remove(index);
    m_selected = -1;
    update();
    emit regionsChanged();
}

QVector<core::RegionStatsResult> ImageView::regionStats() const {
    QVector<core::RegionStatsResult> out;
    for (const core::RegionStatsParams& r : m_regions) {
        if (m_data.empty()) {
            core::RegionStatsResult none;
            none.error = "no image";
            out << none;
        } else {
            out << core::regionStats(m_data, r);
        }
    }
    return out;
}

// The last region drawn is on top: it is the one a press takes.
int ImageView::regionAt(QPointF widgetPos) const {
    const QPointF at = toImage(widgetPos);
    const double slack = 3 / m_zoom;  // a few screen pixels around the outline
    for (int i = int(m_regions.size()) - 1; i >= 0; --i)
        if (regionContains(m_regions[i], at, slack)) return i;
    return -1;
}

QRect ImageView::shownImageRect() const {
    const QRectF img(toWidget(QPointF(-0.5, -0.5)), toWidget(QPointF(m_image.width() - 0.5, m_image.height() - 0.5)));
    return (img & QRectF(rect())).toAlignedRect() & rect();
}

int ImageView::exportHeight(int width) const {
    const QRect area = shownImageRect();
    if (area.isEmpty()) return 0;
    return std::max(1, int(std::lround(double(width) * area.height() / area.width())));
}

QImage ImageView::renderView(int width) const {
    const QRect area = shownImageRect();
    if (m_image.isNull() || area.isEmpty() || width < 1) return {};
    QImage out(width, exportHeight(width), QImage::Format_ARGB32);
    out.fill(Qt::black);
    QPainter p(&out);
    const double s = double(width) / area.width();
    p.scale(s, s);
    p.translate(-area.topLeft());
    paintContent(p, area);
    return out;
}

bool ImageView::exportView(const QString& path, int width, QString* error) const {
    const QRect area = shownImageRect();
    if (m_image.isNull() || area.isEmpty()) {
        *error = tr("no image to export");
        return false;
    }
    const QString suffix = QFileInfo(path).suffix().toLower();
    const QSize size(width, exportHeight(width));
    auto draw = [&](QPaintDevice* dev, double s) {
        QPainter p(dev);
        p.scale(s, s);
        p.translate(-area.topLeft());
        paintContent(p, area);
        return p.isActive();
    };
    QSaveFile f(path);  // written whole, then renamed into place
    if (!f.open(QIODevice::WriteOnly)) {
        *error = f.errorString();
        return false;
    }
    bool drawn = false;
    if (suffix == "svg") {
        QSvgGenerator svg;
        svg.setOutputDevice(&f);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(m_exportName);
        drawn = draw(&svg, double(width) / area.width());
    } else if (suffix == "pdf") {
        QPdfWriter pdf(&f);
        pdf.setResolution(96);
        pdf.setPageSize(QPageSize(QSizeF(size), QPageSize::Point));  // 1 px = 1 pt
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        drawn = draw(&pdf, double(pdf.width()) / area.width());
    } else {
        const QImage img = renderView(width);
        drawn = !img.isNull() && img.save(&f, "PNG");
    }
    if (!drawn || !f.commit()) {
        *error = drawn ? f.errorString() : tr("cannot draw the view into %1").arg(path);
        return false;
    }
    return true;
}

bool ImageView::exportDialog() {
    if (m_image.isNull()) return false;
    bool ok = false;
    const int width = QInputDialog::getInt(this, tr("Export view"), tr("Width in pixels (the height follows the view):"),
                                           std::max(1024, shownImageRect().width()), 16, 16000, 1, &ok);
    if (!ok) return false;
    const QString name = (m_exportName.isEmpty() ? QStringLiteral("view") : m_exportName);
    const QString path = askSavePath(this, tr("Export view"), "paths/lastViewExport", name + ".png",
                                     tr("PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf)"));
    if (path.isEmpty()) return false;
    QString err;
    if (!exportView(path, width, &err)) {
        emit status(tr("Cannot export the view: %1").arg(err));
        return false;
    }
    emit status(tr("Exported the view (%1 × %2 px) to %3").arg(width).arg(exportHeight(width)).arg(path));
    return true;
}

}  // namespace lwb::ui
