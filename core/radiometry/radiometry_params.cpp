#include "core/radiometry/radiometry_params.hpp"

namespace lwb::core::radiometry {

const Schema<RadiometryParams>& radiometrySchema() {
    static const Schema<RadiometryParams> schema = [] {
        using R = RadiometryParams;
        Schema<R> s("radiometry");
        const double big = 1e300;
        // ---- reflectance fit and image (radiometry fit | apply | check) -------------------------
        s.real("dn_min", LWB_FIELD(R, fit.dnMin), "DN", {-big, big}, {0, 1000}, "camera linear range, lower end (paper 003: 100)");
        s.real("dn_max", LWB_FIELD(R, fit.dnMax), "DN", {-big, big}, {1000, 65535},
               "camera linear range, upper end (paper 003: 60000)");
        s.boolean("exclude_out_of_range", LWB_FIELD(R, fit.excludeOutOfRange),
                  "leave regions whose mean DN is outside the linear range out of the fit (else: warn)");
        s.real("vm_pct", LWB_FIELD(R, fit.spectrometerPct), "%", {0, 100, false, true}, {0, 2},
               "spectrometer uncertainty V_M (paper 003: 0.17)");
        s.boolean("mask_out_of_range_pixels", LWB_FIELD(R, fit.maskOutOfRangePixels),
                  "measured regions: pixels outside the linear range are masked from the mean (false: only counted)");
        s.integer("min_region_pixels", LWB_FIELD(R, fit.minRegionPixels), "px", {1, 1000000000}, {1, 400},
                  "pixels a measured region keeps after masking, else it is left out of the fit");
        s.real("min_region_fraction", LWB_FIELD(R, fit.minRegionFraction), "", {0, 1}, {0, 1},
               "and this fraction of its pixels");
        s.boolean("nan_out_of_range", LWB_FIELD(R, outOfRangeToNan), "reflectance image: pixels outside the range become NaN");
        s.boolean("uncertainty_image", LWB_FIELD(R, uncertaintyImage), "also compute the per-pixel uncertainty image");
        s.real("limit_pct", LWB_FIELD(R, limitPct), "%", {0, 1000, true, false}, {1, 20},
               "relative-error limit of the check regions (paper 003: 5)");
        // ---- row mosaic (radiometry mosaic) -------------------------------------------------------
        s.choice("mosaic.features", LWB_FIELD(R, mosaic.features), {"orb", "akaze"},
                 "keypoints: akaze (sub-pixel) or orb (faster, about 0.5 px)");
        s.integer("mosaic.max_features", LWB_FIELD(R, mosaic.maxFeatures), "", {100, 100000}, {500, 20000},
                  "ORB keypoints per frame");
        s.real("mosaic.ratio_test", LWB_FIELD(R, mosaic.ratioTest), "", {0, 1, true, true}, {0.5, 0.9},
               "Lowe's ratio for the two nearest descriptors");
        s.choice("mosaic.model", LWB_FIELD(R, mosaic.model), {"translation", "similarity", "affine", "homography"},
                 "transform between neighbouring frames");
        s.real("mosaic.ransac_px", LWB_FIELD(R, mosaic.ransacThresholdPx), "px", {0, 1000, true, false}, {0.5, 10},
               "RANSAC inlier distance");
        s.integer("mosaic.min_inliers", LWB_FIELD(R, mosaic.minInliers), "", {4, 100000}, {4, 100},
                  "fewer consistent matches for a pair is an error");
        s.real("mosaic.max_rotation_deg", LWB_FIELD(R, mosaic.maxRotationDeg), "deg", {0, 180}, {0, 30},
               "warn above this rotation between neighbours");
        s.real("mosaic.max_scale_change", LWB_FIELD(R, mosaic.maxScaleChange), "", {0, 10, false, true}, {0, 0.5},
               "warn above this relative scale change between neighbours");
        s.choice("mosaic.blend", LWB_FIELD(R, mosaic.blend), {"feather", "average", "first"},
                 "overlaps: feathered weights, plain mean, or the earliest frame");
        s.real("mosaic.max_canvas_pixels", LWB_FIELD(R, mosaic.maxCanvasPixels), "px", {1, 4e9}, {1e6, 4e9},
               "larger mosaics are refused (memory)")
            .uiLog = true;
        // ---- geometric correction (radiometry gcp) ------------------------------------------------
        s.choice("gcp.model", LWB_FIELD(R, gcp.model), {"affine", "homography"}, "image -> map transform");
        s.real("gcp.collinear_tolerance", LWB_FIELD(R, gcp.collinearTolerance), "", {0, 0.5}, {1e-5, 0.1},
               "GCPs count as collinear below this spread across / along their best line")
            .uiLog = true;
        s.real("gcp.outlier_p", LWB_FIELD(R, gcp.outlierProbability), "", {0, 0.5, false, false}, {1e-6, 0.05},
               "chance that a sound GCP is named an outlier: one the transform of the others misses by more than "
               "this allows (and 0.5 px) is named, and the map doubtful")
            .uiLog = true;
        // Files written before gcp.outlier_p held gcp.outlier_factor (times the RMS), which has no
        // counterpart: dropped (the default applies).
        s.legacy([](Json& j) {
            if (j.contains("gcp") && j["gcp"].is_object()) j["gcp"].erase("outlier_factor");
        });
        s.real("gcp.pixel_size_m", LWB_FIELD(R, mapPixelSizeM), "m", {0, 1e9, true, true}, {0.001, 1},
               "map pixel size; 0 = the image's own scale")
            .specials = {{0, "auto"}};
        return s;
    }();
    return schema;
}

std::string validate(const RadiometryParams& p) {
    // The fields' ranges, then the rules between fields (dn_min < dn_max): these are checked
    // here, once every setting is applied, so the order of --set options does not matter.
    if (std::string e = radiometrySchema().validate(p); !e.empty()) return e;
    if (std::string e = validate(p.fit); !e.empty()) return "reflectance fit: " + e;
    if (std::string e = validate(p.mosaic); !e.empty()) return "mosaic: " + e;
    if (std::string e = validate(p.gcp); !e.empty()) return "gcp: " + e;
    return {};
}

ApplyParams applyParamsOf(const RadiometryParams& p) {
    ApplyParams ap;
    ap.dnMin = p.fit.dnMin;
    ap.dnMax = p.fit.dnMax;
    ap.outOfRangeToNan = p.outOfRangeToNan;
    ap.uncertaintyImage = p.uncertaintyImage;
    return ap;
}

}  // namespace lwb::core::radiometry
