#include "ui/slr/slr_workspace.hpp"

#include <QAbstractItemView>
#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QDialogButtonBox>
#include <QDialog>
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
#include <QRegularExpression>
#include <QSplitter>
#include <QTabWidget>
#include <QToolButton>
#include <QAction>
#include <QUndoStack>
#include <QVBoxLayout>
#include <qcustomplot.h>
#include <algorithm>
#include <climits>

#include "core/sim/slr_sim.hpp"
#include "core/slr/tune.hpp"
#include "ui/kit/elided_label.hpp"
#include "ui/kit/modal_work.hpp"
#include "ui/kit/save_path.hpp"
#include "ui/kit/app_undo.hpp"
#include "ui/kit/params_command.hpp"
#include "ui/kit/param_slider.hpp"
#include "ui/kit/plot_kit.hpp"
#include "ui/slr/slr_all_passes.hpp"
#include "ui/slr/slr_file_check.hpp"
#include "ui/slr/slr_station_nps.hpp"
#include "ui/slr/slr_strips.hpp"
#include "ui/kit/session_json.hpp"
#include "ui/slr/slr_params_panel.hpp"
#include "ui/kit/workspace_layout.hpp"

namespace lwb::ui {

using namespace core::slr;

namespace {
const QColor kSignal(31, 119, 180), kRecovered(44, 160, 44), kBand(188, 189, 34), kNoise(150, 150, 150), kRejected(214, 39, 40),
    kNormalPoint(0, 0, 0), kForced(255, 127, 14), kStationNp(0, 160, 160);
constexpr size_t kMaxShown = 40000;  // points per graph shown; more are thinned with a fixed stride
constexpr double kMmPerPs = 0.149896229;  // 1 ps two-way = c / 2 · 1 ps of range, one-way

// Undo: the manual edits of the pass as a whole, before and after.
class ForcedCommand : public QUndoCommand {
public:
    ForcedCommand(SlrController* c, std::vector<int8_t> before, std::vector<int8_t> after, const QString& text)
        : QUndoCommand(text), m_c(c), m_before(std::move(before)), m_after(std::move(after)) {}
    void undo() override {
        if (m_c) m_c->setForced(m_before);
    }
    void redo() override {
        if (m_c) m_c->setForced(m_after);
    }

private:
    QPointer<SlrController> m_c;
    std::vector<int8_t> m_before, m_after;
};

void pushParams(SlrWorkspace* w, const SlrParams& before, const SlrParams& after) {
    pushParamsChange<SlrParams>(
        w, slrSchema(), before, after,
        [w](const SlrParams& p) {
            w->paramsPanel()->setParams(p);
            w->controller()->setParams(p);
        },
        QObject::tr("SLR parameters"));
}

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

SlrWorkspace::SlrWorkspace(QWidget* parent) : Workspace(parent) {
    m_controller = new SlrController(this);
    QHBoxLayout* top = buildInputRow();
    m_info = new QLabel(this);
    m_info->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_info->setWordWrap(true);

    buildPlots();
    QWidget* vsplit = buildPlotArea();
    QWidget* panel = buildPanel();
    layoutWorkspace(this, QStringLiteral("slr"), wrapRow(top), m_info, vsplit, panel, 430, 1030);
    wireController();
    m_params->setParams(m_controller->params());
    m_undo->setEnabled(undoStackOf(this).canUndo());
    m_clearEdits->setEnabled(false);
    m_cpfClear->setEnabled(false);
    m_snxClear->setEnabled(false);
    applyTimeAxis();
}

// Top: the inputs (pass file, CPF, CPF folder, SINEX) and their labels.
QHBoxLayout* SlrWorkspace::buildInputRow() {
    auto* top = new QHBoxLayout;
    auto* open = new QPushButton(tr("Open CRD / O-C CSV…"), this);
    open->setToolTip(tr("Open an ILRS CRD full-rate file (every pass is listed) or an O-C table (CSV: epoch_s,oc_s)"));
    auto* cpf = new QPushButton(tr("CPF…"), this);
    cpf->setToolTip(tr("A CPF prediction file: with the SINEX file, O-C from the prediction (replaces the one given)"));
    auto* cpfDir = new QPushButton(tr("CPF folder…"), this);
    cpfDir->setToolTip(tr("A folder of CPF files: for each pass the one whose satellite and time span fit is picked"));
    m_cpfClear = new QToolButton(this);
    m_cpfClear->setText(tr("Clear"));
    m_cpfClear->setToolTip(tr("Clear the prediction: O-C from each pass's own fitted TOF trend"));
    auto* snx = new QPushButton(tr("SINEX…"), this);
    snx->setToolTip(tr("SINEX station coordinates (needed with the CPF for O-C from the prediction, and for day/night normal points)"));
    m_snxClear = new QToolButton(this);
    m_snxClear->setText(tr("Clear"));
    m_snxClear->setToolTip(tr("Clear the station coordinates"));
    // The files' names elided in the middle when the row is short (the whole path in the tooltip).
    m_cpfLabel = new ElidedLabel(tr("no prediction"), this);
    m_cpfLabel->setPlainToolTip(tr("The prediction in use"));
    m_snxLabel = new ElidedLabel(tr("no station file"), this);
    m_snxLabel->setPlainToolTip(tr("The station coordinates in use"));
    for (QLabel* l : {m_cpfLabel, m_snxLabel}) {
        l->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
        l->setMaximumWidth(190);
    }
    top->addWidget(open);
    top->addWidget(cpf);
    top->addWidget(cpfDir);
    top->addWidget(m_cpfLabel);
    top->addWidget(m_cpfClear);
    top->addWidget(snx);
    top->addWidget(m_snxLabel);
    top->addWidget(m_snxClear);
    top->addStretch(1);
    connect(open, &QPushButton::clicked, this, &SlrWorkspace::choosePass);
    auto choose = [this](bool folder, bool cpfFile) {
        QSettings st;
        const QString dir = st.value("paths/slrInputs", st.value("paths/slr")).toString();
        const QString path = folder ? QFileDialog::getExistingDirectory(this, tr("Folder of CPF predictions"), dir)
                             : cpfFile ? QFileDialog::getOpenFileName(this, tr("CPF prediction"), dir, tr("CPF (*.hts *.cpf *.sgf);;All files (*)"))
                                       : QFileDialog::getOpenFileName(this, tr("SINEX station coordinates"), dir, tr("SINEX (*.snx *.SNX);;All files (*)"));
        if (path.isEmpty()) return;
        st.setValue("paths/slrInputs", folder ? path : QFileInfo(path).absolutePath());
        QString err;
        if (!(cpfFile || folder ? setCpf(path, &err) : setSinex(path, &err))) QMessageBox::warning(this, tr("Cannot use the file"), err);
    };
    connect(cpf, &QPushButton::clicked, this, [=] { choose(false, true); });
    connect(cpfDir, &QPushButton::clicked, this, [=] { choose(true, true); });
    connect(snx, &QPushButton::clicked, this, [=] { choose(false, false); });
    connect(m_cpfClear, &QToolButton::clicked, this, [this] {
        QString err;
        if (!setCpf(QString(), &err)) QMessageBox::warning(this, tr("CPF"), err);
    });
    connect(m_snxClear, &QToolButton::clicked, this, [this] {
        QString err;
        if (!setSinex(QString(), &err)) QMessageBox::warning(this, tr("SINEX"), err);
    });
    return top;
}

// The plots: O-C, binary image (with its colour maps and legend entries), residual histogram.
void SlrWorkspace::buildPlots() {
    m_ocPlot = newPlot(this, tr("Epoch (s since 0h UTC)"), tr("O-C (ns, two-way)"));
    m_imagePlot = newPlot(this, tr("Epoch (s since 0h UTC)"), tr("O-C (ns, two-way)"));
    m_imagePlot->plotLayout()->insertRow(0);
    m_imagePlot->plotLayout()->addElement(0, 0, new QCPTextElement(m_imagePlot, tr("Binary image: pixels by region class"), QFont(font().family(), 9)));
    m_ocPlot->plotLayout()->insertRow(0);
    m_ocPlot->plotLayout()->addElement(0, 0, new QCPTextElement(m_ocPlot, tr("O-C"), QFont(font().family(), 9)));
    m_ocPlot->yAxis2->setLabel(tr("mm, one-way"));
    // Short enough for the narrow plot of a 1024 px window; the summary beside it gives the RMS
    // in mm one-way too.
    m_histPlot = newPlot(this, tr("Post-fit residual (ps, two-way)"), tr("Points"));
    m_histPlot->setToolTip(tr("Post-fit residuals of the kept points, ps two-way (1 ps = 0.15 mm one-way)"));
    m_histPlot->setMinimumHeight(110);
    // The shared plot tools (ui/plot_kit.hpp): right-click menu (export PNG/SVG/PDF, copy),
    // box zoom on a right drag, Shift/Ctrl + wheel for one axis, Backspace back, Home, the
    // theme; Home and a double-click are the workspace's own fit of every plot.
    const std::pair<QCustomPlot*, const char*> kits[] = {{m_ocPlot, "slr-oc"}, {m_imagePlot, "slr-binary-image"},
                                                         {m_histPlot, "slr-residuals"}};
    for (const auto& entry : kits) {
        QCustomPlot* plot = entry.first;  // (a structured binding cannot be captured in C++17: clang refuses it)
        const auto& name = entry.second;
        PlotKitOptions o;
        o.home = [this] { resetView(); };
        o.exportName = name;
        o.legendToggle = true;
        o.cursor = CursorMode::External;  // one time cursor for the pass (showTimeCursor)
        PlotKit* kit = installPlotKit(plot, o);
        connect(kit, &PlotKit::hovered, this, [this, plot](QPointF c, QPoint px) { showTimeCursor(plot, c, px); });
        connect(kit, &PlotKit::hoverLeft, this, [this] { clearTimeCursor(); });
    }
    // A useful height whatever the messages above (the legend under each plot takes 4 rows).
    for (QCustomPlot* p : {m_ocPlot, m_imagePlot}) p->setMinimumHeight(270);
    for (QCustomPlot* p : {m_ocPlot, m_imagePlot}) {
        // Legend in a row under the axes, so it never hides the track.
        p->legend->setVisible(true);
        p->legend->setFont(QFont(font().family(), 8));
        p->legend->setIconSize(20, 12);  // (32 × 18 by default) two columns then fit a 1024 px window
        p->legend->setFillOrder(QCPLegend::foColumnsFirst);
        p->legend->setWrap(2);
        p->axisRect()->insetLayout()->take(p->legend);
        p->plotLayout()->addElement(2, 0, p->legend);
        p->plotLayout()->setRowStretchFactor(2, 0.001);
        p->legend->setBorderPen(Qt::NoPen);
        // Two columns where they fit, at 8 pt or 7, else one (the plot kit's fitLegendBelow).
        p->setProperty("lwbLegendBelow", true);
        p->setProperty("lwbLegendColumns", 2);
        p->setProperty("lwbLegendPoints", 8);
    }
    m_imageMap = new QCPColorMap(m_imagePlot->xAxis, m_imagePlot->yAxis);
    m_imageMap->setName(tr("empty"));
    QCPColorGradient g;
    g.clearColorStops();
    // An empty pixel is transparent: the plot's own background shows, white in the light theme
    // and dark in the dark one (issue 42: the binary image stayed white in the dark theme).
    g.setColorStopAt(0.0, QColor(255, 255, 255, 0));
    g.setColorStopAt(0.33, kNoise);
    g.setColorStopAt(0.67, kRecovered);
    g.setColorStopAt(1.0, kSignal);
    g.setLevelCount(4);
    m_imageMap->setGradient(g);
    m_imageMap->setInterpolate(false);
    m_imageMap->setDataRange(QCPRange(0, 3));
    m_imageMap->removeFromLegend();
    m_imageBand = new QCPColorMap(m_imagePlot->xAxis, m_imagePlot->yAxis);
    m_imageBand->setName(QStringLiteral("track band"));
    m_imageBand->setGradient(g);
    m_imageBand->setInterpolate(false);
    m_imageBand->setDataRange(QCPRange(0, 3));
    m_imageBand->removeFromLegend();
    m_imageBand->setVisible(false);
    for (auto [name, color] : {std::pair{tr("noise regions"), kNoise}, std::pair{tr("recovered regions"), kRecovered},
                               std::pair{tr("signal regions"), kSignal}}) {
        // Legend entries only (the colour map itself has none).
        QCPGraph* g2 = m_imagePlot->addGraph();
        g2->setName(name);
        g2->setLineStyle(QCPGraph::lsNone);
        g2->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, color, color, 8));
    }
    // Graph 3: points accepted in a region called noise — taken by the track following (or, on
    // a pass without a noise floor, by its 5σ band) after the image was classified — so that
    // the image shows every accepted point the O-C plot shows.
    {
        QCPGraph* g3 = m_imagePlot->addGraph();
        g3->setLineStyle(QCPGraph::lsNone);
        g3->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(kRecovered, 1.2), Qt::NoBrush, 6));
        g3->removeFromLegend();
    }
}

