#include <cmath>
#include "ui/main_window.hpp"

#include "core/common/atomic_file.hpp"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QDockWidget>
#include <QDialogButtonBox>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QJsonDocument>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QMimeData>
#include <QPainter>
#include <QProgressBar>
#include <QProxyStyle>
#include <QPushButton>
#include <QSaveFile>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QStyleFactory>
#include <QTabWidget>
#include <QUndoGroup>
#include <QUndoStack>
#include <QTableWidget>
#include <QTextBrowser>
#include <QRegularExpression>
#include <QTextDocument>
#include <QTextCursor>
#include <QTextBlock>
#include <QToolButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include "core/common/json.hpp"
#include "ui/app_undo.hpp"
#include "ui/demo.hpp"
#include "ui/save_path.hpp"
#include "ui/workspace_layout.hpp"
#include "ui/footprint_params_panel.hpp"
#include "ui/footprint_workspace.hpp"
#include "ui/slr_controller.hpp"
#include "ui/slr_workspace.hpp"
#include "ui/calib_workspace.hpp"
#include "ui/plot_kit.hpp"
#include "ui/radiometry_workspace.hpp"

// The resources live in the static ui library: registered here, or the linker may drop them.
static void initUiResources() { Q_INIT_RESOURCE(laserwb); }

namespace lwb::ui {

namespace {
constexpr int kSessionVersion = 1;
constexpr int kMaxRecent = 8;

const QStringList kCrdSuffixes = {"frd", "fr2", "npt", "np2", "crd", "v2c", "qlk"};
const QStringList kImageSuffixes = {"png", "tif", "tiff", "pgm", "raw", "bin"};

// The first line that is not empty or a comment, lower-cased (for telling CSV kinds apart).
// The first line that is not blank or a '#' comment, lower case: of the decompressed text when
// the file is gzip-compressed. Only regular files are looked into (a FIFO would block).
QString firstLine(const QString& path) {
    std::string head, why;
    if (!lwb::core::readFileHead(path.toStdString(), 65536, &head, &why)) return QString();
    const QStringList lines = QString::fromUtf8(head.data(), int(head.size())).split('\n');
    for (int i = 0; i < 50 && i < lines.size(); ++i) {
        const QString line = lines[i].trimmed().toLower();
        if (!line.isEmpty() && !line.startsWith('#')) return line;
    }
    return QString();
}

// Fusion draws a checked radio button as a 4 px grey dot (the text colour, darkened and half
// transparent) on a disc of the base colour, in a ring of the window colour darkened: in the
// dark palette neither the ring nor the dot stands out, and which mode was on could hardly be
// told (issue 30). In a dark palette this style draws the ring in a light grey and a checked
// button as a disc of the accent colour around a white dot; a light palette keeps Fusion's.
class WorkbenchStyle : public QProxyStyle {
public:
    WorkbenchStyle() : QProxyStyle(QStyleFactory::create("Fusion")) {}

