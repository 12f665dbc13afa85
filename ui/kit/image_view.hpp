#pragma once
// A zoomable, pannable image view with overlays drawn in image coordinates (x = column,
// y = row, pixel centres at integers) and a pixel readout under the cursor. The wheel zooms
// about the cursor and a drag pans; a right-drag or Shift+drag zooms to the box (as the plots
// do, ui/plot_kit); the zoom steps 2×, 4× and 8× magnify the fitted view about its centre
// (keys 2, 4, 8, or the right-click menu), and 1, Home or a double-click fit it again.
// DS9's other gestures: a middle-drag or Ctrl+drag asks for contrast (up/down) and bias
// (left/right) of the display mapping (contrastBias* signals: the owner of the display limits
// applies them, ui/contrast_bias.hpp); in a region mode (right-click menu) a drag draws a box or
// circle region, a drag on a region moves it, Delete removes the selected one, and the regions'
// pixel statistics come from the core (core/common/region_stats.hpp). The view as shown, with
// its overlays, regions and badge, exports to PNG, SVG or PDF at a chosen size.
#include <QImage>
#include <QPointF>
#include <QRect>
#include <QVector>
#include <QWidget>

class QPainter;
#include <functional>
#include <opencv2/core.hpp>

#include "core/common/region_stats.hpp"

class QRubberBand;

namespace lwb::ui {

/// Where a badge of `size` goes in `area`: the first corner (top left, top right, bottom left,
/// bottom right), `margin` px in from the edges, whose box stays at least `clearance` px from
/// every point of `keepClear`. An empty rect when no corner does.
QRect placeBadge(const QRect& area, QSize size, int margin, const QVector<QPointF>& keepClear, double clearance);

class ImageView : public QWidget {
    Q_OBJECT
public:
    explicit ImageView(QWidget* parent = nullptr);

    /// What a left drag does: pan, or draw box / circle regions (a drag on a region moves it).
    enum class MouseMode { Pan, BoxRegion, CircleRegion };
    void setMouseMode(MouseMode m);
    MouseMode mouseMode() const { return m_mode; }

    /// Regions in data coordinates (as the overlay's); they stay when the image changes.
    const QVector<core::RegionStatsParams>& regions() const { return m_regions; }
    void setRegions(const QVector<core::RegionStatsParams>& regions);
    int selectedRegion() const { return m_selected; }
    void deleteRegion(int index);
    /// Statistics of every region on the current data (data coordinates; add origin() for the
    /// full image's).
    QVector<core::RegionStatsResult> regionStats() const;
    QPointF origin() const { return m_origin; }

    /// Zoom and centre, relative to the fit (so that views of different sizes can share them).
    struct ViewState {
        bool fit = true;
        double magnification = 1;  ///< zoom / fitZoom()
        QPointF centre;            ///< image point at the view's centre
    };
    ViewState viewState() const;
    /// Applies a state without emitting viewChanged().
    void setViewState(const ViewState& s);

    /// The image part of the view as shown (overlays, regions, badge; no focus frame) scaled to
    /// `width` pixels wide (the height follows the shown part's aspect). Null without an image.
    QImage renderView(int width) const;
    /// Height of the export for a width (the shown part's aspect).
    int exportHeight(int width) const;
    /// Writes renderView(width) as PNG, or the same drawing as SVG or PDF, chosen by the suffix.
    bool exportView(const QString& path, int width, QString* error) const;
    /// The name the export dialog offers (without suffix): the shot's file stem and the view.
    void setExportName(const QString& name) { m_exportName = name; }
    /// Asks for a width and a file (ui/save_path), then exports; false when cancelled or failed.
    bool exportDialog();

