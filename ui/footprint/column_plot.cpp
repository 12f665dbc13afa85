#include "ui/footprint/column_plot.hpp"

#include <QComboBox>
#include <QDateTime>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>
#include <map>
#include <qcustomplot.h>

#include "ui/footprint/footprint_controller.hpp"
#include "ui/kit/plot_kit.hpp"
#include "ui/footprint/shot_columns.hpp"
#include "ui/footprint/shot_table_model.hpp"
#include "ui/kit/workspace_layout.hpp"

namespace lwb::ui {

namespace {
QString axisLabel(int col) {
    const ShotColumn& c = shotColumns()[size_t(col)];
    QString l = QLatin1String(c.name);
    if (*c.unit) l += QString(" (%1)").arg(QString::fromUtf8(c.unit));
    return l;
}

// A time axis: hh:mm:ss UTC of one day when the times span less than two days (the values then
// shifted to seconds of that day), else dates. Returns the seconds subtracted.
double setTimeAxis(QCPAxis* axis, double lo, double hi) {
    if (std::isfinite(lo) && hi - lo < 2 * 86400) {
        const QDate day = QDateTime::fromSecsSinceEpoch(qint64(std::floor(lo)), Qt::UTC).date();
        setUtcTimeAxis(axis, day, TimeAxisMode::Utc, QObject::tr("time"));
        return QDateTime(day, QTime(0, 0), Qt::UTC).toSecsSinceEpoch();
    }
    auto t = QSharedPointer<QCPAxisTickerDateTime>(new QCPAxisTickerDateTime);
    t->setDateTimeFormat("yyyy-MM-dd");
    t->setDateTimeSpec(Qt::UTC);
    axis->setTicker(t);
    axis->setLabel(QObject::tr("time (UTC date)"));
    return 0;
}
}  // namespace

ColumnPlot::ColumnPlot(FootprintController* c, ShotFilterProxy* view, QWidget* parent)
    : QWidget(parent), m_c(c), m_view(view) {
    auto* lay = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    m_x = new QComboBox(this);
    m_y = new QComboBox(this);
    for (int col : plottableShotColumns()) {
        const ShotColumn& sc = shotColumns()[size_t(col)];
        for (QComboBox* b : {m_x, m_y}) {
            b->addItem(QLatin1String(sc.name), col);
            b->setItemData(b->count() - 1, tr(sc.doc), Qt::ToolTipRole);
        }
    }
    m_x->setToolTip(tr("Column along x (every numeric column of the shot list, and the time)"));
    m_y->setToolTip(tr("Column along y"));
    auto* xl = new QLabel(tr("&X:"), this);
    auto* yl = new QLabel(tr("&Y:"), this);
    xl->setBuddy(m_x);
    yl->setBuddy(m_y);
    row->addWidget(xl);
    row->addWidget(m_x);
    row->addWidget(yl);
    row->addWidget(m_y);
    row->addStretch(1);
    lay->addLayout(wrapRow(row));
    PlotKitOptions opts;
    opts.exportName = "shot_columns";
    // The crosshair names the shot under the cursor.
    opts.readout = [this](double x, double y) {
        const QPoint px(qRound(m_plot->xAxis->coordToPixel(x)), qRound(m_plot->yAxis->coordToPixel(y)));
        const QString at = PlotKit::axisText(m_plot->xAxis, x) + ", " + PlotKit::axisText(m_plot->yAxis, y);
        const Shot* s = m_c->shot(rowAt(px));
        return s ? QFileInfo(s->file).fileName() + " — " + at : at;
    };
    m_plot = newPlot(this, QString(), QString(), QString(), opts);
    legendBelow(m_plot, 5);
    lay->addWidget(m_plot, 1);
    m_info = new QLabel(this);
    m_info->setWordWrap(true);
    lay->addWidget(m_info);
    m_timer = new QTimer(this);
    m_timer->setSingleShot(true);
    m_timer->setInterval(100);
    connect(m_timer, &QTimer::timeout, this, &ColumnPlot::refresh);
    setColumns("dx", "dy");
    for (QComboBox* b : {m_x, m_y})
        connect(b, &QComboBox::currentIndexChanged, this, [this] {
            refresh();
            emit columnsChanged();
        });
    connect(view, &QAbstractItemModel::modelReset, this, &ColumnPlot::scheduleRefresh);
    connect(view, &QAbstractItemModel::layoutChanged, this, &ColumnPlot::scheduleRefresh);
    connect(view, &QAbstractItemModel::rowsInserted, this, &ColumnPlot::scheduleRefresh);
    connect(view, &QAbstractItemModel::rowsRemoved, this, &ColumnPlot::scheduleRefresh);
    connect(view, &QAbstractItemModel::dataChanged, this, &ColumnPlot::scheduleRefresh);
    connect(m_plot, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) { m_press = e->position().toPoint(); });
    connect(m_plot, &QCustomPlot::mouseRelease, this, [this](QMouseEvent* e) {
        const QPoint p = e->position().toPoint();
        if (e->button() != Qt::LeftButton || e->modifiers() != Qt::NoModifier || (p - m_press).manhattanLength() > 3)
            return;
        const int r = rowAt(p);
        if (r >= 0) emit shotClicked(r);
    });
}