    void drawPrimitive(PrimitiveElement pe, const QStyleOption* o, QPainter* p, const QWidget* w) const override {
        if (pe != PE_IndicatorRadioButton || o->palette.color(QPalette::Base).lightness() >= 128) {
            QProxyStyle::drawPrimitive(pe, o, p, w);
            return;
        }
        const bool on = o->state & State_On, enabled = o->state & State_Enabled;
        const QColor accent = o->palette.color(enabled ? QPalette::Active : QPalette::Disabled, QPalette::Highlight);
        QColor ring = o->palette.color(enabled ? QPalette::Active : QPalette::Disabled, QPalette::Text);
        ring.setAlpha(on ? 255 : 170);
        if (on) ring = accent.lighter(135);
        if ((o->state & State_HasFocus) && (o->state & State_KeyboardFocusChange)) ring = accent.lighter(170);
        QColor fill = on ? accent : o->palette.color(QPalette::Base);
        if (o->state & State_Sunken) fill = fill.lighter(140);
        const QRectF r(o->rect);
        const double radius = std::min(r.width(), r.height()) / 2 - 0.75;
        p->save();
        p->setRenderHint(QPainter::Antialiasing, true);
        p->setPen(QPen(ring, 1.5));
        p->setBrush(fill);
        p->drawEllipse(r.center(), radius, radius);
        if (on) {
            p->setPen(Qt::NoPen);
            p->setBrush(o->palette.color(QPalette::HighlightedText));
            p->drawEllipse(r.center(), radius * 0.4, radius * 0.4);
        }
        p->restore();
    }
};

QPalette darkPalette() {
    QPalette p;
    const QColor window(45, 47, 50), base(30, 32, 35), text(225, 225, 225), disabled(125, 125, 125), accent(42, 130, 218);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, QColor(40, 42, 46));
    p.setColor(QPalette::ToolTipBase, QColor(55, 57, 60));
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, QColor(160, 160, 160));
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, window);
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, Qt::red);
    p.setColor(QPalette::Link, QColor(90, 170, 255));
    p.setColor(QPalette::Highlight, accent);
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::Light, QColor(70, 72, 76));
    p.setColor(QPalette::Midlight, QColor(60, 62, 66));
    p.setColor(QPalette::Mid, QColor(40, 42, 45));
    p.setColor(QPalette::Dark, QColor(25, 26, 28));
    p.setColor(QPalette::Shadow, Qt::black);
    for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::HighlightedText})
        p.setColor(QPalette::Disabled, role, disabled);
    p.setColor(QPalette::Disabled, QPalette::Base, window);
    p.setColor(QPalette::Disabled, QPalette::Highlight, QColor(80, 80, 80));
    return p;
}
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    initUiResources();
    setWindowIcon(QIcon(":/icons/laserwb.svg"));
    m_tabs = new QTabWidget(this);
    m_tabs->setDocumentMode(true);
    m_footprint = new FootprintWorkspace(m_tabs);
    m_tabs->addTab(m_footprint, tr("Footprint review"));
    m_slr = new SlrWorkspace(m_tabs);
    m_tabs->addTab(m_slr, tr("SLR pass screening"));
    m_calib = new CalibWorkspace(m_tabs);
    m_tabs->addTab(m_calib, tr("Altimeter calibration"));
    m_radiometry = new RadiometryWorkspace(m_tabs);
    m_tabs->addTab(m_radiometry, tr("Radiometry"));
    setCentralWidget(m_tabs);
    // A plot's minimum width is otherwise its legend's natural width: the SLR workspace's two
    // plots side by side, each with a three-column legend, asked for a 1271 px window. Plots
    // without a minimum of their own get a small one (a long legend is then clipped, not the window).
    for (QCustomPlot* p : m_tabs->findChildren<QCustomPlot*>())
        if (p->minimumWidth() == 0) p->setMinimumWidth(160);
    buildMenus();
    connect(m_footprint, &FootprintWorkspace::modified, this, [this] { markUnsaved(m_footprint); });
    connect(m_footprint, &FootprintWorkspace::status, this, [this](const QString& s) { workspaceStatus(m_footprint, s, 5000); });
    connect(m_slr, &SlrWorkspace::modified, this, [this] { markUnsaved(m_slr); });
    connect(m_slr, &SlrWorkspace::openRequested, this, [this](const QString& path) { openPaths({path}); });
    connect(m_slr, &SlrWorkspace::status, this, [this](const QString& s) { workspaceStatus(m_slr, s, 8000); });
    connect(m_calib, &CalibWorkspace::modified, this, [this] { markUnsaved(m_calib); });
    connect(m_calib, &CalibWorkspace::status, this, [this](const QString& s) { workspaceStatus(m_calib, s, 8000); });
    connect(m_radiometry, &RadiometryWorkspace::modified, this, [this] { markUnsaved(m_radiometry); });
    connect(m_radiometry, &RadiometryWorkspace::status, this, [this](const QString& s) { workspaceStatus(m_radiometry, s, 8000); });
    connect(m_footprint->controller(), &FootprintController::error, this,
            [this](const QString& msg) { showError(tr("Cannot open the footprint inputs"), msg); });
    // Progress of long loads, with a cancel button, in the status bar.
    m_progress = new QProgressBar(this);
    m_progress->setObjectName("loadProgress");
    m_progress->setMaximumWidth(260);
    m_progress->setFormat(tr("%v / %m shots"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName("loadCancel");
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancel);
    m_progress->hide();
    m_cancel->hide();
    FootprintController* fc = m_footprint->controller();
    connect(fc, &FootprintController::loadProgress, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
        m_progress->setVisible(done < total);
        m_cancel->setVisible(done < total);
    });
    connect(fc, &FootprintController::loadFinished, this, [this] {
        m_progress->hide();
        m_cancel->hide();
    });
    connect(m_cancel, &QPushButton::clicked, fc, &FootprintController::cancelLoading);
    // New data: the undo history refers to the data it was made on.
    // Each workspace's own history: new data in one leaves the others' alone.
    connect(fc, &FootprintController::shotsReset, this, [this] { undoStackOf(m_footprint).clear(); });
    connect(m_slr->controller(), &SlrController::passChanged, this, [this] { undoStackOf(m_slr).clear(); });
    connect(m_calib->controller(), &CalibController::inputsChanged, this, [this] { undoStackOf(m_calib).clear(); });
    connect(m_radiometry->controller(), &RadiometryController::imageChanged, this, [this] { undoStackOf(m_radiometry).clear(); });
    setAcceptDrops(true);
    QSettings st;
    // The last geometry, else 1480 × 900; either fitted to the screen's available area (a
    // 1024 × 700 screen, or 1920 × 1080 at 150 %: 1280 × 720 logical, had the panel and the
    // status bar off-screen).
    if (!restoreGeometry(st.value("window/geometry").toByteArray())) resize(1480, 900);
    if (!isMaximized() && !isFullScreen())
        if (const QScreen* sc = screen() ? screen() : QGuiApplication::primaryScreen())
            setGeometry(fitWindowToScreen(geometry(), minimumSizeHint(), sc->availableGeometry(), QMargins(0, 30, 0, 0)));
    restoreDockLayouts(this);  // each workspace's panels as they were left
    setDarkTheme(st.value("view/theme").toString() == "dark");
    statusBar()->showMessage(tr("Ready"));
    setModified(false);
}

