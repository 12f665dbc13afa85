// libFuzzer target: the parameters of radiometry (every radiometry command's --config and --set, the radiometry part of a session) through their schema. What is checked:
// tests/fuzz/fuzz_schema.hpp.
#include "core/radiometry/radiometry_params.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

using namespace lwb::core;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const Schema<radiometry::RadiometryParams>& schema = radiometry::radiometrySchema();
    lwb::fuzz::fuzzParams(schema, lwb::fuzz::asText(data, size),
                          [&schema](const JsonParseResult& j, radiometry::RadiometryParams* p, std::string* err) {
                              return schema.fromJson(j.value, p, err, &j);
                          });
    return 0;
}
