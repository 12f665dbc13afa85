// libFuzzer target: footprint shot lists (core/footprint/shot_list: the workbench's and
// `laserwb-cli footprint`'s one reader; file[,time,beam,camera,center_x,center_y]). A failed read
// says why; shots that read have a file, a time the trend can read (or none), a finite centre
// when they have one, and their source lines.
#include <cmath>

#include "core/footprint/shot_list.hpp"
#include "core/footprint/trend.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::footprint;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto read = [](const std::string& path, std::vector<ShotSpec>* out, std::string* error) {
        ShotListResult r = readShotList(path);
        *error = r.error;
        *out = std::move(r.shots);
        return r.ok;
    };
    std::vector<ShotSpec> shots;
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", read, &shots)) return 0;
    lwb::fuzz::checkLines(shots);
    for (const ShotSpec& s : shots) {
        check(!s.file.empty());
        std::string month;
        check(s.time.empty() || monthOf(s.time, &month));
        check(!s.hasCenter || (std::isfinite(s.centerX) && std::isfinite(s.centerY)));
    }
    return 0;
}
