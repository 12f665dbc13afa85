#pragma once
// Gaussian spot fit, paper 000 ("Wu") and its extensions, each stage selectable:
//   1. Wu: f·ln f linear least squares by QR on the thresholded domain (eq. 2–8). With
//      xyTerm=false it is the paper's 5-column system (no tilt); with xyTerm=true the f·xy
//      column is added so the fitted ellipse can tilt.
//   2. Guo: the same system re-weighted with the model instead of the noisy data, iterated.
//   3. LM: Levenberg–Marquardt refinement of a rotated Gaussian + background plane on a window
//      around the spot, with residuals weighted by their expected variance, then re-weighted
//      robustly (Cauchy) so that ground features do not pull the centre.
#include <opencv2/core.hpp>
#include <string>

#include "core/footprint/segment.hpp"
#include "core/footprint/spot.hpp"

namespace lwb::core::footprint {

struct GaussParams {
    bool xyTerm = true;          ///< add the f·xy column (tilt); false = the paper's system
    int guoIterations = 3;       ///< model-weighted passes after the first solve (0 = paper)
    bool lmRefine = true;        ///< Levenberg–Marquardt refinement (false = paper / Guo only)
    int lmMaxIterations = 20;    ///< LM iteration cap
    double lmTolerancePx = 1e-3; ///< LM stops when a step moves the centre less than this (px)
    /// LM also stops when a step moves the centre less than this fraction of its uncertainty
    /// (uncertainty_px at the start), and takes that step unevaluated; 0 = off
    double lmToleranceFraction = 0.1;
    /// LM stops only when the step also changes the amplitude and the shape (a, c, and b against
    /// √(ac)) by less than this fraction of their values
    double lmToleranceShape = 0.01;
    double lmMaxMovePx = 3.0;    ///< LM results further than this from the log fit are not kept (px)
    double lmMaxShapeChange = 2.0; ///< nor those whose major σ or σ1·σ2 changed by more than this factor
    bool noiseWeights = true;    ///< LM weights 1/(photon + read + ground-texture variance)
    /// The ground counts as textured when the background σ exceeds the camera's photon + read σ
    /// at that level by this factor. Textured ground gets a tighter window and robust passes
    /// (ground structure under a wide window pulls the centre); photon-limited ground gets a
    /// wide window and plain LM (every pixel carries information).
    double texturedRatio = 1.5;
    double lmWindowSigmas = 3.0;          ///< LM window half-width (major-axis σ), photon-limited
    double lmWindowSigmasTextured = 1.75; ///< the same on textured ground
    int lmMinHalfWidth = 3;      ///< LM window half-width lower bound (px)
    /// Textured ground: LM on the differences of neighbouring pixels instead of the pixels. Real
    /// ground's red spectrum makes its pixel errors correlated; a difference whitens it (close to
    /// generalised least squares for that correlation).
    bool differenceFit = true;
    double lmWindowSigmasDifference = 2.5; ///< LM window for the difference fit (major-axis σ)
    /// uncertainty_px from the shot's own ground (issue 32): the fit's centre templates (the
    /// rows of (JᵀWJ)⁻¹JᵀW, through the differences for the difference fit) applied to the
    /// covariance of the ground measured in this ROI (the autocovariance of the residual field
    /// img − model over the ROI, corrected for its overlap at each lag) plus the photon and read
    /// noise: a sandwich covariance. false = the quick estimate below (before issue 32).
    bool uncertaintyFromGround = true;
    /// The sandwich's one calibrated factor, on the square root of its ground part, for fits with
    /// the Cauchy loss (textured ground) only: the robust fit ignores outlying ground (edges,
    /// bright objects) more than its final weights, which the linear sandwich uses, say. Calibrated
    /// for 63.2 % coverage on photo ground cut from one photograph (aero1, eval seed 11); plain
    /// least-squares fits take the sandwich as it is.
    double uncertaintyScale = 0.86;
    /// radius95_px = this × uncertainty_px: the radius that holds the true centre in 95 % of the
    /// shots. A circular Gaussian error would give 1.7308 (2.45 σ per axis); the centre's error on
    /// real ground is heavier-tailed (edges, bright objects), and the factor is calibrated on the
    /// same photograph as uncertaintyScale.
    double radius95Factor = 2.05;
    /// The quick estimate: the LM covariance (independent pixels) plus, in quadrature,
    /// scale·(ground texture σ of a neighbour difference)·σ/A. It sets LM's stop
    /// (lmToleranceFraction) and, with uncertaintyFromGround off, uncertainty_px. Scales
    /// calibrated for ≈ 63 % coverage on the photo simulator (it misses elsewhere: issue 32).
    double uncertaintyTextureScale = 2.0;          ///< after the difference fit
    double uncertaintyTextureScalePixelFit = 4.0;  ///< after the pixel fit (faint texture)
    double uncertaintyDeadband = 0.1;              ///< texture counts beyond (1 + this)·photon part
    bool robustLoss = true;      ///< textured ground: Cauchy loss instead of least squares
    double robustScale = 1.5;    ///< Cauchy scale in residual σ
    /// When the domain's log-intensity is not peaked (brighter ground joined the domain), the log
    /// fit is tried again on the spot's core: the domain pixels joined to the peak (4-connected)
    /// at or above this fraction of the domain's brightest pixel above the background. 0 =
    /// straight to the moments.
    double coreFraction = 0.3;
};

/// A rotated Gaussian: amplitude·exp(−½[a·dx² + 2b·dx·dy + c·dy²]), dx = x − x0, dy = y − y0.
struct GaussModel {
    double amplitude = 0, x0 = 0, y0 = 0;
    double a = 0, b = 0, c = 0;  ///< inverse covariance (1/px²)
    double bg0 = 0, bgX = 0, bgY = 0;  ///< background plane bg0 + bgX·(x − x0) + bgY·(y − y0)
};

struct GaussResult {
    SpotFit fit;
    GaussModel model;
    std::string stage;   ///< stage that produced the result: "wu", "guo", "moments" or "lm"
    std::string note;    ///< e.g. why LM was not kept
    bool fallbackStart = false;  ///< the log fit was not peaked; LM started from moments (doubtful)
    bool coreStart = false;      ///< the domain's log fit was not peaked; its core's was (doubtful)
};

/// Fits the spot of a CV_32FC1 ROI on the given domain. background/noise from
/// estimateBackground; camera for the noise weights.
GaussResult fitGauss(const cv::Mat& roi, const SpotDomain& domain, double background, double noise,
                     const GaussParams& params = {}, const CameraParams& camera = {});


}  // namespace lwb::core::footprint
