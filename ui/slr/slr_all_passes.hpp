#pragma once
// "Screen all passes": the station-file batch of the core (core/slr/station_day.hpp, the task
// laserwb-cli slr --all-passes runs) on the open CRD file, in the background, with progress and
// Cancel. The table is summary.csv: its columns (core dayColumns, their docs as tooltips), one
// row per block in the file's order, the same statuses (the station's normal points and
// engineering data are listed as what they are, never screened). The settings are the CLI's
// for `--all-passes --preset PRESETS [--cpf --stations]`: the command's defaults and each
// satellite's saved preset. "Export CSV…" writes summary.csv's bytes; "Export products…"
// writes the day's products into a folder, as the CLI does. Activating a screened row opens
// that pass in the workspace.
#include <QDialog>
#include <QFuture>
#include <atomic>
#include <memory>
#include <vector>

#include "core/slr/station_day.hpp"

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace lwb::ui {

class SlrController;

class SlrAllPassesDialog : public QDialog {
    Q_OBJECT
public:
    /// Screens every block of `controller`'s open CRD file (its CPF and SINEX), with the presets
    /// of `presetFile` when it exists — starts at once.
    SlrAllPassesDialog(const SlrController* controller, const QString& presetFile, QWidget* parent = nullptr);
    ~SlrAllPassesDialog() override;
    QTableWidget* table() const { return m_table; }
    /// The table's column of summary.csv's column `name` (-1 when none).
    static int column(const std::string& name);
    /// Blocks decided so far.
    int done() const { return m_done; }
    bool finished() const { return m_finished; }
    /// Stops after the passes under way; the rows not reached say "cancelled".
    void cancel();
    /// summary.csv of the blocks decided so far (the CLI's bytes once finished). False with *error.
    bool exportCsv(const QString& path, QString* error) const;
    /// The day's products into `dir` (the CLI's --all-passes --out-dir DIR), run again in the
    /// background; productsWritten() says when. False (with *error) when they cannot start.
    bool exportProducts(const QString& dir, QString* error);
    /// The pass (0-based index in the file) of a table row.
    int passOfRow(int row) const;

signals:
    void openPass(int passIndex);
    void allDone();
    /// The products export ended: ok, and what it wrote or why not.
    void productsWritten(bool ok, const QString& message);

private:
    void start(const QString& outDir);
    void rowDone(const core::slr::DayRow& row);
    void runDone(const core::slr::DayResult& result, const QString& outDir);

    core::slr::SlrSources m_sources;  ///< what the run is set up from (core runStationDay)
    QTableWidget* m_table;
    QProgressBar* m_progress;
    QLabel* m_label;
    QPushButton *m_cancelButton, *m_exportButton, *m_productsButton, *m_openButton;
    std::shared_ptr<core::Feedback> m_feedback;
    QFuture<void> m_future;
    std::vector<core::slr::DayRow> m_rows;
    int m_total = 0, m_done = 0, m_failed = 0;
    bool m_finished = false, m_exporting = false;
};

}  // namespace lwb::ui
