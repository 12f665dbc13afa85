// libFuzzer target: CRD (ILRS Consolidated Ranging Data, v1 and v2) from memory.
// Invariants (trap when broken): a failed read says why; a file that reads is written back
// (formatCrd) and read again with the same passes, records (same text) and data counts, and
// writing that gives the same bytes; setFilterFlags (what slr --crd-out writes) sets every
// flag. Parsing only otherwise: the O-C against a prediction is fuzz_slr_oc.
#include <string>
#include <vector>

#include "core/slr/crd.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::slr;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const CrdReadResult r = parseCrd(lwb::fuzz::asText(data, size), "fuzz");
    lwb::fuzz::checkReported(r.ok, r.error);
    if (!r.ok) return 0;
    const std::string written = formatCrd(r.file);
    const CrdReadResult again = parseCrd(written, "fuzz");
    check(again.ok);
    check(again.file.passes.size() == r.file.passes.size());
    for (size_t k = 0; k < r.file.passes.size(); ++k) {
        const CrdPass &a = r.file.passes[k], &b = again.file.passes[k];
        const std::vector<CrdRecord> ra = allRecords(a), rb = allRecords(b);
        check(ra.size() == rb.size());
        for (size_t i = 0; i < ra.size(); ++i) check(ra[i].text == rb[i].text);
        check(a.ranges.size() == b.ranges.size());
        check(a.normalPoints.size() == b.normalPoints.size());
    }
    check(formatCrd(again.file) == written);
    for (CrdPass p : r.file.passes) {
        std::string err;
        check(setFilterFlags(&p, std::vector<int>(p.ranges.size(), 2), &err));
        for (const auto& x : p.ranges) check(x.filterFlag == 2);
    }
    return 0;
}
