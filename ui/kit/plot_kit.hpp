#pragma once
// The plot kit every workspace's QCustomPlot goes through: one call, installPlotKit(plot), gives
//   - export as PNG, SVG and PDF and copy to the clipboard (right-click menu; exportPlot());
//   - legend entries that hide and show their series on a click (kept across data rebuilds);
//   - box zoom: drag with the right button, or Shift + left drag, or "Box zoom" in the menu;
//   - per-axis zoom: Shift + wheel zooms x only, Ctrl + wheel y only, the wheel over an axis or a
//     left drag on an axis zooms / pans that axis only; the plain wheel zooms both;
//   - reset / home view: double-click, the Home key or the menu; Backspace or the menu steps
//     back through the zoom history;
//   - the current light / dark theme (setPlotTheme), applied before every replot.
// The home view is the view the workspace last set: the kit notices a range set by code (new
// data, a refit) the next time the user zooms, and makes it the home view, so a workspace need
// not tell the kit anything; a workspace whose home is computed (an image fitted to the window)
// passes it as PlotKitOptions::home.
//
// Shared pieces of the calibration and radiometry workspaces: newPlot (a titled plot with the
// kit), legendBelow (the one legend style: a row under the axis rect, never over the data),
// addImageMap (an image plot with its colour bar), gradientFor (a colour map as a gradient),
// linkXRange (plots following a master's x range) and setUtcTimeAxis (hh:mm:ss ticks in UTC with
// the date in the axis title, or seconds of day).
#include <QColor>
#include <QDate>
#include <QObject>
#include <QPair>
#include <QPointF>
#include <QSet>
#include <QSize>
#include <QString>
#include <QVector>
#include <functional>
#include <vector>

#include "ui/kit/color_maps.hpp"

class QCustomPlot;
class QCPAxis;
class QCPAbstractLegendItem;
class QCPAbstractPlottable;
class QRubberBand;
class QCPColorMap;
class QCPColorScale;
class QCPColorGradient;
class QCPRange;
class QWidget;
class QRect;
class QPoint;

namespace lwb::ui {

/// What the kit's cursor overlay shows over a plot: a vertical line at key `x`, a horizontal line
/// at value `y` (main axes), rings on points, and a readout in the axis rect's top-left corner.
/// Drawn on a transparent widget over the plot: moving it needs no replot, exports leave it out.
struct PlotCursor {
    bool hasX = false, hasY = false;
    double x = 0, y = 0;
    QVector<QPointF> marks;  ///< points ringed, in the main axes' coordinates
    QString text;            ///< the readout
    bool isEmpty() const { return !hasX && !hasY && marks.isEmpty() && text.isEmpty(); }
};

/// Who draws the cursor: the kit (a crosshair at the mouse with its coordinates), the workspace
/// (the kit emits hovered() and hoverLeft(); the workspace calls setCursor, e.g. on every plot of
/// a pass at once), or nobody.
enum class CursorMode { Crosshair, External, Off };

struct PlotKitOptions {
    /// What reset / home does; empty: back to the view the workspace last set.
    std::function<void()> home;
    /// File name stem offered by the export dialogs; empty: the plot's title.
    QString exportName;
    /// Legend entries toggle their series on a click.
    bool legendToggle = true;
    /// The cursor (a crosshair with its readout by default).
    CursorMode cursor = CursorMode::Crosshair;
    /// The crosshair's readout for main-axes coordinates; empty: the axes' own formats
    /// (hh:mm:ss.sss on a UTC axis, digits to the pixel elsewhere, a colour map's cell value).
    std::function<QString(double x, double y)> readout;
};

class PlotKit;

/// Installs the kit on `plot` (once; a second call only updates the options). Owned by the plot.
PlotKit* installPlotKit(QCustomPlot* plot, const PlotKitOptions& options = {});
/// The kit of a plot, or nullptr.
PlotKit* plotKit(const QCustomPlot* plot);

enum class PlotFormat { Png, Svg, Pdf };
/// Writes the plot as PNG, SVG or PDF (by the path's suffix; width/height 0: the widget's size)
/// through a temporary file renamed into place. PNG: drawn at dpi / 96 image pixels per layout
/// pixel with the dpi in the file (0: 96). False with *error naming the path and the cause.
bool exportPlot(QCustomPlot* plot, const QString& path, QString* error, int width = 0, int height = 0, double dpi = 0);
/// The plot as an image on the clipboard.
void copyPlotToClipboard(QCustomPlot* plot);

/// Light or dark plots; every plot with the kit follows (now and at each replot).
void setPlotTheme(bool dark);
bool plotThemeDark();

/// The follower's x range follows the master's (one way: the follower may still zoom its y).
void linkXRange(QCustomPlot* master, QCustomPlot* follower);

/// An axis of seconds since 0 h UTC of `day`: ticks as hh:mm:ss (fractions of a second when
/// zoomed in, wrapping after midnight), the date in the title; or plain seconds of day.
enum class TimeAxisMode { Utc, SecondsOfDay };
void setUtcTimeAxis(QCPAxis* axis, const QDate& day, TimeAxisMode mode = TimeAxisMode::Utc,
                    const QString& what = QString());
/// "12:34:56.789" for seconds of day (wrapping at 24 h), with `decimals` digits of the second.
QString utcClock(double secondsOfDay, int decimals = 0);

/// A plot with a bold title row (if any), axis labels, drag and wheel, the legend style, the kit.
QCustomPlot* newPlot(QWidget* parent, const QString& title, const QString& xLabel, const QString& yLabel,
                     const PlotKitOptions& options = {});
/// The one legend style: entries in rows under the axis rect, no frame, in at most `columns`
/// columns: as many as fit across the plot (at the legend's font or a point smaller), refitted by
/// the kit before a replot when the width or the entries changed (fitLegendBelow).
void legendBelow(QCustomPlot* plot, int columns);
/// Lays a legendBelow legend out for the plot's width; true when its layout changed.
bool fitLegendBelow(QCustomPlot* plot);
/// The colour an empty (transparent) image cell shows in the current theme: the axis rect's
/// background where it has one (an image plot), else the plot's.
QColor emptyCellColor(const QCustomPlot* plot);

/// An image plot: a colour map on the main axes and its colour bar on the right with `label`.
/// yDown: row 0 on top (image pixels). The axis rect's background shows where there is no data.
struct ImageMap {
    QCPColorMap* map = nullptr;
    QCPColorScale* scale = nullptr;
};
ImageMap addImageMap(QCustomPlot* plot, const QString& label, bool yDown);
/// A colour map (ui/color_maps) as a QCustomPlot gradient; NaN cells transparent.
QCPColorGradient gradientFor(ColorMap map);

class PlotKit : public QObject {
    Q_OBJECT
public:
    PlotKit(QCustomPlot* plot, const PlotKitOptions& options);
    QCustomPlot* plot() const { return m_plot; }
    void setOptions(const PlotKitOptions& options) { m_options = options; }
    /// The file name stem the export dialogs offer (a workspace names its plots by their data).
    void setExportName(const QString& stem) { m_options.exportName = stem; }

