#include "core/calib/pointing.hpp"
#include "core/calib/calib_params.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <map>

#include "core/calib/least_squares.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/json.hpp"
#include "core/common/text.hpp"

namespace lwb::core::calib {

Eigen::Vector3d pointingVector(double alpha, double beta) {
    const double sa = std::sin(alpha);
    return {sa * std::cos(beta), sa * std::sin(beta), std::cos(alpha)};
}

void pointingAngles(const Eigen::Vector3d& u, double* alpha, double* beta) {
    const Eigen::Vector3d v = u.normalized();
    *alpha = std::atan2(std::hypot(v.x(), v.y()), v.z());
    *beta = std::atan2(v.y(), v.x());
}

Eigen::Vector3d bodyPointing(const BeamDesign& beam, double dAlpha, double dBeta) {
    return beam.laserToBody.normalized() * pointingVector(beam.alphaRad + dAlpha, beam.betaRad + dBeta);
}

Eigen::Vector3d geolocate(const BeamDesign& beam, const LaserShot& shot, const Eigen::Vector3d& uBody, double dRho) {
    return shot.satEcef + shot.bodyToEcef.normalized() * (beam.offsetBodyM + (shot.rangeM + dRho) * uBody);
}

Eigen::Vector3d geolocate(const BeamDesign& beam, const LaserShot& shot, double dAlpha, double dBeta, double dRho) {
    return geolocate(beam, shot, bodyPointing(beam, dAlpha, dBeta), dRho);
}

ThreeAxisAngles threeAxisAngles(const Eigen::Vector3d& uBody) {
    const Eigen::Vector3d u = uBody.normalized();
    auto ac = [](double c) { return std::acos(std::clamp(c, -1.0, 1.0)); };
    return {ac(u.x()), ac(u.y()), ac(u.z())};
}

namespace {
Eigen::Matrix3d expSo3(const Eigen::Vector3d& w) {
    const double t = w.norm();
    if (t < 1e-300) return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(t, w / t).toRotationMatrix();
}
}  // namespace

Eigen::Matrix3d dualBeamRotation(const BeamDesign& beam1, const BeamDesign& beam2, double r, double a, double b) {
    const Eigen::Vector3d u1 = bodyPointing(beam1, 0, 0), u2 = bodyPointing(beam2, 0, 0);
    const Eigen::Matrix3d r0 = Eigen::Quaterniond::FromTwoVectors(u1, u2).toRotationMatrix();
    Eigen::Vector3d e1 = Eigen::Vector3d::UnitX() - u2.x() * u2;
    if (e1.norm() < 1e-6) e1 = Eigen::Vector3d::UnitY() - u2.y() * u2;
    e1.normalize();
    const Eigen::Vector3d e2 = u2.cross(e1);
    return expSo3(r * e1 + a * e2 + b * u2) * r0;
}

const char* calibModelName(CalibModel m) { return m == CalibModel::DualBeam ? "dual" : "single"; }

std::string validate(const PointingCalibParams& p) {
    CalibParams c;  // the ranges of the schema's rows (calib_params.cpp)
    c.pointing = p;
    return calibSchema().validate(c, "pointing.");
}

double GroundResidual::plan() const { return std::hypot(e, n); }

namespace {

struct BeamIndex {
    int dAlpha = -1, dBeta = -1, dRho = -1;
};

struct Model {
    const std::vector<BeamDesign>* beams = nullptr;
    CalibModel kind = CalibModel::SingleBeam;
    std::vector<BeamIndex> idx;
    int rIdx = -1, aIdx = -1;
    std::vector<std::string> names;

