#include <cmath>
#include "ui/shell/main_window.hpp"

#include "core/common/atomic_file.hpp"

#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
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
#include <QLocale>
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
#include "ui/kit/i18n.hpp"
#include "ui/kit/app_undo.hpp"
#include "ui/kit/save_path.hpp"
#include "ui/kit/workspace_layout.hpp"
#include "ui/kit/plot_kit.hpp"
#include "ui/shell/workspaces.hpp"

// The resources live in the static ui library: registered here, or the linker may drop them.
static void initUiResources() { Q_INIT_RESOURCE(laserwb); }

namespace lwb::ui {

namespace {
constexpr int kSessionVersion = 1;
constexpr int kMaxRecent = 8;

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
    m_workspaces = makeWorkspaces(m_tabs);
    for (Workspace* ws : m_workspaces) m_tabs->addTab(ws, ws->title());
    setCentralWidget(m_tabs);
    // A plot's minimum width is otherwise its legend's natural width: the SLR workspace's two
    // plots side by side, each with a three-column legend, asked for a 1271 px window. Plots
    // without a minimum of their own get a small one (a long legend is then clipped, not the window).
    for (QCustomPlot* p : m_tabs->findChildren<QCustomPlot*>())
        if (p->minimumWidth() == 0) p->setMinimumWidth(160);
    buildMenus();
    // Progress of long loads, with a cancel button, in the status bar.
    m_progress = new QProgressBar(this);
    m_progress->setObjectName("loadProgress");
    m_progress->setMaximumWidth(260);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName("loadCancel");
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancel);
    m_progress->hide();
    m_cancel->hide();
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (m_loading) m_loading->cancelWork();
    });
    for (Workspace* ws : m_workspaces) {
        connect(ws, &Workspace::modified, this, [this, ws] { markUnsaved(ws); });
        connect(ws, &Workspace::status, this, [this, ws](const QString& s) { workspaceStatus(ws, s, 8000); });
        connect(ws, &Workspace::openRequested, this, [this, ws](const QStringList& paths) { openInputsIn(ws, paths); });
        connect(ws, &Workspace::failed, this, &MainWindow::showError);
        connect(ws, &Workspace::progress, this, [this, ws](int done, int total, const QString& format) {
            const bool running = done < total;
            m_loading = running ? ws : nullptr;
            if (running) {
                m_progress->setFormat(format);
                m_progress->setRange(0, total);
                m_progress->setValue(done);
            }
            m_progress->setVisible(running);
            m_cancel->setVisible(running);
        });
    }
    // (New data in a workspace clears its own undo history: the other workspaces' stay.)
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

Workspace* MainWindow::workspace(const QString& key) const {
    for (Workspace* ws : m_workspaces)
        if (ws->key() == key) return ws;
    return nullptr;
}

Workspace* MainWindow::currentWorkspace() const { return qobject_cast<Workspace*>(m_tabs->currentWidget()); }