    /// Zooms the main axis rect to a rectangle in widget pixels (x axes to its width, y axes to
    /// its height). Pushes the view before it on the history.
    void zoomToPixels(const QRect& rect);
    /// Zooms the axes of one orientation (both for 0) by `factor` (< 1: in) about a pixel.
    void zoomAxes(Qt::Orientations which, double factor, const QPoint& centre);
    /// Back to the home view (pushes the current one on the history, so back() returns).
    void home();
    /// One step back in the zoom history; false when there is none.
    bool back();
    int historyDepth() const { return int(m_history.size()); }

    /// A plottable's series key: its "series" property when set (a name that stays when the
    /// counts in the legend text change), else its name.
    static QString seriesKey(const QCPAbstractPlottable* plottable);
    /// Hides or shows the plottables whose series key is `name` (as a legend click does).
    void setSeriesHidden(const QString& name, bool hidden);
    bool isSeriesHidden(const QString& name) const { return m_hidden.contains(name); }

    /// The right-click menu (export, copy, reset, back, box zoom), built for `pos`.
    void showMenu(const QPoint& globalPos);
    /// Asks for a file and exports to it (PNG, SVG or PDF by the chosen filter).
    void exportDialog(PlotFormat format);

    /// The cursor drawn over the plot (setCursor replaces it; an empty cursor hides it).
    void setCursor(const PlotCursor& cursor);
    void clearCursor() { setCursor(PlotCursor{}); }
    const PlotCursor& cursor() const { return m_cursor; }
    /// The crosshair's readout at main-axes coordinates (the option's, else the axes' formats).
    QString readoutAt(double x, double y) const;
    /// A coordinate as its axis shows it: hh:mm:ss.sss on a UTC axis, else the digits a pixel
    /// of the axis needs.
    static QString axisText(const QCPAxis* axis, double value);

    /// Applies the theme's colours (called before every replot).
    void applyTheme();
    /// Sets each axis's tick count to what its labels fit (called before every replot).
    void fitTickCounts();
    /// The same for a layout of `layout` pixels (an export drawn at another size than the plot's:
    /// a 1600 px PNG had kept the on-screen count and labelled 0 and 5000 only, a small one ran
    /// its labels together). The next replot fits them to the screen again.
    void fitTicksTo(const QSize& layout);

signals:
    /// The mouse moved over the axis rect with no button held (main-axes coordinates and the
    /// widget pixel); CursorMode::External draws nothing itself.
    void hovered(QPointF coords, QPoint pixel);
    /// The mouse left the axis rect (or a drag began).
    void hoverLeft();

protected:
    bool eventFilter(QObject* o, QEvent* e) override;

private:
    using Snapshot = QVector<QPair<QCPAxis*, QPair<double, double>>>;
    Snapshot snapshot() const;
    void restore(const Snapshot& s);
    bool sameView(const Snapshot& a, const Snapshot& b) const;
    /// Before a user change of the view: a view the code set since becomes the home view.
    void beginUserChange();
    void endUserChange();
    QCPAxis* axisAt(const QPoint& pos) const;
    void legendClicked(QCPAbstractLegendItem* item);
    QString defaultName() const;

    QCustomPlot* m_plot;
    PlotKitOptions m_options;
    std::vector<Snapshot> m_history;
    Snapshot m_home, m_lastUser;
    bool m_haveHome = false;
    QSet<QString> m_hidden;
    // Mouse gestures.
    enum class Drag { None, Box, Axis, Pan } m_drag = Drag::None;
    QPoint m_pressPos;
    bool m_rightPress = false, m_boxNext = false;
    QCPAxis* m_dragAxis = nullptr;
    double m_dragLower = 0, m_dragUpper = 0;
    QRubberBand* m_band = nullptr;
    qint64 m_lastWheelMs = -1000000;
    QSize m_laidOut;  ///< the viewport of the last replot (fitTickCounts)
    PlotCursor m_cursor;
    QWidget* m_overlay = nullptr;  ///< draws m_cursor over the plot
    void hover(const QPoint& pos);
};

}  // namespace lwb::ui
