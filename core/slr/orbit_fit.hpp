#pragma once
// The range of a circular orbit past a station on the rotating Earth, fitted to a pass's own
// times of flight (issue 43, LEO passes without a prediction). The orbit-arc trend of oc.cpp is
// linear in TOF^2 with free coefficients for the Earth's rotation (up to 8 of them), which a
// pass of 10–30 returns cannot pin down: its normal points then carry 5–20 mm of the noise's
// share in those coefficients where the geometry allows 0.02–1 mm (docs/slr-detection.md). This
// model has the geometry's own parameters: the orbit's radius (Kepler's rate follows it), its
// plane and phase (a rotation) and a range bias, the station's position
// given (the ILRS table's: without it the station's latitude and radius would join the
// parameters, and the search below finds the minimum on too few passes). The instantaneous
// range is modelled (the light time shifts the phase only).
//
// The fit (the model is "sloppy": over a short arc several parameter combinations change the
// range by picoseconds, and a Levenberg–Marquardt from a rough start crawls along them): for a
// trial mean motion n, the squared range is linear in the satellite's two in-plane
// vectors (sat = R (cos(n s) a + sin(n s) b), R Kepler's for n), whose least-squares values,
// projected onto the nearest orthonormal pair, start a fit of the orientation and bias alone;
// n is searched on a grid within 20 % of the arc's rate, the best local minima refined by
// golden section; the whole model then refined from the best. (A free rate, for an eccentric
// orbit, was tried: on the simulated passes it let a wrong minimum through, one NP 57 mm off.)
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace lwb::core::slr {

struct CircularOrbitParams {
    Eigen::Vector3d stationEcef{0, 0, 0};  ///< the station (m, ECEF; any longitude: the orbit's frame absorbs it)
    double arcRate = NAN;           ///< the apparent angular rate of the pass (rad/s): the search's centre
    int maxIterations = 200;        ///< Levenberg–Marquardt iterations of the final fit (1..10000)
    int robustSteps = 2;            ///< Tukey bisquare reweightings after the first fit (0..20; measured on
                                    ///< the sparse passes: 2 keeps the noise points out, more down-weights returns)
};

struct CircularOrbitResult {
    bool ok = false;
    std::string error;
    double radiusM = NAN;           ///< orbit radius
    double meanMotion = NAN;        ///< rad/s
    double biasS = NAN;             ///< range bias (two-way s)
    int parameters = 0;             ///< fitted parameters (for an information criterion)
    double scaleS = NAN;            ///< robust scale (MAD about 0) of the residuals (two-way s)
    std::vector<double> residualS;  ///< observed − model TOF (two-way s), per point
    /// The fit's hat matrix S (row-major n×n: ∂model_i/∂tof_k at the solution, with the robust
    /// weights of the last fit; leastSquaresHat): how each point's time of flight moves the model
    /// at every point (the normal points' precision, postfit.hpp normalPointTrendFactors). Empty
    /// for more than kMaxOrbitHatPoints points.
    std::vector<double> hat;
};

/// CircularOrbitResult::hat is made for at most this many points (32 MB).
inline constexpr size_t kMaxOrbitHatPoints = 2000;

/// The hat matrix S = J (Jᵀ W J)⁺ Jᵀ W of a least-squares fit whose model has Jacobian J (n×p,
/// at the solution) and weights w (n): δmodel = S δdata to first order. Row-major n×n.
std::vector<double> leastSquaresHat(const Eigen::MatrixXd& J, const Eigen::VectorXd& w);

/// Fits the model to epochs s (seconds from the pass's middle epoch) and two-way TOFs (s), with
/// prior weights w (0 = not used; empty = all 1). Never throws.
CircularOrbitResult fitCircularOrbit(const std::vector<double>& s, const std::vector<double>& tofS,
                                     const std::vector<double>& w, const CircularOrbitParams& p);

}  // namespace lwb::core::slr
