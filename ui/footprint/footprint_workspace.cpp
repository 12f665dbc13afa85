#include "ui/footprint/footprint_workspace.hpp"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPainterPath>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QSplitter>
#include <QFileDialog>
#include <QSettings>
#include <QTabWidget>
#include <QTableView>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <qcustomplot.h>

#include "core/common/json.hpp"
#include "core/footprint/image_io.hpp"
#include "ui/kit/save_path.hpp"
#include "ui/kit/app_undo.hpp"
#include "ui/footprint/blink_view.hpp"
#include "ui/kit/contrast_bias.hpp"
#include "ui/kit/image_regions.hpp"
#include "ui/kit/param_slider.hpp"
#include "ui/kit/params_command.hpp"
#include "ui/kit/schema_form.hpp"
#include "ui/kit/color_maps.hpp"
#include "ui/footprint/column_plot.hpp"
#include "ui/footprint/filter_field.hpp"
#include "ui/footprint/shot_columns.hpp"
#include "ui/footprint/contact_sheet.hpp"
#include "ui/footprint/demo.hpp"
#include "ui/kit/display_controls.hpp"
#include "ui/footprint/footprint_export.hpp"
#include "ui/footprint/footprint_params_panel.hpp"
#include "ui/kit/image_view.hpp"
#include "ui/kit/plot_kit.hpp"
#include "ui/footprint/review_commands.hpp"
#include "ui/kit/session_json.hpp"
#include "ui/footprint/shot_table_model.hpp"
#include "ui/kit/workspace_layout.hpp"

