// laserwb-cli radiometry mosaic | gcp | fit | apply | check (paper 003).
#include <cmath>
#include <iostream>

#include "cli_commands.hpp"
#include "cli_batch.hpp"
#include "cli_common.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"
#include "core/radiometry/gcp.hpp"
#include "core/radiometry/geotiff.hpp"
#include "core/radiometry/mosaic.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "core/radiometry/reflectance.hpp"
#include "core/sim/demo_data.hpp"
#include "core/common/rng.hpp"

namespace lwb::cli {

using namespace core::radiometry;

namespace {

std::string fx(double v, int d) { return std::isfinite(v) ? core::formatFixed(v, d) : std::string(); }
std::string outPath(const Args& a) { return a.has("-o") ? a.value("-o") : a.value("--output"); }
bool quiet(const Args& a) { return a.has("-q") || a.has("--quiet"); }
void warn(const std::string& cmd, const std::vector<std::string>& ws, const Args& a, bool doubtful = false) {
    warnings(cmd, ws, quiet(a), doubtful);
}
// --max-pixels: the largest image decoded (its header is read first).
bool maxPixels(const Args& a, long long* out, std::string* err) {
    *out = core::kMaxImagePixels;
    return a.getInt("--max-pixels", 1, 1LL << 40, out, err);
}

const char* kMosaicUsage =
    "usage: laserwb-cli radiometry mosaic FRAME... -o ROW.tif [options]\n"
    "Stitches the frames of one row, given in scan order (paper 003 3.1): keypoints matched between\n"
    "neighbours, RANSAC transform, chained to the first frame, blended.\n"
    "FRAME: single-channel PNG/TIFF/PGM of one depth (colour is converted to grey).\n"
    "  --features akaze|orb     keypoints (default {default:mosaic.features}; akaze: sub-pixel; orb: faster, ~0.5 px)\n"
    "  --model translation|similarity|affine|homography   (default {default:mosaic.model})\n"
    "  --blend feather|average|first   (default {default:mosaic.blend})\n"
    "  --ransac-px T            RANSAC inlier distance (default {default:mosaic.ransac_px})\n"
    "  --min-inliers N          fewer consistent matches for a pair is an error (default {default:mosaic.min_inliers})\n"
    "  -o, --output ROW.tif     the row image (same depth as the frames; .tif or .png)\n"
    "  --coverage MASK.png      255 where a frame contributed\n"
    "  --pairs PAIRS.csv        per pair: keypoints, matches, inliers, RMS, shift, rotation, scale\n"
    "  --max-pixels N           largest image read, from its header (default 268435456 = 16384^2)\n";

const char* kGcpUsage =
    "usage: laserwb-cli radiometry gcp IMAGE --gcps GCPS.csv -o MAP.tif [options]\n"
    "Geometric correction by ground control points (paper 003 3.1, image to map): fits image -> map,\n"
    "reports every GCP's residual and resamples the image onto a north-up map grid.\n"
    "GCPS.csv: id, x, y (image px), map_x, map_y (map m, Y up).\n"
    "  --model affine|homography   (default {default:gcp.model})\n"
    "  --pixel-size M          map pixel size in metres (default: the image's own scale)\n"
    "  --residuals RES.csv     per GCP: map and pixel residuals, and whether it is an outlier: one the\n"
    "                          transform of the others misses by more than a sound GCP would but\n"
    "                          once in 1000 (gcp.outlier_p) and by 0.5 px\n"
    "                          (then exit 3: the map is written but doubtful)\n"
    "  --valid MASK.png        255 where the map pixel came from inside the image\n"
    "  -o MAP.tif is a GeoTIFF (through GDAL): geotransform in the markers' map metres, so GIS tools\n"
    "  open it in place; MAP.png, or --plain-tiff, writes a plain image without georeferencing.\n"
    "  --crs CRS               the CRS of the markers' map coordinates (e.g. EPSG:32650); default a\n"
    "                          local engineering frame in metres\n"
    "  --plain-tiff            write MAP.tif (and --valid) as plain TIFF\n"
    "  --max-pixels N           largest image read, from its header (default 268435456 = 16384^2)\n";

const char* kFitUsage =
    "usage: laserwb-cli radiometry fit REGIONS.csv [--image DN.tif] -o FIT.csv [options]\n"
    "Synchronous radiometric calibration (paper 003 eq. 5-6): V_REF = K * V_DN + B by least squares\n"
    "over marked regions, with the standard errors of K and B and the uncertainty\n"
    "sqrt(V_M^2 + V_err^2).\n"
    "REGIONS.csv: name, reflectance (%), and dn or a rectangle x, y, w, h on --image.\n"
    "  --image DN.tif          measure each region's mean DN on this image\n"
    "  --dn-min D, --dn-max D  camera linear range (default {default:dn_min}, {default:dn_max}). Regions measured on --image:\n"
    "                          pixels outside the range are masked from the region's mean and counted;\n"
    "                          a region left with too few pixels is left out of the fit, with the reason.\n"
    "                          Regions given as dn: a mean outside the range is warned about\n"
    "  --min-region-pixels N   pixels a region keeps after masking (default {default:min_region_pixels})\n"
    "  --min-region-fraction F and this fraction of its pixels (default {default:min_region_fraction})\n"
    "  --no-pixel-mask         average every pixel of a region, out-of-range ones included (only counted)\n"
    "  --exclude-out-of-range  leave regions whose mean DN is outside the range out of the fit\n"
    "  --vm PCT                spectrometer uncertainty V_M (default {default:vm_pct} %)\n"
    "  -o, --output FIT.csv    k, b, k_sd, b_sd, cov_kb, n, residual_sd, r2, mean_dn, vm_pct,\n"
    "                          paper_uncertainty_pct, uncertainty_at_mean_pct\n"
    "  --regions OUT.csv       per region: dn, reflectance, predicted, residual, used, pixels,\n"
    "                          pixels_masked, note\n"
    "  --max-pixels N           largest image read, from its header (default 268435456 = 16384^2)\n";

const char* kApplyUsage =
    "usage: laserwb-cli radiometry apply DN_IMAGE (--fit FIT.csv | --k K --b B) -o REFLECTANCE.tif [options]\n"
    "Converts a DN image to reflectance (%) with V_REF = K * V_DN + B; writes a 32-bit float TIFF.\n"
    "  --dn-min D, --dn-max D  camera linear range (default {default:dn_min}, {default:dn_max}): pixels outside are counted\n"
    "  --nan-out-of-range      and set to NaN\n"
    "  --uncertainty UNC.tif   per-pixel uncertainty sqrt(V_M^2 + prediction variance) (needs --fit)\n"
    "  A georeferenced DN_IMAGE (GeoTIFF) gives georeferenced outputs (same geotransform and CRS);\n"
    "  --plain-tiff            write plain TIFF outputs even then\n"
    "  --check CHECK.csv       check regions (name, reflectance, x, y, w, h) -> relative errors\n"
    "  --table TABLE.csv       the relative-error table (with --check)\n"
    "  --limit PCT             relative-error limit (default {default:limit_pct} %); a check region above it: exit 3\n"
    "                          (the outputs are written)\n"
    "  --max-pixels N           largest image read, from its header (default 268435456 = 16384^2)\n";

const char* kCheckUsage =
    "usage: laserwb-cli radiometry check CHECK.csv [--image REFLECTANCE.tif] [-o TABLE.csv] [--limit PCT]\n"
    "Relative error of simulated (image) against measured reflectance per check region (paper 003\n"
    "tables 5-7): |simulated - measured| / measured * 100.\n"
    "CHECK.csv: name, measured (or reflectance), and simulated or a rectangle x, y, w, h on --image.\n"
    "Exit code 3 when a region exceeds the limit (default 5 %); the table is still written.\n"
    "  --max-pixels N           largest image read, from its header (default 268435456 = 16384^2)\n";

// The radiometry parameters: one schema (core/radiometry/radiometry_params.hpp) for every
// radiometry command, so a workbench session's parameter block is a config file of any of them.
// Today's named options are aliases of --set (flags are applied after the config).
std::string withParams(const char* usage) {
    return std::string(usage) + ParamOptions<RadiometryParams>::paramsHelp("radiometry", "mosaic.ransac_px=3");
}

// The whole table's check (rules between fields included).
std::string check(const RadiometryParams& p) { return validate(p); }

}  // namespace

int cmdRadiometryMosaic(int argc, char** argv) {
    const std::string cmd = "radiometry mosaic";
    const std::string usage = withParams(kMosaicUsage);
    Args a(cmd, usage);
    const ParamOptions<RadiometryParams> params(radiometrySchema(), {{"--features", "mosaic.features"},
                                                                     {"--model", "mosaic.model"},
                                                                     {"--blend", "mosaic.blend"},
                                                                     {"--ransac-px", "mosaic.ransac_px"},
                                                                     {"--min-inliers", "mosaic.min_inliers"}});
    for (const char* o : {"-o", "--output", "--coverage", "--pairs", "--max-pixels"}) a.option(o, true);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    RadiometryParams rp;
    std::string err;
    if (int rc = params.load(cmd, a, &rp, check); rc >= 0) return rc;
    const MosaicParams& p = rp.mosaic;
    const std::string out = outPath(a);
    if (out.empty()) return fail(cmd, "no output file: give -o ROW.tif", kUsage);
    if (a.positional().size() < 2) return fail(cmd, "give at least two frames, in scan order", kUsage);
    long long maxPx = 0;
    if (!maxPixels(a, &maxPx, &err)) return fail(cmd, err, kUsage);
    core::OutputSet outs;
    for (const auto& f : a.positional()) outs.addInput(f);
    outs.addOutput(out);
    for (const char* o : {"--coverage", "--pairs"})
        if (a.has(o)) outs.addOutput(a.value(o));
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    if (const std::string why = mosaicMemoryProblem(a.positional(), memoryBudgetBytes()); !why.empty()) return fail(cmd, why);
    std::vector<cv::Mat> frames;
    for (const auto& f : a.positional()) {
        cv::Mat m;
        if (!readImageAnyDepth(f, &m, &err, maxPx)) return fail(cmd, err);
        frames.push_back(m);
    }
    Progress progress("mosaic", 100, quiet(a));
    core::Feedback fb([&](double f) { progress.update(static_cast<size_t>(100 * f)); });
    const MosaicResult r = mosaicRow(frames, p, &fb);
    progress.finish();
    if (!r.ok) return fail(cmd, r.error);
    warn(cmd, r.warnings, a);
    if (!writeImage(outs.stagingPath(out), r.image, &err) ||
        (a.has("--coverage") && !writeImage(outs.stagingPath(a.value("--coverage")), r.coverage, &err)) ||
        (a.has("--pairs") && !writePairCsv(outs.stagingPath(a.value("--pairs")), r, &err)))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, radiometrySchema().toJson(rp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a)) {
        std::cerr << "radiometry mosaic: " << frames.size() << " frames -> " << r.image.cols << "x" << r.image.rows << " "
                  << out << "\n";
        for (const auto& pr : r.pairs)
            std::cerr << "  frames " << pr.from + 1 << "-" << pr.to + 1 << ": " << pr.inliers << "/" << pr.matches
                      << " inliers, RMS " << fx(pr.rmsPx, 3) << " px, shift " << fx(pr.shiftX, 2) << ", " << fx(pr.shiftY, 2)
                      << " px\n";
    }
    return kOk;
}

