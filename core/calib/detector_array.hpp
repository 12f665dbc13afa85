#pragma once
// Ground infrared detector array (paper 002 §2.2 / §3.2.3): the detectors a laser footprint
// triggered record its energy; a 2D Gaussian surface fitted to the energies by
// Levenberg–Marquardt gives the footprint centre, with its 1σ uncertainty ellipse. Saturated
// and untriggered detectors are set aside, each with its reason.
#include <cmath>
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace lwb::core::calib {

struct Detector {
    std::string id;          ///< as in the input (row number when the file has no id column)
    double e = 0, n = 0;     ///< east, north in the local tangent plane (m)
    double h = NAN;          ///< ellipsoidal height (m), NaN when not given
    double energy = NAN;     ///< captured energy (any linear unit: fJ, counts, DN); NaN = not recorded
    int triggered = -1;      ///< 1 / 0 from the file, −1 when the file has no such column
    int saturated = -1;      ///< 1 / 0 from the file, −1 when the file has no such column
    long line = 0;           ///< source line (for messages)
};

struct DetectorArray {
    std::vector<Detector> detectors;
    bool geographic = false;       ///< positions were given as lat/lon and projected to the tangent plane
    double originLatDeg = NAN, originLonDeg = NAN, originH = 0;  ///< tangent point when geographic
    std::string source;            ///< file name (for messages)
};

/// Reads a detector CSV: header with id (optional), either e,n (or east,north / x,y; metres)
/// or lat,lon (degrees, projected onto the ENU tangent plane at their mean), energy, and
/// optionally h (or height), triggered (0/1), saturated (0/1). An empty energy is allowed only
/// for a detector marked triggered=0. Errors name the file and line.
bool readDetectorCsv(const std::string& path, DetectorArray* out, std::string* error);

enum class SurfaceModel {
    Auto,        ///< Elliptical when at least 10 detectors carry a measurement, else Circular (and
                 ///< below 7 the circular surface without background, held at `background`)
    Elliptical,  ///< amplitude, centre (2), inverse covariance (3), background: 7 parameters
    Circular,    ///< amplitude, centre (2), one width, background: 5 parameters
};
const char* surfaceModelName(SurfaceModel m);

/// Where the detectors' energy noise σ² = floor² + (relative·model)² comes from.
enum class NoiseSource {
    FromData,  ///< estimated from the array: floor and relative term from the fit's residuals (leverage
               ///< corrected, maximum likelihood; the relative term only when it earns its parameter by BIC)
    Given,     ///< relativeNoise and noiseFloor as given (both 0: unweighted, scale from χ²/dof)
};

struct DetectorFitParams {
    SurfaceModel model = SurfaceModel::Auto;  ///< default Auto
    bool fitBackground = true;     ///< false: background held at `background` (one parameter fewer)
    double background = 0;         ///< fixed background when fitBackground is false (energy unit)
    /// Energy at or below this counts as untriggered (energy unit, ≥ 0; default 0 = no threshold:
    /// every recorded energy, zero and negative ones included, is a measurement).
    double triggerThreshold = 0;
    /// Energy at or above this counts as saturated (energy unit, ≥ 0; default 0 = no level: then a
    /// maximum energy shared by two or more detectors without a saturated column is taken as a clip level).
    double saturationLevel = 0;
    NoiseSource noise = NoiseSource::FromData;  ///< default FromData
    double relativeNoise = 0;      ///< Given: energy noise σ as a fraction of the model energy (0..1, default 0)
    double noiseFloor = 0;         ///< Given: energy noise σ floor (energy unit, ≥ 0, default 0)
    /// Censoring (default on): a saturated detector says "at least its level", an untriggered one
    /// that is listed says "at most the trigger level" (the lowest triggered energy when no
    /// threshold is given); both enter the fit through the normal likelihood of that statement.
    /// Off: both are set aside.
    bool censor = true;
    /// Detectors whose residual exceeds this many robust σ are set aside as inconsistent (a dead or
    /// faulty detector): first all of them on a fit with a Cauchy loss (so that they cannot bend the
    /// surface), then one at a time on the least-squares refits (≥ 3; default 4; 0 = keep every
    /// detector and fit by plain least squares).
    double outlierSigma = 4;
    /// Given noise: scale the covariance by the reduced χ² (when dof > 0). Off by default. Always
    /// on when the given noise is unweighted (both terms 0). FromData already scales to the data.
    bool scaleByChi2 = false;
    int recommendedDetectors = 9;  ///< warn below this many detectors seeing the footprint (paper 002: ≥ 9)
    int maxIterations = 200;       ///< LM accepted steps (1..10000)
    /// Given noise: the result is doubtful when χ² is this improbable for its degrees of freedom,
    /// in either tail (0..0.5, default 0.001).
    double chi2Probability = 1e-3;
    /// The result is doubtful when the fitted footprint's major/minor axis ratio exceeds this
    /// (≥ 1; default 2: a laser footprint is nearly round, GF-7's within 1.3; a narrow fitted
    /// ellipse usually explains a dead detector under the peak away).
    double maxAxisRatio = 2;
};

std::string validate(const DetectorFitParams& p);

/// A Gaussian surface E(e, n) = A·exp(−½[a·de² + 2b·de·dn + c·dn²]) + background, de = e − e0.
struct GaussSurface {
    double amplitude = 0;          ///< energy unit
    double e0 = 0, n0 = 0;         ///< centre (m, local tangent plane)
    double a = 0, b = 0, c = 0;    ///< inverse covariance (1/m²)
    double background = 0;         ///< energy unit
    double sigmaMajor = 0, sigmaMinor = 0;  ///< 1σ widths along the principal axes (m)
    double orientationRad = 0;     ///< major axis from east toward north (rad, −π/2..π/2)
};

/// Evaluates the surface at (e, n) in metres.
double evalSurface(const GaussSurface& s, double e, double n);

/// A 1σ uncertainty ellipse of a 2D position (multiply the semi-axes by 2.4477 for 95 %).
struct UncertaintyEllipse {
    double sigmaE = 0, sigmaN = 0, covEN = 0;  ///< marginal σ (m) and covariance (m²)
    double semiMajor = 0, semiMinor = 0;       ///< 1σ semi-axes (m)
    double orientationRad = 0;                 ///< semi-major axis from east toward north (rad)
};
UncertaintyEllipse ellipseFromCovariance(double varE, double varN, double covEN);

enum class DetectorStatus {
    Used,         ///< a measurement in the fit
    Untriggered,  ///< set aside: untriggered
    Saturated,    ///< set aside: saturated (censoring off)
    NoEnergy,     ///< set aside: no energy recorded
    AtLeast,      ///< saturated, in the fit as "energy ≥ bound" (censored)
    AtMost,       ///< untriggered, in the fit as "energy ≤ bound" (censored)
    Outlier,      ///< set aside: inconsistent with the fit by more than outlierSigma (dead or faulty?)
};
const char* detectorStatusName(DetectorStatus s);

struct DetectorOutcome {
    DetectorStatus status = DetectorStatus::Used;
    std::string reason;            ///< why it was set aside (empty when used)
    double model = NAN;            ///< fitted surface at the detector (energy unit)
    double residual = NAN;         ///< energy − model (used detectors)
    double bound = NAN;            ///< AtLeast / AtMost: the censoring bound (energy unit)
    double sigma = NAN;            ///< noise σ of the detector in the final fit (energy unit)
};

/// The noise model a fit used.
struct NoiseModelUsed {
    NoiseSource source = NoiseSource::FromData;
    double floor = NAN;            ///< σ floor (energy unit)
    double relative = NAN;         ///< σ as a fraction of the model energy
    int dof = 0;                   ///< degrees of freedom behind an estimate (0 when given)
    std::string description;       ///< one line for reports
};

struct DetectorFitResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    GaussSurface surface;
    std::vector<std::string> paramNames;  ///< order of the covariance rows
    Eigen::MatrixXd covariance;           ///< of the fitted parameters (units as in paramNames)
    double centreE = NAN, centreN = NAN;  ///< footprint centre (m)
    UncertaintyEllipse centreEllipse;     ///< its 1σ ellipse
    double sigmaMajorSd = NAN, sigmaMinorSd = NAN, amplitudeSd = NAN;
    double centreLatDeg = NAN, centreLonDeg = NAN;  ///< when the array was geographic
    double centreH = NAN;          ///< height at the centre from a plane through the detector heights (m)
    int used = 0;                  ///< measurements in the fit (status Used; bounds are counted in `censored`)
    int dof = 0;                   ///< used − parameters
    double chi2 = NAN;             ///< Σ weighted residual² at the fit
    double rmsResidual = NAN;      ///< unweighted RMS of energy − model over the used detectors
    int iterations = 0;
    std::vector<double> costPerIteration;  ///< Σ weighted residual² after each accepted step
    std::vector<DetectorOutcome> detectors;  ///< one per input detector, same order
    SurfaceModel modelUsed = SurfaceModel::Elliptical;  ///< Elliptical or Circular (Auto resolved)
    NoiseModelUsed noise;          ///< the noise model of the final fit
    /// The 95 % ellipse is centreEllipse × this: 2.4477 (χ²₂) with a known noise, √(2·F₂,ν(0.95))
    /// when the noise scale was estimated from ν degrees of freedom.
    double centreEllipse95Scale = 2.4477;
    int censored = 0;              ///< detectors in the fit as bounds (AtLeast + AtMost)
    int outliers = 0;              ///< detectors set aside as inconsistent
    int seeing = 0;                ///< detectors that see the footprint: energy above background by > 3 noise σ
                                   ///< (and > 1 % of the amplitude), or saturated
    double chi2Exact = NAN;        ///< χ² of the measurements alone (censored terms left out)
    /// The goodness of fit: Σ of the measurements' normal scores², each score taken in the normal
    /// law above the trigger level for a detector that recorded because it triggered (the plain
    /// residual otherwise; equal to chi2Exact on full reports), on gofDof degrees of freedom.
    double chi2Gof = NAN;
    int gofDof = 0;
    double chi2Probability = NAN;  ///< Given noise: P(χ²_gofDof ≥ chi2Gof) (Wilson–Hilferty)
    double centreOutsideSeeingM = NAN;  ///< distance of the centre outside the hull of the seeing detectors (0 inside)
    double centreOutsideArrayM = NAN;   ///< … outside the hull of all detectors (0 inside)
    /// Doubtful: a centre was found but must not be trusted; `doubts` says why (each a sentence).
    bool doubtful = false;
    std::vector<std::string> doubts;
};

