#include "ui/footprint_workspace.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <qcustomplot.h>

#include "core/common/json.hpp"
#include "core/footprint/image_io.hpp"
#include "ui/color_maps.hpp"
#include "ui/demo.hpp"
#include "ui/footprint_params_panel.hpp"
#include "ui/image_view.hpp"
#include "ui/shot_table_model.hpp"
#include "ui/workspace_layout.hpp"

namespace lwb::ui {

using namespace core::footprint;

namespace {
const QColor kGaussColor(0, 220, 255);
const QColor kTefmColor(255, 165, 0);
const QColor kGcmColor(255, 64, 255);
const QColor kDomainColor(255, 255, 255, 200);

QString overrideKey(const Shot& s) {
    return s.hasCenter ? QString("%1#%2,%3").arg(s.file).arg(s.center.x()).arg(s.center.y()) : s.file;
}

// Ellipse through a painter rotated to the axis at `angle` (rad) from +x.
void drawEllipse(QPainter& p, QPointF c, double a, double b, double angleRad, const QPen& pen) {
    p.save();
    p.translate(c);
    p.rotate(angleRad * 180 / M_PI);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(QPointF(0, 0), a, b);
    p.restore();
}

void drawCross(QPainter& p, QPointF c, double size, const QPen& pen, bool diagonal) {
    p.setPen(pen);
    if (diagonal) {
        p.drawLine(c + QPointF(-size, -size), c + QPointF(size, size));
        p.drawLine(c + QPointF(-size, size), c + QPointF(size, -size));
    } else {
        p.drawLine(c + QPointF(-size, 0), c + QPointF(size, 0));
        p.drawLine(c + QPointF(0, -size), c + QPointF(0, size));
    }
}

QCustomPlot* makePlot(const QString& yLabel, QWidget* parent) {
    auto* plot = new QCustomPlot(parent);
    plot->setMinimumHeight(150);
    auto ticker = QSharedPointer<QCPAxisTickerDateTime>(new QCPAxisTickerDateTime);
    ticker->setDateTimeFormat("yyyy-MM");
    ticker->setDateTimeSpec(Qt::UTC);
    plot->xAxis->setTicker(ticker);
    plot->xAxis->setLabel(QObject::tr("Month (UTC)"));
    plot->yAxis->setLabel(yLabel);
    plot->legend->setVisible(true);
    plot->legend->setFont(QFont(plot->font().family(), 8));
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    plot->legend->setBrush(QColor(255, 255, 255, 200));
    plot->legend->setRowSpacing(0);
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    return plot;
}

QDateTime parseTime(const QString& t) {
    QDateTime d = QDateTime::fromString(t, Qt::ISODate);
    if (!d.isValid()) d = QDateTime::fromString(t.left(10), "yyyy-MM-dd");
    if (!d.isValid()) d = QDateTime::fromString(t.left(7) + "-15", "yyyy-MM-dd");
    d.setTimeSpec(Qt::UTC);
    return d;
}
}  // namespace

FootprintWorkspace::FootprintWorkspace(QWidget* parent) : QWidget(parent) {
    m_controller = new FootprintController(this);
    m_model = new ShotTableModel(m_controller, this);
    m_proxy = new ShotFilterProxy(this);
    m_proxy->setSourceModel(m_model);
    m_proxy->setSortRole(ShotTableModel::SortRole);

    // Left: the shot list.
    auto* left = new QWidget(this);
    auto* leftLay = new QVBoxLayout(left);
    leftLay->setContentsMargins(0, 0, 0, 0);
    auto* filterRow = new QHBoxLayout;
    m_filter = new QComboBox(left);
    m_filter->addItems({tr("All shots"), tr("Good only"), tr("Doubtful only"), tr("Rejected only"), tr("Manual verdicts")});
    m_counts = new QLabel(left);
    m_counts->setWordWrap(true);  // a long count line wraps instead of widening the window (issue 10 layout)
    filterRow->addWidget(new QLabel(tr("Show:"), left));
    filterRow->addWidget(m_filter);
    filterRow->addWidget(m_counts, 1);
    leftLay->addLayout(filterRow);
    m_table = new QTableView(left);
    m_table->setModel(m_proxy);
    m_table->setSortingEnabled(true);
    m_table->sortByColumn(-1, Qt::AscendingOrder);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->setDefaultSectionSize(20);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setColumnWidth(ShotTableModel::File, 150);
    m_table->setColumnWidth(ShotTableModel::Time, 84);
    m_table->setColumnWidth(ShotTableModel::Beam, 40);
    m_table->setColumnWidth(ShotTableModel::X, 64);
    m_table->setColumnWidth(ShotTableModel::Y, 64);
    m_table->setColumnWidth(ShotTableModel::VerdictCol, 70);
    m_table->setColumnWidth(ShotTableModel::Reasons, 160);
    leftLay->addWidget(m_table, 1);
    auto* overrideRow = new QHBoxLayout;
    auto* accept = new QPushButton(tr("Accept (A)"), left);
    auto* reject = new QPushButton(tr("Reject (R)"), left);
    auto* clearOv = new QPushButton(tr("Auto"), left);
    clearOv->setToolTip(tr("Drop the manual verdict and use the computed one"));
    overrideRow->addWidget(accept);
    overrideRow->addWidget(reject);
    overrideRow->addWidget(clearOv);
    leftLay->addLayout(overrideRow);
    m_note = new QLineEdit(left);
    m_note->setPlaceholderText(tr("Note on this shot (kept in the session and the export)"));
    leftLay->addWidget(m_note);

    // Centre: review and trend tabs.
    m_tabs = new QTabWidget(this);
    auto* review = new QWidget(m_tabs);
    auto* revLay = new QVBoxLayout(review);
    auto* viewRow = new QHBoxLayout;
    m_colorMap = new QComboBox(review);
    m_colorMap->addItems(colorMapNames());
    m_colorMap->setCurrentIndex(1);
    m_stretch = new QComboBox(review);
    m_stretch->addItems(stretchNames());
    m_showGauss = new QCheckBox(tr("Gaussian 1/e²"), review);
    m_showTefm = new QCheckBox(tr("TEFM ellipse"), review);
    m_showDomain = new QCheckBox(tr("Domain"), review);
    m_showCentres = new QCheckBox(tr("Centres"), review);
    for (QCheckBox* c : {m_showGauss, m_showTefm, m_showDomain, m_showCentres}) c->setChecked(true);
    viewRow->addWidget(new QLabel(tr("Colours:"), review));
    viewRow->addWidget(m_colorMap);
    viewRow->addWidget(m_stretch);
    viewRow->addSpacing(8);
    for (QCheckBox* c : {m_showGauss, m_showTefm, m_showDomain, m_showCentres}) viewRow->addWidget(c);
    viewRow->addStretch(1);
    revLay->addLayout(wrapRow(viewRow));  // wraps in a narrow window (issue 10 layout)
    auto* views = new QSplitter(Qt::Horizontal, review);
    m_roiView = new ImageView(views);
    m_frameView = new ImageView(views);
    views->addWidget(m_roiView);
    views->addWidget(m_frameView);
    views->setStretchFactor(0, 3);
    views->setStretchFactor(1, 2);
    revLay->addWidget(views, 1);
    m_readout = new QLabel(tr("Move the cursor over the ROI for pixel values"), review);
    revLay->addWidget(m_readout);
    m_details = new QLabel(review);
    m_details->setTextFormat(Qt::RichText);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details->setWordWrap(true);
    revLay->addWidget(m_details);
    m_tabs->addTab(review, tr("Review"));

    auto* trend = new QWidget(m_tabs);
    auto* trendLay = new QVBoxLayout(trend);
    m_plotX = makePlot(tr("ΔX from 1st month (px)"), trend);
    m_plotY = makePlot(tr("ΔY from 1st month (px)"), trend);
    m_plotPointing = makePlot(tr("Pointing change (arcsec)"), trend);
    m_trendSummary = new QLabel(trend);
    m_trendSummary->setWordWrap(true);
    trendLay->addWidget(m_plotX, 1);
    trendLay->addWidget(m_plotY, 1);
    trendLay->addWidget(m_plotPointing, 1);
    trendLay->addWidget(m_trendSummary);
    m_tabs->addTab(trend, tr("Trend"));

    // Right: parameters.
    m_panel = new FootprintParamsPanel(this);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_panel);
    scroll->setWidgetResizable(true);
    fitPanelWidth(scroll);  // as wide as the panel needs: nothing cut off, no sideways scrolling

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(left);
    split->addWidget(m_tabs);
    split->addWidget(scroll);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    split->setStretchFactor(2, 0);
    split->setSizes({470, 620, 340});
    auto* lay = new QHBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    lay->addWidget(split);

