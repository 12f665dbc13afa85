// libFuzzer target: CPF (ILRS Consolidated Prediction Format) from memory. A failed read says
// why; on a file that reads, the Lagrange interpolator runs at both ends, the middle and just
// outside the table, and every state it cannot give is explained.
#include "core/slr/cpf.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::slr;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const CpfReadResult r = parseCpf(lwb::fuzz::asText(data, size), "fuzz");
    lwb::fuzz::checkReported(r.ok, r.error);
    if (!r.ok) return 0;
    const CpfInterpolator ip(r.file);
    if (!ip.ok() || ip.size() == 0) return 0;
    const long ref = ip.referenceMjd();
    for (double t : {ip.firstSeconds(), 0.5 * (ip.firstSeconds() + ip.lastSeconds()), ip.lastSeconds(),
                     ip.lastSeconds() + 1.0, ip.firstSeconds() - 1.0}) {
        const CpfState s = ip.atSeconds(ref, t);
        lwb::fuzz::checkReported(s.ok, s.error);
    }
    return 0;
}
