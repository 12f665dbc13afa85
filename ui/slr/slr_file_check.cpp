#include "ui/slr/slr_file_check.hpp"

#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lwb::ui {

using namespace core::slr;

SlrFileCheckDialog::SlrFileCheckDialog(const CrdCheckResult& r, const QString& path, QWidget* parent) : QDialog(parent) {
    setObjectName("slrFileCheck");
    setWindowTitle(tr("CRD file check"));
    const std::string source = path.toStdString();
    for (const CrdProblem& p : r.problems) m_text += QString::fromStdString(formatCrdProblem(source, p)) + '\n';
    m_text += QString::fromStdString(crdCheckSummary(r, source)) + '\n';

    auto* v = new QVBoxLayout(this);
    m_summary = new QLabel(QString::fromStdString(crdCheckSummary(r, source)), this);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(m_summary);
    m_table = new QTableWidget(int(r.problems.size()), 5, this);
    m_table->setHorizontalHeaderLabels({tr("Line"), tr("Severity"), tr("Record"), tr("Rule"), tr("Reason")});
    m_table->horizontalHeaderItem(3)->setToolTip(tr("The rule of the CRD specification it breaks (docs/crd-check.md)"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(false);
    for (int i = 0; i < int(r.problems.size()); ++i) {
        const CrdProblem& p = r.problems[size_t(i)];
        QString line = p.line > 0 ? QString::number(p.line) : tr("file");
        if (p.lastLine > p.line) line += QStringLiteral("–%1").arg(p.lastLine);
        const bool error = p.severity == CrdSeverity::Error;
        QString why = QString::fromStdString(p.message);
        if (p.count > 1) why += tr(" (%n like it)", nullptr, int(p.count));
        const QStringList cells = {line, error ? tr("error") : tr("warning"), QString::fromStdString(p.record),
                                   QString::fromStdString(p.rule), why};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c == 4) item->setToolTip(QString::fromStdString(formatCrdProblem(source, p)));
            if (c == 1) item->setForeground(error ? QColor(170, 0, 0) : QColor(150, 100, 0));
            m_table->setItem(i, c, item);
        }
    }
    m_table->resizeColumnsToContents();
    v->addWidget(m_table, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* copy = buttons->addButton(tr("Copy as text"), QDialogButtonBox::ActionRole);
    copy->setToolTip(tr("The list as laserwb-cli crd check prints it, a line per problem"));
    connect(copy, &QPushButton::clicked, this, [this] { QApplication::clipboard()->setText(m_text); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    v->addWidget(buttons);
    resize(860, 480);
}

}  // namespace lwb::ui