    // Wiring.
    connect(m_filter, &QComboBox::currentIndexChanged, this,
            [this](int i) { m_proxy->setVerdictFilter(ShotFilterProxy::Filter(i)); });
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this] { currentRowChanged(); });
    connect(m_panel, &FootprintParamsPanel::paramsChanged, this, [this](const FootprintParams& p) {
        m_controller->setParams(p);
        emit modified();
    });
    connect(m_controller, &FootprintController::currentDetailReady, this, &FootprintWorkspace::showDetail);
    connect(m_controller, &FootprintController::countsChanged, this, &FootprintWorkspace::updateCounts);
    connect(m_controller, &FootprintController::rejudgeFinished, this, &FootprintWorkspace::refreshTrend);
    connect(m_controller, &FootprintController::shotsAppended, this, [this](int, int) {
        applyPendingOverrides();
        if (!m_table->currentIndex().isValid() && m_proxy->rowCount() > 0) m_table->selectRow(0);
    });
    connect(m_controller, &FootprintController::shotsReset, this, [this] {
        if (m_proxy->rowCount() > 0) m_table->selectRow(0);
    });
    connect(m_controller, &FootprintController::loadProgress, this,
            [this](int done, int total) { emit status(tr("Loaded %1 of %2 shots").arg(done).arg(total)); });
    connect(m_controller, &FootprintController::loadFinished, this, [this](int loaded, int failed, bool cancelled) {
        emit status(cancelled ? tr("Loading cancelled after %1 shots").arg(loaded)
                              : tr("Loaded %1 shots (%2 unreadable)").arg(loaded).arg(failed));
        refreshTrend();
    });
    for (QComboBox* c : {m_colorMap, m_stretch})
        connect(c, &QComboBox::currentIndexChanged, this, [this] { showDetail(m_detail); });
    for (QCheckBox* c : {m_showGauss, m_showTefm, m_showDomain, m_showCentres})
        connect(c, &QCheckBox::toggled, this, [this] { m_roiView->update(); });
    connect(m_roiView, &ImageView::pixelHovered, this, [this](double x, double y, double v) {
        m_readout->setText(tr("Pixel (%1, %2): %3 DN").arg(x, 0, 'f', 0).arg(y, 0, 'f', 0).arg(v, 0, 'f', 0));
    });
    connect(m_frameView, &ImageView::pixelHovered, this, [this](double x, double y, double v) {
        m_readout->setText(tr("Frame pixel (%1, %2): %3 DN").arg(x, 0, 'f', 0).arg(y, 0, 'f', 0).arg(v, 0, 'f', 0));
    });
    connect(accept, &QPushButton::clicked, this, &FootprintWorkspace::acceptCurrent);
    connect(reject, &QPushButton::clicked, this, &FootprintWorkspace::rejectCurrent);
    connect(clearOv, &QPushButton::clicked, this, [this] {
        m_controller->clearOverride(currentSourceRow());
        emit modified();
    });
    connect(m_note, &QLineEdit::editingFinished, this, [this] {
        const Shot* s = m_controller->shot(currentSourceRow());
        if (s && s->note != m_note->text()) {
            m_controller->setNote(currentSourceRow(), m_note->text());
            emit modified();
        }
    });
    auto* a = new QShortcut(QKeySequence(Qt::Key_A), m_table, nullptr, nullptr, Qt::WidgetShortcut);
    auto* r = new QShortcut(QKeySequence(Qt::Key_R), m_table, nullptr, nullptr, Qt::WidgetShortcut);
    connect(a, &QShortcut::activated, this, &FootprintWorkspace::acceptCurrent);
    connect(r, &QShortcut::activated, this, &FootprintWorkspace::rejectCurrent);

    m_roiView->setOverlay([this](QPainter& p, double scale) {
        const ShotDetail& d = m_detail;
        if (d.roi.empty()) return;
        const double lw = 1.6 / scale;
        if (m_showDomain->isChecked() && d.selected.domain.found) {
            const auto& dom = d.selected.domain;
            const int w = dom.width, h = dom.height;
            QPainterPath path;
            auto in = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && dom.mask[size_t(y) * w + x]; };
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    if (!in(x, y)) continue;
                    if (!in(x - 1, y)) { path.moveTo(x - 0.5, y - 0.5); path.lineTo(x - 0.5, y + 0.5); }
                    if (!in(x + 1, y)) { path.moveTo(x + 0.5, y - 0.5); path.lineTo(x + 0.5, y + 0.5); }
                    if (!in(x, y - 1)) { path.moveTo(x - 0.5, y - 0.5); path.lineTo(x + 0.5, y - 0.5); }
                    if (!in(x, y + 1)) { path.moveTo(x - 0.5, y + 0.5); path.lineTo(x + 0.5, y + 0.5); }
                }
            p.setPen(QPen(kDomainColor, lw, Qt::DotLine));
            p.drawPath(path);
        }
        if (m_showGauss->isChecked() && d.gauss.fit.ok)
            drawEllipse(p, {d.gauss.fit.x, d.gauss.fit.y}, 2 * d.gauss.fit.sigmaX, 2 * d.gauss.fit.sigmaY,
                        d.gauss.fit.tiltRad, QPen(kGaussColor, lw));
        if (m_showTefm->isChecked() && d.tefm.fit.ok)
            drawEllipse(p, {d.tefm.tefm.ellipseX, d.tefm.tefm.ellipseY}, d.tefm.tefm.ellipseA, d.tefm.tefm.ellipseB,
                        d.tefm.tefm.ellipseAngleRad, QPen(kTefmColor, lw, Qt::DashLine));
        if (m_showCentres->isChecked()) {
            const double s = 0.6;
            if (d.gcm.fit.ok) drawCross(p, {d.gcm.fit.x, d.gcm.fit.y}, s, QPen(kGcmColor, lw), false);
            if (d.tefm.fit.ok) drawCross(p, {d.tefm.fit.x, d.tefm.fit.y}, s, QPen(kTefmColor, lw), true);
            if (d.gauss.fit.ok) drawCross(p, {d.gauss.fit.x, d.gauss.fit.y}, s, QPen(kGaussColor, lw * 1.3), true);
        }
    });
    updateCounts();
}