void MainWindow::workspaceStatus(QWidget* workspace, const QString& message, int timeoutMs) {
    // Only the workspace in front speaks in the status bar: a workspace working in the
    // background (the radiometry demo mosaic at start-up) must not cover the current one's line.
    if (m_tabs->currentWidget() == workspace) statusBar()->showMessage(message, timeoutMs);
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open… (current workspace)"), QKeySequence::Open, this, &MainWindow::openForCurrent)
        ->setToolTip(tr("Opens the inputs of the workspace in front"));
    file->addAction(tr("Open footprint &frames or shot list…"), this, &MainWindow::openInputs);
    file->addAction(tr("Open &folder of footprint frames…"), this, &MainWindow::openFolder)->setObjectName("actionOpenFolder");
    file->addAction(tr("Open &demo"), this, &MainWindow::openDemo);
    m_recentInputsMenu = file->addMenu(tr("Recent &inputs"));
    file->addSeparator();
    file->addAction(tr("Open &session…"), QKeySequence(tr("Ctrl+Shift+O")), this, &MainWindow::openSessionDialog);
    m_recentMenu = file->addMenu(tr("&Recent sessions"));
    file->addAction(tr("&Save session"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save session &as…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    file->addSeparator();
    file->addAction(tr("&Export… (current workspace)"), QKeySequence(tr("Ctrl+E")), this, &MainWindow::exportForCurrent);
    file->addAction(tr("Export accepted footprint shots…"), this, &MainWindow::exportAccepted);
    file->addAction(tr("Export footprint review &table…"), this, [this] { m_footprint->exportDialog(false); })
        ->setObjectName("actionExportReview");
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    // Edit ▸ Undo acts on the current workspace's history (the group's active stack).
    QAction* undo = appUndoGroup().createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = appUndoGroup().createRedoAction(this, tr("&Redo"));
    redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
    edit->addAction(undo);
    edit->addAction(redo);
    appUndoGroup().setActiveStack(&undoStackOf(m_tabs->currentWidget()));

    QMenu* view = menuBar()->addMenu(tr("&View"));
    m_workspaceGroup = new QActionGroup(this);
    for (int i = 0; i < m_tabs->count(); ++i) {
        QAction* a = view->addAction(m_tabs->tabText(i), this, [this, i] { m_tabs->setCurrentIndex(i); });
        a->setShortcut(QKeySequence(tr("Ctrl+%1").arg(i + 1)));
        a->setCheckable(true);
        a->setChecked(i == m_tabs->currentIndex());
        m_workspaceGroup->addAction(a);
    }
    connect(m_tabs, &QTabWidget::currentChanged, this, [this](int i) {
        const auto acts = m_workspaceGroup->actions();
        if (i >= 0 && i < acts.size()) acts[i]->setChecked(true);
        if (QWidget* ws = m_tabs->widget(i)) appUndoGroup().setActiveStack(&undoStackOf(ws));
        statusBar()->clearMessage();
    });
    view->addSeparator();
    m_panelsAction = view->addAction(tr("&Parameter panels"), this, [this](bool on) { setPanelsVisible(on); });
    m_panelsAction->setCheckable(true);
    m_panelsAction->setChecked(true);
    m_panelsAction->setShortcut(QKeySequence(tr("Ctrl+Shift+P")));
    // Every workspace's docks (shown, hidden) and the arrangement back as it first was.
    QMenu* panelsMenu = view->addMenu(tr("P&anels"));
    for (QDockWidget* d : workspaceDocks(this)) {
        QAction* t = d->toggleViewAction();
        QString ws;
        for (int i = 0; i < m_tabs->count(); ++i)
            if (m_tabs->widget(i)->isAncestorOf(d)) ws = m_tabs->tabText(i).remove('&');
        t->setText(QStringLiteral("%1: %2").arg(ws, d->windowTitle()));
        panelsMenu->addAction(t);
    }
    panelsMenu->addSeparator();
    panelsMenu->addAction(tr("&Reset panel layout"), this, [this] {
        resetDockLayouts(this);
        if (m_panelsAction) m_panelsAction->setChecked(true);
    });
    QAction* sb = view->addAction(tr("&Status bar"), this, [this](bool on) { statusBar()->setVisible(on); });
    sb->setCheckable(true);
    sb->setChecked(true);
    QAction* fs = view->addAction(tr("&Full screen"), this, [this](bool on) {
        if (on) showFullScreen();
        else showNormal();
    });
    fs->setCheckable(true);
    // F11 on every platform: QKeySequence::FullScreen is F11 only under some desktops' themes
    // (none under plain X11), so the guide's F11 did nothing in a real window (issue 42).
    fs->setShortcut(QKeySequence(Qt::Key_F11));
    view->addSeparator();
    auto* themes = new QActionGroup(this);
    m_lightAction = view->addAction(tr("&Light theme"), this, [this] { setDarkTheme(false); });
    m_darkAction = view->addAction(tr("&Dark theme"), this, [this] { setDarkTheme(true); });
    for (QAction* a : {m_lightAction, m_darkAction}) {
        a->setCheckable(true);
        themes->addAction(a);
    }
    m_lightAction->setChecked(true);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&User guide"), QKeySequence::HelpContents, this, &MainWindow::showUserGuide);
    help->addAction(tr("&Keyboard shortcuts"), this, &MainWindow::showShortcuts);
    help->addSeparator();
    help->addAction(tr("&About"), this, [this] {
        QMessageBox::about(this, tr("About Laser Workbench"),
                           tr("<b>Laser Workbench</b> %1<br>Footprint spot centres, SLR signal extraction, "
                              "altimeter and radiometric calibration.<br>Every GUI action has a batch "
                              "equivalent in <tt>laserwb-cli</tt>.<br><br>Free software under the GNU General "
                              "Public License, version 3 or later. The methods and their papers: "
                              "docs/algorithms.md and docs/references.md.")
                               .arg(QApplication::applicationVersion()));
    });
    rebuildRecentMenu();
    rebuildRecentInputsMenu();
}

void MainWindow::setDarkTheme(bool dark) {
    m_dark = dark;
    QApplication::setStyle(new WorkbenchStyle);  // Fusion, with radio buttons readable in the dark palette
    QApplication::setPalette(dark ? darkPalette() : QApplication::style()->standardPalette());
    setPlotTheme(dark);
    if (m_darkAction) (dark ? m_darkAction : m_lightAction)->setChecked(true);
    QSettings().setValue("view/theme", dark ? "dark" : "light");
}

void MainWindow::setPanelsVisible(bool visible) {
    // The parameter panels: every workspace's dock "<workspace>.parameters" (ui/workspace_layout).
    for (QDockWidget* d : workspaceDocks(this))
        if (d->objectName().endsWith(".parameters")) d->setVisible(visible);
    if (m_panelsAction) m_panelsAction->setChecked(visible);
}

QStringList MainWindow::shortcutList() const {
    QStringList out;
    std::function<void(const QList<QAction*>&, const QString&)> walk = [&](const QList<QAction*>& acts, const QString& menu) {
        for (QAction* a : acts) {
            if (a->menu()) {
                walk(a->menu()->actions(), a->menu()->title().remove('&'));
                continue;
            }
            const QList<QKeySequence> keys = a->shortcuts();
            if (keys.isEmpty()) continue;
            QStringList ks;
            for (const QKeySequence& k : keys) ks << k.toString(QKeySequence::NativeText);
            QString text = a->text().remove('&');
            text = text.split('\t').first();
            out << ks.join(", ") + "\t" + menu + " ▸ " + text;
        }
    };
    walk(menuBar()->actions(), QString());
    out << tr("↑ / ↓\tFootprint ▸ previous / next shot") << tr("A\tFootprint ▸ accept the shot and move on")
        << tr("R\tFootprint ▸ reject the shot and move on")
        << tr("N\tFootprint ▸ next shot of the view without a manual verdict")
        << tr("E\tFootprint ▸ note on the shot (Enter keeps it and returns to the table)")
        << tr("Tab, Shift+Tab\tFootprint ▸ leave the shot table (the shot stays)")
        << tr("2 / 4 / 8\tFootprint ▸ zoom the ROI and frame views 2×, 4×, 8× the fit")
        << tr("1\tFootprint ▸ fit the ROI and frame views again")
        << tr("B\tFootprint ▸ blink / tile the selected shots (Ctrl+click, Shift+click select several)");
    out << tr("Right-drag, Shift+drag\tImage view ▸ box zoom") << tr("Home, double-click\tImage view ▸ fit")
        << tr("Right-click\tImage view ▸ menu: zoom steps, mouse mode (pan, box or circle regions), reset contrast and bias, export the view")
        << tr("Middle-drag, Ctrl+drag\tImage view ▸ contrast (up / down) and bias (left / right), as DS9's right-drag")
        << tr("Drag on the colour bar\tImage view ▸ contrast and bias; a double-click on the bar resets them")
        << tr("Drag (region mode)\tImage view ▸ draw a box or circle region; drag a region to move it")
        << tr("Delete\tImage view ▸ delete the selected region (the view reached by Tab)")
        << tr("Space, ← / →, T / B\tBlink / tile ▸ play or pause, step, tile or blink");
    out << tr("Wheel\tPlot ▸ zoom both axes about the cursor") << tr("Shift+Wheel\tPlot ▸ zoom x only")
        << tr("Ctrl+Wheel\tPlot ▸ zoom y only") << tr("Wheel / drag over an axis\tPlot ▸ zoom / pan that axis only")
        << tr("Drag\tPlot ▸ pan") << tr("Right-drag, Shift+drag\tPlot ▸ box zoom")
        << tr("Double-click, Home\tPlot ▸ reset to the home view") << tr("Backspace\tPlot ▸ back in the zoom history")
        << tr("Right-click\tPlot ▸ export PNG / SVG / PDF, copy to the clipboard")
        << tr("Click a legend entry\tPlot ▸ hide / show its series")
        << tr("Hover\tPlot ▸ crosshair with the coordinates (a colour map's value too)")
        << tr("Hover\tSLR ▸ one time cursor on the O-C plot, the binary image and the histogram");
    return out;
}

void MainWindow::showShortcuts() {
    auto* dlg = new QDialog(this);
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    dlg->setWindowTitle(tr("Keyboard shortcuts"));
    auto* lay = new QVBoxLayout(dlg);
    const QStringList rows = shortcutList();
    auto* t = new QTableWidget(int(rows.size()), 2, dlg);
    t->setHorizontalHeaderLabels({tr("Keys"), tr("What")});
    t->verticalHeader()->hide();
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->horizontalHeader()->setStretchLastSection(true);
    for (int i = 0; i < rows.size(); ++i) {
        const QStringList parts = rows[i].split('\t');
        t->setItem(i, 0, new QTableWidgetItem(parts.value(0)));
        t->setItem(i, 1, new QTableWidgetItem(parts.value(1)));
    }
    t->resizeColumnToContents(0);
    lay->addWidget(t);
    auto* bb = new QDialogButtonBox(QDialogButtonBox::Close, dlg);
    connect(bb, &QDialogButtonBox::rejected, dlg, &QDialog::close);
    lay->addWidget(bb);
    dlg->resize(560, 520);
    dlg->show();
}

void MainWindow::showUserGuide() {
    auto* dlg = new QDialog(this);
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    dlg->setWindowTitle(tr("Laser Workbench — user guide"));
    auto* lay = new QVBoxLayout(dlg);
    auto* b = new QTextBrowser(dlg);
    b->setObjectName("userGuide");
    b->setOpenExternalLinks(true);
    // The guide as the program shows it: without the paragraphs for developers (between
    // <!-- developer --> and <!-- /developer -->: building, rendering the screenshots), and its
    // pictures no wider than the window (issue 30: shown at their full 1480 px, and "make run").
    QFile f(QStringLiteral(":/docs/user-guide.md"));
    QString text = f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : tr("The user guide is missing.");
    text.remove(QRegularExpression(QStringLiteral("<!-- developer -->.*?<!-- /developer -->"),
                                   QRegularExpression::DotMatchesEverythingOption));
    b->document()->setBaseUrl(QUrl(QStringLiteral("qrc:/docs/")));
    b->setMarkdown(text);
    lay->addWidget(b);
    auto* bb = new QDialogButtonBox(QDialogButtonBox::Close, dlg);
    connect(bb, &QDialogButtonBox::rejected, dlg, &QDialog::close);
    lay->addWidget(bb);
    dlg->resize(std::min(900, width()), std::min(760, height()));
    fitGuideImages(b, dlg->width() - 60);
    dlg->show();
}

// Every picture of a text browser at most `width` pixels wide (its height in proportion).
void MainWindow::fitGuideImages(QTextBrowser* browser, int width) {
    QTextDocument* doc = browser->document();
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next())
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment frag = it.fragment();
            QTextImageFormat img = frag.charFormat().toImageFormat();
            if (!img.isValid()) continue;
            const QImage picture(":/docs/" + img.name());
            if (picture.isNull() || picture.width() <= width) continue;
            img.setWidth(width);
            img.setHeight(double(width) * picture.height() / picture.width());
            QTextCursor c(doc);
            c.setPosition(frag.position());
            c.setPosition(frag.position() + frag.length(), QTextCursor::KeepAnchor);
            c.setCharFormat(img);
        }
}

