#include "ui/slr_all_passes.hpp"
#include "ui/save_path.hpp"
#include "ui/table_csv.hpp"

#include <QDateTime>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QGuiApplication>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/slr/pass_run.hpp"
#include "ui/slr_controller.hpp"

namespace lwb::ui {

using namespace core::slr;

namespace {
QString fixed(double v, int decimals) { return std::isfinite(v) ? QString::number(v, 'f', decimals) : QString(); }
}  // namespace

SlrAllPassesDialog::SlrAllPassesDialog(const SlrController* controller, const SlrParams& base, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("All passes of %1").arg(QFileInfo(controller->path()).fileName()));
    // As wide as the table wants, within the screen (1100 px put Close off a 1024 px screen).
    const QRect avail = (parent && parent->screen() ? parent->screen() : QGuiApplication::primaryScreen())->availableGeometry();
    resize(std::min(1100, avail.width() - 40), std::min(560, avail.height() - 80));
    auto* l = new QVBoxLayout(this);
    m_table = new QTableWidget(this);
    m_table->setColumnCount(ColCount);
    m_table->setHorizontalHeaderLabels({tr("Pass"), tr("Start (UTC)"), tr("Station"), tr("Satellite"), tr("Points"),
                                        tr("Accepted"), tr("RMS (mm)"), tr("Normal points"), tr("Station flags (P / R)"),
                                        tr("Time (s)"), tr("Status")});
    m_table->horizontalHeaderItem(ColRms)->setToolTip(tr("RMS of the post-fit residuals of the kept points, mm one-way"));
    m_table->horizontalHeaderItem(ColAgreement)->setToolTip(
        tr("The screening against the station's own filter flags: precision / recall (blank when the flags are incomplete)"));
    m_table->horizontalHeaderItem(ColSeconds)->setToolTip(tr("Wall time of the screening and post-fit of the pass"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->setToolTip(tr("Double-click a row (or select it and press Open) to open that pass in the workspace"));
    l->addWidget(m_table, 1);
    auto* row = new QHBoxLayout;
    m_label = new QLabel(this);
    m_progress = new QProgressBar(this);
    m_progress->setToolTip(tr("Passes screened so far"));
    m_cancelButton = new QPushButton(tr("Cancel"), this);
    m_cancelButton->setToolTip(tr("Stop after the pass under way; the passes not reached are marked cancelled"));
    m_exportButton = new QPushButton(tr("Export CSV…"), this);
    m_exportButton->setToolTip(tr("Write the table as it stands to a CSV file (one row per pass, the columns shown)"));
    m_openButton = new QPushButton(tr("Open pass"), this);
    m_openButton->setToolTip(tr("Open the selected pass in the SLR workspace"));
    auto* close = new QPushButton(tr("Close"), this);
    close->setToolTip(tr("Close the table (a screening under way is cancelled)"));
    row->addWidget(m_label, 1);
    row->addWidget(m_progress, 1);
    row->addWidget(m_cancelButton);
    row->addWidget(m_exportButton);
    row->addWidget(m_openButton);
    row->addWidget(close);
    l->addLayout(row);

    // Rows in time order (the start in the H4 record; passes without one last, in file order).
    const std::vector<PassSummary> passes = controller->passes();
    std::vector<int> order(passes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return passes[size_t(a)].start < passes[size_t(b)].start; });
    m_total = int(order.size());
    m_table->setRowCount(m_total);
    for (int r = 0; r < m_total; ++r) {
        const PassSummary& s = passes[size_t(order[size_t(r)])];
        const QStringList cells{QString::number(s.index + 1), QString::fromStdString(s.start), QString::fromStdString(s.station),
                                QString::fromStdString(s.satellite), QString::number(s.ranges)};
        for (int c = 0; c < ColCount; ++c) {
            auto* item = new QTableWidgetItem(c < cells.size() ? cells[c] : QString());
            if (c == ColPass) item->setData(Qt::UserRole, s.index);
            if (c == ColPass || (c >= ColPoints && c <= ColSeconds)) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, c, item);
        }
        m_table->item(r, ColStatus)->setText(tr("waiting"));
    }
    m_table->resizeColumnsToContents();
    m_progress->setRange(0, std::max(1, m_total));
    m_progress->setValue(0);
    m_label->setText(tr("Screening %1 passes…").arg(m_total));

