// libFuzzer target: SLR screening and post-fit parameters through slrSchema() (slr --config and
// --set; the presets file's entries go through the same schema, fuzz_slr_presets). What is
// checked: tests/fuzz/fuzz_schema.hpp.
#include "core/slr/slr_params.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

using namespace lwb::core;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const Schema<slr::SlrParams>& schema = slr::slrSchema();
    lwb::fuzz::fuzzParams(schema, lwb::fuzz::asText(data, size),
                          [&schema](const JsonParseResult& j, slr::SlrParams* p, std::string* err) {
                              return schema.fromJson(j.value, p, err, &j);
                          });
    return 0;
}