namespace lwb::ui {

using namespace core::footprint;

namespace {
const QColor kGaussColor(0, 220, 255);
const QColor kTefmColor(255, 165, 0);
const QColor kGcmColor(255, 64, 255);
const QColor kDomainColor(255, 255, 255, 200);
const char* kReadoutHint = QT_TRANSLATE_NOOP("lwb::ui::FootprintWorkspace", "Move the cursor over the ROI for pixel values");

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

// A trend plot. At 1024x700 each of the three is about 170 px high: the y label is short (the
// long one, "Pointing change (arcsec)", was longer than the axis and clipped), the month label is
// on the bottom plot only (monthLabel), and the legend is one row (one entry per camera and beam,
// toggling its shots and its mean together). `what` is the tooltip and the export name.
QCustomPlot* makePlot(const QString& yLabel, const QString& what, const QString& exportName, bool monthLabel,
                      QWidget* parent) {
    auto* plot = new QCustomPlot(parent);
    plot->setMinimumHeight(150);
    auto ticker = QSharedPointer<QCPAxisTickerDateTime>(new QCPAxisTickerDateTime);
    ticker->setDateTimeFormat("yyyy-MM");
    ticker->setDateTimeSpec(Qt::UTC);
    plot->xAxis->setTicker(ticker);
    if (monthLabel) plot->xAxis->setLabel(QObject::tr("Month (UTC)"));
    plot->yAxis->setLabel(yLabel);
    plot->setToolTip(what);
    // The one legend style (plot kit): a row under the axis rect, so it never covers the first
    // months; two columns, so the window stays usable at 1024 px (four made the page 1294 px wide).
    plot->legend->setFont(QFont(plot->font().family(), 8));
    legendBelow(plot, 2);
    plot->legend->setRowSpacing(0);
    plot->legend->setMargins(QMargins(4, 0, 4, 0));  // one short row: the axis keeps the height
    PlotKitOptions o;
    o.exportName = exportName;
    installPlotKit(plot, o);  // box/axis zoom, reset, export, legend toggle
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

FootprintWorkspace::FootprintWorkspace(QWidget* parent) : Workspace(parent) {
    m_controller = new FootprintController(this);
    m_model = new ShotTableModel(m_controller, this);
    m_proxy = new ShotFilterProxy(this);
    m_proxy->setSourceModel(m_model);
    m_proxy->setSortRole(ShotTableModel::SortRole);

    QWidget* left = buildShotList();
    buildCentre();
    // Right: parameters.
    m_panel = new FootprintParamsPanel(this);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_panel);
    scroll->setWidgetResizable(true);
    fitPanelWidth(scroll);  // as wide as the panel needs: nothing cut off, no sideways scrolling

    // The shot list and the parameters in docks either side of the views (ui/workspace_layout).
    DockPanel shots, params;
    shots.widget = left;
    shots.id = "shots";
    shots.title = tr("Shots");
    shots.area = Qt::LeftDockWidgetArea;
    shots.width = 470;
    params.widget = scroll;
    params.id = "parameters";
    params.title = tr("Parameters");
    params.area = Qt::RightDockWidgetArea;
    params.width = 340;
    dockPanels(this, QStringLiteral("footprint"), m_tabs, {shots, params});

    wireController();
    // "Suggest thresholds": the core's tuning task on the shots with a manual verdict.
    m_tuneJob = new TaskJob<core::footprint::VerdictTuneTask>(this);
    m_tuneJob->bind(
        [this](TaskJob<core::footprint::VerdictTuneTask>::Run* run) {
            if (!m_tuneInputs) return false;
            run->inputs = m_tuneInputs;
            run->params = m_controller->params();
            return true;
        },
        [this](core::footprint::VerdictTuneResult r) {
            emit progress(0, 0, QString());
            showSuggestion(r, m_tuneInputs ? int(m_tuneInputs->shots.size()) : 0);
        });
    connect(m_tuneJob, &LiveJob::progress, this,
            [this](double f) { emit progress(int(f * 1000), 1000, tr("Suggesting thresholds %p%")); });
    connect(m_tuneJob, &LiveJob::idle, this, [this] { emit progress(0, 0, QString()); });
    connect(m_tuneJob, &LiveJob::failed, this, [this](const QString& why) { emit failed(tr("No threshold suggestion"), why); });
    // The strips beside the verdict sliders: again after every rejudge and verdict edit (300 ms
    // after the last).
    m_stripTimer = new QTimer(this);
    m_stripTimer->setSingleShot(true);
    m_stripTimer->setInterval(300);
    connect(m_stripTimer, &QTimer::timeout, this, &FootprintWorkspace::refreshStrips);
    connect(m_controller, &FootprintController::countsChanged, m_stripTimer, qOverload<>(&QTimer::start));
    connect(m_controller, &FootprintController::rejudgeFinished, m_stripTimer, qOverload<>(&QTimer::start));
    wireZoomKeys();
    setRoiOverlay();
    updateCounts();
}

// Left: the shot list, its filter and counts, the review buttons and the note.
QWidget* FootprintWorkspace::buildShotList() {
    auto* left = new QWidget(this);
    auto* leftLay = new QVBoxLayout(left);
    leftLay->setContentsMargins(0, 0, 0, 0);
    auto* filterRow = new QHBoxLayout;
    m_filter = new QComboBox(left);
    m_filter->addItems({tr("All shots"), tr("Good only"), tr("Doubtful only"), tr("Rejected only"), tr("Unreadable only"),
                        tr("Manual verdicts")});
    m_filter->setToolTip(tr("Which shots the table and the contact sheet show (Alt+O)"));
    m_counts = new QLabel(left);
    m_counts->setWordWrap(true);
    auto* show = new QLabel(tr("Sh&ow:"), left);
    show->setBuddy(m_filter);
    filterRow->addWidget(show);
    filterRow->addWidget(m_filter);
    filterRow->addWidget(m_counts, 1);
    leftLay->addLayout(filterRow);
    // The filter expression (issue 30), with the verdict choice: both make the view.
    QStringList words;
    for (const ShotColumn& c : shotColumns()) words << QLatin1String(c.name);
    words << "and" << "or" << "not" << "abs" << "sqrt";
    m_where = new FilterField(shotFilterHelp(), words, left);
    m_where->setPlaceholderText(tr("e.g. snr < 10 and beam == 2"));
    auto* whereLabel = new QLabel(tr("F&ilter:"), left);
    whereLabel->setBuddy(m_where);
    auto* whereRow = new QHBoxLayout;
    whereRow->addWidget(whereLabel);
    whereRow->addWidget(m_where, 1);
    // Above the verdict choice: Alt+O, D, Tab still lands in the table (the documented review
    // by keyboard), and Tab from the expression goes to the choice.
    leftLay->insertLayout(0, whereRow);
    m_reviewed = new QLabel(left);
    m_reviewed->setToolTip(tr("Shots the pipeline judged doubtful that have a manual verdict. "
                              "N goes to the next shot of the view without one"));
    leftLay->addWidget(m_reviewed);
    m_table = new QTableView(left);
    m_table->setModel(m_proxy);
    m_table->setSortingEnabled(true);
    m_table->sortByColumn(-1, Qt::AscendingOrder);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    // Several shots (Ctrl+click, Shift+click, Shift+arrows) for Blink / tile; the review keys act on the current one.
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    // Tab leaves the table for the next widget, as everywhere else in the window. A table moves
    // from cell to cell on Tab by default, and past the last column to the next row: the shot
    // changed under the reviewer's hands (issue 30). The shots are browsed with the arrow keys.
    m_table->setTabKeyNavigation(false);
    m_table->verticalHeader()->setDefaultSectionSize(20);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setColumnWidth(ShotTableModel::File, 150);
    m_table->setColumnWidth(ShotTableModel::Time, 84);
    m_table->setColumnWidth(ShotTableModel::Beam, 40);
    m_table->setColumnWidth(ShotTableModel::X, 64);
    m_table->setColumnWidth(ShotTableModel::Y, 64);
    // Wide enough for "rejected (manual)": a manual verdict was cut to "good ..." in the screenshot.
    m_table->setColumnWidth(ShotTableModel::VerdictCol,
                            m_table->fontMetrics().horizontalAdvance(tr("unreadable (manual)")) + 12);
    m_table->setColumnWidth(ShotTableModel::Reasons, 160);
    // The verdict is what a reviewer reads first: shown right after the file name, so it is in
    // view without scrolling at the default width (it sat behind a horizontal scrollbar,
    // cut to "doubtf", after the time, beam and position columns). Only the view's order moves.
    m_table->horizontalHeader()->moveSection(m_table->horizontalHeader()->visualIndex(ShotTableModel::VerdictCol), 1);
    leftLay->addWidget(m_table, 1);
    setTabOrder(m_where, m_filter);
    setTabOrder(m_filter, m_table);
    auto* overrideRow = new QHBoxLayout;
    auto* accept = new QPushButton(tr("Accept (A)"), left);
    auto* reject = new QPushButton(tr("Reject (R)"), left);
    auto* next = new QPushButton(tr("Next unreviewed (N)"), left);
    auto* clearOv = new QPushButton(tr("Auto"), left);
    accept->setToolTip(tr("Manual verdict good for this shot, then the next shot of the view (A)"));
    reject->setToolTip(tr("Manual verdict rejected for this shot, then the next shot of the view (R)"));
    next->setToolTip(tr("The next shot of the view that has no manual verdict yet (N)"));
    clearOv->setToolTip(tr("Drop the manual verdict and use the computed one"));
    overrideRow->addWidget(accept);
    overrideRow->addWidget(reject);
    overrideRow->addWidget(next);
    overrideRow->addWidget(clearOv);
    auto* suggest = new QPushButton(tr("Suggest thresholds…"), left);
    suggest->setToolTip(tr("The verdict criteria tuned on the shots you gave a manual verdict (Accept / Reject): "
                           "what would change, before and after, cross-validated; applied only if you accept"));
    overrideRow->addWidget(suggest);
    connect(suggest, &QPushButton::clicked, this, [this] { suggestThresholds(); });
    auto* blink = new QPushButton(tr("Blink / tile (B)"), left);
    blink->setToolTip(tr("The selected shots (Ctrl+click, Shift+click) in a grid or blinking, zoom and display locked (B)"));
    overrideRow->addWidget(blink);
    connect(blink, &QPushButton::clicked, this, [this] { openBlinkView(); });
    leftLay->addLayout(wrapRow(overrideRow));  // wraps in a narrow window
    m_note = new QLineEdit(left);
    m_note->setPlaceholderText(tr("Note on this shot (E; Enter keeps it and goes back to the list)"));
    m_note->setToolTip(tr("Kept in the session and the review table export"));
    leftLay->addWidget(m_note);

    connect(m_filter, &QComboBox::currentIndexChanged, this, [this](int i) {
        const int keep = currentSourceRow();
        m_proxy->setVerdictFilter(ShotFilterProxy::Filter(i));
        selectInView(keep);
        viewChanged();
        emit modified();
    });
    connect(m_where, &QLineEdit::textChanged, this, &FootprintWorkspace::applyWhere);
    connect(accept, &QPushButton::clicked, this, &FootprintWorkspace::acceptCurrent);
    connect(reject, &QPushButton::clicked, this, &FootprintWorkspace::rejectCurrent);
    connect(next, &QPushButton::clicked, this, &FootprintWorkspace::nextUnreviewed);
    connect(clearOv, &QPushButton::clicked, this, [this] { judgeCurrent(false, Verdict::Good); });
    connect(m_note, &QLineEdit::editingFinished, this, &FootprintWorkspace::commitNote);
    connect(m_note, &QLineEdit::returnPressed, this, [this] { m_table->setFocus(); });
    return left;
}

// Centre: the review tab (ROI, frame, histogram, colour bar, readout, details), the contact
// sheet and the trend tab.
void FootprintWorkspace::buildCentre() {
    m_tabs = new QTabWidget(this);
    auto* review = new QWidget(m_tabs);
    auto* revLay = new QVBoxLayout(review);
    auto* viewRow = new QHBoxLayout;
    m_colorMap = new QComboBox(review);
    m_colorMap->addItems(colorMapNames());
    m_colorMap->setCurrentIndex(1);
    m_colorMap->setToolTip(tr("Colour map of the ROI, the frame and the contact sheet"));
    m_display = new DisplayControls(review);
    m_showGauss = new QCheckBox(tr("Gaussian 1/e²"), review);
    m_showTefm = new QCheckBox(tr("TEFM ellipse"), review);
    m_showDomain = new QCheckBox(tr("Domain"), review);
    m_showCentres = new QCheckBox(tr("Centres"), review);
    for (QCheckBox* c : {m_showGauss, m_showTefm, m_showDomain, m_showCentres}) c->setChecked(true);
    viewRow->addWidget(new QLabel(tr("Colours:"), review));
    viewRow->addWidget(m_colorMap);
    viewRow->addStretch(1);
    revLay->addLayout(wrapRow(viewRow));  // wraps in a narrow window (issue 10 layout)
    // The display controls on a line of their own: their row wraps inside the tab's width (nested
    // in the wrapping row above, they were laid out at full length and clipped at 1024 px).
    revLay->addWidget(m_display);
    auto* overlayRow = new QHBoxLayout;
    overlayRow->addWidget(new QLabel(tr("Draw:"), review));
    for (QCheckBox* c : {m_showGauss, m_showTefm, m_showDomain, m_showCentres}) overlayRow->addWidget(c);
    overlayRow->addStretch(1);
    revLay->addLayout(wrapRow(overlayRow));
    auto* views = new QSplitter(Qt::Horizontal, review);
    m_roiView = new ImageView(views);
    m_frameView = new ImageView(views);
    views->addWidget(m_roiView);
    views->addWidget(m_frameView);
    views->setStretchFactor(0, 3);
    views->setStretchFactor(1, 2);
    revLay->addWidget(views, 1);
    auto* scaleRow = new QHBoxLayout;
    m_histogram = new HistogramView(review);
    m_colorBar = new ColorBar(review);
    m_histogram->setFixedHeight(72);
    m_colorBar->setFixedHeight(40);
    scaleRow->addWidget(m_histogram, 1);
    scaleRow->addWidget(m_colorBar, 1, Qt::AlignBottom);
    revLay->addLayout(scaleRow);
    m_readout = new QLabel(tr(kReadoutHint), review);
    revLay->addWidget(m_readout);
    m_regionStats = new QLabel(review);  // the regions' statistics (right-click a view: box / circle regions)
    m_regionStats->setObjectName("regionStats");
    m_regionStats->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // A fixed height: a label that appeared or grew in the middle of a drag resized the views
    // under the mouse (the region being drawn jumped by a pixel row). Every line is in the tooltip.
    m_regionStats->setFixedHeight(3 * m_regionStats->fontMetrics().lineSpacing() + 4);
    m_regionStats->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    // Wrapped within the view's width, never widening it (issue 42: a region's statistics on one
    // line widened a 1024 px window to 1613 px and put the parameter panel off-screen).
    m_regionStats->setWordWrap(true);
    m_regionStats->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_regionStats->setText(tr("Regions: right-click a view ▸ Mouse: box / circle regions"));
    revLay->addWidget(m_regionStats);
    m_details = new QLabel(review);
    m_details->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_details->setTextFormat(Qt::RichText);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details->setWordWrap(true);
    revLay->addWidget(m_details);
    m_tabs->addTab(review, tr("Review"));
    m_reviewTab = review;
    m_sheet = new ContactSheet(m_controller, m_proxy, m_tabs);
    m_tabs->addTab(m_sheet, tr("Contact sheet"));

    m_trendTab = buildTrendTab();
    m_tabs->addTab(m_trendTab, tr("Trend"));
    m_columnPlot = new ColumnPlot(m_controller, m_proxy, m_tabs);
    m_tabs->addTab(m_columnPlot, tr("Plot"));
    connect(m_columnPlot, &ColumnPlot::shotClicked, this, [this](int row) { selectRow(row); });

    connect(m_colorMap, &QComboBox::currentIndexChanged, this, [this] {
        m_sheet->setColorMap(colorMapFromIndex(m_colorMap->currentIndex()));
        showDetail(m_detail);
    });
    connect(m_display, &DisplayControls::changed, this, [this] { showDetail(m_detail); });
    wireContrastBias(m_display, {m_roiView, m_frameView}, m_colorBar);
    for (ImageView* v : {m_roiView, m_frameView}) {
        connect(v, &ImageView::regionsChanged, this, [this] {
            const QString text = regionsSummary({{tr("ROI"), m_roiView}, {tr("Frame"), m_frameView}});
            m_regionStats->setText(text.isEmpty() ? tr("Regions: right-click a view ▸ Mouse: box / circle regions") : text);
            m_regionStats->setToolTip(text);
        });
        connect(v, &ImageView::status, this, &FootprintWorkspace::status);
    }
    for (QCheckBox* c : {m_showGauss, m_showTefm, m_showDomain, m_showCentres})
        connect(c, &QCheckBox::toggled, this, [this] { m_roiView->update(); });
    connect(m_roiView, &ImageView::pixelHovered, this, [this](double x, double y, double v) {
        m_readout->setText(tr("Pixel (%1, %2): %3 DN").arg(x, 0, 'f', 0).arg(y, 0, 'f', 0).arg(v, 0, 'f', 0));
    });
    connect(m_frameView, &ImageView::pixelHovered, this, [this](double x, double y, double v) {
        m_readout->setText(tr("Frame pixel (%1, %2): %3 DN").arg(x, 0, 'f', 0).arg(y, 0, 'f', 0).arg(v, 0, 'f', 0));
    });
}

// The undo history, the table's selection, the parameters, the controller's signals, the review
// keys and the contact sheet.
void FootprintWorkspace::wireController() {
    // (the controller, created before the stack, is the context: it goes first when the workspace
    // is destroyed, so that the stack's clear() on its own destruction reaches nobody)
    QUndoStack* undo = &undoStackOf(this);
    connect(m_controller, &FootprintController::shotsAboutToReset, undo, &QUndoStack::clear);
    connect(undo, &QUndoStack::indexChanged, m_controller, [this, undo] {
        if (undo->count() > 0) emit modified();
    });
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this] { currentRowChanged(); });
    // A parameter change is a step of the workspace's undo history (issue 28: a slider change was
    // not, so Ctrl+Z after it took back a manual verdict on a shot that was not on screen).
    connect(m_panel, &FootprintParamsPanel::paramsChanged, this,
            [this](const FootprintParams& p) { changeParams(p, tr("footprint parameters")); });
    connect(m_controller, &FootprintController::currentDetailReady, this, &FootprintWorkspace::showDetail);
    connect(m_controller, &FootprintController::countsChanged, this, &FootprintWorkspace::updateCounts);
    connect(m_controller, &FootprintController::shotsChanged, this, [this](int first, int last) {
        const int cur = currentSourceRow();
        if (cur >= first && cur <= last && !m_note->hasFocus()) {
            const Shot* s = m_controller->shot(cur);
            if (s && m_note->text() != s->note) m_note->setText(s->note);
        }
    });
    connect(m_controller, &FootprintController::rejudgeFinished, this, &FootprintWorkspace::refreshTrend);
    connect(m_controller, &FootprintController::shotsAppended, this, [this](int first, int last) {
        applyPendingOverrides(first, last);
        if (!m_table->currentIndex().isValid() && m_proxy->rowCount() > 0) m_table->selectRow(0);
    });
    connect(m_controller, &FootprintController::shotsReset, this, [this] {
        if (m_proxy->rowCount() > 0) m_table->selectRow(0);
        applyPendingOverrides();
    });
    // New data: the undo history refers to the shots it was made on (the other workspaces' stay).
    connect(m_controller, &FootprintController::shotsReset, this, [this] { undoStackOf(this).clear(); });
    // The window's progress bar and Cancel button, and its error dialog.
    connect(m_controller, &FootprintController::loadProgress, this,
            [this](int done, int total) { emit progress(done, total, tr("%v / %m shots")); });
    connect(m_controller, &FootprintController::loadFinished, this, [this] { emit progress(0, 0, QString()); });
    connect(m_controller, &FootprintController::error, this,
            [this](const QString& msg) { emit failed(tr("Cannot open the footprint inputs"), msg); });
    connect(m_controller, &FootprintController::loadProgress, this,
            [this](int done, int total) { emit status(tr("Loaded %1 of %2 shots").arg(done).arg(total)); });
    connect(m_controller, &FootprintController::loadFinished, this, [this](int loaded, int failed, bool cancelled) {
        QString msg = cancelled ? tr("Loading cancelled after %1 shots").arg(loaded)
                                : tr("Loaded %1 shots (%2 unreadable)").arg(loaded).arg(failed);
        const QStringList& skipped = m_controller->skippedInputs();
        if (!skipped.isEmpty()) {
            QStringList names;
            for (const QString& f : skipped.mid(0, 3)) names << QFileInfo(f).fileName();
            msg += tr("; skipped %1 %2 that %3 not an image (%4%5)")
                       .arg(skipped.size())
                       .arg(skipped.size() == 1 ? tr("file") : tr("files"))
                       .arg(skipped.size() == 1 ? tr("is") : tr("are"))
                       .arg(names.join(", "))
                       .arg(skipped.size() > 3 ? ", …" : "");
        }
        emit status(msg);
        refreshTrend();
    });
    // Review keys on the table and on the contact sheet (the sheet follows the table's current).
    for (QWidget* target : {static_cast<QWidget*>(m_table), static_cast<QWidget*>(m_sheet)}) {
        auto key = [this, target](Qt::Key k, void (FootprintWorkspace::*fn)()) {
            auto* sc = new QShortcut(QKeySequence(k), target, nullptr, nullptr, Qt::WidgetShortcut);
            connect(sc, &QShortcut::activated, this, fn);
        };
        key(Qt::Key_A, &FootprintWorkspace::acceptCurrent);
        key(Qt::Key_R, &FootprintWorkspace::rejectCurrent);
        key(Qt::Key_N, &FootprintWorkspace::nextUnreviewed);
        auto* b = new QShortcut(QKeySequence(Qt::Key_B), target, nullptr, nullptr, Qt::WidgetShortcut);
        connect(b, &QShortcut::activated, this, [this] { openBlinkView(); });
        auto* e = new QShortcut(QKeySequence(Qt::Key_E), target, nullptr, nullptr, Qt::WidgetShortcut);
        connect(e, &QShortcut::activated, this, [this] {
            m_note->setFocus();
            m_note->selectAll();
        });
    }
    connect(m_sheet, &ContactSheet::openShot, this, [this](int row) {
        selectRow(row);
        m_tabs->setCurrentWidget(m_reviewTab);
        m_table->setFocus();
    });
    connect(m_sheet->selectionModel(), &QItemSelectionModel::currentChanged, this, [this] {
        const int row = m_sheet->currentSourceRow();
        if (row >= 0 && row != currentSourceRow()) selectRow(row);
    });
    connect(m_tabs, &QTabWidget::currentChanged, this, [this] {
        if (m_tabs->currentWidget() != m_sheet) return;
        m_sheet->setCurrentSourceRow(currentSourceRow());
        m_sheet->setFocus();  // arrows, A / R / N and Enter act on the sheet at once
    });

}