// The plots' area: the pass list and the plots' tools above them, the histogram and the
// summary below.
QWidget* SlrWorkspace::buildPlotArea() {
    m_passCombo = new QComboBox(this);
    m_passCombo->setMinimumWidth(280);
    // The items are long (start, station, satellite, duration, points, status): the combo does
    // not grow to the longest, its popup shows them whole.
    m_passCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_passCombo->setMinimumContentsLength(28);
    m_passCombo->view()->setMinimumWidth(720);
    m_passCombo->setToolTip(tr("Every pass of the file by start time: station, satellite, UTC start, duration, points, status"));
    auto* all = new QPushButton(tr("Screen all passes…"), this);
    all->setToolTip(tr("Screen every pass of the file in the background: a table of the results, any row opens its pass"));
    // The plots' own tools: main plot, time axis, home, the hover readout.
    auto* tools = new QHBoxLayout;
    m_viewCombo = new QComboBox(this);
    m_viewCombo->addItems({tr("O-C"), tr("Residual (O-C − trend)")});
    m_viewCombo->setToolTip(tr("Main plot: the O-C (ns, two-way), or the residual about the post-fit trend "
                               "(ps two-way, mm one-way on the right axis) where the track's spread is visible"));
    m_sodCheck = new QCheckBox(tr("Seconds of day"), this);
    m_sodCheck->setToolTip(tr("Time axis in seconds since 0h UTC instead of hh:mm:ss"));
    auto* home = new QPushButton(tr("Home"), this);
    home->setToolTip(tr("Fit every plot to its data again (also: double-click a plot)"));
    m_hover = new QLabel(this);
    m_hover->setToolTip(tr("The point nearest the mouse on the main plot: UTC epoch, O-C, residual, class, record index"));
    m_hover->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Two fixed rows, not a row that wraps: a wrapped row's second line is not in the layout's
    // least height, and in a 1024 × 700 window it took the plots' legends (seen under Xvfb).
    // Row 1: the pass; row 2: the view, and the hover readout in the rest of the line (its
    // length changes with the point, the layout must not).
    tools->addWidget(new QLabel(tr("Pass:"), this));
    tools->addWidget(m_passCombo, 1);
    tools->addWidget(all);
    auto* view = new QHBoxLayout;
    view->addWidget(new QLabel(tr("Main plot:"), this));
    view->addWidget(m_viewCombo);
    view->addWidget(m_sodCheck);
    view->addWidget(home);
    view->addSpacing(8);
    view->addWidget(m_hover, 1);
    m_hover->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_hover->setMinimumHeight(m_hover->fontMetrics().height() + 2);
    m_ocPlot->setToolTip(QString());
    auto* plots = new QSplitter(Qt::Horizontal, this);
    plots->addWidget(m_ocPlot);
    plots->addWidget(m_imagePlot);
    plots->setStretchFactor(0, 1);
    plots->setStretchFactor(1, 1);
    plots->setSizes({550, 550});
    auto* vsplit = new QSplitter(Qt::Vertical, this);
    auto* plotBox = new QWidget(this);
    auto* pbl = new QVBoxLayout(plotBox);
    pbl->setContentsMargins(0, 0, 0, 0);
    pbl->addLayout(tools);
    pbl->addLayout(view);
    pbl->addWidget(plots, 1);
    vsplit->addWidget(plotBox);
    auto* bottom = new QWidget(this);
    auto* bl = new QHBoxLayout(bottom);
    bl->setContentsMargins(0, 0, 0, 0);
    // The residual histogram, and the station's normal points beside ours when a file is open.
    m_bottomTabs = new QTabWidget(bottom);
    // Tab names shortened with "…" in a narrow column, never scrolled half out of sight ("gram").
    m_bottomTabs->setElideMode(Qt::ElideRight);
    m_bottomTabs->setUsesScrollButtons(false);
    m_bottomTabs->addTab(m_histPlot, tr("Residual histogram"));
    m_stationNps = new SlrStationNpPanel(bottom);
    m_bottomTabs->addTab(m_stationNps, tr("Station normal points"));
    m_bottomTabs->setTabToolTip(1, tr("Open the station's CRD normal points of the pass: drawn over ours, differences bin by bin"));
    bl->addWidget(m_bottomTabs, 2);
    m_stats = new QLabel(bottom);
    m_stats->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_stats->setTextFormat(Qt::RichText);
    m_stats->setWordWrap(true);  // as wide as the scroll area's viewport (a wider minimum cut it on the right)
    m_stats->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    // In a scroll area: the summary grows (refinement, no noise floor, station flags) and was
    // cut off at the bottom of a 900 px window.
    auto* statsScroll = new QScrollArea(bottom);
    statsScroll->setWidget(m_stats);
    statsScroll->setWidgetResizable(true);
    statsScroll->setFrameShape(QFrame::NoFrame);
    statsScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    statsScroll->setMinimumWidth(300);
    bl->addWidget(statsScroll, 1);
    vsplit->addWidget(bottom);
    vsplit->setStretchFactor(0, 3);
    vsplit->setStretchFactor(1, 1);

    connect(m_passCombo, &QComboBox::activated, this, [this](int i) {
        if (m_loading || !m_controller->crd()) return;
        // (choosing a pass is a view change, not unsaved work: issue 42)
        switchToPass(m_passCombo->itemData(i).toInt());  // a failure is shown in place
    });
    connect(all, &QPushButton::clicked, this, [this] {
        if (!screenAllPasses()) QMessageBox::information(this, tr("Screen all passes"), tr("Open a CRD file first."));
    });
    connect(m_stationNps, &SlrStationNpPanel::openRequested, this, [this] {
        QSettings st;
        const QString path = QFileDialog::getOpenFileName(this, tr("The station's normal points"),
                                                          st.value("paths/slrInputs", st.value("paths/slr")).toString(),
                                                          tr("CRD normal points (*.npt *.np2 *.crd);;All files (*)"));
        if (path.isEmpty()) return;
        st.setValue("paths/slrInputs", QFileInfo(path).absolutePath());
        QString err;
        if (!setStationNormalPoints(path, &err)) QMessageBox::warning(this, tr("Cannot use the file"), err);
    });
    connect(m_stationNps, &SlrStationNpPanel::changed, this, [this] {
        if (!m_stationNps->hasFile()) m_controller->setStationNormalPoints(QString(), nullptr);  // (cleared in the tab)
        if (m_controller->hasRun()) showRun(m_controller->run());
        emit modified();
    });
    connect(home, &QPushButton::clicked, this, &SlrWorkspace::resetView);
    connect(m_viewCombo, qOverload<int>(&QComboBox::activated), this, [this](int i) { setResidualView(i == 1); });
    connect(m_sodCheck, &QCheckBox::toggled, this, &SlrWorkspace::setSecondsOfDay);
    return vsplit;
}

// Right: parameters, the mouse's edit modes, presets and export.
QWidget* SlrWorkspace::buildPanel() {
    auto* panel = new QWidget(this);
    auto* pl = new QVBoxLayout(panel);
    m_params = new SlrParamsPanel(panel);
    pl->addWidget(m_params);
    auto* eg = new QGroupBox(tr("Mouse on the main plot"), panel);
    auto* el = new QVBoxLayout(eg);
    m_modeZoom = new QRadioButton(tr("Pan / zoom"), eg);
    m_modeZoom->setToolTip(tr("Drag pans, the wheel zooms both axes; Shift+wheel zooms time only, Ctrl+wheel O-C only; "
                              "right-drag zooms to a box, Backspace steps back"));
    m_modeBoxZoom = new QRadioButton(tr("Box zoom"), eg);
    m_modeBoxZoom->setToolTip(tr("Drag a box to zoom to it (the linked binary image follows); Home or double-click resets"));
    m_modeIn = new QRadioButton(tr("Box forces points in"), eg);
    m_modeIn->setToolTip(tr("Points in the box are accepted whatever the screening says (undo: Edit ▸ Undo)"));
    m_modeOut = new QRadioButton(tr("Box forces points out"), eg);
    m_modeOut->setToolTip(tr("Points in the box are rejected whatever the screening says (undo: Edit ▸ Undo)"));
    m_modeZoom->setChecked(true);
    auto* modes = new QButtonGroup(this);
    for (QRadioButton* b : {m_modeZoom, m_modeBoxZoom, m_modeIn, m_modeOut}) {
        modes->addButton(b);
        el->addWidget(b);
    }
    auto* er = new QHBoxLayout;
    m_undo = new QPushButton(tr("Undo"), eg);
    m_undo->setToolTip(tr("Undo the last edit or parameter change (the workbench's undo history, Ctrl+Z)"));
    m_clearEdits = new QPushButton(tr("Clear edits"), eg);
    m_clearEdits->setToolTip(tr("Drop every manual edit of the pass (undoable)"));
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
    savePreset->setToolTip(tr("Keep the current parameters (and the scale used) for the passes of this satellite"));
    exCsv->setToolTip(tr("Per point: index, epoch, O-C, class, region, residual, kept, station flag"));
    exCrd->setToolTip(tr("CRD full rate with filter flags 2 (accepted) / 1 (noise): this pass only, or the whole file with this pass's flags set"));
    exNp->setToolTip(tr("The normal points of the pass as a CRD normal-point file"));
    auto* tune = new QPushButton(tr("Tune from this file's passes…"), xg);
    tune->setToolTip(tr("The satellite's parameters chosen from the station's own filter flags (2 data, 1 noise) over "
                        "every pass of the open CRD file; shown before they are applied"));
    connect(tune, &QPushButton::clicked, this, [this] { tuneFromFile(); });
    for (QPushButton* b : {savePreset, tune, exCsv, exCrd, exNp}) xl->addWidget(b);
    pl->addWidget(xg);
    pl->addStretch(1);
    for (QRadioButton* b : {m_modeZoom, m_modeBoxZoom, m_modeIn, m_modeOut})
        connect(b, &QRadioButton::toggled, this, [this] {
            m_ocPlot->setSelectionRectMode(m_modeZoom->isChecked()      ? QCP::srmNone
                                           : m_modeBoxZoom->isChecked() ? QCP::srmZoom
                                                                        : QCP::srmCustom);
        });
    connect(m_undo, &QPushButton::clicked, this, [this] { undoStackOf(this).undo(); });
    connect(m_clearEdits, &QPushButton::clicked, this, [this] {
        pushForced(std::vector<int8_t>(m_controller->forced().size(), 0), tr("Clear SLR edits"));
    });
    connect(savePreset, &QPushButton::clicked, this, [this] {
        QString err;
        if (!m_controller->savePreset(&err)) QMessageBox::warning(this, tr("Preset"), err);
        else emit status(tr("Preset saved for %1 in %2").arg(QString::fromStdString(m_controller->pass().satellite), m_controller->presetFile()));
    });
    auto savePath = [this](const QString& title, const QString& filter) -> QString {
        if (const std::string& damaged = m_controller->pass().damaged; !damaged.empty()) {
            QMessageBox::warning(this, title, QString::fromStdString(damaged));
            return {};
        }
        return askSavePath(this, title, "paths/slrExport", passFileStem(), filter);
    };
    auto exporter = [=](const QString& title, const QString& filter, auto fn) {
        const QString path = savePath(title, filter);
        if (path.isEmpty()) return;
        QString err;
        if (!(m_controller->*fn)(path, &err)) QMessageBox::warning(this, title, err);
        else emit status(tr("Wrote %1").arg(path));
    };
    connect(exCsv, &QPushButton::clicked, this, [=] { exporter(tr("Export points"), tr("CSV (*.csv)"), &SlrController::exportCsv); });
    connect(exCrd, &QPushButton::clicked, this, [=] {
        const QString title = tr("Export CRD full rate");
        // (a simulation or an O-C table has no CRD records to flag: the question read "Pass 0 of
        // 0 passes")
        if (!m_controller->pass().hasCrd) {
            QMessageBox::information(this, title,
                                     tr("This pass is not from a CRD file (%1): there are no CRD records to flag. Export its "
                                        "points as CSV, or its normal points as CRD.")
                                         .arg(m_controller->pass().ocOrigin.empty() ? tr("a simulation")
                                                                                    : QString::fromStdString(m_controller->pass().ocOrigin)));
            return;
        }
        QMessageBox ask(QMessageBox::Question, title, tr("Write which records?"), QMessageBox::Cancel, this);
        ask.setInformativeText(tr("Pass %1 of %2 passes in %3. Its records get filter flag 2 (accepted) or 1 (noise).")
                                   .arg(m_controller->selectedPass() + 1)
                                   .arg(m_controller->passes().size())
                                   .arg(QFileInfo(m_path).fileName()));
        QAbstractButton* one = ask.addButton(tr("This pass only"), QMessageBox::AcceptRole);
        QAbstractButton* whole = ask.addButton(tr("Whole file with this pass's flags set"), QMessageBox::AcceptRole);
        ask.exec();
        if (ask.clickedButton() != one && ask.clickedButton() != whole) return;
        const QString path = savePath(title, tr("CRD (*.frd *.fr2 *.crd)"));
        if (path.isEmpty()) return;
        QString message;
        if (!exportCrd(path, ask.clickedButton() == whole, &message)) QMessageBox::warning(this, title, message);
    });
    connect(exNp, &QPushButton::clicked, this, [=] { exporter(tr("Export normal points"), tr("CRD (*.npt *.np2 *.crd)"), &SlrController::exportNormalPoints); });
    return panel;
}