    int add(const std::string& name) {
        names.push_back(name);
        return static_cast<int>(names.size()) - 1;
    }
    static double at(const Eigen::VectorXd& p, int i) { return i >= 0 ? p(i) : 0.0; }
    Eigen::Vector3d uBody(size_t k, const Eigen::VectorXd& p) const {
        const auto& b = *beams;
        if (kind == CalibModel::DualBeam && k == 1) {
            const Eigen::Vector3d u1 = bodyPointing(b[0], at(p, idx[0].dAlpha), at(p, idx[0].dBeta));
            return dualBeamRotation(b[0], b[1], at(p, rIdx), at(p, aIdx), 0.0) * u1;
        }
        return bodyPointing(b[k], at(p, idx[k].dAlpha), at(p, idx[k].dBeta));
    }
    Eigen::Vector3d ground(size_t k, const LaserShot& s, const Eigen::VectorXd& p) const {
        return geolocate((*beams)[k], s, uBody(k, p), at(p, idx[k].dRho));
    }
};

struct PointPrep {
    size_t design = 0;
    Eigen::MatrixXd whiten;   // L⁻¹·P (2×3 or 3×3)
    Eigen::Matrix3d toEnu;
    Eigen::Vector2d along;    // horizontal unit vector of body +X in ENU
};

GroundResidual residualOf(const PointPrep& pp, const Eigen::Vector3d& dEcef) {
    const Eigen::Vector3d d = pp.toEnu * dEcef;
    GroundResidual g;
    g.e = d.x();
    g.n = d.y();
    g.u = d.z();
    g.along = pp.along.x() * d.x() + pp.along.y() * d.y();
    g.across = pp.along.y() * d.x() - pp.along.x() * d.y();
    return g;
}

std::string pointName(const ControlPoint& c, size_t i) {
    std::string s = "control point " + (c.id.empty() ? std::to_string(i + 1) : c.id);
    if (c.line > 0) s += " (line " + std::to_string(c.line) + ")";
    return s;
}

// ---- the stages of calibratePointing ----

// The beam designs: one per id, finite; two for the dual-beam model. "" when fine.
std::string checkBeams(const std::vector<BeamDesign>& beams, const PointingCalibParams& params, std::map<int, size_t>* byId) {
    for (size_t k = 0; k < beams.size(); ++k) {
        const BeamDesign& b = beams[k];
        if (byId->count(b.id)) {
            return "beam " + std::to_string(b.id) + " is designed twice";
        }
        (*byId)[b.id] = k;
        if (!(std::isfinite(b.alphaRad) && std::isfinite(b.betaRad) && b.offsetBodyM.allFinite() &&
              b.laserToBody.coeffs().allFinite() && b.laserToBody.norm() > 0.5)) {
            return "beam " + std::to_string(b.id) + ": design angles, offset or mounting are not finite";
        }
    }
    if (params.model == CalibModel::DualBeam && beams.size() != 2) {
        return "the dual-beam model needs exactly two beam designs (got " + std::to_string(beams.size()) + ")";
    }
    return {};
}

// One control point: plausible geometry and sigmas, its ENU frame, along-track direction and
// whitening (the observation covariance from the control, range, attitude and orbit noise).
// "" when fine.
std::string preparePoint(const ControlPoint& c, size_t i, const BeamDesign& beam, const PointingCalibParams& params,
                         PointPrep* pp) {
    if (!c.shot.satEcef.allFinite() || !c.groundEcef.allFinite() || !std::isfinite(c.shot.rangeM) ||
        !c.shot.bodyToEcef.coeffs().allFinite()) {
        return pointName(c, i) + ": non-finite satellite position, attitude, range or ground point";
    }
    // Plausible geometry: a ground point near the Earth's surface (6340–6400 km from the centre:
    // polar radius 6357 km, equatorial 6378 km, with room for relief) and a satellite at least
    // 10 km above it but within 100 000 km; anything else is a unit or typing error.
    const double rg = c.groundEcef.norm(), rs = c.shot.satEcef.norm();
    if (!(rg > 6.34e6 && rg < 6.40e6)) {
        return pointName(c, i) + ": ground point " + formatDouble(rg / 1000, 6) +
                    " km from the Earth's centre (expected about 6371 km: ECEF metres?)";
    }
    if (!(rs > rg + 1e4 && rs < 1e8)) {
        return pointName(c, i) + ": satellite " + formatDouble(rs / 1000, 6) +
                    " km from the Earth's centre (expected an orbit above the ground point)";
    }
    if (std::fabs(c.shot.bodyToEcef.norm() - 1) > 1e-3) {
        return pointName(c, i) + ": the attitude quaternion is not a unit quaternion (norm " +
                    formatDouble(c.shot.bodyToEcef.norm(), 6) + ")";
    }
    if (!(c.shot.rangeM > 0)) {
        return pointName(c, i) + ": range must be > 0 m";
    }
    const double sh = std::isnan(c.sigmaHorizontalM) ? params.sigmaHorizontalM : c.sigmaHorizontalM;
    const double sv = std::isnan(c.sigmaVerticalM) ? params.sigmaVerticalM : c.sigmaVerticalM;
    if (!(sh > 0 && std::isfinite(sh)) || !(sv > 0 && std::isfinite(sv))) {
        return pointName(c, i) + ": control-point sigmas must be finite and > 0";
    }
    const Geodetic g = ecefToGeodetic(c.groundEcef);
    pp->toEnu = ecefToEnuRotation(g.latRad, g.lonRad);
    const Eigen::Vector3d x = pp->toEnu * (c.shot.bodyToEcef.normalized() * Eigen::Vector3d::UnitX());
    pp->along = Eigen::Vector2d(x.x(), x.y());
    pp->along = pp->along.norm() > 1e-9 ? pp->along.normalized() : Eigen::Vector2d(0, 1);
    // Observation covariance in ECEF.
    const Eigen::Vector3d u =
        (c.shot.bodyToEcef.normalized() * bodyPointing(beam, 0, 0)).normalized();
    Eigen::Matrix3d C = pp->toEnu.transpose() * Eigen::Vector3d(sh * sh, sh * sh, sv * sv).asDiagonal() * pp->toEnu;
    C += params.sigmaRangeM * params.sigmaRangeM * u * u.transpose();
    C += std::pow(c.shot.rangeM * params.sigmaAttitudeRad, 2) * (Eigen::Matrix3d::Identity() - u * u.transpose());
    C += params.sigmaOrbitM * params.sigmaOrbitM * Eigen::Matrix3d::Identity();
    Eigen::MatrixXd P = c.useHeight ? Eigen::MatrixXd(pp->toEnu) : Eigen::MatrixXd(pp->toEnu.topRows(2));
    const Eigen::MatrixXd Cp = P * C * P.transpose();
    Eigen::LLT<Eigen::MatrixXd> llt(Cp);
    if (llt.info() != Eigen::Success) {
        return pointName(c, i) + ": its covariance is not positive definite";
    }
    pp->whiten = llt.matrixL().solve(P);
    return {};
}

// The unknowns of the model: per beam (single) or beam 1 + relative rotation (dual), with range
// biases when solved. "" when fine (beams without points are warned about, single model).
std::string layoutParameters(const std::vector<BeamDesign>& beams, const std::vector<int>& count, const PointingCalibParams& params,
                             Model* m, std::vector<std::string>* warnings) {
    m->beams = &beams;
    m->kind = params.model;
    m->idx.resize(beams.size());
    if (params.model == CalibModel::DualBeam) {
        const std::string b1 = std::to_string(beams[0].id), b2 = std::to_string(beams[1].id);
        if (count[0] == 0) {
            return "dual-beam model: beam " + b1 + " (the reference) has no control points";
        }
        const bool needBeam2 = !params.fixRelativeRotation || params.solveRange;
        if (count[1] == 0 && needBeam2) {
            return "dual-beam model: beam " + b2 +
                        " has no control points, so its relative rotation and range bias are undetermined "
                        "(hold them with fixRelativeRotation and no range solution, or use the single-beam model)";
        }
        m->idx[0].dAlpha = m->add("dalpha_b" + b1);
        m->idx[0].dBeta = m->add("dbeta_b" + b1);
        if (params.solveRange) m->idx[0].dRho = m->add("drho_b" + b1);
        if (!params.fixRelativeRotation) {
            m->rIdx = m->add("rel_r");
            m->aIdx = m->add("rel_a");
        }
        if (params.solveRange) m->idx[1].dRho = m->add("drho_b" + b2);
    } else {
        for (size_t k = 0; k < beams.size(); ++k) {
            if (count[k] == 0) continue;
            const std::string b = std::to_string(beams[k].id);
            m->idx[k].dAlpha = m->add("dalpha_b" + b);
            m->idx[k].dBeta = m->add("dbeta_b" + b);
            if (params.solveRange) m->idx[k].dRho = m->add("drho_b" + b);
        }
        for (size_t k = 0; k < beams.size(); ++k)
            if (count[k] == 0)
                warnings->push_back("beam " + std::to_string(beams[k].id) + " has no control points: not calibrated");
    }
    return {};
}

// The record of every iteration: parameters, chi2, ground residuals and their RMS.
void recordIterations(const std::vector<LmIterate>& history, const std::vector<ControlPoint>& points,
                      const std::vector<PointPrep>& prep, const Model& m, PointingCalibResult& res) {
    for (const LmIterate& it : history) {
        CalibIteration ci;
        ci.iteration = static_cast<int>(res.iterations.size());
        ci.params.assign(it.params.data(), it.params.data() + it.params.size());
        ci.chi2 = it.cost;
        double sp = 0, sh = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const GroundResidual g = residualOf(prep[i], m.ground(prep[i].design, points[i].shot, it.params) - points[i].groundEcef);
            ci.residuals.push_back(g);
            sp += g.e * g.e + g.n * g.n;
            sh += g.u * g.u;
        }
        ci.rmsPlanM = std::sqrt(sp / points.size());
        ci.rmsHeightM = std::sqrt(sh / points.size());
        ci.rms3dM = std::sqrt((sp + sh) / points.size());
        res.iterations.push_back(std::move(ci));
    }
}

// Per control point: residuals before and after, the normalized residual (outliers warned about).
void recordResiduals(const std::vector<ControlPoint>& points, const std::vector<PointPrep>& prep, const Model& m,
                     const Eigen::VectorXd& p, PointingCalibResult& res) {
    for (size_t i = 0; i < points.size(); ++i) {
        ControlPointResidual cr;
        cr.index = i;
        cr.id = points[i].id.empty() ? std::to_string(i + 1) : points[i].id;
        cr.beam = points[i].beam;
        cr.before = res.iterations.front().residuals[i];
        cr.after = res.iterations.back().residuals[i];
        const Eigen::Vector3d d = m.ground(prep[i].design, points[i].shot, p) - points[i].groundEcef;
        cr.normalized = (prep[i].whiten * d).norm();
        const double dims = points[i].useHeight ? 3 : 2;
        if (cr.normalized > 4 * std::sqrt(dims))
            res.warnings.push_back(pointName(points[i], i) + ": residual " + formatDouble(cr.normalized, 3) +
                                   " sigma after calibration (outlier?)");
        res.residuals.push_back(cr);
    }
}

// Beam k's outcome: corrections, calibrated angles, three-axis angles and their sigmas (by
// numeric propagation of the covariance), and the plan shift of its footprint.
BeamCalibration beamOutcome(size_t k, const std::vector<BeamDesign>& beams, int points_k, const Model& m,
                            const PointingCalibParams& params, const Eigen::VectorXd& p, const Eigen::MatrixXd& cov,
                            const Eigen::VectorXd& steps, const std::vector<ControlPoint>& points,
                            const std::vector<PointPrep>& prep, const std::vector<double>& paramSd) {
    const int np = static_cast<int>(p.size());
    BeamCalibration bc;
    const BeamDesign& b = beams[k];
    bc.id = b.id;
    bc.points = points_k;
    const bool hasParams = m.idx[k].dAlpha >= 0 || (params.model == CalibModel::DualBeam);
    bc.solved = hasParams && (points_k > 0 || params.model == CalibModel::DualBeam);
    bc.rangeSolved = m.idx[k].dRho >= 0;
    auto derived = [&](const Eigen::VectorXd& q) {
        const Eigen::Vector3d ub = m.uBody(k, q);
        const Eigen::Vector3d ul = b.laserToBody.normalized().inverse() * ub;
        double al, be;
        pointingAngles(ul, &al, &be);
        const ThreeAxisAngles t = threeAxisAngles(ub);
        Eigen::VectorXd v(5);
        v << al, be, t.x, t.y, t.z;
        return v;
    };
    const Eigen::VectorXd v = derived(p);
    bc.alphaRad = v(0);
    bc.betaRad = v(1);
    bc.dAlphaRad = v(0) - b.alphaRad;
    bc.dBetaRad = std::remainder(v(1) - b.betaRad, 2 * M_PI);
    bc.dRhoM = Model::at(p, m.idx[k].dRho);
    bc.designAngles = threeAxisAngles(bodyPointing(b, 0, 0));
    bc.calibratedAngles = {v(2), v(3), v(4)};
    if (bc.solved) {
        Eigen::MatrixXd G(5, np);
        for (int j = 0; j < np; ++j) {
            Eigen::VectorXd qp = p, qm = p;
            qp(j) += steps(j);
            qm(j) -= steps(j);
            Eigen::VectorXd d = derived(qp) - derived(qm);
            d(1) = std::remainder(d(1), 2 * M_PI);
            G.col(j) = d / (2 * steps(j));
        }
        const Eigen::MatrixXd cv = G * cov * G.transpose();
        bc.dAlphaSdRad = sqrtVariance(cv(0, 0));
        bc.dBetaSdRad = sqrtVariance(cv(1, 1));
        bc.angleXSdRad = sqrtVariance(cv(2, 2));
        bc.angleYSdRad = sqrtVariance(cv(3, 3));
        bc.angleZSdRad = sqrtVariance(cv(4, 4));
        if (bc.rangeSolved) bc.dRhoSdM = paramSd[m.idx[k].dRho];
        for (size_t i = 0; i < points.size(); ++i) {
            if (prep[i].design != k) continue;
            const Eigen::Vector3d g0 = geolocate(b, points[i].shot, bodyPointing(b, 0, 0), 0);
            const Eigen::Vector3d g1 = geolocate(b, points[i].shot, m.uBody(k, p), 0);
            const Eigen::Vector3d d = prep[i].toEnu * (g1 - g0);
            bc.planShiftM = std::hypot(d.x(), d.y());
            break;
        }
    }
    return bc;
}

}  // namespace

