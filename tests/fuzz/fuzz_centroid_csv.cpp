// libFuzzer target: the per-shot centroid CSV of the long-term trend (trend; time,beam,x,y
// [,camera], time as ISO date/date-time, YYYY-MM or Unix seconds). A failed read says why;
// records that read have finite x, y, a month "YYYY-MM" and their source lines.
#include <cctype>
#include <cmath>

#include "core/footprint/trend.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::footprint;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<CentroidRecord> recs;
    auto read = [](const std::string& path, std::vector<CentroidRecord>* out, std::string* error) {
        return readCentroidCsv(path, out, error);
    };
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", read, &recs)) return 0;
    lwb::fuzz::checkLines(recs);
    for (const CentroidRecord& r : recs) {
        check(std::isfinite(r.x) && std::isfinite(r.y));
        check(r.month.size() >= 7 && r.month[r.month.size() - 3] == '-');
    }
    return 0;
}
