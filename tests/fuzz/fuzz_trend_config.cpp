// libFuzzer target: the parameters of trend (trend --config and --set) through their schema. What is checked:
// tests/fuzz/fuzz_schema.hpp.
#include "core/footprint/trend.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

using namespace lwb::core;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const Schema<footprint::TrendParams>& schema = footprint::trendSchema();
    lwb::fuzz::fuzzParams(schema, lwb::fuzz::asText(data, size),
                          [&schema](const JsonParseResult& j, footprint::TrendParams* p, std::string* err) {
                              return schema.fromJson(j.value, p, err, &j);
                          });
    return 0;
}