namespace {

// Each control point's beam design and whitening; counts per beam and equations. False with
// res->error.
bool prepareControlPoints(const std::vector<BeamDesign>& beams, const std::vector<ControlPoint>& points,
                          const std::map<int, size_t>& byId, const PointingCalibParams& params, std::vector<PointPrep>& prep,
                          std::vector<int>& count, PointingCalibResult* res) {
    for (size_t i = 0; i < points.size(); ++i) {
        const ControlPoint& c = points[i];
        const auto it = byId.find(c.beam);
        if (it == byId.end()) {
            res->error = pointName(c, i) + ": beam " + std::to_string(c.beam) + " has no design";
            return false;
        }
        PointPrep& pp = prep[i];
        pp.design = it->second;
        if (const std::string e = preparePoint(c, i, beams[pp.design], params, &pp); !e.empty()) {
            res->error = e;
            return false;
        }
        ++count[pp.design];
        res->observations += c.useHeight ? 3 : 2;
    }
    return true;
}

// Geometry check at the start: is every parameter determined? False with res->error naming
// the parameters the control points do not separate.
bool geometryDetermined(const LmProblem& prob, const Eigen::VectorXd& p0, const Model& m, const PointingCalibParams& params,
                        PointingCalibResult* res) {
    const int np = static_cast<int>(m.names.size());
    Eigen::VectorXd r;
    Eigen::MatrixXd J, cov;
    if (!prob.evaluate(p0, &r, &J)) {
        res->error = "the model cannot be evaluated at the design values (non-finite geometry)";
        return false;
    }
    Eigen::VectorXd weak;
    if (!covarianceFromJacobian(J, params.minRcond, &cov, &res->rcond, &weak)) {
        std::string which;
        for (int j = 0; j < np; ++j)
            if (std::fabs(weak(j)) > 0.3) which += (which.empty() ? "" : ", ") + m.names[j];
        res->error = "singular calibration geometry (reciprocal condition " + formatDouble(res->rcond, 3) +
                    "): the control points do not separate " + which +
                    " (e.g. identical control points without heights, a beam pointing at nadir, or too few points)";
        return false;
    }
    return true;
}

// The covariance at the solution (scaled by χ²/dof when asked), the parameters' standard
// deviations and the warning when the residuals exceed the stated noise. False with res->error.
bool solutionCovariance(const LmOutcome& o, const PointingCalibParams& params, int np, Eigen::MatrixXd* covOut,
                        PointingCalibResult* res) {
    Eigen::MatrixXd& cov = *covOut;
    Eigen::VectorXd weak;
    if (!covarianceFromJacobian(o.jacobian, params.minRcond, &cov, &res->rcond, &weak)) {
        res->error = "singular calibration geometry at the solution (reciprocal condition " + formatDouble(res->rcond, 3) + ")";
        return false;
    }
    if (params.scaleByChi2) {
        if (res->dof > 0)
            cov *= res->chi2 / res->dof;
        else
            res->warnings.push_back("no redundancy (as many equations as unknowns): covariance from the stated noise only");
    }
    res->covariance = cov;
    for (int j = 0; j < np; ++j) res->paramSd.push_back(sqrtVariance(cov(j, j)));
    if (res->dof > 0 && res->chi2 / res->dof > 4)
        res->warnings.push_back("residuals exceed the stated noise (reduced chi-square " + formatDouble(res->chi2 / res->dof, 3) +
                                "): check the sigmas or look for an outlier");
    return true;
}

}  // namespace

