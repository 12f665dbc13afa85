#pragma once
// A table widget's cells as CSV (its header, then every row as shown), written atomically: the
// "Export CSV" of the workbench's result tables.
#include <QString>

class QTableWidget;

namespace lwb::ui {

/// False with *error ("PATH: why"); nothing is left half written.
bool writeTableCsv(const QTableWidget* table, const QString& path, QString* error);

}  // namespace lwb::ui
