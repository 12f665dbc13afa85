// libFuzzer target: the control-point CSV of the pointing calibration (calib pointing; ECEF or
// lat/lon/h ground points, satellite position, attitude quaternion, range, sigmas). A failed
// read says why; points that read have finite ground and satellite positions and their lines.
#include "core/calib/pointing.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::calib;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<ControlPoint> points;
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", readControlPointCsv, &points)) return 0;
    lwb::fuzz::checkLines(points);
    for (const ControlPoint& c : points) check(c.groundEcef.allFinite() && c.shot.satEcef.allFinite());
    return 0;
}