// The controller's signals, the parameters panel, the plots' links, selection and legends.
void SlrWorkspace::wireController() {
    connect(m_controller, &SlrController::runReady, this, &SlrWorkspace::showRun);
    m_strips = new SlrStrips(m_controller, m_params, this);
    connect(m_controller, &SlrController::runFailed, this,
            [this](const QString& m) { m_stats->setText(tr("<b>Screening failed:</b> %1").arg(m.toHtmlEscaped())); });
    connect(m_controller, &SlrController::status, this, &SlrWorkspace::status);
    connect(m_controller, &SlrController::passListChanged, this, &SlrWorkspace::fillPassList);
    connect(m_controller, &SlrController::editsChanged, this, [this] {
        bool any = false;
        for (int8_t f : m_controller->forced()) any = any || f;
        m_clearEdits->setEnabled(any);
    });
    // (the button is the context: created before the stack, it goes first when the workspace is
    // destroyed, so that the stack's clear() on its own destruction reaches nobody)
    QUndoStack* undo = &undoStackOf(this);
    auto undoState = [this, undo] { m_undo->setEnabled(undo->canUndo()); };
    connect(undo, &QUndoStack::canUndoChanged, m_undo, undoState);
    connect(m_controller, &SlrController::passChanged, this, &SlrWorkspace::showPass);
    // New data: the undo history refers to the pass it was made on (the other workspaces' stay).
    connect(m_controller, &SlrController::passChanged, this, [this] { undoStackOf(this).clear(); });
    connect(m_params, &SlrParamsPanel::paramsChanged, this, [this](const SlrParams& p) {
        const SlrParams before = m_controller->params();
        m_controller->setParams(p);
        if (!m_applyingParams) pushParams(this, before, p);
        emit modified();
    });
    connect(m_ocPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { linkRanges(m_ocPlot, m_imagePlot); });
    connect(m_ocPlot->yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this](const QCPRange& r) {
        m_ocPlot->yAxis2->setRange(r.lower * kMmPerPs, r.upper * kMmPerPs);  // mm one-way beside ps two-way
        linkRanges(m_ocPlot, m_imagePlot);
    });
    connect(m_imagePlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { linkRanges(m_imagePlot, m_ocPlot); });
    connect(m_imagePlot->yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { linkRanges(m_imagePlot, m_ocPlot); });
    connect(m_ocPlot->selectionRect(), &QCPSelectionRect::accepted, this,
            [this](const QRect& r, QMouseEvent*) { boxSelected(r); });
    // The plot kit (buildPlots) zooms, pans, resets on a double-click, exports, and switches a
    // series on and off from its legend entry (by its "series" key, kept across runs).
    // (the hover readout and the time cursor: the plot kit's hovered signal, buildPlots)
}

bool SlrWorkspace::exportCrd(const QString& path, bool wholeFile, QString* message) {
    if (!m_controller->exportCrd(path, message, wholeFile)) {
        emit status(tr("Nothing written: %1").arg(*message));
        return false;
    }
    const PassData& p = m_controller->pass();
    size_t data = 0;
    for (uint8_t a : m_controller->run().accepted) data += a;
    const QString flags = tr("pass %1 (%2, %3): %4 of %5 screened records flagged 2 (data), the rest 1 (noise)")
                              .arg(p.passIndex + 1)
                              .arg(QString::fromStdString(p.satellite), QString::fromStdString(m_controller->passes().empty() ? std::string() : m_controller->passes()[size_t(p.passIndex)].start))
                              .arg(data)
                              .arg(p.t.size());
    *message = wholeFile ? tr("Wrote %1: the whole file (%2 passes), %3; the other passes as read").arg(path).arg(p.crd ? p.crd->passes.size() : size_t(0)).arg(flags)
                         : tr("Wrote %1: this pass only, %2").arg(path, flags);
    emit status(*message);
    return true;
}

void SlrWorkspace::showSourceNames() {
    const QFileInfo cpf(m_cpfPath), snx(m_snxPath);
    m_cpfLabel->setFullText(m_cpfPath.isEmpty() ? tr("no prediction") : cpf.fileName() + (cpf.isDir() ? "/" : ""));
    m_cpfLabel->setPlainToolTip(m_cpfPath.isEmpty() ? tr("The prediction in use: none") : m_cpfPath);
    m_snxLabel->setFullText(m_snxPath.isEmpty() ? tr("no station file") : snx.fileName());
    m_snxLabel->setPlainToolTip(m_snxPath.isEmpty() ? tr("The station coordinates in use: none") : m_snxPath);
    m_cpfClear->setEnabled(!m_cpfPath.isEmpty());
    m_snxClear->setEnabled(!m_snxPath.isEmpty());
}

bool SlrWorkspace::setCpf(const QString& path, QString* error) {
    if (!m_controller->setSources(path, m_snxPath, error)) return false;
    m_cpfPath = path;
    showSourceNames();
    emit modified();
    return true;
}

bool SlrWorkspace::setSinex(const QString& path, QString* error) {
    if (!m_controller->setSources(m_cpfPath, path, error)) return false;
    m_snxPath = path;
    showSourceNames();
    emit modified();
    return true;
}

SlrAllPassesDialog* SlrWorkspace::screenAllPasses() {
    if (!m_controller->crd()) return nullptr;
    if (m_all) m_all->deleteLater();
    m_all = new SlrAllPassesDialog(m_controller, m_controller->presetFile(), this);
    m_all->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_all, &SlrAllPassesDialog::openPass, this, [this](int index) {
        switchToPass(index);  // (a view change: issue 42)
    });
    m_all->show();
    return m_all;
}

