#pragma once
// GeoTIFF output and input through GDAL: the GCP-corrected mosaic and the reflectance image
// carry their place on the ground (the markers' map coordinates, metres), so that GIS tools
// (QGIS, ENVI) open them at the right position and scale; a georeferenced input keeps its
// georeferencing through the processing.
//
// Conventions: GDAL's geotransform maps the *corner* of a pixel, X = t0 + col·t1 + row·t2,
// Y = t3 + col·t4 + row·t5 with (col, row) = (0, 0) the top-left corner of the top-left pixel;
// the project's map grid (gcp.hpp) names the *centre* of pixel (0, 0): the two differ by half
// a pixel, converted here and nowhere else.
#include <opencv2/core.hpp>
#include <string>

#include "core/common/geo_reference.hpp"
#include "core/common/image_header.hpp"
#include "core/radiometry/gcp.hpp"

namespace lwb::core::radiometry {

using core::GeoReference;  // (core/common/geo_reference.hpp)

/// The georeferencing of a north-up map grid: pixel size s, centre of pixel (0, 0) at (X0, Y0)
/// → transform (X0 − s/2, s, 0, Y0 + s/2, 0, −s). crsWkt: from crsFromUserInput, or "" for the
/// markers' own local frame (metres, written as a local engineering CRS).
GeoReference geoReferenceOf(const MapGrid& grid, const std::string& crsWkt = {});

/// Map position of the centre of pixel (col, row) under a georeference.
cv::Point2d pixelCentreToMap(const GeoReference& geo, double col, double row);

/// "EPSG:32650", a PROJ string or WKT → WKT. False with *error naming the text when GDAL does not
/// know it.
bool crsFromUserInput(const std::string& text, std::string* wkt, std::string* error);

/// Writes a single-channel 8U, 16U or 32F image as a (Geo)TIFF through GDAL, atomically (a
/// temporary beside the target, renamed). With geo.valid the geotransform and the CRS (a local
/// metre CRS when geo.crsWkt is empty) are written; without, a plain TIFF. noData (when finite, or
/// NaN for a float image with hasNoData) is recorded as the band's no-data value.
bool writeGeoTiff(const std::string& path, const cv::Mat& image, const GeoReference& geo, std::string* error,
                  bool hasNoData = false, double noData = 0);

/// True when the path ends in .tif or .tiff (any case).
bool isTiffPath(const std::string& path);

/// An image output of the map steps (radiometry gcp): a GeoTIFF through GDAL when geo.valid, the
/// path is a .tif and plain TIFF was not asked for (floatNoData: NaN recorded as no data); else
/// the plain writer (PNG, TIFF, PGM by extension: writeImage).
bool writeMapImage(const std::string& path, const cv::Mat& image, const GeoReference& geo, bool plain, std::string* error,
                   bool floatNoData = false);

/// A float image output of radiometry apply (reflectance, its uncertainty): a GeoTIFF with NaN as
/// no data under the same condition, else a plain 32-bit float TIFF (writeFloatTiff).
bool writeFloatMapImage(const std::string& path, const cv::Mat& image, const GeoReference& geo, bool plain,
                        std::string* error);

/// Reads the georeferencing of an image file through GDAL (header only, no pixels). A file
/// without one (PNG, plain TIFF) gives geo->valid = false and true. False with *error only
/// when the file cannot be opened as a raster.
bool readGeoReference(const std::string& path, GeoReference* geo, std::string* error);

/// Reads a GeoTIFF's first band as an image (8U, 16U, 32F or 64F kept; other types converted to
/// 32F) with its georeference. Images over maxPixels are refused before the pixels are read.
bool readGeoTiff(const std::string& path, cv::Mat* image, GeoReference* geo, std::string* error,
                 long long maxPixels = kMaxImagePixels);

}  // namespace lwb::core::radiometry
