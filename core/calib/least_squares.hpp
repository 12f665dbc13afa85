#pragma once
// A small dense Levenberg–Marquardt solver (Marquardt's diagonal scaling) shared by the
// calibration fits: detector-array Gaussian surface, waveform decomposition, pointing and
// range calibration. The caller supplies whitened residuals r(p) and their Jacobian; the
// solver minimises Σ r² and keeps every accepted iterate for convergence plots.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace lwb::core::calib {

struct LmProblem {
    int parameters = 0;
    /// Fills r (whitened residuals) and, when J is not null, the Jacobian ∂r/∂p. Returns false
    /// when p lies outside the model's domain (the step is then rejected and damped).
    std::function<bool(const Eigen::VectorXd& p, Eigen::VectorXd* r, Eigen::MatrixXd* J)> evaluate;
};

struct LmOptions {
    int maxIterations = 100;      ///< accepted steps at most (1..10000)
    double costTolerance = 1e-12; ///< converged when a step lowers Σr² by less than this fraction
    double costToleranceAbs = 0;  ///< … or by less than this much (Δχ² ≪ 1 is statistically nothing)
    double stepTolerance = 1e-10; ///< converged when ‖J·δ‖ < this · (‖r‖ + 1e-300)
    double lambda0 = 1e-3;        ///< starting damping (0 = start as Gauss–Newton)
};

struct LmIterate {
    int iteration = 0;            ///< 0 = the start point
    double cost = 0;              ///< Σ r² after the step
    double lambda = 0;            ///< damping used for the step
    Eigen::VectorXd params;
};

struct LmOutcome {
    bool ok = false;              ///< false: the start point could not be evaluated
    std::string error;
    bool converged = false;       ///< false: stopped at maxIterations or could not descend further
    Eigen::VectorXd params;
    Eigen::VectorXd residuals;    ///< at params
    Eigen::MatrixXd jacobian;     ///< at params
    double cost = 0;              ///< Σ r² at params
    std::vector<LmIterate> history;  ///< start point and every accepted step
};

/// Minimises Σ r(p)² from `start`. Never throws; deterministic.
LmOutcome levenbergMarquardt(const LmProblem& problem, const Eigen::VectorXd& start, const LmOptions& options = {});

/// Forward-difference helper: fills column j of J from r(p + h_j e_j) − r(p). False when an
/// evaluation falls outside the domain.
bool numericJacobian(const std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd*)>& f, const Eigen::VectorXd& p,
                     const Eigen::VectorXd& r0, const Eigen::VectorXd& steps, Eigen::MatrixXd* J, bool central = true);

/// Covariance (JᵀJ)⁻¹ by SVD with the reciprocal condition number; false when J is rank
/// deficient (rcond below `minRcond`) after column scaling.
bool covarianceFromJacobian(const Eigen::MatrixXd& J, double minRcond, Eigen::MatrixXd* cov, double* rcond,
                            Eigen::VectorXd* weakest = nullptr);

}  // namespace lwb::core::calib
