#pragma once
// Image size from the file header, read before decoding, so that a small file announcing a huge
// image (a 0.8 MB PNG of 20000 x 20000 px decodes to gigabytes) is refused up front.
// OpenCV has no public header-only read; the four formats the project reads keep their size in
// fixed places (PNG IHDR, the first TIFF/BigTIFF IFD, the PNM header, a JPEG SOF marker), so a
// few lines here avoid linking libpng, libtiff and libjpeg directly for two integers.
#include <string>
#include <string_view>

namespace lwb::core {

/// Largest image decoded by default (pixels): 2^28 = 16384 x 16384 (radiometry frames and mosaics).
constexpr long long kMaxImagePixels = 1LL << 28;
/// Largest footprint frame decoded by default: 4096 x 4096 = 2^24 pixels. A frame takes about 16
/// bytes per pixel through the footprint pipeline (its 16-bit and float copies and the ROI
/// search): 270 MB at the limit, where a 0.5 MB PNG of 16384 x 16384 took 4.2 GB. GF-7 frames are
/// 550 x 550; --max-pixels raises it.
constexpr long long kMaxFootprintFramePixels = 1LL << 24;

struct ImageHeader {
    bool recognised = false;  ///< a PNG, TIFF, BigTIFF, PNM or JPEG signature
    bool complete = false;    ///< width and height were found
    const char* format = "";  ///< "PNG", "TIFF", "PNM", "JPEG"
    long long width = 0, height = 0;
};

/// Reads the image size from the first bytes of a file (the whole file is fine).
ImageHeader readImageHeader(std::string_view bytes);

/// "" when the image may be decoded; else why not, prefixed with `source`: an unrecognised or
/// truncated header, or width x height above maxPixels (0 = no limit).
std::string imageSizeProblem(std::string_view bytes, const std::string& source, long long maxPixels);

}  // namespace lwb::core
