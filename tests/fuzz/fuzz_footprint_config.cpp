// libFuzzer target: footprint parameters from JSON (footprint --config, eval footprint
// --config, the GUI's parameter presets and the footprint part of a session). A failed read
// says why; parameters that read are written (footprintParamsToJson) and read again to the
// same document.
#include "core/footprint/pipeline.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const JsonParseResult j = parseJson(std::string(lwb::fuzz::asText(data, size)), "fuzz");
    lwb::fuzz::checkReported(j.ok, j.error);
    if (!j.ok) return 0;
    footprint::FootprintParams p;
    std::string err;
    lwb::fuzz::checkReported(footprintParamsFromJson(j.value, &p, &err), err);
    if (!err.empty()) return 0;
    const std::string text = footprintParamsToJson(p).dump();
    const JsonParseResult back = parseJson(text, "fuzz");
    check(back.ok);
    footprint::FootprintParams q;
    check(footprintParamsFromJson(back.value, &q, &err));
    check(footprintParamsToJson(q).dump() == text);
    return 0;
}