SlrFileCheckDialog* SlrWorkspace::checkFile() {
    if (m_path.isEmpty() || !m_controller->crd()) {
        emit failed(tr("CRD file check"), tr("Open a CRD file first: the pass shown is not from one."));
        return nullptr;
    }
    const std::string path = m_path.toStdString();
    bool cancelled = false;
    const core::slr::CrdCheckResult r = runModal<core::slr::CrdCheckResult>(
        this, tr("Checking %1…").arg(QFileInfo(m_path).fileName()),
        [path](const core::Feedback* fb) { return core::slr::checkCrd(path, {}, fb); }, &cancelled);
    if (cancelled) return nullptr;
    if (!r.ok) {
        emit failed(tr("CRD file check"), QString::fromStdString(r.error));
        return nullptr;
    }
    auto* d = new SlrFileCheckDialog(r, m_path, this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
    emit status(QString::fromStdString(core::slr::crdCheckSummary(r, path)));
    return d;
}

QDialog* SlrWorkspace::tuneFromFile() {
    const QString title = tr("Tune from this file's passes");
    if (m_path.isEmpty() || !m_controller->crd()) {
        emit failed(title, tr("Open a CRD file whose filter flags hold the station's decisions (2 data, 1 noise) first."));
        return nullptr;
    }
    return tuneOn(m_path, title);
}

QDialog* SlrWorkspace::tuneFromFolder(QString folder) {
    const QString title = tr("Tune from a folder's passes");
    if (!m_controller->hasPass()) {
        emit failed(title, tr("Open a pass of the satellite to tune first: the folder's passes of that satellite are "
                              "tuned on."));
        return nullptr;
    }
    if (folder.isEmpty())
        folder = QFileDialog::getExistingDirectory(this, tr("A folder of CRD files with the station's flags"),
                                                   QFileInfo(m_path).absolutePath());
    if (folder.isEmpty()) return nullptr;
    return tuneOn(folder, title);
}

QDialog* SlrWorkspace::tuneOn(const QString& input, const QString& title) {
    using namespace core::slr;
    TuneSources src;
    src.files = {input.toStdString()};
    // (on the O-C the open pass is screened on: the workspace's prediction and station file)
    if (!m_snxPath.isEmpty()) {  // (a CPF is used with a SINEX only, as for the open pass)
        src.stations = m_snxPath.toStdString();
        src.cpf = m_cpfPath.toStdString();
        src.cpfFallback = true;
    }
    src.satellite = m_controller->pass().satellite;
    if (QFileInfo::exists(m_controller->presetFile())) src.presets = m_controller->presetFile().toStdString();
    bool cancelled = false;
    const TuneResult r = runModal<TuneResult>(
        this, tr("Tuning on the passes of %1…").arg(QFileInfo(input).fileName()),
        [src](const core::Feedback* fb) { return tuneSlr(src, fb); }, &cancelled);
    if (cancelled) return nullptr;
    if (!r.ok) {
        emit failed(title, QString::fromStdString(r.error.message));
        return nullptr;
    }
    auto* d = new QDialog(this);
    d->setObjectName("slrTuning");
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->setWindowTitle(tr("Parameters from the station's flags: %1").arg(QString::fromStdString(r.satellite)));
    auto* lay = new QVBoxLayout(d);
    const TuneCandidate& best = r.candidates[r.best];
    const auto f1 = [](double v) { return QString::number(v, 'f', 4); };
    QString html = tr("<p>%1 pass(es) of %2 screened with %3 candidates; the station's filter flags are the labels.</p>")
                       .arg(r.passes.size())
                       .arg(QString::fromStdString(r.satellite).toHtmlEscaped())
                       .arg(r.candidates.size());
    if (r.best == 0 && r.notHeldOut != 0)
        html += tr("<p><b>The starting point stays</b>: the best candidate, %1 (mean F1 %2), does not hold out: the choices "
                   "made without each pass in turn score %3 on the passes left out, the starting point %4.</p>")
                    .arg(QString::fromStdString(r.candidates[r.notHeldOut].label).toHtmlEscaped())
                    .arg(f1(r.candidates[r.notHeldOut].meanF1), f1(r.heldOutMeanF1), f1(r.startMeanF1));
    else
        html += r.best == 0 ? tr("<p><b>The starting point stays</b>: no candidate beats it by more than 0.001 without losing "
                                 "more than 0.002 on a pass.</p>")
                            : tr("<p>Chosen: <b>%1</b></p>").arg(QString::fromStdString(best.label).toHtmlEscaped());
    html += QStringLiteral("<table cellpadding='3'><tr><th align='left'>%1</th><th>%2</th><th>%3</th><th>%4</th><th>%5</th></tr>")
                .arg(tr("Pass"), tr("Points (data)"), tr("F1 now"), tr("F1 chosen"), tr("Held out"));
    for (const TunedPass& p : r.passes) {
        // "FILE pass K": the file by its name (within the folder tuned on)
        QString name = QString::fromStdString(p.name);
        const int at = name.lastIndexOf(QLatin1String(" pass "));
        if (at > 0) name = QFileInfo(name.left(at)).fileName() + name.mid(at);
        html += QStringLiteral("<tr><td>%1</td><td align='right'>%2 (%3)</td><td align='right'>%4</td><td align='right'><b>%5</b></td>"
                               "<td align='right'>%6</td></tr>")
                    .arg(name.toHtmlEscaped())
                    .arg(p.points)
                    .arg(p.labelledSignal)
                    .arg(f1(p.scores[0].f1), f1(p.scores[r.best].f1), f1(p.heldOutF1));
    }
    html += QStringLiteral("<tr><td><i>%1</i></td><td></td><td align='right'>%2</td><td align='right'><b>%3</b></td><td align='right'>%4</td></tr></table>")
                .arg(tr("mean"), f1(r.candidates[0].meanF1), f1(best.meanF1), f1(r.heldOutMeanF1));
    html += tr("<p><i>Held out: each pass scored with the choice made without it (leave one pass out).</i></p>");
    // (a folder's files by their names, as in the table)
    const QString folderPrefix = QFileInfo(input).isDir() ? input + (input.endsWith('/') ? "" : "/") : QString();
    for (const std::string& n : r.notes) {
        // (the choice that did not hold out is the headline's already)
        if (r.notHeldOut != 0 && n.rfind("the best candidate (", 0) == 0) continue;
        QString note = QString::fromStdString(n);
        if (!folderPrefix.isEmpty()) note.replace(folderPrefix, QString());
        html += QStringLiteral("<p>%1</p>").arg(note.toHtmlEscaped());
    }
    auto* text = new QLabel(html, d);
    text->setObjectName("tuningText");
    text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    text->setWordWrap(true);  // (a long headline or note ran past the screen's edge, the buttons with it)
    lay->addWidget(text);
    auto* buttons = new QDialogButtonBox(d);
    QPushButton* apply = buttons->addButton(tr("Apply to this pass"), QDialogButtonBox::AcceptRole);
    apply->setObjectName("applyTuning");
    apply->setToolTip(tr("Sets the chosen cosine constant, rejection and band in the parameters (one step: Edit ▸ Undo "
                         "takes it back); Save as this satellite's preset keeps them"));
    buttons->addButton(QDialogButtonBox::Close);
    lay->addWidget(buttons);
    const SlrParams chosen = best.params;
    connect(buttons, &QDialogButtonBox::accepted, d, [this, d, chosen] {
        const SlrParams before = m_controller->params();
        SlrParams after = before;
        after.screen.cosineC = chosen.screen.cosineC;
        after.postfit.rejectSigma = chosen.postfit.rejectSigma;
        after.postfit.takeBand = chosen.postfit.takeBand;
        m_params->setParams(after);
        m_controller->setParams(after);
        pushParams(this, before, after);
        emit modified();
        d->accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, d, &QDialog::reject);
    d->open();
    return d;
}

QList<QAction*> SlrWorkspace::fileOpenActions() {
    auto* a = new QAction(tr("Check the CRD file…"), this);
    a->setObjectName("actionCheckCrd");
    a->setToolTip(tr("Every record of the open CRD file against the CRD format, as laserwb-cli crd check lists them"));
    connect(a, &QAction::triggered, this, [this] { checkFile(); });
    auto* t = new QAction(tr("Tune from this file's passes…"), this);
    t->setObjectName("actionTuneSlr");
    t->setToolTip(tr("The satellite's parameters chosen from the station's own filter flags over every pass of the open "
                     "CRD file, as laserwb-cli slr tune chooses them"));
    connect(t, &QAction::triggered, this, [this] { tuneFromFile(); });
    auto* f = new QAction(tr("Tune from a folder's passes…"), this);
    f->setObjectName("actionTuneSlrFolder");
    f->setToolTip(tr("The open satellite's parameters chosen from the station's own filter flags over every pass of it "
                     "in the CRD files of a folder (a station's archive), as laserwb-cli slr tune FOLDER chooses them"));
    connect(f, &QAction::triggered, this, [this] { tuneFromFolder(); });
    return {a, t, f};
}

bool SlrWorkspace::readPass(const QString& path, int passIndex, const QString& cpf, const QString& sinex, const SlrParams& params,
                            SlrOpening* out, QString* error) {
    PassInputParams in = m_controller->inputParams();
    in.cpfPath = cpf.toStdString();
    in.sinexPath = sinex.toStdString();
    // Read on a worker with progress and Cancel (a 10^6-point pass takes seconds: issue 42);
    // the window keeps painting and takes no input meanwhile.
    bool cancelled = false;
    *out = runModal<SlrOpening>(
        this, tr("Opening %1…").arg(QFileInfo(path).fileName()),
        [path, passIndex, in, params](const core::Feedback* fb) { return SlrController::readForOpen(path, passIndex, in, params, fb); },
        &cancelled);
    m_openCancelled = cancelled;
    if (cancelled) {
        if (error) *error = tr("%1: opening cancelled; the pass shown before stays").arg(path);
        emit status(tr("Opening %1 cancelled").arg(QFileInfo(path).fileName()));
        return false;
    }
    if (!out->read && error) *error = out->error;
    return out->read;
}

bool SlrWorkspace::openPath(const QString& path, int passIndex, QString* error) {
    SlrOpening o;
    // What a session's check read for this file, with these prediction and station files.
    if (m_preparedOpening && m_preparedOpening->path == path && m_preparedOpening->passIndex == passIndex &&
        m_preparedOpening->input.cpfPath == m_cpfPath.toStdString() && m_preparedOpening->input.sinexPath == m_snxPath.toStdString()) {
        o = std::move(*m_preparedOpening);
        m_preparedOpening.reset();
    } else if (!readPass(path, passIndex, m_cpfPath, m_snxPath, m_controller->params(), &o, error)) {
        return false;
    }
    if (!m_controller->adoptOpening(std::move(o), error)) return false;
    m_path = path;
    fillPassList();
    emit modified();
    return true;
}

bool SlrWorkspace::switchToPass(int index) {
    const auto read = m_controller->passReader(index);
    if (!read) return false;
    bool cancelled = false;
    OpenedPass o = runModal<OpenedPass>(this, tr("Opening pass %1…").arg(index + 1), read, &cancelled);
    if (cancelled) {  // the pass shown stays, and the list says so
        fillPassList();
        emit status(tr("Opening pass %1 cancelled").arg(index + 1));
        return false;
    }
    return m_controller->showSelectedPass(index, std::move(o), nullptr);
}

void SlrWorkspace::fillPassList() {
    // Every pass by start time: station, satellite, UTC start, duration, points, status.
    m_loading = true;
    m_passCombo->clear();
    std::vector<PassSummary> passes = m_controller->passes();
    if (passes.empty() && m_controller->hasPass())  // a simulated pass
        m_passCombo->addItem(QString::fromStdString(m_controller->pass().source), 0);
    std::stable_sort(passes.begin(), passes.end(), [](const PassSummary& a, const PassSummary& b) { return a.start < b.start; });
    for (const PassSummary& s : passes) {
        if (s.satellite.empty() && s.start.empty()) {
            m_passCombo->addItem(tr("O-C table, %1 points").arg(s.ranges), s.index);
            continue;
        }
        const QDateTime t0 = QDateTime::fromString(QString::fromStdString(s.start), "yyyy-MM-dd hh:mm:ss"),
                        t1 = QDateTime::fromString(QString::fromStdString(s.end), "yyyy-MM-dd hh:mm:ss");
        const qint64 d = t0.isValid() && t1.isValid() ? t0.secsTo(t1) : -1;
        const QString why = m_controller->passError(s.index);
        // What is known before screening, as laserwb-cli slr --all-passes lists it (core
        // blockStatus): the station's normal points, engineering data, too few records; nothing
        // for a pass to screen (issue 30: passes of 3 and 4 records were listed "ok").
        const BlockStatus b = blockStatus(s);
        const QString status = !why.isEmpty()     ? tr("cannot be processed: %1").arg(why)
                               : !b.status.empty() ? QString::fromStdString(b.status + (b.reason.empty() ? "" : ": " + b.reason))
                                                   : QString();
        QString text = tr("%1. %2 · %3 · %4 · %5 · %6 pts")
                           .arg(s.index + 1)
                           .arg(QString::fromStdString(s.start), QString::fromStdString(s.station), QString::fromStdString(s.satellite))
                           .arg(d >= 0 ? QString("%1:%2").arg(d / 60).arg(d % 60, 2, 10, QChar('0')) : QString("?"))
                           .arg(s.ranges);
        if (!status.isEmpty()) text += " · " + (status.size() > 70 ? status.left(69) + "…" : status);
        m_passCombo->addItem(text, s.index);
        const int i = m_passCombo->count() - 1;
        m_passCombo->setItemData(i, status, Qt::ToolTipRole);
        if (!why.isEmpty()) m_passCombo->setItemData(i, QColor(170, 0, 0), Qt::ForegroundRole);
        else if (!b.status.empty()) m_passCombo->setItemData(i, QColor(120, 120, 120), Qt::ForegroundRole);
    }
    m_passCombo->setCurrentIndex(m_passCombo->findData(m_controller->selectedPass()));
    m_loading = false;
}

// "blits_20120622_2019": the open pass's satellite and UTC start, for the names offered by
// exports (the plots', the points', the CRD files'); "slr_pass" for an O-C table or the demo.
QString SlrWorkspace::passFileStem() const {
    const PassData& p = m_controller->pass();
    const int sel = m_controller->selectedPass();
    QString stem = QString::fromStdString(p.satellite).toLower();
    stem.replace(QRegularExpression("[^a-z0-9]+"), "-");
    if (p.hasCrd && sel >= 0 && size_t(sel) < m_controller->passes().size()) {
        const QString start = QString::fromStdString(m_controller->passes()[size_t(sel)].start);  // yyyy-MM-dd hh:mm:ss
        stem += "_" + QString(start).remove(QRegularExpression("[^0-9]")).left(12).insert(8, '_');
    }
    return stem.isEmpty() || stem == "_" ? QStringLiteral("slr_pass") : stem;
}

void SlrWorkspace::showPass() {
    fillPassList();
    const QString stem = passFileStem();
    for (auto [plot, what] : {std::pair{m_ocPlot, "oc"}, std::pair{m_imagePlot, "binary-image"}, std::pair{m_histPlot, "residuals"}})
        if (PlotKit* kit = plotKit(plot)) kit->setExportName(stem + "_" + what);
    undoStackOf(this).clear();  // commands refer to the pass they were made on
    m_params->setParams(m_controller->params());  // a satellite preset may have come with the pass
    const PassData& p = m_controller->pass();
    m_hover->clear();
    // The station's comparison belongs to the pass shown: until the new pass's first run it
    // says there is nothing of ours yet (it kept the last pass's table).
    if (m_stationNps->hasFile()) m_stationNps->update(p, nullptr);
    if (!m_controller->hasPass()) {
        // A pass that cannot be processed: its reason in place, the plots empty, the list usable.
        for (QCustomPlot* plot : {m_ocPlot, m_histPlot}) plot->clearPlottables();
        for (int g = 0; g < m_imagePlot->graphCount(); ++g) m_imagePlot->graph(g)->data()->clear();
        m_imageMap->data()->clear();
        m_imageBand->data()->clear();
        m_imageBand->setVisible(false);
        m_y.clear();
        m_class.clear();
        m_imgMagT = m_imgMagOc = 0;
        clearTimeCursor();
        m_stats->clear();
        m_info->setText(m_controller->passProblem().isEmpty()
                            ? QString()
                            : tr("<b style=\"color:#b00000\">Pass %1 cannot be processed:</b> %2<br>The other passes of the file can be chosen in the list.")
                                  .arg(m_controller->selectedPass() >= 0 ? QString::number(m_controller->selectedPass() + 1) : QString())
                                  .arg(m_controller->passProblem().toHtmlEscaped().replace("\n", "<br>")));
        for (QCustomPlot* plot : {m_ocPlot, m_imagePlot, m_histPlot}) plot->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    QString text = tr("<b>%1</b> %2 — %3 points, O-C from %4%5")
                       .arg(QString::fromStdString(p.satellite).toHtmlEscaped(),
                            p.ilrsId.empty() ? QString() : "(" + QString::fromStdString(p.ilrsId) + ")")
                       .arg(p.t.size())
                       .arg(QString::fromStdString(p.ocOrigin))
                       .arg(p.station.empty() ? QString() : tr(", station %1").arg(QString::fromStdString(p.station)));
    // The preset the pass was opened with, in view (issue 42: said only in the status bar, which
    // another workspace in front had at that moment; the CLI prints "; preset NAME").
    if (!m_controller->appliedPreset().isEmpty())
        text += tr("; <b>preset %1</b> applied (%2)")
                    .arg(m_controller->appliedPreset().toHtmlEscaped(), QFileInfo(m_controller->presetFile()).fileName().toHtmlEscaped());
    // Why a prediction that was given is not used (another satellite, a span that misses the pass).
    if (!p.ocNote.empty()) text += tr("<br><b style=\"color:#a05000\">Prediction not used:</b> %1").arg(QString::fromStdString(p.ocNote).toHtmlEscaped());
    // What the readers said about the files, in view (not only in the status bar): a damaged
    // record means an incomplete pass, and no export (the CLI refuses such a pass too).
    if (!p.damaged.empty())
        text += tr("<br><b style=\"color:#b00000\">Damaged records: exports are refused.</b> %1")
                    .arg(QString::fromStdString(p.damaged).toHtmlEscaped());
    // What the O-C is relative to when there is no prediction: information, in grey, not among
    // the warnings (issue 42: "no prediction" was listed as a warning reading the files).
    for (const std::string& n : m_controller->notes())
        text += "<br><span style=\"color:#808080\">" + QString::fromStdString(n).toHtmlEscaped() + "</span>";
    // (the prediction's note is said above: not again among the readers' warnings)
    std::vector<std::string> warnings;
    for (const std::string& w : m_controller->warnings())
        if (p.ocNote.empty() || w != p.ocNote) warnings.push_back(w);
    const size_t shown = std::min<size_t>(warnings.size(), 5);
    if (!warnings.empty()) text += tr("<br><b>%n warning(s) reading the files:</b>", nullptr, int(warnings.size()));
    for (size_t i = 0; i < shown; ++i) text += "<br>" + QString::fromStdString(warnings[i]).toHtmlEscaped();
    if (warnings.size() > shown) text += tr("<br>… and %1 more (in the status messages)").arg(warnings.size() - shown);
    m_info->setText(text);
    applyTimeAxis();
    m_ocPlot->setProperty("fresh", true);  // fit the view on the first run of the new pass
}

SlrWorkspace::SimulatedDemo SlrWorkspace::simulatedDemo(int points) {
    using namespace core::sim;
    SlrSimParams p = slrSimPreset(SlrKind::Khz);
    p.points = points;
    p.signalFraction = 0.10;
    p.durationS = 300;
    return {simulateSlrPass(p, 42), p.altitudeKm};
}

void SlrWorkspace::openDemo(int points) {
    const SimulatedDemo demo = simulatedDemo(points);
    const core::sim::SlrSimPass& pass = demo.pass;
    m_path.clear();
    m_passCombo->clear();
    m_passCombo->addItem(tr("Simulated kHz pass (10 % signal)"), 0);
    m_controller->setSimulatedPass(pass.epochS, pass.ocS, pass.tofS, pass.isSignal, tr("Simulated kHz pass"),
                                   demo.altitudeKm);
    // The simulated pass has its own geometry: no prediction or station file of an earlier pass
    // is named beside it (issue 42: the demo kept the previous pass's CPF and SINEX names);
    // cleared once it is in, so that no CRD pass is read again without them.
    QString ignored;
    m_cpfPath.clear();
    m_snxPath.clear();
    m_controller->setSources(QString(), QString(), &ignored);
    showSourceNames();
}

ParamSlider* SlrWorkspace::cosineSlider() const { return m_params->slider("screen.cosine_c"); }
ParamSlider* SlrWorkspace::magOcSlider() const { return m_params->slider("screen.mag_oc"); }
ParamSlider* SlrWorkspace::areaSlider() const { return m_params->slider("screen.area_limit"); }
QCheckBox* SlrWorkspace::autoCheck() const { return m_params->autoCheck(); }

void SlrWorkspace::linkRanges(QCustomPlot* from, QCustomPlot* to) {
    // hh:mm:ss, with milliseconds when zoomed in to seconds.
    for (QCustomPlot* p : {from, to})
        if (auto t = qSharedPointerDynamicCast<QCPAxisTickerTime>(p->xAxis->ticker()))
            t->setTimeFormat(p->xAxis->range().size() < 20 ? "%h:%m:%s.%z" : "%h:%m:%s");
    // Time always follows; the O-C axis only when both plots show the same quantity.
    if (m_linking) return;
    m_linking = true;
    to->xAxis->setRange(from->xAxis->range());
    if (!m_imageFlattened && !m_ocPlot->yAxis2->visible()) to->yAxis->setRange(from->yAxis->range());
    to->replot(QCustomPlot::rpQueuedReplot);
    m_linking = false;
}

void SlrWorkspace::boxSelected(const QRect& rect) {
    if (!m_controller->hasPass() || m_y.size() != int(m_controller->pass().t.size())) return;
    if (!m_modeIn->isChecked() && !m_modeOut->isChecked()) return;
    const double x0 = m_ocPlot->xAxis->pixelToCoord(rect.left()), x1 = m_ocPlot->xAxis->pixelToCoord(rect.right());
    const double y0 = m_ocPlot->yAxis->pixelToCoord(rect.bottom()), y1 = m_ocPlot->yAxis->pixelToCoord(rect.top());
    const PassData& p = m_controller->pass();
    const bool in = m_modeIn->isChecked();
    std::vector<int8_t> after = m_controller->forced();
    int count = 0;
    for (size_t i = 0; i < p.t.size(); ++i) {
        const double y = m_y[int(i)];  // in the units shown (O-C or residual)
        if (p.t[i] >= std::min(x0, x1) && p.t[i] <= std::max(x0, x1) && y >= std::min(y0, y1) && y <= std::max(y0, y1)) {
            after[i] = in ? 1 : -1;
            ++count;
        }
    }
    if (!count) return;
    pushForced(after, in ? tr("Force %n SLR point(s) in", nullptr, count) : tr("Force %n SLR point(s) out", nullptr, count));
    emit status(tr("%1 points forced %2 (Edit ▸ Undo takes it back)").arg(count).arg(in ? tr("in") : tr("out")));
}

void SlrWorkspace::pushForced(const std::vector<int8_t>& after, const QString& text) {
    if (after == m_controller->forced()) return;
    undoStackOf(this).push(new ForcedCommand(m_controller, m_controller->forced(), after, text));
    emit modified();
}

void SlrWorkspace::setBoxMode(BoxMode mode) {
    (mode == BoxMode::Pan ? m_modeZoom : mode == BoxMode::Zoom ? m_modeBoxZoom : mode == BoxMode::ForceIn ? m_modeIn : m_modeOut)
        ->setChecked(true);
}

void SlrWorkspace::setResidualView(bool on) {
    m_residual = on;
    m_viewCombo->setCurrentIndex(on ? 1 : 0);
    if (m_controller->hasRun() && m_controller->hasPass()) showRun(m_controller->run());
}

void SlrWorkspace::setSecondsOfDay(bool on) {
    m_secondsOfDay = on;
    m_sodCheck->setChecked(on);
    applyTimeAxis();
}

void SlrWorkspace::applyTimeAxis() {
    // UTC hh:mm:ss with the date in the title for a CRD pass (epochs are seconds since 0h UTC
    // of the pass day; past midnight the clock starts again at 00:00:00); seconds as given
    // otherwise.
    const PassData& p = m_controller->pass();
    const int sel = m_controller->selectedPass();
    const QString date = p.hasCrd && sel >= 0 && size_t(sel) < m_controller->passes().size()
                             ? QString::fromStdString(m_controller->passes()[size_t(sel)].start).left(10)
                             : QString();
    const bool utc = !date.isEmpty() && !m_secondsOfDay;
    QString label = !p.hasCrd ? tr("Epoch (s)") : utc ? tr("UTC on %1 (hh:mm:ss)").arg(date) : tr("Seconds of day (UTC %1)").arg(date);
    for (QCustomPlot* plot : {m_ocPlot, m_imagePlot}) {
        // (the plot kit's UTC ticker: fractions of a second when zoomed in; the kit sets the
        // tick count the plot's width fits before each replot)
        if (utc) setUtcTimeAxis(plot->xAxis, QDate::fromString(date, Qt::ISODate));
        else plot->xAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
        plot->xAxis->setLabel(label);
        plot->replot(QCustomPlot::rpQueuedReplot);
    }
}

void SlrWorkspace::fitMainPlot() {
    // Fit the view to the points (noise, signal, recovered graphs), not to the trend or markers.
    bool first = true;
    QCPRange keys, values;
    for (int g = 0; g < m_ocPlot->graphCount(); ++g) {
        const QString key = m_ocPlot->graph(g)->property("series").toString();
        const bool residual = m_ocPlot->yAxis2->visible();
        // In the residual view the noise spans the range gate: fit to the track.
        if (key != "signal" && key != "recovered" && key != "band" && (residual || key != "noise")) continue;
        bool found = false;
        const QCPRange kr = m_ocPlot->graph(g)->getKeyRange(found);
        if (!found) continue;
        const QCPRange vr = m_ocPlot->graph(g)->getValueRange(found);
        // Accumulated here, set once below: a series of one point has an empty range, which
        // QCPAxis::setRange ignores, and the union then took in the axis's old range (a pass
        // with one noise point was shown from 00:00 UTC and from 0 to 5 ns).
        if (first) {
            keys = kr;
            values = vr;
            first = false;
        } else {
            keys.expand(kr);
            values.expand(vr);
        }
    }
    if (!first) {
        auto widen = [](QCPRange r, double minHalf) {
            if (r.size() < 2 * minHalf) r = QCPRange(r.center() - minHalf, r.center() + minHalf);
            return r;
        };
        m_ocPlot->xAxis->setRange(widen(keys, 0.5));                                       // s
        m_ocPlot->yAxis->setRange(widen(values, m_ocPlot->yAxis2->visible() ? 1 : 1e-3));  // ps or ns
    } else {
        m_ocPlot->rescaleAxes();
    }
    m_ocPlot->xAxis->scaleRange(1.04);
    m_ocPlot->yAxis->scaleRange(1.08);
    m_ocPlot->replot(QCustomPlot::rpQueuedReplot);
}

void SlrWorkspace::fitImagePlot() {
    // The image in its own O-C frame: fitted to the signal, recovered and followed pixels, so
    // that the axis shows the track in that frame (the noise pixels span the whole range gate).
    bool found = false;
    QCPRange vr;
    for (int g : {1, 2, 3}) {
        bool f = false;
        const QCPRange r = m_imagePlot->graph(g)->getValueRange(f);
        if (!f) continue;
        vr = found ? QCPRange(std::min(vr.lower, r.lower), std::max(vr.upper, r.upper)) : r;
        found = true;
    }
    m_linking = true;
    if (found) {
        // At least a few pixels each side: a flattened track can lie on one pixel row (seen on
        // beaconc_20070511 pass 3, 0.28 ns pixels: the axis spanned ±0.001 ns, the pixel a wall).
        const double magOc = m_controller->hasRun() ? m_controller->run().screen.magOc : 0;
        const double pixelNs = magOc > 0 ? 1e9 / magOc : 0;
        const double pad = std::max({0.25 * vr.size(), 5 * pixelNs, 1e-3});
        m_imagePlot->yAxis->setRange(vr.lower - pad, vr.upper + pad);
    } else {
        m_imagePlot->yAxis->rescale();
    }
    m_linking = false;
    m_imagePlot->replot(QCustomPlot::rpQueuedReplot);
}

void SlrWorkspace::resetView() {
    fitMainPlot();
    linkRanges(m_ocPlot, m_imagePlot);
    if (m_imageFlattened || m_ocPlot->yAxis2->visible()) fitImagePlot();
    m_histPlot->rescaleAxes();
    if (m_histPlot->plottableCount()) m_histPlot->yAxis->setRangeLower(0);
    m_histPlot->replot(QCustomPlot::rpQueuedReplot);
}

// Point i's pixel centre on the binary image drawn (s, ns): drawImage's mapping, of the O-C less
// the track's trend where the kept image was flattened (the run drawn is the controller's: the
// image is drawn again on every run).
QPointF SlrWorkspace::imagePixelOf(size_t i) const {
    const PassData& p = m_controller->pass();
    const ScreenResult& s = m_controller->run().screen;
    const double oc = s.flattenS.size() == p.t.size() ? p.oc[i] - s.flattenS[i] : p.oc[i];
    return QPointF(std::llround(p.t[i] * m_imgMagT) / m_imgMagT, std::llround(oc * m_imgMagOc) / m_imgMagOc * 1e9);
}

int SlrWorkspace::pointNear(const QCustomPlot* plot, const QPointF& pixel) const {
    const PassData& p = m_controller->pass();
    if (!m_controller->hasRun() || m_y.size() != int(p.t.size())) return -1;
    const bool image = plot == m_imagePlot;
    if (image && !(m_imgMagT > 0)) return -1;
    // The nearest point within 10 px.
    double best = 100;
    int k = -1;
    for (int i = 0; i < m_y.size(); ++i) {
        const double x = image ? std::llround(p.t[size_t(i)] * m_imgMagT) / m_imgMagT : p.t[size_t(i)];
        const double dx = plot->xAxis->coordToPixel(x) - pixel.x();
        if (std::fabs(dx) > 10) continue;
        const double dy = plot->yAxis->coordToPixel(image ? imagePixelOf(size_t(i)).y() : m_y[i]) - pixel.y();
        if (dx * dx + dy * dy < best) {
            best = dx * dx + dy * dy;
            k = i;
        }
    }
    return k;
}

void SlrWorkspace::clearTimeCursor() {
    for (QCustomPlot* plot : {m_ocPlot, m_imagePlot, m_histPlot}) plotKit(plot)->clearCursor();
    m_hover->clear();
}

void SlrWorkspace::showTimeCursor(QCustomPlot* source, const QPointF& coords, const QPoint& pixel) {
    const PassData& p = m_controller->pass();
    PlotCursor oc, image, hist;
    if (source == m_histPlot) {
        // No time on the histogram: its own crosshair only.
        hist.hasX = hist.hasY = true;
        hist.x = coords.x();
        hist.y = coords.y();
        hist.text = plotKit(m_histPlot)->readoutAt(coords.x(), coords.y());
        plotKit(m_ocPlot)->clearCursor();
        plotKit(m_imagePlot)->clearCursor();
        plotKit(m_histPlot)->setCursor(hist);
        m_hover->clear();
        return;
    }
    const int k = pointNear(source, pixel);
    // The epoch: the hovered point's, else the mouse's.
    const double t = k >= 0 ? p.t[size_t(k)] : coords.x();
    oc.hasX = image.hasX = true;
    oc.x = image.x = t;
    PlotCursor& own = source == m_ocPlot ? oc : image;
    own.hasY = true;
    own.y = coords.y();
    if (k >= 0) {
        oc.marks = {QPointF(t, m_y[k])};
        if (m_imgMagT > 0) image.marks = {imagePixelOf(size_t(k))};
        const SlrRun& run = m_controller->run();
        if (run.post.ok && size_t(k) < run.post.residuals.size()) {
            hist.hasX = true;
            hist.x = run.post.residuals[size_t(k)] * 1e12;  // the histogram's axis: ps two-way
        }
        // Two short lines over the plot (the hover line above the plots has the rest).
        const double y = source == m_ocPlot ? m_y[k] : imagePixelOf(size_t(k)).y();
        const bool ps = source == m_ocPlot && m_ocPlot->yAxis2->visible();
        own.text = tr("%1 · %2 %3 %4\n%5")
                       .arg(PlotKit::axisText(source->xAxis, t), ps ? tr("residual") : source == m_ocPlot ? tr("O-C") : tr("image"),
                            PlotKit::axisText(source->yAxis, y), ps ? tr("ps") : tr("ns"), tr(m_class[k]));
    } else {
        own.text = plotKit(source)->readoutAt(coords.x(), coords.y());
    }
    plotKit(m_ocPlot)->setCursor(oc);
    plotKit(m_imagePlot)->setCursor(image);
    plotKit(m_histPlot)->setCursor(hist);
    // Elided to the line's width; the whole of it in the tooltip.
    const QString full = k >= 0 ? pointText(k) : QString();
    m_hover->setText(m_hover->fontMetrics().elidedText(full, Qt::ElideRight, std::max(40, m_hover->width())));
    m_hover->setToolTip(full.isEmpty() ? tr("The point nearest the mouse on the O-C plot or the binary image: UTC epoch, O-C, residual, class, record index") : full);
}

QString SlrWorkspace::readoutAt(const QPointF& pixel) const {
    const int k = pointNear(m_ocPlot, pixel);
    return k < 0 ? QString() : pointText(k);
}

QString SlrWorkspace::pointText(int k) const {
    const PassData& p = m_controller->pass();
    const SlrRun& run = m_controller->run();
    const double t = p.t[size_t(k)];
    const double sod = std::fmod(t, 86400.0);
    QString epoch = p.hasCrd ? QString("%1:%2:%3 UTC")
                                   .arg(int(t / 3600), 2, 10, QChar('0'))
                                   .arg(int(sod / 60) % 60, 2, 10, QChar('0'))
                                   .arg(std::fmod(sod, 60.0), 9, 'f', 6, QChar('0'))
                             : QString("%1 s").arg(t, 0, 'f', 6);
    QString text = tr("%1 · O-C %2 ns").arg(epoch).arg(p.oc[size_t(k)] * 1e9, 0, 'f', 3);
    if (run.post.ok)
        text += tr(" · residual %1 ps (%2 mm)").arg(run.post.residuals[size_t(k)] * 1e12, 0, 'f', 1).arg(run.post.residuals[size_t(k)] * 1e12 * kMmPerPs, 0, 'f', 1);
    text += " · " + tr(m_class[k]);
    const auto& forced = m_controller->forced();
    if (size_t(k) < forced.size() && forced[size_t(k)]) text += forced[size_t(k)] > 0 ? tr(" (forced in)") : tr(" (forced out)");
    if (p.stationFlag.size() == p.t.size()) text += tr(" · station flag %1").arg(int(p.stationFlag[size_t(k)]));
    text += p.rangeIndex.size() == p.t.size() ? tr(" · record %1").arg(p.rangeIndex.at(size_t(k))) : tr(" · row %1").arg(k);
    return text;
}

void SlrWorkspace::showRun(const SlrRun& run) {
    const PassData& p = m_controller->pass();
    if (p.t.empty() || run.accepted.size() != p.t.size()) return;
    // The scale used, on the fields left at auto.
    m_params->showScale(scaleChoice(run.screen));
    m_params->showPostfit(run.post);
    clearTimeCursor();  // its point may be another one now
    const bool fresh = m_ocPlot->property("fresh").toBool();
    const QCPRange xr = m_ocPlot->xAxis->range(), yr = m_ocPlot->yAxis->range();
    // The main plot: O-C (ns) or the residual about the post-fit trend (ps two-way), by class.
    const bool residual = m_residual && run.post.ok;
    if (m_stationNps->hasFile()) m_stationNps->update(p, run.post.ok ? &run.post : nullptr);
    drawMainPlot(run, residual);
    drawImage(run);
    if (fresh || residual != m_ocPlot->property("residualShown").toBool()) {
        fitMainPlot();
        if (!fresh) m_ocPlot->xAxis->setRange(xr);  // a switch of view keeps the time span
        m_ocPlot->setProperty("fresh", false);
        m_ocPlot->setProperty("residualShown", residual);
    } else {
        m_ocPlot->xAxis->setRange(xr);
        m_ocPlot->yAxis->setRange(yr);
    }
    linkRanges(m_ocPlot, m_imagePlot);
    if (m_imageFlattened || residual) fitImagePlot();
    drawHistogram(run);
    m_stats->setText(summaryHtml(run));
    m_ocPlot->replot(QCustomPlot::rpQueuedReplot);
    m_imagePlot->replot(QCustomPlot::rpQueuedReplot);
    m_histPlot->replot(QCustomPlot::rpQueuedReplot);
}

// The main plot's series: noise, signal, recovered, rejected, manual edits, the station's flags,
// the trend per segment and the normal points; in O-C (ns) or as residuals (ps).
void SlrWorkspace::drawMainPlot(const SlrRun& run, bool residual) {
    const PassData& p = m_controller->pass();
    m_ocPlot->clearGraphs();
    const size_t n = p.t.size();
    const auto& forced = m_controller->forced();
    m_y.resize(int(n));
    m_class.resize(int(n));
    QVector<double> nx, ny, sx, sy, rx, ry, bx, by, jx, jy, fx, fy, dx, dy;
    for (size_t i = 0; i < n; ++i) {
        const double x = p.t[i], y = residual ? run.post.residuals[i] * 1e12 : p.oc[i] * 1e9;
        m_y[int(i)] = y;
        // The run's class (core: the CSV's), drawn as such; the post-fit's rejections apart.
        const PointClass c = i < run.classes.size() ? run.classes[i] : (run.accepted[i] ? PointClass::Signal : PointClass::Noise);
        if (c == PointClass::Noise) {
            nx << x;
            ny << y;
            m_class[int(i)] = QT_TR_NOOP("noise");
        } else if (run.post.ok && !run.post.kept[i]) {
            jx << x;
            jy << y;
            m_class[int(i)] = QT_TR_NOOP("rejected by the post-fit");
        } else if (c == PointClass::Recovered) {
            rx << x;
            ry << y;
            m_class[int(i)] = QT_TR_NOOP("recovered");
        } else if (c == PointClass::Band) {
            bx << x;
            by << y;
            m_class[int(i)] = QT_TR_NOOP("in the post-fit's band");
        } else {
            sx << x;
            sy << y;
            m_class[int(i)] = QT_TR_NOOP("signal");
        }
        if (i < forced.size() && forced[i]) {
            fx << x;
            fy << y;
        }
        if (p.stationFlag.size() == n && p.stationFlag[i] == 2) {
            dx << x;
            dy << y;
        }
    }
    auto keyed = [](QCPGraph* g, const QString& key) {
        g->setProperty("series", key);  // (the plot kit hides it before the replot when switched off)
        return g;
    };
    if (p.stationFlag.size() == n) {
        // The station's own screening, for comparison: small outline marks drawn first, under the
        // classes and the edits, so that they stay visible.
        QCPGraph* g = keyed(m_ocPlot->addGraph(), "station");
        g->setName(tr("station flag 2 (%1)").arg(dx.size()));
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(QColor(150, 90, 200), 1), Qt::NoBrush, 6));
        fill(g, dx, dy);
    }
    fill(keyed(scatter(m_ocPlot, tr("noise (%1)").arg(nx.size()), kNoise, QCPScatterStyle::ssDisc, 2.5), "noise"), nx, ny);
    fill(keyed(scatter(m_ocPlot, tr("signal (%1)").arg(sx.size()), kSignal, QCPScatterStyle::ssDisc, 3), "signal"), sx, sy);
    fill(keyed(scatter(m_ocPlot, tr("recovered (%1)").arg(rx.size()), kRecovered, QCPScatterStyle::ssDisc, 3.5), "recovered"), rx, ry);
    if (!bx.isEmpty())  // (only when the post-fit's band took points: PostfitParams::takeBand)
        fill(keyed(scatter(m_ocPlot, tr("post-fit band (%1)").arg(bx.size()), kBand, QCPScatterStyle::ssDisc, 3.5), "band"), bx, by);
    fill(keyed(scatter(m_ocPlot, tr("rejected (%1)").arg(jx.size()), kRejected, QCPScatterStyle::ssCross, 5), "rejected"), jx, jy);
    if (!fx.isEmpty()) {
        QCPGraph* g = keyed(scatter(m_ocPlot, tr("manual (%1)").arg(fx.size()), kForced, QCPScatterStyle::ssSquare, 7), "manual");
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(kForced, 1.5), Qt::NoBrush, 7));
        fill(g, fx, fy);
    }
    if (run.post.ok) {
        QVector<double> tx, ty, px, py;
        // The trend per segment, only where it was fitted (a polynomial outside its span means
        // nothing, and the pass is split at gaps): a break between the segments.
        for (const TrendSegment& seg : run.post.segments) {
            for (int k = 0; k <= 100; ++k) {
                const double t = seg.tStart + (seg.tEnd - seg.tStart) * k / 100.0;
                tx << t;
                ty << (residual ? 0.0 : evaluateTrend(run.post, t) * 1e9);
            }
            tx << seg.tEnd;
            ty << qQNaN();
        }
        QCPGraph* trend = keyed(m_ocPlot->addGraph(), "trend");
        const PostfitParams& pp = m_controller->postfitParams();
        trend->setName(residual           ? tr("trend (zero)")
                       : pp.autoDegree ? tr("trend (deg %1, max %2)").arg(run.post.degree).arg(pp.degree)
                                       : tr("trend (degree %1)").arg(run.post.degree));
        trend->setPen(QPen(QColor(60, 60, 60), 1.2));
        trend->setData(tx, ty, true);
        for (const NormalPoint& np : run.post.normalPoints) {
            px << np.epochS;
            py << (residual ? np.meanResidualS * 1e12 : np.ocS * 1e9);
        }
        fill(keyed(scatter(m_ocPlot, tr("normal points (%1)").arg(px.size()), kNormalPoint, QCPScatterStyle::ssDiamond, 8), "np"), px, py);
        // The station's normal points over ours: hollow, larger, another colour.
        const NpComparison& cmp = m_stationNps->comparison();
        if (cmp.ok) {
            QVector<double> qx, qy;
            for (const NpDifference& d : cmp.rows) {
                const double y = residual ? d.stationResidualS * 1e12 : d.stationOcS * 1e9;
                if (d.match == NpDifference::Match::OursOnly || !std::isfinite(y)) continue;
                qx << d.stationT;
                qy << y;
            }
            QCPGraph* g = keyed(m_ocPlot->addGraph(), "stationnp");
            g->setName(tr("station normal points (%1)").arg(qx.size()));
            g->setLineStyle(QCPGraph::lsNone);
            g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(kStationNp, 2), Qt::NoBrush, 12));
            fill(g, qx, qy);
        }
    }
    m_ocPlot->yAxis->setLabel(residual ? tr("O-C − trend (ps, two-way)") : tr("O-C (ns, two-way)"));
    m_ocPlot->yAxis2->setVisible(residual);
    if (auto* title = qobject_cast<QCPTextElement*>(m_ocPlot->plotLayout()->element(0, 0)))
        title->setText(residual ? tr("Residual about the post-fit trend")
                       : m_residual ? tr("O-C (no post-fit, so no residual view: %1)").arg(QString::fromStdString(run.post.error))
                                    : tr("O-C"));
}

