#pragma once
// The workbench's "save as" question: a file dialog opened in the folder last used for this
// kind of output (QSettings key), with a suggested name, and the filter's suffix added when the
// name given has none ("table" → "table.csv": files without a suffix were written before).
#include <QString>

class QWidget;

namespace lwb::ui {

/// "" when cancelled. `filter`: Qt's syntax, "CSV (*.csv)"; the suffix added is the first
/// pattern's of the filter chosen.
QString askSavePath(QWidget* parent, const QString& title, const QString& settingsKey, const QString& suggestedName,
                    const QString& filter);
/// `path` with `suffix` ("csv") added when its name has none of the filter's suffixes.
QString withFilterSuffix(const QString& path, const QString& filter);

}  // namespace lwb::ui
