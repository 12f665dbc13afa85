#include "ui/calib/calib_workspace.hpp"

#include <QApplication>
#include <utility>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QJsonArray>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>
#include <map>
#include <qcustomplot.h>

#include <QUndoStack>
#include <algorithm>
#include "ui/kit/save_path.hpp"
#include "ui/kit/app_undo.hpp"
#include "ui/calib/calib_params_panel.hpp"
#include "ui/kit/color_maps.hpp"
#include "ui/kit/param_slider.hpp"
#include "ui/kit/plot_kit.hpp"
#include "ui/kit/session_json.hpp"
#include "ui/kit/workspace_layout.hpp"

namespace lwb::ui {

using namespace core::calib;

namespace {

const QColor kBlue(31, 119, 180), kOrange(255, 127, 14), kGreen(44, 160, 44), kRed(214, 39, 40), kGrey(150, 150, 150),
    kPurple(148, 103, 189);

// Shows a box of data with one unit of x as long on screen as one unit of y: the box is
// centred and the shorter side widened. The box is kept (as a property) and refitted whenever
// the plot is resized.
void fitEqual(QCustomPlot* plot, double x0, double x1, double y0, double y1) {
    plot->setProperty("box", QRectF(QPointF(x0, y0), QPointF(x1, y1)));
    const QRect ar = plot->axisRect()->rect();
    const double w = std::max(x1 - x0, 1e-12), h = std::max(y1 - y0, 1e-12);
    if (ar.width() < 10 || ar.height() < 10) {
        plot->xAxis->setRange(x0, x1);
        plot->yAxis->setRange(y0, y1);
        return;
    }
    const double s = std::max(w / ar.width(), h / ar.height());  // data units per pixel
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
    plot->xAxis->setRange(cx - 0.5 * s * ar.width(), cx + 0.5 * s * ar.width());
    plot->yAxis->setRange(cy - 0.5 * s * ar.height(), cy + 0.5 * s * ar.height());
}

// Back to the kept box (the plot kit's home view of an equal-aspect plot).
void refitEqual(QCustomPlot* p) {
    const QRectF b = p->property("box").toRectF();
    if (b.isNull()) return;
    fitEqual(p, b.left(), b.right(), b.top(), b.bottom());
    p->replot(QCustomPlot::rpQueuedReplot);
}

class EqualAspect : public QObject {
public:
    explicit EqualAspect(QCustomPlot* plot) : QObject(plot), m_plot(plot) {
        plot->installEventFilter(this);
        PlotKitOptions o;
        o.home = [plot] { refitEqual(plot); };
        installPlotKit(plot, o);
    }

protected:
    bool eventFilter(QObject* o, QEvent* e) override {
        if (o == m_plot && e->type() == QEvent::Resize)
            QMetaObject::invokeMethod(m_plot, [p = m_plot] { refitEqual(p); }, Qt::QueuedConnection);
        return false;
    }

private:
    QCustomPlot* m_plot;
};

QCPGraph* scatter(QCustomPlot* p, const QString& name, QCPScatterStyle style, QCPAxis* y = nullptr) {
    QCPGraph* g = p->addGraph(p->xAxis, y ? y : p->yAxis);
    g->setName(name);
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(style);
    return g;
}

QCPCurve* ellipseCurve(QCustomPlot* p, const QString& name, const QPen& pen) {
    auto* c = new QCPCurve(p->xAxis, p->yAxis);
    c->setName(name);
    c->setPen(pen);
    c->setScatterStyle(QCPScatterStyle::ssNone);
    return c;
}

// Points of an ellipse with semi-axes a, b, the a-axis at `angle` from +x toward +y.
void setEllipse(QCPCurve* c, double x0, double y0, double a, double b, double angle) {
    QVector<double> t, x, y;
    const double ca = std::cos(angle), sa = std::sin(angle);
    for (int i = 0; i <= 120; ++i) {
        const double u = 2 * M_PI * i / 120;
        t << i;
        x << x0 + a * ca * std::cos(u) - b * sa * std::sin(u);
        y << y0 + a * sa * std::cos(u) + b * ca * std::sin(u);
    }
    c->setData(t, x, y, true);
}

QString num(double v, int decimals) { return std::isfinite(v) ? QString::number(v, 'f', decimals) : QString("—"); }

QTableWidget* newTable(QWidget* parent, const QStringList& headers) {
    auto* t = new QTableWidget(parent);
    t->setColumnCount(headers.size());
    t->setHorizontalHeaderLabels(headers);
    t->verticalHeader()->setDefaultSectionSize(21);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionBehavior(QAbstractItemView::SelectRows);
    t->setAlternatingRowColors(true);
    t->horizontalHeader()->setStretchLastSection(true);
    return t;
}

QTableWidgetItem* cell(const QString& text, Qt::Alignment align = Qt::AlignRight | Qt::AlignVCenter) {
    auto* it = new QTableWidgetItem(text);
    it->setTextAlignment(align);
    return it;
}

// The detectors on a regular grid (the usual layout): origin, spacing and size; else not ok.
struct Grid {
    bool ok = false;
    double e0 = 0, n0 = 0, de = 1, dn = 1;
    int nx = 0, ny = 0;
};

Grid gridOf(const DetectorArray& a) {
    Grid g;
    if (a.detectors.size() < 2) return g;
    std::vector<double> es, ns;
    for (const auto& d : a.detectors) {
        if (!std::isfinite(d.e) || !std::isfinite(d.n)) return g;
        es.push_back(d.e);
        ns.push_back(d.n);
    }
    auto spacing = [](std::vector<double> v, double* lo) {
        std::sort(v.begin(), v.end());
        *lo = v.front();
        const double span = v.back() - v.front();
        double s = 0;
        for (size_t i = 1; i < v.size(); ++i) {
            const double d = v[i] - v[i - 1];
            if (d > 1e-6 * std::max(1.0, span) && (s == 0 || d < s)) s = d;
        }
        return s;
    };
    g.de = spacing(es, &g.e0);
    g.dn = spacing(ns, &g.n0);
    if (g.de == 0) g.de = g.dn;
    if (g.dn == 0) g.dn = g.de;
    if (!(g.de > 0)) return g;
    double emax = g.e0, nmax = g.n0;
    for (const auto& d : a.detectors) {
        const double i = (d.e - g.e0) / g.de, j = (d.n - g.n0) / g.dn;
        if (std::fabs(i - std::round(i)) > 0.05 || std::fabs(j - std::round(j)) > 0.05) return g;
        emax = std::max(emax, d.e);
        nmax = std::max(nmax, d.n);
    }
    g.nx = int(std::lround((emax - g.e0) / g.de)) + 1;
    g.ny = int(std::lround((nmax - g.n0) / g.dn)) + 1;
    g.ok = g.nx <= 4000 && g.ny <= 4000 && double(g.nx) * g.ny <= 4e6;
    return g;
}

}  // namespace

CalibWorkspace::CalibWorkspace(QWidget* parent) : Workspace(parent) {
    m_controller = new CalibController(this);
    QHBoxLayout* top = buildInputRow();
    m_inputs = new QLabel(this);
    m_inputs->setWordWrap(true);
    m_inputs->setTextFormat(Qt::RichText);
    m_inputs->setForegroundRole(QPalette::PlaceholderText);

    m_tabs = new QTabWidget(this);
    m_tabs->addTab(buildArrayTab(), tr("Detector array, pointing and validation"));
    m_tabs->addTab(buildWaveformTab(), tr("Waveform match"));

    // Right: parameters.
    auto* panel = new QWidget(this);
    buildPanel(panel);
    layoutWorkspace(this, QStringLiteral("calibration"), top, m_inputs, m_tabs, panel, 350, 1100);

    // Wiring.
    connect(m_controller, &CalibController::runReady, this, &CalibWorkspace::showRun);
    connect(m_controller, &CalibController::status, this, &CalibWorkspace::status);
    // New inputs: the undo history refers to the inputs it was made on (the other workspaces' stay).
    connect(m_controller, &CalibController::inputsChanged, this, [this] { undoStackOf(this).clear(); });
    // An undo or redo changes the work a session saves.
    connect(&undoStackOf(this), &QUndoStack::indexChanged, this, [this] {
        if (undoStackOf(this).count() > 0) emit modified();
    });
    connect(m_controller, &CalibController::inputsChanged, this, [this] {
        m_fresh = true;
        showInputs();
    });
    widgetsFromParams();
    showInputs();
}

// Top: the inputs (demo, detectors, control and check points, differences, waveform,
// candidates) and the exports.
QHBoxLayout* CalibWorkspace::buildInputRow() {
    auto* top = new QHBoxLayout;
    auto* demo = new QPushButton(tr("Demo"), this);
    demo->setToolTip(tr("Simulated inputs with known truth: detector array, calibration passes, check passes, waveform"));
    auto* openDet = new QPushButton(tr("Detectors…"), this);
    openDet->setToolTip(tr("Detector CSV: id, e, n (m) or lat, lon (deg), energy [, h, triggered, saturated]"));
    auto* openCp = new QPushButton(tr("Control points…"), this);
    openCp->setToolTip(tr("Control-point CSV of calib pointing; beams.json beside it gives the beam designs"));
    auto* openCheck = new QPushButton(tr("Check points…"), this);
    openCheck->setToolTip(tr("Independent check points (control-point CSV): validation of the calibration"));
    auto* openDiff = new QPushButton(tr("Differences…"), this);
    openDiff->setToolTip(tr("Elevation differences CSV: d (or diff, dh), or laser and control; optional group column"));
    auto* openWave = new QPushButton(tr("Waveform…"), this);
    openWave->setToolTip(tr("Waveform CSV: amplitude [, time_ns | sample]"));
    auto* openFeat = new QPushButton(tr("Candidates…"), this);
    openFeat->setToolTip(tr("Candidate features CSV: id, h [, e, n | lat, lon]"));
    auto* exportBtn = new QToolButton(this);
    exportBtn->setText(tr("Export"));
    exportBtn->setPopupMode(QToolButton::InstantPopup);
    exportBtn->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto* exportMenu = new QMenu(exportBtn);
    exportBtn->setMenu(exportMenu);
    for (QWidget* w : std::initializer_list<QWidget*>{demo, openDet, openCp, openCheck, openDiff, openWave, openFeat})
        top->addWidget(w);
    top->addStretch(1);
    top->addWidget(exportBtn);
    connect(demo, &QPushButton::clicked, this, [this] {
        openDemo();
        emit modified();
    });
    auto opener = [this](QPushButton* b, const QString& title, const QString& filter, auto fn) {
        connect(b, &QPushButton::clicked, this, [this, title, filter, fn] {
            const QString path = openFile(title, filter);
            if (path.isEmpty()) return;
            QString err;
            if (fn(path, &err)) emit modified();
            else if (!err.isEmpty()) showError(tr("Cannot open %1").arg(QFileInfo(path).fileName()), err);
        });
    };
    const QString csv = tr("CSV (*.csv *.txt);;All files (*)");
    opener(openDet, tr("Detector array"), csv, [this](const QString& p, QString* e) { return m_controller->openDetectors(p, e); });
    opener(openCp, tr("Control points"), csv, [this](const QString& p, QString* e) {
        QString beams;
        if (!QFileInfo::exists(QFileInfo(p).absolutePath() + "/beams.json")) {
            beams = openFile(tr("Beam designs (JSON) for %1").arg(QFileInfo(p).fileName()), tr("JSON (*.json);;All files (*)"));
            if (beams.isEmpty()) return false;  // cancelled: nothing to report
        }
        return m_controller->openControlPoints(p, beams, e);
    });
    opener(openCheck, tr("Check points"), csv, [this](const QString& p, QString* e) { return m_controller->openCheckPoints(p, e); });
    opener(openDiff, tr("Elevation differences"), csv, [this](const QString& p, QString* e) {
        bool ok = true;
        QString group;
        if (qApp->platformName() != "offscreen")
            group = QInputDialog::getText(this, tr("Group column"),
                                          tr("Column that splits the differences (e.g. beam); empty for one group:"),
                                          QLineEdit::Normal, m_controller->inputs().groupColumn, &ok);
        if (!ok) return false;  // cancelled: nothing to report
        return m_controller->openDifferences(p, group.trimmed(), e);
    });
    opener(openWave, tr("Waveform"), csv, [this](const QString& p, QString* e) { return m_controller->openWaveform(p, e); });
    opener(openFeat, tr("Candidate features"), csv, [this](const QString& p, QString* e) { return m_controller->openFeatures(p, e); });
    const QString csvOut = tr("CSV (*.csv)");
    exportMenu->addAction(tr("Detector report (per detector)…"), this,
                          [=] { exportWith(tr("Export detector report"), csvOut, &CalibController::exportDetectorReport); });
    exportMenu->addAction(tr("Footprint centre and surface…"), this,
                          [=] { exportWith(tr("Export footprint centre"), csvOut, &CalibController::exportCentre); });
    exportMenu->addAction(tr("Calibrated parameters…"), this,
                          [=] { exportWith(tr("Export calibrated parameters"), csvOut, &CalibController::exportPointing); });
    exportMenu->addAction(tr("Calibration iterations…"), this,
                          [=] { exportWith(tr("Export iterations"), csvOut, &CalibController::exportIterations); });
    exportMenu->addAction(tr("Validation statistics…"), this,
                          [=] { exportWith(tr("Export statistics"), csvOut, &CalibController::exportStats); });
    exportMenu->addAction(tr("Candidate ranking…"), this,
                          [=] { exportWith(tr("Export candidate ranking"), csvOut, &CalibController::exportRanking); });
    return top;
}

// Tab 1: detector array, pointing, statistics.
QWidget* CalibWorkspace::buildArrayTab() {
    auto* page = new QWidget(m_tabs);
    auto* pageLay = new QVBoxLayout(page);
    pageLay->setContentsMargins(2, 2, 2, 2);

    m_energyPlot = newPlot(page, tr("Detector energies and the fitted footprint"), tr("East (m)"), tr("North (m)"));
    const ImageMap energy = addImageMap(m_energyPlot, tr("Energy (file unit)"), false);
    m_energyMap = energy.map;
    m_energyScale = energy.scale;
    m_energyMap->setName(tr("energy"));
    new EqualAspect(m_energyPlot);

    m_centrePlot = newPlot(page, tr("Footprint centre: uncertainty"), tr("ΔEast from the fitted centre (cm)"),
                           tr("ΔNorth (cm)"));
    new EqualAspect(m_centrePlot);
    legendBelow(m_centrePlot, 2);
    m_detSummary = new QLabel(page);
    m_detSummary->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_detSummary->setWordWrap(true);
    m_detSummary->setTextFormat(Qt::RichText);
    m_detSummary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_detSummary->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    // The plot keeps room for its axes and legend; the summary (8 lines and more) scrolls
    // below it (issue 30: it covered the legend at 1024 × 700).
    m_centrePlot->setMinimumHeight(175);
    auto* centreCol = new QWidget(page);
    auto* centreLay = new QVBoxLayout(centreCol);
    centreLay->setContentsMargins(0, 0, 0, 0);
    centreLay->addWidget(m_centrePlot, 1);
    centreLay->addWidget(boundedText(m_detSummary, 5));

    auto* topRow = new QSplitter(Qt::Horizontal, page);
    topRow->addWidget(m_energyPlot);
    topRow->addWidget(centreCol);
    topRow->setStretchFactor(0, 3);
    topRow->setStretchFactor(1, 2);
    topRow->setSizes({640, 460});

    // (Titles and labels short enough for half of the area left of the panel in a 1024 px
    // window; the tooltips say the rest.)
    m_convPlot = newPlot(page, tr("Pointing & range fit: convergence"), tr("Iteration (0 = design)"), tr("χ²"));
    m_convPlot->setToolTip(tr("Pointing & range calibration (eq. 2–5): χ² of the whitened residuals (left) and the RMS "
                              "residuals in metres (right) per iteration; iteration 0 is the design values"));
    m_convPlot->yAxis->setScaleType(QCPAxis::stLogarithmic);
    m_convPlot->yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    m_convPlot->yAxis->setNumberFormat("eb");
    m_convPlot->yAxis->setNumberPrecision(0);
    m_convPlot->yAxis2->setVisible(true);
    m_convPlot->yAxis2->setLabel(tr("RMS (m)"));
    m_convPlot->yAxis2->setScaleType(QCPAxis::stLogarithmic);
    m_convPlot->yAxis2->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    m_convPlot->yAxis2->setNumberFormat("gb");
    auto intTicker = QSharedPointer<QCPAxisTickerFixed>(new QCPAxisTickerFixed);
    intTicker->setTickStep(1);
    intTicker->setScaleStrategy(QCPAxisTickerFixed::ssMultiples);
    m_convPlot->xAxis->setTicker(intTicker);
    legendBelow(m_convPlot, 2);

    m_detConvPlot = newPlot(page, tr("Detector fit: convergence"), tr("Accepted LM step"), tr("χ²"));
    m_detConvPlot->setToolTip(tr("Detector surface fit (paper 002 §3.2.3): χ² of the weighted energies after each "
                                 "accepted Levenberg–Marquardt step"));
    m_detConvPlot->yAxis->setScaleType(QCPAxis::stLogarithmic);
    m_detConvPlot->yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    m_detConvPlot->yAxis->setNumberFormat("eb");
    m_detConvPlot->yAxis->setNumberPrecision(0);
    m_detConvPlot->xAxis->setTicker(intTicker);
    legendBelow(m_detConvPlot, 1);

    // Statistics and parameters.
    auto* tables = new QTabWidget(page);
    auto* statsPage = new QWidget(tables);
    auto* statsLay = new QVBoxLayout(statsPage);
    statsLay->setContentsMargins(4, 4, 4, 4);
    m_statsSource = new QLabel(statsPage);
    m_statsSource->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_statsSource->setWordWrap(true);
    m_statsTable = newTable(statsPage, {});
    m_statsTable->setAlternatingRowColors(true);
    m_statsTable->horizontalHeader()->setStretchLastSection(false);
    m_statsTable->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_statsTable->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    statsLay->addWidget(m_statsSource);
    statsLay->addWidget(m_statsTable, 1);
    tables->addTab(statsPage, tr("Validation statistics"));
    auto* paramPage = new QWidget(tables);
    auto* paramLay = new QVBoxLayout(paramPage);
    paramLay->setContentsMargins(4, 4, 4, 4);
    m_pointingSummary = new QLabel(paramPage);
    m_pointingSummary->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_pointingSummary->setWordWrap(true);
    m_pointingSummary->setTextFormat(Qt::RichText);
    m_paramTable = newTable(paramPage, {tr("Parameter"), tr("Estimate"), tr("1σ"), tr("Simulated"), tr("Error / σ")});
    m_paramTable->verticalHeader()->hide();
    m_paramTable->horizontalHeaderItem(0)->setToolTip(tr("Corrections Δα, Δβ, Δρ (eq. 2) and the calibrated three-axis "
                                                         "pointing angles of the body frame (eq. 5)"));
    m_paramTable->horizontalHeaderItem(4)->setToolTip(tr("(estimate − simulated) / 1σ: within ±3 in 99.7 % of honest fits"));
    m_paramTable->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    for (int c = 1; c < 5; ++c) m_paramTable->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    m_paramTable->horizontalHeader()->setStretchLastSection(false);
    paramLay->addWidget(m_pointingSummary);
    paramLay->addWidget(m_paramTable, 1);
    tables->addTab(paramPage, tr("Calibrated parameters"));

    // The convergence plots in a third tab, side by side: three across left each a third of
    // 650 px at 1024 × 700, titles cut and legends squeezed (issue 30).
    auto* convergence = new QSplitter(Qt::Horizontal, tables);
    convergence->addWidget(m_convPlot);
    convergence->addWidget(m_detConvPlot);
    convergence->setChildrenCollapsible(false);
    tables->addTab(convergence, tr("Convergence"));
    m_bottomTabs = tables;
    auto* vsplit = new QSplitter(Qt::Vertical, page);
    vsplit->addWidget(topRow);
    vsplit->addWidget(tables);
    vsplit->setStretchFactor(0, 3);
    vsplit->setStretchFactor(1, 2);
    vsplit->setSizes({480, 320});
    pageLay->addWidget(vsplit);

    return page;
}

// Tab 2: the waveform match.
QWidget* CalibWorkspace::buildWaveformTab() {
    auto* wpage = new QWidget(m_tabs);
    auto* wLay = new QVBoxLayout(wpage);
    wLay->setContentsMargins(2, 2, 2, 2);
    m_wavePlot = newPlot(wpage, tr("Echo waveform: two Gaussian returns + baseline"), tr("Time (ns, two-way)"),
                         tr("Amplitude (DN)"));
    legendBelow(m_wavePlot, 5);
    m_waveSummary = new QLabel(wpage);
    m_waveSummary->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_waveSummary->setWordWrap(true);
    m_waveSummary->setTextFormat(Qt::RichText);
    m_waveSummary->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_waveSummary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_rankTable = newTable(wpage, {tr("Rank"), tr("Candidate"), tr("h (m)"), tr("Δh (m)"), tr("Δh ≤ thred_h"), tr("Footprint")});
    m_rankTable->horizontalHeaderItem(2)->setToolTip(tr("Surveyed height of the feature above the ground around it"));
    m_rankTable->horizontalHeaderItem(3)->setToolTip(tr("|h − h_waveform| (paper 002 eq. 1)"));
    m_rankTable->verticalHeader()->hide();
    for (int c = 0; c < 6; ++c) m_rankTable->horizontalHeader()->setSectionResizeMode(c, QHeaderView::Stretch);
    auto* wBottom = new QSplitter(Qt::Horizontal, wpage);
    wBottom->addWidget(m_rankTable);
    wBottom->addWidget(m_waveSummary);
    wBottom->setSizes({650, 450});
    auto* wsplit = new QSplitter(Qt::Vertical, wpage);
    wsplit->addWidget(m_wavePlot);
    wsplit->addWidget(wBottom);
    wsplit->setSizes({580, 220});
    wLay->addWidget(wsplit);

    return wpage;
}

void CalibWorkspace::buildPanel(QWidget* panel) {
    auto* pl = new QVBoxLayout(panel);
    pl->setContentsMargins(4, 4, 4, 4);

    m_params = new CalibParamsPanel(panel);
    pl->addWidget(m_params);
    bindParamsPanel(m_params, m_controller, this, tr("calibration parameters"));

    auto* vg = new QGroupBox(tr("View"), panel);
    auto* vf = new QFormLayout(vg);
    m_colorMap = new QComboBox(vg);
    m_colorMap->addItems(colorMapNames());
    m_colorMap->setCurrentIndex(int(ColorMap::Inferno));
    m_showTruth = new QCheckBox(tr("Show the simulated truth (demo)"), vg);
    m_showTruth->setChecked(true);
    vf->addRow(tr("Energy colours"), m_colorMap);
    vf->addRow(m_showTruth);
    pl->addWidget(vg);
    pl->addStretch(1);

    connect(m_colorMap, &QComboBox::currentIndexChanged, this, [this] {
        if (m_controller->hasRun()) showDetector(m_controller->run());
        emit modified();
    });
    connect(m_showTruth, &QCheckBox::toggled, this, [this] {
        if (m_controller->hasRun()) showRun(m_controller->run());
        emit modified();
    });
}

void CalibWorkspace::showError(const QString& title, const QString& message) {
    emit status(title + ": " + message);
    if (qApp->platformName() == "offscreen") {
        qWarning("%s: %s", qPrintable(title), qPrintable(message));
        return;
    }
    QMessageBox::warning(this, title, message);
}

QString CalibWorkspace::openFile(const QString& title, const QString& filter) {
    QSettings st;
    const QString path = QFileDialog::getOpenFileName(this, title, st.value("paths/calib").toString(), filter);
    if (!path.isEmpty()) st.setValue("paths/calib", QFileInfo(path).absolutePath());
    return path;
}

void CalibWorkspace::exportWith(const QString& title, const QString& filter,
                                bool (CalibController::*fn)(const QString&, QString*) const) {
    const QString path = askSavePath(this, title, "paths/calibExport", QString(), filter);
    if (path.isEmpty()) return;
    QString err;
    if (!(m_controller->*fn)(path, &err)) showError(title, err);
    else emit status(tr("Wrote %1").arg(path));
}

void CalibWorkspace::openDemo() {
    // The detector fit's noise model is set to the simulator's (5 % of the energy, floor 2), as
    // the simulated control points come with their own noise model (the pointing defaults).
    CalibParams p = m_controller->params();
    p.detector.noise = NoiseSource::Given;
    p.detector.relativeNoise = 0.05;
    p.detector.noiseFloor = 2;
    m_controller->setParams(p);
    widgetsFromParams();
    m_controller->openDemo();
    emit status(tr("Calibration demo: simulated detector array (energy noise 5 % + 2, set in the fit), 4 calibration passes "
                   "and 22 check passes of both beams, a double-peak waveform"));
}

void CalibWorkspace::showTab(const QString& name) { m_tabs->setCurrentIndex(name == "waveform" ? 1 : 0); }

void CalibWorkspace::showInputs() {
    const CalibInputs& in = m_controller->inputs();
    auto src = [](const QString& s) {
        if (s.isEmpty()) return QObject::tr("<i>none</i>");
        if (s == "demo") return QObject::tr("simulated");
        return QString("<span title='%1'>%2</span>").arg(s.toHtmlEscaped(), QFileInfo(s).fileName().toHtmlEscaped());
    };
    QString stats = !in.differences.isEmpty() ? src(in.differences)
                    : !in.checkPoints.isEmpty() ? tr("check points %1").arg(src(in.checkPoints))
                                                : tr("control-point residuals");
    m_inputs->setText(tr("<b>Detectors</b> %1 · <b>control points</b> %2 (beams %3) · <b>statistics</b> %4 · "
                         "<b>waveform</b> %5 · <b>candidates</b> %6")
                          .arg(src(in.detectors), src(in.controlPoints), src(in.beams), stats, src(in.waveform),
                               src(in.features)));
}

void CalibWorkspace::widgetsFromParams() { m_params->setParams(m_controller->params()); }

QDoubleSpinBox* CalibWorkspace::triggerField() const { return m_params->field("detector.trigger"); }
QDoubleSpinBox* CalibWorkspace::thresholdField() const { return m_params->field("waveform.thred_h"); }
QComboBox* CalibWorkspace::pointingModelBox() const { return m_params->combo("pointing.model"); }

// ---------------------------------------------------------------------------------------------

void CalibWorkspace::showRun(const CalibRun& run) {
    showDetector(run);
    showPointing(run);
    showStats(run);
    showWaveform(run);
    m_fresh = false;
}

void CalibWorkspace::showDetector(const CalibRun& run) {
    QCustomPlot* p = m_energyPlot;
    // Everything but the colour map is rebuilt.
    p->clearGraphs();
    for (int i = p->plottableCount() - 1; i >= 0; --i)
        if (p->plottable(i) != m_energyMap) p->removePlottable(i);
    m_centrePlot->clearPlottables();
    m_centrePlot->clearItems();
    m_detConvPlot->clearPlottables();
    const DetectorArray& a = run.data->array;
    const DetectorFitResult& r = run.detector;
    const bool truth = run.data->hasDetectorTruth && m_showTruth->isChecked();
    QCPColorGradient grad = gradientFor(colorMapFromIndex(m_colorMap->currentIndex()));
    m_energyMap->setGradient(grad);
    m_energyMap->data()->clear();
    if (a.detectors.empty()) {
        m_detSummary->setText(tr("No detector array: open a detector CSV or the demo."));
        for (QCustomPlot* q : {m_energyPlot, m_centrePlot, m_detConvPlot}) q->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    drawEnergyMap(run, truth, grad);
    // The centre's uncertainty, in cm about the fitted centre.
    if (r.ok) {
        drawCentrePlot(run, truth);
        drawDetectorConvergence(run);
        m_detSummary->setText(detectorSummary(run, truth));
    } else {
        m_detSummary->setText(tr("<span style='color:#c0392b'><b>Detector fit failed:</b> %1</span>")
                                  .arg(QString::fromStdString(r.error).toHtmlEscaped()));
    }
    m_centrePlot->legend->setFillOrder(QCPLegend::foColumnsFirst, true);
    m_detConvPlot->legend->setFillOrder(QCPLegend::foColumnsFirst, true);
    m_centrePlot->replot(QCustomPlot::rpQueuedReplot);
    m_detConvPlot->replot(QCustomPlot::rpQueuedReplot);
}

// The detectors' energies (cells of the grid, or coloured markers for an irregular layout), the
// untriggered, set-aside and bound detectors, the fitted footprint and centre (and the truth).
void CalibWorkspace::drawEnergyMap(const CalibRun& run, bool truth, QCPColorGradient grad) {
    QCustomPlot* p = m_energyPlot;
    const DetectorArray& a = run.data->array;
    const DetectorFitResult& r = run.detector;
    // Energies: cells of the detector grid, or coloured markers for an irregular layout.
    double emax = 0;
    for (const auto& d : a.detectors)
        if (std::isfinite(d.energy)) emax = std::max(emax, d.energy);
    if (!(emax > 0)) emax = 1;
    const Grid g = gridOf(a);
    QVector<double> ux, uy, sx, sy, bx, by;
    std::vector<DetectorStatus> status(a.detectors.size(), DetectorStatus::Used);
    if (r.ok || r.detectors.size() == a.detectors.size())
        for (size_t i = 0; i < r.detectors.size(); ++i) status[i] = r.detectors[i].status;
    if (g.ok) {
        m_energyMap->setVisible(true);
        m_energyMap->data()->setSize(g.nx, g.ny);
        m_energyMap->data()->setRange(QCPRange(g.e0, g.e0 + (g.nx - 1) * g.de), QCPRange(g.n0, g.n0 + (g.ny - 1) * g.dn));
        m_energyMap->data()->fill(qQNaN());
    } else {
        m_energyMap->setVisible(false);
    }
    constexpr int kLevels = 24;
    QVector<double> lx[kLevels], ly[kLevels];
    for (size_t i = 0; i < a.detectors.size(); ++i) {
        const Detector& d = a.detectors[i];
        if (!std::isfinite(d.energy) || d.triggered == 0) {
            ux << d.e;
            uy << d.n;
            continue;
        }
        if (status[i] == DetectorStatus::AtLeast || status[i] == DetectorStatus::AtMost) {
            bx << d.e;
            by << d.n;
        } else if (status[i] != DetectorStatus::Used) {
            sx << d.e;
            sy << d.n;
        }
        if (g.ok) {
            m_energyMap->data()->setCell(int(std::lround((d.e - g.e0) / g.de)), int(std::lround((d.n - g.n0) / g.dn)), d.energy);
        } else {
            const int k = std::clamp(int(d.energy / emax * kLevels), 0, kLevels - 1);
            lx[k] << d.e;
            ly[k] << d.n;
        }
    }
    m_energyMap->setDataRange(QCPRange(0, emax));
    m_energyScale->setDataRange(QCPRange(0, emax));
    m_energyScale->setGradient(grad);
    if (!g.ok)
        for (int k = 0; k < kLevels; ++k) {
            if (lx[k].isEmpty()) continue;
            const QColor c = grad.color((k + 0.5) / kLevels * emax, QCPRange(0, emax));
            QCPGraph* lg = scatter(p, QString(), QCPScatterStyle(QCPScatterStyle::ssSquare, c, c, 8));
            lg->setData(lx[k], ly[k]);
            lg->removeFromLegend();
        }
    scatter(p, tr("untriggered (no energy)"), QCPScatterStyle(QCPScatterStyle::ssDisc, kGrey, kGrey, 2.5))->setData(ux, uy);
    if (!sx.isEmpty())
        scatter(p, tr("set aside (outlier, or censoring off)"), QCPScatterStyle(QCPScatterStyle::ssCross, QPen(kRed, 1.6), Qt::NoBrush, 8))
            ->setData(sx, sy);
    if (!bx.isEmpty())
        scatter(p, tr("in the fit as a bound (threshold / saturation)"),
                QCPScatterStyle(QCPScatterStyle::ssPlus, QPen(QColor(230, 140, 0), 1.6), Qt::NoBrush, 8))
            ->setData(bx, by);
    if (r.ok) {
        const GaussSurface& s = r.surface;
        setEllipse(ellipseCurve(p, tr("fitted footprint 1σ"), QPen(QColor(0, 200, 255), 1.6)), s.e0, s.n0, s.sigmaMajor,
                   s.sigmaMinor, s.orientationRad);
        setEllipse(ellipseCurve(p, tr("1/e² (2σ)"), QPen(QColor(0, 200, 255), 1.3, Qt::DashLine)), s.e0, s.n0,
                   2 * s.sigmaMajor, 2 * s.sigmaMinor, s.orientationRad);
        scatter(p, tr("fitted centre"), QCPScatterStyle(QCPScatterStyle::ssCrossCircle, QPen(QColor(0, 200, 255), 1.8), Qt::NoBrush, 11))
            ->setData({r.centreE}, {r.centreN});
    }
    if (truth)
        scatter(p, tr("simulated centre"), QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(kGreen, 1.8), Qt::NoBrush, 9))
            ->setData({run.data->detectorTruth.e0}, {run.data->detectorTruth.n0});
    if (!p->legend->visible()) legendBelow(p, 3);
    p->legend->setFillOrder(QCPLegend::foColumnsFirst, true);
    if (m_fresh) {
        // Around the triggered detectors (the footprint), not the whole array.
        double e0 = INFINITY, e1 = -INFINITY, n0 = INFINITY, n1 = -INFINITY;
        for (const auto& d : a.detectors)
            if (std::isfinite(d.energy) && d.triggered != 0) {
                e0 = std::min(e0, d.e);
                e1 = std::max(e1, d.e);
                n0 = std::min(n0, d.n);
                n1 = std::max(n1, d.n);
            }
        if (!std::isfinite(e0))
            for (const auto& d : a.detectors) {
                e0 = std::min(e0, d.e);
                e1 = std::max(e1, d.e);
                n0 = std::min(n0, d.n);
                n1 = std::max(n1, d.n);
            }
        const double pad = 2 * std::max(g.ok ? std::max(g.de, g.dn) : 1.0, 0.05 * std::max(e1 - e0, n1 - n0));
        p->replot();  // lays out the legend and colour scale: the axis rect has its final size
        fitEqual(p, e0 - pad, e1 + pad, n0 - pad, n1 + pad);
    }
    p->replot(QCustomPlot::rpQueuedReplot);
}

// The centre's 1σ and 95 % ellipses in cm about the fitted centre (and the truth).
void CalibWorkspace::drawCentrePlot(const CalibRun& run, bool truth) {
    const DetectorFitResult& r = run.detector;
    const UncertaintyEllipse& e = r.centreEllipse;
    setEllipse(ellipseCurve(m_centrePlot, tr("1σ ellipse"), QPen(kBlue, 1.8)), 0, 0, 100 * e.semiMajor, 100 * e.semiMinor,
               e.orientationRad);
    const double k95 = std::isfinite(r.centreEllipse95Scale) ? r.centreEllipse95Scale : 2.4477;
    setEllipse(ellipseCurve(m_centrePlot, tr("95 % ellipse (×%1)").arg(num(k95, 3)), QPen(kBlue, 1.3, Qt::DashLine)), 0, 0,
               100 * k95 * e.semiMajor, 100 * k95 * e.semiMinor, e.orientationRad);
    scatter(m_centrePlot, tr("fitted centre"), QCPScatterStyle(QCPScatterStyle::ssCrossCircle, QPen(kBlue, 1.8), Qt::NoBrush, 11))
        ->setData({0.0}, {0.0});
    double lim = k95 * 100 * e.semiMajor * 1.5;
    if (truth) {
        const double dx = 100 * (run.data->detectorTruth.e0 - r.centreE), dy = 100 * (run.data->detectorTruth.n0 - r.centreN);
        scatter(m_centrePlot, tr("simulated centre"), QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(kGreen, 1.8), Qt::NoBrush, 10))
            ->setData({dx}, {dy});
        lim = std::max(lim, 1.3 * std::max(std::fabs(dx), std::fabs(dy)));
    }
    m_centrePlot->replot();
    fitEqual(m_centrePlot, -lim, lim, -lim, lim);
}

