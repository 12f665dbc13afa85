#pragma once
// Laser altimeter pointing and range calibration (paper 002 §2.1.2 eq. 2, §2.2 eq. 3–5).
//
// Geolocation model (eq. 2), one beam, one shot:
//     G = S + R_att · ( o + (ρ + Δρ) · M · u(α + Δα, β + Δβ) )
//   S      satellite position reference (ECEF, m)
//   R_att  attitude: body → ECEF rotation (the caller composes body→inertial with inertial→ECEF)
//   o      laser origin in the body frame (m); M laser frame → body frame mounting rotation
//   u(α,β) = [sin α cos β, sin α sin β, cos α]: α off the laser +Z axis, β azimuth from +X to +Y
//   ρ      measured one-way range, already corrected for atmosphere and tides (m); Δρ its bias
// Body frame convention of the simulator: +X along track, +Z toward nadir, +Y = Z × X (right of
// the flight direction); GF-7 beam 1 points 0.7° to the right (β = 90°), beam 2 to the left.
//
// Dual-beam model (eq. 3): beam 2's body-frame pointing is beam 1's rotated by
//     u2 = ΔR(r, a, b) · ΔR0 · u1,   ΔR = exp([r·e1 + a·e2 + b·u2⁰]×),
// ΔR0 the design rotation taking beam 1's design pointing to beam 2's, u2⁰ = ΔR0·u1⁰ and e1, e2
// a basis perpendicular to it (e1 from the body X axis). A twist b about beam 2's own axis does
// not move its footprint, so b is unobservable and held at 0; r and a are solved (or held at 0
// with fixRelativeRotation: rigid beams, a common pointing correction).
//
// Solution (eq. 4): Levenberg–Marquardt on the ground residuals G_model − G_control of every
// control point, each weighted by its full 3×3 covariance (control-point survey σ, range noise
// along the beam, attitude noise across it, orbit noise), so the parameter covariance is an
// honest 1σ when the stated noise is right.
//
// Three-axis pointing angles (eq. 5): Angle_X = arccos(u·X), Angle_Y = arccos(u·Y),
// Angle_Z = arccos(u·Z) of the body-frame pointing unit vector u.
#include <cmath>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/calib/geodesy.hpp"

