#pragma once
// Image decoding and encoding for the core: OpenCV's imdecode / imencode / imread, called through
// the codec module (liblaserwb_codecs.so, core/common/codec_api.hpp says why), which is
// loaded the first time an image is read or written. Same semantics as OpenCV's functions; when
// the module cannot be loaded they throw cv::Exception naming the reason, which every caller
// already reports as "cannot decode/encode ...".
//
// The module is looked for in $LWB_CODECS (a file), beside the running executable, and at the
// path where this build put it.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace lwb::core {

cv::Mat imageDecode(const cv::Mat& buf, int flags);
bool imageEncode(const std::string& ext, const cv::Mat& image, std::vector<uchar>& buf, const std::vector<int>& params = {});
cv::Mat imageRead(const std::string& path, int flags);

namespace codecs {
struct CodecModule;
/// The loaded module, or null with *why saying what was tried (first call loads it; thread-safe).
const CodecModule* codecModule(std::string* why = nullptr);
}  // namespace codecs

}  // namespace lwb::core
