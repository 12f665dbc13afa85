#pragma once
// The columns of the footprint shot list as the filter expression (core/common/row_filter) and
// the column plot see them: the table's columns and the report's (`laserwb-cli footprint`)
// under their CSV names, plus dx, dy and manual. One list, so that the filter field's tooltip
// and completer, the filter and the plot's X / Y choosers agree.
#include <QString>
#include <QStringList>
#include <vector>

#include "core/common/row_filter.hpp"

namespace lwb::ui {

struct Shot;
class FootprintController;

/// The ROI index of shot `row` within its frame (the shots of a frame follow one another).
int shotRoiIndex(const FootprintController& c, int row);

enum class ShotColumnKind { Number, Text, Time };

struct ShotColumn {
    const char* name;  ///< as in the CSV report (lower case)
    ShotColumnKind kind;
    const char* doc;   ///< one line for the tooltip and the plot's axis label
    const char* unit;  ///< "" when none
};

/// Every column, in the order of the filter's row cells.
const std::vector<ShotColumn>& shotColumns();
/// The names (row_filter's RowFilterParams::columns).
const std::vector<std::string>& shotColumnNames();
/// Index of a column by name (case-insensitive), or -1.
int shotColumnIndex(const QString& name);
/// The columns a plot can use (numbers and the time), as indices into shotColumns().
std::vector<int> plottableShotColumns();

/// The cell of column `col` for a shot. `roiIndex`: the shot's ROI within its frame.
core::FilterCell shotCell(const Shot& s, int roiIndex, int col);
/// A number for the plot: the number, or for the time seconds since 1970 UTC (NaN: none).
double shotNumber(const Shot& s, int roiIndex, int col);
/// A shot's time as seconds since 1970 UTC (ISO date-time, date or month), NaN when none.
double shotTimeSeconds(const QString& time);

/// The filter field's tooltip: the language in short and the columns.
QString shotFilterHelp();

}  // namespace lwb::ui
