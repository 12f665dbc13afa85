// libFuzzer target: the radiometry parameters (every radiometry command's --config and --set, the radiometry part of a session) through their schema. What is checked:
// tests/fuzz/fuzz_schema.hpp.
#include "core/radiometry/radiometry_params.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return lwb::fuzz::fuzzSchemaConfig(lwb::core::radiometry::radiometrySchema(), data, size);
}
