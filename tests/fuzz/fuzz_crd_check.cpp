// libFuzzer target: the CRD checker (laserwb-cli crd check) from memory.
// Invariants (trap when broken): any text is checked (never an error); the problems are in line
// order, each with a rule and a reason, on a line of the text (0: the file); the error and warning
// counts are the sums of the problems' counts; the sessions lie within the text, in order; the
// same text checked with every repeat listed has at least as many lines and the same counts.
#include <string>

#include "core/slr/crd_check.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::slr;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(lwb::fuzz::asText(data, size));
    const CrdCheckResult r = checkCrdText(text, "fuzz.frd");
    check(r.ok);
    size_t errors = 0, warnings = 0;
    long last = 0;
    for (const CrdProblem& p : r.problems) {
        check(!p.rule.empty() && !p.message.empty() && p.count >= 1);
        check(p.line >= 0 && p.line <= r.lines && p.line >= last);
        last = p.line;
        (p.severity == CrdSeverity::Error ? errors : warnings) += p.count;
    }
    check(errors == r.errors && warnings == r.warnings);
    long prev = 0;
    for (const CrdCheckPass& p : r.passes) {
        check(p.firstLine >= prev && p.firstLine <= p.h4Line && p.lastLine <= r.lines);
        prev = p.h4Line;
    }
    CrdCheckParams all;
    all.maxRepeats = 0;
    const CrdCheckResult every = checkCrdText(text, "fuzz.frd", all);
    check(every.ok && every.errors == r.errors && every.warnings == r.warnings);
    check(every.problems.size() >= r.problems.size());
    return 0;
}
