// libFuzzer target: the ground-control-point CSV (radiometry gcp; x,y or col,row and map_x,map_y
// or X,Y / e,n). A failed read says why; GCPs that read are finite and carry their lines.
#include <cmath>

#include "core/radiometry/gcp.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::radiometry;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<Gcp> gcps;
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", readGcpCsv, &gcps)) return 0;
    lwb::fuzz::checkLines(gcps);
    for (const Gcp& g : gcps)
        check(std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.mapX) && std::isfinite(g.mapY));
    return 0;
}
