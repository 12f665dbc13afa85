#include "core/calib/geodesy.hpp"

#include <cmath>

namespace lwb::core::calib {

namespace {
constexpr double kE2 = kWgs84F * (2 - kWgs84F);  // first eccentricity squared
}

Eigen::Vector3d geodeticToEcef(double lat, double lon, double h) {
    const double s = std::sin(lat), c = std::cos(lat);
    const double n = kWgs84A / std::sqrt(1 - kE2 * s * s);
    return {(n + h) * c * std::cos(lon), (n + h) * c * std::sin(lon), (n * (1 - kE2) + h) * s};
}

Geodetic ecefToGeodetic(const Eigen::Vector3d& p) {
    Geodetic g;
    const double x = p.x(), y = p.y(), z = p.z();
    const double r = std::hypot(x, y);
    g.lonRad = std::atan2(y, x);
    const double b = kWgs84A * (1 - kWgs84F);
    const double ep2 = (kWgs84A * kWgs84A - b * b) / (b * b);
    // Bowring's start, then Newton-like refinement of the latitude.
    const double th = std::atan2(z * kWgs84A, r * b);
    double lat = std::atan2(z + ep2 * b * std::pow(std::sin(th), 3), r - kE2 * kWgs84A * std::pow(std::cos(th), 3));
    double h = 0;
    for (int i = 0; i < 5; ++i) {
        const double s = std::sin(lat);
        const double n = kWgs84A / std::sqrt(1 - kE2 * s * s);
        h = std::fabs(std::cos(lat)) > 1e-10 ? r / std::cos(lat) - n : std::fabs(z) - b;
        lat = std::atan2(z, r * (1 - kE2 * n / (n + h)));
    }
    g.latRad = lat;
    g.h = h;
    return g;
}

Eigen::Matrix3d ecefToEnuRotation(double lat, double lon) {
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    Eigen::Matrix3d r;
    r << -so, co, 0,  //
        -sl * co, -sl * so, cl,  //
        cl * co, cl * so, sl;
    return r;
}

LocalFrame::LocalFrame(double lat, double lon, double h)
    : m_origin(geodeticToEcef(lat, lon, h)), m_rot(ecefToEnuRotation(lat, lon)) {
    m_geo.latRad = lat;
    m_geo.lonRad = lon;
    m_geo.h = h;
}

}  // namespace lwb::core::calib
