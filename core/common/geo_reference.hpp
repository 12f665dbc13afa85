#pragma once
// A raster's place on the ground, as GDAL gives it: what the image codecs (core/common/
// image_codecs.hpp, the codec module) and the radiometry's GeoTIFF writers share, so that the
// codec interface needs nothing of core/radiometry.
#include <string>

namespace lwb::core {

struct GeoReference {
    bool valid = false;            ///< false: the image has no georeferencing
    double transform[6] = {0, 1, 0, 0, 0, 1};  ///< GDAL geotransform (corner convention, map units)
    std::string crsWkt;            ///< coordinate reference system as WKT ("" = none recorded)
};

}  // namespace lwb::core
