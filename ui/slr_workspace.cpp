#include "ui/slr_workspace.hpp"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QVBoxLayout>
#include <qcustomplot.h>
#include <algorithm>
#include <climits>

#include "core/sim/slr_sim.hpp"
#include "ui/param_slider.hpp"
#include "ui/workspace_layout.hpp"

namespace lwb::ui {

using namespace core::slr;

namespace {
const QColor kSignal(31, 119, 180), kRecovered(44, 160, 44), kNoise(150, 150, 150), kRejected(214, 39, 40),
    kNormalPoint(0, 0, 0), kForced(255, 127, 14);
constexpr size_t kMaxShown = 40000;  // points per graph shown; more are thinned with a fixed stride

QCustomPlot* newPlot(QWidget* parent, const QString& x, const QString& y) {
    auto* p = new QCustomPlot(parent);
    p->xAxis->setLabel(x);
    p->yAxis->setLabel(y);
    p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    p->setMinimumHeight(180);
    p->setNoAntialiasingOnDrag(true);
    return p;
}

QCPGraph* scatter(QCustomPlot* p, const QString& name, const QColor& c, QCPScatterStyle::ScatterShape shape, double size) {
    QCPGraph* g = p->addGraph();
    g->setName(name);
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(shape, c, c, size));
    g->setAdaptiveSampling(true);
    return g;
}

// Thinned (x, y) vectors for display: at most kMaxShown points with a fixed stride.
void fill(QCPGraph* g, const QVector<double>& x, const QVector<double>& y) {
    if (x.size() <= int(kMaxShown)) {
        g->setData(x, y);
        return;
    }
    const int stride = int(x.size() / kMaxShown) + 1;
    QVector<double> xs, ys;
    xs.reserve(x.size() / stride + 1);
    ys.reserve(x.size() / stride + 1);
    for (int i = 0; i < x.size(); i += stride) {
        xs << x[i];
        ys << y[i];
    }
    g->setData(xs, ys);
}
}  // namespace