int FootprintWorkspace::currentSourceRow() const {
    const QModelIndex i = m_table->currentIndex();
    return i.isValid() ? m_proxy->mapToSource(i).row() : -1;
}

void FootprintWorkspace::selectRow(int sourceRow) {
    const QModelIndex p = m_proxy->mapFromSource(m_model->index(sourceRow, 0));
    if (p.isValid()) m_table->selectRow(p.row());
}

void FootprintWorkspace::currentRowChanged() {
    const int row = currentSourceRow();
    m_controller->setCurrent(row);
    const Shot* s = m_controller->shot(row);
    m_note->setText(s ? s->note : QString());
}

void FootprintWorkspace::showTab(const QString& name) { m_tabs->setCurrentIndex(name == "trend" ? 1 : 0); }

void FootprintWorkspace::acceptCurrent() {
    const int row = currentSourceRow();
    if (row < 0) return;
    m_controller->setOverride(row, Verdict::Good, m_note->text());
    emit modified();
    const int next = m_table->currentIndex().row() + 1;
    if (next < m_proxy->rowCount()) m_table->selectRow(next);
}

void FootprintWorkspace::rejectCurrent() {
    const int row = currentSourceRow();
    if (row < 0) return;
    m_controller->setOverride(row, Verdict::Rejected, m_note->text());
    emit modified();
    const int next = m_table->currentIndex().row() + 1;
    if (next < m_proxy->rowCount()) m_table->selectRow(next);
}

