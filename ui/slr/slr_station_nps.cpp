#include "ui/slr/slr_station_nps.hpp"

#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "core/slr/crd.hpp"
#include "ui/kit/elided_label.hpp"
#include "ui/kit/save_path.hpp"
#include "core/common/atomic_file.hpp"
#include "core/slr/np_compare.hpp"
#include "ui/kit/workspace_layout.hpp"

namespace lwb::ui {

using namespace core::slr;

namespace {

enum Col { ColUtc, ColMatch, ColDelta, ColStationN, ColOurN, ColStationRms, ColOurRms, ColCount };

QString utc(double t) {
    if (!std::isfinite(t)) return {};
    const double day = std::fmod(std::fmod(t, 86400.0) + 86400.0, 86400.0);
    const long ms = std::lround(day * 1000.0);
    return QString::asprintf("%02ld:%02ld:%02ld.%03ld", ms / 3600000 % 24, ms / 60000 % 60, ms / 1000 % 60, ms % 1000);
}

QString number(double v, int decimals) { return std::isfinite(v) ? QString::number(v, 'f', decimals) : QString(); }

}  // namespace

SlrStationNpPanel::SlrStationNpPanel(QWidget* parent) : QWidget(parent) {
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(2, 2, 2, 2);
    auto* row = new QHBoxLayout;
    m_open = new QPushButton(tr("Station normal points…"), this);
    m_open->setToolTip(tr("Open the station's CRD normal-point file (.npt) for this pass: its normal points are drawn over "
                          "ours and the differences listed here"));
    m_fileLabel = new ElidedLabel(tr("no station file"), this);
    m_clear = new QToolButton(this);
    m_clear->setText(tr("Clear"));
    m_clear->setToolTip(tr("Stop comparing with the station's normal points"));
    m_export = new QToolButton(this);
    m_export->setText(tr("Export CSV…"));
    m_export->setToolTip(tr("The table of differences as CSV"));
    // The buttons with the file's name beside them, elided; the summary on one line,
    // elided (whole in its tooltip); the table has the rest. (Issue 42: at 1024 × 700 the
    // wrapping row and a wrapped summary covered Export CSV… and left the table its header.)
    // (two short rows: the tab shares a narrow column with the histogram at 1024 px)
    row->addWidget(m_open);
    row->addWidget(m_clear);
    row->addStretch(1);
    v->addLayout(row);
    auto* row2 = new QHBoxLayout;
    row2->addWidget(m_export);
    row2->addWidget(m_fileLabel, 1);
    v->addLayout(row2);
    m_summary = new ElidedLabel(QString(), this, Qt::ElideRight);
    v->addWidget(m_summary);
    m_table = new QTableWidget(0, ColCount, this);
    m_table->setHorizontalHeaderLabels({tr("UTC"), tr("Bin"), tr("Δ (mm)"), tr("Station N"), tr("Our N"), tr("Station RMS (ps)"),
                                        tr("Our RMS (ps)")});
    m_table->horizontalHeaderItem(ColStationN)->setToolTip(tr("Ranges in the station's normal point"));
    m_table->horizontalHeaderItem(ColOurN)->setToolTip(tr("Ranges in our normal point"));
    m_table->horizontalHeaderItem(ColDelta)->setToolTip(
        tr("Ours − station: our normal point less the station's, one-way range (mm), at the station's epoch (ours moved "
           "along our post-fit trend)"));
    m_table->horizontalHeaderItem(ColMatch)->setToolTip(tr("Both in this bin, or only one of the two"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->setVisible(false);
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // At least its header and two rows in view (more would take the plots' legends at 700 px).
    m_table->setMinimumHeight(m_table->horizontalHeader()->sizeHint().height() + 2 * m_table->verticalHeader()->defaultSectionSize() +
                              2 * m_table->frameWidth());
    v->addWidget(m_table, 1);
    connect(m_open, &QPushButton::clicked, this, &SlrStationNpPanel::openRequested);
    connect(m_clear, &QToolButton::clicked, this, [this] {
        clear();
        emit changed();
    });
    connect(m_export, &QToolButton::clicked, this, [this] {
        const QString path =
            askSavePath(this, tr("Export the differences"), "paths/slrExport", "station_np_differences.csv", tr("CSV (*.csv)"));
        QString err;
        if (!path.isEmpty() && !exportCsv(path, &err)) m_summary->setFullText(err);
    });
    clear();
}

void SlrStationNpPanel::show(std::shared_ptr<const CrdFile> file, const QString& path) {
    if (!file) {
        clear();
        return;
    }
    m_file = std::move(file);
    m_path = path;
    m_fileLabel->setFullText(QFileInfo(path).fileName());
    m_fileLabel->setPlainToolTip(path);
    m_clear->setEnabled(true);
}

void SlrStationNpPanel::clear() {
    m_file.reset();
    m_path.clear();
    m_cmp = NpComparison{};
    m_fileLabel->setFullText(tr("no station file"));
    m_fileLabel->setPlainToolTip(QString());
    m_clear->setEnabled(false);
    fill();
}

void SlrStationNpPanel::update(const PassData& pass, const PostfitResult* post) {
    m_cmp = NpComparison{};
    if (m_file) {
        if (post) {
            m_cmp = compareWithStation(pass, *post, *m_file, m_path.toStdString());
        } else {
            m_cmp.error = tr("%1: no post-fit of the pass yet, so no normal points of ours").arg(m_path).toStdString();
        }
    }
    fill();
}

void SlrStationNpPanel::fill() {
    m_table->setRowCount(0);
    m_export->setEnabled(m_cmp.ok);
    if (!m_file) {
        m_summary->setFullText(tr("Open the station's normal points of this pass to see them over ours, bin by bin."));
        return;
    }
    if (!m_cmp.ok) {
        m_summary->setFullText(QString::fromStdString(m_cmp.error));
        return;
    }
    m_summary->setFullText(tr("%1, %2 (block %3): %4")
                           .arg(QString::fromStdString(m_cmp.stationName), QString::fromStdString(m_cmp.satellite))
                           .arg(m_cmp.block + 1)
                           .arg(QString::fromStdString(m_cmp.describe())));
    m_table->setRowCount(int(m_cmp.rows.size()));
    for (int r = 0; r < int(m_cmp.rows.size()); ++r) {
        const NpDifference& d = m_cmp.rows[size_t(r)];
        const QString match = d.match == NpDifference::Match::Both          ? tr("both")
                              : d.match == NpDifference::Match::StationOnly ? tr("station only")
                                                                            : tr("ours only");
        const QStringList cells = {utc(d.t),
                                   match,
                                   number(d.deltaMm, 2),
                                   d.stationRanges ? QString::number(d.stationRanges) : QString(),
                                   d.ourRanges ? QString::number(d.ourRanges) : QString(),
                                   number(d.stationRmsPs, 1),
                                   number(d.ourRmsPs, 1)};
        for (int c = 0; c < ColCount; ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c != ColUtc && c != ColMatch) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, c, item);
        }
    }
}

bool SlrStationNpPanel::exportCsv(const QString& path, QString* error) const {
    if (!m_cmp.ok) {
        *error = tr("Nothing to export: %1").arg(QString::fromStdString(m_cmp.error));
        return false;
    }
    // The core's CSV (machine column names, the date with the time): not the table's cells.
    std::string why;
    if (!core::writeFileAtomic(path.toStdString(), npComparisonCsv(m_cmp), &why)) {
        *error = QString::fromStdString(why);
        return false;
    }
    return true;
}

}  // namespace lwb::ui