void MainWindow::showError(const QString& what, const QString& detail) {
    statusBar()->showMessage(what, 8000);
    if (qApp->platformName() == "offscreen") {
        qWarning("%s: %s", qPrintable(what), qPrintable(detail));
        return;
    }
    QMessageBox::warning(this, what, detail);
}

void MainWindow::inputsOpened(QWidget* workspace) {
    // Other data than the session file describes: Save asks for a name (Ctrl+S replaced the
    // restored session, its verdicts and notes, with the new data). The workspace's unsaved
    // work was offered for saving before (maybeSave(workspace)) and is replaced; the other
    // workspaces keep theirs (issue 42: opening a pass cleared the footprint review's unsaved
    // verdicts, and Ctrl+Q then quit without asking).
    m_sessionPath.clear();
    QPointer<QWidget> ws(workspace);
    QMetaObject::invokeMethod(this, [this, ws] { markSaved(ws); }, Qt::QueuedConnection);  // after the workspace's own signals
    markSaved(workspace);
}

void MainWindow::markUnsaved(QWidget* workspace) {
    m_unsaved.insert(workspace);
    setModified(true);
}

void MainWindow::markSaved(QWidget* workspace) {
    m_unsaved.remove(workspace);
    setModified(!m_unsaved.isEmpty());
}

