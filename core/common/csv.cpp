#include "core/common/csv.hpp"

#include <unordered_map>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"

namespace lwb::core {

int CsvTable::column(std::string_view name) const {
    const std::string want = toLower(trim(name));
    for (size_t i = 0; i < header.size(); ++i)
        if (toLower(trim(header[i])) == want) return static_cast<int>(i);
    return -1;
}

int CsvTable::firstColumn(std::initializer_list<const char*> names) const {
    for (const char* n : names)
        if (const int c = column(n); c >= 0) return c;
    return -1;
}

namespace {
// Splits one logical record starting at text[pos]; advances pos past its line end.
// Returns false with *err on an unterminated quote.
bool nextRecord(std::string_view text, size_t& pos, long& line, std::vector<std::string>& fields,
                std::string* err) {
    fields.clear();
    std::string cur;
    bool inQuotes = false, fieldStarted = false;
    const long startLine = line;
    while (pos < text.size()) {
        const char c = text[pos++];
        if (inQuotes) {
            if (c == '"') {
                if (pos < text.size() && text[pos] == '"') {
                    cur.push_back('"');
                    ++pos;
                } else {
                    inQuotes = false;
                }
            } else {
                if (c == '\n') ++line;
                cur.push_back(c);
            }
            continue;
        }
        if (c == '"' && !fieldStarted) {
            inQuotes = true;
            fieldStarted = true;
        } else if (c == ',') {
            fields.push_back(std::move(cur));
            cur.clear();
            fieldStarted = false;
        } else if (c == '\n') {
            ++line;
            break;
        } else if (c == '\r') {
            // dropped: CRLF line ends
        } else {
            cur.push_back(c);
            fieldStarted = true;
        }
    }
    if (inQuotes) {
        *err = std::to_string(startLine) + ": a quoted field opened on this line is never closed (a \" missing, or the file cut short)";
        return false;
    }
    fields.push_back(std::move(cur));
    return true;
}
}  // namespace

CsvReadResult parseCsv(std::string_view given, const std::string& source) {
    CsvReadResult r;
    std::string storage;
    std::string_view text = plainText(given, &storage);  // (no byte order mark, LF line ends)
    size_t pos = 0;
    long line = 1;
    std::vector<std::string> fields;
    bool haveHeader = false;
    size_t fieldCount = 0;
    while (pos < text.size()) {
        const long recLine = line;
        std::string err;
        if (!nextRecord(text, pos, line, fields, &err)) {
            r.error = source + ":" + err;
            return r;
        }
        if (fields.size() == 1 && trim(fields[0]).empty()) continue;  // blank line
        if (!fields.empty() && !fields[0].empty() && trim(fields[0]).substr(0, 1) == "#") continue;
        if (!haveHeader) {
            for (auto& f : fields) f = std::string(trim(f));
            // A name twice: which column is meant cannot be known (it was the first, silently).
            // One pass with a hash of the names seen (a nested scan took 42 s for 40 000 columns).
            std::unordered_map<std::string, size_t> seen;
            seen.reserve(fields.size());
            for (size_t k = 0; k < fields.size(); ++k) {
                if (fields[k].empty()) continue;
                const auto [it, fresh] = seen.emplace(toLower(fields[k]), k);
                if (!fresh) {
                    r.error = source + ":" + std::to_string(recLine) + ": column \"" + printableExcerpt(fields[it->second]) +
                              "\" appears twice in the header (columns " + std::to_string(it->second + 1) + " and " +
                              std::to_string(k + 1) + ")";
                    return r;
                }
            }
            r.table.header = fields;
            haveHeader = true;
            continue;
        }
        // Every field is a std::string (32 bytes before its text): a file of empty fields took 33
        // times its size (51 MB -> 1.65 GB). The tables read here (calibration, radiometry,
        // trend, shot lists) hold thousands of fields; beyond kMaxCsvFields it is refused.
        fieldCount += fields.size();
        if (fieldCount > kMaxCsvFields) {
            r.error = source + ":" + std::to_string(recLine) + ": more than " + std::to_string(kMaxCsvFields) +
                      " fields: larger than this reader takes (about " + std::to_string(kMaxCsvFields * 40 / 1000000) +
                      " MB in memory); split the table";
            r.table = CsvTable();
            return r;
        }
        if (fields.size() != r.table.header.size()) {
            r.error = source + ":" + std::to_string(recLine) + ": " + std::to_string(fields.size()) +
                      " fields, but the header has " + std::to_string(r.table.header.size());
            return r;
        }
        r.table.rows.push_back(fields);
        r.table.lines.push_back(recLine);
    }
    if (!haveHeader) {
        r.error = source + ": empty file (no header line)";
        return r;
    }
    r.ok = true;
    return r;
}

CsvReadResult readCsv(const std::string& path) {
    CsvReadResult r;
    std::string text;
    if (!readFileText(path, &text, &r.error)) return r;
    return parseCsv(text, path);
}

std::string csvEscape(std::string_view field) {
    if (field.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(field);
    std::string out = "\"";
    for (char c : field) {
        if (c == '"') out.push_back('"');
        out.push_back(c);
    }
    out.push_back('"');
    return out;
}

}  // namespace lwb::core
