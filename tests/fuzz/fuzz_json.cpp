// libFuzzer target: the JSON parser (core::parseJson) behind --config, the SLR presets and the
// beams file. A failed parse says why; a document that parses is written (dump, one line and
// indented) and parsed again to the same text.
#include "core/common/json.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const JsonParseResult r = parseJson(std::string(lwb::fuzz::asText(data, size)), "fuzz");
    lwb::fuzz::checkReported(r.ok, r.error);
    if (!r.ok) return 0;
    for (int indent : {-1, 2}) {
        const std::string text = r.value.dump(indent);
        const JsonParseResult back = parseJson(text, "fuzz");
        check(back.ok);
        check(back.value.dump(indent) == text);
    }
    return 0;
}