// The detector fit's χ² per accepted step, against its degrees of freedom.
void CalibWorkspace::drawDetectorConvergence(const CalibRun& run) {
    const DetectorFitResult& r = run.detector;
    // Convergence of the detector fit.
    QVector<double> x, y;
    for (size_t i = 0; i < r.costPerIteration.size(); ++i) {
        x << double(i);
        y << std::max(r.costPerIteration[i], 1e-12);
    }
    QCPGraph* cg = m_detConvPlot->addGraph();
    cg->setName(tr("χ² (best of 3 starts; 2 re-weightings)"));
    cg->setPen(QPen(kPurple, 1.8));
    cg->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, kPurple, Qt::white, 6));
    cg->setData(x, y);
    if (r.dof > 0) {
        QCPGraph* dg = m_detConvPlot->addGraph();
        dg->setName(tr("dof = %1 (expected χ²)").arg(r.dof));
        dg->setPen(QPen(kGrey, 1.2, Qt::DashLine));
        dg->setData({0.0, std::max(1.0, double(x.size() - 1))}, {double(r.dof), double(r.dof)});
    }
    m_detConvPlot->rescaleAxes();
    m_detConvPlot->xAxis->setRange(-0.3, std::max(1.0, double(x.size() - 1)) + 0.3);
    m_detConvPlot->yAxis->scaleRange(1.6, std::sqrt(m_detConvPlot->yAxis->range().lower * m_detConvPlot->yAxis->range().upper));
}