    connect(m_cancelButton, &QPushButton::clicked, this, &SlrAllPassesDialog::cancel);
    connect(close, &QPushButton::clicked, this, &QDialog::reject);
    connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int r, int) { emit openPass(passOfRow(r)); });
    connect(m_openButton, &QPushButton::clicked, this, [this] {
        if (m_table->currentRow() >= 0) emit openPass(passOfRow(m_table->currentRow()));
    });
    connect(this, &QDialog::rejected, this, &SlrAllPassesDialog::cancel);

    connect(m_exportButton, &QPushButton::clicked, this, [this] {
        const QString path = askSavePath(this, tr("Export the table"), "paths/slrExport", "all_passes.csv", tr("CSV (*.csv)"));
        QString err;
        if (!path.isEmpty() && !exportCsv(path, &err)) m_label->setText(err);
    });

    // The worker: the file, the sources and the settings shared read-only.
    const auto crd = controller->crd();
    const auto sources = controller->sources();
    PassInputParams input = controller->inputParams();
    input.cpfFallback = true;
    const std::string path = controller->path().toStdString();
    const auto cancelFlag = m_cancel;
    QPointer<SlrAllPassesDialog> self(this);
    m_future = QtConcurrent::run([=] {
        for (int r = 0; r < int(order.size()); ++r) {
            if (cancelFlag->load()) return;
            const int index = order[size_t(r)];
            QStringList cells;
            bool ok = false;
            // Not a pass to screen (the station's own normal points, engineering data, too few
            // records): listed as laserwb-cli slr --all-passes lists it (core blockStatus).
            if (const BlockStatus b = blockStatus(passes[size_t(index)]); !b.status.empty()) {
                cells << QString() << QString() << QString() << QString() << QString()
                      << QString::fromStdString(b.status + ": " + b.reason);
                QMetaObject::invokeMethod(
                    qApp, [self, r, cells] {
                        if (self) self->rowDone(r, cells, true);
                    },
                    Qt::QueuedConnection);
                continue;
            }
            const PassInputResult p = crd ? passFromCrd(crd, path, index, input, *sources) : PassInputResult{};
            std::string err;
            PassSettings settings;
            if (!crd) {
                cells << tr("failed: no CRD file");
            } else if (!p.ok) {
                cells << tr("failed: %1").arg(QString::fromStdString(p.error).section('\n', 0, 0));
            } else if (!p.pass.damaged.empty()) {
                cells << tr("failed: %1").arg(QString::fromStdString(p.pass.damaged));
            } else if (!passSettings(p.pass, base, nullptr, std::string(), sources->haveStations ? &sources->stations : nullptr,
                                     &settings, &err)) {
                cells << tr("failed: %1").arg(QString::fromStdString(err));
            } else {
                const PassRunResult run = runPass(p.pass, settings.params);
                if (!run.ok) {
                    cells << tr("failed: screening: %1").arg(QString::fromStdString(run.error));
                } else {
                    ok = true;
                    const double rms = run.postOk ? run.post.stats.rms : NAN;
                    const StationAgreement& a = run.agreement;
                    cells << QString::number(run.acceptedCount) << fixed(rms * 0.5 * 299792458.0 * 1e3, 2)
                          << (run.postOk ? QString::number(run.post.normalPoints.size()) : QString())
                          // (a precision of nothing accepted is 0/0: a dash, not a blank before the slash)
                          << (a.available ? QString("%1 / %2").arg(std::isfinite(a.precision) ? fixed(a.precision, 3)
                                                                                              : QString::fromUtf8("—"),
                                                                   fixed(a.recall, 3))
                                          : QString())
                          << fixed(run.seconds, 2);
                    // The CLI's status (core runStatus): ok, no signal or doubtful, with its reason.
                    const BlockStatus st = runStatus(p.pass, run);
                    QString status = st.status == "doubtful"
                                         ? QString::fromStdString("doubtful: " + st.reason)
                                         : tr("%1, O-C from %2").arg(QString::fromStdString(st.status), QString::fromStdString(p.pass.ocOrigin));
                    if (st.status != "doubtful" && !st.reason.empty() && st.reason != "no signal found")
                        status += " — " + QString::fromStdString(st.reason);
                    cells << status;
                }
            }
            QMetaObject::invokeMethod(
                qApp, [self, r, cells, ok] {
                    if (self) self->rowDone(r, cells, ok);
                },
                Qt::QueuedConnection);
        }
    });
}

SlrAllPassesDialog::~SlrAllPassesDialog() {
    m_cancel->store(true);
    m_future.waitForFinished();
}

void SlrAllPassesDialog::cancel() {
    if (m_finished) return;
    m_cancel->store(true);
    m_cancelButton->setEnabled(false);
    m_label->setText(tr("Cancelling after the pass under way…"));
    // The rows the worker will not reach.
    m_future.waitForFinished();
    QCoreApplication::sendPostedEvents();
    for (int r = 0; r < m_total; ++r)
        if (m_table->item(r, ColStatus)->text() == tr("waiting")) m_table->item(r, ColStatus)->setText(tr("cancelled"));
    m_finished = true;
    m_label->setText(tr("Cancelled: %1 of %2 passes screened (%3 failed)").arg(m_done).arg(m_total).arg(m_failed));
    emit allDone();
}

bool SlrAllPassesDialog::exportCsv(const QString& path, QString* error) const {
    return writeTableCsv(m_table, path, error);
}

int SlrAllPassesDialog::passOfRow(int row) const {
    const QTableWidgetItem* item = m_table->item(row, ColPass);
    return item ? item->data(Qt::UserRole).toInt() : -1;
}

void SlrAllPassesDialog::rowDone(int row, const QStringList& cells, bool ok) {
    if (m_finished) return;
    if (ok)
        for (int k = 0; k < cells.size(); ++k) m_table->item(row, ColAccepted + k)->setText(cells[k]);
    else {
        m_table->item(row, ColStatus)->setText(cells.value(0));
        m_table->item(row, ColStatus)->setToolTip(cells.value(0));
        for (int c = 0; c < ColCount; ++c) m_table->item(row, c)->setForeground(QColor(170, 0, 0));
        ++m_failed;
    }
    m_table->item(row, ColStatus)->setToolTip(m_table->item(row, ColStatus)->text());
    ++m_done;
    m_progress->setValue(m_done);
    m_label->setText(tr("%1 of %2 passes screened (%3 failed)").arg(m_done).arg(m_total).arg(m_failed));
    if (m_done == m_total) {
        m_finished = true;
        m_cancelButton->setEnabled(false);
        m_table->resizeColumnsToContents();
        emit allDone();
    }
}

}  // namespace lwb::ui
