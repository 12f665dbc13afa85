#include "ui/slr/slr_all_passes.hpp"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <algorithm>

#include "core/common/atomic_file.hpp"
#include "ui/kit/save_path.hpp"
#include "ui/slr/slr_controller.hpp"

namespace lwb::ui {

using namespace core::slr;

namespace {
// A row not decided yet (a status of the table only: summary.csv never holds it).
constexpr const char* kWaiting = "waiting";
}  // namespace

int SlrAllPassesDialog::column(const std::string& name) {
    const auto& cols = dayColumns();
    for (size_t c = 0; c < cols.size(); ++c)
        if (cols[c].name == name) return int(c);
    return -1;
}

SlrAllPassesDialog::SlrAllPassesDialog(const SlrController* controller, const QString& presetFile, QWidget* parent)
    : QDialog(parent), m_sources(controller->setup().sources) {
    setWindowTitle(tr("All passes of %1").arg(QFileInfo(controller->path()).fileName()));
    // As wide as the table wants, within the screen (1100 px put Close off a 1024 px screen).
    const QRect avail = (parent && parent->screen() ? parent->screen() : QGuiApplication::primaryScreen())->availableGeometry();
    resize(std::min(1100, avail.width() - 40), std::min(560, avail.height() - 80));
    // The CLI's sources for a station's file: the file, its prediction and stations, and each
    // satellite's saved preset (the panel's parameters, its oc.* rows among them, are not the
    // batch's: the passes are opened and resolved with the defaults alike). The core sets the
    // run up from them (runStationDay) as for laserwb-cli slr --all-passes --preset; a presets
    // file it cannot read fails the run with its reason.
    m_sources.config = core::Json();
    m_sources.set.clear();
    m_sources.passNumber = 0;
    m_sources.presets.clear();
    if (!presetFile.isEmpty() && QFileInfo::exists(presetFile)) m_sources.presets = presetFile.toStdString();
    auto* l = new QVBoxLayout(this);
    auto* about = new QLabel(
        !m_sources.presets.empty()
            ? tr("The command's defaults and the saved preset of each satellite (%1), as laserwb-cli slr --all-passes --preset.")
                  .arg(presetFile)
            : tr("The command's defaults (no saved presets), as laserwb-cli slr --all-passes."),
        this);
    about->setWordWrap(true);
    l->addWidget(about);
    m_table = new QTableWidget(this);
    const auto& cols = dayColumns();
    m_table->setColumnCount(int(cols.size()));
    for (size_t c = 0; c < cols.size(); ++c) {
        auto* h = new QTableWidgetItem(QString::fromStdString(cols[c].name));
        h->setToolTip(QString::fromStdString(cols[c].doc + (cols[c].unit.empty() ? "" : " (" + cols[c].unit + ")")));
        m_table->setHorizontalHeaderItem(int(c), h);
    }
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->setToolTip(tr("Double-click a screened row (or select it and press Open) to open that pass in the workspace"));
    l->addWidget(m_table, 1);
    auto* row = new QHBoxLayout;
    m_label = new QLabel(this);
    m_label->setWordWrap(true);
    m_progress = new QProgressBar(this);
    m_progress->setToolTip(tr("Blocks decided so far"));
    m_cancelButton = new QPushButton(tr("Cancel"), this);
    m_cancelButton->setToolTip(tr("Stop after the passes under way; the blocks not reached are marked cancelled"));
    m_exportButton = new QPushButton(tr("Export CSV…"), this);
    m_exportButton->setToolTip(tr("Write the table as summary.csv (laserwb-cli slr --all-passes writes the same bytes)"));
    m_productsButton = new QPushButton(tr("Export products…"), this);
    m_productsButton->setToolTip(
        tr("Write the day's products into a folder, as laserwb-cli slr --all-passes --out-dir: passNNN.csv/.frd/.npt, "
           "normal_points.npt, summary.csv, provenance.json"));
    m_productsButton->setEnabled(false);
    m_openButton = new QPushButton(tr("Open pass"), this);
    m_openButton->setToolTip(tr("Open the selected pass in the SLR workspace"));
    auto* close = new QPushButton(tr("Close"), this);
    close->setToolTip(tr("Close the table (a screening under way is cancelled)"));
    row->addWidget(m_label, 1);
    row->addWidget(m_progress, 1);
    row->addWidget(m_cancelButton);
    row->addWidget(m_exportButton);
    row->addWidget(m_productsButton);
    row->addWidget(m_openButton);
    row->addWidget(close);
    l->addLayout(row);

    // Every block of the file, in its order (summary.csv's), waiting.
    const std::vector<PassSummary>& passes = controller->passes();
    m_total = int(passes.size());
    m_rows.resize(passes.size());
    m_table->setRowCount(m_total);
    for (int r = 0; r < m_total; ++r) {
        DayRow& d = m_rows[size_t(r)];
        d.pass = size_t(r) + 1;
        d.block = passes[size_t(r)];
        d.status = kWaiting;
        for (int c = 0; c < int(cols.size()); ++c) {
            auto* item = new QTableWidgetItem(QString::fromStdString(cols[size_t(c)].cell(d)));
            if (c == 0) item->setData(Qt::UserRole, r);
            m_table->setItem(r, c, item);
        }
    }
    m_table->resizeColumnsToContents();
    m_progress->setRange(0, std::max(1, m_total));
    m_progress->setValue(0);
    m_label->setText(tr("Screening %1 blocks…").arg(m_total));

    connect(m_cancelButton, &QPushButton::clicked, this, &SlrAllPassesDialog::cancel);
    connect(close, &QPushButton::clicked, this, &QDialog::reject);
    connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int r, int) { emit openPass(passOfRow(r)); });
    connect(m_openButton, &QPushButton::clicked, this, [this] {
        if (m_table->currentRow() >= 0) emit openPass(passOfRow(m_table->currentRow()));
    });
    connect(this, &QDialog::rejected, this, &SlrAllPassesDialog::cancel);
    connect(m_exportButton, &QPushButton::clicked, this, [this] {
        const QString path = askSavePath(this, tr("Export the table"), "paths/slrExport", "summary.csv", tr("CSV (*.csv)"));
        QString err;
        if (!path.isEmpty() && !exportCsv(path, &err)) m_label->setText(err);
    });
    connect(m_productsButton, &QPushButton::clicked, this, [this] {
        QSettings settings;
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Export the day's products into a folder"),
                                                              settings.value("paths/slrProducts").toString());
        if (dir.isEmpty()) return;
        settings.setValue("paths/slrProducts", dir);
        QString err;
        if (!exportProducts(dir, &err)) m_label->setText(err);
    });
    connect(this, &SlrAllPassesDialog::productsWritten, this, [this](bool, const QString& message) { m_label->setText(message); });
    start(QString());
}

