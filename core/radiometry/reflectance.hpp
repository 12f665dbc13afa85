#pragma once
// Synchronous radiometric correction of a ground mosaic (paper 003 §2.2 eq. 5, §4 eq. 6):
// the mean DN of marked regions (grey panels, markers) against the reflectance a spectrometer
// measured there (350–900 nm average) gives the line V_REF = K·V_DN + B by least squares; the
// line turns the whole DN mosaic into a reflectance image. Reflectances are in percent.
//
// Uncertainty. Paper eq. 6: V_T = √(V_M² + V_err²), V_M the spectrometer's 0.17 %, V_err the
// fit error; the paper's tables 3 → 4 add the standard errors of K and B in quadrature as if both
// were percentages (V_err² = σ_K² + σ_B²): paperUncertaintyPct. Because σ_B is the error of the
// line at DN = 0, far outside the data, the propagated error of the line at a given DN,
// √(σ_K²·DN² + 2·DN·cov(K,B) + σ_B²), is offered too (predictionUncertaintyPct).
#include "core/common/image_header.hpp"
#include <cmath>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace lwb::core::radiometry {

struct Region {
    std::string name;
    double reflectance = NAN;   ///< measured reflectance (%), spectrometer
    double dn = NAN;            ///< mean DN: given, or measured from an image over `rect`
    double simulated = NAN;     ///< reflectance from the reflectance image (%): given, or measured over `rect`
    cv::Rect rect;              ///< region in image pixels (empty when the DN / simulated value is given)
    int pixels = 0;             ///< pixels averaged (when measured)
    int pixelsOutOfRange = 0;   ///< of those, outside the camera's linear range
    double dnStd = NAN;         ///< DN standard deviation inside the region (when measured)
    long line = 0;              ///< source line (for messages)
};

/// Reads regions: header name (or id), reflectance (or measured), and dn, and/or simulated,
/// and/or x, y, w, h (a rectangle in image pixels). Errors name the file and line.
bool readRegionCsv(const std::string& path, std::vector<Region>* out, std::string* error);

struct ReflectanceFitParams {
    double dnMin = 100;                 ///< camera linear range, lower end (DN); paper 003: 100
    double dnMax = 60000;               ///< camera linear range, upper end (DN); paper 003: 60000
    bool excludeOutOfRange = false;     ///< leave regions outside the range out of the fit (else: warn)
    double spectrometerPct = 0.17;      ///< V_M, spectrometer uncertainty (%, ≥ 0); paper 003: 0.17
};
std::string validate(const ReflectanceFitParams& p);

/// Mean (and σ) DN of every region with a rectangle, from a single-channel image of any depth.
/// Counts the pixels outside [dnMin, dnMax]. False (with *error naming the region) when a
/// rectangle leaves the image or the image has more than one channel.
bool measureRegionDn(const cv::Mat& image, const ReflectanceFitParams& params, std::vector<Region>* regions,
                     std::string* error);

struct ReflectanceFit {
    double k = NAN, b = NAN;            ///< V_REF = K·V_DN + B (%/DN, %)
    double kSd = NAN, bSd = NAN;        ///< standard errors (%/DN, %)
    double covKB = NAN;                 ///< covariance of K and B (%²/DN)
    int n = 0;                          ///< regions in the fit
    double residualSd = NAN;            ///< √(Σ residual² / (n − 2)) (%)
    double r2 = NAN;                    ///< coefficient of determination
    double meanDn = NAN;                ///< mean DN of the fitted regions
    double spectrometerPct = 0.17;      ///< V_M used in the uncertainties
    double paperUncertaintyPct = NAN;   ///< eq. 6 as tabulated: √(V_M² + σ_K² + σ_B²)
    double uncertaintyAtMeanPct = NAN;  ///< √(V_M² + prediction variance at meanDn)
};

struct RegionOutcome {
    bool used = true;
    std::string note;                   ///< why left out or what is doubtful
    double predicted = NAN;             ///< K·DN + B (%)
    double residual = NAN;              ///< measured − predicted (%)
};

struct ReflectanceFitResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    ReflectanceFit fit;
    std::vector<RegionOutcome> regions;  ///< same order as the input
};

