#pragma once
// OpenCV settings shared by the image targets, applied once from LLVMFuzzerInitialize (defined
// here: include this header in the target's one source file):
// - no worker threads (one input at a time; faster and quieter under ASan);
// - no log lines (imread reports every undecodable input);
// - a decoded-size cap of 2^20 pixels through OpenCV's own OPENCV_IO_MAX_IMAGE_PIXELS (unless
//   already set), so that a few header bytes declaring a huge image are refused before the
//   pixel buffer is allocated instead of ending the run as an out-of-memory. This stands in for
//   the readers' own decoded-size limit while there is none; it is not part of what is tested.
#include <cstdlib>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>

namespace lwb::fuzz {

inline void quietOpenCv() {
    ::setenv("OPENCV_IO_MAX_IMAGE_PIXELS", "1048576", 0);
    cv::setNumThreads(0);
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
}

}  // namespace lwb::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    lwb::fuzz::quietOpenCv();
    return 0;
}