// The fit's figures: centre, σ, ellipse, geographic position, truth, footprint, χ², noise,
// doubts and warnings.
QString CalibWorkspace::detectorSummary(const CalibRun& run, bool truth) const {
    const DetectorArray& a = run.data->array;
    const DetectorFitResult& r = run.detector;
    const UncertaintyEllipse& e = r.centreEllipse;
    QString html;
    html = tr("<b>Centre</b> E %1 m, N %2 m · σ<sub>E</sub> %3 m, σ<sub>N</sub> %4 m · 1σ ellipse %5 × %6 m at %7°")
               .arg(num(r.centreE, 3), num(r.centreN, 3), num(e.sigmaE, 3), num(e.sigmaN, 3), num(e.semiMajor, 3),
                    num(e.semiMinor, 3), num(e.orientationRad * 180 / M_PI, 0));
    if (std::isfinite(r.centreLatDeg))
        html += tr("<br>lat %1°, lon %2°%3")
                    .arg(num(r.centreLatDeg, 8), num(r.centreLonDeg, 8),
                         std::isfinite(r.centreH) ? tr(", h %1 m").arg(num(r.centreH, 2)) : QString());
    if (truth) {
        const GaussSurface& t = run.data->detectorTruth;
        const double de = r.centreE - t.e0, dn = r.centreN - t.n0;
        // Mahalanobis distance of the truth from the fit under the centre covariance.
        const double vE = e.sigmaE * e.sigmaE, vN = e.sigmaN * e.sigmaN, c = e.covEN, det = vE * vN - c * c;
        const double m = det > 0 ? std::sqrt((vN * de * de - 2 * c * de * dn + vE * dn * dn) / det) : NAN;
        html += tr("<br><span style='color:#2c8c2c'>Simulated centre E %1, N %2 m: fit − truth %3, %4 m = %5σ "
                   "(Mahalanobis)</span>")
                    .arg(num(t.e0, 3), num(t.n0, 3), num(de, 3), num(dn, 3), num(m, 2));
    }
    html += tr("<br><b>Footprint</b> σ %1 × %2 m at %3° · amplitude %4 ± %5 · background %6<br>"
               "<b>Fit</b> %7 of %8 detectors · %9 dof · χ² %10 · RMS residual %11 · %12 steps")
                .arg(num(r.surface.sigmaMajor, 2), num(r.surface.sigmaMinor, 2),
                     num(r.surface.orientationRad * 180 / M_PI, 0), QString::number(r.surface.amplitude, 'g', 5),
                     QString::number(r.amplitudeSd, 'g', 3), QString::number(r.surface.background, 'g', 3))
                .arg(r.used)
                .arg(a.detectors.size())
                .arg(r.dof)
                .arg(num(r.chi2, 1), QString::number(r.rmsResidual, 'g', 3))
                .arg(r.iterations);
    html += tr("<br><b>Noise</b> %1").arg(QString::fromStdString(r.noise.description).toHtmlEscaped());
    for (const auto& d : r.doubts)
        html += "<br><b style='color:#c03030'>" + tr("Doubtful: %1").arg(QString::fromStdString(d).toHtmlEscaped()) + "</b>";
    for (const auto& w : r.warnings) html += "<br><i>" + QString::fromStdString(w).toHtmlEscaped() + "</i>";
    return html;
}

