// libFuzzer target: the detector-array CSV of the ground calibration (calib detector; e,n or
// lat,lon, energy, h, triggered, saturated). A failed read says why; detectors that read have
// finite positions and their source lines.
#include <cmath>

#include "core/calib/detector_array.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::calib;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    DetectorArray a;
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", readDetectorCsv, &a)) return 0;
    lwb::fuzz::checkLines(a.detectors);
    for (const Detector& d : a.detectors) check(std::isfinite(d.e) && std::isfinite(d.n));
    return 0;
}
