// libFuzzer target: the calibration-region CSV (radiometry fit / check; name, reflectance or
// measured, and dn and/or simulated and/or x,y,w,h). A failed read says why; regions that read
// carry their lines, a finite reflectance and, when they have one, a rectangle with x, y >= 0
// and w, h >= 1.
#include <cmath>

#include "core/radiometry/reflectance.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::radiometry;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<Region> regions;
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", readRegionCsv, &regions)) return 0;
    lwb::fuzz::checkLines(regions);
    for (const Region& r : regions) {
        check(std::isfinite(r.reflectance));
        if (!r.rect.empty()) check(r.rect.x >= 0 && r.rect.y >= 0 && r.rect.width > 0 && r.rect.height > 0);
    }
    return 0;
}
