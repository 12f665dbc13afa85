#pragma once
// OpenCV settings shared by the image targets, applied once from LLVMFuzzerInitialize (defined
// here: include this header in the target's one source file):
// - no worker threads (one input at a time; faster and quieter under ASan);
// - no log lines (imread reports every undecodable input);
// - kMaxPixels (2^20) as the readers' own decoded-size limit (checked from the header, before
//   decoding: a few header bytes can declare a 65535x65535 image), and the same cap through
//   OpenCV's OPENCV_IO_MAX_IMAGE_PIXELS (unless already set) as a backstop for a header our check
//   does not parse, so that such an input is refused instead of ending the run as an
//   out-of-memory.
#include <cstdlib>
#include <string>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>

namespace lwb::fuzz {

constexpr long long kMaxPixels = 1 << 20;

inline void quietOpenCv() {
    ::setenv("OPENCV_IO_MAX_IMAGE_PIXELS", std::to_string(kMaxPixels).c_str(), 0);
    cv::setNumThreads(0);
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
}

}  // namespace lwb::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    lwb::fuzz::quietOpenCv();
    return 0;
}
