// libFuzzer target: SLR screening and post-fit parameters through slrSchema() (slr --config and
// --set; the presets file's entries go through the same schema, fuzz_slr_presets). What is
// checked: tests/fuzz/fuzz_schema.hpp.
#include "core/slr/slr_params.hpp"
#include "tests/fuzz/fuzz_schema.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return lwb::fuzz::fuzzSchemaConfig(lwb::core::slr::slrSchema(), data, size);
}
