#pragma once
// A small expression language that selects rows of a table by their columns, as the footprint
// shot list's filter field and `laserwb-cli footprint --where` use it:
//
//   snr < 10 and beam == 2        verdict == "doubtful" or note != ""
//   abs(dx) > 0.5                 not (roi == 1)         x - roi_x0 > 16
//
// Comparisons < <= > >= == !=, and / or / not (words), parentheses, numbers, "quoted" or
// 'quoted' strings, + - * / on numbers, the functions abs and sqrt, and column names
// (case-insensitive). Precedence, loosest first: or, and, not, comparison, + -, * /, unary -.
// A comparison of a number with a text compares the text's number (a text that is no number
// makes the comparison false); two texts compare without regard to case. A missing or NaN number
// makes every comparison with it false (so `snr < 10` and `snr >= 10` are both false for a shot
// without an SNR; `not (snr >= 10)` is true).
//
// The text is compiled once (compileRowFilter) into a tree and evaluated per row
// (RowFilter::matches). No exception leaves these functions.
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace lwb::core {

/// One cell of a row: a number (NaN = missing) or a text (whose number, when it reads as one,
/// is kept beside it).
struct FilterCell {
    double number = std::numeric_limits<double>::quiet_NaN();
    std::string text;
    bool isText = false;
    static FilterCell num(double v) {
        FilterCell c;
        c.number = v;
        return c;
    }
    static FilterCell str(std::string s);
};

struct RowFilterParams {
    std::string text;                  ///< the expression
    std::vector<std::string> columns;  ///< the column names a row's cells follow (case-insensitive)
};

struct RowFilterNode;
struct RowFilterResult;

/// A compiled expression.
class RowFilter {
public:
    /// True when the row (cells in the order of RowFilterParams::columns) is selected. A row
    /// shorter than a used column reads that column as missing.
    bool matches(const std::vector<FilterCell>& row) const;
    /// Columns the expression reads (indices into RowFilterParams::columns, ascending, once each).
    const std::vector<int>& usedColumns() const { return m_used; }

private:
    friend struct RowFilterCompiler;
    friend RowFilterResult compileRowFilter(const RowFilterParams& params);
    std::vector<RowFilterNode> m_nodes;  // the tree, children before parents; the root is last
    std::vector<int> m_used;
};

struct RowFilterResult {
    bool ok = false;
    /// "column 'snrr' unknown at 1; columns: file, x, ..." — positions are 1-based characters.
    std::string error;
    size_t errorPos = 0;  ///< 1-based position of the error (0: none)
    std::shared_ptr<const RowFilter> filter;
    /// An empty (blank) expression: every row is selected; `filter` is null.
    bool empty = false;
};

RowFilterResult compileRowFilter(const RowFilterParams& params);

}  // namespace lwb::core