SlrAllPassesDialog::~SlrAllPassesDialog() {
    if (m_feedback) m_feedback->cancel();
    m_future.waitForFinished();
}

void SlrAllPassesDialog::start(const QString& outDir) {
    m_feedback = std::make_shared<core::Feedback>();
    const auto feedback = m_feedback;
    const SlrSources sources = m_sources;
    DayOptions opt;
    opt.outDir = outDir.toStdString();
    QPointer<SlrAllPassesDialog> self(this);
    m_future = QtConcurrent::run([=] {
        DayObserver obs;
        obs.fb = feedback.get();
        obs.row = [self](const DayRow& row) {
            QMetaObject::invokeMethod(
                qApp, [self, row] {
                    if (self) self->rowDone(row);
                },
                Qt::QueuedConnection);
        };
        const DayResult r = runStationDay(sources, opt, obs);
        QMetaObject::invokeMethod(
            qApp, [self, r, outDir] {
                if (self) self->runDone(r, outDir);
            },
            Qt::QueuedConnection);
    });
}

void SlrAllPassesDialog::cancel() {
    if (m_finished && !m_exporting) return;
    if (m_feedback) m_feedback->cancel();
    m_cancelButton->setEnabled(false);
    m_label->setText(tr("Cancelling after the passes under way…"));
    m_future.waitForFinished();
    QCoreApplication::sendPostedEvents();
}