// Binary image: the occupied pixels as a colour map in (epoch, O-C) units, so its axes can
// follow the O-C plot. Cells hold 0 empty, 1 noise, 2 recovered, 3 signal; an image larger than
// 2000 × 2000 cells is shown max-pooled (a cell shows the strongest class it covers). After a
// refinement round the kept image is of the O-C less the accepted track's trend
// (ScreenResult::flattenS); it is drawn in that frame, with only the time axis linked.
void SlrWorkspace::drawImage(const SlrRun& run) {
    const PassData& p = m_controller->pass();
    const ScreenResult& s = run.screen;
    const size_t n = p.t.size();
    const bool flattened = s.flattenS.size() == n;
    m_imageFlattened = flattened;
    std::vector<double> imgOc(p.oc);
    if (flattened)
        for (size_t i = 0; i < n; ++i) imgOc[i] -= s.flattenS[i];
    // (each point's pixel centre, which the time cursor rings: imagePixelOf)
    m_imgMagT = s.magT;
    m_imgMagOc = s.magOc;
    // (Short enough for the plot's height in a 1024×700 window.)
    m_imagePlot->yAxis->setLabel(flattened ? tr("O-C − track trend (ns)") : tr("O-C (ns, two-way)"));
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
        // A cell shows the strongest class of the points on it: 1 noise, 2 recovered, 3 signal.
        auto markCell = [&s](QCPColorMap* map, int x, int y, size_t i) {
            const RegionClass rc = s.regionClass[s.pointRegion[i]];
            const double v = rc == RegionClass::Signal ? 3 : rc == RegionClass::Recovered ? 2 : 1;
            if (map->data()->cell(x, y) < v) map->data()->setCell(x, y, v);
        };
        for (size_t i = 0; i < n; ++i) {
            const int x = int((std::llround(p.t[i] * s.magT) - r0) / fr), y = int((std::llround(imgOc[i] * s.magOc) - c0) / fc);
            markCell(m_imageMap, x, y, i);
        }
        m_imageMap->setDataRange(QCPRange(0, 3));
        // Pooled O-C cells (a 1 µs gate at 87 ps pixels: 6 pixels a cell) drew the track's cell
        // half a nanosecond tall and beside the track, at the view fitted to the track (seen on
        // a 100 000-point pass in a real window). The band of O-C pixels around the accepted
        // pixels is drawn again over it, unpooled (pooled only past 2000 pixels).
        m_imageBand->setVisible(false);
        long long s0 = LLONG_MAX, s1 = LLONG_MIN;
        for (size_t i = 0; i < n; ++i)
            if (s.regionClass[s.pointRegion[i]] != RegionClass::Noise) {
                const long long c = std::llround(imgOc[i] * s.magOc);
                s0 = std::min(s0, c);
                s1 = std::max(s1, c);
            }
        if (fc > 1 && s0 <= s1) {
            const long long margin = std::max<long long>(64, s1 - s0);
            const long long b0 = std::max(c0, s0 - margin), b1 = std::min(c1, s1 + margin);
            const long long fb = (b1 - b0 + 1 + 1999) / 2000;
            const int brows = int((b1 - b0 + fb) / fb);
            m_imageBand->data()->setSize(cols, brows);
            m_imageBand->data()->setRange(QCPRange(r0 / s.magT, (r0 + (cols - 1) * fr) / s.magT),
                                          QCPRange(b0 / s.magOc * 1e9, (b0 + (brows - 1) * fb) / s.magOc * 1e9));
            m_imageBand->data()->fill(0);
            // The pooled cells the band covers whole are emptied: the band draws them again,
            // unpooled, and its empty cells are transparent (the theme's background shows, light
            // or dark). Left filled they showed through the band (seen in a real window once
            // empty cells became transparent for the dark theme: the track a block 1.2 ns tall).
            const double bandLo = double(b0) - 0.5 * double(fb), bandHi = double(b0 + (brows - 1) * fb) + 0.5 * double(fb);
            for (int y = 0; y < rows; ++y) {
                const double lo = double(c0 + y * fc) - 0.5 * double(fc);
                if (lo >= bandLo && lo + double(fc) <= bandHi)
                    for (int x = 0; x < cols; ++x) m_imageMap->data()->setCell(x, y, 0);
            }
            for (size_t i = 0; i < n; ++i) {
                const long long c = std::llround(imgOc[i] * s.magOc);
                if (c < b0 || c > b1) continue;
                markCell(m_imageBand, int((std::llround(p.t[i] * s.magT) - r0) / fr), int((c - b0) / fb), i);
            }
            m_imageBand->setVisible(true);
        }
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
        QVector<double> ox, oy;
        for (size_t i = 0; i < n; ++i)
            if (s.pointClass[i] != PointClass::Noise && s.regionClass[s.pointRegion[i]] == RegionClass::Noise) {
                ox << std::llround(p.t[i] * s.magT) / s.magT;
                oy << std::llround(imgOc[i] * s.magOc) / s.magOc * 1e9;
            }
        QCPGraph* off = m_imagePlot->graph(3);
        off->setData(ox, oy);
        off->setName(s.floorless ? tr("5σ band (%1)").arg(ox.size()) : tr("followed (%1)").arg(ox.size()));
        if (ox.isEmpty()) off->removeFromLegend();
        else off->addToLegend();
    }
}

