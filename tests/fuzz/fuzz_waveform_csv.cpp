// libFuzzer target: the echo-waveform CSV (calib waveform; time_ns,amplitude or amplitude alone
// or sample,amplitude at 0.5 ns). A failed read says why; a waveform that reads has one finite
// amplitude per sample time and strictly increasing finite times.
#include <cmath>

#include "core/calib/waveform.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::calib;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Waveform w;
    auto read = [](const std::string& path, Waveform* out, std::string* error) {
        return readWaveformCsv(path, 0.5, out, error);
    };
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "csv", read, &w)) return 0;
    check(w.timeNs.size() == w.amplitude.size());
    for (size_t i = 0; i < w.timeNs.size(); ++i) {
        check(std::isfinite(w.timeNs[i]) && std::isfinite(w.amplitude[i]));
        if (i) check(w.timeNs[i] > w.timeNs[i - 1]);
    }
    return 0;
}