int cmdRadiometryGcp(int argc, char** argv) {
    const std::string cmd = "radiometry gcp";
    const std::string usage = withParams(kGcpUsage);
    Args a(cmd, usage);
    const ParamOptions<RadiometryParams> params(radiometrySchema(),
                                                {{"--model", "gcp.model"}, {"--pixel-size", "gcp.pixel_size_m"}});
    for (const char* o : {"--gcps", "--residuals", "--valid", "-o", "--output", "--max-pixels", "--crs"}) a.option(o, true);
    a.option("--plain-tiff", false);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    RadiometryParams rp;
    std::string err;
    if (int rc = params.load(cmd, a, &rp, check); rc >= 0) return rc;
    const GcpFitParams& p = rp.gcp;
    const double pixel = rp.mapPixelSizeM;
    if (a.positional().size() != 1) return fail(cmd, "give exactly one image", kUsage);
    if (!a.has("--gcps")) return fail(cmd, "no control points: give --gcps GCPS.csv", kUsage);
    const std::string out = outPath(a);
    if (out.empty()) return fail(cmd, "no output file: give -o MAP.tif", kUsage);
    long long maxPx = 0;
    if (!maxPixels(a, &maxPx, &err)) return fail(cmd, err, kUsage);
    std::string crsWkt;
    if (a.has("--crs") && !crsFromUserInput(a.value("--crs"), &crsWkt, &err)) return fail(cmd, "--crs: " + err, kUsage);
    const bool plain = a.has("--plain-tiff");
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    outs.addInput(a.value("--gcps"));
    outs.addOutput(out);
    for (const char* o : {"--valid", "--residuals"})
        if (a.has(o)) outs.addOutput(a.value(o));
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    std::vector<Gcp> gcps;
    if (!readGcpCsv(a.value("--gcps"), &gcps, &err)) return fail(cmd, err);
    cv::Mat img;
    if (!readImageAnyDepth(a.positional()[0], &img, &err, maxPx)) return fail(cmd, err);
    const GcpFitResult fit = fitGcpTransform(gcps, p);
    if (!fit.ok) return fail(cmd, a.value("--gcps") + ": " + fit.error);
    warn(cmd, fit.warnings, a, !fit.outliers.empty());  // (outliers: the map is doubtful, exit 3)
    const MapGrid grid = gridCovering(fit, img.size(), pixel > 0 ? pixel : fit.metresPerPixel);
    const WarpResult w = warpToMap(img, fit, grid);
    if (!w.ok) return fail(cmd, w.error);
    const GeoReference geo = geoReferenceOf(grid, crsWkt);
    if (!writeMapImage(outs.stagingPath(out), w.image, geo, plain, &err, w.image.depth() == CV_32F) ||
        (a.has("--valid") && !writeMapImage(outs.stagingPath(a.value("--valid")), w.valid, geo, plain, &err)) ||
        (a.has("--residuals") && !writeGcpResidualCsv(outs.stagingPath(a.value("--residuals")), gcps, fit, &err)))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, radiometrySchema().toJson(rp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a))
        std::cerr << "radiometry gcp: " << gcps.size() << " GCPs, " << geoModelName(fit.model) << "; RMS "
                  << fx(fit.rmsMap, 4) << " m = " << fx(fit.rmsPx, 3) << " px; map grid " << grid.width << "x" << grid.height
                  << " at " << core::formatDouble(grid.pixelSize, 4) << " m, top-left centre (" << fx(grid.originX, 4)
                  << ", " << fx(grid.originY, 4) << ")" << (geo.valid && !plain && isTiffPath(out) ? ", GeoTIFF" : "") << "\n";
    if (!fit.outliers.empty()) {
        std::cerr << "laserwb-cli " << cmd << ": doubtful: " << fit.outliers.size()
                  << " GCP(s) do not agree with the others (outlier column of --residuals); exit 3\n";
        return kDoubtful;
    }
    return kOk;
}

