#include "ui/kit/plot_kit.hpp"

#include <QLocale>
#include "ui/kit/save_path.hpp"

#include <QApplication>
#include <QClipboard>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QDialogButtonBox>
#include <QDialog>
#include <QFileInfo>
#include <QKeyEvent>
#include <QMenu>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPainter>
#include <QPdfWriter>
#include <QPointer>
#include <QRegularExpression>
#include <QRubberBand>
#include <QSaveFile>
#include <QSettings>
#include <QSvgGenerator>
#include <QWheelEvent>
#include <cmath>
#include <typeinfo>
#include <qcustomplot.h>

namespace lwb::ui {

namespace {

bool g_dark = false;

struct Theme {
    QColor background, text, axis, grid, subGrid, legendBrush, legendBorder, noData, hiddenText, ink;
};

Theme theme() {
    if (g_dark)
        return {QColor(37, 40, 44),  QColor(222, 222, 222), QColor(165, 165, 165), QColor(78, 82, 88),
                QColor(58, 61, 66),  QColor(45, 48, 53, 220), QColor(100, 100, 100), QColor(70, 72, 76),
                QColor(120, 120, 120), QColor(231, 231, 231)};
    return {Qt::white, QColor(20, 20, 20), QColor(40, 40, 40), QColor(200, 200, 200), QColor(225, 225, 225),
            QColor(255, 255, 255, 215), QColor(180, 180, 180), QColor(222, 222, 222), QColor(170, 170, 170), Qt::black};
}

// The ink of series drawn "in black": black on light plots, near-white on dark ones.
const QColor kLightInk(231, 231, 231);
QColor swapInk(const QColor& c) {
    if (g_dark && c == QColor(Qt::black)) return kLightInk;
    if (!g_dark && c == kLightInk) return Qt::black;
    return c;
}

QPen inked(QPen p) {
    p.setColor(swapInk(p.color()));
    return p;
}

// Ticks as hh:mm:ss of UTC for seconds of day, wrapping after midnight.
class UtcTicker : public QCPAxisTicker {
protected:
    QString getTickLabel(double tick, const QLocale&, QChar, int) override {
        // Decimals of the second as the tick step needs them.
        const double step = m_step > 0 ? m_step : 1;
        const int decimals = step >= 1 ? 0 : std::min(6, int(std::ceil(-std::log10(step) - 1e-9)));
        return utcClock(tick, decimals);
    }
    double getTickStep(const QCPRange& range) override {
        // (the clock's steps are coarse: a step a little below range / count still fits, as the
        // count leaves a gap of two characters per label; 150 s on 2 labels' width takes 60 s
        // steps, two labels, where 75 s rounded up to 120 s left one)
        const double ideal = range.size() / (mTickCount + 0.5);
        if (ideal >= 1) {
            const double steps[] = {1, 2, 5, 10, 15, 20, 30, 60, 120, 180, 240, 300, 600, 900, 1200, 1800, 3600, 7200, 10800, 21600, 43200, 86400};
            // The first step at least the ideal one; but never a single label where two fit:
            // then the largest step that puts two ticks in the range.
            double chosen = 86400 * std::ceil(ideal / 86400), below = 0;
            for (double s : steps) {
                if (s <= range.size() / 2) below = s;
                if (s >= ideal) {
                    chosen = s;
                    break;
                }
            }
            if (mTickCount >= 2 && range.size() / chosen < 2 && below > 0) chosen = below;
            return m_step = chosen;
        }
        const double mag = std::pow(10.0, std::floor(std::log10(ideal)));
        const double m = ideal / mag;
        return m_step = (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * mag;
    }

private:
    double m_step = 1;
};

// QCustomPlot's plain ticker with one rule more: at least two ticks in the range (its nice steps
// left a 60 s pass one label, "36200", on a narrow plot).
class SpanTicker : public QCPAxisTicker {
protected:
    double getTickStep(const QCPRange& range) override {
        double step = QCPAxisTicker::getTickStep(range);
        auto ticksIn = [&](double st) { return std::floor(range.upper / st) - std::ceil(range.lower / st) + 1; };
        for (int i = 0; i < 12 && step > 0 && std::isfinite(step) && ticksIn(step) < 2; ++i) {
            // The next smaller of 1, 2, 2.5, 5 × 10^k.
            const double mag = std::pow(10.0, std::floor(std::log10(step) - 1e-12));
            const double m = step / mag;
            step = (m > 5 + 1e-9 ? 5 : m > 2.5 + 1e-9 ? 2.5 : m > 2 + 1e-9 ? 2 : m > 1 + 1e-9 ? 1 : 0.5) * mag;
        }
        return step;
    }
};

// The cursor over a plot: a transparent widget the size of the plot, above it, drawing the
// kit's PlotCursor with the axes' current mapping (so a zoom moves it with the data).
class CursorOverlay : public QWidget {
public:
    CursorOverlay(QCustomPlot* plot, const PlotCursor* cursor) : QWidget(plot), m_plot(plot), m_cursor(cursor) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
        setGeometry(plot->rect());
        show();
    }

protected:
    void paintEvent(QPaintEvent*) override {
        const PlotCursor& c = *m_cursor;
        if (c.isEmpty()) return;
        QPainter g(this);
        const QRect area = m_plot->axisRect()->rect();
        g.setClipRect(area);
        const bool dark = plotThemeDark();
        const QColor ink = dark ? QColor(230, 230, 230, 190) : QColor(40, 40, 40, 170);
        g.setPen(QPen(ink, 1, Qt::DashLine));
        const QCPAxis *xa = m_plot->xAxis, *ya = m_plot->yAxis;
        if (c.hasX) {
            const double px = xa->coordToPixel(c.x);
            if (std::isfinite(px)) g.drawLine(QPointF(px, area.top()), QPointF(px, area.bottom()));
        }
        if (c.hasY) {
            const double py = ya->coordToPixel(c.y);
            if (std::isfinite(py)) g.drawLine(QPointF(area.left(), py), QPointF(area.right(), py));
        }
        g.setRenderHint(QPainter::Antialiasing);
        for (const QPointF& m : c.marks) {
            const QPointF px(xa->coordToPixel(m.x()), ya->coordToPixel(m.y()));
            if (!std::isfinite(px.x()) || !std::isfinite(px.y())) continue;
            g.setPen(QPen(dark ? QColor(255, 235, 80) : QColor(0, 0, 0), 2));
            g.setBrush(Qt::NoBrush);
            g.drawEllipse(px, 6, 6);
        }
        if (!c.text.isEmpty()) {
            QFont f = font();
            f.setPointSizeF(std::max(7.0, f.pointSizeF() - 1));
            g.setFont(f);
            const QFontMetrics fm(f);
            const QRect box = fm.boundingRect(area.adjusted(4, 4, -4, -4), Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, c.text)
                                  .adjusted(-3, -2, 3, 2);
            g.setPen(Qt::NoPen);
            g.setBrush(dark ? QColor(30, 30, 30, 215) : QColor(255, 255, 255, 215));
            g.drawRect(box);
            g.setPen(dark ? QColor(235, 235, 235) : QColor(20, 20, 20));
            g.drawText(box.adjusted(3, 2, -3, -2), Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, c.text);
        }
    }

private:
    QCustomPlot* m_plot;
    const PlotCursor* m_cursor;
};

// A coordinate as its axis shows it: the clock on a UTC axis, else the digits one pixel needs.
QString axisValue(const QCPAxis* a, double v) {
    if (!std::isfinite(v)) return QString();
    const int pixels = std::max(1, a->orientation() == Qt::Horizontal ? a->axisRect()->width() : a->axisRect()->height());
    const double perPixel = std::fabs(a->range().size()) / pixels;
    if (dynamic_cast<UtcTicker*>(a->ticker().data())) {
        const int decimals = perPixel >= 1 ? 0 : std::min(6, int(std::ceil(-std::log10(perPixel))));
        return utcClock(v, decimals);
    }
    if (a->scaleType() == QCPAxis::stLogarithmic) return QString::number(v, 'g', 4);
    if (perPixel <= 0 || std::fabs(v) >= 1e7 || (v != 0 && std::fabs(v) < 1e-4)) return QString::number(v, 'g', 6);
    const int decimals = std::clamp(int(std::ceil(-std::log10(perPixel))), 0, 9);
    return QString::number(v, 'f', decimals);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

QString utcClock(double s, int decimals) {
    if (!std::isfinite(s)) return QString();
    double t = std::fmod(s, 86400.0);
    if (t < 0) t += 86400;
    const double scale = std::pow(10.0, decimals);
    // Round once, on the whole value, so 59.9996 s shows as the next minute.
    const qint64 units = qint64(std::llround(t * scale)) % qint64(86400 * scale);
    const qint64 whole = qint64(units / scale);
    QString out = QString("%1:%2:%3")
                      .arg(whole / 3600, 2, 10, QChar('0'))
                      .arg((whole / 60) % 60, 2, 10, QChar('0'))
                      .arg(whole % 60, 2, 10, QChar('0'));
    if (decimals > 0) out += QString(".%1").arg(units % qint64(scale), decimals, 10, QChar('0'));
    return out;
}

void setUtcTimeAxis(QCPAxis* axis, const QDate& day, TimeAxisMode mode, const QString& what) {
    const QString date = day.isValid() ? day.toString(Qt::ISODate) : QObject::tr("date unknown");
    const QString lead = what.isEmpty() ? QString() : what + ", ";
    if (mode == TimeAxisMode::Utc) {
        axis->setTicker(QSharedPointer<QCPAxisTicker>(new UtcTicker));
        axis->setLabel(QObject::tr("%1UTC on %2 (hh:mm:ss)").arg(lead, date));
    } else {
        axis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
        axis->setLabel(QObject::tr("%1seconds of day, UTC %2 (s)").arg(lead, date));
    }
}

QCPColorGradient gradientFor(ColorMap map) {
    QCPColorGradient g;
    g.clearColorStops();
    for (int i = 0; i <= 16; ++i) g.setColorStopAt(i / 16.0, QColor(mapColor(map, i / 16.0)));
    g.setNanHandling(QCPColorGradient::nhTransparent);
    return g;
}

void legendBelow(QCustomPlot* p, int columns) {
    p->legend->setVisible(true);
    p->legend->setWrap(columns);
    p->legend->setFillOrder(QCPLegend::foColumnsFirst, true);
    if (p->axisRect()->insetLayout()->elements(false).contains(p->legend)) {
        p->axisRect()->insetLayout()->take(p->legend);
        const int row = p->plotLayout()->rowCount();
        p->plotLayout()->addElement(row, 0, p->legend);
        p->plotLayout()->setRowStretchFactor(row, 0.001);
    }
    p->legend->setBorderPen(Qt::NoPen);
    p->legend->setBrush(Qt::NoBrush);
    p->setProperty("lwbLegendBelow", true);
    p->setProperty("lwbLegendColumns", std::max(1, columns));
    p->setProperty("lwbLegendPoints", p->legend->font().pointSize());
    p->setProperty("lwbLegendFitKey", QVariant());  // fitted again at the next replot
}

bool fitLegendBelow(QCustomPlot* p) {
    if (!p->property("lwbLegendBelow").toBool() || !p->legend) return false;
    QCPLegend* lg = p->legend;
    // A legend below the axes with no entry (no data yet) capped its layout column, and with it the
    // axes, at the axes' least width (~120 px of a 500 px plot, seen in a real window): QCPLayoutGrid
    // gives a column at most its elements' maximum widths, and an empty legend's is its margins.
    // While empty it is hidden and its maximum width is set explicitly (the layout then takes that
    // instead of the legend's own); with entries it is shown and sized by them again.
    const bool empty = lg->itemCount() == 0;
    if (lg->visible() == empty) {
        lg->setVisible(!empty);
        // (an explicit width: 10⁵ px, no screen's; QWIDGETSIZE_MAX − 1 plus the margins counts as unset)
        lg->setMaximumSize(empty ? 100000 : QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
    }
    if (empty) return false;
    // Only when the width or the entries changed since the last fit (it runs before every replot).
    QString key = QString::number(p->width());
    for (int i = 0; i < lg->itemCount(); ++i)
        if (auto* it = qobject_cast<QCPPlottableLegendItem*>(lg->item(i))) key += '|' + it->plottable()->name();
        else key += "|?";
    if (p->property("lwbLegendFitKey").toString() == key) return false;
    p->setProperty("lwbLegendFitKey", key);
    const int maxColumns = std::max(1, p->property("lwbLegendColumns").toInt());
    const int base = p->property("lwbLegendPoints").toInt() > 0 ? p->property("lwbLegendPoints").toInt() : lg->font().pointSize();
    const int beforeWrap = lg->wrap(), beforeSize = lg->font().pointSize();
    // The legend's room: the plot's width less the other columns of its layout row (an image's
    // colour bar beside the axes).
    int room = p->width() - p->plotLayout()->margins().left() - p->plotLayout()->margins().right();
    QCPLayoutGrid* grid = p->plotLayout();
    int legendCol = -1;
    for (int i = 0; i < grid->elementCount(); ++i)
        if (grid->elementAt(i) == lg) {
            int r = 0;
            grid->indexToRowCol(i, r, legendCol);
        }
    for (int c = 0; legendCol >= 0 && c < grid->columnCount(); ++c) {
        if (c == legendCol) continue;
        int w = 0;
        for (int r = 0; r < grid->rowCount(); ++r)
            if (grid->hasElement(r, c)) {
                // (as wide as it was laid out last; its least width before the first layout)
                const QCPLayoutElement* e = grid->element(r, c);
                w = std::max({w, e->minimumOuterSizeHint().width(), e->outerRect().width()});
            }
        room -= w + grid->columnSpacing();
    }
    auto layOut = [&](int columns, int points) {
        QFont f = lg->font();
        f.setPointSize(points);
        lg->setFont(f);
        for (int i = 0; i < lg->itemCount(); ++i)
            if (QCPAbstractLegendItem* it = lg->item(i)) it->setFont(f);
        lg->setWrap(columns);
        lg->setFillOrder(QCPLegend::foColumnsFirst, true);  // re-lays the entries out
        return lg->minimumOuterSizeHint().width() <= room;
    };
    bool fits = false;
    for (int c = maxColumns; c >= 1 && !fits; --c) fits = layOut(c, base) || layOut(c, base - 1);
    if (!fits) layOut(1, base - 1);
    return lg->wrap() != beforeWrap || lg->font().pointSize() != beforeSize;
}

QCustomPlot* newPlot(QWidget* parent, const QString& title, const QString& x, const QString& y, const PlotKitOptions& options) {
    auto* p = new QCustomPlot(parent);
    p->setMinimumSize(200, 150);
    p->xAxis->setLabel(x);
    p->yAxis->setLabel(y);
    p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    if (!title.isEmpty()) {
        p->plotLayout()->insertRow(0);
        QFont f = p->font();
        f.setBold(true);
        f.setPointSizeF(f.pointSizeF() * 0.95);
        auto* t = new QCPTextElement(p, title, f);
        t->setObjectName("title");
        p->plotLayout()->addElement(0, 0, t);
    }
    p->legend->setFont(QFont(p->font().family(), 8));
    installPlotKit(p, options);
    return p;
}

ImageMap addImageMap(QCustomPlot* p, const QString& label, bool yDown) {
    ImageMap im;
    if (yDown) p->yAxis->setRangeReversed(true);
    im.map = new QCPColorMap(p->xAxis, p->yAxis);
    im.map->setInterpolate(false);
    im.map->setTightBoundary(false);
    im.map->removeFromLegend();
    im.scale = new QCPColorScale(p);
    im.scale->setType(QCPAxis::atRight);
    im.scale->setLabel(label);
    im.scale->setBarWidth(12);
    // Beside the axis rect, in its row (under a title row when there is one).
    int row = 0;
    for (int r = 0; r < p->plotLayout()->rowCount(); ++r)
        if (p->plotLayout()->element(r, 0) == p->axisRect()) row = r;
    p->plotLayout()->addElement(row, 1, im.scale);
    im.map->setColorScale(im.scale);
    auto* group = new QCPMarginGroup(p);
    p->axisRect()->setMarginGroup(QCP::msBottom | QCP::msTop, group);
    im.scale->setMarginGroup(QCP::msBottom | QCP::msTop, group);
    p->setProperty("lwbImage", true);
    if (PlotKit* k = plotKit(p)) k->applyTheme();
    return im;
}

// ---------------------------------------------------------------------------------------------

bool exportPlot(QCustomPlot* plot, const QString& path, QString* error, int width, int height, double dpi) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const int w = width > 0 ? width : std::max(plot->width(), 100);
    const int h = height > 0 ? height : std::max(plot->height(), 80);
    QSaveFile f(path);
    auto fail = [&](const QString& why) {
        f.cancelWriting();
        if (error) *error = QObject::tr("%1: %2").arg(path, why);
        return false;
    };
    if (suffix != "png" && suffix != "svg" && suffix != "pdf")
        return fail(QObject::tr("unknown plot format \"%1\" (use .png, .svg or .pdf)").arg(suffix));
    if (!f.open(QIODevice::WriteOnly)) return fail(f.errorString());
    plot->replot(QCustomPlot::rpImmediateRefresh);  // lays out with the current data
    // Ticks as many as fit the export's layout, not the window's; the screen's come back after.
    if (PlotKit* k = plotKit(plot)) k->fitTicksTo(QSize(w, h));
    struct Refit {
        QCustomPlot* p;
        ~Refit() { p->replot(QCustomPlot::rpQueuedReplot); }
    } refit{plot};
    if (suffix == "png") {
        // Laid out at w × h, drawn at dpi / 96 pixels per layout pixel, with the DPI in the file
        // (a 1600 × 1000 layout at 300 dpi: 5000 × 3125 pixels, 13.3 × 8.3 cm when placed).
        const double scale = dpi > 0 ? dpi / 96.0 : 1.0;
        QImage img = plot->toPixmap(w, h, scale).toImage();
        if (img.isNull()) return fail(QObject::tr("cannot render the plot as PNG"));
        const int dpm = qRound((dpi > 0 ? dpi : 96.0) / 0.0254);
        img.setDotsPerMeterX(dpm);
        img.setDotsPerMeterY(dpm);
        if (!img.save(&f, "PNG")) return fail(QObject::tr("cannot render the plot as PNG"));
    } else if (suffix == "svg") {
        QSvgGenerator gen;
        gen.setOutputDevice(&f);
        gen.setSize(QSize(w, h));
        gen.setViewBox(QRect(0, 0, w, h));
        gen.setTitle(QFileInfo(path).completeBaseName());
        gen.setDescription(QObject::tr("Laser Workbench plot"));
        QCPPainter painter;
        if (!painter.begin(&gen)) return fail(QObject::tr("cannot start the SVG painter"));
        painter.setMode(QCPPainter::pmVectorized);
        plot->toPainter(&painter, w, h);
        painter.end();
    } else {
        QPdfWriter pdf(&f);
        pdf.setCreator(QObject::tr("Laser Workbench"));
        pdf.setResolution(72);  // one device unit = one point = one screen pixel of the plot
        pdf.setPageSize(QPageSize(QSizeF(w, h), QPageSize::Point, QString(), QPageSize::ExactMatch));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        QCPPainter painter;
        if (!painter.begin(&pdf)) return fail(QObject::tr("cannot start the PDF painter"));
        painter.setMode(QCPPainter::pmVectorized);
        plot->toPainter(&painter, w, h);
        painter.end();
    }
    if (!f.commit()) return fail(f.errorString());
    plot->replot(QCustomPlot::rpQueuedReplot);
    return true;
}

void copyPlotToClipboard(QCustomPlot* plot) {
    QApplication::clipboard()->setPixmap(plot->toPixmap(plot->width(), plot->height(), plot->devicePixelRatioF()));
}

// ---------------------------------------------------------------------------------------------

void setPlotTheme(bool dark) {
    g_dark = dark;
    for (QWidget* w : QApplication::allWidgets())
        if (auto* p = qobject_cast<QCustomPlot*>(w))
            if (PlotKit* k = plotKit(p)) {
                k->applyTheme();
                p->replot(QCustomPlot::rpQueuedReplot);
            }
}

bool plotThemeDark() { return g_dark; }

void linkXRange(QCustomPlot* master, QCustomPlot* follower) {
    QPointer<QCustomPlot> f(follower);
    QObject::connect(master->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), follower, [f](const QCPRange& r) {
        if (!f || f->xAxis->range() == r) return;
        f->xAxis->setRange(r);
        f->replot(QCustomPlot::rpQueuedReplot);
    });
}

PlotKit* plotKit(const QCustomPlot* plot) { return plot ? plot->findChild<PlotKit*>(QString(), Qt::FindDirectChildrenOnly) : nullptr; }

PlotKit* installPlotKit(QCustomPlot* plot, const PlotKitOptions& options) {
    if (PlotKit* k = plotKit(plot)) {
        k->setOptions(options);
        return k;
    }
    return new PlotKit(plot, options);
}

// ---------------------------------------------------------------------------------------------

PlotKit::PlotKit(QCustomPlot* plot, const PlotKitOptions& options) : QObject(plot), m_plot(plot), m_options(options) {
    plot->installEventFilter(this);
    plot->setFocusPolicy(Qt::ClickFocus);
    // Tick labels as the CLI and the files write numbers ("1e+04", "0.5", no grouping): Qt 6's
    // en_US and zh_CN locales write an upper-case exponent ("1E+04", seen on the calibration's
    // convergence axes), which QCustomPlot's powers of ten ("eb") do not recognise.
    plot->setLocale(QLocale::c());
    plot->setContextMenuPolicy(Qt::PreventContextMenu);  // the kit's own menu, on a right click
    // No tooltip over the whole plot (it would cover the data); the gestures are in the
    // right-click menu, Help ▸ Keyboard shortcuts and the user guide.
    connect(plot, &QCustomPlot::legendClick, this, [this](QCPLegend*, QCPAbstractLegendItem* item, QMouseEvent* e) {
        if (m_options.legendToggle && item && e->button() == Qt::LeftButton) legendClicked(item);
    });
    connect(plot, &QCustomPlot::beforeReplot, this, [this] {
        fitLegendBelow(m_plot);
        fitTickCounts();
        applyTheme();
    });
    connect(plot, &QCustomPlot::afterReplot, this, [this] {
        m_laidOut = m_plot->viewport().size();
        if (m_overlay && !m_cursor.isEmpty()) m_overlay->update();  // the cursor moves with the data
    });
    plot->setMouseTracking(true);  // the cursor follows the mouse with no button held
    m_overlay = new CursorOverlay(plot, &m_cursor);
    applyTheme();
}

void PlotKit::setCursor(const PlotCursor& cursor) {
    if (cursor.isEmpty() && m_cursor.isEmpty()) return;
    m_cursor = cursor;
    m_overlay->raise();
    m_overlay->update();
}

QString PlotKit::axisText(const QCPAxis* axis, double value) { return axisValue(axis, value); }

QString PlotKit::readoutAt(double x, double y) const {
    if (m_options.readout) return m_options.readout(x, y);
    QString text = QStringLiteral("%1, %2").arg(axisValue(m_plot->xAxis, x), axisValue(m_plot->yAxis, y));
    // The value under the cursor of a colour map on the main axes (the top one that has a cell there).
    for (int i = m_plot->plottableCount() - 1; i >= 0; --i) {
        auto* map = qobject_cast<QCPColorMap*>(m_plot->plottable(i));
        if (!map || !map->visible() || map->keyAxis() != m_plot->xAxis) continue;
        int kx = 0, ky = 0;
        map->data()->coordToCell(x, y, &kx, &ky);
        if (kx < 0 || ky < 0 || kx >= map->data()->keySize() || ky >= map->data()->valueSize()) continue;
        if (!map->data()->keyRange().contains(x) && map->data()->keySize() > 1) continue;
        const double v = map->data()->cell(kx, ky);
        if (std::isfinite(v)) text += QStringLiteral(" = %1").arg(QString::number(v, 'g', 5));
        break;
    }
    return text;
}

void PlotKit::hover(const QPoint& pos) {
    if (m_options.cursor == CursorMode::Off) return;
    if (m_drag != Drag::None || !m_plot->axisRect()->rect().contains(pos)) {
        if (m_options.cursor == CursorMode::External) emit hoverLeft();
        else clearCursor();
        return;
    }
    const QPointF c(m_plot->xAxis->pixelToCoord(pos.x()), m_plot->yAxis->pixelToCoord(pos.y()));
    if (m_options.cursor == CursorMode::External) {
        emit hovered(c, pos);
        return;
    }
    PlotCursor k;
    k.hasX = k.hasY = true;
    k.x = c.x();
    k.y = c.y();
    k.text = readoutAt(c.x(), c.y());
    setCursor(k);
}

PlotKit::Snapshot PlotKit::snapshot() const {
    Snapshot s;
    for (QCPAxis* a : m_plot->axisRect()->axes()) s.append({a, {a->range().lower, a->range().upper}});
    return s;
}

void PlotKit::restore(const Snapshot& s) {
    const QList<QCPAxis*> live = m_plot->axisRect()->axes();
    for (const auto& e : s)
        if (live.contains(e.first)) e.first->setRange(e.second.first, e.second.second);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    m_lastUser = snapshot();
}

bool PlotKit::sameView(const Snapshot& a, const Snapshot& b) const {
    if (a.size() != b.size()) return false;
    for (int i = 0; i < a.size(); ++i) {
        if (a[i].first != b[i].first) return false;
        const double tol = 1e-9 * std::max(1e-300, std::fabs(a[i].second.second - a[i].second.first));
        if (std::fabs(a[i].second.first - b[i].second.first) > tol || std::fabs(a[i].second.second - b[i].second.second) > tol)
            return false;
    }
    return true;
}

void PlotKit::beginUserChange() {
    const Snapshot now = snapshot();
    if (!m_haveHome || !sameView(now, m_lastUser)) {
        // The code set this view since the user last zoomed: it is the new home, the old
        // history is of other data.
        m_home = now;
        m_haveHome = true;
        m_history.clear();
    }
    if (!m_history.empty() && sameView(m_history.back(), now)) return;  // already the last step
    m_history.push_back(now);
    if (m_history.size() > 100) m_history.erase(m_history.begin());
}

void PlotKit::endUserChange() {
    m_lastUser = snapshot();
    // A gesture that changed nothing (a click) leaves no history step.
    if (!m_history.empty() && sameView(m_history.back(), m_lastUser)) m_history.pop_back();
}

void PlotKit::zoomToPixels(const QRect& r0) {
    const QRect r = r0.normalized().intersected(m_plot->axisRect()->rect());
    if (r.width() < 3 || r.height() < 3) return;
    beginUserChange();
    for (QCPAxis* a : m_plot->axisRect()->axes()) {
        const bool horizontal = a->orientation() == Qt::Horizontal;
        const double c0 = a->pixelToCoord(horizontal ? r.left() : r.top());
        const double c1 = a->pixelToCoord(horizontal ? r.right() : r.bottom());
        a->setRange(std::min(c0, c1), std::max(c0, c1));
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    endUserChange();
}

void PlotKit::zoomAxes(Qt::Orientations which, double factor, const QPoint& centre) {
    for (QCPAxis* a : m_plot->axisRect()->axes())
        if (which.testFlag(a->orientation()))
            a->scaleRange(factor, a->pixelToCoord(a->orientation() == Qt::Horizontal ? centre.x() : centre.y()));
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void PlotKit::home() {
    beginUserChange();  // the current view, so that back() returns to it
    if (m_options.home) m_options.home();
    else restore(m_home);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    endUserChange();
}

bool PlotKit::back() {
    if (m_history.empty()) return false;
    const Snapshot s = m_history.back();
    m_history.pop_back();
    restore(s);
    return true;
}

QCPAxis* PlotKit::axisAt(const QPoint& pos) const {
    if (m_plot->axisRect()->rect().contains(pos)) return nullptr;
    for (QCPAxis* a : m_plot->axisRect()->axes())
        if (a->visible() && a->selectTest(pos, false) >= 0) return a;
    return nullptr;
}

// A series is known by its "series" property when the workspace sets one (a name with a count
// in it, "signal (121)", changes at each run), else by its name.
QString PlotKit::seriesKey(const QCPAbstractPlottable* pl) {
    const QString key = pl->property("series").toString();
    return key.isEmpty() ? pl->name() : key;
}

void PlotKit::setSeriesHidden(const QString& name, bool hidden) {
    if (hidden) m_hidden.insert(name);
    else m_hidden.remove(name);
    for (int i = 0; i < m_plot->plottableCount(); ++i)
        if (seriesKey(m_plot->plottable(i)) == name) m_plot->plottable(i)->setVisible(!hidden);
    applyTheme();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void PlotKit::legendClicked(QCPAbstractLegendItem* item) {
    auto* pli = qobject_cast<QCPPlottableLegendItem*>(item);
    if (!pli) return;
    const QString name = seriesKey(pli->plottable());
    setSeriesHidden(name, !m_hidden.contains(name));
}

void PlotKit::fitTickCounts() {
    // As many ticks as their labels fit: a fixed count crowded "20:19:20:19:20" together on a
    // narrow plot and left a single label on a wide one. The widest label of the last layout
    // (at least a clock's "00:00:00") plus a gap per tick across, two text lines per tick up.
    // This runs before the layout of the replot: a resize has changed the viewport but not yet
    // the axis rects, whose sizes are taken as the new viewport less the last layout's margins
    // (m_laidOut: the viewport of the last replot).
    const QSize last = m_laidOut.isValid() ? m_laidOut : m_plot->viewport().size(), now = m_plot->viewport().size();
    for (QCPAxisRect* r : m_plot->axisRects())
        for (QCPAxis* a : r->axes()) {
            if (!a->ticker() || !a->visible()) continue;
            // A plain ticker becomes the kit's (two ticks at least), with its settings.
            if (typeid(*a->ticker()) == typeid(QCPAxisTicker)) {
                auto span = QSharedPointer<SpanTicker>(new SpanTicker);
                span->setTickStepStrategy(a->ticker()->tickStepStrategy());
                span->setTickOrigin(a->ticker()->tickOrigin());
                a->setTicker(span);
            }
            const QFontMetrics fm(a->tickLabelFont());
            int count;
            if (a->orientation() == Qt::Horizontal) {
                int widest = fm.horizontalAdvance(QStringLiteral("00:00:00"));
                for (const QString& label : a->tickVectorLabels()) widest = std::max(widest, fm.horizontalAdvance(label));
                const int width = r->width() + now.width() - last.width();
                count = std::clamp(width / (widest + 2 * fm.averageCharWidth() + 8), 2, 8);
                // The tickers round the step to nice values (a date axis to whole months), which
                // can put labels closer than the count meant: try the ticks that count gives and
                // take fewer while two labels come within 4 px of each other.
                const QCPRange range = a->range();
                const double perPx = width > 0 ? range.size() / width : 0;
                for (; count > 2 && perPx > 0 && a->scaleType() == QCPAxis::stLinear; --count) {
                    a->ticker()->setTickCount(count);
                    QVector<double> ticks;
                    QVector<QString> labels;
                    a->ticker()->generate(range, m_plot->locale(), a->numberFormat().isEmpty() ? QLatin1Char('g') : a->numberFormat().at(0),
                                          a->numberPrecision(), ticks, nullptr, &labels);
                    bool apart = true;
                    for (int i = 1; i < ticks.size() && i < labels.size() && apart; ++i)
                        apart = std::fabs(ticks[i] - ticks[i - 1]) / perPx >=
                                (fm.horizontalAdvance(labels[i]) + fm.horizontalAdvance(labels[i - 1])) / 2.0 + 4;
                    if (apart) break;
                }
            } else {
                count = (r->height() + now.height() - last.height()) / (3 * fm.height());
            }
            a->ticker()->setTickCount(std::clamp(count, 2, 8));
        }
}

void PlotKit::fitTicksTo(const QSize& layout) {
    const QSize was = m_laidOut;
    const QRect shown = m_plot->viewport();
    m_laidOut = shown.size();  // (the axis rects are the on-screen layout's)
    m_plot->setViewport(QRect(QPoint(0, 0), layout));
    fitTickCounts();
    m_plot->setViewport(shown);
    m_laidOut = was;
}

QColor emptyCellColor(const QCustomPlot* plot) {
    const QCPAxisRect* r = plot ? plot->axisRect() : nullptr;
    if (r && r->backgroundBrush().style() != Qt::NoBrush) return r->backgroundBrush().color();
    return theme().background;
}

void PlotKit::applyTheme() {
    const Theme t = theme();
    QCustomPlot* p = m_plot;
    p->setBackground(t.background);
    auto styleAxis = [&](QCPAxis* a) {
        a->setBasePen(QPen(t.axis, 1));
        a->setTickPen(QPen(t.axis, 1));
        a->setSubTickPen(QPen(t.axis, 1));
        a->setTickLabelColor(t.text);
        a->setLabelColor(t.text);
        a->grid()->setPen(QPen(t.grid, 1, Qt::DotLine));
        a->grid()->setSubGridPen(QPen(t.subGrid, 1, Qt::DotLine));
        a->grid()->setZeroLinePen(QPen(t.grid, 1));
    };
    for (QCPAxisRect* r : p->axisRects()) {
        for (QCPAxis* a : r->axes()) styleAxis(a);
        r->setBackground(p->property("lwbImage").toBool() ? QBrush(t.noData) : QBrush(Qt::NoBrush));
    }
    for (QCPLayoutElement* e : p->plotLayout()->elements(true)) {
        if (auto* te = qobject_cast<QCPTextElement*>(e)) te->setTextColor(t.text);
        if (auto* cs = qobject_cast<QCPColorScale*>(e)) styleAxis(cs->axis());
    }
    if (!p->property("lwbLegendBelow").toBool()) {
        p->legend->setBrush(t.legendBrush);
        p->legend->setBorderPen(QPen(t.legendBorder));
    } else {
        // A legend in a row of its own is on the plot's background: QCPLegend's default white
        // brush under the dark theme's light text had left its entries blank (issue 42).
        p->legend->setBrush(Qt::NoBrush);
    }
    p->legend->setTextColor(t.text);
    // Series: the hidden ones (by name, so a rebuild keeps them hidden), black ink swapped.
    for (int i = 0; i < p->plottableCount(); ++i) {
        QCPAbstractPlottable* pl = p->plottable(i);
        const QString key = seriesKey(pl);
        if (!key.isEmpty() && m_hidden.contains(key)) pl->setVisible(false);
        pl->setPen(inked(pl->pen()));
        if (auto* g = qobject_cast<QCPGraph*>(pl)) {
            QCPScatterStyle ss = g->scatterStyle();
            if (ss.pen().color() == QColor(Qt::black) || ss.pen().color() == kLightInk) {
                ss.setPen(inked(ss.pen()));
                g->setScatterStyle(ss);
            }
        }
        if (QCPPlottableLegendItem* li = p->legend->itemWithPlottable(pl))
            li->setTextColor(m_hidden.contains(key) ? t.hiddenText : t.text);
    }
    // Labels drawn on the plot.
    for (int i = 0; i < p->itemCount(); ++i)
        if (auto* it = qobject_cast<QCPItemText*>(p->item(i))) it->setColor(t.text);
}

QString PlotKit::defaultName() const {
    if (!m_options.exportName.isEmpty()) return m_options.exportName;
    for (QCPLayoutElement* e : m_plot->plotLayout()->elements(true))
        if (auto* te = qobject_cast<QCPTextElement*>(e)) {
            QString s = te->text().toLower();
            s.replace(QRegularExpression("[^a-z0-9]+"), "-");
            s = s.mid(0, 48);
            while (s.endsWith('-')) s.chop(1);
            while (s.startsWith('-')) s.remove(0, 1);
            if (!s.isEmpty()) return s;
        }
    return QStringLiteral("plot");
}

// The size of an exported plot: its layout in pixels (points for SVG and PDF) and, for PNG,
// the resolution; remembered between exports. False when cancelled.
static bool askExportSize(QWidget* parent, PlotFormat format, QSize shown, QSize* size, double* dpi) {
    QSettings st;
    QDialog dlg(parent);
    dlg.setWindowTitle(QObject::tr("Plot size"));
    auto* form = new QFormLayout(&dlg);
    auto* w = new QSpinBox(&dlg);
    auto* h = new QSpinBox(&dlg);
    for (QSpinBox* b : {w, h}) {
        b->setRange(100, 10000);
        b->setSuffix(format == PlotFormat::Png ? QObject::tr(" px") : QObject::tr(" pt"));
    }
    w->setValue(st.value("plotExport/width", std::max(shown.width(), 800)).toInt());
    h->setValue(st.value("plotExport/height", std::max(shown.height(), 500)).toInt());
    auto* asShown = new QPushButton(QObject::tr("As shown (%1 × %2)").arg(shown.width()).arg(shown.height()), &dlg);
    QObject::connect(asShown, &QPushButton::clicked, &dlg, [=] {
        w->setValue(shown.width());
        h->setValue(shown.height());
    });
    form->addRow(format == PlotFormat::Png ? QObject::tr("Layout width") : QObject::tr("Width"), w);
    form->addRow(format == PlotFormat::Png ? QObject::tr("Layout height") : QObject::tr("Height"), h);
    form->addRow(QString(), asShown);
    auto* res = new QSpinBox(&dlg);
    res->setRange(72, 1200);
    res->setSuffix(QObject::tr(" dpi"));
    res->setValue(st.value("plotExport/dpi", 192).toInt());
    res->setToolTip(QObject::tr("Pixels per inch of the image: the layout above is drawn at dpi / 96 pixels per pixel "
                                "(96: as on screen; 300: print)"));
    // What will be written, said as the numbers change (issue 42: "192 dpi, 1200 px" wrote a
    // 2400 px image without saying so).
    auto* outcome = new QLabel(&dlg);
    outcome->setObjectName("exportOutcome");
    auto say = [=] {
        const double scale = res->value() / 96.0;
        const int pw = qRound(w->value() * scale), ph = qRound(h->value() * scale);
        outcome->setText(format == PlotFormat::Png
                             ? QObject::tr("Writes %1 × %2 pixels (%3 × %4 cm at %5 dpi): the layout drawn at %6×")
                                   .arg(pw).arg(ph)
                                   .arg(pw / double(res->value()) * 2.54, 0, 'f', 1)
                                   .arg(ph / double(res->value()) * 2.54, 0, 'f', 1)
                                   .arg(res->value())
                                   .arg(scale, 0, 'g', 3)
                             : QObject::tr("Writes a page of %1 × %2 points (%3 × %4 cm)")
                                   .arg(w->value()).arg(h->value())
                                   .arg(w->value() / 72.0 * 2.54, 0, 'f', 1)
                                   .arg(h->value() / 72.0 * 2.54, 0, 'f', 1));
    };
    for (QSpinBox* b : {w, h, res}) QObject::connect(b, &QSpinBox::valueChanged, &dlg, say);
    say();
    if (format == PlotFormat::Png) form->addRow(QObject::tr("Resolution"), res);
    form->addRow(outcome);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dlg);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dlg, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dlg, &QDialog::reject);
    form->addRow(buttons);
    if (dlg.exec() != QDialog::Accepted) return false;
    *size = QSize(w->value(), h->value());
    *dpi = format == PlotFormat::Png ? res->value() : 0;
    st.setValue("plotExport/width", size->width());
    st.setValue("plotExport/height", size->height());
    if (format == PlotFormat::Png) st.setValue("plotExport/dpi", res->value());
    return true;
}

void PlotKit::exportDialog(PlotFormat format) {
    const QString ext = format == PlotFormat::Png ? "png" : format == PlotFormat::Svg ? "svg" : "pdf";
    const QString filter = format == PlotFormat::Png   ? tr("PNG image (*.png)")
                           : format == PlotFormat::Svg ? tr("SVG drawing (*.svg)")
                                                       : tr("PDF document (*.pdf)");
    QSize size;
    double dpi = 0;
    if (!askExportSize(m_plot, format, m_plot->size(), &size, &dpi)) return;
    const QString path = askSavePath(m_plot, tr("Export the plot"), "paths/plotExport", defaultName() + "." + ext, filter);
    if (path.isEmpty()) return;
    QString err;
    if (!exportPlot(m_plot, path, &err, size.width(), size.height(), dpi)) QMessageBox::warning(m_plot, tr("Cannot export the plot"), err);
}

void PlotKit::showMenu(const QPoint& globalPos) {
    QMenu menu(m_plot);
    menu.addAction(tr("Reset view\tHome / double-click"), this, &PlotKit::home);
    menu.addAction(tr("Back\tBackspace"), this, [this] { back(); })->setEnabled(!m_history.empty());
    menu.addAction(tr("Box zoom (next drag)\tright-drag / Shift+drag"), this, [this] { m_boxNext = true; });
    if (!m_hidden.isEmpty())
        menu.addAction(tr("Show all series"), this, [this] {
            const QSet<QString> names = m_hidden;
            for (const QString& n : names) setSeriesHidden(n, false);
        });
    menu.addSeparator();
    menu.addAction(tr("Export as PNG…"), this, [this] { exportDialog(PlotFormat::Png); });
    menu.addAction(tr("Export as SVG…"), this, [this] { exportDialog(PlotFormat::Svg); });
    menu.addAction(tr("Export as PDF…"), this, [this] { exportDialog(PlotFormat::Pdf); });
    menu.addAction(tr("Copy to clipboard"), this, [this] { copyPlotToClipboard(m_plot); });
    menu.exec(globalPos);
}

namespace {

// A box drag's rubber band from the press to the mouse, shown once the mouse has moved 5 pixels.
void showRubberBand(QRubberBand*& band, QCustomPlot* plot, const QPoint& from, const QPoint& to) {
    if ((to - from).manhattanLength() < 5 && !band) return;
    if (!band) band = new QRubberBand(QRubberBand::Rectangle, plot);
    band->setGeometry(QRect(from, to).normalized());
    band->show();
}

// An axis dragged from `from` to `to`: its range at the press (lower, upper) shifted by the drag
// (scaled on a logarithmic axis).
void dragAxisRange(QCPAxis* a, double lower, double upper, const QPoint& from, const QPoint& to) {
    a->setRange(lower, upper);
    const bool h = a->orientation() == Qt::Horizontal;
    const double c0 = a->pixelToCoord(h ? from.x() : from.y());
    const double c1 = a->pixelToCoord(h ? to.x() : to.y());
    if (a->scaleType() == QCPAxis::stLogarithmic && c0 > 0 && c1 > 0) a->setRange(lower * c0 / c1, upper * c0 / c1);
    else a->setRange(lower + c0 - c1, upper + c0 - c1);
}

// Home: the home view; Backspace: one step back. True when the key was one of them.
bool homeOrBackKey(PlotKit& kit, const QKeyEvent* ke) {
    if (ke->key() == Qt::Key_Home) {
        kit.home();
        return true;
    }
    if (ke->key() == Qt::Key_Backspace) {
        kit.back();
        return true;
    }
    return false;
}

}  // namespace

bool PlotKit::eventFilter(QObject* o, QEvent* e) {
    if (o != m_plot) return false;
    switch (e->type()) {
    case QEvent::Wheel: {
        auto* we = static_cast<QWheelEvent*>(e);
        const QPoint pos = we->position().toPoint();
        const int delta = we->angleDelta().y() != 0 ? we->angleDelta().y() : we->angleDelta().x();
        if (delta == 0) return true;
        Qt::Orientations which = Qt::Horizontal | Qt::Vertical;
        if (QCPAxis* a = axisAt(pos)) which = a->orientation();
        else if (!m_plot->axisRect()->rect().contains(pos)) return false;  // over the legend, the colour bar
        if (we->modifiers() & Qt::ShiftModifier) which = Qt::Horizontal;
        else if (we->modifiers() & Qt::ControlModifier) which = Qt::Vertical;
        // One history step per wheel gesture (a pause of 0.6 s starts a new one).
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        if (now - m_lastWheelMs > 600 || !sameView(snapshot(), m_lastUser)) beginUserChange();
        m_lastWheelMs = now;
        zoomAxes(which, std::pow(0.85, delta / 120.0), pos);
        endUserChange();
        return true;
    }
    case QEvent::MouseButtonPress: {
        auto* me = static_cast<QMouseEvent*>(e);
        const QPoint pos = me->position().toPoint();
        m_pressPos = pos;
        if (me->button() == Qt::RightButton) {
            m_rightPress = true;
            m_drag = Drag::Box;
            return true;
        }
        if (me->button() != Qt::LeftButton) return false;
        if (m_boxNext || ((me->modifiers() & Qt::ShiftModifier) && m_plot->selectionRectMode() == QCP::srmNone &&
                          m_plot->axisRect()->rect().contains(pos))) {
            m_boxNext = false;
            m_drag = Drag::Box;
            return true;
        }
        if (QCPAxis* a = axisAt(pos)) {
            m_drag = Drag::Axis;
            m_dragAxis = a;
            beginUserChange();
            m_dragLower = a->range().lower;
            m_dragUpper = a->range().upper;
            return true;
        }
        if (m_plot->axisRect()->rect().contains(pos)) {
            m_drag = Drag::Pan;
            beginUserChange();
        }
        return false;
    }
    case QEvent::MouseMove: {
        auto* me = static_cast<QMouseEvent*>(e);
        const QPoint pos = me->position().toPoint();
        if (m_drag == Drag::Box) {
            showRubberBand(m_band, m_plot, m_pressPos, pos);
            return true;
        }
        if (m_drag == Drag::Axis && m_dragAxis) {
            dragAxisRange(m_dragAxis, m_dragLower, m_dragUpper, m_pressPos, pos);
            m_plot->replot(QCustomPlot::rpQueuedReplot);
            return true;
        }
        if (!(me->buttons() & (Qt::LeftButton | Qt::RightButton))) hover(pos);
        else if (!m_cursor.isEmpty() || m_options.cursor == CursorMode::External) hover(QPoint(-1, -1));  // hidden while dragging
        return false;
    }
    case QEvent::Leave:
        hover(QPoint(-1, -1));
        return false;
    case QEvent::Resize:
        m_overlay->setGeometry(m_plot->rect());
        return false;
    case QEvent::MouseButtonRelease: {
        auto* me = static_cast<QMouseEvent*>(e);
        const QPoint pos = me->position().toPoint();
        const Drag drag = m_drag;
        m_drag = Drag::None;
        if (drag == Drag::Box) {
            const bool wasBand = m_band && m_band->isVisible();
            if (m_band) m_band->hide();
            if (wasBand || (pos - m_pressPos).manhattanLength() >= 5) zoomToPixels(QRect(m_pressPos, pos));
            else if (m_rightPress) showMenu(m_plot->mapToGlobal(pos));
            m_rightPress = false;
            return true;
        }
        if (drag == Drag::Axis) {
            m_dragAxis = nullptr;
            endUserChange();
            return true;
        }
        if (drag == Drag::Pan) endUserChange();
        return false;
    }
    case QEvent::MouseButtonDblClick: {
        auto* me = static_cast<QMouseEvent*>(e);
        if (me->button() == Qt::LeftButton) home();
        return false;
    }
    case QEvent::KeyPress:
        return homeOrBackKey(*this, static_cast<QKeyEvent*>(e));
    default:
        return false;
    }
}

}  // namespace lwb::ui
