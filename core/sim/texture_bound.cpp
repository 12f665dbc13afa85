#include "core/sim/texture_bound.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/footprint/crlb.hpp"
#include "core/common/rng.hpp"
#include "core/sim/terrain_photo.hpp"

namespace lwb::core::sim {

double GroundCorrelation::at(int dx, int dy) const {
    if (dy < 0) {  // ρ(dx, dy) = ρ(−dx, −dy)
        dy = -dy;
        dx = -dx;
    }
    if (std::abs(dx) > maxLag || dy > maxLag) return 0;
    return rho[size_t(dy + maxLag) * size_t(2 * maxLag + 1) + size_t(dx + maxLag)];
}

GroundCorrelation photoGroundCorrelation(int patches, int maxLag, uint64_t seed) {
    GroundCorrelation g;
    const TerrainPhotos& photos = terrainPhotos();
    if (!photos.ok) {
        g.error = photos.error;
        return g;
    }
    if (patches < 1 || maxLag < 0) {
        g.error = "at least one patch and a lag of 0 or more are needed";
        return g;
    }
    g.maxLag = maxLag;
    const int side = 2 * maxLag + 1, n = 2 * maxLag + 2;  // patches just larger than the lags
    std::vector<double> sum(size_t(side) * side, 0.0), count(size_t(side) * side, 0.0);
    Rng rng(seed);
    for (int k = 0; k < patches; ++k) {
        const cv::Mat p = terrainPatch(photos, n, n, 0.0, 1.0, rng);
        const double mean = cv::mean(p)[0];
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const double v = p.at<float>(y, x) - mean;
                for (int dy = 0; dy <= maxLag && y + dy < n; ++dy)
                    for (int dx = -maxLag; dx <= maxLag; ++dx) {
                        if (x + dx < 0 || x + dx >= n) continue;
                        const size_t i = size_t(dy + maxLag) * side + size_t(dx + maxLag);
                        sum[i] += v * (p.at<float>(y + dy, x + dx) - mean);
                        count[i] += 1;
                    }
            }
    }
    g.rho.assign(size_t(side) * side, 0.0);
    const size_t zero = size_t(maxLag) * side + size_t(maxLag);
    const double r0 = sum[zero] / count[zero];
    if (!(r0 > 0)) {
        g.error = "the ground patches have no variance";
        return g;
    }
    for (size_t i = 0; i < sum.size(); ++i)
        if (count[i] > 0) g.rho[i] = sum[i] / count[i] / r0;
    g.ok = true;
    return g;
}

TextureBound textureBound(const FootprintSimTruth& t, int width, int height, const footprint::CameraParams& camera,
                          const GroundCorrelation& rho, int window) {
    TextureBound b;
    if (!rho.ok || !t.hasSpot || window < 3 || !(t.sigmaMajor > 0) || !(t.sigmaMinor > 0)) return b;
    const footprint::GaussModel m = truthModel(t);
    const int cx = static_cast<int>(std::lround(t.x)), cy = static_cast<int>(std::lround(t.y));
    const int xa = std::clamp(cx - window / 2, 0, std::max(0, width - window));
    const int ya = std::clamp(cy - window / 2, 0, std::max(0, height - window));
    const int xb = std::min(width - 1, xa + window - 1), yb = std::min(height - 1, ya + window - 1);
    std::vector<int> px, py;
    for (int y = ya; y <= yb; ++y)
        for (int x = xa; x <= xb; ++x) {
            px.push_back(x);
            py.push_back(y);
        }
    const int n = static_cast<int>(px.size());
    const double g = camera.gainEPerDn, rn = camera.readNoiseE / camera.gainEPerDn;
    Eigen::MatrixXd J(n, 9);
    Eigen::VectorXd white(n);
    for (int k = 0; k < n; ++k) {
        // The pixel-integrated spot (3×3 points a pixel, as the eval's photon bound), + a plane.
        double d[6];
        const double spot = footprint::spotPixelDerivatives(m, px[k], py[k], 3, d);
        J.row(k) << d[0], d[1], d[2], d[3], d[4], d[5], 1, px[k] - t.x, py[k] - t.y;
        white(k) = std::max(t.groundMean + spot, 0.0) / g + rn * rn;
    }
    Eigen::MatrixXd S(n, n);
    const double tex2 = t.textureRms * t.textureRms;
    for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l) S(k, l) = tex2 * rho.at(px[l] - px[k], py[l] - py[k]) + (k == l ? white(k) : 0.0);
    const Eigen::MatrixXd fisher = J.transpose() * S.ldlt().solve(J);
    const Eigen::MatrixXd fisherWhite = J.transpose() * white.cwiseInverse().asDiagonal() * J;
    const Eigen::MatrixXd cov = fisher.ldlt().solve(Eigen::MatrixXd::Identity(9, 9));
    const Eigen::MatrixXd covWhite = fisherWhite.ldlt().solve(Eigen::MatrixXd::Identity(9, 9));
    b.radialPx = std::sqrt(M_PI * (cov(1, 1) + cov(2, 2))) / 2;
    b.whiteRadialPx = std::sqrt(M_PI * (covWhite(1, 1) + covWhite(2, 2))) / 2;
    b.ok = std::isfinite(b.radialPx) && std::isfinite(b.whiteRadialPx);
    return b;
}

}  // namespace lwb::core::sim
