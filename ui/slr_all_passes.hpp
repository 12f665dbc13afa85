#pragma once
// "Screen all passes": every pass of the open CRD file screened in the background (core
// runPass per pass, the same path as `laserwb-cli slr --all-passes`), one table row per pass in
// time order, with progress and Cancel; a failing pass is a row with its reason and the rest go
// on; activating a row opens that pass in the workspace.
#include <QDialog>
#include <QFuture>
#include <atomic>
#include <memory>

#include "core/slr/slr_params.hpp"

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace lwb::ui {

class SlrController;

class SlrAllPassesDialog : public QDialog {
    Q_OBJECT
public:
    /// Columns of the table.
    enum Column { ColPass, ColStart, ColStation, ColSatellite, ColPoints, ColAccepted, ColRms, ColNormalPoints,
                  ColAgreement, ColSeconds, ColStatus, ColCount };
    /// Screens every pass of `controller`'s open CRD file with `base` (per pass: its preset-free
    /// settings, core::slr::passSettings) — starts at once.
    SlrAllPassesDialog(const SlrController* controller, const core::slr::SlrParams& base, QWidget* parent = nullptr);
    ~SlrAllPassesDialog() override;
    QTableWidget* table() const { return m_table; }
    /// Passes finished (screened or failed).
    int done() const { return m_done; }
    bool finished() const { return m_finished; }
    /// Stops after the pass under way; the rows not reached say "cancelled".
    void cancel();
    /// The table as it stands, as CSV (the columns shown, one row per block), written whole or
    /// not at all. False with *error.
    bool exportCsv(const QString& path, QString* error) const;
    /// The pass (0-based index in the file) of a table row.
    int passOfRow(int row) const;

signals:
    void openPass(int passIndex);
    void allDone();

private:
    void rowDone(int row, const QStringList& cells, bool ok);

    QTableWidget* m_table;
    QProgressBar* m_progress;
    QLabel* m_label;
    QPushButton *m_cancelButton, *m_exportButton, *m_openButton;
    std::shared_ptr<std::atomic<bool>> m_cancel = std::make_shared<std::atomic<bool>>(false);
    QFuture<void> m_future;
    int m_total = 0, m_done = 0, m_failed = 0;
    bool m_finished = false;
};

}  // namespace lwb::ui