namespace lwb::core::calib {

struct BeamDesign {
    int id = 1;                          ///< beam number as used in the control-point file
    double alphaRad = 0.7 * kDeg;        ///< design angle off the laser +Z axis (rad, 0..π/2)
    double betaRad = 90 * kDeg;          ///< design azimuth from laser +X toward +Y (rad)
    Eigen::Vector3d offsetBodyM = Eigen::Vector3d::Zero();       ///< laser origin in the body frame (m)
    Eigen::Quaterniond laserToBody = Eigen::Quaterniond::Identity();  ///< mounting rotation M
};

struct LaserShot {
    Eigen::Vector3d satEcef = Eigen::Vector3d::Zero();              ///< satellite position (m, ECEF)
    Eigen::Quaterniond bodyToEcef = Eigen::Quaterniond::Identity();  ///< attitude
    double rangeM = 0;                   ///< measured one-way range (m), atmosphere/tide corrected
};

struct ControlPoint {
    std::string id;
    int beam = 1;
    LaserShot shot;
    Eigen::Vector3d groundEcef = Eigen::Vector3d::Zero();  ///< surveyed footprint centre (m, ECEF)
    double sigmaHorizontalM = NAN;       ///< 1σ per horizontal axis (m); NaN = the params default
    double sigmaVerticalM = NAN;         ///< 1σ height (m); NaN = the params default
    bool useHeight = true;               ///< false: only the horizontal position constrains
    long line = 0;                       ///< source line (for messages)
};

/// u(α, β) in the laser frame (unit vector).
Eigen::Vector3d pointingVector(double alphaRad, double betaRad);
/// (α, β) of a laser-frame unit vector (β in −π..π).
void pointingAngles(const Eigen::Vector3d& u, double* alphaRad, double* betaRad);
/// Body-frame pointing of a beam with corrections (Δα, Δβ) in rad.
Eigen::Vector3d bodyPointing(const BeamDesign& beam, double dAlpha, double dBeta);
/// Eq. 2: ground point (ECEF, m) of a shot along a body-frame pointing uBody with range bias dRho.
Eigen::Vector3d geolocate(const BeamDesign& beam, const LaserShot& shot, const Eigen::Vector3d& uBody, double dRho);
/// Eq. 2 with the beam's design pointing corrected by (Δα, Δβ).
Eigen::Vector3d geolocate(const BeamDesign& beam, const LaserShot& shot, double dAlpha, double dBeta, double dRho);

struct ThreeAxisAngles {
    double x = 0, y = 0, z = 0;          ///< Angle_X, Angle_Y, Angle_Z (rad)
};
/// Eq. 5: arccos of the body-frame unit vector's components.
ThreeAxisAngles threeAxisAngles(const Eigen::Vector3d& uBody);

/// The rotation of the dual-beam model: exp([r·e1 + a·e2 + b·u2]×) · ΔR0 (see the header).
Eigen::Matrix3d dualBeamRotation(const BeamDesign& beam1, const BeamDesign& beam2, double r, double a, double b);

enum class CalibModel {
    SingleBeam,  ///< each beam on its own: (Δα, Δβ[, Δρ]) per beam with control points
    DualBeam,    ///< beam 1 (Δα1, Δβ1[, Δρ1]) + relative rotation (r, a) [+ Δρ2]
};
const char* calibModelName(CalibModel m);

struct PointingCalibParams {
    CalibModel model = CalibModel::SingleBeam;
    bool solveRange = true;              ///< false: pointing only (the paper's coarse step)
    bool fixRelativeRotation = false;    ///< dual: hold r = a = 0 (beams rigid to their design)
    double sigmaHorizontalM = 0.5;       ///< default control-point σ per horizontal axis (m, > 0)
    double sigmaVerticalM = 0.05;        ///< default control-point height σ (m, > 0); RTK: ≤ 0.05
    double sigmaRangeM = 0.1;            ///< range noise per shot (m, ≥ 0)
    double sigmaAttitudeRad = 1e-6;      ///< attitude noise per axis per shot (rad, ≥ 0)
    double sigmaOrbitM = 0.05;           ///< orbit position noise per axis (m, ≥ 0)
    bool scaleByChi2 = false;            ///< scale the covariance by the reduced χ² (when dof > 0)
    int maxIterations = 20;              ///< accepted LM steps (1..1000)
    double minRcond = 1e-9;              ///< below this reciprocal condition the geometry is singular
};
std::string validate(const PointingCalibParams& p);

/// Residual of one control point (model − control) in its local ENU frame (m), and the same
/// split along / across track (along = body +X projected on the horizontal; across = to its right).
struct GroundResidual {
    double e = 0, n = 0, u = 0, along = 0, across = 0;
    double plan() const;
};

struct ControlPointResidual {
    size_t index = 0;                    ///< into the control-point list
    std::string id;
    int beam = 0;
    GroundResidual before;               ///< with the design pointing and zero range bias
    GroundResidual after;                ///< with the calibrated parameters
    double normalized = 0;               ///< √(whitened residual²) after (≈ √dims when the σ are honest)
};

struct CalibIteration {
    int iteration = 0;                   ///< 0 = start (design values)
    std::vector<double> params;          ///< in paramNames order (rad, m)
    double chi2 = 0;                     ///< Σ whitened residual²
    double rmsPlanM = 0, rmsHeightM = 0, rms3dM = 0;
    std::vector<GroundResidual> residuals;  ///< per control point, for convergence plots
};

struct BeamCalibration {
    int id = 0;
    int points = 0;                      ///< control points of this beam
    bool solved = false;                 ///< false: no control points, parameters left at design
    bool rangeSolved = false;
    double dAlphaRad = 0, dBetaRad = 0, dRhoM = 0;
    double dAlphaSdRad = NAN, dBetaSdRad = NAN, dRhoSdM = NAN;
    double alphaRad = 0, betaRad = 0;    ///< calibrated pointing angles (laser frame)
    ThreeAxisAngles designAngles, calibratedAngles;  ///< eq. 5, body frame (rad)
    double angleXSdRad = NAN, angleYSdRad = NAN, angleZSdRad = NAN;
    double planShiftM = 0;               ///< ground shift of the footprint at the mean range from the correction
};

struct PointingCalibResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    CalibModel model = CalibModel::SingleBeam;
    std::vector<std::string> paramNames; ///< e.g. dalpha_b1, dbeta_b1, drho_b1, r, a, drho_b2
    std::vector<double> params;          ///< rad / m
    Eigen::MatrixXd covariance;          ///< of params (rad², m², rad·m)
    std::vector<double> paramSd;
    std::vector<BeamCalibration> beams;  ///< one per design, in design order
    std::vector<CalibIteration> iterations;  ///< start + every accepted step
    std::vector<ControlPointResidual> residuals;
    int observations = 0;                ///< scalar equations (3 per point, 2 without height)
    int dof = 0;
    double chi2 = 0;
    double rcond = 0;                    ///< reciprocal condition of the scaled normal matrix
    bool converged = false;
};

/// Solves the pointing corrections and range biases from the control points (eq. 2–4).
/// Errors: no or too few control points, unknown beams, non-finite inputs, singular geometry.
PointingCalibResult calibratePointing(const std::vector<BeamDesign>& beams, const std::vector<ControlPoint>& points,
                                      const PointingCalibParams& params = {});

/// Reads control points: header beam, [id], sat_x, sat_y, sat_z (m ECEF), q_w, q_x, q_y, q_z
/// (body→ECEF), range_m, then gcp_x, gcp_y, gcp_z (m ECEF) or gcp_lat, gcp_lon (deg), gcp_h (m),
/// and optionally sigma_h, sigma_v (m), use_height (0/1). Errors name the file and line.
bool readControlPointCsv(const std::string& path, std::vector<ControlPoint>* out, std::string* error);
/// Writes control points in the format readControlPointCsv reads (ECEF ground), atomically.
bool writeControlPointCsv(const std::string& path, const std::vector<ControlPoint>& points, std::string* error);

/// Reads beam designs from JSON: {"beams": [{"id": 1, "alpha_deg": 0.7, "beta_deg": 90,
/// "offset_m": [x, y, z], "mounting_quat": [w, x, y, z]}, ...]} (offset and mounting optional).
bool readBeamsJson(const std::string& path, std::vector<BeamDesign>* out, std::string* error);
std::string beamsToJson(const std::vector<BeamDesign>& beams);

}  // namespace lwb::core::calib
