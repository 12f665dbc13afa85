#pragma once
// Cramér–Rao lower bound on the spot centre for photon (Poisson) + read noise.
#include "core/footprint/gauss_fit.hpp"
#include "core/footprint/spot.hpp"

namespace lwb::core::footprint {

struct CrlbResult {
    bool ok = false;
    double varMajor = 0, varMinor = 0;  ///< px², along the spot's principal axes
    double radialPx = 0;                ///< sqrt(var x + var y): the bound on the RMS radial error
};

/// Closed form of Rieger & Stallinga (2014), per principal axis:
///   Var ≈ (σa²/N)(1 + 4τ + √(2τ/(1+4τ))),  τ = 2π σa,1 σa,2 (b + σr²)/N,
/// N spot electrons, b background electrons per pixel, σr read noise (e⁻). sigmaMajor/Minor
/// are the spot's σ (px); pixelIntegrated adds the 1/12 px² of pixel integration (pass false
/// for σ fitted with a point-sampled model, which already includes it).
CrlbResult crlbClosedForm(double amplitudeDn, double sigmaMajor, double sigmaMinor, double backgroundDn,
                          const CameraParams& camera, bool pixelIntegrated);

/// The spot part of pixel (x, y) of a model, integrated over the pixel with supersample²
/// points: returns amplitude·(mean of exp) and fills d with its derivatives by amplitude, x0,
/// y0, a, b, c (the background's are 1 and, for a plane, dx, dy). Shared by the Fisher bounds.
double spotPixelDerivatives(const GaussModel& m, int x, int y, int supersample, double d[6]);

/// Numerical bound: Fisher information I = Σ_k g²(∂μ_k/∂θ)(∂μ_k/∂θ)ᵀ/(g·μ_k + σr²) of a
/// pixel-integrated rotated Gaussian on a flat background (parameters amplitude, x0, y0, a, b, c,
/// background) over a width×height ROI; `supersample`² points per pixel for the integral.
CrlbResult crlbFisher(const GaussModel& spot, int width, int height, const CameraParams& camera,
                      int supersample = 4);

}  // namespace lwb::core::footprint
