#pragma once
// The footprint report's columns, declared once: name, unit, meaning, type, how the CSV writes
// the number, and the getter of a row's value. The CSV writer (core/footprint/batch.hpp), the
// CLI's --where, the workbench's shot table and filter, and Python's arrays all read this table,
// so a new column is one row here.
#include <string>
#include <string_view>
#include <vector>

#include "core/common/row_filter.hpp"
#include "core/footprint/pipeline.hpp"

namespace lwb::core::footprint {

/// One row of a report: a shot's ROI (or its frame, unreadable), with the analyst's review.
struct ReportRow {
    std::string_view file, time, beam, camera;
    const FootprintResult* result = nullptr;  ///< null: the frame could not be read
    std::string_view readError;               ///< (when result is null)
    int roi = 0;                              ///< the ROI's index in its frame
    int originX = 0, originY = 0;             ///< the ROI's first pixel in the frame
    Method method = Method::Gauss;            ///< the run's method (a failed row's method column)
    // The review (review reports: the workbench's exports)
    bool review = false;                      ///< the effective verdict is the manual one where set
    bool overridden = false;
    Verdict manual = Verdict::Good;
    std::string_view note;

    bool failed() const { return !result || !result->ok; }
    /// The verdict the row reports: rejected when failed, the manual one (review) where set.
    Verdict verdict() const;
};

enum class ColumnType { Text, Integer, Real };

struct FootprintColumn {
    const char* name;
    const char* unit;       ///< "" none
    const char* doc;        ///< one line: the CLI's help, the table's tooltip, the plot's axis
    ColumnType type;
    int decimals;           ///< Real: digits after the point; -1 = 4 significant digits (1.234e-05)
    bool reviewOnly;        ///< only in review reports (auto_verdict, override, note)
    FilterCell (*value)(const ReportRow&);  ///< NaN / "" = an empty cell
};

/// Every column, in the report's order (the review columns last).
const std::vector<FootprintColumn>& footprintColumns();
/// The report's column names (review: with the review columns).
std::vector<std::string> footprintColumnNames(bool review = false);
/// A cell as the CSV writes it (numbers at the column's precision, text CSV-escaped).
std::string footprintCsvCell(const FootprintColumn& c, const ReportRow& row);

}  // namespace lwb::core::footprint
