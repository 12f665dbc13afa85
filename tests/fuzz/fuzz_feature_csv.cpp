// libFuzzer target: the feature-candidate CSV (calib waveform --features; id, h, optional
// position). A failed read says why; candidates that read have a finite height and their lines.
#include <cmath>

#include "core/calib/waveform.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::calib;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<FeatureCandidate> c;
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", readFeatureCsv, &c)) return 0;
    lwb::fuzz::checkLines(c);
    for (const FeatureCandidate& f : c) check(std::isfinite(f.heightM));
    return 0;
}