SlrWorkspace::SlrWorkspace(QWidget* parent) : QWidget(parent) {
    m_controller = new SlrController(this);

    // Top: inputs.
    auto* top = new QHBoxLayout;
    auto* open = new QPushButton(tr("Open CRD / O-C CSV…"), this);
    auto* cpf = new QPushButton(tr("CPF…"), this);
    auto* snx = new QPushButton(tr("SINEX…"), this);
    m_cpfLabel = new QLabel(tr("no prediction"), this);
    m_snxLabel = new QLabel(tr("no station file"), this);
    m_passCombo = new QComboBox(this);
    m_passCombo->setMinimumWidth(280);
    top->addWidget(open);
    top->addWidget(cpf);
    top->addWidget(m_cpfLabel);
    top->addWidget(snx);
    top->addWidget(m_snxLabel);
    top->addWidget(new QLabel(tr("Pass:"), this));
    top->addWidget(m_passCombo, 1);
    m_info = new QLabel(this);
    m_info->setWordWrap(true);

    // Plots.
    m_ocPlot = newPlot(this, tr("Epoch (s since 0h UTC)"), tr("O-C (ns, two-way)"));
    m_imagePlot = newPlot(this, tr("Epoch (s since 0h UTC)"), tr("O-C (ns, two-way)"));
    m_imagePlot->plotLayout()->insertRow(0);
    m_imagePlot->plotLayout()->addElement(0, 0, new QCPTextElement(m_imagePlot, tr("Binary image: occupied pixels by region class"), QFont(font().family(), 9)));
    m_ocPlot->plotLayout()->insertRow(0);
    m_ocPlot->plotLayout()->addElement(0, 0, new QCPTextElement(m_ocPlot, tr("O-C residuals"), QFont(font().family(), 9)));
    m_histPlot = newPlot(this, tr("Post-fit residual (ps, two-way; 1 ps = 0.15 mm one-way)"), tr("Points"));
    m_histPlot->setMinimumHeight(140);
    for (QCustomPlot* p : {m_ocPlot, m_imagePlot}) {
        // Legend in a row under the axes, so it never hides the track.
        p->legend->setVisible(true);
        p->legend->setFont(QFont(font().family(), 8));
        p->legend->setFillOrder(QCPLegend::foColumnsFirst);
        p->legend->setWrap(3);
        p->axisRect()->insetLayout()->take(p->legend);
        p->plotLayout()->addElement(2, 0, p->legend);
        p->plotLayout()->setRowStretchFactor(2, 0.001);
        p->legend->setBorderPen(Qt::NoPen);
    }
    m_imageMap = new QCPColorMap(m_imagePlot->xAxis, m_imagePlot->yAxis);
    m_imageMap->setName(tr("empty"));
    QCPColorGradient g;
    g.clearColorStops();
    g.setColorStopAt(0.0, Qt::white);
    g.setColorStopAt(0.33, kNoise);
    g.setColorStopAt(0.67, kRecovered);
    g.setColorStopAt(1.0, kSignal);
    g.setLevelCount(4);
    m_imageMap->setGradient(g);
    m_imageMap->setInterpolate(false);
    m_imageMap->setDataRange(QCPRange(0, 3));
    m_imageMap->removeFromLegend();
    for (auto [name, color] : {std::pair{tr("noise regions"), kNoise}, std::pair{tr("recovered regions"), kRecovered},
                               std::pair{tr("signal regions"), kSignal}}) {
        // Legend entries only (the colour map itself has none).
        QCPGraph* g2 = m_imagePlot->addGraph();
        g2->setName(name);
        g2->setLineStyle(QCPGraph::lsNone);
        g2->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, color, color, 8));
    }
    auto* plots = new QSplitter(Qt::Horizontal, this);
    plots->addWidget(m_ocPlot);
    plots->addWidget(m_imagePlot);
    plots->setStretchFactor(0, 1);
    plots->setStretchFactor(1, 1);
    plots->setSizes({550, 550});
    auto* vsplit = new QSplitter(Qt::Vertical, this);
    vsplit->addWidget(plots);
    auto* bottom = new QWidget(this);
    auto* bl = new QHBoxLayout(bottom);
    bl->setContentsMargins(0, 0, 0, 0);
    bl->addWidget(m_histPlot, 2);
    m_stats = new QLabel(bottom);
    m_stats->setTextFormat(Qt::RichText);
    m_stats->setWordWrap(true);
    m_stats->setMinimumWidth(300);
    m_stats->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    bl->addWidget(m_stats, 1);
    vsplit->addWidget(bottom);
    vsplit->setStretchFactor(0, 3);
    vsplit->setStretchFactor(1, 1);

    // Right: parameters.
    auto* panel = new QWidget(this);
    auto* pl = new QVBoxLayout(panel);
    auto* sg = new QGroupBox(tr("Screening (binary image)"), panel);
    auto* sf = new QFormLayout(sg);
    m_auto = new QCheckBox(tr("Automatic scale, area limit and connectivity"), sg);
    m_auto->setChecked(true);
    m_magT = new ParamSlider(tr("mag_T"), 1e-3, 1e4, 1, 4, true, tr("px/s"), sg);
    m_magOc = new ParamSlider(tr("mag_OC"), 1e5, 1e13, 1e9, 4, true, tr("px/s"), sg);
    m_area = new ParamSlider(tr("Area limit"), 1, 200, 7, 0, false, tr("px"), sg);
    m_connectivity = new QComboBox(sg);
    m_connectivity->addItems({tr("4-connectivity"), tr("8-connectivity")});
    m_cosine = new ParamSlider(tr("Cosine C"), 0.90, 0.999, 0.95, 3, false, {}, sg);
    m_cosine->setToolTipText(tr("Recovery accepts a pending region when C < |cos| of the angle to its two nearest signal regions"));
    sf->addRow(m_auto);
    sf->addRow(m_magT);
    sf->addRow(m_magOc);
    sf->addRow(m_area);
    sf->addRow(tr("Connectivity"), m_connectivity);
    sf->addRow(m_cosine);
    pl->addWidget(sg);
    auto* pg = new QGroupBox(tr("Post-fit and normal points"), panel);
    auto* pf = new QFormLayout(pg);
    m_reject = new QComboBox(pg);
    m_reject->addItems({tr("2.5 σ (single photon)"), tr("3 σ (multi photon)"), tr("off")});
    m_reject->setCurrentIndex(1);
    m_degree = new ParamSlider(tr("Trend degree"), 0, 20, 10, 0, false, {}, pg);
    pf->addRow(tr("Rejection"), m_reject);
    pf->addRow(m_degree);
    pl->addWidget(pg);
    auto* eg = new QGroupBox(tr("Manual edits (box on the O-C plot)"), panel);
    auto* el = new QVBoxLayout(eg);
    m_modeZoom = new QRadioButton(tr("Pan / zoom"), eg);
    m_modeIn = new QRadioButton(tr("Box forces points in"), eg);
    m_modeOut = new QRadioButton(tr("Box forces points out"), eg);
    m_modeZoom->setChecked(true);
    auto* modes = new QButtonGroup(this);
    for (QRadioButton* b : {m_modeZoom, m_modeIn, m_modeOut}) {
        modes->addButton(b);
        el->addWidget(b);
    }
    auto* er = new QHBoxLayout;
    m_undo = new QPushButton(tr("Undo edit"), eg);
    m_clearEdits = new QPushButton(tr("Clear edits"), eg);
    er->addWidget(m_undo);
    er->addWidget(m_clearEdits);
    el->addLayout(er);
    pl->addWidget(eg);
    auto* xg = new QGroupBox(tr("Presets and export"), panel);
    auto* xl = new QVBoxLayout(xg);
    auto* savePreset = new QPushButton(tr("Save as this satellite's preset"), xg);
    auto* exCsv = new QPushButton(tr("Export points (CSV)…"), xg);
    auto* exCrd = new QPushButton(tr("Export CRD full rate with flags…"), xg);
    auto* exNp = new QPushButton(tr("Export normal points (CRD)…"), xg);
    for (QPushButton* b : {savePreset, exCsv, exCrd, exNp}) xl->addWidget(b);
    pl->addWidget(xg);
    pl->addStretch(1);
    layoutWorkspace(this, top, m_info, vsplit, panel, 340, 1100);

    // Wiring.
    connect(m_controller, &SlrController::runReady, this, &SlrWorkspace::showRun);
    connect(m_controller, &SlrController::runFailed, this,
            [this](const QString& m) { m_stats->setText(tr("<b>Screening failed:</b> %1").arg(m.toHtmlEscaped())); });
    connect(m_controller, &SlrController::status, this, &SlrWorkspace::status);
    connect(m_controller, &SlrController::editsChanged, this, [this] {
        m_undo->setEnabled(m_controller->editCount() > 0);
        m_clearEdits->setEnabled(m_controller->editCount() > 0);
    });
    connect(m_controller, &SlrController::passChanged, this, [this] {
        widgetsFromParams();
        const PassData& p = m_controller->pass();
        m_info->setText(tr("<b>%1</b> %2 — %3 points, O-C from %4%5")
                            .arg(QString::fromStdString(p.satellite).toHtmlEscaped(),
                                 p.ilrsId.empty() ? QString() : "(" + QString::fromStdString(p.ilrsId) + ")")
                            .arg(p.t.size())
                            .arg(QString::fromStdString(p.ocOrigin))
                            .arg(p.station.empty() ? QString() : tr(", station %1").arg(QString::fromStdString(p.station))));
        // What the readers said about the files, in view (not only in the status bar): a damaged
        // record means an incomplete pass, and no export (the CLI refuses such a pass too).
        QString notes;
        if (!p.damaged.empty())
            notes += tr("<br><b style=\"color:#b00000\">Damaged records: exports are refused.</b> %1")
                         .arg(QString::fromStdString(p.damaged).toHtmlEscaped());
        const auto& warnings = m_controller->warnings();
        const size_t shown = std::min<size_t>(warnings.size(), 5);
        if (!warnings.empty())
            notes += tr("<br><b>%n warning(s) reading the files:</b>", nullptr, int(warnings.size()));
        for (size_t i = 0; i < shown; ++i) notes += "<br>" + QString::fromStdString(warnings[i]).toHtmlEscaped();
        if (warnings.size() > shown) notes += tr("<br>… and %1 more (in the status messages)").arg(warnings.size() - shown);
        m_info->setText(m_info->text() + notes);
        m_ocPlot->xAxis->setRange(0, 1);  // force a rescale on the first run of the new pass
        m_ocPlot->setProperty("fresh", true);
    });
    for (ParamSlider* s : {m_magT, m_magOc, m_area, m_cosine, m_degree})
        connect(s, &ParamSlider::valueChanged, this, [this] { paramsFromWidgets(); });
    connect(m_auto, &QCheckBox::toggled, this, [this] { paramsFromWidgets(); });
    connect(m_connectivity, &QComboBox::currentIndexChanged, this, [this] { paramsFromWidgets(); });
    connect(m_reject, &QComboBox::currentIndexChanged, this, [this] { paramsFromWidgets(); });
    connect(m_ocPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { linkRanges(m_ocPlot, m_imagePlot); });
    connect(m_ocPlot->yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { linkRanges(m_ocPlot, m_imagePlot); });
    connect(m_imagePlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { linkRanges(m_imagePlot, m_ocPlot); });
    connect(m_imagePlot->yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { linkRanges(m_imagePlot, m_ocPlot); });
    connect(m_ocPlot->selectionRect(), &QCPSelectionRect::accepted, this,
            [this](const QRect& r, QMouseEvent*) { boxSelected(r); });
    for (QRadioButton* b : {m_modeZoom, m_modeIn, m_modeOut})
        connect(b, &QRadioButton::toggled, this, [this] {
            m_ocPlot->setSelectionRectMode(m_modeZoom->isChecked() ? QCP::srmNone : QCP::srmCustom);
        });
    connect(m_undo, &QPushButton::clicked, this, [this] {
        m_controller->undoEdit();
        emit modified();
    });
    connect(m_clearEdits, &QPushButton::clicked, this, [this] {
        m_controller->clearEdits();
        emit modified();
    });
    connect(open, &QPushButton::clicked, this, [this] {
        QSettings st;
        const QString path = QFileDialog::getOpenFileName(this, tr("Open a ranging pass"), st.value("paths/slr").toString(),
                                                          tr("CRD and O-C tables (*.frd *.fr2 *.npt *.np2 *.crd *.csv);;All files (*)"));
        if (path.isEmpty()) return;
        st.setValue("paths/slr", QFileInfo(path).absolutePath());
        QString err;
        if (!openPath(path, -1, &err)) QMessageBox::warning(this, tr("Cannot open the pass"), err);
    });
    connect(cpf, &QPushButton::clicked, this, [this] {
        pickFile(&m_cpfPath, m_cpfLabel, tr("CPF prediction"), tr("CPF (*.hts *.cpf *.sgf *.*)"));
    });
    connect(snx, &QPushButton::clicked, this, [this] {
        pickFile(&m_snxPath, m_snxLabel, tr("SINEX station coordinates"), tr("SINEX (*.snx *.SNX *.*)"));
    });
    connect(m_passCombo, &QComboBox::activated, this, [this](int i) {
        QString err;
        if (!m_path.isEmpty() && !openPath(m_path, m_passCombo->itemData(i).toInt(), &err))
            QMessageBox::warning(this, tr("Cannot open the pass"), err);
    });
    connect(savePreset, &QPushButton::clicked, this, [this] {
        QString err;
        if (!m_controller->savePreset(&err)) QMessageBox::warning(this, tr("Preset"), err);
        else emit status(tr("Preset saved for %1 in %2").arg(QString::fromStdString(m_controller->pass().satellite), m_controller->presetFile()));
    });
    auto exporter = [this](const QString& title, const QString& filter, auto fn) {
        if (const std::string& damaged = m_controller->pass().damaged; !damaged.empty()) {
            QMessageBox::warning(this, title, QString::fromStdString(damaged));
            return;
        }
        QSettings st;
        const QString path = QFileDialog::getSaveFileName(this, title, st.value("paths/slrExport").toString(), filter);
        if (path.isEmpty()) return;
        st.setValue("paths/slrExport", QFileInfo(path).absolutePath());
        QString err;
        if (!(m_controller->*fn)(path, &err)) QMessageBox::warning(this, title, err);
        else emit status(tr("Wrote %1").arg(path));
    };
    connect(exCsv, &QPushButton::clicked, this, [=] { exporter(tr("Export points"), tr("CSV (*.csv)"), &SlrController::exportCsv); });
    connect(exCrd, &QPushButton::clicked, this, [=] { exporter(tr("Export CRD full rate"), tr("CRD (*.frd *.fr2 *.crd)"), &SlrController::exportCrd); });
    connect(exNp, &QPushButton::clicked, this, [=] { exporter(tr("Export normal points"), tr("CRD (*.npt *.np2 *.crd)"), &SlrController::exportNormalPoints); });
    widgetsFromParams();
    m_undo->setEnabled(false);
    m_clearEdits->setEnabled(false);
}

