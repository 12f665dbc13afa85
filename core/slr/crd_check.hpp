#pragma once
// A checker of CRD files (ILRS Consolidated laser Ranging Data format, v1.01 and v2.01; the
// drafts before v1.00 that call themselves "version 0" too): every record against the format, as
// the ILRS checker (crd_chk) and the Operation Center's checks do, every problem with its line,
// its rule and its reason. `laserwb-cli crd check` prints them; the workbench lists them for an
// opened file. docs/crd-check.md lists the rules with the specification's figures.
//
// What is checked, per record and per file:
//  - structure: H1 H2 H3 before each H4 (or in force from an earlier pass), H4 .. H8 per
//    session, configuration and data records inside a session, H9 at the end, nothing after it;
//    known record types (H1-H5, H8, H9, C0-C7, 00, 10-12, 20, 21, 30, 40-42, 50, 60, 9x); no
//    blank lines, ASCII text; records of v2 only (H5, C5-C7, 41, 42) in a v1 file;
//  - each record's field count for its version, each field's type (integer, number, text), "na"
//    where the specification allows it (v2; -1 in v1), codes and flags in their ranges, physical
//    values that are implausible (a warning);
//  - the H1 format and version, the H2 station time scale, the H3 ids and target class, the H4
//    data type, dates, times and flags; v1 header records in their fixed columns;
//  - the data against the H4: 10 records in a full-rate or sampled session and 11 records in a
//    normal-point session (and at least one), epochs within the H4 start and end, in time order
//    within a session (a day rollover allowed), seconds of day 0..86400 (86400..86401 only on a
//    day that ends with a leap second), epoch events against the H4 range type;
//  - configuration: every system configuration id a 10/11/12/40/41/42/50/60 record uses defined
//    by a C0 of its session, C0 ids unique, the component ids a C0 names defined by C1..C7;
//  - what the workbench's reader (crd.hpp) says of the file: a record or pass it cannot use.
//
// Errors break the specification (the ILRS would reject the file, or a reader may misread it);
// warnings are doubtful values or practices (a temperature of 28 K, extra fields, a missing line
// end). A problem repeated on many records of a session is listed maxRepeats times and then
// counted in one line. Never throws.
#include <string>
#include <string_view>
#include <vector>

#include "core/common/feedback.hpp"

namespace lwb::core::slr {

enum class CrdSeverity { Error, Warning };

/// "error" or "warning".
const char* severityName(CrdSeverity s);

struct CrdProblem {
    long line = 0;            ///< 1-based line of the record; 0 for the file as a whole
    std::string record;       ///< the record id as written ("H4", "10", "c0"); "" for the file or a blank line
    CrdSeverity severity = CrdSeverity::Error;
    std::string rule;         ///< the rule broken: "field-count", "order", "range", ... (docs/crd-check.md)
    std::string message;      ///< why, with the values and the specification's figures
    size_t count = 1;         ///< 1, or how many like problems this line stands for ("N more ...")
    long lastLine = 0;        ///< for a line that stands for several records: the last of them (else 0)
};

/// One session (H4 .. H8 block) as the checker saw it.
struct CrdCheckPass {
    size_t ordinal = 0;       ///< 1-based, in file order
    long firstLine = 0;       ///< its first header record (H1/H2/H3 before the H4, else the H4)
    long h4Line = 0;
    long lastLine = 0;        ///< its H8, or the line before what closed it
    bool endedWithH8 = false;
    int version = 1;          ///< CRD version in force (0 drafts, 1, 2)
    int dataType = -1;        ///< H4 data type (0 full rate, 1 normal point, 2 sampled), -1 unreadable
    std::string station, target;  ///< H2 station name, H3 target name in force
    std::string start;        ///< H4 start "YYYY-MM-DD hh:mm:ss" (UTC), "" when unreadable
    size_t records = 0;       ///< configuration and data records of the session
    size_t ranges = 0;        ///< type 10
    size_t normalPoints = 0;  ///< type 11
    size_t errors = 0, warnings = 0;  ///< problems on its lines (counts of summarised lines included)
};

struct CrdCheckParams {
    /// Per session (and between sessions), the problems of one rule on one record type and field
    /// listed one by one; further ones are counted in one closing line. 0: list every one.
    size_t maxRepeats = 10;
    /// Also what the workbench's reader says (crd.hpp: records it skips, passes it cannot use),
    /// where the checker itself has said nothing about that line.
    bool readerMessages = true;
};

struct CrdCheckResult {
    bool ok = false;          ///< the input was read and checked (its problems, if any, are listed)
    std::string error;        ///< when not: "FILE: why" (no such file, a folder, unreadable)
    std::string path;         ///< as given
    int version = -1;         ///< CRD version of the first H1 (-1: none readable)
    long lines = 0;
    std::vector<CrdProblem> problems;  ///< in line order
    size_t errors = 0, warnings = 0;   ///< every problem found (summarised ones included)
    std::vector<CrdCheckPass> passes;
    bool clean() const { return ok && errors == 0 && warnings == 0; }
};

/// "" or what is wrong with the parameters.
std::string validate(const CrdCheckParams& p);

/// Checks a CRD file: a regular file, a gzip-compressed one, or "-" (standard input). Reads it
/// line by line (the memory of one session's configuration ids, not of the file). `feedback`
/// gives progress and may cancel (then ok is false, error "cancelled").
CrdCheckResult checkCrd(const std::string& path, const CrdCheckParams& params = {}, const Feedback* feedback = nullptr);

/// Checks CRD text; `source` names it in messages and decides the file-name rule (its extension).
CrdCheckResult checkCrdText(std::string_view text, const std::string& source, const CrdCheckParams& params = {});

/// "SOURCE:LINE: error RULE: MESSAGE" ("SOURCE: ..." for the file as a whole).
std::string formatCrdProblem(const std::string& source, const CrdProblem& p);

/// One line for a checked file: "SOURCE: clean (...)" or "SOURCE: 2 errors, 3 warnings (...)",
/// with its sessions, records and CRD version; or "SOURCE: not checked: why".
std::string crdCheckSummary(const CrdCheckResult& r, const std::string& source);

}  // namespace lwb::core::slr
