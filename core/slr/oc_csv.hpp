#pragma once
// Plain O-C tables as CSV: a header line naming the columns, then one row per point.
// Required columns epoch_s (s) and oc_s (s, two-way); any order; other columns are ignored
// unless asked for by name. Blank lines and lines starting with '#' are skipped; CRLF and a
// UTF-8 BOM are accepted; fields may be double-quoted. Numbers are strict: the whole field
// must be a decimal number; NaN, inf and anything else stop the read with "FILE:LINE: ...".
// Implausible values stop it too: |epoch_s| beyond kMaxOcEpochS, |oc_s| beyond kMaxOcS.
// A hand-written parser (no per-field strings): 10^6 rows read in about 0.1 s.
#include <string>
#include <string_view>
#include <vector>

#include "core/slr/oc.hpp"

namespace lwb::core::slr {

/// Largest |epoch_s| read (s): 317 years from whatever origin (Unix, GPS and MJD seconds all fit);
/// beyond it a double no longer resolves the 2 us that SLR epochs need.
constexpr double kMaxOcEpochS = 1e10;
/// Largest |oc_s| read (s, two-way): more than the two-way time of flight to the Moon (2.6 s). A
/// larger value is not an O-C in seconds (nanoseconds or metres by mistake, or a damaged field).
constexpr double kMaxOcS = 3.0;

struct OcTable {
    std::vector<double> epoch_s;                ///< s (seconds since 0h UTC of the pass day, or any origin the writer chose)
    std::vector<double> oc_s;                   ///< observed - computed two-way time of flight (s)
    std::vector<long> line;                     ///< source line of each row (reader), 0 otherwise
    std::vector<std::string> extraNames;        ///< names of the extra numeric columns
    std::vector<std::vector<double>> extra;     ///< extra[k][row], one vector per name
};

struct OcCsvParams {
    std::vector<std::string> extraColumns;      ///< further numeric columns to read (case-insensitive; must exist;
                                                ///< an empty field there reads as NaN)
    std::vector<std::string> optionalColumns;   ///< read as extraColumns when the header has them (after them
                                                ///< in OcTable::extra), else left out
};

/// Empty when valid: extra column names must be non-empty and differ from epoch_s / oc_s.
std::string validate(const OcCsvParams& p);

struct OcCsvReadResult {
    bool ok = false;
    std::string error;                          ///< "FILE:LINE: what is wrong"
    std::vector<std::string> warnings;
    OcTable table;
};

/// Parses an O-C CSV held in memory; `source` names it in messages. Never throws.
OcCsvReadResult parseOcCsv(std::string_view text, const std::string& source, const OcCsvParams& params = {});
/// Reads and parses an O-C CSV file.
OcCsvReadResult readOcCsv(const std::string& path, const OcCsvParams& params = {});

/// CSV text: "epoch_s,oc_s[,extra...]" and one row per point, shortest round-trip numbers
/// (reading it back gives the same doubles). Non-finite values are written as empty fields.
std::string formatOcCsv(const OcTable& table);
/// Writes formatOcCsv(table) atomically. False with *error (also for inconsistent column sizes).
bool writeOcCsv(const std::string& path, const OcTable& table, std::string* error);

/// The table of an O-C result: epoch_s, oc_s and the extra columns elevation_deg, filter_flag, line.
OcTable ocTableFrom(const OcResult& oc);

}  // namespace lwb::core::slr
