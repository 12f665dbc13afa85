#pragma once
// CSV reading (RFC 4180 quoting, CRLF, '#' comment lines) with line numbers kept for
// error messages, and field escaping for writers.
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace lwb::core {

struct CsvTable {
    std::vector<std::string> header;             ///< first non-comment line
    std::vector<std::vector<std::string>> rows;  ///< data rows, each header.size() fields
    std::vector<long> lines;                     ///< 1-based source line of each row
    /// Column index of `name` (exact, case-insensitive), or -1.
    int column(std::string_view name) const;
    /// Index of the first of `names` present (aliases for one quantity), or -1.
    int firstColumn(std::initializer_list<const char*> names) const;
};

struct CsvReadResult {
    bool ok = false;
    std::string error;  ///< "FILE:LINE: what is wrong"
    CsvTable table;
};

/// Most data fields a table may hold (rows x columns): 10 million, about 400 MB in memory.
constexpr size_t kMaxCsvFields = 10000000;

/// Parses CSV text. `source` names the input in error messages.
CsvReadResult parseCsv(std::string_view text, const std::string& source);
/// Reads and parses a CSV file.
CsvReadResult readCsv(const std::string& path);

/// Quotes a field when it holds a comma, quote or line break.
std::string csvEscape(std::string_view field);

}  // namespace lwb::core
