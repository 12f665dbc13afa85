#pragma once
// Types shared by the footprint spot methods (gcm, tefm, gauss).
#include <cmath>
#include <string>

namespace lwb::core::footprint {

/// Shape and quality of one fitted spot, in ROI pixel coordinates (x = column, y = row,
/// pixel centres at integers, origin at the centre of the ROI's top-left pixel).
///
/// Axis convention (paper 000's σx, σy, C and θ): the spot's two principal axes are split
/// into the one nearer the x axis ("x axis of the spot") and the other. tiltRad is the
/// angle of the x-near axis from +x, in (−45°, 45°]; sigmaX is the spread along it and
/// sigmaY along the other; axisRatio = sigmaX / sigmaY, so it is > 1 when the long axis
/// lies near x (the paper's good-spot range C ∈ (1, 1.5)) and < 1 when it lies near y.
struct SpotFit {
    bool ok = false;
    std::string error;          ///< why the fit failed (when !ok)
    double x = 0, y = 0;        ///< centre (px)
    double sigmaX = 0;          ///< spread along the x-near principal axis (px; σ for gauss)
    double sigmaY = 0;          ///< spread along the other principal axis (px)
    double axisRatio = 0;       ///< sigmaX / sigmaY
    double tiltRad = 0;         ///< angle of the x-near principal axis from +x (rad)
    double majorAxisPx = 0;     ///< full major-axis length at the 1/e² contour (px); 4σ for a Gaussian
    double minorAxisPx = 0;     ///< full minor-axis length at the same contour (px)
    double eccentricity = 0;    ///< sqrt(1 − (minor/major)²)
    double areaPx = 0;          ///< pixels in the spot domain
    double amplitude = 0;       ///< peak above background (DN)
    double background = 0;      ///< background under the spot (DN)
    double mse = 0;             ///< paper 000 eq. 8: ‖A − B·C‖²/N with f normalised to unit sum
    double snr = 0;             ///< amplitude / background noise σ
    double uncertaintyPx = 0;   ///< 1-σ radial position uncertainty sqrt(var x + var y) (px)
    /// The centre's covariance (px²) that uncertaintyPx comes from: for the Gaussian fit, the
    /// sandwich of the fit's templates with the shot's own ground texture (docs/footprint-accuracy.md);
    /// NaN where the method gives none
    double covXX = NAN, covXY = NAN, covYY = NAN;
    /// Radius holding the true centre in 95 % of shots (px); NaN where the method gives none
    double radius95Px = NAN;
    int iterations = 0;         ///< solver iterations used (Guo + LM for gauss)
};

/// Camera model for noise weights, the simulator and the Cramér–Rao bound.
struct CameraParams {
    double gainEPerDn = 2.0;       ///< electrons per DN
    double readNoiseE = 20.0;      ///< read noise (e⁻ rms)
    double saturationDn = 16383;   ///< full scale (14-bit data)
};

/// Derives sigmaX/sigmaY/axisRatio/tilt/majorAxis/eccentricity from a 2×2 spread matrix
/// (covariance for Gaussians, or the second moments of a shape). sizeFactor turns the major
/// σ into majorAxisPx (4 for the 1/e² diameter of a Gaussian).
void setShapeFromCovariance(double sxx, double sxy, double syy, double sizeFactor, SpotFit* fit);

}  // namespace lwb::core::footprint