// The image views' zoom steps from the shot table, where the keyboard is during a review (a
// click in a view leaves it there): 2, 4 and 8 magnify both the ROI and the frame about their
// centres, 1 fits them again. Each view has the same keys when it has the focus.
void FootprintWorkspace::wireZoomKeys() {
    for (int step : {1, 2, 4, 8}) {
        auto* sc = new QShortcut(QKeySequence(Qt::Key_0 + step), m_table, nullptr, nullptr, Qt::WidgetShortcut);
        connect(sc, &QShortcut::activated, this, [this, step] {
            for (ImageView* v : {m_roiView, m_frameView}) v->setZoomStep(step);
        });
    }
}

// What the ROI view draws over the image: the domain's outline, the Gaussian's 1/e² ellipse,
// the TEFM ellipse and the centres.
void FootprintWorkspace::setRoiOverlay() {
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
}

void FootprintWorkspace::selectInView(int sourceRow) {
    // Stay on the shot when it is in the new view, else start at the top.
    const QModelIndex p = m_proxy->mapFromSource(m_model->index(sourceRow, 0));
    if (p.isValid())
        m_table->selectRow(p.row());
    else if (m_proxy->rowCount() > 0)
        m_table->selectRow(0);
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
    m_columnPlot->setCurrentRow(row);
    const Shot* s = m_controller->shot(row);
    m_note->setText(s ? s->note : QString());
    m_readout->setText(tr(kReadoutHint));  // the value under the cursor belonged to the last shot
    if (m_tabs->currentWidget() == m_sheet && m_sheet->currentSourceRow() != row) m_sheet->setCurrentSourceRow(row);
}