PointingCalibResult calibratePointing(const std::vector<BeamDesign>& beams, const std::vector<ControlPoint>& points,
                                      const PointingCalibParams& params) {
    PointingCalibResult res;
    res.model = params.model;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    if (beams.empty()) {
        res.error = "no beam designs";
        return res;
    }
    if (points.empty()) {
        res.error = "no control points: the calibration needs at least one per beam";
        return res;
    }
    std::map<int, size_t> byId;
    if (const std::string e = checkBeams(beams, params, &byId); !e.empty()) {
        res.error = e;
        return res;
    }
    std::vector<int> count(beams.size(), 0);
    std::vector<PointPrep> prep(points.size());
    if (!prepareControlPoints(beams, points, byId, params, prep, count, &res)) return res;
    // Parameter layout.
    Model m;
    if (const std::string e = layoutParameters(beams, count, params, &m, &res.warnings); !e.empty()) {
        res.error = e;
        return res;
    }
    const int np = static_cast<int>(m.names.size());
    res.paramNames = m.names;
    if (res.observations < np) {
        res.error = "too few control points: " + std::to_string(res.observations) + " equations for " +
                    std::to_string(np) + " unknowns (" + std::to_string(points.size()) + " point" +
                    (points.size() == 1 ? "" : "s") + ")";
        return res;
    }
    // Residual function.
    auto residuals = [&](const Eigen::VectorXd& p, Eigen::VectorXd* r) {
        r->resize(res.observations);
        int row = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const Eigen::Vector3d d = m.ground(prep[i].design, points[i].shot, p) - points[i].groundEcef;
            const Eigen::VectorXd w = prep[i].whiten * d;
            r->segment(row, w.size()) = w;
            row += static_cast<int>(w.size());
        }
        return r->allFinite();
    };
    Eigen::VectorXd steps(np);
    for (int j = 0; j < np; ++j) steps(j) = m.names[j].rfind("drho", 0) == 0 ? 1e-3 : 1e-7;
    LmProblem prob;
    prob.parameters = np;
    prob.evaluate = [&](const Eigen::VectorXd& p, Eigen::VectorXd* r, Eigen::MatrixXd* J) {
        if (!residuals(p, r)) return false;
        return !J || numericJacobian(residuals, p, *r, steps, J, true);
    };
    const Eigen::VectorXd p0 = Eigen::VectorXd::Zero(np);
    if (!geometryDetermined(prob, p0, m, params, &res)) return res;
    LmOptions opt;
    opt.maxIterations = params.maxIterations;
    opt.lambda0 = 1e-6;  // nearly linear: start as Gauss–Newton
    opt.costTolerance = 1e-9;
    opt.costToleranceAbs = 1e-6;  // a step worth Δχ² < 1e-6 changes nothing (paper 002: 3 iterations)
    const LmOutcome o = levenbergMarquardt(prob, p0, opt);
    if (!o.ok) {
        res.error = "calibration failed: " + o.error;
        return res;
    }
    res.converged = o.converged;
    if (!o.converged) res.warnings.push_back("stopped at the iteration limit before converging");
    const Eigen::VectorXd& p = o.params;
    res.params.assign(p.data(), p.data() + np);
    res.chi2 = o.cost;
    res.dof = res.observations - np;
    if (!std::isfinite(res.chi2) || !p.allFinite()) {
        res.error = "the calibration did not converge to finite values (chi-square " + formatDouble(res.chi2, 4) +
                    "): check the control points' geometry";
        return res;
    }
    Eigen::MatrixXd cov;
    if (!solutionCovariance(o, params, np, &cov, &res)) return res;
    // Stages of the outcome: iterations, per-point residuals, per-beam results.
    recordIterations(o.history, points, prep, m, res);
    recordResiduals(points, prep, m, p, res);
    for (size_t k = 0; k < beams.size(); ++k)
        res.beams.push_back(beamOutcome(k, beams, count[k], m, params, p, cov, steps, points, prep, res.paramSd));
    res.ok = true;
    return res;
}