bool ColumnPlot::setColumns(const QString& x, const QString& y) {
    const int xi = m_x->findText(x, Qt::MatchFixedString), yi = m_y->findText(y, Qt::MatchFixedString);
    if (xi < 0 || yi < 0) return false;
    const QSignalBlocker bx(m_x), by(m_y);
    m_x->setCurrentIndex(xi);
    m_y->setCurrentIndex(yi);
    refresh();
    emit columnsChanged();
    return true;
}

QString ColumnPlot::xColumn() const { return m_x->currentText(); }
QString ColumnPlot::yColumn() const { return m_y->currentText(); }

void ColumnPlot::scheduleRefresh() {
    if (!m_timer->isActive()) m_timer->start();
}

void ColumnPlot::refresh() {
    m_timer->stop();
    const int xc = m_x->currentData().toInt(), yc = m_y->currentData().toInt();
    m_points.clear();
    m_plot->clearGraphs();
    // One series per verdict (as the table shows it), in the table's order of states.
    std::map<int, std::vector<const Point*>> byState;
    int inView = 0;
    std::vector<int> states;
    for (int i = 0; i < m_c->count(); ++i) {
        if (!m_view->acceptsSourceRow(i)) continue;
        ++inView;
        const Shot& s = *m_c->shot(i);
        const int roi = shotRoiIndex(*m_c, i);
        const double x = shotNumber(s, roi, xc), y = shotNumber(s, roi, yc);
        if (!std::isfinite(x) || !std::isfinite(y)) continue;
        m_points.push_back({x, y, i});
        states.push_back(int(shotState(s)));
    }
    const bool xTime = shotColumns()[size_t(xc)].kind == ShotColumnKind::Time;
    const bool yTime = shotColumns()[size_t(yc)].kind == ShotColumnKind::Time;
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (const Point& p : m_points) {
        xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
        ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
    }
    m_xOffset = 0;
    double yOffset = 0;
    if (xTime) m_xOffset = setTimeAxis(m_plot->xAxis, xlo, xhi);
    else {
        m_plot->xAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
        m_plot->xAxis->setLabel(axisLabel(xc));
    }
    if (yTime) yOffset = setTimeAxis(m_plot->yAxis, ylo, yhi);
    else {
        m_plot->yAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
        m_plot->yAxis->setLabel(axisLabel(yc));
    }
    for (Point& p : m_points) {
        p.x -= m_xOffset;
        p.y -= yOffset;
    }
    for (int st : {int(ShotState::Good), int(ShotState::Doubtful), int(ShotState::Rejected), int(ShotState::Unreadable),
                   int(ShotState::Pending)}) {
        QVector<double> xs, ys;
        for (size_t k = 0; k < m_points.size(); ++k)
            if (states[k] == st) xs << m_points[k].x, ys << m_points[k].y;
        if (xs.isEmpty()) continue;
        QCPGraph* g = m_plot->addGraph();
        const QString label = shotStateLabel(ShotState(st));
        g->setProperty("series", label);
        g->setName(tr("%1 (%2)").arg(label).arg(xs.size()));
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, shotStateColor(ShotState(st)), 6));
        g->setData(xs, ys);  // (sorted by x inside the graph; rowAt searches m_points)
    }
    QCPGraph* cur = m_plot->addGraph();
    cur->setName(tr("current shot"));
    cur->setProperty("series", "current shot");
    cur->setLineStyle(QCPGraph::lsNone);
    cur->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(0, 170, 255), 2), Qt::NoBrush, 13));
    cur->removeFromLegend();
    showCurrent();
    if (!m_points.empty()) {
        m_plot->rescaleAxes();
        for (QCPAxis* a : {m_plot->xAxis, m_plot->yAxis}) {
            if (a->range().size() <= 0) a->setRange(a->range().lower - 1, a->range().upper + 1);
            a->scaleRange(1.1);
        }
    }
    m_info->setText(
        tr("%1 of the %2 shots in view have both %3 and %4%5. Click a point to open its shot.")
            .arg(m_points.size())
            .arg(inView)
            .arg(xColumn(), yColumn())
            .arg(m_view->isFiltered() ? tr(" (the table's filter applies; %1 shots in all)").arg(m_c->count()) : QString()));
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void ColumnPlot::setCurrentRow(int sourceRow) {
    if (m_current == sourceRow) return;
    m_current = sourceRow;
    showCurrent();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void ColumnPlot::showCurrent() {
    if (m_plot->graphCount() == 0) return;
    QCPGraph* cur = m_plot->graph(m_plot->graphCount() - 1);
    cur->data()->clear();
    for (const Point& p : m_points)
        if (p.row == m_current) cur->addData(p.x, p.y);
}

int ColumnPlot::rowAt(const QPoint& pixel) const {
    int best = -1;
    double bestD = 8.0 * 8.0;
    for (const Point& p : m_points) {
        const double px = m_plot->xAxis->coordToPixel(p.x), py = m_plot->yAxis->coordToPixel(p.y);
        const double d = (px - pixel.x()) * (px - pixel.x()) + (py - pixel.y()) * (py - pixel.y());
        if (d <= bestD) {
            bestD = d;
            best = p.row;
        }
    }
    return best;
}

QPoint ColumnPlot::pixelOf(int sourceRow) const {
    for (const Point& p : m_points)
        if (p.row == sourceRow)
            return QPoint(qRound(m_plot->xAxis->coordToPixel(p.x)), qRound(m_plot->yAxis->coordToPixel(p.y)));
    return {-1, -1};
}

}  // namespace lwb::ui