void FootprintWorkspace::showTab(const QString& name) {
    m_tabs->setCurrentWidget(name == "trend"  ? m_trendTab
                             : name == "plot" ? static_cast<QWidget*>(m_columnPlot)
                             : name == "sheet" ? static_cast<QWidget*>(m_sheet)
                                               : m_reviewTab);
}

void FootprintWorkspace::commitNote() {
    const int row = currentSourceRow();
    const Shot* s = m_controller->shot(row);
    if (s && s->note != m_note->text()) undoStackOf(this).push(new ShotNoteCommand(m_controller, row, m_note->text()));
}

void FootprintWorkspace::judgeCurrent(bool overridden, Verdict v) {
    const QModelIndex cur = m_table->currentIndex();
    const int row = currentSourceRow();
    if (row < 0) return;
    // The next shot of the view as it is now: after the verdict this shot may leave the view
    // (a doubtful shot accepted under "Doubtful only"), and the row after it would move up.
    const int nextProxy = cur.row() + 1;
    const int nextSource =
        nextProxy < m_proxy->rowCount() ? m_proxy->mapToSource(m_proxy->index(nextProxy, 0)).row() : -1;
    const Shot* s = m_controller->shot(row);
    const bool noteChanged = s->note != m_note->text();
    if (noteChanged) undoStackOf(this).beginMacro(tr("note and verdict on %1").arg(QFileInfo(s->file).fileName()));
    if (noteChanged) undoStackOf(this).push(new ShotNoteCommand(m_controller, row, m_note->text()));
    undoStackOf(this).push(new ShotVerdictCommand(m_controller, row, overridden, v));
    if (noteChanged) undoStackOf(this).endMacro();
    emit modified();
    if (!overridden) return;  // "Auto" stays on the shot
    if (nextSource >= 0) {
        selectRow(nextSource);
    } else {
        // The last shot of the view: stay on it if it is still shown, else on the new last row.
        const QModelIndex p = m_proxy->mapFromSource(m_model->index(row, 0));
        if (p.isValid())
            m_table->selectRow(p.row());
        else if (m_proxy->rowCount() > 0)
            m_table->selectRow(m_proxy->rowCount() - 1);
        emit status(tr("Last shot of the view"));
    }
    if (m_tabs->currentWidget() == m_sheet) m_sheet->setCurrentSourceRow(currentSourceRow());
}

void FootprintWorkspace::acceptCurrent() { judgeCurrent(true, Verdict::Good); }

void FootprintWorkspace::rejectCurrent() { judgeCurrent(true, Verdict::Rejected); }

void FootprintWorkspace::nextUnreviewed() {
    const int n = m_proxy->rowCount();
    if (n == 0) return;
    const int start = m_table->currentIndex().isValid() ? m_table->currentIndex().row() : -1;
    for (int k = 1; k <= n; ++k) {
        const int p = (start + k) % n;
        const Shot* s = m_controller->shot(m_proxy->mapToSource(m_proxy->index(p, 0)).row());
        if (s && !s->overridden) {
            m_table->selectRow(p);
            if (m_tabs->currentWidget() == m_sheet) m_sheet->setCurrentSourceRow(currentSourceRow());
            return;
        }
    }
    emit status(tr("Every shot of this view has a manual verdict"));
}

bool FootprintWorkspace::exportTable(const QString& path, bool acceptedOnly, QString* error, int* rows) {
    commitNote();
    return writeFootprintReview(m_controller->shots(), m_controller->params().method, path, acceptedOnly, error, rows);
}