void CalibWorkspace::showPointing(const CalibRun& run) {
    m_convPlot->clearPlottables();
    m_paramTable->setRowCount(0);
    const PointingCalibResult& r = run.pointing;
    if (!run.hasPointing) {
        m_pointingSummary->setText(tr("No control points: open a control-point CSV or the demo."));
        m_convPlot->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    if (!r.ok) {
        m_pointingSummary->setText(tr("<span style='color:#c0392b'><b>Calibration failed:</b> %1</span>")
                                       .arg(QString::fromStdString(r.error).toHtmlEscaped()));
        m_convPlot->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    QVector<double> it, chi, plan, height;
    for (const CalibIteration& c : r.iterations) {
        it << c.iteration;
        chi << std::max(c.chi2, 1e-9);
        plan << std::max(c.rmsPlanM, 1e-6);
        height << std::max(c.rmsHeightM, 1e-6);
    }
    QCPGraph* gc = m_convPlot->addGraph(m_convPlot->xAxis, m_convPlot->yAxis);
    gc->setName(tr("χ² (left)"));
    gc->setPen(QPen(Qt::black, 1.8));
    gc->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, Qt::black, Qt::white, 7));
    gc->setData(it, chi);
    QCPGraph* gp = m_convPlot->addGraph(m_convPlot->xAxis, m_convPlot->yAxis2);
    gp->setName(tr("RMS plan (right)"));
    gp->setPen(QPen(kBlue, 1.6, Qt::DashLine));
    gp->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, kBlue, kBlue, 6));
    gp->setData(it, plan);
    QCPGraph* gh = m_convPlot->addGraph(m_convPlot->xAxis, m_convPlot->yAxis2);
    gh->setName(tr("RMS height (right)"));
    gh->setPen(QPen(kOrange, 1.6, Qt::DashLine));
    gh->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssTriangle, kOrange, kOrange, 7));
    gh->setData(it, height);
    m_convPlot->rescaleAxes();
    m_convPlot->xAxis->setRange(-0.3, std::max(1.0, double(it.size() - 1)) + 0.3);
    for (QCPAxis* ax : {m_convPlot->yAxis, m_convPlot->yAxis2}) {
        const QCPRange rg = ax->range();
        ax->setRange(rg.lower / 2.5, rg.upper * 2.5);
    }
    m_convPlot->legend->setFillOrder(QCPLegend::foColumnsFirst, true);
    m_convPlot->replot(QCustomPlot::rpQueuedReplot);

    // Parameters with σ (and the truth of the simulation).
    const CalibData& d = *run.data;
    const bool truth = d.hasPointingTruth && m_showTruth->isChecked();
    auto addRow = [&](const QString& name, double v, double sd, double t, int decimals = -1) {
        const int row = m_paramTable->rowCount();
        m_paramTable->insertRow(row);
        m_paramTable->setItem(row, 0, cell(name, Qt::AlignLeft | Qt::AlignVCenter));
        const int dec = decimals >= 0 ? decimals : std::fabs(v) >= 100 ? 1 : 3;
        m_paramTable->setItem(row, 1, cell(num(v, dec)));
        m_paramTable->setItem(row, 2, cell(num(sd, decimals >= 0 ? decimals : 3)));
        m_paramTable->setItem(row, 3, cell(truth && std::isfinite(t) ? num(t, dec) : QString("—")));
        const double z = truth && std::isfinite(t) && sd > 0 ? (v - t) / sd : NAN;
        auto* zi = cell(num(z, 2));
        if (std::isfinite(z)) zi->setForeground(std::fabs(z) <= 3 ? QColor(30, 120, 50) : QColor(190, 40, 40));
        m_paramTable->setItem(row, 4, zi);
    };
    for (size_t k = 0; k < r.beams.size(); ++k) {
        const BeamCalibration& b = r.beams[k];
        if (!b.solved) continue;
        const bool t = k < 2;
        addRow(tr("beam %1 Δα (µrad)").arg(b.id), b.dAlphaRad * 1e6, b.dAlphaSdRad * 1e6, t ? d.trueDAlpha[k] * 1e6 : NAN);
        addRow(tr("beam %1 Δβ (µrad)").arg(b.id), b.dBetaRad * 1e6, b.dBetaSdRad * 1e6, t ? d.trueDBeta[k] * 1e6 : NAN);
        if (b.rangeSolved) addRow(tr("beam %1 Δρ (m)").arg(b.id), b.dRhoM, b.dRhoSdM, t ? d.trueDRho[k] : NAN);
    }
    for (size_t k = 0; k < r.beams.size(); ++k) {
        const BeamCalibration& b = r.beams[k];
        if (!b.solved) continue;
        const double deg = 180 / M_PI;
        addRow(tr("beam %1 Angle_X (°)").arg(b.id), b.calibratedAngles.x * deg, b.angleXSdRad * deg, NAN, 6);
        addRow(tr("beam %1 Angle_Y (°)").arg(b.id), b.calibratedAngles.y * deg, b.angleYSdRad * deg, NAN, 6);
        addRow(tr("beam %1 Angle_Z (°)").arg(b.id), b.calibratedAngles.z * deg, b.angleZSdRad * deg, NAN, 6);
    }
    for (size_t j = 0; j < r.paramNames.size(); ++j)
        if (r.paramNames[j] == "rel_r" || r.paramNames[j] == "rel_a")
            addRow(tr("relative rotation %1 (µrad)").arg(QString::fromStdString(r.paramNames[j]).mid(4)), r.params[j] * 1e6,
                   r.paramSd[j] * 1e6, NAN);
    QString html = tr("<b>%1-beam model</b>, %2 control points, %3 iterations%4 · RMS plan %5 → %6 m, height %7 → %8 m · "
                      "χ² %9 for %10 dof")
                       .arg(r.model == CalibModel::DualBeam ? tr("Dual") : tr("Single"))
                       .arg(d.points.size())
                       .arg(r.iterations.size() - 1)
                       .arg(r.converged ? QString() : tr(" (not converged)"))
                       .arg(num(r.iterations.front().rmsPlanM, 2), num(r.iterations.back().rmsPlanM, 2),
                            num(r.iterations.front().rmsHeightM, 3), num(r.iterations.back().rmsHeightM, 3), num(r.chi2, 2))
                       .arg(r.dof);
    for (const auto& w : r.warnings) html += "<br><i>" + QString::fromStdString(w).toHtmlEscaped() + "</i>";
    m_pointingSummary->setText(html);
}