int cmdRadiometryFit(int argc, char** argv) {
    const std::string cmd = "radiometry fit";
    const std::string usage = withParams(kFitUsage);
    Args a(cmd, usage);
    const ParamOptions<RadiometryParams> params(radiometrySchema(), {{"--dn-min", "dn_min"},
                                                                     {"--dn-max", "dn_max"},
                                                                     {"--vm", "vm_pct"},
                                                                     {"--min-region-pixels", "min_region_pixels"},
                                                                     {"--min-region-fraction", "min_region_fraction"}});
    for (const char* o : {"--image", "-o", "--output", "--regions", "--max-pixels"}) a.option(o, true);
    for (const char* o : {"--exclude-out-of-range", "--no-pixel-mask"}) a.option(o, false);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    RadiometryParams rp;
    std::string err;
    if (int rc = params.load(cmd, a, &rp, check, [&](RadiometryParams* q) {
            if (a.has("--exclude-out-of-range")) q->fit.excludeOutOfRange = true;
            if (a.has("--no-pixel-mask")) q->fit.maskOutOfRangePixels = false;
            return int(kOk);
        });
        rc >= 0)
        return rc;
    const ReflectanceFitParams& p = rp.fit;
    if (a.positional().size() != 1) return fail(cmd, "give exactly one region CSV", kUsage);
    const std::string out = outPath(a);
    if (out.empty()) return fail(cmd, "no output file: give -o FIT.csv", kUsage);
    long long maxPx = 0;
    if (!maxPixels(a, &maxPx, &err)) return fail(cmd, err, kUsage);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    outs.addInput(a.value("--image"));
    outs.addOutput(out);
    if (a.has("--regions")) outs.addOutput(a.value("--regions"));
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    std::vector<Region> regions;
    if (!readRegionCsv(a.positional()[0], &regions, &err)) return fail(cmd, err);
    if (a.has("--image")) {
        cv::Mat img;
        if (!readImageAnyDepth(a.value("--image"), &img, &err, maxPx)) return fail(cmd, err);
        if (!measureRegionDn(img, p, &regions, &err)) return fail(cmd, a.positional()[0] + ": " + err);
    }
    const ReflectanceFitResult r = fitReflectance(regions, p);
    if (!r.ok) return fail(cmd, a.positional()[0] + ": " + r.error);
    warn(cmd, r.warnings, a);
    if (!writeFitCsv(outs.stagingPath(out), r.fit, &err) ||
        (a.has("--regions") && !writeRegionFitCsv(outs.stagingPath(a.value("--regions")), regions, r, &err)))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, radiometrySchema().toJson(rp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a)) {
        const auto& f = r.fit;
        std::cerr << "radiometry fit: " << f.n << " regions; K = " << core::formatDouble(f.k, 6) << " +- "
                  << core::formatDouble(f.kSd, 3) << " %/DN, B = " << core::formatDouble(f.b, 6) << " +- "
                  << core::formatDouble(f.bSd, 3) << " %; R^2 " << fx(f.r2, 5) << "; uncertainty (eq. 6) "
                  << fx(f.paperUncertaintyPct, 4) << " %, at the mean DN " << fx(f.uncertaintyAtMeanPct, 4) << " %\n";
        long long outside = 0;
        for (const Region& rg : regions) outside += rg.pixelsOutOfRange;
        if (a.has("--image"))
            std::cerr << "  linear range " << core::formatDouble(p.dnMin, 6) << ".." << core::formatDouble(p.dnMax, 6) << ": "
                      << outside << " region pixels outside, " << (p.maskOutOfRangePixels ? "masked" : "not masked")
                      << ", " << r.regionsExcluded << " region" << (r.regionsExcluded == 1 ? "" : "s") << " left out\n";
    }
    return kOk;
}