void FootprintWorkspace::exportDialog(bool acceptedOnly) {
    const QString path = askSavePath(this, acceptedOnly ? tr("Export accepted shots") : tr("Export the review table"),
                                     "paths/lastExport", acceptedOnly ? "accepted_shots.csv" : "review.csv", tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString err;
    int rows = 0;
    if (!exportTable(path, acceptedOnly, &err, &rows)) {
        emit status(tr("Cannot export: %1").arg(err));
        return;
    }
    emit status(acceptedOnly ? m_controller->acceptedExportMessage(rows, path)
                             : tr("Exported the review table (%1 shots) to %2").arg(m_controller->count()).arg(path));
}

BlinkView* FootprintWorkspace::openBlinkView() {
    QList<int> rows;  // source rows in the table's order
    for (const QModelIndex& i : m_table->selectionModel()->selectedRows()) rows << i.row();
    std::sort(rows.begin(), rows.end());
    if (rows.size() < 2) {
        rows.clear();  // fewer than two selected: the view's first shots
        for (int p = 0; p < m_proxy->rowCount() && rows.size() < 9; ++p) rows << p;
    }
    std::vector<BlinkFrame> frames;
    for (int p : rows) {
        const Shot* s = m_controller->shot(m_proxy->mapToSource(m_proxy->index(p, 0)).row());
        if (!s || s->roi.empty()) continue;
        frames.push_back({QFileInfo(s->file).fileName(), s->roi, QPointF(s->origin), s->fit.ok, QPointF(s->fit.x, s->fit.y)});
    }
    if (frames.size() < 2) {
        emit status(tr("Blink / tile needs two shots with an image: select them in the table (Ctrl+click, Shift+click)"));
        return nullptr;
    }
    auto* v = new BlinkView(std::move(frames), colorMapFromIndex(m_colorMap->currentIndex()), m_display->settings(), this);
    v->show();
    return v;
}

void FootprintWorkspace::updateCounts() {
    const auto c = m_controller->counts();
    QString t = tr("<span style='color:#2e8b57'>%1 good</span> · <span style='color:#d68910'>%2 doubtful</span> · "
                   "<span style='color:#c0392b'>%3 rejected</span>")
                    .arg(c.good)
                    .arg(c.doubtful)
                    .arg(c.rejected);
    if (c.unreadable) t += tr(" · <span style='color:#6e6e78'>%1 unreadable</span>").arg(c.unreadable);
    if (c.pending) t += tr(" · %1 pending").arg(c.pending);
    if (c.overridden) t += tr(" · %1 manual").arg(c.overridden);
    if (m_proxy->isFiltered()) t += tr(" · <b>%1 of %2 shown</b>").arg(m_proxy->rowCount()).arg(m_controller->count());
    m_counts->setText(t);
    int doubtful = 0, reviewed = 0;
    for (const Shot& s : m_controller->shots()) {
        if (!s.loadError.isEmpty() || !s.processed || s.verdict != Verdict::Doubtful) continue;
        ++doubtful;
        reviewed += s.overridden;
    }
    m_reviewed->setText(tr("Reviewed %1 of %2 doubtful").arg(reviewed).arg(doubtful));
}

void FootprintWorkspace::showDetail(const ShotDetail& d) {
    m_detail = d;
    const Shot* s = m_controller->shot(d.index);
    if (!s || d.roi.empty()) {
        // Nothing of the previous shot stays on display: its colour bar stayed, and read as this
        // shot's scale (issue 30). The ROI view says why there is no image.
        const QString why = !s                         ? QString()
                            : !s->loadError.isEmpty() ? tr("Unreadable: %1").arg(s->loadError)
                                                      : tr("Not loaded yet");
        m_roiView->clear(why);
        m_frameView->clear();
        m_frameView->setVisible(false);
        m_histogram->clear();
        m_colorBar->clear();
        m_details->setText(s ? tr("<b>%1</b><br>%2").arg(s->file.toHtmlEscaped(), s->loadError.toHtmlEscaped()) : QString());
        return;
    }
    const ColorMap cm = colorMapFromIndex(m_colorMap->currentIndex());
    const DisplaySettings ds = m_display->settings();
    const core::DisplayLimits lim = displayLimits(d.roi, ds);
    m_display->showLimits(lim.lo, lim.hi);
    m_roiView->setImage(d.roi, renderStretched(d.roi, cm, ds.stretch, lim.lo, lim.hi), QPointF(d.origin));
    m_roiView->setExportName(QFileInfo(s->file).completeBaseName() + "_roi");
    m_frameView->setExportName(QFileInfo(s->file).completeBaseName() + "_frame");
    m_histogram->setData(d.roi, lim.lo, lim.hi);
    m_colorBar->setScale(cm, ds.stretch, lim.lo, lim.hi);
    const FootprintResult& r = d.selected;
    const Verdict v = s->effectiveVerdict();
    QString badge = shotStateText(ShotState(int(v))).toUpper();
    if (s->overridden) badge += tr(" (manual; computed: %1)").arg(shotStateText(ShotState(int(s->verdict))));
    for (const auto& reason : r.reasons) badge += "\n• " + QString::fromStdString(reason);
    m_roiView->setBadge(badge, verdictColor(v));
    // The badge must not hide the spot: it keeps clear of every centre marker drawn.
    QVector<QPointF> centres;
    for (const FootprintResult* m : {&d.gauss, &d.tefm, &d.gcm})
        if (m->fit.ok) centres << QPointF(m->fit.x, m->fit.y);
    m_roiView->setKeepClear(centres);
    // Full-frame context.
    if (s->fullFrame) {
        if (m_frameFile != s->file) {
            m_frame = FootprintController::frameOf(*s);
            m_frameFile = s->file;
        }
        if (!m_frame.empty()) {
            // Show a 128 px window of the frame around the ROI.
            const int half = 64;
            const int cx = d.origin.x() + d.roi.cols / 2, cy = d.origin.y() + d.roi.rows / 2;
            const cv::Rect win = cv::Rect(cx - half, cy - half, 2 * half, 2 * half) & cv::Rect(0, 0, m_frame.cols, m_frame.rows);
            const cv::Mat crop = m_frame(win).clone();
            const core::DisplayLimits fl = ds.limits == LimitsMode::Manual ? lim : displayLimits(crop, ds);
            m_frameView->setImage(crop, renderStretched(crop, cm, ds.stretch, fl.lo, fl.hi), QPointF(win.x, win.y));
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
            QVector<QPointF> spot;
            if (r.fit.ok) spot << QPointF(r.fit.x + d.origin.x() - win.x, r.fit.y + d.origin.y() - win.y);
            m_frameView->setKeepClear(spot);
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

QWidget* FootprintWorkspace::buildTrendTab() {
    auto* trend = new QWidget(m_tabs);
    auto* trendLay = new QVBoxLayout(trend);
    m_plotX = makePlot(tr("ΔX (px)"), tr("Change of the spot centre's x from the first month's mean (px): each shot "
                                         "(dots) and the monthly mean (line)"),
                       "trend_dx", false, trend);
    m_plotY = makePlot(tr("ΔY (px)"), tr("Change of the spot centre's y from the first month's mean (px): each shot "
                                         "(dots) and the monthly mean (line)"),
                       "trend_dy", false, trend);
    m_plotPointing = makePlot(tr("Pointing (″)"), tr("Planar pointing change from the first month (arcsec)"),
                              "trend_pointing", true, trend);
    m_trendSummary = new QLabel(trend);
    m_trendSummary->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_trendSummary->setWordWrap(true);
    trendLay->addWidget(m_plotX, 1);
    trendLay->addWidget(m_plotY, 1);
    trendLay->addWidget(m_plotPointing, 1);
    trendLay->addWidget(m_trendSummary);
    return trend;
}

QList<QCustomPlot*> FootprintWorkspace::trendPlots() const { return {m_plotX, m_plotY, m_plotPointing}; }

// The filter expression: applied when valid; an invalid text is marked and the filter in force stays.
void FootprintWorkspace::applyWhere() {
    QString err;
    const int keep = currentSourceRow();
    if (!m_proxy->setExpression(m_where->text(), &err)) {
        m_where->setError(err);
        emit status(tr("Filter: %1 (the previous filter stays)").arg(err));
        return;
    }
    m_where->setError(QString());
    selectInView(keep);
    viewChanged();
    emit status(m_proxy->expression().isEmpty() ? tr("Filter cleared")
                                                : tr("Filter: %1 of %2 shots").arg(m_proxy->rowCount()).arg(m_controller->count()));
    emit modified();
}

// The view (verdict choice and filter) changed: the trend and the column plot follow it.
void FootprintWorkspace::viewChanged() {
    refreshTrend();
    m_columnPlot->refresh();
    updateCounts();
}

void FootprintWorkspace::refreshTrend() {
    TrendParams tp;
    const bool filtered = m_proxy->isFiltered();
    const TrendResult tr_ =
        filtered ? m_controller->trend(tp, [this](int row) { return m_proxy->acceptsSourceRow(row); }) : m_controller->trend(tp);
    for (QCustomPlot* p : {m_plotX, m_plotY, m_plotPointing}) p->clearGraphs();
    if (!tr_.ok) {
        // No empty legend boxes or axes left from an earlier list: the plots go, the reason stays.
        m_trendSummary->setText(tr("Trend: %1. A shot list CSV with time and beam columns (or the demo) gives the "
                                   "monthly centroid trend.").arg(QString::fromStdString(tr_.error)));
        for (QCustomPlot* p : {m_plotX, m_plotY, m_plotPointing}) {
            p->legend->setVisible(false);
            p->hide();
        }
        return;
    }
    for (QCustomPlot* p : {m_plotX, m_plotY, m_plotPointing}) {
        p->legend->setVisible(true);
        p->show();
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
            // The shots and the monthly mean are one legend entry (its series key): a click on it
            // hides both (four entries did not fit at 1024 px and were cut to "monthly mea").
            QCPGraph* g = p->addGraph();
            g->setName(key + tr(" shots"));
            g->setProperty("series", key);
            g->setLineStyle(QCPGraph::lsNone);
            g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colors[k % 4].lighter(150), 3));
            g->removeFromLegend();
            QCPGraph* m = p->addGraph();
            m->setName(key);
            m->setProperty("series", key);
            m->setPen(QPen(colors[k % 4], 2));
            m->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, colors[k % 4], 6));
        }
        QCPGraph* pg = m_plotPointing->addGraph();
        pg->setName(key);
        pg->setPen(QPen(colors[k % 4], 2));
        pg->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, colors[k % 4], 6));
        return k;
    };
    for (int i = 0; i < m_controller->count(); ++i) {
        const Shot& s = *m_controller->shot(i);
        if (filtered && !m_proxy->acceptsSourceRow(i)) continue;
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
    QString view;
    if (filtered) {
        int shown = 0;
        for (int i = 0; i < m_controller->count(); ++i) shown += m_proxy->acceptsSourceRow(i);
        view = tr("Filter applied: the trend of the %1 of %2 shots in view (%3). ")
                   .arg(shown)
                   .arg(m_controller->count())
                   .arg(m_proxy->expression().isEmpty() ? m_filter->currentText()
                        : m_filter->currentIndex() == 0 ? m_proxy->expression()
                                                        : m_filter->currentText() + ", " + m_proxy->expression());
    }
    m_trendSummary->setText(view + tr("Change from the first month: shots (dots) and monthly means (lines) of the "
                                      "accepted shots; 3σ rejection within each month; 0.31″ per px. ") + summary);
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
    o["params"] = toQtJson(footprintParamsToJson(m_controller->params()));  // every field
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
    if (const Shot* cur = m_controller->shot(currentSourceRow())) o["current_key"] = overrideKey(*cur);
    o["filter"] = ShotFilterProxy::filterKeys().value(m_filter->currentIndex());
    // The text as typed (an invalid one too: it comes back marked, as it was left).
    if (!m_where->text().trimmed().isEmpty()) o["where"] = m_where->text();
    QJsonObject plot;
    plot["x"] = m_columnPlot->xColumn();
    plot["y"] = m_columnPlot->yColumn();
    o["plot"] = plot;
    const DisplaySettings ds = m_display->settings();
    QJsonObject disp;
    disp["limits"] = int(ds.limits);
    disp["stretch"] = QString::fromLatin1(core::stretchKindName(ds.stretch));
    disp["low"] = ds.manualLo;
    disp["high"] = ds.manualHi;
    disp["colors"] = m_colorMap->currentIndex();
    o["display"] = disp;
    return o;
}

