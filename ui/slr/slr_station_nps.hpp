#pragma once
// The station's normal points beside ours (issue 29): a station's CRD normal-point file opened
// beside the pass; the block of the pass's satellite is matched with our normal points bin by
// bin (core slr::compareWithStation), the differences listed here and the station's points
// drawn over the O-C by the SLR workspace. Follows every run: the table changes with the
// parameters.
#include <memory>

#include <QWidget>

#include "ui/kit/elided_label.hpp"
#include "core/slr/np_compare.hpp"

class QLabel;
class QPushButton;
class QTableWidget;
class QToolButton;

namespace lwb::ui {

class SlrStationNpPanel : public QWidget {
    Q_OBJECT
public:
    explicit SlrStationNpPanel(QWidget* parent = nullptr);

    /// Shows the station's normal points of the run (read by the core into the run's set-up:
    /// SlrController::setStationNormalPoints), named `path`; null clears.
    void show(std::shared_ptr<const core::slr::CrdFile> file, const QString& path);
    void clear();
    bool hasFile() const { return static_cast<bool>(m_file); }
    QString path() const { return m_path; }
    /// Compares again with this pass and its post-fit (nullptr: none, the table says why).
    void update(const core::slr::PassData& pass, const core::slr::PostfitResult* post);
    const core::slr::NpComparison& comparison() const { return m_cmp; }
    /// The table as CSV (written to a temporary and renamed). False with *error.
    bool exportCsv(const QString& path, QString* error) const;

    QTableWidget* table() const { return m_table; }
    QLabel* summaryLabel() const { return m_summary; }

signals:
    /// A file was opened or cleared, or the comparison changed: the overlay is to be drawn again.
    void changed();
    /// The user asked to open a file (the workspace opens its dialog, as for its other inputs).
    void openRequested();

private:
    void fill();

    std::shared_ptr<const core::slr::CrdFile> m_file;
    QString m_path;
    core::slr::NpComparison m_cmp;
    ElidedLabel *m_fileLabel, *m_summary;
    QPushButton* m_open;
    QToolButton *m_clear, *m_export;
    QTableWidget* m_table;
};

}  // namespace lwb::ui
