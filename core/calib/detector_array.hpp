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
    Elliptical,  ///< amplitude, centre (2), inverse covariance (3), background: 7 parameters
    Circular,    ///< amplitude, centre (2), one width, background: 5 parameters
};

struct DetectorFitParams {
    SurfaceModel model = SurfaceModel::Elliptical;
    bool fitBackground = true;     ///< false: background held at `background` (one parameter fewer)
    double background = 0;         ///< fixed background when fitBackground is false (energy unit)
    double triggerThreshold = 0;   ///< energy at or below this counts as untriggered (energy unit, ≥ 0)
    double saturationLevel = 0;    ///< energy at or above this counts as saturated (0 = no level; ≥ 0)
    double relativeNoise = 0.05;   ///< energy noise σ as a fraction of the model energy (0..1)
    double noiseFloor = 0;         ///< energy noise σ floor (energy unit, ≥ 0); both 0 = unweighted
    /// Scale the covariance by the reduced χ² (when dof > 0). Off by default: with the noise model
    /// above the unscaled covariance is honest, while a χ² from the few degrees of freedom of a
    /// footprint (often 3–10) is itself too uncertain. Always on when the fit is unweighted.
    bool scaleByChi2 = false;
    int recommendedDetectors = 9;  ///< warn below this many usable detectors (paper 002: ≥ 9)
    int maxIterations = 200;       ///< LM accepted steps (1..10000)
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

enum class DetectorStatus { Used, Untriggered, Saturated, NoEnergy };
const char* detectorStatusName(DetectorStatus s);

struct DetectorOutcome {
    DetectorStatus status = DetectorStatus::Used;
    std::string reason;            ///< why it was set aside (empty when used)
    double model = NAN;            ///< fitted surface at the detector (energy unit)
    double residual = NAN;         ///< energy − model (used detectors)
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
    int used = 0;                  ///< detectors in the fit
    int dof = 0;                   ///< used − parameters
    double chi2 = NAN;             ///< Σ weighted residual² at the fit
    double rmsResidual = NAN;      ///< unweighted RMS of energy − model over the used detectors
    int iterations = 0;
    std::vector<double> costPerIteration;  ///< Σ weighted residual² after each accepted step
    std::vector<DetectorOutcome> detectors;  ///< one per input detector, same order
};

/// Fits the Gaussian surface to the usable detectors (paper 002 §3.2.3). Errors: fewer usable
/// detectors than parameters, non-finite positions, collinear detectors, a fit that diverges.
DetectorFitResult fitDetectorArray(const DetectorArray& array, const DetectorFitParams& params = {});

/// Writes the array in the format readDetectorCsv reads (lat/lon when geographic), atomically.
bool writeDetectorCsv(const std::string& path, const DetectorArray& array, std::string* error);

/// Writes one row per detector (id, e, n, energy, status, reason, model, residual), atomically.
bool writeDetectorReportCsv(const std::string& path, const DetectorArray& array, const DetectorFitResult& r,
                            std::string* error);

}  // namespace lwb::core::calib
