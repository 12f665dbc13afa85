// libFuzzer target: the reflectance fit CSV (radiometry apply --fit; k, b and optional
// statistics, one row). A failed read says why; a fit that reads has finite k and b, and
// written (writeFitCsv) and read again it gives k and b to 12 significant digits.
#include <cmath>

#include "core/radiometry/reflectance.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::radiometry;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    ReflectanceFit fit;
    const auto bytes = lwb::fuzz::asText(data, size);
    if (!lwb::fuzz::readThroughFile(bytes, "csv", readFitCsv, &fit)) return 0;
    check(std::isfinite(fit.k) && std::isfinite(fit.b));
    std::string err;
    const std::string& path = lwb::fuzz::inputFile("", "csv");
    check(writeFitCsv(path, fit, &err));
    ReflectanceFit back;
    check(readFitCsv(path, &back, &err));
    check(std::fabs(back.k - fit.k) <= 1e-11 * std::fabs(fit.k));
    check(std::fabs(back.b - fit.b) <= 1e-11 * std::fabs(fit.b));
    return 0;
}
