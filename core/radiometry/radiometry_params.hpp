#pragma once
// The radiometry parameters an analyst sets (paper 003): the reflectance fit and its linear
// range, the reflectance image, the relative-error limit of the check regions, the row mosaic
// and the GCP correction, declared once in one schema table (core/common/schema.hpp). The CLI's
// radiometry commands (--config / --print-config / --set / --help-params, and their named
// options as aliases) and the workbench's session read and write them through it.
#include "core/common/schema.hpp"
#include "core/radiometry/gcp.hpp"
#include "core/radiometry/mosaic.hpp"
#include "core/radiometry/reflectance.hpp"

namespace lwb::core::radiometry {

struct RadiometryParams {
    ReflectanceFitParams fit;     ///< linear range, exclusion, V_M, region masking
    bool outOfRangeToNan = false;  ///< reflectance image: pixels outside the range -> NaN
    bool uncertaintyImage = true;  ///< also compute the per-pixel uncertainty
    double limitPct = 5.0;         ///< relative-error limit of the check regions (paper 003: 5 %)
    MosaicParams mosaic;
    GcpFitParams gcp;
    double mapPixelSizeM = 0;      ///< GCP map pixel size (m); 0 = the image's own scale
};

/// Keys "dn_min", "vm_pct", "mosaic.ransac_px", "gcp.model", ...; messages name them
/// "radiometry.dn_min".
const Schema<RadiometryParams>& radiometrySchema();

/// "" when every field and rule holds, else the first problem.
std::string validate(const RadiometryParams& p);

/// The apply step's parameters: the fit's linear range and the image options.
ApplyParams applyParamsOf(const RadiometryParams& p);

}  // namespace lwb::core::radiometry