void SlrWorkspace::pickFile(QString* target, QLabel* label, const QString& title, const QString& filter) {
    QSettings st;
    const QString path = QFileDialog::getOpenFileName(this, title, st.value("paths/slr").toString(), filter);
    if (path.isEmpty()) return;
    *target = path;
    label->setText(QFileInfo(path).fileName());
    if (!m_path.isEmpty()) {
        QString err;
        if (!openPath(m_path, m_controller->pass().passIndex, &err)) QMessageBox::warning(this, title, err);
    }
}

bool SlrWorkspace::openPath(const QString& path, int passIndex, QString* error) {
    PassInputParams in = m_controller->inputParams();
    in.cpfPath = m_cpfPath.toStdString();
    in.sinexPath = m_snxPath.toStdString();
    if (!m_controller->open(path, passIndex, in, error)) return false;
    m_path = path;
    m_loading = true;
    m_passCombo->clear();
    for (const PassSummary& s : m_controller->passes())
        m_passCombo->addItem(s.satellite.empty() ? tr("O-C table, %1 points").arg(s.ranges)
                                                 : tr("%1: %2 %3, %4 ranges").arg(s.index + 1).arg(QString::fromStdString(s.satellite),
                                                                                                 QString::fromStdString(s.start))
                                                                                     .arg(s.ranges),
                             s.index);
    m_passCombo->setCurrentIndex(m_passCombo->findData(m_controller->pass().passIndex));
    m_loading = false;
    emit modified();
    return true;
}

