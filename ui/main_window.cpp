#include <cmath>
#include "ui/main_window.hpp"

#include <QApplication>
#include <QCloseEvent>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonDocument>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>

#include "core/common/json.hpp"
#include "ui/demo.hpp"
#include "ui/footprint_params_panel.hpp"
#include "ui/footprint_workspace.hpp"
#include "ui/slr_controller.hpp"
#include "ui/slr_workspace.hpp"
#include "ui/calib_workspace.hpp"
#include "ui/radiometry_workspace.hpp"

namespace lwb::ui {

namespace {
constexpr int kSessionVersion = 1;
constexpr int kMaxRecent = 8;
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
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
    buildMenus();
    connect(m_footprint, &FootprintWorkspace::modified, this, [this] { setModified(true); });
    connect(m_footprint, &FootprintWorkspace::status, this, [this](const QString& s) { statusBar()->showMessage(s, 5000); });
    connect(m_slr, &SlrWorkspace::modified, this, [this] { setModified(true); });
    connect(m_slr, &SlrWorkspace::status, this, [this](const QString& s) { statusBar()->showMessage(s, 8000); });
    connect(m_calib, &CalibWorkspace::modified, this, [this] { setModified(true); });
    connect(m_calib, &CalibWorkspace::status, this, [this](const QString& s) { statusBar()->showMessage(s, 8000); });
    connect(m_radiometry, &RadiometryWorkspace::modified, this, [this] { setModified(true); });
    connect(m_radiometry, &RadiometryWorkspace::status, this, [this](const QString& s) { statusBar()->showMessage(s, 8000); });
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
    QSettings st;
    if (!restoreGeometry(st.value("window/geometry").toByteArray())) resize(1480, 900);
    statusBar()->showMessage(tr("Ready"));
    setModified(false);
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open frames or shot list…"), QKeySequence::Open, this, &MainWindow::openInputs);
    file->addAction(tr("Open &folder of frames…"), this, &MainWindow::openFolder)->setObjectName("actionOpenFolder");
    file->addAction(tr("Open &demo"), this, &MainWindow::openDemo);
    file->addSeparator();
    file->addAction(tr("Open &session…"), QKeySequence(tr("Ctrl+Shift+O")), this, &MainWindow::openSessionDialog);
    m_recentMenu = file->addMenu(tr("&Recent sessions"));
    file->addAction(tr("&Save session"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save session &as…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    file->addSeparator();
    file->addAction(tr("&Export accepted shots…"), QKeySequence(tr("Ctrl+E")), this, &MainWindow::exportAccepted);
    file->addAction(tr("Export review &table…"), this, [this] { m_footprint->exportDialog(false); })
        ->setObjectName("actionExportReview");
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About"), this, [this] {
        QMessageBox::about(this, tr("About Laser Workbench"),
                           tr("<b>Laser Workbench</b> 0.1<br>Footprint spot centres, SLR signal extraction, "
                              "altimeter and radiometric calibration.<br>Every GUI action has a batch "
                              "equivalent in <tt>laserwb-cli</tt>."));
    });
    rebuildRecentMenu();
}

void MainWindow::showError(const QString& what, const QString& detail) {
    statusBar()->showMessage(what, 8000);
    if (qApp->platformName() == "offscreen") {
        qWarning("%s: %s", qPrintable(what), qPrintable(detail));
        return;
    }
    QMessageBox::warning(this, what, detail);
}

void MainWindow::setModified(bool m) {
    m_modified = m;
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
    setModified(false);
    return true;
}

bool MainWindow::openFootprintInputs(const QStringList& paths) {
    if (paths.isEmpty() || !maybeSave()) return false;
    m_footprint->controller()->open(paths);
    setModified(true);
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
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return fail(tr("%1: %2").arg(path, f.errorString()));
    const QByteArray text = f.readAll();
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
        (o.contains("calibration") && !m_calib->restoreState(o["calibration"].toObject(), &err)) ||
        (o.contains("radiometry") && !m_radiometry->restoreState(o["radiometry"].toObject(), &err))) {
        QString ignored;
        m_footprint->restoreState(before, &ignored);
        m_slr->restoreState(slrBefore, &ignored);
        m_calib->restoreState(calibBefore, &ignored);
        m_radiometry->restoreState(radBefore, &ignored);
        return fail(err.startsWith(path + ":") ? err : tr("%1: %2").arg(path, err));
    }
    m_sessionPath = path;
    addRecent(path);
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

bool MainWindow::maybeSave() {
    if (!m_modified) return true;
    QMessageBox::StandardButton answer;
    if (m_prompt) {
        answer = m_prompt();
    } else if (qApp->platformName() == "offscreen") {
        qWarning("unsaved changes discarded: no one can answer a dialog on the offscreen platform");
        answer = QMessageBox::Discard;
    } else {
        answer = QMessageBox::question(this, tr("Unsaved changes"),
                                       tr("The session has unsaved changes (verdicts, notes, parameters). Save them?"),
                                       QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    }
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::exportAccepted() {
    QSettings st;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export accepted shots"), st.value("paths/lastExport").toString(),
                                                      tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    st.setValue("paths/lastExport", QFileInfo(path).absolutePath());
    QString err;
    if (!m_footprint->controller()->exportAccepted(path, &err))
        showError(tr("Cannot export"), err);
    else
        statusBar()->showMessage(tr("Exported %1 accepted shots to %2").arg(m_footprint->controller()->counts().good).arg(path), 6000);
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
    e->accept();
}

}  // namespace lwb::ui