/// Least-squares line through (mean DN, reflectance) of the regions (eq. 5) with standard
/// errors. Errors: fewer than 3 usable regions (2 fix the line, the third measures its error),
/// all regions at one DN, non-finite values.
ReflectanceFitResult fitReflectance(const std::vector<Region>& regions, const ReflectanceFitParams& params = {});

/// Eq. 6 as the paper evaluates it: √(V_M² + σ_K² + σ_B²) (all in %).
double paperUncertaintyPct(double spectrometerPct, double kSd, double bSd);
/// √(V_M² + σ_K²·DN² + 2·DN·cov(K,B) + σ_B²): the line's uncertainty at one DN (%).
double predictionUncertaintyPct(const ReflectanceFit& fit, double dn);

/// Writes the fit as a one-row CSV (k, b, k_sd, b_sd, cov_kb, n, residual_sd, r2, mean_dn,
/// vm_pct, paper_uncertainty_pct, uncertainty_at_mean_pct), atomically.
bool writeFitCsv(const std::string& path, const ReflectanceFit& fit, std::string* error);
/// Reads a fit CSV written by writeFitCsv (k and b required; the rest optional).
bool readFitCsv(const std::string& path, ReflectanceFit* fit, std::string* error);
/// Writes the per-region table (name, dn, reflectance, predicted, residual, used, note), atomically.
bool writeRegionFitCsv(const std::string& path, const std::vector<Region>& regions, const ReflectanceFitResult& r,
                       std::string* error);

struct ApplyParams {
    double dnMin = 100, dnMax = 60000;  ///< camera linear range (DN)
    bool outOfRangeToNan = false;       ///< pixels outside the range become NaN (else converted, and counted)
    bool uncertaintyImage = false;      ///< also produce the per-pixel uncertainty (%)
};

std::string validate(const ApplyParams& p);

struct ApplyResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    cv::Mat reflectance;                ///< CV_32FC1, %
    cv::Mat uncertainty;                ///< CV_32FC1, % (when asked)
    size_t belowRange = 0, aboveRange = 0;  ///< pixels outside the linear range
};

/// Converts a single-channel DN image (8U, 16U, 32F, 64F) to reflectance with the fit (eq. 5).
ApplyResult applyReflectance(const cv::Mat& dn, const ReflectanceFit& fit, const ApplyParams& params = {});

struct RelativeErrorRow {
    std::string name;
    double measured = NAN, simulated = NAN;  ///< reflectance (%)
    double relativeErrorPct = NAN;      ///< |simulated − measured| / measured · 100
    bool withinLimit = false;
};

struct RelativeErrorResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    std::vector<RelativeErrorRow> rows;
    double maxPct = NAN, meanPct = NAN;
    bool allWithinLimit = false;
};

/// Paper 003 tables 5–7: relative error of the reflectance image against check regions. A
/// region's simulated value is taken from `reflectanceImage` over its rectangle when it has one
/// (and the image is given), else from its `simulated` field. limitPct: paper 003 accepts 5 %.
RelativeErrorResult relativeErrors(const std::vector<Region>& regions, const cv::Mat* reflectanceImage = nullptr,
                                   double limitPct = 5.0);

/// Writes the relative-error table (name, measured, simulated, relative_error_pct, within_limit), atomically.
bool writeRelativeErrorCsv(const std::string& path, const RelativeErrorResult& r, std::string* error);

/// Writes a single-channel CV_32F image as a 32-bit float TIFF, atomically.
bool writeFloatTiff(const std::string& path, const cv::Mat& image, std::string* error);

/// Reads a single-channel image of any depth (PNG, TIFF, PGM, JPEG) unchanged; colour is
/// converted to grey. Images over maxPixels (0 = no limit) are refused from their header,
/// before decoding. Errors name the file.
bool readImageAnyDepth(const std::string& path, cv::Mat* out, std::string* error,
                       long long maxPixels = kMaxImagePixels);

/// Writes an image in the format of the path's extension (.tif/.tiff keep 8U, 16U and 32F;
/// .png keeps 8U and 16U), atomically.
bool writeImage(const std::string& path, const cv::Mat& image, std::string* error);

}  // namespace lwb::core::radiometry