void MainWindow::setModified(bool m) {
    if (!m) m_unsaved.clear();  // (the whole session saved, opened or replaced)
    const QString name = m_sessionPath.isEmpty() ? tr("untitled") : QFileInfo(m_sessionPath).fileName();
    setWindowTitle(tr("%1%2 — Laser Workbench").arg(name, m ? "*" : ""));
}

bool MainWindow::openDemo() {
    if (!maybeSave()) return false;
    m_footprint->controller()->setShots(demoFootprintShots());
    m_footprint->controller()->setParams(m_footprint->paramsPanel()->params());
    m_slr->openDemo();
    m_calib->openDemo();
    m_radiometry->openDemo();
    statusBar()->showMessage(tr("Built-in demo: %1 simulated footprint shots, a simulated kHz pass, a simulated "
                                "calibration and a synthetic radiometric scene")
                                 .arg(m_footprint->controller()->count()),
                             8000);
    m_sessionPath.clear();
    clearUndoHistories();
    setModified(false);
    return true;
}

bool MainWindow::openFootprintInputs(const QStringList& paths) {
    if (paths.isEmpty() || !maybeSave(m_footprint)) return false;
    m_footprint->controller()->open(paths);
    inputsOpened(m_footprint);
    // One entry for a folder or a shot list; several frames are remembered by their folder.
    const QString first = paths.first();
    addRecentInput("footprint", paths.size() == 1 ? first : QFileInfo(first).absolutePath());
    return true;
}

void MainWindow::openFolder() {
    QSettings st;
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open a folder of footprint frames"),
                                                          st.value("paths/lastInput").toString());
    if (dir.isEmpty()) return;
    st.setValue("paths/lastInput", dir);
    openFootprintInputs({dir});
}

void MainWindow::openInputs() {
    QSettings st;
    const QString dir = st.value("paths/lastInput").toString();
    QFileDialog dlg(this, tr("Open footprint frames, a folder, or a shot list (CSV)"), dir);
    dlg.setFileMode(QFileDialog::ExistingFiles);
    dlg.setNameFilters({tr("Frames and shot lists (*.png *.tif *.tiff *.pgm *.raw *.bin *.csv)"), tr("All files (*)")});
    if (!dlg.exec()) return;
    QStringList files = dlg.selectedFiles();
    if (files.isEmpty()) return;
    st.setValue("paths/lastInput", QFileInfo(files.first()).absolutePath());
    openFootprintInputs(files);
}

QString MainWindow::workspaceForPath(const QString& path) const {
    const QFileInfo fi(path);
    if (fi.isDir()) return "footprint";
    const QString suffix = QString::fromStdString(lwb::core::inputExtension(path.toStdString()));  // (without .gz)
    const bool gz = fi.suffix().toLower() == "gz";
    if (kImageSuffixes.contains(suffix) && !gz)
        return m_tabs->currentWidget() == m_radiometry && suffix != "raw" && suffix != "bin" ? "radiometry" : "footprint";
    const QString head = firstLine(path);
    // A prediction or station coordinates go with the SLR pass (by their first record or name).
    if (head.startsWith("h1 cpf") || suffix == "cpf" || suffix == "hts") return "slr-cpf";
    if (head.startsWith("%=snx") || suffix == "snx") return "slr-sinex";
    // A station's normal points (.npt, .np2) go beside the pass they were formed from.
    if (suffix == "npt" || suffix == "np2") return "slr-npt";
    if (kCrdSuffixes.contains(suffix)) return "slr";
    if (suffix == "json") return head.contains("{") || head.isEmpty() ? "session" : QString();
    if (suffix == "csv" || suffix == "txt") {
        if (head.contains("oc_s") || head.contains("epoch_s")) return "slr";
        if (head.startsWith("file")) return "footprint";
        return QString();
    }
    // No or another ending: a CRD file is told by its first record.
    if (head.startsWith("h1 ") || head.startsWith("h1\t")) return "slr";
    return QString();
}

