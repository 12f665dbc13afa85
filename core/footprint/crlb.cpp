#include "core/footprint/crlb.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace lwb::core::footprint {

CrlbResult crlbClosedForm(double amplitudeDn, double sigmaMajor, double sigmaMinor, double backgroundDn,
                          const CameraParams& camera, bool pixelIntegrated) {
    CrlbResult r;
    const double add = pixelIntegrated ? 1.0 / 12.0 : 0.0;
    const double s1 = std::sqrt(sigmaMajor * sigmaMajor + add), s2 = std::sqrt(sigmaMinor * sigmaMinor + add);
    const double g = camera.gainEPerDn;
    // Total spot electrons: the amplitude of the point-sampled model times its area.
    const double N = amplitudeDn * 2 * M_PI * (pixelIntegrated ? sigmaMajor * sigmaMinor : s1 * s2) * g;
    const double b = std::max(0.0, backgroundDn) * g + camera.readNoiseE * camera.readNoiseE;
    if (!(N > 0) || !std::isfinite(N)) return r;
    const double tau = 2 * M_PI * s1 * s2 * b / N;
    const double k = 1 + 4 * tau + std::sqrt(2 * tau / (1 + 4 * tau));
    r.varMajor = s1 * s1 / N * k;
    r.varMinor = s2 * s2 / N * k;
    r.radialPx = std::sqrt(r.varMajor + r.varMinor);
    r.ok = std::isfinite(r.radialPx);
    return r;
}

double spotPixelDerivatives(const GaussModel& m, int x, int y, int supersample, double d[6]) {
    const int s = std::max(1, supersample);
    double mu = 0;
    for (int k = 0; k < 6; ++k) d[k] = 0;
    for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
            const double dx = x - 0.5 + (i + 0.5) / s - m.x0, dy = y - 0.5 + (j + 0.5) / s - m.y0;
            const double e = std::exp(-0.5 * (m.a * dx * dx + 2 * m.b * dx * dy + m.c * dy * dy));
            const double gg = m.amplitude * e;
            mu += gg;
            d[0] += e;
            d[1] += gg * (m.a * dx + m.b * dy);
            d[2] += gg * (m.b * dx + m.c * dy);
            d[3] += -0.5 * gg * dx * dx;
            d[4] += -gg * dx * dy;
            d[5] += -0.5 * gg * dy * dy;
        }
    const double inv = 1.0 / (s * s);
    for (int k = 0; k < 6; ++k) d[k] *= inv;
    return mu * inv;
}

CrlbResult crlbFisher(const GaussModel& m, int width, int height, const CameraParams& camera, int supersample) {
    CrlbResult r;
    using Vec7 = Eigen::Matrix<double, 7, 1>;
    Eigen::Matrix<double, 7, 7> F = Eigen::Matrix<double, 7, 7>::Zero();
    const double g = camera.gainEPerDn, rn2 = camera.readNoiseE * camera.readNoiseE;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double dd[6];
            const double mu = spotPixelDerivatives(m, x, y, supersample, dd) + m.bg0;
            Vec7 d;
            d << dd[0], dd[1], dd[2], dd[3], dd[4], dd[5], 1.0;
            F += (g * g / (g * std::max(mu, 0.0) + rn2)) * d * d.transpose();
        }
    const Eigen::Matrix<double, 7, 7> C = F.inverse();
    if (!C.allFinite()) return r;
    // Principal-axis split of the 2×2 position block.
    const double vxx = C(1, 1), vyy = C(2, 2), vxy = C(1, 2);
    const double tr = vxx + vyy, disc = std::sqrt(std::max(0.0, 0.25 * (vxx - vyy) * (vxx - vyy) + vxy * vxy));
    r.varMajor = 0.5 * tr + disc;
    r.varMinor = 0.5 * tr - disc;
    r.radialPx = std::sqrt(tr);
    r.ok = tr > 0 && std::isfinite(tr);
    return r;
}

}  // namespace lwb::core::footprint