bool SlrAllPassesDialog::exportCsv(const QString& path, QString* error) const {
    std::string err;
    if (!core::writeFileAtomic(path.toStdString(), dayCsv(m_rows), &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrAllPassesDialog::exportProducts(const QString& dir, QString* error) {
    if (!m_finished || m_exporting) {
        *error = tr("the screening is still under way: export when it has finished");
        return false;
    }
    m_exporting = true;
    m_productsButton->setEnabled(false);
    m_cancelButton->setEnabled(true);
    m_progress->setValue(0);
    m_done = 0;
    m_label->setText(tr("Writing the day's products into %1…").arg(dir));
    start(dir);
    return true;
}

int SlrAllPassesDialog::passOfRow(int row) const {
    const QTableWidgetItem* item = m_table->item(row, 0);
    return item ? item->data(Qt::UserRole).toInt() : -1;
}

void SlrAllPassesDialog::rowDone(const DayRow& row) {
    const int r = int(row.pass) - 1;
    if (r < 0 || r >= m_total) return;
    m_rows[size_t(r)] = row;
    const auto& cols = dayColumns();
    for (size_t c = 0; c < cols.size(); ++c) m_table->item(r, int(c))->setText(QString::fromStdString(cols[c].cell(row)));
    const int status = column("status"), reason = column("reason");
    m_table->item(r, status)->setToolTip(QString::fromStdString(row.reason));
    m_table->item(r, reason)->setToolTip(QString::fromStdString(row.reason));
    const bool failed = row.status == "failed";
    const bool notScreened = !row.screened && !failed;
    for (size_t c = 0; c < cols.size(); ++c)
        m_table->item(r, int(c))->setForeground(failed ? QColor(170, 0, 0) : notScreened ? QColor(120, 120, 120) : palette().text().color());
    if (!m_exporting) m_failed += failed;
    ++m_done;
    m_progress->setValue(m_done);
    if (!m_exporting) m_label->setText(tr("%1 of %2 blocks decided (%3 failed)").arg(m_done).arg(m_total).arg(m_failed));
}

void SlrAllPassesDialog::runDone(const DayResult& result, const QString& outDir) {
    const bool exporting = m_exporting;
    m_exporting = false;
    m_finished = true;
    m_cancelButton->setEnabled(false);
    // Blocks never reached: cancelled, or not run when the run stopped before them (a presets
    // file it could not read: seen in a real window, the rows said "waiting" under "Stopped").
    if (result.cancelled || !result.ok)
        for (int r = 0; r < m_total; ++r)
            if (m_rows[size_t(r)].status == kWaiting) {
                m_rows[size_t(r)].status = result.cancelled ? "cancelled" : "not run";
                m_table->item(r, column("status"))->setText(result.cancelled ? tr("cancelled") : tr("not run"));
            }
    m_productsButton->setEnabled((!result.cancelled && result.ok) || exporting);
    if (exporting) {
        const QString msg = result.ok ? tr("Wrote %1 files into %2").arg(result.written.size()).arg(outDir)
                                      : tr("Products not written: %1").arg(QString::fromStdString(result.error.message));
        emit productsWritten(result.ok, msg);
        return;
    }
    m_table->resizeColumnsToContents();
    if (result.cancelled)
        m_label->setText(tr("Cancelled: %1 of %2 blocks decided (%3 failed)").arg(m_done).arg(m_total).arg(m_failed));
    else if (!result.ok)
        m_label->setText(tr("Stopped: %1").arg(QString::fromStdString(result.error.message)));
    else
        m_label->setText(tr("%1 blocks: %2 screened, %3 doubtful, %4 failed, %5 station normal points, %6 skipped")
                             .arg(m_total)
                             .arg(result.screened)
                             .arg(result.doubtful)
                             .arg(result.failed)
                             .arg(result.stationNormalPoints)
                             .arg(result.skipped));
    emit allDone();
}

}  // namespace lwb::ui