void SlrWorkspace::openDemo(int points) {
    using namespace core::sim;
    SlrSimParams p = slrSimPreset(SlrKind::Khz);
    p.points = points;
    p.signalFraction = 0.10;
    p.durationS = 300;
    const SlrSimPass pass = simulateSlrPass(p, 42);
    m_path.clear();
    m_passCombo->clear();
    m_passCombo->addItem(tr("Simulated kHz pass (10 % signal)"), 0);
    m_controller->setSimulatedPass(pass.epochS, pass.ocS, pass.tofS, pass.isSignal, tr("Simulated kHz pass"),
                                   p.altitudeKm);
}

void SlrWorkspace::widgetsFromParams() {
    m_loading = true;
    const ScreenParams& s = m_controller->screenParams();
    m_auto->setChecked(s.automatic);
    if (s.magT > 0) m_magT->setValue(s.magT);
    if (s.magOc > 0) m_magOc->setValue(s.magOc);
    if (s.areaLimit > 0) m_area->setValue(s.areaLimit);
    if (s.connectivity) m_connectivity->setCurrentIndex(s.connectivity == 4 ? 0 : 1);
    m_cosine->setValue(s.cosineC);
    for (QWidget* w : std::initializer_list<QWidget*>{m_magT, m_magOc, m_area, m_connectivity}) w->setEnabled(!s.automatic);
    const PostfitParams& p = m_controller->postfitParams();
    m_reject->setCurrentIndex(p.rejectSigma == 0 ? 2 : p.rejectSigma < 2.75 ? 0 : 1);
    m_degree->setValue(p.degree);
    m_loading = false;
}

