#include "core/calib/calib_check.hpp"

#include "core/calib/geodesy.hpp"

namespace lwb::core::calib {

namespace {
std::string pointLabel(const ControlPoint& c, size_t i) {
    std::string s = "check point " + (c.id.empty() ? std::to_string(i + 1) : c.id);
    if (c.line > 0) s += " (line " + std::to_string(c.line) + ")";
    return s;
}
bool finite(const Eigen::Vector3d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
}  // namespace

CalibrationCheckResult checkCalibration(const std::vector<BeamDesign>& beams, const PointingCalibResult& calib,
                                        const std::vector<ControlPoint>& points, const CalibrationCheckParams& params) {
    CalibrationCheckResult res;
    if (params.applyCalibration) {
        if (!calib.ok) {
            res.error = "the calibration did not succeed" + (calib.error.empty() ? std::string() : ": " + calib.error);
            return res;
        }
        if (calib.beams.size() != beams.size()) {
            res.error = "the calibration has " + std::to_string(calib.beams.size()) + " beams, the design " +
                        std::to_string(beams.size());
            return res;
        }
        for (size_t k = 0; k < beams.size(); ++k)
            if (calib.beams[k].id != beams[k].id) {
                res.error = "the calibration's beam " + std::to_string(calib.beams[k].id) + " is not the design's beam " +
                            std::to_string(beams[k].id);
                return res;
            }
    }
    if (points.empty()) {
        res.error = "no check points";
        return res;
    }
    // The calibrated designs: the solved angles replace the design angles (the dual-beam model's
    // relative rotation is already folded into beam 2's angles), plus the range bias.
    std::vector<BeamDesign> used = beams;
    std::vector<double> dRho(beams.size(), 0.0);
    if (params.applyCalibration)
        for (size_t k = 0; k < beams.size(); ++k) {
            if (!calib.beams[k].solved) continue;
            used[k].alphaRad = calib.beams[k].alphaRad;
            used[k].betaRad = calib.beams[k].betaRad;
            if (calib.beams[k].rangeSolved) dRho[k] = calib.beams[k].dRhoM;
        }
    for (size_t i = 0; i < points.size(); ++i) {
        const ControlPoint& c = points[i];
        size_t k = beams.size();
        for (size_t j = 0; j < beams.size(); ++j)
            if (beams[j].id == c.beam) k = j;
        if (k == beams.size()) {
            res.error = pointLabel(c, i) + ": beam " + std::to_string(c.beam) + " is not among the beam designs";
            return res;
        }
        if (params.applyCalibration && !calib.beams[k].solved) {
            res.error = pointLabel(c, i) + ": beam " + std::to_string(c.beam) + " was not calibrated (no control points)";
            return res;
        }
        if (!finite(c.shot.satEcef) || !finite(c.groundEcef) || !std::isfinite(c.shot.rangeM) ||
            !std::isfinite(c.shot.bodyToEcef.w()) || !std::isfinite(c.shot.bodyToEcef.vec().norm())) {
            res.error = pointLabel(c, i) + ": non-finite position, attitude or range";
            return res;
        }
        const Eigen::Vector3d g = geolocate(used[k], c.shot, 0.0, 0.0, dRho[k]);
        const Geodetic geo = ecefToGeodetic(c.groundEcef);
        const Eigen::Vector3d d = ecefToEnuRotation(geo.latRad, geo.lonRad) * (g - c.groundEcef);
        CheckPointDifference p;
        p.id = c.id.empty() ? std::to_string(i + 1) : c.id;
        p.beam = c.beam;
        p.e = d.x();
        p.n = d.y();
        p.u = d.z();
        p.plan = std::hypot(d.x(), d.y());
        p.line = c.line;
        res.points.push_back(p);
    }
    res.ok = true;
    return res;
}

std::vector<double> heightDifferences(const CalibrationCheckResult& r, int beam) {
    std::vector<double> d;
    for (const auto& p : r.points)
        if (beam == 0 || p.beam == beam) d.push_back(p.u);
    return d;
}

}  // namespace lwb::core::calib
