#include "core/radiometry/geotiff.hpp"

#include <algorithm>
#include <cmath>

#include "core/common/codec_api.hpp"
#include "core/common/output_set.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/image_codecs.hpp"
#include "core/common/text.hpp"
#include "core/radiometry/reflectance.hpp"

// The GDAL side of these functions is in the codec module (core/codecs_module/codecs_module.cpp),
// loaded on first use; here are the checks and the atomic write around it.
namespace lwb::core::radiometry {

GeoReference geoReferenceOf(const MapGrid& g, const std::string& crsWkt) {
    GeoReference geo;
    geo.valid = g.pixelSize > 0 && std::isfinite(g.originX) && std::isfinite(g.originY);
    const double s = g.pixelSize;
    const double t[6] = {g.originX - 0.5 * s, s, 0, g.originY + 0.5 * s, 0, -s};
    std::copy(t, t + 6, geo.transform);
    geo.crsWkt = crsWkt;
    return geo;
}

cv::Point2d pixelCentreToMap(const GeoReference& geo, double col, double row) {
    const double* t = geo.transform;
    const double c = col + 0.5, r = row + 0.5;
    return {t[0] + c * t[1] + r * t[2], t[3] + c * t[4] + r * t[5]};
}

bool crsFromUserInput(const std::string& text, std::string* wkt, std::string* error) {
    const codecs::CodecModule* m = codecs::codecModule(error);
    if (!m) return false;
    std::string gdal;
    if (m->crsToWkt(text, wkt, &gdal)) return true;
    *error = "\"" + printableExcerpt(text) + "\" is not a coordinate reference system GDAL knows (e.g. EPSG:32650)" + gdal;
    return false;
}

bool writeGeoTiff(const std::string& path, const cv::Mat& image, const GeoReference& geo, std::string* error,
                  bool hasNoData, double noData) {
    const codecs::CodecModule* m = codecs::codecModule(error);
    if (!m) return false;
    std::string bytes;
    return m->geoTiffBytes(path, image, geo, hasNoData, noData, &bytes, error) && writeFileAtomic(path, bytes, error);
}

bool isTiffPath(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    const std::string ext = dot == std::string::npos ? std::string() : toLower(path.substr(dot + 1));
    return ext == "tif" || ext == "tiff";
}

bool writeMapImage(const std::string& path, const cv::Mat& image, const GeoReference& geo, bool plain, std::string* error,
                   bool floatNoData) {
    if (geo.valid && !plain && isTiffPath(path)) return writeGeoTiff(path, image, geo, error, floatNoData, NAN);
    return writeImage(path, image, error);
}

bool writeFloatMapImage(const std::string& path, const cv::Mat& image, const GeoReference& geo, bool plain,
                        std::string* error) {
    if (geo.valid && !plain && isTiffPath(path)) return writeGeoTiff(path, image, geo, error, true, NAN);
    return writeFloatTiff(path, image, error);
}

bool readGeoReference(const std::string& path, GeoReference* geo, std::string* error) {
    if (regularFileProblem(path, error)) return false;  // no FIFOs, devices, folders
    noteInputRead(path);
    const codecs::CodecModule* m = codecs::codecModule(error);
    return m && m->readGeoReference(path, geo, error);
}

bool readGeoTiff(const std::string& path, cv::Mat* image, GeoReference* geo, std::string* error, long long maxPixels) {
    if (regularFileProblem(path, error)) return false;
    noteInputRead(path);
    const codecs::CodecModule* m = codecs::codecModule(error);
    return m && m->readGeoTiff(path, image, geo, error, maxPixels);
}

}  // namespace lwb::core::radiometry
