// libFuzzer target: radiometry images of any depth (core::radiometry::readImageAnyDepth: PNG,
// TIFF incl. float, PGM, JPEG; colour turned grey) used by radiometry mosaic / gcp / fit /
// apply, with the reader's decoded-size limit at kMaxPixels (fuzz_opencv.hpp). A failed read
// says why; an image that reads is non-empty and single-channel.
#include <opencv2/core.hpp>

#include "core/radiometry/reflectance.hpp"
#include "tests/fuzz/fuzz_opencv.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::radiometry;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    cv::Mat image;
    auto read = [](const std::string& path, cv::Mat* out, std::string* error) {
        return readImageAnyDepth(path, out, error, lwb::fuzz::kMaxPixels);
    };
    if (!lwb::fuzz::readThroughFile(lwb::fuzz::asText(data, size), "tif", read, &image)) return 0;
    check(!image.empty() && image.channels() == 1);
    return 0;
}
