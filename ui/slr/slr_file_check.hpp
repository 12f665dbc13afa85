#pragma once
// The CRD file check in the workbench (issue 43): every problem core checkCrd finds in the open
// file, as `laserwb-cli crd check FILE` lists them (the same checker, the same lines: Copy puts
// the CLI's text on the clipboard), in a table by line with the rule and the reason.
#include <QDialog>

#include "core/slr/crd_check.hpp"

class QLabel;
class QTableWidget;

namespace lwb::ui {

class SlrFileCheckDialog : public QDialog {
    Q_OBJECT
public:
    SlrFileCheckDialog(const core::slr::CrdCheckResult& result, const QString& path, QWidget* parent = nullptr);

    /// The problems as `laserwb-cli crd check` prints them, a line each, then its summary line.
    QString cliText() const { return m_text; }
    QTableWidget* table() const { return m_table; }
    QLabel* summaryLabel() const { return m_summary; }

private:
    QString m_text;
    QLabel* m_summary;
    QTableWidget* m_table;
};

}  // namespace lwb::ui
