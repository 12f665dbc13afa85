// libFuzzer target: the O-C CSV (epoch_s, oc_s, optional extra columns) from memory, read
// plain and asking for the extra column elevation_deg. A failed read says why; a table that
// reads is written (formatOcCsv) and read back to the same doubles.
#include "core/slr/oc_csv.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::slr;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    OcCsvParams withExtra;
    withExtra.extraColumns = {"elevation_deg"};
    for (const OcCsvParams& params : {OcCsvParams(), withExtra}) {
        const OcCsvReadResult r = parseOcCsv(lwb::fuzz::asText(data, size), "fuzz", params);
        lwb::fuzz::checkReported(r.ok, r.error);
        if (!r.ok) continue;
        check(r.table.epoch_s.size() == r.table.oc_s.size());
        const OcCsvReadResult back = parseOcCsv(formatOcCsv(r.table), "fuzz", params);
        check(back.ok);
        check(back.table.epoch_s == r.table.epoch_s);
        check(back.table.oc_s == r.table.oc_s);
    }
    return 0;
}
