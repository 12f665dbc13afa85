#pragma once
// The workbench's "save as" question: a file dialog opened in the folder last used for this
// kind of output (QSettings key), with a suggested name, and the filter's suffix added when the
// name given has none of the dialog's types ("table" → "table.csv": files without a suffix were
// written before; "x.svg" stays "x.svg" whichever type is chosen).
#include <QString>

class QWidget;

namespace lwb::ui {

/// "" when cancelled. `filter`: Qt's syntax, "CSV (*.csv)"; the suffix added is the first
/// pattern's of the filter chosen.
QString askSavePath(QWidget* parent, const QString& title, const QString& settingsKey, const QString& suggestedName,
                    const QString& filter);
/// `path` with the first suffix of `filter` (the type chosen, "CSV (*.csv)") added when its name
/// has none of that filter's suffixes, nor one of `allFilters` (the dialog's whole list: a name
/// "x.svg" with the PNG type chosen stays "x.svg", and is written as SVG).
QString withFilterSuffix(const QString& path, const QString& filter, const QString& allFilters = QString());

}  // namespace lwb::ui
