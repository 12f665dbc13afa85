#include "core/slr/oc_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include "core/common/atomic_file.hpp"
#include "core/common/parallel.hpp"
#include "core/common/text.hpp"

namespace lwb::core::slr {

namespace {

inline bool isBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimBlanks(std::string_view s) {
    size_t b = 0, e = s.size();
    while (b < e && isBlank(s[b])) ++b;
    while (e > b && isBlank(s[e - 1])) --e;
    return s.substr(b, e - b);
}

std::string fieldExcerpt(std::string_view s, size_t maxLen = 32) { return printableExcerpt(s, maxLen); }

/// Splits one line into fields (handles "quoted, fields" with "" escapes). Returns false on an
/// unterminated quote. Fields are views into the line (quotes stripped; escaped quotes stay doubled,
/// which no number contains anyway).
bool splitLine(std::string_view line, std::vector<std::string_view>* out) {
    out->clear();
    size_t i = 0;
    const size_t n = line.size();
    while (true) {
        size_t b = i;
        while (b < n && isBlank(line[b])) ++b;
        if (b < n && line[b] == '"') {
            size_t j = b + 1;
            while (true) {
                if (j >= n) return false;
                if (line[j] == '"') {
                    if (j + 1 < n && line[j + 1] == '"') {
                        j += 2;
                        continue;
                    }
                    break;
                }
                ++j;
            }
            out->push_back(line.substr(b + 1, j - b - 1));
            size_t k = j + 1;
            while (k < n && line[k] != ',') ++k;  // anything after the closing quote up to the comma is dropped
            if (k >= n) return true;
            i = k + 1;
            continue;
        }
        const void* comma = i < n ? std::memchr(line.data() + i, ',', n - i) : nullptr;
        if (!comma) {
            out->push_back(line.substr(i));
            return true;
        }
        const size_t c = static_cast<size_t>(static_cast<const char*>(comma) - line.data());
        out->push_back(line.substr(i, c - i));
        i = c + 1;
    }
}

/// Strict decimal number (core::parseDouble): no hex, no inf/nan, nothing cut short; finite.
bool parseNumber(std::string_view s, double* out) { return parseDouble(trimBlanks(s), out); }

std::string lower(std::string_view s) { return toLower(trimBlanks(s)); }

void appendNumber(std::string* out, double v) {
    if (!std::isfinite(v)) return;
    char buf[40];  // the shortest round-trip text of a double has at most 24 characters
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    if (r.ec == std::errc()) out->append(buf, static_cast<size_t>(r.ptr - buf));
    else *out += formatDouble(v, 17);  // not reached; never the buffer's old bytes
}

// One stretch of the file's body (whole lines), parsed side by side with the others: first its
// lines and data rows are counted, then its rows are written into the table at their place.
struct RowChunk {
    std::string_view text;
    long lines = 0;      // lines in the stretch
    size_t rows = 0;     // data rows (neither blank nor a comment)
    long errorLine = 0;  // line in the file of the first error; 0: none
    std::string error;   // what was wrong there (without "FILE:LINE: ")
};

struct Columns {
    size_t count = 0;
    size_t epoch = 0, oc = 0;
    std::vector<size_t> extra;
    const std::vector<std::string>* extraNames = nullptr;
};

// Calls line(view) for each line of text (without its '\n' and a final '\r') until it returns
// false; returns the offset just after the last line it was given.
template <class Line>
size_t forEachLine(std::string_view text, Line&& line) {
    size_t pos = 0;
    while (pos < text.size()) {
        const void* nl = std::memchr(text.data() + pos, '\n', text.size() - pos);
        const size_t end = nl ? static_cast<size_t>(static_cast<const char*>(nl) - text.data()) : text.size();
        std::string_view l = text.substr(pos, end - pos);
        pos = std::min(end + 1, text.size());
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        if (!line(l)) break;
    }
    return pos;
}

bool isDataLine(std::string_view line) {
    const std::string_view tl = trimBlanks(line);
    return !tl.empty() && tl[0] != '#';
}

// Counted in locals: the chunks lie side by side in memory, and a count kept in the chunk
// would share a cache line with the next chunk's, counted at the same time on the other core.
void countRows(RowChunk* c) {
    long lines = 0;
    size_t rows = 0;
    forEachLine(c->text, [&](std::string_view line) {
        ++lines;
        rows += isDataLine(line);
        return true;
    });
    c->lines = lines;
    c->rows = rows;
}

// The chunk's rows into t from row `first` (t sized for every row); `lineNo`: the line before
// the chunk's first.
void parseRows(const Columns& cols, size_t first, long lineNo, OcTable& t, RowChunk* c) {
    std::vector<std::string_view> fields;
    fields.reserve(16);
    size_t row = first;
    auto fail = [&](std::string what) {
        c->errorLine = lineNo;
        c->error = std::move(what);
        return false;
    };
    forEachLine(c->text, [&](std::string_view line) {
        ++lineNo;
        if (!isDataLine(line)) return true;
        if (std::memchr(line.data(), '\0', line.size())) return fail("binary data (NUL byte): not a CSV text file");
        if (!splitLine(line, &fields)) return fail("unterminated quoted field");
        if (fields.size() != cols.count)
            return fail(std::to_string(fields.size()) + " fields, the header has " + std::to_string(cols.count));
        double e = 0, o = 0;
        if (!parseNumber(fields[cols.epoch], &e))
            return fail("epoch_s is not a finite number: \"" + fieldExcerpt(fields[cols.epoch]) + "\"");
        if (!parseNumber(fields[cols.oc], &o)) return fail("oc_s is not a finite number: \"" + fieldExcerpt(fields[cols.oc]) + "\"");
        if (!(std::fabs(e) <= kMaxOcEpochS))
            return fail("epoch_s " + fieldExcerpt(fields[cols.epoch]) + " is not a plausible epoch in seconds (|epoch_s| <= 1e10 s)");
        if (!(std::fabs(o) <= kMaxOcS))
            return fail("oc_s " + fieldExcerpt(fields[cols.oc]) +
                        " is not a plausible O-C in seconds of two-way time of flight (|oc_s| <= 3 s)");
        for (size_t k = 0; k < cols.extra.size(); ++k) {
            double v = NAN;
            const std::string_view fv = fields[cols.extra[k]];
            if (!trimBlanks(fv).empty() && !parseNumber(fv, &v))
                return fail((*cols.extraNames)[k] + " is not a finite number: \"" + fieldExcerpt(fv) + "\"");
            t.extra[k][row] = v;
        }
        t.epoch_s[row] = e;
        t.oc_s[row] = o;
        t.line[row] = lineNo;
        ++row;
        return true;
    });
}

// The header line: the columns of epoch_s, oc_s and the extra ones (their names into *names).
// Empty, or what is wrong with it (without "FILE:LINE: ").
std::string readHeader(std::string_view line, const OcCsvParams& params, Columns* cols, std::vector<std::string>* names) {
    if (std::memchr(line.data(), '\0', line.size())) return "binary data (NUL byte): not a CSV text file";
    std::vector<std::string_view> fields;
    if (!splitLine(line, &fields)) return "unterminated quoted field";
    int cEpoch = -1, cOc = -1;
    for (size_t i = 0; i < fields.size(); ++i) {
        const std::string name = lower(fields[i]);
        if (name == "epoch_s") {
            if (cEpoch >= 0) return "column epoch_s appears twice";
            cEpoch = static_cast<int>(i);
        } else if (name == "oc_s") {
            if (cOc >= 0) return "column oc_s appears twice";
            cOc = static_cast<int>(i);
        }
    }
    if (cEpoch < 0 || cOc < 0) return "header must name the columns epoch_s and oc_s (found \"" + fieldExcerpt(line, 60) + "\")";
    // The extra columns asked for (they must be there), then the optional ones (where they are).
    const size_t required = params.extraColumns.size();
    std::vector<std::string> wanted = params.extraColumns;
    wanted.insert(wanted.end(), params.optionalColumns.begin(), params.optionalColumns.end());
    for (size_t w = 0; w < wanted.size(); ++w) {
        int found = -1;
        for (size_t i = 0; i < fields.size(); ++i)
            if (lower(fields[i]) == toLower(wanted[w])) {
                if (found >= 0) return "column " + wanted[w] + " appears twice";
                found = static_cast<int>(i);
            }
        if (found < 0 && w < required) return "header has no column \"" + wanted[w] + "\"";
        if (found < 0) continue;
        cols->extra.push_back(static_cast<size_t>(found));
        names->push_back(wanted[w]);
    }
    cols->count = fields.size();
    cols->epoch = static_cast<size_t>(cEpoch);
    cols->oc = static_cast<size_t>(cOc);
    cols->extraNames = names;
    return {};
}

}  // namespace

std::string validate(const OcCsvParams& p) {
    std::vector<std::string> all = p.extraColumns;
    all.insert(all.end(), p.optionalColumns.begin(), p.optionalColumns.end());
    for (const auto& n : all) {
        const std::string l = lower(n);
        if (l.empty()) return "extra column names must not be empty";
        if (l == "epoch_s" || l == "oc_s") return "epoch_s and oc_s are always read; not an extra column";
    }
    return {};
}

OcCsvReadResult parseOcCsv(std::string_view text, const std::string& source, const OcCsvParams& params) {
    OcCsvReadResult res;
    const std::string src = source.empty() ? "csv" : source;
    auto at = [&](long line) { return src + ":" + std::to_string(line) + ": "; };
    try {
        if (const std::string e = validate(params); !e.empty()) {
            res.error = e;
            return res;
        }
        std::string storage;
        text = plainText(text, &storage);  // (no byte order mark, LF line ends)
        long lineNo = 0;
        OcTable& t = res.table;
        Columns cols;
        // The header: the first line that is neither blank nor a comment; the body follows it.
        std::string headerError;
        const size_t pos = forEachLine(text, [&](std::string_view line) {
            ++lineNo;
            if (!isDataLine(line)) return true;
            headerError = readHeader(line, params, &cols, &t.extraNames);
            return false;
        });
        if (!headerError.empty()) {
            res.error = at(lineNo) + headerError;
            return res;
        }
        if (cols.count == 0) {
            res.error = src + ": empty file (no header line)";
            return res;
        }
        // The rows, in stretches of whole lines parsed side by side on the cores (a 10⁵-row
        // table in about half the time on two); one stretch below 1 MB. Each stretch's rows are
        // counted first and then written in place: no second copy of the table (stretches with
        // tables of their own, joined after, raised the peak of a 10⁶-point pass by half). The
        // first error in file order is reported, with its line in the file.
        const std::string_view body = pos < text.size() ? text.substr(pos) : std::string_view();
        const size_t want = body.size() < (1u << 20) ? 1 : 8;
        std::vector<RowChunk> chunks;
        for (size_t from = 0, k = 1; from < body.size() || chunks.empty(); ++k) {
            size_t to = body.size();
            if (k < want) {
                const size_t at0 = std::max(from, body.size() * k / want);
                const void* nl = at0 < body.size() ? std::memchr(body.data() + at0, '\n', body.size() - at0) : nullptr;
                if (nl) to = static_cast<size_t>(static_cast<const char*>(nl) - body.data()) + 1;
            }
            chunks.emplace_back().text = body.substr(from, to - from);
            from = to;
        }
        parallelFor(chunks.size(), coresFor(0), [&](size_t k) { countRows(&chunks[k]); });
        size_t total = 0;
        for (const RowChunk& c : chunks) total += c.rows;
        t.epoch_s.resize(total);
        t.oc_s.resize(total);
        t.line.resize(total);
        t.extra.assign(cols.extra.size(), std::vector<double>(total));
        std::vector<size_t> firstRow(chunks.size());
        std::vector<long> lineBefore(chunks.size());
        for (size_t k = 1; k < chunks.size(); ++k) {
            firstRow[k] = firstRow[k - 1] + chunks[k - 1].rows;
            lineBefore[k] = lineBefore[k - 1] + chunks[k - 1].lines;
        }
        parallelFor(chunks.size(), coresFor(0),
                    [&](size_t k) { parseRows(cols, firstRow[k], lineNo + lineBefore[k], t, &chunks[k]); });
        for (const RowChunk& c : chunks)
            if (!c.error.empty()) {
                res.error = at(c.errorLine) + c.error;
                return res;
            }
        if (t.epoch_s.empty()) {
            res.error = src + ": no data rows after the header";
            return res;
        }
        for (size_t i = 1; i < t.epoch_s.size(); ++i)
            if (t.epoch_s[i] < t.epoch_s[i - 1]) {
                res.warnings.push_back(at(t.line[i]) + "epochs are not in increasing order");
                break;
            }
        res.ok = true;
    } catch (const std::exception& e) {
        res = OcCsvReadResult();
        res.error = src + ": " + e.what();
    }
    return res;
}

OcCsvReadResult readOcCsv(const std::string& path, const OcCsvParams& params) {
    OcCsvReadResult r;
    std::string text;
    if (!readFileText(path, &text, &r.error)) return r;
    return parseOcCsv(text, path, params);
}

std::string formatOcCsv(const OcTable& table) {
    std::string out = "epoch_s,oc_s";
    for (const auto& n : table.extraNames) out += "," + n;
    out += "\n";
    out.reserve(out.size() + table.epoch_s.size() * (48 + 20 * table.extra.size()));
    for (size_t i = 0; i < table.epoch_s.size(); ++i) {
        appendNumber(&out, table.epoch_s[i]);
        out += ',';
        appendNumber(&out, i < table.oc_s.size() ? table.oc_s[i] : NAN);
        for (const auto& col : table.extra) {
            out += ',';
            appendNumber(&out, i < col.size() ? col[i] : NAN);
        }
        out += '\n';
    }
    return out;
}

bool writeOcCsv(const std::string& path, const OcTable& table, std::string* error) {
    try {
        if (table.oc_s.size() != table.epoch_s.size() || table.extra.size() != table.extraNames.size()) {
            if (error) *error = path + ": inconsistent O-C table (column sizes differ)";
            return false;
        }
        for (const auto& c : table.extra)
            if (c.size() != table.epoch_s.size()) {
                if (error) *error = path + ": inconsistent O-C table (column sizes differ)";
                return false;
            }
        for (const auto& n : table.extraNames)
            if (n.empty() || n.find_first_of(",\"\r\n") != std::string::npos) {
                if (error) *error = path + ": column name \"" + n + "\" is empty or holds a comma, quote or line break";
                return false;
            }
        return writeFileAtomic(path, formatOcCsv(table), error);
    } catch (const std::exception& e) {
        if (error) *error = path + ": " + e.what();
        return false;
    }
}

OcTable ocTableFrom(const OcResult& oc) {
    OcTable t;
    t.epoch_s = oc.epoch_s;
    t.oc_s = oc.oc_s;
    t.line.assign(oc.epoch_s.size(), 0);
    t.extraNames = {"elevation_deg", "filter_flag", "line"};
    t.extra.resize(3);
    for (size_t i = 0; i < oc.epoch_s.size(); ++i) {
        t.extra[0].push_back(i < oc.elevation_rad.size() ? oc.elevation_rad[i] * 180.0 / M_PI : NAN);
        t.extra[1].push_back(i < oc.filter_flag.size() ? oc.filter_flag[i] : NAN);
        t.extra[2].push_back(i < oc.line.size() ? static_cast<double>(oc.line[i]) : NAN);
    }
    return t;
}

}  // namespace lwb::core::slr
