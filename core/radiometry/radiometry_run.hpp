#pragma once
// The radiometry run layer (paper 003), like SLR's pass_input / pass_run: a DN image, the
// regions picked on it and the parameters -> measure -> fit -> apply -> check in one call, and
// the regions' result table beside it. The workbench's controller runs it on every change; the
// CLI's radiometry commands call the same step functions (measureRegionDn, fitReflectance,
// applyReflectance, relativeErrors) and the same writers.
#include <string>
#include <vector>

#include "core/common/task.hpp"
#include "core/radiometry/radiometry_params.hpp"

namespace lwb::core::radiometry {

/// A region as the analyst defined it: a rectangle on the image (or a mean DN given without
/// one), its role and the spectrometer's reflectance.
struct RegionPick {
    std::string name;
    bool check = false;       ///< a check region (relative error), else a fit region
    cv::Rect rect;            ///< image pixels; empty when dn is given
    double reflectance = NAN; ///< % ; NaN = not entered yet
    double dn = NAN;          ///< mean DN given without a rectangle
};

struct RadiometryRunResult {
    std::vector<Region> measured;      ///< per region, same order: mean DN, sigma, pixels
    std::vector<int> fitIndex;         ///< region index of each fit input
    ReflectanceFitResult fit;          ///< regions in fitIndex order
    std::string error;                 ///< why there is no fit (or no image)
    ApplyResult apply;                 ///< reflectance (and uncertainty) image
    std::vector<int> checkIndex;       ///< region index of each check row
    RelativeErrorResult check;
    std::string checkError;
    std::vector<std::string> notes;    ///< per region: why it is not in the fit, or doubts
};

/// The radiometry task (core/common/task.hpp): measures every rectangle inside the image, fits
/// V_REF = K V_DN + B over the fit regions that have a reflectance and a DN, converts the image
/// (when there is one) and takes the relative errors of the check regions (on the reflectance
/// image, or K DN + B for regions given by their DN alone). Regions that cannot take part get a
/// note, never an error of the run. The workbench's radiometry workspace runs it live
/// (TaskJob<RadiometryTask>); the CLI's radiometry commands run its steps one at a time.
struct RadiometryTask {
    static constexpr const char* kName = "radiometry";
    using Params = RadiometryParams;
    static const Schema<RadiometryParams>& schema() { return radiometrySchema(); }
    struct Inputs {
        cv::Mat dn;                      ///< the mosaic's DN image (empty: regions given by DN only)
        std::vector<RegionPick> regions;
    };
    using Reuse = NoReuse;
    using Outputs = RadiometryRunResult;
    static RadiometryRunResult run(const Inputs& in, const RadiometryParams& p, const NoReuse&, Feedback* fb);
};

/// The regions with their results (re-readable as a regions file): name, role, reflectance,
/// x, y, w, h, dn, dn_sd, pixels, predicted, residual, used, note.
std::string regionResultsCsv(const std::vector<RegionPick>& regions, const RadiometryRunResult& r);

}  // namespace lwb::core::radiometry