// ---------------------------------------------------------------------------------------------
// Files

bool readControlPointCsv(const std::string& path, std::vector<ControlPoint>* out, std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const char* required[] = {"beam", "sat_x", "sat_y", "sat_z", "q_w", "q_x", "q_y", "q_z", "range_m"};
    std::vector<int> col;
    for (const char* r : required) {
        const int c = t.column(r);
        if (c < 0) {
            *error = path + ":1: header needs the column " + r +
                     " (beam, sat_x..z, q_w..z, range_m, gcp_x..z or gcp_lat, gcp_lon, gcp_h)";
            return false;
        }
        col.push_back(c);
    }
    const int gx = t.column("gcp_x"), gy = t.column("gcp_y"), gz = t.column("gcp_z");
    const int glat = t.column("gcp_lat"), glon = t.column("gcp_lon"), gh = t.column("gcp_h");
    const bool ecef = gx >= 0 && gy >= 0 && gz >= 0;
    if (!ecef && (glat < 0 || glon < 0 || gh < 0)) {
        *error = path + ":1: header needs the ground point as gcp_x, gcp_y, gcp_z (ECEF m) or gcp_lat, gcp_lon, gcp_h";
        return false;
    }
    const int cid = t.firstColumn({"id", "name"}), csh = t.column("sigma_h"), csv2 = t.column("sigma_v"),
              cuh = t.column("use_height");
    std::vector<ControlPoint> v;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        const std::string where = whereInFile(path, t.lines[i]);
        ControlPoint c;
        c.line = t.lines[i];
        c.id = cid >= 0 ? std::string(trim(row[cid])) : std::to_string(i + 1);
        long long beam = 0;
        if (!parseLong(row[col[0]], &beam) || beam < 0 || beam > 1000000) {
            *error = where + "beam must be a whole number, not \"" + printableExcerpt(row[col[0]]) + "\"";
            return false;
        }
        c.beam = static_cast<int>(beam);
        double v9[8];
        for (int k = 0; k < 8; ++k)
            if (!parseDouble(row[col[k + 1]], &v9[k])) {
                *error = where + t.header[col[k + 1]] + " must be a finite number, not \"" + printableExcerpt(row[col[k + 1]]) + "\"";
                return false;
            }
        c.shot.satEcef = Eigen::Vector3d(v9[0], v9[1], v9[2]);
        c.shot.bodyToEcef = Eigen::Quaterniond(v9[3], v9[4], v9[5], v9[6]);
        c.shot.rangeM = v9[7];
        if (!(c.shot.rangeM > 0)) {
            *error = where + "range_m must be > 0";
            return false;
        }
        const double qn = c.shot.bodyToEcef.norm();
        if (std::fabs(qn - 1) > 1e-3) {
            *error = where + "the attitude quaternion q_w..q_z is not a unit quaternion (norm " + formatDouble(qn, 6) + ")";
            return false;
        }
        c.shot.bodyToEcef.normalize();
        double g[3];
        const int gc[3] = {ecef ? gx : glat, ecef ? gy : glon, ecef ? gz : gh};
        for (int k = 0; k < 3; ++k)
            if (!parseDouble(row[gc[k]], &g[k])) {
                *error = where + t.header[gc[k]] + " must be a finite number, not \"" + printableExcerpt(row[gc[k]]) + "\"";
                return false;
            }
        if (ecef) {
            c.groundEcef = Eigen::Vector3d(g[0], g[1], g[2]);
        } else {
            if (std::fabs(g[0]) > 90 || std::fabs(g[1]) > 360) {
                *error = where + "gcp_lat / gcp_lon out of range";
                return false;
            }
            c.groundEcef = geodeticToEcef(g[0] * kDeg, g[1] * kDeg, g[2]);
        }
        auto optSigma = [&](int cc, double* s) {
            if (cc < 0 || trim(row[cc]).empty()) return true;
            if (!parseDouble(row[cc], s) || !(*s > 0)) {
                *error = where + t.header[cc] + " must be a number > 0, not \"" + printableExcerpt(row[cc]) + "\"";
                return false;
            }
            return true;
        };
        if (!optSigma(csh, &c.sigmaHorizontalM) || !optSigma(csv2, &c.sigmaVerticalM)) return false;
        if (cuh >= 0 && !trim(row[cuh]).empty()) {
            const std::string u = toLower(trim(row[cuh]));
            if (u != "0" && u != "1") {
                *error = where + "use_height must be 0 or 1, not \"" + printableExcerpt(row[cuh]) + "\"";
                return false;
            }
            c.useHeight = u == "1";
        }
        v.push_back(std::move(c));
    }
    if (v.empty()) {
        *error = path + ": no control-point rows";
        return false;
    }
    *out = std::move(v);
    return true;
}

