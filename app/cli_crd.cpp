// laserwb-cli crd check: every record of CRD files checked against the format (core/slr/crd_check),
// every problem as FILE:LINE with its rule and reason, as the ILRS checker (crd_chk) lists them.
#include <iostream>
#include <string>

#include "cli_commands.hpp"
#include "cli_common.hpp"
#include "core/slr/crd_check.hpp"

namespace lwb::cli {

namespace slr = core::slr;

namespace {

const char* kCrdCheckUsage =
    "usage: laserwb-cli crd check [options] FILE...\n"
    "Checks CRD files (ILRS Consolidated laser Ranging Data, v1.01 and v2.01; the drafts of \"version 0\"\n"
    "too) record by record against the format, as the ILRS checker does, and lists every problem:\n"
    "  FILE:LINE: error|warning RULE: reason\n"
    "then one line per file: FILE: clean, or FILE: N errors, M warnings (sessions, records, lines, version).\n"
    "Checked: the order of the records (H1 H2 H3 H4 ... H8 per session, H9 at the end, configuration and\n"
    "data records inside a session), the field count of each record for its version, each field's type,\n"
    "\"na\" where the format allows it, codes and flags in their ranges (filter flag, epoch event, H4 data\n"
    "type and indicators, ...), implausible values (a warning), v1 headers in their fixed columns, the\n"
    "data against the H4 (10 records in a full-rate session, 11 in a normal-point one; epochs within its\n"
    "start and end), epochs in time order within a session (a day rollover allowed), leap seconds, the\n"
    "system configuration ids of the data defined by a C0 of the session, and what the workbench's reader\n"
    "says of the file. Errors break the format (the ILRS would reject the file, a reader may misread it);\n"
    "warnings are doubtful values or practices. docs/crd-check.md lists every rule.\n"
    "FILE: a CRD file (gzip-compressed too), or - for standard input.\n"
    "  --warnings-ok         warnings are listed but do not fail the check (exit 0 when no file has an error)\n"
    "  --max-repeats N       per session, list N problems of one rule on one record type and field, count\n"
    "                        the others in one line (default 10; 0 lists every one)\n"
    "  --no-reader           leave out what the workbench's reader says (the format's rules only)\n"
    "  -q, --quiet           print nothing: the exit code says (unreadable files still on stderr)\n"
    "Exit codes: 0 every file clean (with --warnings-ok: no errors), 1 a file could not be read (no\n"
    "such file, a folder, unreadable; the others are still checked), 2 usage error, 3 problems found.\n";

int cmdCrdCheck(int argc, char** argv) {
    const std::string cmd = "crd check";
    Args a(cmd, kCrdCheckUsage);
    a.option("--warnings-ok", false);
    a.option("--max-repeats", true);
    a.option("--no-reader", false);
    if (int rc = a.parseWithHelp(argc, argv, 3); rc >= 0) return rc;
    if (a.positional().empty()) return fail(cmd, "no input file", kUsage);
    slr::CrdCheckParams params;
    long long repeats = static_cast<long long>(params.maxRepeats);
    std::string err;
    if (!a.getInt("--max-repeats", 0, 100000000, &repeats, &err)) return fail(cmd, err, kUsage);
    params.maxRepeats = static_cast<size_t>(repeats);
    params.readerMessages = !a.has("--no-reader");
    const bool quiet = a.quiet(), warningsOk = a.has("--warnings-ok");
    size_t stdinCount = 0;
    for (const std::string& f : a.positional()) stdinCount += f == "-";
    if (stdinCount > 1) return fail(cmd, "standard input (-) given more than once", kUsage);

    bool unreadable = false, problems = false;
    for (const std::string& path : a.positional()) {
        const slr::CrdCheckResult r = slr::checkCrd(path, params);
        if (!r.ok) {
            unreadable = true;
            std::cerr << "laserwb-cli crd check: " << r.error << "\n";
            continue;
        }
        if (r.errors > 0 || (r.warnings > 0 && !warningsOk)) problems = true;
        if (quiet) continue;
        for (const slr::CrdProblem& p : r.problems) std::cout << slr::formatCrdProblem(path, p) << "\n";
        std::cout << slr::crdCheckSummary(r, path) << "\n";
    }
    std::cout.flush();
    return unreadable ? kFailed : problems ? kDoubtful : kOk;
}

}  // namespace

int cmdCrd(int argc, char** argv) {
    const std::string sub = argc > 2 ? argv[2] : "";
    if (sub == "check") return cmdCrdCheck(argc, argv);
    if (sub == "--help" || sub == "-h") {
        std::cout << kCrdCheckUsage;  // (one kind of crd command so far)
        return kOk;
    }
    return fail("crd", (sub.empty() ? "which one? (" : "unknown kind \"" + sub + "\" (") + std::string("check)"), kUsage);
}

}  // namespace lwb::cli