bool MainWindow::openPaths(const QStringList& paths, QString* errorOut) {
    QStringList problems, footprint, radiometry, cpf, sinex, npt;
    for (const QString& p : paths) {
        if (!QFileInfo::exists(p)) {
            problems << tr("%1: no such file or folder").arg(p);
            continue;
        }
        const QString where = workspaceForPath(p);
        if (where == "slr-cpf") {
            cpf << p;  // after the pass (given before or after it)
        } else if (where == "slr-sinex") {
            sinex << p;
        } else if (where == "slr-npt") {
            npt << p;  // after the pass (given before or after it)
        } else if (where == "footprint") {
            footprint << p;
        } else if (where == "radiometry") {
            radiometry << p;
        } else if (where == "slr") {
            QString err;
            if (!maybeSave(m_slr)) continue;
            if (!m_slr->openPath(p, -1, &err)) problems << err;
            else {
                m_tabs->setCurrentWidget(m_slr);
                addRecentInput("slr", p, m_slr->controller()->pass().passIndex);
                inputsOpened(m_slr);
            }
        } else if (where == "session") {
            if (!maybeSave()) continue;
            QString err;
            if (!openSession(p, true, &err)) problems << err;
        } else {
            problems << tr("%1: not a file the workbench opens (CRD, CPF, SINEX, O-C or shot-list CSV, images, a "
                           "folder of frames, a session)")
                            .arg(p);
        }
    }
    // A station's normal points: compared with the open pass (Station normal points tab); with no
    // pass open there is nothing to compare them with (a normal-point file is not screened).
    if (npt.size() > 1) {
        problems << tr("%1 and %2: one station normal-point file at a time").arg(npt.at(0), npt.at(1));
    } else if (npt.size() == 1 && !m_slr->controller()->hasPass()) {
        problems << tr("%1: a station's normal points are compared with the full-rate pass they were formed from, "
                       "and no pass is open: open the pass and this file together, or this file in the Station normal "
                       "points tab of the open pass")
                        .arg(npt.first());
    } else if (npt.size() == 1) {
        QString err;
        if (!m_slr->setStationNormalPoints(npt.first(), &err)) problems << err;
        else m_tabs->setCurrentWidget(m_slr);
    }
    for (const QStringList* list : {&sinex, &cpf}) {
        if (list->size() > 1) {
            problems << tr("%1 and %2: one %3 at a time").arg(list->at(0), list->at(1), list == &cpf ? tr("prediction") : tr("station file"));
            continue;
        }
        if (list->isEmpty()) continue;
        QString err;
        const bool ok = list == &cpf ? m_slr->setCpf(list->first(), &err) : m_slr->setSinex(list->first(), &err);
        if (!ok) problems << err;
        else m_tabs->setCurrentWidget(m_slr);
    }
    if (!footprint.isEmpty()) {
        openFootprintInputs(footprint);
        m_tabs->setCurrentWidget(m_footprint);
    }
    if (!radiometry.isEmpty() && maybeSave(m_radiometry)) {
        std::sort(radiometry.begin(), radiometry.end());  // file names carry the scan order
        QString err;
        const bool ok = radiometry.size() == 1 ? m_radiometry->controller()->openImage(radiometry.first(), &err)
                                               : m_radiometry->controller()->openFrames(radiometry, &err);
        if (!ok) problems << err;
        else {
            addRecentInput("radiometry", radiometry.size() == 1 ? radiometry.first() : QFileInfo(radiometry.first()).absolutePath());
            inputsOpened(m_radiometry);
        }
    }
    if (!problems.isEmpty()) {
        if (errorOut) *errorOut = problems.join("\n");
        showError(tr("Cannot open everything given"), problems.join("\n"));
        return false;
    }
    return true;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    if (!e->mimeData()->hasUrls()) return;
    for (const QUrl& u : e->mimeData()->urls())
        if (!u.isLocalFile()) return;
    e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
    QStringList paths;
    for (const QUrl& u : e->mimeData()->urls())
        if (u.isLocalFile()) paths << u.toLocalFile();
    if (paths.isEmpty()) return;
    e->acceptProposedAction();
    // After the drop returns: opening may show a dialog.
    QMetaObject::invokeMethod(this, [this, paths] { openPaths(paths); }, Qt::QueuedConnection);
}

QList<QAction*> MainWindow::openActions(QWidget* ws) {
    QList<QAction*> out;
    if (ws == m_footprint) {
        auto* a = new QAction(tr("Frames, folder or shot list…"), ws);
        connect(a, &QAction::triggered, this, &MainWindow::openInputs);
        out << a;
        return out;
    }
    if (ws == m_slr) {
        auto* a = new QAction(tr("CRD file or O-C table…"), ws);
        connect(a, &QAction::triggered, this, [this] {
            QSettings st;
            const QString path = QFileDialog::getOpenFileName(this, tr("Open a ranging pass"), st.value("paths/slr").toString(),
                                                              tr("CRD and O-C tables (*.frd *.fr2 *.npt *.np2 *.crd *.csv);;All files (*)"));
            if (path.isEmpty()) return;
            st.setValue("paths/slr", QFileInfo(path).absolutePath());
            openPaths({path});
        });
        out << a;
        return out;
    }
    // The calibration and radiometry workspaces: the "…" buttons of their input row.
    for (QPushButton* b : ws->findChildren<QPushButton*>()) {
        const QString t = b->text();
        if (!t.endsWith(QStringLiteral("…")) || t.startsWith(tr("Export")) || !b->isEnabled()) continue;
        auto* a = new QAction(t, ws);
        a->setToolTip(b->toolTip());
        connect(a, &QAction::triggered, b, &QPushButton::click);
        out << a;
    }
    return out;
}

QList<QAction*> MainWindow::exportActions(QWidget* ws) {
    QList<QAction*> out;
    if (ws == m_footprint) {
        auto* a = new QAction(tr("Accepted shots (CSV)…"), ws);
        connect(a, &QAction::triggered, this, &MainWindow::exportAccepted);
        out << a;
        return out;
    }
    // The workspace's "Export…" buttons and the entries of its Export menus.
    for (QWidget* w : ws->findChildren<QWidget*>()) {
        if (auto* tb = qobject_cast<QToolButton*>(w); tb && tb->menu() && tb->text().startsWith(tr("Export"))) {
            for (QAction* a : tb->menu()->actions())
                if (!a->isSeparator()) out << a;
        } else if (auto* pb = qobject_cast<QPushButton*>(w); pb && pb->text().startsWith(tr("Export"))) {
            auto* a = new QAction(pb->text(), ws);
            a->setEnabled(pb->isEnabled());
            connect(a, &QAction::triggered, pb, &QPushButton::click);
            out << a;
        }
    }
    return out;
}

namespace {
// One entry runs at once; several are offered in a menu under the cursor.
void runOrOffer(QWidget* parent, const QList<QAction*>& actions, const QString& none, QStatusBar* bar) {
    if (actions.isEmpty()) {
        bar->showMessage(none, 6000);
        return;
    }
    if (actions.size() == 1) {
        actions.first()->trigger();
        return;
    }
    QMenu menu(parent);
    menu.addActions(actions);
    QPoint at = parent->mapToGlobal(parent->rect().center());
    if (parent->rect().contains(parent->mapFromGlobal(QCursor::pos()))) at = QCursor::pos();
    menu.exec(at);
}
}  // namespace

void MainWindow::openForCurrent() {
    QWidget* ws = m_tabs->currentWidget();
    const QList<QAction*> acts = openActions(ws);
    runOrOffer(ws, acts, tr("Nothing to open here"), statusBar());
    for (QAction* a : acts)
        if (a->parent() == ws) a->deleteLater();  // made for this call (menu entries stay)
}

void MainWindow::exportForCurrent() {
    QWidget* ws = m_tabs->currentWidget();
    const QList<QAction*> acts = exportActions(ws);
    runOrOffer(ws, acts, tr("Nothing to export here"), statusBar());
    for (QAction* a : acts)
        if (a->parent() == ws) a->deleteLater();  // made for this call (menu entries stay)
}

