// libFuzzer target: footprint parameters through footprintSchema() (footprint --config and
// --set, eval footprint --config, the GUI's parameter presets and the footprint part of a
// session); a config is read by footprintParamsFromJson (a named preset first), as the CLI
// does. What is checked: tests/fuzz/fuzz_schema.hpp.
#include "core/footprint/pipeline.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

using namespace lwb::core;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    lwb::fuzz::fuzzParams(footprint::footprintSchema(), lwb::fuzz::asText(data, size),
                          [](const JsonParseResult& j, footprint::FootprintParams* p, std::string* err) {
                              return footprint::footprintParamsFromJson(j.value, p, err, &j);
                          });
    return 0;
}
