// libFuzzer target: SINEX station coordinates from memory. A failed read says why; on a file
// that reads, the station lookup runs for the first 20 solutions and by CDP pad id.
#include "core/slr/sinex.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::slr;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const SinexReadResult r = parseSinex(lwb::fuzz::asText(data, size), "fuzz");
    lwb::fuzz::checkReported(r.ok, r.error);
    if (!r.ok) return 0;
    size_t n = 0;
    for (const auto& s : r.file.solutions) {
        if (++n > 20) break;
        const StationPositionResult p = stationPosition(r.file, s.code, 56000, 0.0);
        lwb::fuzz::checkReported(p.ok, p.error);
    }
    const StationPositionResult p = stationPositionByPad(r.file, 7941, 56000, 0.0);
    lwb::fuzz::checkReported(p.ok, p.error);
    return 0;
}
