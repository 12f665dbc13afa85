#pragma once
// The interface between laserwb_core and the image codec module (liblaserwb_codecs.so, built from
// codecs_module.cpp). The module holds every call into OpenCV's imgcodecs and into GDAL: those
// two libraries pull in about 120 shared libraries (GDCM, HEIF, HDF5, Poppler, ...) whose
// relocation and start-up code cost every process about 0.1 s before main() (316 million
// instructions measured), although most runs (all SLR and calibration commands) never read an
// image. The core loads the module on first use (core/common/image_codecs.hpp).
//
// One build, one compiler: the functions take and return C++ types. A module of another build
// is refused by the ABI tag.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/geo_reference.hpp"

namespace lwb::core::codecs {

constexpr int kCodecAbi = 1;

struct CodecModule {
    int abi = 0;             ///< kCodecAbi
    size_t size = 0;         ///< sizeof(CodecModule) of the module's build
    // OpenCV imgcodecs, with its own semantics (cv::Exception on failure, empty Mat when unreadable).
    cv::Mat (*decode)(const cv::Mat& buf, int flags) = nullptr;
    bool (*encode)(const std::string& ext, const cv::Mat& image, std::vector<uchar>* buf, const std::vector<int>& params) =
        nullptr;
    cv::Mat (*read)(const std::string& path, int flags) = nullptr;
    // GDAL. Messages are complete ("PATH: what is wrong ..."), as the public functions of
    // core/radiometry/geotiff.hpp give them; the core keeps the file checks and the atomic write.
    bool (*crsToWkt)(const std::string& text, std::string* wkt, std::string* gdalMessage) = nullptr;
    bool (*geoTiffBytes)(const std::string& path, const cv::Mat& image, const GeoReference& geo, bool hasNoData,
                         double noData, std::string* bytes, std::string* error) = nullptr;
    bool (*readGeoReference)(const std::string& path, GeoReference* geo, std::string* error) = nullptr;
    bool (*readGeoTiff)(const std::string& path, cv::Mat* image, GeoReference* geo, std::string* error,
                        long long maxPixels) = nullptr;
};

}  // namespace lwb::core::codecs

/// The module's one exported symbol.
extern "C" const lwb::core::codecs::CodecModule* lwb_codec_module();
