#pragma once
// WGS-84 geodesy used by the calibration code: geodetic ↔ ECEF, and a local east-north-up
// tangent plane (detector arrays, residuals of control points). Angles in radians.
#include <Eigen/Dense>

namespace lwb::core::calib {

constexpr double kWgs84A = 6378137.0;                 ///< semi-major axis (m)
constexpr double kWgs84F = 1.0 / 298.257223563;       ///< flattening
constexpr double kSpeedOfLight = 299792458.0;         ///< m/s (exact)

struct Geodetic {
    double latRad = 0, lonRad = 0;  ///< geodetic latitude, longitude (rad)
    double h = 0;                   ///< ellipsoidal height (m)
};

/// Geodetic (lat, lon in rad, h in m) → Earth-centred Earth-fixed (m).
Eigen::Vector3d geodeticToEcef(double latRad, double lonRad, double h);
/// ECEF (m) → geodetic; exact to < 1 mm anywhere above −100 km (Bowring start + iterations).
Geodetic ecefToGeodetic(const Eigen::Vector3d& ecef);
/// Rotation whose rows are the east, north and up unit vectors (ECEF) at (lat, lon).
Eigen::Matrix3d ecefToEnuRotation(double latRad, double lonRad);

/// A local tangent plane: ENU coordinates (m) about an origin on or near the ellipsoid.
class LocalFrame {
public:
    LocalFrame() = default;
    LocalFrame(double latRad, double lonRad, double h);
    Eigen::Vector3d toEnu(const Eigen::Vector3d& ecef) const { return m_rot * (ecef - m_origin); }
    Eigen::Vector3d toEcef(const Eigen::Vector3d& enu) const { return m_origin + m_rot.transpose() * enu; }
    const Eigen::Matrix3d& rotation() const { return m_rot; }  ///< ECEF → ENU
    const Eigen::Vector3d& origin() const { return m_origin; }
    Geodetic originGeodetic() const { return m_geo; }

private:
    Eigen::Vector3d m_origin = Eigen::Vector3d::Zero();
    Eigen::Matrix3d m_rot = Eigen::Matrix3d::Identity();
    Geodetic m_geo;
};

constexpr double kDeg = 0.017453292519943295;  ///< radians per degree

}  // namespace lwb::core::calib