int cmdRadiometryApply(int argc, char** argv) {
    const std::string cmd = "radiometry apply";
    const std::string usage = withParams(kApplyUsage);
    Args a(cmd, usage);
    const ParamOptions<RadiometryParams> params(radiometrySchema(),
                                                {{"--dn-min", "dn_min"}, {"--dn-max", "dn_max"}, {"--limit", "limit_pct"}});
    for (const char* o : {"--fit", "--k", "--b", "--uncertainty", "--check", "--table", "-o", "--output", "--max-pixels"})
        a.option(o, true);
    for (const char* o : {"--nan-out-of-range", "--plain-tiff"}) a.option(o, false);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    RadiometryParams rp;
    std::string err;
    ReflectanceFit fit;
    if (!a.getDouble("--k", -1e300, 1e300, &fit.k, &err) || !a.getDouble("--b", -1e300, 1e300, &fit.b, &err))
        return fail(cmd, err, kUsage);
    if (int rc = params.load(cmd, a, &rp, check, [&](RadiometryParams* q) {
            if (a.has("--nan-out-of-range")) q->outOfRangeToNan = true;
            return int(kOk);
        });
        rc >= 0)
        return rc;
    // The uncertainty image is made when it is written.
    rp.uncertaintyImage = a.has("--uncertainty");
    const ApplyParams p = applyParamsOf(rp);
    const double limit = rp.limitPct;
    if (a.has("--fit") == (a.has("--k") || a.has("--b")) || a.has("--k") != a.has("--b"))
        return fail(cmd, "give --fit FIT.csv, or --k K and --b B", kUsage);
    if (a.has("--uncertainty") && !a.has("--fit")) return fail(cmd, "--uncertainty needs --fit (the errors of K and B)", kUsage);
    if (a.has("--table") && !a.has("--check")) return fail(cmd, "--table needs --check", kUsage);
    if (a.positional().size() != 1) return fail(cmd, "give exactly one DN image", kUsage);
    const std::string out = outPath(a);
    if (out.empty()) return fail(cmd, "no output file: give -o REFLECTANCE.tif", kUsage);
    long long maxPx = 0;
    if (!maxPixels(a, &maxPx, &err)) return fail(cmd, err, kUsage);
    core::OutputSet outs;
    for (const char* in : {"--fit", "--check"}) outs.addInput(a.value(in));
    outs.addInput(a.positional()[0]);
    outs.addOutput(out);
    for (const char* o : {"--uncertainty", "--table"})
        if (a.has(o)) outs.addOutput(a.value(o));
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    if (a.has("--fit") && !readFitCsv(a.value("--fit"), &fit, &err)) return fail(cmd, err);
    cv::Mat img;
    if (!readImageAnyDepth(a.positional()[0], &img, &err, maxPx)) return fail(cmd, err);
    GeoReference geo;  // the input's georeferencing, when it has one (a file GDAL cannot open has none)
    if (std::string gerr; !readGeoReference(a.positional()[0], &geo, &gerr)) geo = GeoReference{};
    const bool plain = a.has("--plain-tiff");
    const ApplyResult r = applyReflectance(img, fit, p);
    const cv::Size size = img.size();
    img.release();  // (the DN image is not needed while the reflectance is written)
    if (!r.ok) return fail(cmd, r.error);
    warn(cmd, r.warnings, a);
    RelativeErrorResult check;
    if (a.has("--check")) {
        std::vector<Region> regions;
        if (!readRegionCsv(a.value("--check"), &regions, &err)) return fail(cmd, err);
        check = relativeErrors(regions, &r.reflectance, limit);
        if (!check.ok) return fail(cmd, a.value("--check") + ": " + check.error);
    }
    auto writeFloat = [&](const std::string& path, const cv::Mat& m) { return writeFloatMapImage(path, m, geo, plain, &err); };
    if (!writeFloat(outs.stagingPath(out), r.reflectance) ||
        (a.has("--uncertainty") && !writeFloat(outs.stagingPath(a.value("--uncertainty")), r.uncertainty)) ||
        (a.has("--table") && !writeRelativeErrorCsv(outs.stagingPath(a.value("--table")), check, &err)))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, radiometrySchema().toJson(rp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a))
        std::cerr << "radiometry apply: " << size.width << "x" << size.height << " -> " << out
                  << (geo.valid && !plain ? " (georeferenced as the input)" : "") << "\n";
    if (a.has("--check")) {
        for (const auto& row : check.rows)
            std::cout << row.name << ": measured " << fx(row.measured, 4) << " %, image " << fx(row.simulated, 4)
                      << " %, relative error " << fx(row.relativeErrorPct, 3) << " %\n";
        std::cout << "max relative error " << fx(check.maxPct, 3) << " % (limit " << core::formatDouble(limit, 4) << " %)\n";
        warn(cmd, check.warnings, a, !check.allWithinLimit);
        if (!check.allWithinLimit) {
            std::cerr << "laserwb-cli " << cmd << ": doubtful: a check region exceeds the " << core::formatDouble(limit, 4)
                      << " % limit (outputs written; exit 3)\n";
            return kDoubtful;
        }
    }
    return kOk;
}