void SlrWorkspace::paramsFromWidgets() {
    if (m_loading) return;
    ScreenParams s = m_controller->screenParams();
    s.automatic = m_auto->isChecked();
    for (QWidget* w : std::initializer_list<QWidget*>{m_magT, m_magOc, m_area, m_connectivity}) w->setEnabled(!s.automatic);
    if (s.automatic) {
        s.magT = s.magOc = 0;
        s.areaLimit = s.connectivity = 0;
    } else {
        s.magT = m_magT->value();
        s.magOc = m_magOc->value();
        s.areaLimit = int(std::lround(m_area->value()));
        s.connectivity = m_connectivity->currentIndex() == 0 ? 4 : 8;
    }
    s.cosineC = m_cosine->value();
    if (!validate(s).empty()) return;
    PostfitParams p = m_controller->postfitParams();
    p.rejectSigma = m_reject->currentIndex() == 0 ? 2.5 : m_reject->currentIndex() == 1 ? 3.0 : 0.0;
    p.degree = int(std::lround(m_degree->value()));
    m_controller->setScreenParams(s);
    m_controller->setPostfitParams(p);
    emit modified();
}

void SlrWorkspace::linkRanges(QCustomPlot* from, QCustomPlot* to) {
    if (m_linking) return;
    m_linking = true;
    to->xAxis->setRange(from->xAxis->range());
    if (!m_imageFlattened) to->yAxis->setRange(from->yAxis->range());
    to->replot(QCustomPlot::rpQueuedReplot);
    m_linking = false;
}

void SlrWorkspace::boxSelected(const QRect& rect) {
    if (!m_controller->hasPass() || m_modeZoom->isChecked()) return;
    const double x0 = m_ocPlot->xAxis->pixelToCoord(rect.left()), x1 = m_ocPlot->xAxis->pixelToCoord(rect.right());
    const double y0 = m_ocPlot->yAxis->pixelToCoord(rect.bottom()), y1 = m_ocPlot->yAxis->pixelToCoord(rect.top());
    const PassData& p = m_controller->pass();
    std::vector<uint32_t> idx;
    for (size_t i = 0; i < p.t.size(); ++i) {
        const double y = p.oc[i] * 1e9;
        if (p.t[i] >= std::min(x0, x1) && p.t[i] <= std::max(x0, x1) && y >= std::min(y0, y1) && y <= std::max(y0, y1))
            idx.push_back(uint32_t(i));
    }
    m_controller->forcePoints(idx, m_modeIn->isChecked());
    emit status(tr("%1 points forced %2").arg(idx.size()).arg(m_modeIn->isChecked() ? tr("in") : tr("out")));
    emit modified();
}