void FootprintWorkspace::updateCounts() {
    const auto c = m_controller->counts();
    QString t = tr("<span style='color:#2e8b57'>%1 good</span> · <span style='color:#d68910'>%2 doubtful</span> · "
                   "<span style='color:#c0392b'>%3 rejected</span>")
                    .arg(c.good)
                    .arg(c.doubtful)
                    .arg(c.rejected);
    if (c.pending) t += tr(" · %1 pending").arg(c.pending);
    if (c.overridden) t += tr(" · %1 manual").arg(c.overridden);
    m_counts->setText(t);
}

void FootprintWorkspace::showDetail(const ShotDetail& d) {
    m_detail = d;
    const Shot* s = m_controller->shot(d.index);
    if (!s || d.roi.empty()) {
        m_roiView->clear();
        m_frameView->clear();
        m_details->setText(s ? tr("<b>%1</b><br>%2").arg(s->file.toHtmlEscaped(), s->loadError.toHtmlEscaped()) : QString());
        return;
    }
    const ColorMap cm = colorMapFromIndex(m_colorMap->currentIndex());
    const Stretch st = stretchFromIndex(m_stretch->currentIndex());
    m_roiView->setImage(d.roi, renderImage(d.roi, cm, st), QPointF(d.origin));
    const FootprintResult& r = d.selected;
    const Verdict v = s->effectiveVerdict();
    QString badge = verdictLabel(v).toUpper();
    if (s->overridden) badge += tr(" (manual; computed: %1)").arg(verdictLabel(s->verdict));
    for (const auto& reason : r.reasons) badge += "\n• " + QString::fromStdString(reason);
    m_roiView->setBadge(badge, verdictColor(v));
    // Full-frame context.
    if (s->fullFrame) {
        if (m_frameFile != s->file) {
            const ImageReadResult img = readFrame(s->file.toStdString());
            m_frame = img.ok ? img.image : cv::Mat();
            m_frameFile = s->file;
        }
        if (!m_frame.empty()) {
            // Show a 128 px window of the frame around the ROI.
            const int half = 64;
            const int cx = d.origin.x() + d.roi.cols / 2, cy = d.origin.y() + d.roi.rows / 2;
            const cv::Rect win = cv::Rect(cx - half, cy - half, 2 * half, 2 * half) & cv::Rect(0, 0, m_frame.cols, m_frame.rows);
            const cv::Mat crop = m_frame(win).clone();
            m_frameView->setImage(crop, renderImage(crop, cm, st), QPointF(win.x, win.y));
            m_frameView->setOverlay([this, win](QPainter& p, double scale) {
                const QPointF o(m_detail.origin.x() - win.x, m_detail.origin.y() - win.y);
                p.setPen(QPen(Qt::white, 1.5 / scale));
                p.setBrush(Qt::NoBrush);
                p.drawRect(QRectF(o.x() - 0.5, o.y() - 0.5, m_detail.roi.cols, m_detail.roi.rows));
                if (m_detail.selected.fit.ok)
                    drawCross(p, {m_detail.selected.fit.x + o.x(), m_detail.selected.fit.y + o.y()}, 4 / scale,
                              QPen(kGaussColor, 1.5 / scale), true);
            });
            m_frameView->setBadge(tr("Frame around the ROI"), QColor(60, 60, 60));
        }
    } else {
        m_frame.release();
        m_frameFile.clear();
        m_frameView->clear();
    }
    m_frameView->setVisible(s->fullFrame && !m_frame.empty());
    // Numbers.
    const SpotFit& f = r.fit;
    QString html = tr("<b>%1</b> — %2").arg(QFileInfo(s->file).fileName().toHtmlEscaped(),
                                             QString(methodName(r.method)));
    if (r.gaussStage.size()) html += tr(" (stage %1)").arg(QString::fromStdString(r.gaussStage));
    html += tr(" · noise class <b>%1</b>, background %2 DN ± %3")
                .arg(noiseClassName(r.background.noiseClass))
                .arg(r.background.level, 0, 'f', 0)
                .arg(r.background.noise, 0, 'f', 0);
    if (f.ok) {
        html += tr("<br>centre (%1, %2) px ± %3 · CRLB %4 px · σx %5 σy %6 px · C %7 · θ %8° · L_A %9 px")
                    .arg(f.x + d.origin.x(), 0, 'f', 3)
                    .arg(f.y + d.origin.y(), 0, 'f', 3)
                    .arg(f.uncertaintyPx, 0, 'f', 3)
                    .arg(r.crlbPx, 0, 'f', 4)
                    .arg(f.sigmaX, 0, 'f', 2)
                    .arg(f.sigmaY, 0, 'f', 2)
                    .arg(f.axisRatio, 0, 'f', 3)
                    .arg(f.tiltRad * 180 / M_PI, 0, 'f', 1)
                    .arg(f.majorAxisPx, 0, 'f', 1);
        html += tr("<br>e %1 · area %2 px · MSE %3 · SNR %4 · amplitude %5 DN")
                    .arg(f.eccentricity, 0, 'f', 3)
                    .arg(f.areaPx, 0, 'f', 0)
                    .arg(std::isfinite(f.mse) ? QString::number(f.mse, 'g', 3) : QString("—"))
                    .arg(f.snr, 0, 'f', 1)
                    .arg(f.amplitude, 0, 'f', 0);
    }
    auto centre = [&](const char* name, const FootprintResult& m, const QColor& c) {
        if (!m.fit.ok) return QString("<span style='color:%1'>%2 —</span>").arg(c.name(), name);
        return QString("<span style='color:%1'>■</span> %2 (%3, %4)")
            .arg(c.name(), name)
            .arg(m.fit.x + d.origin.x(), 0, 'f', 2)
            .arg(m.fit.y + d.origin.y(), 0, 'f', 2);
    };
    html += "<br>" + centre("Gauss", d.gauss, kGaussColor.darker(130)) + " &nbsp; " +
            centre("TEFM", d.tefm, kTefmColor.darker(120)) + " &nbsp; " + centre("GCM", d.gcm, kGcmColor.darker(130));
    m_details->setText(html);
}

