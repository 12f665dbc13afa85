#include "core/calib/calib_csv.hpp"

#include <cmath>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::calib {

namespace {
std::string fx(double v, int d) { return std::isfinite(v) ? formatFixed(v, d) : std::string(); }
std::string gx(double v) { return std::isfinite(v) ? formatDouble(v, 10) : std::string(); }
std::string groundCells(const GroundResidual& x) {
    return fx(x.e, 4) + "," + fx(x.n, 4) + "," + fx(x.u, 4) + "," + fx(x.along, 4) + "," + fx(x.across, 4) + "," + fx(x.plan(), 4);
}
}  // namespace

std::string pointingBeamsCsv(const PointingCalibResult& r) {
    const double urad = 1e6, deg = 1 / kDeg;
    std::string s =
        "beam,points,solved,d_alpha_urad,d_alpha_sd_urad,d_beta_urad,d_beta_sd_urad,d_rho_m,d_rho_sd_m,alpha_deg,beta_deg,"
        "angle_x_design_deg,angle_y_design_deg,angle_z_design_deg,angle_x_deg,angle_y_deg,angle_z_deg,"
        "d_angle_x_deg,d_angle_y_deg,d_angle_z_deg,angle_x_sd_deg,angle_y_sd_deg,angle_z_sd_deg,plan_shift_m\n";
    for (const auto& b : r.beams) {
        const auto& d = b.designAngles;
        const auto& c = b.calibratedAngles;
        s += std::to_string(b.id) + "," + std::to_string(b.points) + "," + (b.solved ? "1" : "0") + "," +
             fx(b.dAlphaRad * urad, 4) + "," + fx(b.dAlphaSdRad * urad, 4) + "," + fx(b.dBetaRad * urad, 3) + "," +
             fx(b.dBetaSdRad * urad, 3) + "," + (b.rangeSolved ? fx(b.dRhoM, 4) : "") + "," +
             (b.rangeSolved ? fx(b.dRhoSdM, 4) : "") + "," + fx(b.alphaRad * deg, 9) + "," + fx(b.betaRad * deg, 9) + "," +
             fx(d.x * deg, 9) + "," + fx(d.y * deg, 9) + "," + fx(d.z * deg, 9) + "," + fx(c.x * deg, 9) + "," +
             fx(c.y * deg, 9) + "," + fx(c.z * deg, 9) + "," + fx((c.x - d.x) * deg, 9) + "," + fx((c.y - d.y) * deg, 9) + "," +
             fx((c.z - d.z) * deg, 9) + "," + fx(b.angleXSdRad * deg, 9) + "," + fx(b.angleYSdRad * deg, 9) + "," +
             fx(b.angleZSdRad * deg, 9) + "," + fx(b.planShiftM, 3) + "\n";
    }
    return s;
}

std::string pointingParamsCsv(const PointingCalibResult& r) {
    std::string s = "name,value,sd,unit\n";
    for (size_t j = 0; j < r.params.size(); ++j)
        s += r.paramNames[j] + "," + gx(r.params[j]) + "," + gx(r.paramSd[j]) + "," +
             (r.paramNames[j].rfind("drho", 0) == 0 ? "m" : "rad") + "\n";
    return s;
}

std::string pointingResidualsCsv(const PointingCalibResult& r) {
    std::string s =
        "id,beam,before_e_m,before_n_m,before_u_m,before_along_m,before_across_m,before_plan_m,after_e_m,after_n_m,after_u_m,"
        "after_along_m,after_across_m,after_plan_m,normalized\n";
    for (const auto& c : r.residuals)
        s += csvEscape(c.id) + "," + std::to_string(c.beam) + "," + groundCells(c.before) + "," + groundCells(c.after) + "," +
             fx(c.normalized, 4) + "\n";
    return s;
}

std::string pointingIterationsCsv(const PointingCalibResult& r) {
    std::string s = "iteration,chi2,rms_plan_m,rms_height_m,rms_3d_m";
    for (const auto& n : r.paramNames) s += "," + n;
    s += "\n";
    for (const auto& it : r.iterations) {
        s += std::to_string(it.iteration) + "," + gx(it.chi2) + "," + fx(it.rmsPlanM, 4) + "," + fx(it.rmsHeightM, 4) + "," +
             fx(it.rms3dM, 4);
        for (double v : it.params) s += "," + gx(v);
        s += "\n";
    }
    return s;
}

std::vector<BeamDesign> calibratedBeams(const std::vector<BeamDesign>& design, const PointingCalibResult& r) {
    std::vector<BeamDesign> out = design;
    for (size_t k = 0; k < out.size() && k < r.beams.size(); ++k) {
        out[k].alphaRad = r.beams[k].alphaRad;
        out[k].betaRad = r.beams[k].betaRad;
    }
    return out;
}

std::string statsCsv(const std::vector<std::pair<std::string, ElevationStats>>& groups) {
    std::string s = "group,n,mean,rms_about_zero,std_sample,std_population,min,max,median,mean_abs\n";
    for (const auto& [name, t] : groups)
        s += csvEscape(name) + "," + std::to_string(t.n) + "," + fx(t.mean, 6) + "," + fx(t.rmsAboutZero, 6) + "," +
             fx(t.stdSample, 6) + "," + fx(t.stdPopulation, 6) + "," + fx(t.min, 6) + "," + fx(t.max, 6) + "," +
             fx(t.median, 6) + "," + fx(t.meanAbs, 6) + "\n";
    return s;
}

std::string rankingCsv(const std::vector<FeatureCandidate>& candidates, const FeatureMatchResult& r) {
    std::string s = "rank,id,h_m,delta_h_m,below_threshold,chosen\n";
    for (size_t k = 0; k < r.ranking.size(); ++k) {
        const auto& d = r.ranking[k];
        s += std::to_string(k + 1) + "," + csvEscape(candidates[d.index].id) + "," + gx(candidates[d.index].heightM) + "," +
             fx(d.deltaHM, 4) + "," + (d.belowThreshold ? "1" : "0") + "," + (r.found && k == 0 ? "1" : "0") + "\n";
    }
    return s;
}

std::string waveformModelCsv(const Waveform& w, const WaveformResult& r) {
    std::string s = "time_ns,amplitude,model\n";
    for (size_t i = 0; i < w.timeNs.size(); ++i)
        s += gx(w.timeNs[i]) + "," + gx(w.amplitude[i]) + "," + (i < r.model.size() ? gx(r.model[i]) : std::string()) + "\n";
    return s;
}

bool writeTextOutput(const std::string& path, const std::string& text, std::string* error) {
    return writeFileAtomic(path, text, error);
}

}  // namespace lwb::core::calib