QStringList MainWindow::recentInputs() const { return QSettings().value("recentInputs").toStringList(); }

void MainWindow::addRecentInput(const QString& kind, const QString& path, int pass) {
    const QString abs = QFileInfo(path).absoluteFilePath();
    QString entry = kind + "\t" + abs;
    if (pass >= 0) entry += "\t" + QString::number(pass);
    QStringList recent = recentInputs();
    // One entry per input (a newer pass of the same file replaces the older one).
    for (int i = recent.size() - 1; i >= 0; --i) {
        const QStringList f = recent[i].split('\t');
        if (f.value(0) == kind && f.value(1) == abs) recent.removeAt(i);
    }
    recent.prepend(entry);
    while (recent.size() > kMaxRecent) recent.removeLast();
    QSettings().setValue("recentInputs", recent);
    rebuildRecentInputsMenu();
}

void MainWindow::rebuildRecentInputsMenu() {
    if (!m_recentInputsMenu) return;
    m_recentInputsMenu->clear();
    const QStringList recent = recentInputs();
    const QMap<QString, QString> kinds = {{"footprint", tr("footprint")}, {"slr", tr("SLR")}, {"radiometry", tr("radiometry")}};
    for (const QString& e : recent) {
        const QStringList f = e.split('\t');
        if (f.size() < 2) continue;
        const QString kind = f[0], path = f[1];
        const int pass = f.size() > 2 ? f[2].toInt() : -1;
        QString label = tr("%1 — %2").arg(kinds.value(kind, kind), QFileInfo(path).fileName());
        if (pass >= 0) label += tr(", pass %1").arg(pass + 1);
        QAction* a = m_recentInputsMenu->addAction(label, this, [this, kind, path, pass] {
            QString err;
            if (kind == "slr") {
                if (!m_slr->openPath(path, pass, &err)) showError(tr("Cannot open the pass"), err);
                else m_tabs->setCurrentWidget(m_slr);
            } else if (kind == "radiometry") {
                const bool ok = QFileInfo(path).isDir() ? false : m_radiometry->controller()->openImage(path, &err);
                if (!ok) showError(tr("Cannot open the image"), err.isEmpty() ? tr("%1: a folder of frames; open them with Mosaic frames…").arg(path) : err);
                else m_tabs->setCurrentWidget(m_radiometry);
            } else {
                if (!openFootprintInputs({path})) return;
                m_tabs->setCurrentWidget(m_footprint);
            }
        });
        a->setToolTip(path);
    }
    m_recentInputsMenu->setEnabled(!m_recentInputsMenu->isEmpty());
}

QJsonObject MainWindow::sessionState() const {
    QJsonObject o;
    o["format"] = "laserwb-session";
    o["version"] = kSessionVersion;
    QWidget* cur = m_tabs->currentWidget();
    o["workspace"] = cur == m_slr ? "slr" : cur == m_calib ? "calibration" : cur == m_radiometry ? "radiometry" : "footprint";
    o["footprint"] = m_footprint->saveState();
    o["slr"] = m_slr->saveState();
    o["calibration"] = m_calib->saveState();
    o["radiometry"] = m_radiometry->saveState();
    return o;
}

bool MainWindow::saveSession(const QString& path, QString* error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        *error = tr("%1: %2").arg(path, f.errorString());
        return false;
    }
    f.write(QJsonDocument(sessionState()).toJson(QJsonDocument::Indented));
    if (!f.commit()) {
        *error = tr("%1: %2").arg(path, f.errorString());
        return false;
    }
    m_sessionPath = path;
    addRecent(path);
    setModified(false);
    return true;
}

bool MainWindow::openSession(const QString& path, bool quiet, QString* errorOut) {
    auto fail = [&](const QString& why) {
        if (errorOut) *errorOut = why;
        if (!quiet) showError(tr("Cannot open the session"), why);
        return false;
    };
    if (!maybeSave()) {  // the analyst cancelled: not an error to report
        if (errorOut) *errorOut = tr("%1: not opened (cancelled; the current changes are kept)").arg(path);
        return false;
    }
    // Through the core's reader, as the CLI reads its inputs: a regular file (a FIFO would block,
    // a device never end) of at most kMaxSessionBytes, read once.
    std::string raw, why;
    if (!core::readFileText(path.toStdString(), &raw, &why, kMaxSessionBytes)) return fail(QString::fromStdString(why));
    const QByteArray text = QByteArray::fromStdString(raw);
    raw.clear();
    raw.shrink_to_fit();
    // Parsed by the core's reader first: strict (duplicate keys refused), and its positions
    // give the parameter sections' messages their line and column.
    const core::JsonParseResult parsed = core::parseJson(text.toStdString(), path.toStdString());
    if (!parsed.ok) return fail(QString::fromStdString(parsed.error));
    const QJsonObject o = QJsonDocument::fromJson(text).object();
    if (!parsed.value.is_object()) return fail(tr("%1: a session is a JSON object").arg(path));
    if (o["format"].toString() != "laserwb-session")
        return fail(tr("%1: not a Laser Workbench session (no \"format\": \"laserwb-session\")").arg(path));
    // A whole number 1..kSessionVersion (toInt() would turn 1e300 or 1.5 into 0 and let it pass).
    const QJsonValue version = o["version"];
    const double vd = version.toDouble(-1);
    if (!version.isDouble() || vd != std::floor(vd) || vd < 1 || vd > 1e9)
        return fail(tr("%1: \"version\" must be a whole number from 1 to %2, not %3")
                        .arg(path)
                        .arg(kSessionVersion)
                        .arg(version.isDouble() ? QString::number(vd, 'g', 6) : QStringLiteral("a non-number")));
    if (vd > kSessionVersion)
        return fail(tr("%1: session version %2 is newer than this program reads (%3)").arg(path).arg(qint64(vd)).arg(kSessionVersion));
    // Validate everything before touching the current state.
    QString err;
    const QJsonObject before = m_footprint->saveState();
    const QJsonObject slrBefore = m_slr->saveState();
    const QJsonObject calibBefore = m_calib->saveState();
    const QJsonObject radBefore = m_radiometry->saveState();
    if (!m_footprint->restoreState(o["footprint"].toObject(), &err, &parsed) ||
        (o.contains("slr") && !m_slr->restoreState(o["slr"].toObject(), &err, &parsed)) ||
        (o.contains("calibration") && !m_calib->restoreState(o["calibration"].toObject(), &err, &parsed)) ||
        (o.contains("radiometry") && !m_radiometry->restoreState(o["radiometry"].toObject(), &err, &parsed))) {
        QString ignored;
        m_footprint->restoreState(before, &ignored);
        m_slr->restoreState(slrBefore, &ignored);
        m_calib->restoreState(calibBefore, &ignored);
        m_radiometry->restoreState(radBefore, &ignored);
        return fail(err.startsWith(path + ":") ? err : tr("%1: %2").arg(path, err));
    }
    m_sessionPath = path;
    addRecent(path);
    clearUndoHistories();
    setModified(false);
    showWorkspace(o["workspace"].toString());
    statusBar()->showMessage(tr("Opened %1").arg(path), 5000);
    return true;
}

