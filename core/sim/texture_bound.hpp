#pragma once
// The Cramér–Rao bound of a footprint spot's centre when the ground's texture is part of the
// noise: the texture taken as a Gaussian random field with the ensemble autocorrelation of the
// photo simulator's ground (core/sim/terrain_photo), plus photon and read noise. The white
// bound (core/footprint/crlb) counts photons alone, and on textured ground it is 3–15 times
// below what any fit reaches; this one says what the texture leaves reachable.
#include <cstdint>
#include <string>
#include <vector>

#include "core/footprint/spot.hpp"
#include "core/sim/footprint_sim.hpp"

namespace lwb::core::sim {

/// Normalised autocorrelation ρ(dx, dy) (ρ(0, 0) = 1) of the photo ground, averaged over
/// `patches` random patches (each at its own zoom, rotation, flip and band), lags up to maxLag.
struct GroundCorrelation {
    bool ok = false;
    std::string error;
    int maxLag = 0;
    std::vector<double> rho;  ///< (2·maxLag + 1)² values, row dy + maxLag, column dx + maxLag
    double at(int dx, int dy) const;  ///< 0 beyond maxLag
};
GroundCorrelation photoGroundCorrelation(int patches, int maxLag, uint64_t seed);

struct TextureBound {
    bool ok = false;
    double radialPx = 0;       ///< expected radial error of an unbiased estimator at the bound, texture + photons
    double whiteRadialPx = 0;  ///< the same with photon + read noise alone
};
/// The bound for the shot's true spot (pixel-integrated Gaussian + plane; 9 parameters) over a window
/// of side `window` px around the truth inside a width × height ROI, the texture of RMS
/// truth.textureRms with correlation rho. Radial error from the covariance C of (x, y):
/// √(π·(Cxx + Cyy))/2, exact for a circular 2-D Gaussian error.
TextureBound textureBound(const FootprintSimTruth& truth, int width, int height, const footprint::CameraParams& camera,
                          const GroundCorrelation& rho, int window = 24);

}  // namespace lwb::core::sim
