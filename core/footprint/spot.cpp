#include "core/footprint/spot.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lwb::core::footprint {

void setShapeFromCovariance(double sxx, double sxy, double syy, double sizeFactor, SpotFit* fit) {
    // Eigen-decomposition of [[sxx, sxy], [sxy, syy]].
    const double tr = sxx + syy;
    const double det = sxx * syy - sxy * sxy;
    const double disc = std::sqrt(std::max(0.0, 0.25 * tr * tr - det));
    const double l1 = 0.5 * tr + disc;   // larger eigenvalue
    const double l2 = std::max(0.5 * tr - disc, 0.0);
    double phi = 0.5 * std::atan2(2 * sxy, sxx - syy);  // angle of the l1 axis from +x, (−90°, 90°]
    double sAlong = std::sqrt(l1), sAcross = std::sqrt(l2);
    // Use the principal axis nearer x: if the major axis is more than 45° from x, the x-near
    // axis is the minor one, rotated by 90°.
    if (phi > M_PI / 4 || phi <= -M_PI / 4) {
        phi += phi > 0 ? -M_PI / 2 : M_PI / 2;
        std::swap(sAlong, sAcross);
    }
    fit->tiltRad = phi;
    fit->sigmaX = sAlong;
    fit->sigmaY = sAcross;
    fit->axisRatio = sAcross > 0 ? sAlong / sAcross : INFINITY;
    const double major = std::sqrt(l1), minor = std::sqrt(l2);
    fit->majorAxisPx = sizeFactor * major;
    fit->minorAxisPx = sizeFactor * minor;
    fit->eccentricity = major > 0 ? std::sqrt(std::max(0.0, 1 - (minor * minor) / (major * major))) : 0;
}

}  // namespace lwb::core::footprint
