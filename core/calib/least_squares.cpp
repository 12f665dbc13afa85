#include "core/calib/least_squares.hpp"

#include <algorithm>
#include <cmath>

namespace lwb::core::calib {

LmOutcome levenbergMarquardt(const LmProblem& problem, const Eigen::VectorXd& start, const LmOptions& options) {
    LmOutcome out;
    const int n = problem.parameters;
    Eigen::VectorXd p = start, r;
    Eigen::MatrixXd J;
    if (start.size() != n || !problem.evaluate(p, &r, &J) || !r.allFinite() || !J.allFinite()) {
        out.error = "the model cannot be evaluated at the start point";
        return out;
    }
    double cost = r.squaredNorm();
    double lambda = options.lambda0;
    out.history.push_back({0, cost, 0.0, p});
    bool converged = false;
    int it = 0;
    for (; it < options.maxIterations && !converged; ++it) {
        const Eigen::MatrixXd jtj = J.transpose() * J;
        const Eigen::VectorXd g = J.transpose() * r;
        Eigen::VectorXd diag = jtj.diagonal().cwiseMax(1e-300);
        bool accepted = false;
        for (int tries = 0; tries < 40; ++tries) {
            Eigen::MatrixXd a = jtj;
            a.diagonal() += lambda * diag;
            // A tiny ridge keeps the solve defined when a column is (nearly) zero.
            a.diagonal() += Eigen::VectorXd::Constant(n, 1e-15 * std::max(1.0, diag.maxCoeff()));
            const Eigen::VectorXd delta = -a.ldlt().solve(g);
            if (!delta.allFinite()) {
                lambda = std::max(lambda * 10, 1e-6);
                continue;
            }
            const Eigen::VectorXd trial = p + delta;
            Eigen::VectorXd rt;
            Eigen::MatrixXd Jt;
            if (!problem.evaluate(trial, &rt, &Jt) || !rt.allFinite() || !Jt.allFinite()) {
                lambda = std::max(lambda * 10, 1e-6);
                continue;
            }
            const double ct = rt.squaredNorm();
            if (ct <= cost) {
                const double jd = (J * delta).norm();
                converged = (cost - ct) <= std::max(options.costTolerance * cost, options.costToleranceAbs) || jd < options.stepTolerance * (std::sqrt(cost) + 1e-300);
                p = trial;
                r = rt;
                J = Jt;
                cost = ct;
                out.history.push_back({it + 1, cost, lambda, p});
                lambda = lambda * 0.1;
                if (lambda < 1e-12) lambda = 0;
                accepted = true;
                break;
            }
            lambda = std::max(lambda * 10, 1e-6);
        }
        if (!accepted) {
            converged = true;  // no descent possible: at the minimum within precision
            break;
        }
    }
    out.ok = true;
    out.converged = converged;
    out.params = p;
    out.residuals = r;
    out.jacobian = J;
    out.cost = cost;
    return out;
}

bool numericJacobian(const std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd*)>& f, const Eigen::VectorXd& p,
                     const Eigen::VectorXd& r0, const Eigen::VectorXd& steps, Eigen::MatrixXd* J, bool central) {
    J->resize(r0.size(), p.size());
    for (int j = 0; j < p.size(); ++j) {
        Eigen::VectorXd q = p, rp, rm;
        q(j) += steps(j);
        if (!f(q, &rp) || rp.size() != r0.size()) return false;
        if (central) {
            q(j) = p(j) - steps(j);
            if (!f(q, &rm) || rm.size() != r0.size()) return false;
            J->col(j) = (rp - rm) / (2 * steps(j));
        } else {
            J->col(j) = (rp - r0) / steps(j);
        }
    }
    return true;
}

bool covarianceFromJacobian(const Eigen::MatrixXd& J, double minRcond, Eigen::MatrixXd* cov, double* rcond,
                            Eigen::VectorXd* weakest) {
    const int n = static_cast<int>(J.cols());
    if (J.rows() < n || n == 0) {
        if (rcond) *rcond = 0;
        return false;
    }
    Eigen::VectorXd scale(n);
    for (int j = 0; j < n; ++j) {
        const double s = J.col(j).norm();
        scale(j) = s > 0 ? s : 1.0;
    }
    const Eigen::MatrixXd js = J * scale.cwiseInverse().asDiagonal();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(js, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd s = svd.singularValues();
    const double rc = s(0) > 0 ? s(n - 1) / s(0) : 0;
    if (rcond) *rcond = rc;
    if (weakest) *weakest = svd.matrixV().col(n - 1);
    if (!(rc >= minRcond)) return false;
    // (JᵀJ)⁻¹ = D⁻¹ V S⁻² Vᵀ D⁻¹ with D the column scales.
    const Eigen::MatrixXd v = svd.matrixV();
    const Eigen::MatrixXd inner = v * s.array().square().inverse().matrix().asDiagonal() * v.transpose();
    *cov = scale.cwiseInverse().asDiagonal() * inner * scale.cwiseInverse().asDiagonal();
    return true;
}

}  // namespace lwb::core::calib