bool FootprintWorkspace::readState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc,
                                   const std::vector<std::string>& at, StatePhase phase) {
    if (!checkSessionKeys(state, {"inputs", "demo", "params", "overrides", "current", "current_key", "filter", "where", "plot", "display"},
                          "footprint", error, doc, at))
        return false;
    // Every parameter from the session over the defaults.
    FootprintParams p;
    if (state.contains("params")) {
        std::vector<std::string> where = at;
        where.push_back("params");
        std::string err;
        if (!footprintSchema().fromJson(fromQtJson(state["params"]), &p, &err, doc, where)) {
            *error = QString::fromStdString(err);
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
    const QString filter = state["filter"].toString("all");
    const int filterIndex = ShotFilterProxy::filterKeys().indexOf(filter);
    if (filterIndex < 0) {
        *error = tr("unknown filter \"%1\" (one of %2)").arg(filter, ShotFilterProxy::filterKeys().join(", "));
        return false;
    }
    if (phase != StatePhase::Apply) return true;  // (nothing above changes the workspace; no input is read before)
    m_panel->setParams(p);
    m_controller->setParams(p);
    m_filter->setCurrentIndex(filterIndex);
    m_where->setText(state["where"].toString());
    if (state.contains("plot"))
        m_columnPlot->setColumns(state["plot"].toObject()["x"].toString("dx"), state["plot"].toObject()["y"].toString("dy"));
    if (state.contains("display")) {
        const QJsonObject disp = state["display"].toObject();
        DisplaySettings ds;
        ds.limits = LimitsMode(std::clamp(disp["limits"].toInt(int(ds.limits)), 0, int(LimitsMode::Manual)));
        for (core::StretchKind k : {core::StretchKind::Linear, core::StretchKind::Sqrt, core::StretchKind::Log, core::StretchKind::Asinh})
            if (disp["stretch"].toString() == core::stretchKindName(k)) ds.stretch = k;
        ds.manualLo = disp["low"].toDouble(0);
        ds.manualHi = disp["high"].toDouble(1);
        m_display->setSettings(ds);
        m_colorMap->setCurrentIndex(std::clamp(disp["colors"].toInt(1), 0, m_colorMap->count() - 1));
    }
    m_pendingOverrides.clear();
    for (auto it = ov.begin(); it != ov.end(); ++it) m_pendingOverrides.insert(it.key(), it.value().toObject());
    m_pendingCurrent = state["current_key"].toString();
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
    if (m_pendingCurrent.isEmpty() && cur >= 0 && cur < m_controller->count()) selectRow(cur);
    return true;
}

void FootprintWorkspace::applyPendingOverrides(int first, int last) {
    if (last < 0 || last >= m_controller->count()) last = m_controller->count() - 1;
    first = std::max(first, 0);
    std::vector<FootprintController::Review> reviews;
    for (int i = first; !m_pendingOverrides.isEmpty() && i <= last; ++i) {
        const auto it = m_pendingOverrides.constFind(overrideKey(*m_controller->shot(i)));
        if (it == m_pendingOverrides.constEnd()) continue;
        FootprintController::Review r;
        r.index = i;
        r.note = it->value("note").toString();
        if (it->contains("verdict")) {
            r.setVerdict = true;
            parseVerdict((*it)["verdict"].toString().toStdString(), &r.verdict);
        }
        reviews.push_back(r);
        m_pendingOverrides.erase(it);
    }
    m_controller->applyReviews(reviews);
    // The session's current shot, once it has arrived (after its override: it decides the view).
    for (int i = first; !m_pendingCurrent.isEmpty() && i <= last; ++i) {
        if (overrideKey(*m_controller->shot(i)) != m_pendingCurrent) continue;
        m_pendingCurrent.clear();
        selectRow(i);
    }
}

void FootprintWorkspace::openDemo() {
    m_controller->setShots(demoFootprintShots());
    m_controller->setParams(m_panel->params());
}

QString FootprintWorkspace::demoSummary() const { return tr("%1 simulated footprint shots").arg(m_controller->count()); }

QString FootprintWorkspace::claim(const InputProbe& probe, bool) const {
    static const QStringList frames = {"png", "tif", "tiff", "pgm", "raw", "bin"};
    if (probe.isDir) return key();
    if (frames.contains(probe.suffix) && !probe.gz) return key();
    if (probe.suffix == "csv" || probe.suffix == "txt") return probe.head.startsWith("file") ? key() : QString();
    return QString();
}

OpenOutcome FootprintWorkspace::openInputs(const QMap<QString, QStringList>& byRole, int) {
    OpenOutcome out;
    const QStringList paths = byRole.value(key());
    if (paths.isEmpty()) return out;
    m_controller->open(paths);  // in the background; errors come as the controller's error signal
    out.opened = out.replaced = true;
    // One entry for a folder or a shot list; several frames are remembered by their folder.
    out.recentPath = paths.size() == 1 ? paths.first() : QFileInfo(paths.first()).absolutePath();
    return out;
}

void FootprintWorkspace::chooseInputs() {
    QSettings st;
    QFileDialog dlg(this, tr("Open footprint frames, a folder, or a shot list (CSV)"), st.value("paths/lastInput").toString());
    dlg.setFileMode(QFileDialog::ExistingFiles);
    dlg.setNameFilters({tr("Frames and shot lists (*.png *.tif *.tiff *.pgm *.raw *.bin *.csv)"), tr("All files (*)")});
    if (!dlg.exec()) return;
    const QStringList files = dlg.selectedFiles();
    if (files.isEmpty()) return;
    st.setValue("paths/lastInput", QFileInfo(files.first()).absolutePath());
    emit openRequested(files);
}

void FootprintWorkspace::chooseFolder() {
    QSettings st;
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open a folder of footprint frames"), st.value("paths/lastInput").toString());
    if (dir.isEmpty()) return;
    st.setValue("paths/lastInput", dir);
    emit openRequested({dir});
}

void FootprintWorkspace::exportAcceptedShots() {
    const QString path = askSavePath(this, tr("Export accepted shots"), "paths/lastExport", "accepted_shots.csv", tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString err;
    int rows = 0;
    if (!m_controller->exportAccepted(path, &err, &rows)) emit failed(tr("Cannot export"), err);
    else emit status(m_controller->acceptedExportMessage(rows, path));
}

QList<QAction*> FootprintWorkspace::openActions() {
    auto* a = new QAction(tr("Frames, folder or shot list…"), this);
    connect(a, &QAction::triggered, this, &FootprintWorkspace::chooseInputs);
    return {a};
}

QList<QAction*> FootprintWorkspace::exportActions() {
    auto* a = new QAction(tr("Accepted shots (CSV)…"), this);
    connect(a, &QAction::triggered, this, &FootprintWorkspace::exportAcceptedShots);
    return {a};
}

QList<QAction*> FootprintWorkspace::fileOpenActions() {
    auto* frames = new QAction(tr("Open footprint &frames or shot list…"), this);
    connect(frames, &QAction::triggered, this, &FootprintWorkspace::chooseInputs);
    auto* folder = new QAction(tr("Open &folder of footprint frames…"), this);
    folder->setObjectName("actionOpenFolder");
    connect(folder, &QAction::triggered, this, &FootprintWorkspace::chooseFolder);
    return {frames, folder};
}

QList<QAction*> FootprintWorkspace::fileExportActions() {
    auto* accepted = new QAction(tr("Export accepted footprint shots…"), this);
    connect(accepted, &QAction::triggered, this, &FootprintWorkspace::exportAcceptedShots);
    auto* table = new QAction(tr("Export footprint review &table…"), this);
    table->setObjectName("actionExportReview");
    connect(table, &QAction::triggered, this, [this] { exportDialog(false); });
    return {accepted, table};
}

QStringList FootprintWorkspace::shortcutNotes() const {
    return {tr("↑ / ↓\tFootprint ▸ previous / next shot"), tr("A\tFootprint ▸ accept the shot and move on"),
            tr("R\tFootprint ▸ reject the shot and move on"),
            tr("N\tFootprint ▸ next shot of the view without a manual verdict"),
            tr("E\tFootprint ▸ note on the shot (Enter keeps it and returns to the table)"),
            tr("Tab, Shift+Tab\tFootprint ▸ leave the shot table (the shot stays)"),
            tr("2 / 4 / 8\tFootprint ▸ zoom the ROI and frame views 2×, 4×, 8× the fit"),
            tr("1\tFootprint ▸ fit the ROI and frame views again"),
            tr("B\tFootprint ▸ blink / tile the selected shots (Ctrl+click, Shift+click select several)"),
            tr("Space, ← / →, T / B\tBlink / tile ▸ play or pause, step, tile or blink")};
}

void FootprintWorkspace::cancelWork() {
    m_controller->cancelLoading();
    m_tuneJob->cancel();
}

void FootprintWorkspace::changeParams(const FootprintParams& p, const QString& what) {
    const FootprintParams before = m_controller->params();
    m_controller->setParams(p);
    pushParamsChange<FootprintParams>(
        this, footprintSchema(), before, p,
        [this](const FootprintParams& q) {
            m_panel->setParams(q);
            m_controller->setParams(q);
        },
        what);
    emit modified();
}

bool FootprintWorkspace::suggestThresholds() {
    using namespace core::footprint;
    if (m_controller->busy() || m_tuneJob->busy()) {
        emit failed(tr("No threshold suggestion yet"),
                    tr("The shots are still being processed: suggest again when they are done."));
        return false;
    }
    // The shots the analyst judged, as the verdict stage reads them.
    auto in = std::make_shared<VerdictTuneTask::Inputs>();
    for (int i = 0; i < m_controller->count(); ++i) {
        const Shot* s = m_controller->shot(i);
        if (!s->overridden || !s->processed) continue;
        LabelledShot l;
        l.name = overrideKey(*s).toStdString();
        l.measures = measureResult(s->result, s->roi.cols, s->roi.rows);
        if (!s->result.ok) l.measures.refusal = s->result.error.empty() ? "not processed" : s->result.error;
        l.label = s->overrideVerdict;
        in->shots.push_back(std::move(l));
    }
    m_tuneInputs = in;
    m_tuneJob->startNow();
    return true;
}

void FootprintWorkspace::showSuggestion(const core::footprint::VerdictTuneResult& r, int labelled) {
    using namespace core::footprint;
    if (!r.ok) {
        emit failed(tr("No threshold suggestion"),
                    tr("%1.\nThe criteria are tuned on the shots you gave a manual verdict (Accept A, Reject R): "
                       "at least 10, some good and some not.")
                        .arg(QString::fromStdString(r.error)));
        return;
    }
    // The shots' fits were made under r.before: a change of the fit since (a slider moved while
    // the task ran) makes the suggestion stale.
    if (!onlyVerdictDiffers(r.before, m_controller->params())) {
        emit failed(tr("No threshold suggestion"),
                    tr("The fit's parameters changed while the suggestion was made: suggest again."));
        return;
    }
    delete m_suggestion;
    m_suggestion = new QDialog(this);
    m_suggestion->setObjectName("thresholdSuggestion");
    m_suggestion->setWindowTitle(tr("Thresholds suggested from your verdicts"));
    auto* lay = new QVBoxLayout(m_suggestion);
    auto pct = [](int k, int n) { return n > 0 ? QString::number(100.0 * k / n, 'f', 1) + " %" : QStringLiteral("–"); };
    auto cell = [&](int k, int n) { return QStringLiteral("%1 of %2 (%3)").arg(k).arg(n).arg(pct(k, n)); };
    QString html = tr("<p>Tuned on the <b>%1</b> shots you gave a manual verdict.</p>").arg(labelled);
    if (r.changes.empty()) {
        html += tr("<p>No threshold moved: the current criteria are already the best found.</p>");
    } else {
        html += QStringLiteral("<table cellpadding='3'><tr><th align='left'>%1</th><th>%2</th><th>%3</th></tr>")
                    .arg(tr("Criterion"), tr("Now"), tr("Suggested"));
        for (const VerdictChange& c : r.changes) {
            // The row as the panel names it, and which end moved.
            const QString end = c.end == "lo" ? tr("min") : c.end == "hi" ? tr("max") : QString::fromStdString(c.end);
            html += QStringLiteral("<tr><td>%1</td><td align='right'>%2</td><td align='right'><b>%3</b></td></tr>")
                        .arg((m_panel->rowLabel(c.key) + " " + end).trimmed().toHtmlEscaped(),
                             QString::number(c.before, 'g', 4), QString::number(c.after, 'g', 4));
        }
        html += QStringLiteral("</table>");
    }
    const VerdictConfusion &b = r.confusionBefore, &a = r.confusionAfter, &h = r.heldOut;
    html += QStringLiteral("<p><table cellpadding='3'><tr><th></th><th>%1</th><th>%2</th>%3</tr>")
                .arg(tr("Now"), tr("Suggested"), r.folds ? QStringLiteral("<th>%1</th>").arg(tr("Held out")) : QString());
    html += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td>%4</tr>")
                .arg(tr("Your good shots judged not good"), cell(b.falseDoubts(), b.analystGood()),
                     cell(a.falseDoubts(), a.analystGood()),
                     r.folds ? QStringLiteral("<td>%1</td>").arg(cell(h.falseDoubts(), h.analystGood())) : QString());
    html += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td>%4</tr></table></p>")
                .arg(tr("Your other shots judged good"), cell(b.misses(), b.analystNotGood()),
                     cell(a.misses(), a.analystNotGood()),
                     r.folds ? QStringLiteral("<td>%1</td>").arg(cell(h.misses(), h.analystNotGood())) : QString());
    if (r.folds)
        html += tr("<p><i>Held out: each shot judged by criteria tuned without it (%1-fold cross-validation), "
                   "what to expect on shots not yet reviewed.</i></p>")
                    .arg(r.folds);
    auto* text = new QLabel(html, m_suggestion);
    text->setObjectName("suggestionText");
    text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(text);
    auto* buttons = new QDialogButtonBox(m_suggestion);
    QPushButton* apply = buttons->addButton(tr("Apply"), QDialogButtonBox::AcceptRole);
    apply->setObjectName("applySuggestion");
    apply->setEnabled(!r.changes.empty());
    apply->setToolTip(tr("Sets the suggested criteria in the parameters (one step: Edit > Undo takes it back)"));
    buttons->addButton(QDialogButtonBox::Close);
    lay->addWidget(buttons);
    const VerdictParams suggested = r.after.verdict;
    connect(buttons, &QDialogButtonBox::accepted, m_suggestion, [this, suggested] {
        // The verdict criteria alone, over the parameters of now (the rest stays as it is).
        FootprintParams p = m_controller->params();
        p.verdict = suggested;
        m_panel->setParams(p);
        changeParams(p, tr("verdict thresholds to the suggested ones"));
        m_suggestion->accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, m_suggestion, &QDialog::reject);
    m_suggestion->open();
}

void FootprintWorkspace::refreshStrips() {
    using namespace core::footprint;
    if (m_controller->busy()) {  // (the rejudge's end starts the timer again)
        m_stripTimer->start();
        return;
    }
    if (m_stripWork) m_stripWork->cancel();
    auto work = std::make_shared<core::Feedback>();
    m_stripWork = work;
    // What the verdict stage reads of each shot, and the analyst's verdicts.
    auto shots = std::make_shared<std::vector<VerdictMeasures>>();
    auto labels = std::make_shared<std::vector<int>>();
    for (const Shot& s : m_controller->shots()) {
        if (!s.processed) continue;
        shots->push_back(measureResult(s.result, s.roi.cols, s.roi.rows));
        if (!s.result.ok) shots->back().refusal = s.result.error.empty() ? "not processed" : s.result.error;
        labels->push_back(s.overridden ? int(s.overrideVerdict) : -1);
    }
    // Every verdict threshold the panel shows with a slider, switched on.
    struct Strip {
        std::string key, end;
        QPointer<ParamSlider> slider;
        std::vector<double> values;
        CriterionSweep sweep;
    };
    auto strips = std::make_shared<std::vector<Strip>>();
    const FootprintParams params = m_controller->params();
    for (const auto& f : footprintSchema().fields()) {
        if (f.key.rfind("verdict.", 0) != 0) continue;
        QWidget* w = m_panel->form().widget(f.key);
        if (auto* range = qobject_cast<RangeEdit*>(w)) {
            const bool on = f.getRange(params).enabled;
            for (auto [end, slider] : {std::pair<const char*, ParamSlider*>{"lo", range->loSlider()}, {"hi", range->hiSlider()}})
                if (on) strips->push_back({f.key, end, slider, slider->trackValues(48), {}});
                else slider->clearStrip();
        } else if (auto* slider = qobject_cast<ParamSlider*>(w)) {
            const bool on = std::isfinite(f.get(params)) && slider->slider()->isEnabled();
            if (on) strips->push_back({f.key, "", slider, slider->trackValues(48), {}});
            else slider->clearStrip();
        }
    }
    if (shots->empty()) {
        for (Strip& s : *strips)
            if (s.slider) s.slider->clearStrip();
        return;
    }
    QPointer<FootprintWorkspace> self(this);
    (void)QtConcurrent::run([self, work, shots, labels, strips, params] {
        for (Strip& s : *strips) {
            s.sweep = sweepCriterion(*shots, *labels, params, s.key, s.end, s.values, work.get());
            if (work->isCancelled()) return;
        }
        QMetaObject::invokeMethod(qApp, [self, work, strips] {
            if (!self || work->isCancelled() || self->m_stripWork != work) return;
            for (Strip& s : *strips) {
                if (!s.slider || s.sweep.changed.size() != s.values.size()) continue;
                const CriterionSweep& w = s.sweep;
                const int most = *std::max_element(w.changed.begin(), w.changed.end());
                std::vector<double> area, line;
                for (int c : w.changed) area.push_back(most > 0 ? double(c) / most : 0.0);
                QString tip = tr("Strip: shots whose verdict would change along the slider (up to %1)").arg(most);
                if (w.labelled > 0) {
                    const auto [lo, hi] = std::minmax_element(w.disagree.begin(), w.disagree.end());
                    for (int d : w.disagree) line.push_back(*hi > *lo ? double(d - *lo) / (*hi - *lo) : 0.5);
                    tip += tr("; orange: disagreements with your %1 manual verdicts (%2 to %3, fewest at %4)")
                               .arg(w.labelled)
                               .arg(*lo)
                               .arg(*hi)
                               .arg(QString::number(s.values[size_t(lo - w.disagree.begin())], 'g', 4));
                }
                s.slider->setStrip(std::move(area), std::move(line), tip);
            }
            emit self->stripsReady();
        });
    });
}

}  // namespace lwb::ui
