// libFuzzer target: the calib parameters (every calib command's --config and --set, the calibration part of a session) through their schema. What is checked:
// tests/fuzz/fuzz_schema.hpp.
#include "core/calib/calib_params.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return lwb::fuzz::fuzzSchemaConfig(lwb::core::calib::calibSchema(), data, size);
}