// Residual histogram of the kept points.
void SlrWorkspace::drawHistogram(const SlrRun& run) {
    m_histPlot->clearPlottables();
    const size_t n = m_controller->pass().t.size();
    std::vector<double> res;
    if (run.post.ok)
        for (size_t i = 0; i < n; ++i)
            if (run.post.kept[i]) res.push_back(run.post.residuals[i] * 1e12);
    // Nothing kept: empty axes of their own and the reason on them, not the last pass's bars'
    // axes (issue 42: after nothing was accepted the histogram kept its old axis).
    if (!m_histEmpty) {
        m_histEmpty = new QCPItemText(m_histPlot);
        m_histEmpty->position->setType(QCPItemPosition::ptAxisRectRatio);
        m_histEmpty->position->setCoords(0.5, 0.5);
        m_histEmpty->setObjectName("histogramEmpty");
    }
    m_histEmpty->setVisible(res.empty());
    if (res.empty()) {
        m_histEmpty->setText(run.post.ok ? tr("No point kept by the post-fit")
                                         : tr("No post-fit residuals: %1").arg(QString::fromStdString(run.post.error).left(60)));
        m_histPlot->xAxis->setRange(-100, 100);
        m_histPlot->yAxis->setRange(0, 1);
    }
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
}

// The summary beside the histogram: accepted, RMS, normal points or why none, the scale, the
// refinement, the regions, the agreement with the truth or the station's flags, the warnings.
QString SlrWorkspace::summaryHtml(const SlrRun& run) const {
    const PassData& p = m_controller->pass();
    const ScreenResult& s = run.screen;
    const size_t n = p.t.size();
    const bool flattened = s.flattenS.size() == n;
    QString statsHtml;
    if (run.post.ok) {
        const ResidualStats& st = run.post.stats;
        statsHtml += tr("<b>Accepted</b> %1 of %2 (signal %3, recovered %4), post-fit kept %5, rejected %6<br>"
                        "<b>RMS</b> %7 ps (%8 mm one-way) · skew %9 · kurtosis %10 · peak−mean %11 ps<br>")
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
                         .arg(st.peakMinusMean * 1e12, 0, 'f', 1);
        if (run.bandTaken > 0)
            statsHtml += tr("%1 more points within the post-fit's band (where the image stopped)<br>").arg(run.bandTaken);
        if (std::isfinite(run.post.noiseBandS))
            statsHtml += tr("Band narrowed by the noise beside it: ±%1 ps = %2 σ of the signal's %3 ps (best expected F1)<br>")
                             .arg(run.post.noiseBandS * 1e12, 0, 'f', 1)
                             .arg(run.post.noiseBandS / run.post.signalSigmaS, 0, 'f', 2)
                             .arg(run.post.signalSigmaS * 1e12, 0, 'f', 1);
        if (run.postNote.empty()) {
            statsHtml += tr("<b>Normal points</b> %1 (bins of %2 s)").arg(run.post.normalPoints.size()).arg(run.post.binLengthS, 0, 'f', 0);
        } else if (!run.post.normalPoints.empty() && run.doubt.empty()) {
            // Normal points formed, with a note (some dropped as standing below the noise beside
            // them): the note under the count, not a "no normal points" heading over it.
            statsHtml += tr("<b>Normal points</b> %1 (bins of %2 s)").arg(run.post.normalPoints.size()).arg(run.post.binLengthS, 0, 'f', 0) +
                         tr("<br>(%1)").arg(QString::fromStdString(run.postNote).toHtmlEscaped());
        } else {
            const QString prefix = QStringLiteral("no normal points: ");  // the heading says it already
            QString why = QString::fromStdString(run.postNote);
            if (why.startsWith(prefix)) why = why.mid(prefix.size());
            // A doubtful result (core judgeRun, as the CLI's exit 3) in the warning colour, with
            // its doubt first: a ghost track on a pass whose normal points were off anyway (no
            // altitude) was shown with the altitude as its only reason.
            const QString doubt = QString::fromStdString(run.doubt);
            if (doubt.isEmpty())
                statsHtml += tr("<b>No normal points</b>: %1").arg(why.toHtmlEscaped());
            else
                statsHtml += tr("<b><span style='color:#c05000'>Doubtful, no normal points</span></b>: %1").arg(doubt.toHtmlEscaped()) +
                             (why == doubt ? QString() : tr("<br>(also: %1)").arg(why.toHtmlEscaped()));
        }
    } else {
        // A doubtful pass with no post-fit (nothing accepted, or too few points on its own TOF
        // trend) says so first, as the CLI's exit 3 does.
        if (!run.doubt.empty())
            statsHtml += tr("<b><span style='color:#c05000'>Doubtful, no normal points</span></b>: %1<br>")
                             .arg(QString::fromStdString(run.doubt).toHtmlEscaped());
        statsHtml += tr("<b>Post-fit:</b> %1<br>").arg(QString::fromStdString(run.post.error).toHtmlEscaped());
    }
    if (run.bias.ok)  // the station's check against the prediction (core passBias, as the CLI prints it)
        statsHtml += tr("<br><b>Against the prediction</b>: %1").arg(QString::fromStdString(describeBias(run.bias)).toHtmlEscaped());
    statsHtml += tr("<br><b>Scale</b> mag_T %1 px/s, mag_OC %2 px/s, area ≥ %3 px, %4-connectivity%5 · C %6")
                     .arg(s.magT, 0, 'g', 4)
                     .arg(s.magOc, 0, 'g', 4)
                     .arg(s.areaLimit)
                     .arg(s.connectivity)
                     .arg(m_controller->screenParams().automatic
                              ? (m_controller->scaleReused() ? tr(" (automatic, kept while C moves)") : tr(" (automatic)"))
                              : QString())
                     .arg(m_controller->screenParams().cosineC, 0, 'f', 3);
    if (flattened) {
        // The panel's greyed fields show the search's scale (where unticking Automatic starts);
        // the line above is the last round's: both said, so that the two numbers do not differ
        // unexplained (0.0764 in the field, 0.054 here on STELLA).
        const ScaleChoice base = scaleChoice(s);
        statsHtml += tr("<br>Refined: screened again on the O-C less the accepted track's trend (%1 round(s); the "
                        "search's scale, in the panel: mag_T %2 px/s, mag_OC %3 px/s)")
                         .arg(s.refinedRounds)
                         .arg(base.magT, 0, 'g', 4)
                         .arg(base.magOc, 0, 'g', 4);
    }
    statsHtml += tr("<br>%1 regions, %2 candidates, %3 on the line, %4 recovered · %5 ms")
                     .arg(s.regionCount)
                     .arg(s.candidates)
                     .arg(s.linearRegions)
                     .arg(s.recoveredRegions)
                     .arg(s.totalMs, 0, 'f', 0);
    if (s.floorless)
        statsHtml += tr("<br><b>No noise floor</b>: a filtered pass (σ %1 ps); +%2 within 5σ")
                         .arg(s.floorSigmaS * 1e12, 0, 'f', 1)
                         .arg(s.floorlessAdded);
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
                         .arg(tp + fp ? QString::number(double(tp) / (tp + fp), 'f', 3) : tr("undefined (nothing accepted)"))
                         .arg(tp + fn ? double(tp) / (tp + fn) : 0, 0, 'f', 3);
    }
    for (const auto& w : s.warnings) statsHtml += "<br><i>" + QString::fromStdString(w).toHtmlEscaped() + "</i>";
    return statsHtml;
}