void FootprintWorkspace::refreshTrend() {
    TrendParams tp;
    const TrendResult tr_ = m_controller->trend(tp);
    for (QCustomPlot* p : {m_plotX, m_plotY, m_plotPointing}) p->clearGraphs();
    if (!tr_.ok) {
        m_trendSummary->setText(tr("Trend: %1. A shot list CSV with time and beam columns (or the demo) gives the "
                                   "monthly centroid trend.").arg(QString::fromStdString(tr_.error)));
        for (QCustomPlot* p : {m_plotX, m_plotY, m_plotPointing}) p->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    static const QColor colors[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44), QColor(148, 103, 189)};
    // Every series is shown as the change from its first month's mean, so both beams share an
    // axis and a drift of a tenth of a pixel is visible.
    auto keyOf = [this](const std::string& camera, const std::string& beam) {
        return (camera.empty() ? QString() : QString::fromStdString(camera) + " ") + tr("beam ") + QString::fromStdString(beam);
    };
    std::map<QString, std::pair<double, double>> first;
    for (const TrendRow& r : tr_.rows) {
        const QString key = keyOf(r.camera, r.beam);
        if (!first.count(key)) first[key] = {r.xMean, r.yMean};
    }
    std::map<QString, int> series;
    auto seriesFor = [&](const QString& key) {
        if (series.count(key)) return series[key];
        const int k = int(series.size());
        series[key] = k;
        for (QCustomPlot* p : {m_plotX, m_plotY}) {
            QCPGraph* g = p->addGraph();
            g->setName(key + tr(" shots"));
            g->setLineStyle(QCPGraph::lsNone);
            g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colors[k % 4].lighter(150), 3));
            QCPGraph* m = p->addGraph();
            m->setName(key + tr(" monthly mean"));
            m->setPen(QPen(colors[k % 4], 2));
            m->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, colors[k % 4], 6));
        }
        QCPGraph* pg = m_plotPointing->addGraph();
        pg->setName(key);
        pg->setPen(QPen(colors[k % 4], 2));
        pg->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, colors[k % 4], 6));
        return k;
    };
    for (const Shot& s : m_controller->shots()) {
        if (s.time.isEmpty() || s.beam.isEmpty() || s.effectiveVerdict() != Verdict::Good || !s.fit.ok) continue;
        const QString key = keyOf(s.camera.toStdString(), s.beam.toStdString());
        if (!first.count(key)) continue;
        const int k = seriesFor(key);
        const double t = QCPAxisTickerDateTime::dateTimeToKey(parseTime(s.time));
        m_plotX->graph(2 * k)->addData(t, s.fullX() - first[key].first);
        m_plotY->graph(2 * k)->addData(t, s.fullY() - first[key].second);
    }
    QString summary;
    for (const TrendRow& r : tr_.rows) {
        const QString key = keyOf(r.camera, r.beam);
        const int k = seriesFor(key);
        const double t = QCPAxisTickerDateTime::dateTimeToKey(parseTime(QString::fromStdString(r.month) + "-15"));
        m_plotX->graph(2 * k + 1)->addData(t, r.dx);
        m_plotY->graph(2 * k + 1)->addData(t, r.dy);
        m_plotPointing->graph(k)->addData(t, r.pointingArcsec);
    }
    for (const auto& [key, k] : series) {
        const auto* data = m_plotPointing->graph(k)->data().data();
        if (data->isEmpty()) continue;
        summary += tr("%1: %2″ planar pointing change by the last month. ").arg(key).arg((data->constEnd() - 1)->value, 0, 'f', 3);
    }
    m_trendSummary->setText(tr("Accepted shots only; 3σ rejection within each month; 0.31″ per px. ") + summary);
    for (QCustomPlot* p : {m_plotX, m_plotY, m_plotPointing}) {
        p->rescaleAxes();
        p->xAxis->scaleRange(1.08);
        p->yAxis->scaleRange(1.15);
        p->replot(QCustomPlot::rpQueuedReplot);
    }
}

