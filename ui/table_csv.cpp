#include "ui/table_csv.hpp"

#include <QTableWidget>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"

namespace lwb::ui {

bool writeTableCsv(const QTableWidget* table, const QString& path, QString* error) {
    auto cell = [](const QTableWidgetItem* item) { return core::csvEscape(item ? item->text().toStdString() : std::string()); };
    std::string text;
    for (int c = 0; c < table->columnCount(); ++c) text += (c ? "," : "") + cell(table->horizontalHeaderItem(c));
    text += "\n";
    for (int r = 0; r < table->rowCount(); ++r) {
        for (int c = 0; c < table->columnCount(); ++c) text += (c ? "," : "") + cell(table->item(r, c));
        text += "\n";
    }
    std::string err;
    if (core::writeFileAtomic(path.toStdString(), text, &err)) return true;
    if (error) *error = QString::fromStdString(err);
    return false;
}

}  // namespace lwb::ui