void MainWindow::openSessionDialog() {
    QSettings st;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open session"), st.value("paths/lastSession").toString(),
                                                      tr("Laser Workbench sessions (*.lwb.json *.json)"));
    if (path.isEmpty()) return;
    st.setValue("paths/lastSession", QFileInfo(path).absolutePath());
    openSession(path);
}

bool MainWindow::save() {
    if (m_sessionPath.isEmpty()) return saveAs();
    QString err;
    if (!saveSession(m_sessionPath, &err)) {
        showError(tr("Cannot save the session"), err);
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(m_sessionPath), 5000);
    return true;
}

bool MainWindow::saveAs() {
    QSettings st;
    QString path = QFileDialog::getSaveFileName(this, tr("Save session"), st.value("paths/lastSession").toString(),
                                                tr("Laser Workbench sessions (*.lwb.json)"));
    if (path.isEmpty()) return false;
    if (!path.endsWith(".json")) path += ".lwb.json";
    st.setValue("paths/lastSession", QFileInfo(path).absolutePath());
    m_sessionPath = path;
    return save();
}

bool MainWindow::maybeSave(QWidget* workspace) {
    QStringList which;  // the workspaces whose unsaved work would be lost, by their tab names
    for (int i = 0; i < m_tabs->count(); ++i)
        if (m_unsaved.contains(m_tabs->widget(i)) && (!workspace || m_tabs->widget(i) == workspace)) which << m_tabs->tabText(i);
    if (which.isEmpty()) return true;
    QMessageBox::StandardButton answer;
    if (m_prompt) {
        answer = m_prompt();
    } else if (qApp->platformName() == "offscreen") {
        qWarning("unsaved changes discarded: no one can answer a dialog on the offscreen platform");
        answer = QMessageBox::Discard;
    } else {
        answer = QMessageBox::question(this, tr("Unsaved changes"),
                                       tr("%1 has unsaved changes (verdicts, notes, edits, parameters). Save the session?")
                                           .arg(which.join(tr(", "))),
                                       QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    }
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::exportAccepted() {
    const QString path = askSavePath(this, tr("Export accepted shots"), "paths/lastExport", "accepted_shots.csv", tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString err;
    int rows = 0;
    if (!m_footprint->controller()->exportAccepted(path, &err, &rows))
        showError(tr("Cannot export"), err);
    else
        statusBar()->showMessage(m_footprint->controller()->acceptedExportMessage(rows, path), 6000);
}

void MainWindow::addRecent(const QString& path) {
    QSettings st;
    QStringList recent = st.value("recentSessions").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    st.setValue("recentSessions", recent);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    if (!m_recentMenu) return;
    m_recentMenu->clear();
    const QStringList recent = QSettings().value("recentSessions").toStringList();
    for (const QString& p : recent)
        m_recentMenu->addAction(QFileInfo(p).fileName(), this, [this, p] { openSession(p); })->setToolTip(p);
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void MainWindow::clearUndoHistories() {
    for (QWidget* ws : {static_cast<QWidget*>(m_footprint), static_cast<QWidget*>(m_slr), static_cast<QWidget*>(m_calib),
                        static_cast<QWidget*>(m_radiometry)})
        undoStackOf(ws).clear();
}

void MainWindow::showWorkspace(const QString& name) {
    // "footprint" or "footprint:trend" (a workspace, then optionally its tab).
    const QStringList parts = name.split(':');
    if (parts[0] == "footprint") {
        m_tabs->setCurrentWidget(m_footprint);
        if (parts.size() > 1) m_footprint->showTab(parts[1]);
    } else if (parts[0] == "slr") {
        m_tabs->setCurrentWidget(m_slr);
    } else if (parts[0] == "calibration") {
        m_tabs->setCurrentWidget(m_calib);
        if (parts.size() > 1) m_calib->showTab(parts[1]);
    } else if (parts[0] == "radiometry") {
        m_tabs->setCurrentWidget(m_radiometry);
    }
}

bool MainWindow::waitIdle(int timeoutMs) {
    // Every workspace idle at once, twice in a row with events processed between (a finished
    // job may start the next one, e.g. the radiometry mosaic and then its fit).
    QElapsedTimer t;
    t.start();
    auto allIdle = [&](int ms) {
        return m_footprint->controller()->waitIdle(ms) && m_slr->controller()->waitIdle(ms) &&
               m_calib->controller()->waitIdle(ms) && m_radiometry->controller()->waitIdle(ms);
    };
    int quietRounds = 0;
    while (t.elapsed() < timeoutMs && quietRounds < 2) {
        const int left = int(std::max<qint64>(1, timeoutMs - t.elapsed()));
        if (!allIdle(left)) return false;
        QElapsedTimer settle;
        settle.start();
        while (settle.elapsed() < 150) QApplication::processEvents(QEventLoop::AllEvents, 20);
        quietRounds = allIdle(1) ? quietRounds + 1 : 0;
    }
    return quietRounds >= 2;
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!maybeSave()) {
        e->ignore();
        return;
    }
    QSettings().setValue("window/geometry", saveGeometry());
    saveDockLayouts(this);
    e->accept();
}

}  // namespace lwb::ui
