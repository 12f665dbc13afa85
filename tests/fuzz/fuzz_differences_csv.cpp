// libFuzzer target: the elevation-difference CSV (calib stats; d or laser,control), read
// without a group column and grouped by "beam" (calib stats --group beam). A failed read says
// why; differences that read are finite.
#include <cmath>

#include "core/calib/validation_stats.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::calib;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    for (const char* group : {"", "beam"}) {
        std::vector<DifferenceGroup> groups;
        auto read = [group](const std::string& path, std::vector<DifferenceGroup>* out, std::string* error) {
            return readDifferencesCsv(path, group, out, error);
        };
        if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", read, &groups)) continue;
        for (const DifferenceGroup& g : groups)
            for (double d : g.d) check(std::isfinite(d));
    }
    return 0;
}