QJsonObject FootprintWorkspace::saveState() const {
    QJsonObject o;
    QJsonArray inputs;
    for (const QString& i : m_controller->inputs()) inputs.append(i);
    o["inputs"] = inputs;
    o["demo"] = m_controller->inputs().isEmpty() && m_controller->count() > 0 &&
                m_controller->shot(0)->file.startsWith("demo:");
    o["params"] = QJsonDocument::fromJson(QByteArray::fromStdString(footprintParamsToJson(m_controller->params()).dump())).object();
    QJsonObject ov;
    for (const Shot& s : m_controller->shots()) {
        if (!s.overridden && s.note.isEmpty()) continue;
        QJsonObject e;
        if (s.overridden) e["verdict"] = verdictLabel(s.overrideVerdict);
        if (!s.note.isEmpty()) e["note"] = s.note;
        ov[overrideKey(s)] = e;
    }
    o["overrides"] = ov;
    o["current"] = m_controller->current();
    return o;
}

bool FootprintWorkspace::restoreState(const QJsonObject& state, QString* error) {
    FootprintParams p;
    if (state.contains("params")) {
        const std::string text = QJsonDocument(state["params"].toObject()).toJson().toStdString();
        const core::JsonParseResult j = core::parseJson(text, "session params");
        std::string err;
        if (!j.ok || !footprintParamsFromJson(j.value, &p, &err)) {
            *error = tr("footprint parameters: %1").arg(QString::fromStdString(j.ok ? err : j.error));
            return false;
        }
    }
    const QJsonObject ov = state["overrides"].toObject();
    for (auto it = ov.begin(); it != ov.end(); ++it) {
        Verdict v;
        const QJsonObject e = it.value().toObject();
        if (e.contains("verdict") && !parseVerdict(e["verdict"].toString().toStdString(), &v)) {
            *error = tr("override of %1: unknown verdict \"%2\"").arg(it.key(), e["verdict"].toString());
            return false;
        }
    }
    m_panel->setParams(p);
    m_controller->setParams(p);
    m_pendingOverrides = ov;
    QStringList inputs;
    for (const auto& v : state["inputs"].toArray()) inputs << v.toString();
    if (state["demo"].toBool())
        m_controller->setShots(demoFootprintShots());
    else if (!inputs.isEmpty())
        m_controller->open(inputs);
    else
        m_controller->clear();
    applyPendingOverrides();
    const int cur = state["current"].toInt(-1);
    if (cur >= 0 && cur < m_controller->count()) selectRow(cur);
    return true;
}

void FootprintWorkspace::applyPendingOverrides() {
    if (m_pendingOverrides.isEmpty()) return;
    for (int i = 0; i < m_controller->count(); ++i) {
        const Shot& s = *m_controller->shot(i);
        const QString key = overrideKey(s);
        if (!m_pendingOverrides.contains(key)) continue;
        const QJsonObject e = m_pendingOverrides[key].toObject();
        if (e.contains("verdict")) {
            Verdict v = Verdict::Good;
            parseVerdict(e["verdict"].toString().toStdString(), &v);
            m_controller->setOverride(i, v, e["note"].toString());
        } else {
            m_controller->setNote(i, e["note"].toString());
        }
        m_pendingOverrides.remove(key);
    }
}

}  // namespace lwb::ui
