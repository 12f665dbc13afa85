#include "core/slr/solar.hpp"

#include <algorithm>
#include <cmath>

namespace lwb::core::slr {

namespace {
constexpr double kDeg = M_PI / 180.0;
}

double sunElevationDeg(double mjdUtc, double latDeg, double lonDeg) {
    // Days from J2000.0 (UT is close enough to TT here: 69 s moves the Sun by 0.0008°).
    const double n = mjdUtc - 51544.5;
    const double L = std::fmod(280.460 + 0.9856474 * n, 360.0);
    const double g = std::fmod(357.528 + 0.9856003 * n, 360.0) * kDeg;
    const double lambda = (L + 1.915 * std::sin(g) + 0.020 * std::sin(2 * g)) * kDeg;
    const double eps = (23.439 - 0.0000004 * n) * kDeg;
    const double ra = std::atan2(std::cos(eps) * std::sin(lambda), std::cos(lambda));
    const double dec = std::asin(std::sin(eps) * std::sin(lambda));
    // Greenwich mean sidereal time (hours) and the local hour angle.
    const double gmstH = std::fmod(18.697374558 + 24.06570982441908 * n, 24.0);
    const double H = gmstH * 15.0 * kDeg + lonDeg * kDeg - ra;
    const double phi = latDeg * kDeg;
    const double s = std::sin(phi) * std::sin(dec) + std::cos(phi) * std::cos(dec) * std::cos(H);
    return std::asin(std::clamp(s, -1.0, 1.0)) / kDeg;
}

void geodeticFromEcef(double x, double y, double z, double* latDeg, double* lonDeg, double* heightM) {
    const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f);
    const double p = std::hypot(x, y);
    double lat = std::atan2(z, p * (1 - e2)), h = 0;
    for (int i = 0; i < 6; ++i) {
        const double N = a / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat));
        h = p / std::max(1e-9, std::cos(lat)) - N;
        lat = std::atan2(z, p * (1 - e2 * N / (N + h)));
    }
    *latDeg = lat / kDeg;
    *lonDeg = std::atan2(y, x) / kDeg;
    *heightM = h;
}

}  // namespace lwb::core::slr