int cmdRadiometryCheck(int argc, char** argv) {
    const std::string cmd = "radiometry check";
    const std::string usage = withParams(kCheckUsage);
    Args a(cmd, usage);
    const ParamOptions<RadiometryParams> params(radiometrySchema(), {{"--limit", "limit_pct"}});
    for (const char* o : {"--image", "-o", "--output", "--max-pixels"}) a.option(o, true);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    RadiometryParams rp;
    std::string err;
    if (int rc = params.load(cmd, a, &rp, check); rc >= 0) return rc;
    const double limit = rp.limitPct;
    if (a.positional().size() != 1) return fail(cmd, "give exactly one check-region CSV", kUsage);
    long long maxPx = 0;
    if (!maxPixels(a, &maxPx, &err)) return fail(cmd, err, kUsage);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    outs.addInput(a.value("--image"));
    if (!outPath(a).empty()) outs.addOutput(outPath(a));
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    std::vector<Region> regions;
    if (!readRegionCsv(a.positional()[0], &regions, &err)) return fail(cmd, err);
    cv::Mat img;
    if (a.has("--image") && !readImageAnyDepth(a.value("--image"), &img, &err, maxPx)) return fail(cmd, err);
    const RelativeErrorResult r = relativeErrors(regions, a.has("--image") ? &img : nullptr, limit);
    if (!r.ok) return fail(cmd, a.positional()[0] + ": " + r.error);
    if (!outPath(a).empty() && !writeRelativeErrorCsv(outs.stagingPath(outPath(a)), r, &err))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, radiometrySchema().toJson(rp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    for (const auto& row : r.rows)
        std::cout << row.name << ": measured " << fx(row.measured, 5) << " %, simulated " << fx(row.simulated, 5)
                  << " %, relative error " << fx(row.relativeErrorPct, 6) << " %\n";
    std::cout << "max " << fx(r.maxPct, 4) << " %, mean " << fx(r.meanPct, 4) << " % (limit " << core::formatDouble(limit, 4)
              << " %)\n";
    warn(cmd, r.warnings, a, !r.allWithinLimit);
    if (!r.allWithinLimit)
        std::cerr << "laserwb-cli " << cmd << ": doubtful: a region exceeds the limit (table written; exit 3)\n";
    return r.allWithinLimit ? kOk : kDoubtful;
}

namespace {
const char* kSimRadiometryUsage =
    "usage: laserwb-cli simulate radiometry OUTDIR\n"
    "Writes the inputs of a zero stadia standard image (paper 003) with exact truth, the field of the\n"
    "workbench's radiometry demo: a textured ground with six grey panels of known reflectance and four\n"
    "check surfaces, photographed as six overlapping 16-bit frames of one row.\n"
    "  OUTDIR/frame_1.png ... frame_6.png   the frames in scan order (radiometry mosaic)\n"
    "  OUTDIR/regions.csv   the grey panels: name, reflectance (%), x, y, w, h on the row image that\n"
    "                       `radiometry mosaic` makes of the frames with default settings (radiometry fit)\n"
    "  OUTDIR/check.csv     the check surfaces, the same way (radiometry apply --check, radiometry check)\n"
    "  OUTDIR/gcps.csv      six ground control points: id, x, y on the row image (picked to 0.3 px),\n"
    "                       map_x, map_y in metres (1 cm ground pixels, Y up; surveyed to 2 mm)\n"
    "                       (radiometry gcp)\n"
    "  OUTDIR/truth.csv     the simulated line V_REF = k * V_DN + b (%)\n"
    "  -q, --quiet          no summary on stderr\n";
}

int cmdSimulateRadiometry(int argc, char** argv) {
    const std::string cmd = "simulate radiometry";
    Args a(cmd, kSimRadiometryUsage);
    if (int rc = a.parseWithHelp(argc, argv, 3); rc >= 0) return rc;
    if (a.positional().size() != 1) return fail(cmd, "give exactly one output folder", kUsage);
    const std::string dir = a.positional()[0];
    const FolderForOutputs folder(dir);
    if (!folder.ok()) return fail(cmd, dir + ": cannot create the folder");
    const core::sim::RadiometryDemoField field = core::sim::demoRadiometryField();
    core::OutputSet outs;
    std::vector<std::string> names;
    for (size_t k = 0; k < field.frames.size(); ++k) {
        names.push_back(dir + "/frame_" + std::to_string(k + 1) + ".png");
        outs.addOutput(names.back());
    }
    for (const char* f : {"/regions.csv", "/check.csv", "/gcps.csv", "/truth.csv"}) outs.addOutput(dir + f);
    outs.setManifest(dir + "/truth.csv", dir, {"frame_[0-9]*.png"});
    if (int rc = checkOutputs(cmd, outs)) return rc;
    // The regions as an analyst would mark them on the row image: scene pixels mapped through
    // frame 1's transform in the mosaic of these frames with default settings.
    const MosaicResult m = mosaicRow(field.frames, RadiometryParams{}.mosaic);
    if (!m.ok) return fail(cmd, "internal error: the simulated frames do not mosaic: " + m.error);
    const cv::Matx33d& t = m.frameToMosaic[0];
    auto toRow = [&](double x, double y) {
        const cv::Vec3d v = t * cv::Vec3d(x - field.frame0.x, y - field.frame0.y, 1);
        return cv::Point2d(v[0] / v[2], v[1] / v[2]);
    };
    std::string regions = "name,reflectance,x,y,w,h\n", checks = regions;
    for (const auto& r : field.regions) {
        const cv::Point2d p0 = toRow(r.rect.x, r.rect.y), p1 = toRow(r.rect.x + r.rect.width, r.rect.y + r.rect.height);
        const long x0 = std::lround(p0.x), y0 = std::lround(p0.y);
        (r.check ? checks : regions) += r.name + "," + core::formatDouble(r.reflectance, 6) + "," + std::to_string(x0) + "," +
                                        std::to_string(y0) + "," + std::to_string(std::lround(p1.x) - x0) + "," +
                                        std::to_string(std::lround(p1.y) - y0) + "\n";
    }
    // Control points: marks on the ground at known scene positions, surveyed at 1 cm per scene
    // pixel (map Y up) to 2 mm, found on the row image where the mosaic put them and picked there
    // to 0.3 px (both errors Gaussian, 1 sigma, from a fixed seed).
    std::string gcps = "id,x,y,map_x,map_y\n";
    core::sim::Rng pick(20261127);
    const int sceneH = field.frames[0].rows + 2 * field.frame0.y;
    const double marks[][2] = {{60, 40}, {700, 50}, {1500, 45}, {80, 320}, {900, 330}, {1600, 310}};
    int id = 0;
    for (const auto& mk : marks) {
        const double sx = field.frame0.x + mk[0], sy = field.frame0.y + mk[1];
        const cv::Point2d q = toRow(sx, sy);
        if (q.x < 0 || q.y < 0 || q.x > m.image.cols - 1 || q.y > m.image.rows - 1) continue;
        const double px = q.x + 0.3 * pick.normal(), py = q.y + 0.3 * pick.normal();
        const double mx = sx * 0.01 + 0.002 * pick.normal(), my = (sceneH - sy) * 0.01 + 0.002 * pick.normal();
        gcps += "G" + std::to_string(++id) + "," + core::formatFixed(px, 2) + "," + core::formatFixed(py, 2) + "," +
                core::formatFixed(mx, 4) + "," + core::formatFixed(my, 4) + "\n";
    }
    std::string err;
    for (size_t k = 0; k < field.frames.size(); ++k)
        if (!writeImage(outs.stagingPath(names[k]), field.frames[k], &err)) return fail(cmd, outs.unstaged(err));
    const std::string truth = "k,b\n" + core::formatDouble(field.k, 12) + "," + core::formatDouble(field.b, 12) + "\n";
    if (!core::writeFileAtomic(outs.stagingPath(dir + "/regions.csv"), regions, &err) ||
        !core::writeFileAtomic(outs.stagingPath(dir + "/check.csv"), checks, &err) ||
        !core::writeFileAtomic(outs.stagingPath(dir + "/gcps.csv"), gcps, &err) ||
        !core::writeFileAtomic(outs.stagingPath(dir + "/truth.csv"), truth, &err))
        return fail(cmd, outs.unstaged(err));
    if (int rc = commitOutputs(cmd, outs)) return rc;
    folder.keep();
    if (!quiet(a))
        std::cerr << cmd << ": " << field.frames.size() << " frames, 6 grey panels, 4 check surfaces, " << id
                  << " control points -> " << dir << "\n";
    return kOk;
}

}  // namespace lwb::cli
