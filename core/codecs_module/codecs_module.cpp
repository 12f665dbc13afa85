// liblaserwb_codecs.so: every call of laserwb into OpenCV's imgcodecs and into GDAL, loaded by
// the core on first use (codec_api.hpp says why). GeoTIFF through GDAL: conventions in
// core/radiometry/geotiff.hpp.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <mutex>
#include <ogr_srs_api.h>
#include <opencv2/imgcodecs.hpp>

#include "core/common/codec_api.hpp"

namespace lwb::core::codecs {
namespace {
using core::GeoReference;

// GDAL is initialised once; its messages go to the caller's error text, not to stderr, and it
// writes no .aux.xml side files (an output is exactly one file, renamed into place).
void initGdal() {
    static std::once_flag once;
    std::call_once(once, [] {
        GDALAllRegister();
        CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");
    });
}

// Collects GDAL's last error for this thread while in scope (quiet handler).
class GdalErrors {
public:
    GdalErrors() {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLErrorReset();
    }
    ~GdalErrors() { CPLPopErrorHandler(); }
    std::string last() const {
        const char* m = CPLGetLastErrorMsg();
        return m && *m ? std::string(": ") + m : std::string();
    }
};

std::string localMetreCrs() {
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRSetLocalCS(srs, "laserwb marker frame (metres)");
    OSRSetLinearUnits(srs, SRS_UL_METER, 1.0);
    char* wkt = nullptr;
    std::string out;
    if (OSRExportToWkt(srs, &wkt) == OGRERR_NONE && wkt) out = wkt;
    CPLFree(wkt);
    OSRDestroySpatialReference(srs);
    return out;
}

std::atomic<unsigned> g_memCounter{0};

cv::Mat decode(const cv::Mat& buf, int flags) { return cv::imdecode(buf, flags); }

bool encode(const std::string& ext, const cv::Mat& image, std::vector<uchar>* buf, const std::vector<int>& params) {
    return cv::imencode(ext, image, *buf, params);
}

cv::Mat read(const std::string& path, int flags) { return cv::imread(path, flags); }

bool crsToWkt(const std::string& text, std::string* wkt, std::string* gdalMessage) {
    initGdal();
    GdalErrors ge;
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    bool ok = OSRSetFromUserInput(srs, text.c_str()) == OGRERR_NONE;
    char* w = nullptr;
    ok = ok && OSRExportToWkt(srs, &w) == OGRERR_NONE && w;
    if (ok) *wkt = w;
    else *gdalMessage = ge.last();
    CPLFree(w);
    OSRDestroySpatialReference(srs);
    return ok;
}

bool geoTiffBytes(const std::string& path, const cv::Mat& image, const GeoReference& geo, bool hasNoData, double noData,
                  std::string* out, std::string* error) {
    initGdal();
    if (image.empty() || image.channels() != 1) {
        *error = path + ": a GeoTIFF is written from a non-empty single-channel image";
        return false;
    }
    GDALDataType type = GDT_Unknown;
    switch (image.depth()) {
        case CV_8U: type = GDT_Byte; break;
        case CV_16U: type = GDT_UInt16; break;
        case CV_32F: type = GDT_Float32; break;
        default:
            *error = path + ": GeoTIFF output takes 8-bit, 16-bit or 32-bit float images";
            return false;
    }
    GdalErrors ge;
    GDALDriverH drv = GDALGetDriverByName("GTiff");
    if (!drv) {
        *error = path + ": GDAL has no GTiff driver";
        return false;
    }
    // Written in memory; the core renames it into place (writeFileAtomic): never a half file on disk.
    const std::string mem = "/vsimem/laserwb_geotiff_" + std::to_string(g_memCounter++) + ".tif";
    const char* options[] = {"COMPRESS=DEFLATE", "TILED=NO", nullptr};
    GDALDatasetH ds = GDALCreate(drv, mem.c_str(), image.cols, image.rows, 1, type, const_cast<char**>(options));
    if (!ds) {
        *error = path + ": GDAL cannot create the GeoTIFF" + ge.last();
        return false;
    }
    bool ok = true;
    if (geo.valid) {
        double t[6];
        std::copy(geo.transform, geo.transform + 6, t);
        const std::string wkt = geo.crsWkt.empty() ? localMetreCrs() : geo.crsWkt;
        ok = GDALSetGeoTransform(ds, t) == CE_None && (wkt.empty() || GDALSetProjection(ds, wkt.c_str()) == CE_None);
    }
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    if (ok && hasNoData) ok = GDALSetRasterNoDataValue(band, noData) == CE_None;
    const cv::Mat src = image.isContinuous() ? image : image.clone();
    if (ok)
        ok = GDALRasterIO(band, GF_Write, 0, 0, src.cols, src.rows, const_cast<uchar*>(src.data), src.cols, src.rows, type, 0,
                          0) == CE_None;
    std::string why = ge.last();
    CPLErrorReset();
    GDALClose(ds);  // flushes the file: a failure here shows as a GDAL error
    if (CPLGetLastErrorType() >= CE_Failure) {
        ok = false;
        if (why.empty()) why = ge.last();
    }
    vsi_l_offset size = 0;
    GByte* bytes = ok ? VSIGetMemFileBuffer(mem.c_str(), &size, FALSE) : nullptr;
    if (ok && bytes) out->assign(reinterpret_cast<const char*>(bytes), size);
    else *error = path + ": GDAL could not write the GeoTIFF" + (why.empty() ? ge.last() : why);
    VSIUnlink(mem.c_str());
    return ok && bytes;
}

// Opens a raster read-only.
GDALDatasetH openRaster(const std::string& path, std::string* error) {
    initGdal();  // (the core has checked that path is a regular file)
    GdalErrors ge;
    GDALDatasetH ds = GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
    if (!ds) *error = path + ": not a raster GDAL can read" + ge.last();
    return ds;
}

void fillGeo(GDALDatasetH ds, GeoReference* geo) {
    *geo = GeoReference{};
    double t[6];
    if (GDALGetGeoTransform(ds, t) == CE_None) {
        // GDAL reports (0, 1, 0, 0, 0, 1) for files without one: that is "none".
        const bool identity = t[0] == 0 && t[1] == 1 && t[2] == 0 && t[3] == 0 && t[4] == 0 && t[5] == 1;
        geo->valid = !identity && std::isfinite(t[1]) && std::isfinite(t[5]) && (t[1] * t[5] - t[2] * t[4]) != 0;
        std::copy(t, t + 6, geo->transform);
    }
    const char* wkt = GDALGetProjectionRef(ds);
    if (wkt) geo->crsWkt = wkt;
}

bool readGeoReference(const std::string& path, GeoReference* geo, std::string* error) {
    GDALDatasetH ds = openRaster(path, error);
    if (!ds) return false;
    fillGeo(ds, geo);
    GDALClose(ds);
    return true;
}

bool readGeoTiff(const std::string& path, cv::Mat* image, GeoReference* geo, std::string* error, long long maxPixels) {
    GDALDatasetH ds = openRaster(path, error);
    if (!ds) return false;
    GdalErrors ge;
    const int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
    bool ok = GDALGetRasterCount(ds) >= 1 && w > 0 && h > 0;
    if (!ok) *error = path + ": no raster band";
    if (ok && maxPixels > 0 && static_cast<long long>(w) * h > maxPixels) {
        *error = path + ": " + std::to_string(w) + "x" + std::to_string(h) + " pixels exceed the limit of " +
                 std::to_string(maxPixels);
        ok = false;
    }
    if (ok) {
        GDALRasterBandH band = GDALGetRasterBand(ds, 1);
        const GDALDataType t = GDALGetRasterDataType(band);
        int cvType = CV_32F;
        GDALDataType readAs = GDT_Float32;
        if (t == GDT_Byte) cvType = CV_8U, readAs = GDT_Byte;
        else if (t == GDT_UInt16) cvType = CV_16U, readAs = GDT_UInt16;
        else if (t == GDT_Float64) cvType = CV_64F, readAs = GDT_Float64;
        try {
            image->create(h, w, cvType);
        } catch (const cv::Exception& e) {
            *error = path + ": cannot allocate the image: " + e.what();
            ok = false;
        }
        if (ok && GDALRasterIO(band, GF_Read, 0, 0, w, h, image->data, w, h, readAs, 0, 0) != CE_None) {
            *error = path + ": cannot read the pixels" + ge.last();
            ok = false;
        }
        if (ok) fillGeo(ds, geo);
    }
    GDALClose(ds);
    return ok;
}
}  // namespace
}  // namespace lwb::core::codecs

extern "C" __attribute__((visibility("default"))) const lwb::core::codecs::CodecModule* lwb_codec_module() {
    using namespace lwb::core::codecs;
    static const CodecModule m = [] {
        CodecModule c;
        c.abi = kCodecAbi;
        c.size = sizeof(CodecModule);
        c.decode = decode;
        c.encode = encode;
        c.read = read;
        c.crsToWkt = crsToWkt;
        c.geoTiffBytes = geoTiffBytes;
        c.readGeoReference = readGeoReference;
        c.readGeoTiff = readGeoTiff;
        return c;
    }();
    return &m;
}