/// Fits the Gaussian surface to the usable detectors (paper 002 §3.2.3). Errors: fewer usable
/// detectors than parameters, non-finite positions, collinear detectors, a fit that diverges.
/// A result that is found but implausible is returned with doubtful = true and its reasons: χ²
/// improbable under a given noise model, the centre outside the detectors that see the footprint
/// or outside the array by more than the footprint's 1/e² radius, a 95 % ellipse larger than the
/// array, a footprint wider than twice the array or narrower than the detector spacing, an axis
/// ratio above maxAxisRatio, a peak less than 3 noise σ above the background.
DetectorFitResult fitDetectorArray(const DetectorArray& array, const DetectorFitParams& params = {});

/// Writes the array in the format readDetectorCsv reads (lat/lon when geographic), atomically.
bool writeDetectorCsv(const std::string& path, const DetectorArray& array, std::string* error);

/// Writes the centre as a one-row CSV (centre, 1σ and 95 % ellipse, lat/lon, height, surface,
/// fit figures, noise model, doubtful and its reasons), atomically.
bool writeDetectorCentreCsv(const std::string& path, const DetectorFitResult& r, std::string* error);

/// Writes one row per detector (id, e, n, energy, status, reason, model, residual, bound, sigma), atomically.
bool writeDetectorReportCsv(const std::string& path, const DetectorArray& array, const DetectorFitResult& r,
                            std::string* error);

}  // namespace lwb::core::calib