void CalibWorkspace::showStats(const CalibRun& run) {
    m_statsTable->clear();
    m_statsTable->setRowCount(0);
    m_statsTable->setColumnCount(0);
    QString src = run.statsSource.toHtmlEscaped();
    if (!run.statsError.isEmpty())
        src += (src.isEmpty() ? QString() : "<br>") +
               tr("<span style='color:#c0392b'>%1</span>").arg(run.statsError.toHtmlEscaped());
    if (run.stats.empty() && src.isEmpty()) src = tr("No elevation differences: open check points or a differences CSV.");
    m_statsSource->setText(src + (run.stats.empty() ? QString()
                                                    : tr("<br><small>Paper 002's “RMSE” is the sample std for beam 1 "
                                                         "but the RMS about zero for beam 2: read the labels.</small>")));
    m_statsSource->setTextFormat(Qt::RichText);
    if (run.stats.empty()) return;
    std::vector<LabelledValue> labels;
    for (const StatsColumn& c : run.stats)
        if (c.stats.ok) {
            labels = labelledStats(c.stats.stats);
            break;
        }
    if (labels.empty()) return;
    m_statsTable->setColumnCount(int(run.stats.size()));
    m_statsTable->setRowCount(int(labels.size()));
    QStringList headers, rows;
    // (the core names a column "beam N": the interface's word for it)
    for (const StatsColumn& c : run.stats) headers << (c.name.startsWith("beam ") ? tr("beam %1").arg(c.name.mid(5)) : c.name);
    const std::map<std::string, QString> shortNames = {
        {"n", tr("n")},
        {"mean", tr("mean (m)")},
        {"rms_about_zero", tr("RMS about zero (m)")},
        {"std_sample", tr("sample std, n−1 (m)")},
        {"std_population", tr("population std, n (m)")},
        {"min", tr("min (m)")},
        {"max", tr("max (m)")},
        {"median", tr("median (m)")},
        {"mean_abs", tr("mean |d| (m)")},
    };
    for (const LabelledValue& lv : labels) {
        const auto it = shortNames.find(lv.key);
        rows << (it != shortNames.end() ? it->second : QString::fromStdString(lv.label));
    }
    m_statsTable->setHorizontalHeaderLabels(headers);
    m_statsTable->setVerticalHeaderLabels(rows);
    for (int r = 0; r < int(labels.size()); ++r)
        m_statsTable->verticalHeaderItem(r)->setToolTip(QString::fromStdString(labels[size_t(r)].label));
    for (int c = 0; c < int(run.stats.size()); ++c) {
        const StatsColumn& col = run.stats[size_t(c)];
        if (!col.stats.ok) {
            m_statsTable->setItem(0, c, cell(QString::fromStdString(col.stats.error)));
            continue;
        }
        const std::vector<LabelledValue> v = labelledStats(col.stats.stats);
        for (int r = 0; r < int(v.size()) && r < int(labels.size()); ++r)
            m_statsTable->setItem(r, c, cell(v[size_t(r)].key == "n" ? QString::number(col.stats.stats.n)
                                                                       : num(v[size_t(r)].value, 4)));
    }
}