bool writeControlPointCsv(const std::string& path, const std::vector<ControlPoint>& points, std::string* error) {
    std::string s = "id,beam,sat_x,sat_y,sat_z,q_w,q_x,q_y,q_z,range_m,gcp_x,gcp_y,gcp_z,sigma_h,sigma_v,use_height\n";
    auto f = [](double v, int d) { return std::isfinite(v) ? formatFixed(v, d) : std::string(); };
    for (const auto& c : points) {
        const auto& q = c.shot.bodyToEcef;
        s += csvEscape(c.id) + "," + std::to_string(c.beam) + "," + f(c.shot.satEcef.x(), 4) + "," +
             f(c.shot.satEcef.y(), 4) + "," + f(c.shot.satEcef.z(), 4) + "," + f(q.w(), 15) + "," + f(q.x(), 15) + "," +
             f(q.y(), 15) + "," + f(q.z(), 15) + "," + f(c.shot.rangeM, 4) + "," + f(c.groundEcef.x(), 4) + "," +
             f(c.groundEcef.y(), 4) + "," + f(c.groundEcef.z(), 4) + "," + f(c.sigmaHorizontalM, 4) + "," +
             f(c.sigmaVerticalM, 4) + "," + (c.useHeight ? "1" : "0") + "\n";
    }
    return writeFileAtomic(path, s, error);
}