    /// The data (CV_32FC1, for the readout) and its rendering. origin: full-image coordinates of
    /// the data's pixel (0,0), shown in the readout.
    void setImage(const cv::Mat& data, const QImage& rendered, QPointF origin = {});
    /// Drops the image and the badge; the overlay function stays (it draws the next image).
    /// message: what the view says in the image's place (why there is none); empty: "No image".
    void clear(const QString& message = QString());
    /// Painter callback for overlays; the painter is already transformed to image coordinates
    /// (one unit = one pixel; pixel (x, y) covers x−0.5..x+0.5). pxScale: screen px per image px.
    using OverlayFn = std::function<void(class QPainter&, double pxScale)>;
    void setOverlay(OverlayFn fn);
    bool hasOverlay() const { return bool(m_overlay); }
    bool hasImage() const { return !m_image.isNull(); }
    void setBadge(const QString& text, const QColor& color);
    /// Image points (data coordinates, as the overlay's) the badge must leave in view: the spot's
    /// centre markers. The badge takes the first corner clear of them; when the whole badge fits
    /// in none, its first line (the verdict) does. Dropped with the image (clear()).
    void setKeepClear(const QVector<QPointF>& points);
    void fitToWindow();
    /// Screen pixels per image pixel.
    double zoom() const { return m_zoom; }
    /// The zoom at which the whole image fits the view.
    double fitZoom() const;
    /// The zoom steps: `magnification` times the fit (1: the fit itself), about the view's centre.
    void setZoomStep(double magnification);
    /// Zooms so that a box of widget pixels fills the view, the box's centre at the view's.
    void zoomToBox(const QRectF& widgetBox);
    /// Widget position of an image point (data coordinates, as the overlay's).
    QPointF toWidget(QPointF image) const;
    /// The part of the image in view (data coordinates, pixel edges at ±0.5).
    QRectF visibleImageRect() const;
    /// Where the badge is drawn (widget pixels; empty without a badge or an image).
    QRect badgeRect() const { return layoutBadge().box; }
    /// What the view says in place of an image.
    QString placeholderText() const { return m_message.isEmpty() ? tr("No image") : m_message; }

signals:
    /// Cursor moved over pixel (x, y) of the data (full-image coordinates) holding value.
    void pixelHovered(double x, double y, double value);
    /// The user zoomed or panned (not setViewState).
    void viewChanged();
    /// A contrast / bias drag (middle or Ctrl+drag) started; then moved by dx, dy as fractions of
    /// the view's width and height (right, down positive) from where it started.
    void contrastBiasStarted();
    void contrastBiasDragged(double dxFraction, double dyFraction);
    void contrastBiasResetRequested();
    /// A region was drawn, moved or deleted, or the data under them changed.
    void regionsChanged();
    /// A status line (an export written or refused).
    void status(const QString& message);

protected:
    void paintEvent(QPaintEvent*) override;
    void wheelEvent(class QWheelEvent*) override;
    void mousePressEvent(class QMouseEvent*) override;
    void mouseMoveEvent(class QMouseEvent*) override;
    void mouseReleaseEvent(class QMouseEvent*) override;
    void mouseDoubleClickEvent(class QMouseEvent*) override;
    void keyPressEvent(class QKeyEvent*) override;
    void resizeEvent(class QResizeEvent*) override;
    QSize sizeHint() const override { return {360, 360}; }

private:
    struct BadgeLayout {
        QRect box;
        QString text;
    };
    BadgeLayout layoutBadge() const { return layoutBadge(rect()); }
    BadgeLayout layoutBadge(const QRect& area) const;
    /// Draws the image, the overlay, the regions and the badge (placed in `area`, widget px).
    void paintContent(QPainter& p, const QRect& area) const;
    void paintRegions(QPainter& p) const;
    /// The image's part of the widget (widget px).
    QRect shownImageRect() const;
    int regionAt(QPointF widgetPos) const;
    void emitViewChanged();
    void regionPress(QPointF pos);
    void regionMove(QPointF pos);
    QPointF toImage(QPointF widget) const;
    /// Sets the zoom keeping the image point under widgetPos where it is.
    void zoomAbout(QPointF widgetPos, double zoom);
    void showMenu(const QPoint& globalPos);
    cv::Mat m_data;
    QImage m_image;
    QPointF m_origin;
    OverlayFn m_overlay;
    QString m_badge;
    QColor m_badgeColor;
    QVector<QPointF> m_keepClear;
    QString m_message;  // said in place of the image
    double m_zoom = 1;
    QPointF m_offset;  // widget position of image point (−0.5, −0.5)
    bool m_fit = true;
    // Mouse gestures: a left drag pans, a right drag (or Shift + left) draws a zoom box, a
    // middle or Ctrl+drag sets contrast and bias; in a region mode a left drag draws or moves.
    enum class Drag { None, Pan, Box, Contrast, DrawRegion, MoveRegion } m_drag = Drag::None;
    MouseMode m_mode = MouseMode::Pan;
    QVector<core::RegionStatsParams> m_regions;
    int m_selected = -1;
    core::RegionStatsParams m_regionStart;
    bool m_applyingState = false;
    QString m_exportName;
    bool m_rightPress = false;
    QPointF m_dragStart, m_offsetStart;
    QRubberBand* m_band = nullptr;
};

}  // namespace lwb::ui