void MainWindow::workspaceStatus(Workspace* workspace, const QString& message, int timeoutMs) {
    // Only the workspace in front speaks in the status bar: a workspace working in the
    // background (the radiometry demo mosaic at start-up) must not cover the current one's line.
    if (m_tabs->currentWidget() == workspace) statusBar()->showMessage(message, timeoutMs);
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open… (current workspace)"), QKeySequence::Open, this, &MainWindow::openForCurrent)
        ->setToolTip(tr("Opens the inputs of the workspace in front"));
    for (Workspace* ws : m_workspaces) file->addActions(ws->fileOpenActions());
    file->addAction(tr("Open &demo"), this, &MainWindow::openDemo);
    m_recentInputsMenu = file->addMenu(tr("Recent &inputs"));
    file->addSeparator();
    file->addAction(tr("Open &session…"), QKeySequence(tr("Ctrl+Shift+O")), this, &MainWindow::openSessionDialog);
    m_recentMenu = file->addMenu(tr("&Recent sessions"));
    file->addAction(tr("&Save session"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save session &as…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    file->addSeparator();
    file->addAction(tr("&Export… (current workspace)"), QKeySequence(tr("Ctrl+E")), this, &MainWindow::exportForCurrent);
    for (Workspace* ws : m_workspaces) file->addActions(ws->fileExportActions());
    file->addAction(tr("&Report… (PDF)"), this, &MainWindow::reportForCurrent)
        ->setObjectName("actionReport");
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
    edit->addSeparator();
    // The batch command of the current result, to paste into a terminal, and the same as a
    // Python script: the workspace's text on the clipboard, what it leaves out on the status line.
    auto copyOf = [this](QString (Workspace::*text)(QString*) const, const QString& none,
                         const std::function<QString(const QString&, const QString&)>& said) {
        return [this, text, none, said] {
            Workspace* ws = currentWorkspace();
            QString note;
            const QString t = ws ? (ws->*text)(&note) : QString();
            if (t.isEmpty()) {
                statusBar()->showMessage(none, 6000);
                return;
            }
            QApplication::clipboard()->setText(t);
            statusBar()->showMessage(said(t, note), 10000);
        };
    };
    edit->addAction(tr("Copy as &command line"), this,
                    copyOf(&Workspace::commandLine, tr("No result here that a command reproduces"),
                           [this](const QString& cmd, const QString& note) {
                               return note.isEmpty() ? tr("Copied: %1").arg(cmd) : tr("Copied (%1): %2").arg(note, cmd);
                           }))
        ->setObjectName("actionCopyCommand");
    edit->addAction(tr("Copy as &Python"), this,
                    copyOf(&Workspace::pythonScript, tr("No result here that a script reproduces"),
                           [this](const QString& script, const QString& note) {
                               return note.isEmpty() ? tr("Copied the Python script (%n line(s))", nullptr, int(script.count('\n')))
                                                     : tr("Copied the Python script (%1)").arg(note);
                           }))
        ->setObjectName("actionCopyPython");
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
    // The interface language: the system's, English or Chinese, from the next start (every
    // widget takes its text when it is made); `laserwb --language` for one run.
    QMenu* language = view->addMenu(tr("Lan&guage"));
    language->setObjectName("languageMenu");
    auto* languages = new QActionGroup(this);
    const QString chosen = QSettings().value(kLanguageSetting).toString();
    const QList<QPair<QString, QString>> choices = {{QString(), tr("As the system (%1)").arg(QLocale::system().name())},
                                                    {QStringLiteral("en"), QStringLiteral("English")},
                                                    {QStringLiteral("zh_CN"), QStringLiteral("中文（简体）")}};
    for (const auto& [code, name] : choices) {
        QAction* a = language->addAction(name);
        a->setCheckable(true);
        a->setChecked(code == chosen);
        a->setData(code);
        languages->addAction(a);
        connect(a, &QAction::triggered, this, [this, code] {
            QSettings().setValue(kLanguageSetting, code);
            const QString next = resolveLanguage(code);
            if (next == currentLanguage()) return;
            const QString text = tr("The interface will be in %1 from the next start of the workbench.")
                                     .arg(next == QLatin1String("en") ? QStringLiteral("English") : QStringLiteral("中文"));
            statusBar()->showMessage(text, 8000);
            if (qApp->platformName() != QLatin1String("offscreen"))
                QMessageBox::information(this, tr("Language"), text);
        });
    }

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

namespace {
// A menu text as a list names it: without its accelerator ("&File" -> "File", "文件(&F)" -> "文件").
QString withoutAccelerator(QString text) {
    static const QRegularExpression inParentheses(QStringLiteral("\\(&[^)]\\)"));
    text.remove(inParentheses);
    return text.remove('&');
}
}  // namespace

QStringList MainWindow::shortcutList() const {
    QStringList out;
    std::function<void(const QList<QAction*>&, const QString&)> walk = [&](const QList<QAction*>& acts, const QString& menu) {
        for (QAction* a : acts) {
            if (a->menu()) {
                walk(a->menu()->actions(), withoutAccelerator(a->menu()->title()));
                continue;
            }
            const QList<QKeySequence> keys = a->shortcuts();
            if (keys.isEmpty()) continue;
            QStringList ks;
            for (const QKeySequence& k : keys) ks << k.toString(QKeySequence::NativeText);
            QString text = withoutAccelerator(a->text()).split('\t').first();
            out << ks.join(", ") + "\t" + menu + " ▸ " + text;
        }
    };
    walk(menuBar()->actions(), QString());
    for (const Workspace* ws : m_workspaces) out << ws->shortcutNotes();  // the keys each handles itself
    out << tr("Right-drag, Shift+drag\tImage view ▸ box zoom") << tr("Home, double-click\tImage view ▸ fit")
        << tr("Right-click\tImage view ▸ menu: zoom steps, mouse mode (pan, box or circle regions), reset contrast and bias, export the view")
        << tr("Middle-drag, Ctrl+drag\tImage view ▸ contrast (up / down) and bias (left / right), as DS9's right-drag")
        << tr("Drag on the colour bar\tImage view ▸ contrast and bias; a double-click on the bar resets them")
        << tr("Drag (region mode)\tImage view ▸ draw a box or circle region; drag a region to move it")
        << tr("Delete\tImage view ▸ delete the selected region (the view reached by Tab)");
    out << tr("Shift+drag\tParameter slider ▸ ten times finer than the mouse");
    out << tr("Wheel\tPlot ▸ zoom both axes about the cursor") << tr("Shift+Wheel\tPlot ▸ zoom x only")
        << tr("Ctrl+Wheel\tPlot ▸ zoom y only") << tr("Wheel / drag over an axis\tPlot ▸ zoom / pan that axis only")
        << tr("Drag\tPlot ▸ pan") << tr("Right-drag, Shift+drag\tPlot ▸ box zoom")
        << tr("Double-click, Home\tPlot ▸ reset to the home view") << tr("Backspace\tPlot ▸ back in the zoom history")
        << tr("Right-click\tPlot ▸ export PNG / SVG / PDF, copy to the clipboard")
        << tr("Click a legend entry\tPlot ▸ hide / show its series")
        << tr("Hover\tPlot ▸ crosshair with the coordinates (a colour map's value too)");
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
    placeOnScreen(dlg, QSize(560, 520));
    dlg->show();
}

void MainWindow::reportForCurrent() {
    Workspace* ws = currentWorkspace();
    const QString name = ws ? ws->reportName() : QString();
    if (name.isEmpty()) {
        showError(tr("No report"), tr("%1 has no result to report yet.").arg(ws ? ws->title() : tr("This workspace")));
        return;
    }
    const QString path = askSavePath(this, tr("Write report"), QStringLiteral("paths/lastReport"), name, tr("PDF (*.pdf)"));
    if (path.isEmpty()) return;
    writeReportTo(path);
}

bool MainWindow::writeReportTo(const QString& path) {
    Workspace* ws = currentWorkspace();
    QString err;
    if (!ws || !ws->writeReport(path, &err)) {
        showError(tr("Report not written"), err.isEmpty() ? tr("nothing to report") : err);
        return false;
    }
    statusBar()->showMessage(tr("Report written: %1").arg(path), 8000);
    return true;
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
    // The guide in the interface's language (docs/user-guide.zh_CN.md), else the English one.
    QFile f(QStringLiteral(":/docs/user-guide.%1.md").arg(currentLanguage()));
    if (!f.exists()) f.setFileName(QStringLiteral(":/docs/user-guide.md"));
    QString text = f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : tr("The user guide is missing.");
    text.remove(QRegularExpression(QStringLiteral("<!-- developer -->.*?<!-- /developer -->"),
                                   QRegularExpression::DotMatchesEverythingOption));
    b->document()->setBaseUrl(QUrl(QStringLiteral("qrc:/docs/")));
    b->setMarkdown(text);
    lay->addWidget(b);
    auto* bb = new QDialogButtonBox(QDialogButtonBox::Close, dlg);
    connect(bb, &QDialogButtonBox::rejected, dlg, &QDialog::close);
    lay->addWidget(bb);
    placeOnScreen(dlg, QSize(std::min(900, width()), std::min(760, height())));
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

void MainWindow::inputsOpened(Workspace* workspace) {
    // Other data than the session file describes: Save asks for a name (Ctrl+S replaced the
    // restored session, its verdicts and notes, with the new data). The workspace's unsaved
    // work was offered for saving before (maybeSave(workspace)) and is replaced; the other
    // workspaces keep theirs (issue 42: opening a pass cleared the footprint review's unsaved
    // verdicts, and Ctrl+Q then quit without asking).
    m_sessionPath.clear();
    QPointer<Workspace> ws(workspace);
    QMetaObject::invokeMethod(this, [this, ws] { markSaved(ws); }, Qt::QueuedConnection);  // after the workspace's own signals
    markSaved(workspace);
}

void MainWindow::markUnsaved(Workspace* workspace) {
    m_unsaved.insert(workspace);
    setModified(true);
}

void MainWindow::markSaved(Workspace* workspace) {
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
    for (Workspace* ws : m_workspaces) ws->openDemo();
    QStringList parts;
    for (const Workspace* ws : m_workspaces) parts << ws->demoSummary();
    const QString last = parts.isEmpty() ? QString() : parts.takeLast();
    statusBar()->showMessage(tr("Built-in demo: %1").arg(parts.isEmpty() ? last : tr("%1 and %2").arg(parts.join(tr(", ")), last)), 8000);
    m_sessionPath.clear();
    clearUndoHistories();
    setModified(false);
    return true;
}

namespace {
InputProbe probeInput(const QString& path) {
    InputProbe p;
    const QFileInfo fi(path);
    p.path = path;
    p.isDir = fi.isDir();
    if (p.isDir) return p;
    p.suffix = QString::fromStdString(lwb::core::inputExtension(path.toStdString()));  // (without .gz)
    p.gz = fi.suffix().toLower() == "gz";
    p.head = firstLine(path);
    return p;
}
}  // namespace

Workspace* MainWindow::route(const InputProbe& probe, QString* role) const {
    // The workspace in front first (an image is a radiometry scene there, frames elsewhere).
    Workspace* cur = currentWorkspace();
    if (cur && !(*role = cur->claim(probe, true)).isEmpty()) return cur;
    for (Workspace* ws : m_workspaces)
        if (ws != cur && !(*role = ws->claim(probe, false)).isEmpty()) return ws;
    role->clear();
    return nullptr;
}

QString MainWindow::workspaceForPath(const QString& path) const {
    const InputProbe probe = probeInput(path);
    if (!probe.isDir && probe.suffix == "json") return probe.head.contains("{") || probe.head.isEmpty() ? "session" : QString();
    QString role;
    route(probe, &role);
    return role;
}

bool MainWindow::openRouted(const QMap<Workspace*, QMap<QString, QStringList>>& routed, int pass, QStringList* problems) {
    bool asked = true;
    for (Workspace* ws : m_workspaces) {
        const auto it = routed.constFind(ws);
        if (it == routed.cend()) continue;
        bool replaces = false;
        for (auto r = it->cbegin(); r != it->cend(); ++r) replaces = replaces || ws->replacesData(r.key());
        if (replaces && !maybeSave(ws)) {  // the analyst kept the unsaved work: nothing opened there
            asked = false;
            continue;
        }
        const OpenOutcome o = ws->openInputs(*it, pass);
        *problems << o.problems;
        if (o.replaced) inputsOpened(ws);
        if (!o.recentPath.isEmpty()) addRecentInput(ws->key(), o.recentPath, o.recentPass);
        if (o.opened) m_tabs->setCurrentWidget(ws);
    }
    return asked;
}

bool MainWindow::openPaths(const QStringList& paths, QString* errorOut) {
    QStringList problems, sessions;
    QMap<Workspace*, QMap<QString, QStringList>> routed;
    for (const QString& p : paths) {
        if (!QFileInfo::exists(p)) {
            problems << tr("%1: no such file or folder").arg(p);
            continue;
        }
        const QString where = workspaceForPath(p);
        QString role;
        Workspace* ws = where == "session" ? nullptr : route(probeInput(p), &role);
        if (where == "session") sessions << p;
        else if (ws) routed[ws][role] << p;
        else
            problems << tr("%1: not a file the workbench opens (CRD, CPF, SINEX, O-C or shot-list CSV, images, a "
                           "folder of frames, a session)")
                            .arg(p);
    }
    for (const QString& p : sessions) {
        QString err;
        if (!openSession(p, true, &err)) problems << err;  // (asks about every workspace's unsaved work)
    }
    openRouted(routed, -1, &problems);
    if (!problems.isEmpty()) {
        if (errorOut) *errorOut = problems.join("\n");
        showError(tr("Cannot open everything given"), problems.join("\n"));
        return false;
    }
    return true;
}

bool MainWindow::openInputsIn(Workspace* ws, const QStringList& paths, QString* errorOut) {
    QStringList problems;
    QMap<Workspace*, QMap<QString, QStringList>> routed;
    for (const QString& p : paths) {
        const QString role = QFileInfo::exists(p) ? ws->claim(probeInput(p), true) : QString();
        if (!QFileInfo::exists(p)) problems << tr("%1: no such file or folder").arg(p);
        else if (role.isEmpty()) problems << tr("%1: not an input of the %2 workspace").arg(p, ws->title());
        else routed[ws][role] << p;
    }
    const bool asked = openRouted(routed, -1, &problems);
    if (!problems.isEmpty()) {
        if (errorOut) *errorOut = problems.join("\n");
        showError(tr("Cannot open everything given"), problems.join("\n"));
        return false;
    }
    return asked;
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
    Workspace* ws = currentWorkspace();
    if (!ws) return;
    const QList<QAction*> acts = openActions(ws);
    runOrOffer(ws, acts, tr("Nothing to open here"), statusBar());
    for (QAction* a : acts)
        if (a->parent() == ws) a->deleteLater();  // made for this call (menu entries stay)
}

void MainWindow::exportForCurrent() {
    Workspace* ws = currentWorkspace();
    if (!ws) return;
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
    for (const QString& e : recent) {
        const QStringList f = e.split('\t');
        Workspace* ws = f.size() < 2 ? nullptr : workspace(f[0]);
        if (!ws) continue;
        const QString path = f[1];
        const int pass = f.size() > 2 ? f[2].toInt() : -1;
        QString label = tr("%1 — %2").arg(ws->title(), QFileInfo(path).fileName());
        if (pass >= 0) label += tr(", pass %1").arg(pass + 1);
        QAction* a = m_recentInputsMenu->addAction(label, this, [this, ws, path, pass] {
            // Through the same opening as a file dropped on the window: the workspace's unsaved
            // work is asked about first, the others' kept.
            QStringList problems;
            if (!QFileInfo::exists(path)) problems << tr("%1: no such file or folder").arg(path);
            else openRouted({{ws, {{ws->key(), {path}}}}}, pass, &problems);
            if (!problems.isEmpty()) showError(tr("Cannot open the recent input"), problems.join("\n"));
        });
        a->setToolTip(path);
    }
    m_recentInputsMenu->setEnabled(!m_recentInputsMenu->isEmpty());
}

QJsonObject MainWindow::sessionState() const {
    QJsonObject o;
    o["format"] = "laserwb-session";
    o["version"] = kSessionVersion;
    if (const Workspace* cur = currentWorkspace()) o["workspace"] = cur->key();
    for (const Workspace* ws : m_workspaces) o[ws->key()] = ws->saveState();
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
    // Every workspace's part checked, and then its inputs read, before any is restored: a part
    // refused leaves every workspace as it was, with no work started (a restored footprint part
    // and then its undoing, when the SLR part's pass could not be read, reloaded the shots and
    // lost the shot shown). The checks that read no file come first, so that a session refused
    // for a value reads no pass. The restore uses what was read; should it still fail, every
    // part is put back as it was.
    QString err;
    for (const bool prepare : {false, true})
        for (Workspace* ws : m_workspaces) {
            if (!o.contains(ws->key())) continue;
            const QJsonObject part = o[ws->key()].toObject();
            const std::vector<std::string> at{ws->key().toStdString()};
            if (prepare ? ws->prepareState(part, &err, &parsed, at) : ws->checkState(part, &err, &parsed, at)) continue;
            for (Workspace* w : m_workspaces) w->dropPrepared();
            return fail(err.startsWith(path + ":") ? err : tr("%1: %2").arg(path, err));
        }
    QHash<Workspace*, QJsonObject> before;  // each workspace's state, back if any part fails
    for (Workspace* ws : m_workspaces) before[ws] = ws->saveState();
    for (Workspace* ws : m_workspaces) {
        if (!o.contains(ws->key()) || ws->restoreState(o[ws->key()].toObject(), &err, &parsed, {ws->key().toStdString()}))
            continue;
        QString ignored;
        for (Workspace* w : m_workspaces) {
            w->dropPrepared();
            w->restoreState(before[w], &ignored, nullptr, {w->key().toStdString()});
        }
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

bool MainWindow::maybeSave(Workspace* workspace) {
    QStringList which;  // the workspaces whose unsaved work would be lost, by their tab names
    for (int i = 0; i < m_tabs->count(); ++i)
        if (auto* ws = qobject_cast<Workspace*>(m_tabs->widget(i)); m_unsaved.contains(ws) && (!workspace || ws == workspace))
            which << m_tabs->tabText(i);
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
    for (Workspace* ws : m_workspaces) undoStackOf(ws).clear();
}

void MainWindow::showWorkspace(const QString& name) {
    // "footprint" or "footprint:trend" (a workspace, then optionally its tab).
    const QStringList parts = name.split(':');
    Workspace* ws = workspace(parts[0]);
    if (!ws) return;
    m_tabs->setCurrentWidget(ws);
    if (parts.size() > 1) ws->showTab(parts[1]);
}

bool MainWindow::waitIdle(int timeoutMs) {
    // Every workspace idle at once, twice in a row with events processed between (a finished
    // job may start the next one, e.g. the radiometry mosaic and then its fit).
    QElapsedTimer t;
    t.start();
    auto allIdle = [&](int ms) {
        for (Workspace* ws : m_workspaces)
            if (!ws->waitIdle(ms)) return false;
        return true;
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
