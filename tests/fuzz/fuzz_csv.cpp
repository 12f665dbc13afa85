// libFuzzer target: the CSV tokenizer every typed CSV reader uses (core::parseCsv; RFC 4180
// quotes, CRLF, '#' comments, a UTF-8 BOM). A failed read says why; a table that reads has
// rows as wide as the header with increasing source lines, and written back with csvEscape
// (after a BOM, which the reader removes once) reads back to the same header and rows.
#include <string>

#include "core/common/csv.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core;
using lwb::fuzz::check;

namespace {
std::string joinEscaped(const std::vector<std::string>& fields) {
    std::string s;
    for (size_t i = 0; i < fields.size(); ++i) s += (i ? "," : "") + csvEscape(fields[i]);
    return s + "\n";
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const CsvReadResult r = parseCsv(lwb::fuzz::asText(data, size), "fuzz");
    lwb::fuzz::checkReported(r.ok, r.error);
    if (!r.ok) return 0;
    const CsvTable& t = r.table;
    check(t.rows.size() == t.lines.size());
    long previous = 0;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        check(t.rows[i].size() == t.header.size());
        check(t.lines[i] > previous);
        previous = t.lines[i];
    }
    std::string text = "\xEF\xBB\xBF" + joinEscaped(t.header);
    for (const auto& row : t.rows) text += joinEscaped(row);
    const CsvReadResult back = parseCsv(text, "fuzz");
    check(back.ok);
    check(back.table.header == t.header);
    check(back.table.rows == t.rows);
    return 0;
}
