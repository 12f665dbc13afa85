// libFuzzer target: the trend parameters (trend --config and --set) through their schema. What is checked:
// tests/fuzz/fuzz_schema.hpp.
#include "core/footprint/trend.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return lwb::fuzz::fuzzSchemaConfig(lwb::core::footprint::trendSchema(), data, size);
}
