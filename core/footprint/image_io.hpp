#pragma once
// Footprint frame input: 16-bit PNG / TIFF / PGM through OpenCV, and raw little-endian
// 16-bit with the size given. 14-bit data (0..16383) is taken as it is, never rescaled.
#include <opencv2/core.hpp>

#include "core/common/image_header.hpp"
#include <string>
#include <vector>

namespace lwb::core::footprint {

struct ImageReadParams {
    int rawWidth = 0;       ///< width of .raw/.bin frames (px); required for them
    int rawHeight = 0;      ///< height of .raw/.bin frames (px)
    bool rawBigEndian = false;  ///< raw byte order (GF-7 products are little-endian)
    long long maxPixels = kMaxFootprintFramePixels;  ///< larger images are refused before decoding (0 = no limit)
};

struct ImageReadResult {
    bool ok = false;
    std::string error;     ///< "FILE: what is wrong"
    cv::Mat image;         ///< CV_32FC1, DN
    int storedBits = 0;    ///< 16 for 16-bit files, 32 for float TIFF
    double maxValue = 0;   ///< largest pixel value
};

/// Reads one frame or ROI. Rejects missing files, 8-bit and multi-channel images,
/// NaN/inf pixels, wrong raw sizes and blank (all-zero) frames with a clear message.
ImageReadResult readFrame(const std::string& path, const ImageReadParams& params = {});

/// True for the file endings readFrame understands (png tif tiff pgm raw bin), any case.
bool isFrameFile(const std::string& path);

/// Expands files and folders (non-recursive for folders, sorted by name) into frame files.
/// Folders contribute only frame files; a named file is kept whatever its ending.
/// Missing paths are reported in *error (first one) and make the call return false, except,
/// with `keepMissing`, a missing path named as a frame (isFrameFile): it is kept, for its reading
/// to fail and the run to report it (--keep-going: a rejected row).
bool expandInputs(const std::vector<std::string>& inputs, std::vector<std::string>* files,
                  std::string* error, bool keepMissing = false);

/// Writes a CV_16UC1 image as 16-bit PNG/TIFF/PGM (by ending) or raw little-endian (.raw),
/// atomically. False with *error on failure.
bool writeFrame16(const std::string& path, const cv::Mat& image16, std::string* error);

}  // namespace lwb::core::footprint
