// libFuzzer target: the parameters of calib (every calib command's --config and --set, the calibration part of a session) through their schema. What is checked:
// tests/fuzz/fuzz_schema.hpp.
#include "core/calib/calib_params.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

using namespace lwb::core;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const Schema<calib::CalibParams>& schema = calib::calibSchema();
    lwb::fuzz::fuzzParams(schema, lwb::fuzz::asText(data, size),
                          [&schema](const JsonParseResult& j, calib::CalibParams* p, std::string* err) {
                              return schema.fromJson(j.value, p, err, &j);
                          });
    return 0;
}