QJsonObject SlrWorkspace::saveState() const {
    QJsonObject o;
    o["path"] = m_path;
    o["cpf"] = m_cpfPath;
    o["sinex"] = m_snxPath;
    o["pass"] = m_controller->pass().passIndex;
    o["demo"] = m_path.isEmpty() && m_controller->hasPass();
    o["main_plot"] = m_residual ? "residual" : "oc";
    if (m_stationNps->hasFile()) o["station_npt"] = m_stationNps->path();
    // The schema's JSON: its sections, every field.
    const QJsonObject params = toQtJson(slrSchema().toJson(m_controller->params()));
    for (auto it = params.begin(); it != params.end(); ++it) o[it.key()] = it.value();
    QJsonArray forced;
    const auto& f = m_controller->forced();
    for (size_t i = 0; i < f.size(); ++i)
        if (f[i]) forced.append(QJsonArray{qint64(i), int(f[i])});
    o["forced"] = forced;
    return o;
}

bool SlrWorkspace::readState(const QJsonObject& o, QString* error, const core::JsonParseResult* doc,
                             const std::vector<std::string>& at, StatePhase phase) {
    // The parameters' sections (oc, screen, postfit): the first parts of the schema's keys.
    std::vector<std::string> sections;
    for (const auto& f : slrSchema().fields()) {
        const std::string section = f.key.substr(0, f.key.find('.'));
        if (std::find(sections.begin(), sections.end(), section) == sections.end()) sections.push_back(section);
    }
    std::vector<std::string> known{"path", "cpf", "sinex", "pass", "demo", "forced", "main_plot", "station_npt"};
    known.insert(known.end(), sections.begin(), sections.end());
    if (!checkSessionKeys(o, known, "slr", error, doc, at)) return false;
    // Every parameter from the session over the defaults (the sections the schema writes).
    core::Json j = core::Json::object();
    for (const std::string& section : sections)
        if (o.contains(QString::fromStdString(section))) j[section] = fromQtJson(o[QString::fromStdString(section)]);
    SlrParams params;
    std::string err;
    if (!slrSchema().fromJson(j, &params, &err, doc, at)) {
        *error = QString::fromStdString(err);
        return false;
    }
    const QString mainPlot = o["main_plot"].toString("oc");
    if (mainPlot != "oc" && mainPlot != "residual") {
        *error = tr("slr.main_plot: \"%1\" is neither \"oc\" nor \"residual\"").arg(mainPlot);
        return false;
    }
    if (phase == StatePhase::Check) return true;  // (nothing above changes the workspace)
    if (phase == StatePhase::Prepare) return prepareInputs(o, params, error);
    m_residual = mainPlot == "residual";
    m_viewCombo->setCurrentIndex(m_residual ? 1 : 0);
    m_cpfPath = o["cpf"].toString();
    m_snxPath = o["sinex"].toString();
    showSourceNames();
    const QString path = o["path"].toString();
    if (!path.isEmpty()) {
        if (!openPath(path, o["pass"].toInt(-1), error)) return false;
    } else if (o["demo"].toBool()) {
        openDemo();
    }
    // A session written before every field was saved has no altitude: the pass's stays.
    if (!o["postfit"].toObject().contains("altitude_km")) params.postfit.altitudeKm = m_controller->params().postfit.altitudeKm;
    m_controller->setParams(params);
    std::vector<uint32_t> in, out;
    if (!readForcedEdits(o["forced"].toArray(), m_controller->pass().t.size(), &in, &out, error)) return false;
    m_controller->forcePoints(in, true);
    m_controller->forcePoints(out, false);
    m_params->setParams(m_controller->params());
    if (const QString npt = o["station_npt"].toString(); npt != m_stationNps->path() && !setStationNormalPoints(npt, error))
        return false;
    return true;
}