void SlrWorkspace::showRun(const SlrRun& run) {
    const PassData& p = m_controller->pass();
    const ScreenResult& s = run.screen;
    // Show the automatic choice on the (disabled) sliders.
    if (m_controller->screenParams().automatic) {
        m_loading = true;
        m_magT->setValue(s.magT);
        m_magOc->setValue(s.magOc);
        m_area->setValue(s.areaLimit);
        m_connectivity->setCurrentIndex(s.connectivity == 4 ? 0 : 1);
        m_loading = false;
    }
    const bool fresh = m_ocPlot->property("fresh").toBool();
    const QCPRange xr = m_ocPlot->xAxis->range(), yr = m_ocPlot->yAxis->range();
    // O-C scatter by class.
    m_ocPlot->clearGraphs();
    QVector<double> nx, ny, sx, sy, rx, ry, jx, jy, fx, fy;
    const size_t n = p.t.size();
    const auto& forced = m_controller->forced();
    for (size_t i = 0; i < n; ++i) {
        const double x = p.t[i], y = p.oc[i] * 1e9;
        if (!run.accepted[i]) {
            nx << x;
            ny << y;
        } else if (run.post.ok && !run.post.kept[i]) {
            jx << x;
            jy << y;
        } else if (s.pointClass[i] == PointClass::Recovered) {
            rx << x;
            ry << y;
        } else {
            sx << x;
            sy << y;
        }
        if (i < forced.size() && forced[i]) {
            fx << x;
            fy << y;
        }
    }
    fill(scatter(m_ocPlot, tr("noise (%1)").arg(nx.size()), kNoise, QCPScatterStyle::ssDisc, 2.5), nx, ny);
    fill(scatter(m_ocPlot, tr("signal (%1)").arg(sx.size()), kSignal, QCPScatterStyle::ssDisc, 3), sx, sy);
    fill(scatter(m_ocPlot, tr("recovered (%1)").arg(rx.size()), kRecovered, QCPScatterStyle::ssDisc, 3.5), rx, ry);
    fill(scatter(m_ocPlot, tr("rejected by post-fit (%1)").arg(jx.size()), kRejected, QCPScatterStyle::ssCross, 5), jx, jy);
    if (!fx.isEmpty()) fill(scatter(m_ocPlot, tr("manual (%1)").arg(fx.size()), kForced, QCPScatterStyle::ssCircle, 7), fx, fy);
    if (p.stationFlag.size() == n) {  // the station's own screening, for comparison
        QVector<double> dx, dy;
        for (size_t i = 0; i < n; ++i)
            if (p.stationFlag[i] == 2) {
                dx << p.t[i];
                dy << p.oc[i] * 1e9;
            }
        QCPGraph* g = m_ocPlot->addGraph();
        g->setName(tr("station flag: data (%1)").arg(dx.size()));
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(90, 40, 140), 1), Qt::NoBrush, 7));
        fill(g, dx, dy);
    }
    if (run.post.ok) {
        QVector<double> tx, ty, px, py;
        // The trend only where it was fitted (a polynomial outside its span means nothing).
        double t0 = INFINITY, t1 = -INFINITY;
        for (size_t i = 0; i < n; ++i)
            if (run.post.kept[i]) {
                t0 = std::min(t0, p.t[i]);
                t1 = std::max(t1, p.t[i]);
            }
        if (!(t1 > t0)) t0 = t1 = p.t.front();
        for (int k = 0; k <= 200; ++k) {
            const double t = t0 + (t1 - t0) * k / 200.0;
            tx << t;
            ty << evaluateTrend(run.post, t) * 1e9;
        }
        QCPGraph* trend = m_ocPlot->addGraph();
        trend->setName(tr("trend (degree %1)").arg(run.post.degree));
        trend->setPen(QPen(QColor(60, 60, 60), 1.2));
        trend->setData(tx, ty);
        for (const NormalPoint& np : run.post.normalPoints) {
            px << np.epochS;
            py << np.ocS * 1e9;
        }
        fill(scatter(m_ocPlot, tr("normal points (%1)").arg(px.size()), kNormalPoint, QCPScatterStyle::ssDiamond, 8), px, py);
    }
    // Binary image: the occupied pixels as a colour map in (epoch, O-C) units, so its axes can
    // follow the O-C plot. Cells hold 0 empty, 1 noise, 2 recovered, 3 signal; an image larger
    // than 2000 × 2000 cells is shown max-pooled (a cell shows the strongest class it covers).
    // After a refinement round the kept image is of the O-C less the accepted track's trend
    // (ScreenResult::flattenS); it is drawn in that frame, with only the time axis linked.
    const bool flattened = s.flattenS.size() == n;
    m_imageFlattened = flattened;
    std::vector<double> imgOc(p.oc);
    if (flattened)
        for (size_t i = 0; i < n; ++i) imgOc[i] -= s.flattenS[i];
    m_imagePlot->yAxis->setLabel(flattened ? tr("O-C less the track's trend (ns, two-way)") : tr("O-C (ns, two-way)"));
    {
        long long r0 = LLONG_MAX, r1 = LLONG_MIN, c0 = LLONG_MAX, c1 = LLONG_MIN;
        for (size_t i = 0; i < n; ++i) {
            const long long r = std::llround(p.t[i] * s.magT), c = std::llround(imgOc[i] * s.magOc);
            r0 = std::min(r0, r);
            r1 = std::max(r1, r);
            c0 = std::min(c0, c);
            c1 = std::max(c1, c);
        }
        const long long nr = r1 - r0 + 1, nc = c1 - c0 + 1;
        const long long fr = (nr + 1999) / 2000, fc = (nc + 1999) / 2000;
        const int cols = int((nr + fr - 1) / fr), rows = int((nc + fc - 1) / fc);
        m_imageMap->data()->setSize(cols, rows);
        m_imageMap->data()->setRange(QCPRange(r0 / s.magT, (r0 + (cols - 1) * fr) / s.magT),
                                     QCPRange(c0 / s.magOc * 1e9, (c0 + (rows - 1) * fc) / s.magOc * 1e9));
        m_imageMap->data()->fill(0);
        for (size_t i = 0; i < n; ++i) {
            const int x = int((std::llround(p.t[i] * s.magT) - r0) / fr), y = int((std::llround(imgOc[i] * s.magOc) - c0) / fc);
            const RegionClass rc = s.regionClass[s.pointRegion[i]];
            const double v = rc == RegionClass::Signal ? 3 : rc == RegionClass::Recovered ? 2 : 1;
            if (m_imageMap->data()->cell(x, y) < v) m_imageMap->data()->setCell(x, y, v);
        }
        m_imageMap->setDataRange(QCPRange(0, 3));
        // The track is a few pixels thick in an image thousands of pixels tall: draw the signal
        // and recovered pixels again as small marks on top so it stays visible when zoomed out.
        QVector<double> gx[2], gy[2];
        for (size_t i = 0; i < n; ++i) {
            const RegionClass rc = s.regionClass[s.pointRegion[i]];
            if (rc == RegionClass::Noise) continue;
            const int k = rc == RegionClass::Signal ? 1 : 0;
            gx[k] << std::llround(p.t[i] * s.magT) / s.magT;
            gy[k] << std::llround(imgOc[i] * s.magOc) / s.magOc * 1e9;
        }
        m_imagePlot->graph(1)->setData(gx[0], gy[0]);
        m_imagePlot->graph(1)->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, kRecovered, kRecovered, 3));
        fill(m_imagePlot->graph(2), gx[1], gy[1]);
        m_imagePlot->graph(2)->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, kSignal, kSignal, 3));
    }
    if (fresh) {
        // Fit the view to the points (noise and signal graphs), not to the trend or markers.
        m_ocPlot->rescaleAxes();
        bool first = true;
        for (int g = 0; g < std::min(2, m_ocPlot->graphCount()); ++g) {
            bool found = false;
            const QCPRange kr = m_ocPlot->graph(g)->getKeyRange(found);
            if (!found) continue;
            const QCPRange vr = m_ocPlot->graph(g)->getValueRange(found);
            if (first) {
                m_ocPlot->xAxis->setRange(kr);
                m_ocPlot->yAxis->setRange(vr);
                first = false;
            } else {
                m_ocPlot->xAxis->setRange(QCPRange(std::min(kr.lower, m_ocPlot->xAxis->range().lower), std::max(kr.upper, m_ocPlot->xAxis->range().upper)));
                m_ocPlot->yAxis->setRange(QCPRange(std::min(vr.lower, m_ocPlot->yAxis->range().lower), std::max(vr.upper, m_ocPlot->yAxis->range().upper)));
            }
        }
        m_ocPlot->xAxis->scaleRange(1.04);
        m_ocPlot->yAxis->scaleRange(1.08);
        m_ocPlot->setProperty("fresh", false);
    } else {
        m_ocPlot->xAxis->setRange(xr);
        m_ocPlot->yAxis->setRange(yr);
    }
    linkRanges(m_ocPlot, m_imagePlot);
    if (flattened) {
        m_imagePlot->yAxis->rescale();
        m_imagePlot->yAxis->scaleRange(1.08);
    }
    // Residual histogram of the kept points.
    m_histPlot->clearPlottables();
    QString statsHtml;
    if (run.post.ok) {
        std::vector<double> res;
        for (size_t i = 0; i < n; ++i)
            if (run.post.kept[i]) res.push_back(run.post.residuals[i] * 1e12);
        if (!res.empty()) {
            const auto [mn, mx] = std::minmax_element(res.begin(), res.end());
            const int bins = std::clamp(int(std::sqrt(double(res.size()))), 10, 120);
            const double w = (*mx - *mn) / bins + 1e-9;
            QVector<double> keys(bins), vals(bins, 0);
            for (int b = 0; b < bins; ++b) keys[b] = *mn + (b + 0.5) * w;
            for (double v : res) vals[std::min(bins - 1, int((v - *mn) / w))] += 1;
            auto* bars = new QCPBars(m_histPlot->xAxis, m_histPlot->yAxis);
            bars->setWidth(w);
            bars->setData(keys, vals, true);
            bars->setPen(Qt::NoPen);
            bars->setBrush(kSignal);
            m_histPlot->rescaleAxes();
            m_histPlot->yAxis->setRangeLower(0);
        }
        const ResidualStats& st = run.post.stats;
        statsHtml += tr("<b>Accepted</b> %1 of %2 (signal %3, recovered %4), post-fit kept %5, rejected %6<br>"
                        "<b>RMS</b> %7 ps (%8 mm one-way) · skew %9 · kurtosis %10 · peak−mean %11 ps<br>"
                        "<b>Normal points</b> %12 (bins of %13 s)")
                         .arg(run.post.used)
                         .arg(n)
                         .arg(s.signalPoints)
                         .arg(s.recoveredPoints)
                         .arg(run.post.used - run.post.rejected)
                         .arg(run.post.rejected)
                         .arg(st.rms * 1e12, 0, 'f', 1)
                         .arg(st.rms * 1e12 * 0.149896229, 0, 'f', 2)
                         .arg(st.skew, 0, 'f', 2)
                         .arg(st.kurtosis, 0, 'f', 2)
                         .arg(st.peakMinusMean * 1e12, 0, 'f', 1)
                         .arg(run.post.normalPoints.size())
                         .arg(run.post.binLengthS, 0, 'f', 0);
    } else {
        statsHtml += tr("<b>Post-fit:</b> %1<br>").arg(QString::fromStdString(run.post.error).toHtmlEscaped());
    }
    statsHtml += tr("<br><b>Scale</b> mag_T %1 px/s, mag_OC %2 px/s, area ≥ %3 px, %4-connectivity%5 · C %6")
                     .arg(s.magT, 0, 'g', 4)
                     .arg(s.magOc, 0, 'g', 4)
                     .arg(s.areaLimit)
                     .arg(s.connectivity)
                     .arg(m_controller->screenParams().automatic
                              ? (m_controller->scaleReused() ? tr(" (automatic, kept while C moves)") : tr(" (automatic)"))
                              : QString())
                     .arg(m_controller->screenParams().cosineC, 0, 'f', 3);
    if (flattened) statsHtml += tr("<br>Refined: screened again on the O-C less the accepted track's trend (%1 round(s))").arg(s.refinedRounds);
    statsHtml += tr("<br>%1 regions, %2 candidates, %3 on the line, %4 recovered · %5 ms")
                     .arg(s.regions.size())
                     .arg(s.candidates)
                     .arg(s.linearRegions)
                     .arg(s.recoveredRegions)
                     .arg(s.totalMs, 0, 'f', 0);
    // Against the truth (simulation) or the station's own flags (CRD).
    const auto& truth = m_controller->truth();
    const bool haveTruth = truth.size() == n;
    const bool haveFlags = p.stationFlag.size() == n;
    if (haveTruth || haveFlags) {
        long tp = 0, fp = 0, fn = 0;
        for (size_t i = 0; i < n; ++i) {
            const bool real = haveTruth ? truth[i] != 0 : p.stationFlag[i] == 2;
            tp += run.accepted[i] && real;
            fp += run.accepted[i] && !real;
            fn += !run.accepted[i] && real;
        }
        statsHtml += tr("<br><b>vs %1</b>: precision %2, recall %3")
                         .arg(haveTruth ? tr("simulation truth") : tr("station filter flags"))
                         .arg(tp + fp ? double(tp) / (tp + fp) : 0, 0, 'f', 3)
                         .arg(tp + fn ? double(tp) / (tp + fn) : 0, 0, 'f', 3);
    }
    for (const auto& w : s.warnings) statsHtml += "<br><i>" + QString::fromStdString(w).toHtmlEscaped() + "</i>";
    m_stats->setText(statsHtml);
    m_ocPlot->replot(QCustomPlot::rpQueuedReplot);
    m_imagePlot->replot(QCustomPlot::rpQueuedReplot);
    m_histPlot->replot(QCustomPlot::rpQueuedReplot);
}