void CalibWorkspace::showWaveform(const CalibRun& run) {
    QCustomPlot* p = m_wavePlot;
    p->clearPlottables();
    p->clearItems();
    m_rankTable->setRowCount(0);
    // (its times as the run used them: waveform.sample_interval_ns for a file without a time column)
    const Waveform w = withSampleInterval(run.data->waveform, m_controller->params().waveform.sampleIntervalNs);
    if (w.amplitude.empty()) {
        m_waveSummary->setText(tr("No waveform: open a waveform CSV or the demo."));
        p->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    QVector<double> t(w.timeNs.begin(), w.timeNs.end()), a(w.amplitude.begin(), w.amplitude.end());
    QCPGraph* gs = scatter(p, tr("samples"), QCPScatterStyle(QCPScatterStyle::ssDisc, kGrey, kGrey, 4));
    gs->setData(t, a);
    const WaveformResult& r = run.waveform;
    QString html;
    if (r.ok) {
        QVector<double> m(r.model.begin(), r.model.end()), c1, c2, base;
        for (double x : w.timeNs) {
            c1 << r.baseline + r.first.amplitude * std::exp(-0.5 * std::pow((x - r.first.centreNs) / r.first.sigmaNs, 2));
            c2 << r.baseline + r.second.amplitude * std::exp(-0.5 * std::pow((x - r.second.centreNs) / r.second.sigmaNs, 2));
            base << r.baseline;
        }
        QCPGraph* gb = p->addGraph();
        gb->setName(tr("baseline"));
        gb->setPen(QPen(kGrey, 1, Qt::DotLine));
        gb->setData(t, base);
        QCPGraph* g1 = p->addGraph();
        g1->setName(tr("top return (feature)"));
        g1->setPen(QPen(kGreen, 1.5, Qt::DashLine));
        g1->setData(t, c1);
        g1->setBrush(QColor(kGreen.red(), kGreen.green(), kGreen.blue(), 45));
        g1->setChannelFillGraph(gb);
        QCPGraph* g2 = p->addGraph();
        g2->setName(tr("ground return"));
        g2->setPen(QPen(kOrange, 1.5, Qt::DashLine));
        g2->setData(t, c2);
        g2->setBrush(QColor(kOrange.red(), kOrange.green(), kOrange.blue(), 45));
        g2->setChannelFillGraph(gb);
        QCPGraph* gm = p->addGraph();
        gm->setName(tr("fitted model"));
        gm->setPen(QPen(kBlue, 1.6));
        gm->setData(t, m);
        gs->setLayer("overlay");  // the samples over the curves
        // Δt between the peaks.
        const double ymax = *std::max_element(w.amplitude.begin(), w.amplitude.end());
        const double yArrow = ymax * 1.08;
        for (double x : {r.first.centreNs, r.second.centreNs}) {
            auto* l = new QCPItemLine(p);
            l->start->setCoords(x, r.baseline);
            l->end->setCoords(x, yArrow);
            l->setPen(QPen(QColor(90, 90, 90), 1, Qt::DashLine));
        }
        auto* arrow = new QCPItemLine(p);
        arrow->start->setCoords(r.first.centreNs, yArrow);
        arrow->end->setCoords(r.second.centreNs, yArrow);
        arrow->setHead(QCPLineEnding::esSpikeArrow);
        arrow->setTail(QCPLineEnding::esSpikeArrow);
        auto* label = new QCPItemText(p);
        label->position->setCoords(0.5 * (r.first.centreNs + r.second.centreNs), yArrow);
        label->setPositionAlignment(Qt::AlignHCenter | Qt::AlignBottom);
        label->setText(tr("Δt = %1 ns → h = %2 m").arg(num(r.deltaTNs, 2), num(r.heightM, 3)));
        label->setPadding(QMargins(2, 2, 2, 4));
        p->rescaleAxes();
        p->yAxis->setRange(std::min(0.0, p->yAxis->range().lower), yArrow * 1.12);
        const double span = t.last() - t.first();
        p->xAxis->setRange(t.first() - 0.02 * span, t.last() + 0.02 * span);
        html = tr("<b>Returns</b> at %1 ± %2 and %3 ± %4 ns (σ %5 and %6 ns)<br><b>Δt</b> %7 ± %8 ns two-way · "
                  "<b>h_waveform</b> = Δt·c/2/cos θ = <b>%9 ± %10 m</b> (θ = %11°)<br>RMS residual %12 · %13 iterations")
                   .arg(num(r.first.centreNs, 2), num(r.first.centreSdNs, 2), num(r.second.centreNs, 2),
                        num(r.second.centreSdNs, 2), num(r.first.sigmaNs, 2), num(r.second.sigmaNs, 2), num(r.deltaTNs, 3),
                        num(r.deltaTSdNs, 3), num(r.heightM, 3))
                   .arg(num(r.heightSdM, 3), num(run.params.waveform.incidenceDeg, 2), QString::number(r.rmsResidual, 'g', 3))
                   .arg(r.iterations);
        if (std::isfinite(run.data->trueHeightM) && m_showTruth->isChecked())
            html += tr("<br><span style='color:#2c8c2c'>Simulated feature height %1 m</span>").arg(num(run.data->trueHeightM, 3));
        for (const auto& wn : r.warnings) html += "<br><i>" + QString::fromStdString(wn).toHtmlEscaped() + "</i>";
    } else {
        p->rescaleAxes();
        html = tr("<span style='color:#c0392b'><b>Decomposition failed:</b> %1</span>")
                   .arg(QString::fromStdString(r.error).toHtmlEscaped());
    }
    if (run.hasMatch && run.match.ok) {
        const auto& cands = run.data->features;
        const FeatureMatchResult& mr = run.match;
        for (size_t k = 0; k < mr.ranking.size(); ++k) {
            const FeatureDelta& fd = mr.ranking[k];
            const bool chosen = mr.found && k == 0;
            m_rankTable->insertRow(int(k));
            m_rankTable->setItem(int(k), 0, cell(QString::number(k + 1)));
            m_rankTable->setItem(int(k), 1, cell(QString::fromStdString(cands[fd.index].id), Qt::AlignLeft | Qt::AlignVCenter));
            m_rankTable->setItem(int(k), 2, cell(num(cands[fd.index].heightM, 3)));
            m_rankTable->setItem(int(k), 3, cell(num(fd.deltaHM, 3)));
            m_rankTable->setItem(int(k), 4, cell(fd.belowThreshold ? tr("yes") : tr("no"), Qt::AlignCenter));
            m_rankTable->setItem(int(k), 5, cell(chosen ? tr("◀ here") : QString(), Qt::AlignCenter));
            if (chosen)
                for (int c = 0; c < 6; ++c) m_rankTable->item(int(k), c)->setBackground(QColor(210, 240, 210));
        }
        html += mr.found ? tr("<br><b>Footprint on %1</b> (Δh %2 m ≤ thred_h %3 m)")
                               .arg(QString::fromStdString(cands[mr.best].id).toHtmlEscaped(), num(mr.bestDeltaHM, 3),
                                    num(run.params.match.thresholdM, 3))
                         : tr("<br><b>No candidate within thred_h %1 m</b> (closest %2, Δh %3 m)")
                               .arg(num(run.params.match.thresholdM, 3),
                                    QString::fromStdString(cands[mr.best].id).toHtmlEscaped(), num(mr.bestDeltaHM, 3));
    } else if (run.hasMatch) {
        html += tr("<br><span style='color:#c0392b'>%1</span>").arg(QString::fromStdString(run.match.error).toHtmlEscaped());
    } else if (run.data->features.empty()) {
        html += tr("<br>No candidate features: open a candidates CSV to locate the footprint.");
    }
    m_waveSummary->setText(html);
    p->replot(QCustomPlot::rpQueuedReplot);
}

// ---------------------------------------------------------------------------------------------

QJsonObject CalibWorkspace::saveState() const {
    const CalibInputs& in = m_controller->inputs();
    QJsonObject i;
    i["detectors"] = in.detectors;
    i["control_points"] = in.controlPoints;
    i["beams"] = in.beams;
    i["check_points"] = in.checkPoints;
    i["differences"] = in.differences;
    i["group_column"] = in.groupColumn;
    i["waveform"] = in.waveform;
    i["features"] = in.features;
    QJsonObject o;
    o["inputs"] = i;
    o["params"] = calibParamsToJson(m_controller->params());
    QJsonObject v;
    v["color_map"] = m_colorMap->currentIndex();
    v["show_truth"] = m_showTruth->isChecked();
    v["tab"] = m_tabs->currentIndex() == 1 ? "waveform" : "detector";
    o["view"] = v;
    return o;
}

bool CalibWorkspace::readState(const QJsonObject& o, QString* error, const core::JsonParseResult* doc,
                               const std::vector<std::string>& at, StatePhase phase) {
    // Each message starts with the session's file:line:col of the value when `doc` is given.
    auto where = [&](std::vector<std::string> rel) {
        rel.insert(rel.begin(), at.begin(), at.end());
        return QString::fromStdString(doc ? doc->where(rel) : std::string());
    };
    if (!checkSessionKeys(o, {"inputs", "params", "view"}, "calibration", error, doc, at)) return false;
    CalibParams p;
    QString err;
    std::vector<std::string> paramsAt = at;
    paramsAt.push_back("params");
    if (!calibParamsFromJson(o["params"].toObject(), &p, &err, doc, paramsAt)) {
        *error = err;
        return false;
    }
    const QJsonObject i = o["inputs"].toObject();
    CalibInputs in;
    const struct {
        const char* key;
        QString* dst;
    } keys[] = {{"detectors", &in.detectors},   {"control_points", &in.controlPoints}, {"beams", &in.beams},
                {"check_points", &in.checkPoints}, {"differences", &in.differences},     {"group_column", &in.groupColumn},
                {"waveform", &in.waveform},     {"features", &in.features}};
    std::vector<std::string> inputKeys;
    for (const auto& k : keys) inputKeys.push_back(k.key);
    std::vector<std::string> inputsAt = at;
    inputsAt.push_back("inputs");
    if (!checkSessionKeys(i, inputKeys, "calibration inputs", error, doc, inputsAt)) return false;
    for (const auto& k : keys) {
        if (i.contains(k.key) && !i[k.key].isString()) {
            *error = where({"inputs", k.key}) +
                     tr("calibration inputs: %1 must be a path, \"demo\" or empty").arg(k.key);
            return false;
        }
        *k.dst = i[k.key].toString();
    }
    const QJsonObject v = o["view"].toObject();
    const int cmap = v["color_map"].toInt(int(ColorMap::Inferno));
    if (cmap < 0 || cmap >= m_colorMap->count()) {
        *error = where({"view", "color_map"}) + tr("calibration view: colour map %1 out of range").arg(cmap);
        return false;
    }
    if (phase == StatePhase::Check) return true;  // (nothing above changes the workspace)
    // The inputs, all or nothing: read when prepared (and kept for the restore), else now.
    if (phase == StatePhase::Prepare || !m_preparedInputs || !(m_preparedInputs->inputs == in)) {
        m_preparedInputs = m_controller->readInputs(in, &err);
        if (!m_preparedInputs) {
            *error = tr("calibration inputs: %1").arg(err);
            return false;
        }
    }
    if (phase == StatePhase::Prepare) return true;
    m_controller->adoptInputs(std::exchange(m_preparedInputs, nullptr));
    m_controller->setParams(p);
    widgetsFromParams();
    m_colorMap->setCurrentIndex(cmap);
    m_showTruth->setChecked(v["show_truth"].toBool(true));
    showTab(v["tab"].toString());
    return true;
}

}  // namespace lwb::ui