bool readBeamsJson(const std::string& path, std::vector<BeamDesign>* out, std::string* error) {
    const JsonParseResult j = readJsonFile(path);
    if (!j.ok) {
        *error = j.error;
        return false;
    }
    const Json& root = j.value;
    if (!root.is_object() || !root.contains("beams") || !root["beams"].is_array() || root["beams"].empty()) {
        *error = path + ": needs {\"beams\": [{\"id\": 1, \"alpha_deg\": ..., \"beta_deg\": ...}, ...]}";
        return false;
    }
    const Json& arr = root["beams"];
    std::vector<BeamDesign> v;
    std::unordered_map<long long, size_t> seen;  // beam id -> index
    for (size_t i = 0; i < arr.size(); ++i) {
        const Json& b = arr[i];
        // (the position is looked up only for a message: finding it walks the text, and doing it
        // for every beam made 20 000 beams take a minute)
        auto where = [&] {
            const std::string at = "[" + std::to_string(i) + "]";
            return j.where({"beams", at}) + "beams" + at + ": ";
        };
        if (!b.is_object()) {
            *error = where() + "not an object";
            return false;
        }
        BeamDesign d;
        double alpha = NAN, beta = NAN;
        std::string err;
        if (!jsonInt(b, "id", &d.id, &err) || !jsonNumber(b, "alpha_deg", &alpha, &err) ||
            !jsonNumber(b, "beta_deg", &beta, &err)) {
            *error = where() + err;
            return false;
        }
        if (!b.contains("id") || !std::isfinite(alpha) || !std::isfinite(beta)) {
            *error = where() + "needs id, alpha_deg and beta_deg";
            return false;
        }
        if (alpha < 0 || alpha > 90) {
            *error = where() + "alpha_deg must be within 0..90";
            return false;
        }
        if (const auto [it, fresh] = seen.emplace(d.id, i); !fresh) {
            *error = where() + "id " + std::to_string(d.id) + " is already used by beams[" + std::to_string(it->second) +
                     "]; each beam is designed once";
            return false;
        }
        d.alphaRad = alpha * kDeg;
        d.betaRad = beta * kDeg;
        auto vec = [&](const char* key, size_t n, double* dst) {
            if (!b.contains(key)) return true;
            const Json& a = b[key];
            if (!a.is_array() || a.size() != n) {
                *error = where() + key + " must be an array of " + std::to_string(n) + " numbers";
                return false;
            }
            for (size_t k = 0; k < n; ++k) {
                if (!a[k].is_number() || !std::isfinite(a[k].get<double>())) {
                    *error = where() + key + " must hold finite numbers";
                    return false;
                }
                dst[k] = a[k].get<double>();
            }
            return true;
        };
        double off[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
        if (!vec("offset_m", 3, off) || !vec("mounting_quat", 4, q)) return false;
        d.offsetBodyM = Eigen::Vector3d(off[0], off[1], off[2]);
        d.laserToBody = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
        if (std::fabs(d.laserToBody.norm() - 1) > 1e-3) {
            *error = where() + "mounting_quat is not a unit quaternion";
            return false;
        }
        d.laserToBody.normalize();
        v.push_back(d);
    }
    *out = std::move(v);
    return true;
}

std::string beamsToJson(const std::vector<BeamDesign>& beams) {
    Json arr = Json::array();
    for (const auto& b : beams)
        arr.push_back({{"id", b.id},
                       {"alpha_deg", b.alphaRad / kDeg},
                       {"beta_deg", b.betaRad / kDeg},
                       {"offset_m", {b.offsetBodyM(0), b.offsetBodyM(1), b.offsetBodyM(2)}},
                       {"mounting_quat", {b.laserToBody.w(), b.laserToBody.x(), b.laserToBody.y(), b.laserToBody.z()}}});
    return dumpJson(Json{{"beams", arr}});
}

}  // namespace lwb::core::calib
