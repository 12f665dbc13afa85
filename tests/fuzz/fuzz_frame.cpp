// libFuzzer target: footprint frames (core::footprint::readFrame): 16-bit PNG, TIFF (16-bit and
// 32-bit float), PGM, and raw 16-bit. The input's first bytes pick the file ending: a PNG, TIFF
// or PGM signature keeps its kind (OpenCV decodes by content); anything else is a raw frame
// whose first byte gives the width (3 + byte % 64), second byte's low bit the byte order, and
// the rest the pixels (height = what fits). A failed read says why; a frame that reads is a
// single-channel float image of at least 3x3 px with finite pixels >= 0 and a positive maximum
// equal to maxValue.
#include <cmath>
#include <cstring>
#include <opencv2/core.hpp>

#include "core/footprint/image_io.hpp"
#include "tests/fuzz/fuzz_opencv.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::footprint;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes = lwb::fuzz::asText(data, size);
    auto starts = [&](const char* magic, size_t n) { return size >= n && std::memcmp(data, magic, n) == 0; };
    ImageReadParams params;
    params.maxPixels = lwb::fuzz::kMaxPixels;
    std::string path;
    if (starts("\x89PNG", 4)) path = lwb::fuzz::inputFile(bytes, "png");
    else if (starts("II*\0", 4) || starts("MM\0*", 4)) path = lwb::fuzz::inputFile(bytes, "tif");
    else if (starts("P5", 2) || starts("P2", 2)) path = lwb::fuzz::inputFile(bytes, "pgm");
    else {
        if (size < 2) return 0;
        params.rawWidth = 3 + data[0] % 64;
        params.rawBigEndian = data[1] & 1;
        params.rawHeight = std::max<int>(1, int((size - 2) / (2 * size_t(params.rawWidth))));
        path = lwb::fuzz::inputFile(bytes.substr(2), "raw");
    }
    const ImageReadResult r = readFrame(path, params);
    lwb::fuzz::checkReported(r.ok, r.error);
    if (!r.ok) return 0;
    check(r.image.type() == CV_32FC1 && r.image.cols >= 3 && r.image.rows >= 3);
    check(r.storedBits == 16 || r.storedBits == 32);
    check(cv::checkRange(r.image, true));
    double mn = 0, mx = 0;
    cv::minMaxLoc(r.image, &mn, &mx);
    check(mn >= 0 && mx > 0 && mx == r.maxValue);
    return 0;
}