QJsonObject SlrWorkspace::saveState() const {
    QJsonObject o;
    o["path"] = m_path;
    o["cpf"] = m_cpfPath;
    o["sinex"] = m_snxPath;
    o["pass"] = m_controller->pass().passIndex;
    o["demo"] = m_path.isEmpty() && m_controller->hasPass();
    const ScreenParams& s = m_controller->screenParams();
    QJsonObject sp;
    sp["automatic"] = s.automatic;
    sp["mag_t"] = s.magT;
    sp["mag_oc"] = s.magOc;
    sp["area_limit"] = s.areaLimit;
    sp["connectivity"] = s.connectivity;
    sp["cosine_c"] = s.cosineC;
    o["screen"] = sp;
    QJsonObject pp;
    pp["reject_sigma"] = m_controller->postfitParams().rejectSigma;
    pp["degree"] = m_controller->postfitParams().degree;
    o["postfit"] = pp;
    QJsonArray forced;
    const auto& f = m_controller->forced();
    for (size_t i = 0; i < f.size(); ++i)
        if (f[i]) forced.append(QJsonArray{qint64(i), int(f[i])});
    o["forced"] = forced;
    return o;
}

bool SlrWorkspace::restoreState(const QJsonObject& o, QString* error) {
    ScreenParams s;
    const QJsonObject sp = o["screen"].toObject();
    s.automatic = sp["automatic"].toBool(true);
    s.magT = sp["mag_t"].toDouble();
    s.magOc = sp["mag_oc"].toDouble();
    s.areaLimit = sp["area_limit"].toInt();
    s.connectivity = sp["connectivity"].toInt();
    s.cosineC = sp["cosine_c"].toDouble(0.95);
    if (const std::string e = validate(s); !e.empty()) {
        *error = tr("SLR screening parameters: %1").arg(QString::fromStdString(e));
        return false;
    }
    const QJsonObject pp = o["postfit"].toObject();
    const double rejectSigma = pp["reject_sigma"].toDouble(3.0);
    const int degree = pp["degree"].toInt(10);
    if (!(rejectSigma == 0 || (rejectSigma >= 1 && rejectSigma <= 10)) || degree < 0 || degree > 30) {
        *error = tr("SLR post-fit parameters: rejection %1 σ, degree %2 out of range").arg(rejectSigma).arg(degree);
        return false;
    }
    m_cpfPath = o["cpf"].toString();
    m_snxPath = o["sinex"].toString();
    m_cpfLabel->setText(m_cpfPath.isEmpty() ? tr("no prediction") : QFileInfo(m_cpfPath).fileName());
    m_snxLabel->setText(m_snxPath.isEmpty() ? tr("no station file") : QFileInfo(m_snxPath).fileName());
    const QString path = o["path"].toString();
    if (!path.isEmpty()) {
        if (!openPath(path, o["pass"].toInt(-1), error)) return false;
    } else if (o["demo"].toBool()) {
        openDemo();
    }
    m_controller->setScreenParams(s);
    PostfitParams p = m_controller->postfitParams();  // the altitude comes with the pass
    p.rejectSigma = rejectSigma;
    p.degree = degree;
    m_controller->setPostfitParams(p);
    std::vector<uint32_t> in, out;
    for (const auto& v : o["forced"].toArray()) {
        const QJsonArray a = v.toArray();
        const qint64 i = a.at(0).toInteger(-1);
        if (i < 0 || size_t(i) >= m_controller->pass().t.size()) {
            *error = tr("SLR manual edit of point %1: the pass has %2 points").arg(i).arg(m_controller->pass().t.size());
            return false;
        }
        (a.at(1).toInt() > 0 ? in : out).push_back(uint32_t(i));
    }
    m_controller->forcePoints(in, true);
    m_controller->forcePoints(out, false);
    widgetsFromParams();
    return true;
}

}  // namespace lwb::ui
