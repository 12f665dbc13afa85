// libFuzzer target: the SLR per-satellite presets file (slr --preset, the SLR workspace). A
// failed read says why; presets that read are written (presetsToJson) and read again to the
// same entries and the same document.
#include "core/slr/presets.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const slr::PresetsResult r = slr::loadPresets(lwb::fuzz::inputFile(lwb::fuzz::asText(data, size), "json"));
    lwb::fuzz::checkReported(r.ok, r.error);
    if (!r.ok) return 0;
    const std::string text = slr::presetsToJson(r.presets).dump();
    const JsonParseResult j = parseJson(text, "fuzz");
    check(j.ok);
    const slr::PresetsResult back = slr::presetsFromJson(j.value, "fuzz");
    check(back.ok);
    check(back.presets.size() == r.presets.size());
    check(slr::presetsToJson(back.presets).dump() == text);
    return 0;
}