bool SlrWorkspace::readForcedEdits(const QJsonArray& forced, size_t points, std::vector<uint32_t>* in, std::vector<uint32_t>* out,
                                   QString* error) {
    for (const auto& v : forced) {
        const QJsonArray a = v.toArray();
        const qint64 i = a.at(0).toInteger(-1);
        if (i < 0 || size_t(i) >= points) {
            *error = tr("SLR manual edit of point %1: the pass has %2 points").arg(i).arg(points);
            return false;
        }
        (a.at(1).toInt() > 0 ? in : out)->push_back(uint32_t(i));
    }
    return true;
}

bool SlrWorkspace::prepareInputs(const QJsonObject& o, const SlrParams& params, QString* error) {
    // The pass read (and kept for the restore), as openPath reads it, with the session's oc.*
    // rows (its O-C is made when it is read: with the window's, setting the session's afterwards
    // read it again).
    const QString path = o["path"].toString();
    if (!path.isEmpty()) {
        SlrOpening read;
        if (!readPass(path, o["pass"].toInt(-1), o["cpf"].toString(), o["sinex"].toString(), params, &read, error)) return false;
        m_preparedOpening = std::move(read);
    }
    // The manual edits against the points of the pass they will be made on: the one read, the
    // demo's, or the one open.
    const QJsonArray forced = o["forced"].toArray();
    if (!forced.isEmpty()) {
        size_t points = m_controller->pass().t.size();
        if (m_preparedOpening)
            points = m_preparedOpening->opened.ok && m_preparedOpening->opened.pass ? m_preparedOpening->opened.pass->t.size() : 0;
        else if (o["demo"].toBool())
            points = simulatedDemo(kDemoPoints).pass.epochS.size();
        std::vector<uint32_t> in, out;
        if (!readForcedEdits(forced, points, &in, &out, error)) return false;
    }
    // The station's normal points, read as setStationNormalPoints reads them.
    if (const QString npt = o["station_npt"].toString(); !npt.isEmpty() && npt != m_stationNps->path()) {
        core::slr::SlrSetup scratch;
        SlrError e;
        if (!core::slr::setStationNormalPoints(&scratch, QFileInfo(npt).absoluteFilePath().toStdString(), &e)) {
            *error = QString::fromStdString(e.message);
            return false;
        }
    }
    return true;
}

void SlrWorkspace::dropPrepared() { m_preparedOpening.reset(); }

bool SlrWorkspace::setStationNormalPoints(const QString& path, QString* error) {
    // Read into the run's set-up by the core: the tab, the report and the copied command use it.
    if (!m_controller->setStationNormalPoints(path, error)) return false;
    m_stationNps->show(m_controller->setup().stationNormalPoints, path);
    if (!path.isEmpty()) m_bottomTabs->setCurrentWidget(m_stationNps);
    if (m_controller->hasRun()) showRun(m_controller->run());
    else m_stationNps->update(m_controller->pass(), nullptr);
    emit modified();
    return true;
}

void SlrWorkspace::choosePass() {
    QSettings st;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a ranging pass"), st.value("paths/slr").toString(),
                                                      tr("CRD and O-C tables (*.frd *.fr2 *.npt *.np2 *.crd *.csv);;All files (*)"));
    if (path.isEmpty()) return;
    st.setValue("paths/slr", QFileInfo(path).absolutePath());
    // Through the window when there is one: it asks about this workspace's unsaved work and
    // leaves the other workspaces' alone (issue 42), as for a file opened from its menu.
    if (receivers(SIGNAL(openRequested(QStringList))) > 0) {
        emit openRequested({path});
        return;
    }
    QString err;
    if (!openPath(path, -1, &err)) QMessageBox::warning(this, tr("Cannot open the file"), err);
}

QString SlrWorkspace::claim(const InputProbe& probe, bool) const {
    static const QStringList crd = {"frd", "fr2", "npt", "np2", "crd", "v2c", "qlk"};
    static const QStringList notRanging = {"json", "png", "tif", "tiff", "pgm", "raw", "bin"};
    if (probe.isDir || (notRanging.contains(probe.suffix) && !probe.gz)) return QString();
    // A prediction or station coordinates go with the pass (by their first record or name).
    if (probe.head.startsWith("h1 cpf") || probe.suffix == "cpf" || probe.suffix == "hts") return QStringLiteral("slr-cpf");
    if (probe.head.startsWith("%=snx") || probe.suffix == "snx") return QStringLiteral("slr-sinex");
    // A station's normal points (.npt, .np2) go beside the pass they were formed from.
    if (probe.suffix == "npt" || probe.suffix == "np2") return QStringLiteral("slr-npt");
    if (crd.contains(probe.suffix)) return key();
    if (probe.suffix == "csv" || probe.suffix == "txt")
        return probe.head.contains("oc_s") || probe.head.contains("epoch_s") ? key() : QString();
    if (notRanging.contains(probe.suffix)) return QString();
    // No or another ending: a CRD file is told by its first record.
    return probe.head.startsWith("h1 ") || probe.head.startsWith("h1\t") ? key() : QString();
}

OpenOutcome SlrWorkspace::openInputs(const QMap<QString, QStringList>& byRole, int pass) {
    OpenOutcome out;
    for (const QString& p : byRole.value(key())) {
        QString err;
        if (!openPath(p, pass, &err)) {
            if (!m_openCancelled) out.problems << err;  // (a Cancel is the analyst's choice: said in the status line)
            continue;
        }
        out.opened = out.replaced = true;
        out.recentPath = p;
        out.recentPass = m_controller->pass().passIndex;
    }
    // A station's normal points: compared with the open pass (Station normal points tab); with no
    // pass open there is nothing to compare them with (a normal-point file is not screened).
    const QStringList npt = byRole.value(QStringLiteral("slr-npt"));
    if (npt.size() > 1) {
        out.problems << tr("%1 and %2: one station normal-point file at a time").arg(npt.at(0), npt.at(1));
    } else if (npt.size() == 1 && !m_controller->hasPass()) {
        out.problems << tr("%1: a station's normal points are compared with the full-rate pass they were formed from, "
                           "and no pass is open: open the pass and this file together, or this file in the Station normal "
                           "points tab of the open pass")
                            .arg(npt.first());
    } else if (npt.size() == 1) {
        QString err;
        if (!setStationNormalPoints(npt.first(), &err)) out.problems << err;
        else out.opened = true;
    }
    for (const bool cpf : {false, true}) {
        const QStringList list = byRole.value(cpf ? QStringLiteral("slr-cpf") : QStringLiteral("slr-sinex"));
        if (list.size() > 1) {
            out.problems << tr("%1 and %2: one %3 at a time").arg(list.at(0), list.at(1), cpf ? tr("prediction") : tr("station file"));
            continue;
        }
        if (list.isEmpty()) continue;
        QString err;
        if (!(cpf ? setCpf(list.first(), &err) : setSinex(list.first(), &err))) out.problems << err;
        else out.opened = true;
    }
    return out;
}

QList<QAction*> SlrWorkspace::openActions() {
    auto* a = new QAction(tr("CRD file or O-C table…"), this);
    connect(a, &QAction::triggered, this, &SlrWorkspace::choosePass);
    return {a};
}

QStringList SlrWorkspace::shortcutNotes() const {
    return {tr("Hover\tSLR ▸ one time cursor on the O-C plot, the binary image and the histogram")};
}

// The run in front as the CLI or Python names it: its files as absolute paths, its pass, its
// resolved parameters; *note says what neither carries (manual edits).
QString SlrWorkspace::commandLine(QString* note) const {
    if (!m_controller->hasRun() || m_path.isEmpty()) return QString();  // (the demo's pass is simulated: no file)
    const core::slr::PassData& p = m_controller->pass();
    // The run's own sources (absolute paths: the controller's set-up), as the report names them.
    const auto args = core::slr::slrCommandArgs(m_controller->setup().sources, p.hasCrd ? p.passIndex + 1 : 0,
                                                core::slr::commandParams(m_controller->setup(), p, m_controller->settings().params));
    if (note) *note = editsNote();
    return QStringLiteral("laserwb-cli ") + QString::fromStdString(core::slr::shellCommand(args));
}

QString SlrWorkspace::pythonScript(QString* note) const {
    if (!m_controller->hasRun() || m_path.isEmpty()) return QString();
    const core::slr::PassData& p = m_controller->pass();
    // A prediction the pass did not use (another satellite or day: the TOF trend instead, with a
    // note) is left out: load_pass would refuse it where the workbench fell back.
    const bool cpfUsed = !m_cpfPath.isEmpty() && p.ocNote.empty();
    QString edits = editsNote();
    if (!m_cpfPath.isEmpty() && !cpfUsed)
        edits += (edits.isEmpty() ? QString() : QStringLiteral("; ")) + tr("the prediction, which this pass did not use, is left out");
    if (note) *note = edits;
    return QString::fromStdString(core::slr::slrPythonScript(m_controller->setup().sources, p.hasCrd ? p.passIndex + 1 : 0,
                                                             core::slr::commandParams(m_controller->setup(), p, m_controller->settings().params),
                                                             cpfUsed));
}

QString SlrWorkspace::editsNote() const {
    long long edits = 0;
    for (int8_t f : m_controller->forced()) edits += f != 0;
    return edits ? tr("%n point(s) forced in or out by hand are not in the command", nullptr, int(edits)) : QString();
}

QString SlrWorkspace::reportName() const {
    if (!m_controller->hasRun()) return QString();
    const core::slr::PassData& p = m_controller->pass();
    QString base = m_path.isEmpty() ? QStringLiteral("demo") : QFileInfo(m_path).completeBaseName();
    if (p.hasCrd) base += QStringLiteral("_pass%1").arg(p.passIndex + 1);
    return base + QStringLiteral("_report.pdf");
}

bool SlrWorkspace::writeReport(const QString& path, QString* error) const { return m_controller->exportReport(path, error); }

}  // namespace lwb::ui
