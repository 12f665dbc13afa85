// laserwb-cli calib detector | waveform | pointing | stats, and simulate calib (paper 002).
#include <cmath>
#include <iostream>
#include <sys/stat.h>

#include "cli_commands.hpp"
#include "cli_common.hpp"
#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/calib/waveform.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/sim/calib_sim.hpp"
#include "core/sim/rng.hpp"

namespace lwb::cli {

using namespace core::calib;
namespace sim = core::sim;

namespace {

std::string fx(double v, int d) { return std::isfinite(v) ? core::formatFixed(v, d) : std::string(); }
std::string gx(double v) { return std::isfinite(v) ? core::formatDouble(v, 10) : std::string(); }
std::string outPath(const Args& a) { return a.has("-o") ? a.value("-o") : a.value("--output"); }
bool quiet(const Args& a) { return a.has("-q") || a.has("--quiet"); }
bool wantsHelp(const Args& a) { return a.has("--help") || a.has("-h"); }
void warn(const std::string& cmd, const std::vector<std::string>& ws) {
    for (const auto& w : ws) std::cerr << "laserwb-cli " << cmd << ": warning: " << w << "\n";
}

// ------------------------------------------------------------------------------------------
const char* kDetectorUsage =
    "usage: laserwb-cli calib detector DETECTORS.csv [options] [-o CENTRE.csv] [--detectors REPORT.csv]\n"
    "Footprint centre from a ground detector array (paper 002 3.2.3): a 2D Gaussian surface fitted\n"
    "to the detector energies by Levenberg-Marquardt, with its 1-sigma uncertainty ellipse.\n"
    "DETECTORS.csv: header id, e, n (metres) or lat, lon (degrees; projected to the local tangent\n"
    "plane at their mean), energy, and optionally h, triggered (0/1), saturated (0/1).\n"
    "  --model elliptical|circular  surface (default elliptical: 7 parameters; circular: 5)\n"
    "  --fixed-background B         hold the background at B instead of fitting it\n"
    "  --trigger T                  energies <= T count as untriggered (default 0)\n"
    "  --saturation S               energies >= S count as saturated (default: none)\n"
    "  --rel-noise R                energy noise as a fraction of the energy (default 0.05)\n"
    "  --noise-floor F              additive energy noise sigma (default 0)\n"
    "  --scale-chi2                 scale the covariance by the reduced chi-square\n"
    "  -o, --output CENTRE.csv      one row: centre, ellipse, lat/lon, height, surface, fit figures\n"
    "  --detectors REPORT.csv       one row per detector: status, reason, model, residual\n"
    "  -q, --quiet                  no summary on stderr\n";

const char* kWaveformUsage =
    "usage: laserwb-cli calib waveform (WAVEFORM.csv | --height H) [--features CANDIDATES.csv] [options]\n"
    "Paper 002 2.1.1: the feature height from a double-peak waveform (two Gaussians + baseline,\n"
    "h = dt * c / 2 / cos(incidence)) and the surveyed feature that matches it (smallest |h_i - h|\n"
    "below thred_h).\n"
    "WAVEFORM.csv: amplitude [, time_ns | sample]; CANDIDATES.csv: id, h [, e, n | lat, lon].\n"
    "  --dt NS              sample interval when the file has no time column (default 0.5)\n"
    "  --incidence DEG      beam incidence from the vertical (default 0)\n"
    "  --height H           skip the waveform: match this height (m)\n"
    "  --thred-h M          height threshold (default 0.1 m)\n"
    "  -o, --output OUT.csv candidates ranked: rank, id, h, delta_h, below_threshold, chosen\n"
    "  --model MODEL.csv    the fitted waveform: time_ns, amplitude, model\n"
    "Exit code 1 also when no candidate lies within thred_h (the table is still written).\n";

const char* kPointingUsage =
    "usage: laserwb-cli calib pointing CONTROL.csv --beams BEAMS.json [options] -o BEAMS_OUT.csv\n"
    "Pointing corrections and range biases from control points (paper 002 eq. 2-5), with their\n"
    "1-sigma uncertainties and the residuals of every iteration.\n"
    "CONTROL.csv: beam, [id,] sat_x, sat_y, sat_z (ECEF m), q_w, q_x, q_y, q_z (body->ECEF), range_m,\n"
    "  gcp_x, gcp_y, gcp_z (ECEF m) or gcp_lat, gcp_lon, gcp_h, [sigma_h, sigma_v, use_height].\n"
    "BEAMS.json: {\"beams\": [{\"id\": 1, \"alpha_deg\": 0.7, \"beta_deg\": 90}, ...]}.\n"
    "  --model single|dual      each beam on its own (default), or beam 2 = beam 1 rotated by dR(r,a,b)\n"
    "  --no-range               pointing only (the coarse step)\n"
    "  --fix-relative           dual: hold the relative rotation at its design\n"
    "  --sigma-h M, --sigma-v M default control-point sigmas (0.5, 0.05 m)\n"
    "  --sigma-range M          range noise (0.1 m)\n"
    "  --sigma-attitude-urad U  attitude noise per axis (1 urad)\n"
    "  --sigma-orbit M          orbit noise per axis (0.05 m)\n"
    "  --scale-chi2             scale the covariance by the reduced chi-square\n"
    "  -o, --output OUT.csv     per beam: corrections, sigmas, three-axis angles (design, calibrated)\n"
    "  --params PARAMS.csv      the solved parameters with sigmas\n"
    "  --residuals RES.csv      per control point: E/N/U and along/across residuals before and after\n"
    "  --iterations ITER.csv    per iteration: chi2, RMS plan/height and the parameters\n"
    "  --beams-out BEAMS.json   calibrated beam designs\n";

const char* kStatsUsage =
    "usage: laserwb-cli calib stats DIFFS.csv [--group COLUMN] [-o STATS.csv]\n"
    "Validation statistics of elevation differences (paper 002 3.3), each labelled: n, mean, RMS\n"
    "about zero, sample std (n-1), population std (n), min, max, median, mean |d|.\n"
    "DIFFS.csv: a column d (or diff, dh, difference), or the columns laser and control.\n"
    "Paper 002's 'RMSE' is the sample std for beam 1 (0.097 m) but the RMS about zero for beam 2\n"
    "(0.104 m): read the labels, not the word.\n"
    "  --group COLUMN     one set of statistics per value of this column (e.g. beam)\n"
    "  -o, --output OUT.csv  group, n, mean, rms_about_zero, std_sample, std_population, min, max, median, mean_abs\n";

const char* kSimCalibUsage =
    "usage: laserwb-cli simulate calib OUTDIR [--seed S] [--passes N] [--single-beam]\n"
    "Writes simulated calibration inputs with exact truth: beams.json, control_points.csv and\n"
    "pointing_truth.csv; detectors.csv and detector_truth.csv; waveform.csv, features.csv and\n"
    "waveform_truth.csv.\n"
    "  --seed S        random seed (default 1)\n"
    "  --passes N      calibration passes (default 4)\n"
    "  --single-beam   only beam 1 fires\n"
    "  --geographic    detector positions as lat/lon\n"
    "  --saturation S  detector saturation level (default none)\n";


}  // namespace

int cmdCalibDetector(int argc, char** argv) {
    const std::string cmd = "calib detector";
    Args a(cmd, kDetectorUsage);
    for (const char* o : {"--model", "--fixed-background", "--trigger", "--saturation", "--rel-noise", "--noise-floor", "-o",
                          "--output", "--detectors"})
        a.option(o, true);
    for (const char* o : {"--scale-chi2", "--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (wantsHelp(a)) {
        std::cout << kDetectorUsage;
        return kOk;
    }
    DetectorFitParams p;
    std::string err;
    if (a.has("--model")) {
        const std::string m = a.value("--model");
        if (m == "elliptical") p.model = SurfaceModel::Elliptical;
        else if (m == "circular") p.model = SurfaceModel::Circular;
        else return fail(cmd, "--model must be elliptical or circular, not \"" + m + "\"", kUsage);
    }
    if (a.has("--fixed-background")) {
        p.fitBackground = false;
        if (!a.getDouble("--fixed-background", -1e300, 1e300, &p.background, &err)) return fail(cmd, err, kUsage);
    }
    if (!a.getDouble("--trigger", 0, 1e300, &p.triggerThreshold, &err) ||
        !a.getDouble("--saturation", 0, 1e300, &p.saturationLevel, &err) ||
        !a.getDouble("--rel-noise", 0, 1, &p.relativeNoise, &err) || !a.getDouble("--noise-floor", 0, 1e300, &p.noiseFloor, &err))
        return fail(cmd, err, kUsage);
    p.scaleByChi2 = a.has("--scale-chi2");
    if (const std::string e = validate(p); !e.empty()) return fail(cmd, e, kUsage);
    if (a.positional().size() != 1) return fail(cmd, "give exactly one detector CSV", kUsage);
    const std::string out = outPath(a);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    if (!out.empty()) outs.addOutput(out);
    if (a.has("--detectors")) outs.addOutput(a.value("--detectors"));
    if (int rc = checkOutputs(cmd, outs)) return rc;
    DetectorArray arr;
    if (!readDetectorCsv(a.positional()[0], &arr, &err)) return fail(cmd, err);
    const DetectorFitResult r = fitDetectorArray(arr, p);
    if (!r.ok) return fail(cmd, a.positional()[0] + ": " + r.error);
    warn(cmd, r.warnings);
    if (!out.empty()) {
        const auto& s = r.surface;
        const auto& e = r.centreEllipse;
        const std::string csv =
            "centre_e_m,centre_n_m,sigma_e_m,sigma_n_m,cov_en_m2,ellipse_major_m,ellipse_minor_m,ellipse_deg,lat_deg,lon_deg,"
            "h_m,amplitude,amplitude_sd,sigma_major_m,sigma_major_sd_m,sigma_minor_m,sigma_minor_sd_m,orientation_deg,"
            "background,used,dof,chi2,rms_residual,iterations\n" +
            fx(r.centreE, 4) + "," + fx(r.centreN, 4) + "," + fx(e.sigmaE, 4) + "," + fx(e.sigmaN, 4) + "," + gx(e.covEN) + "," +
            fx(e.semiMajor, 4) + "," + fx(e.semiMinor, 4) + "," + fx(e.orientationRad / kDeg, 3) + "," +
            fx(r.centreLatDeg, 9) + "," + fx(r.centreLonDeg, 9) + "," + fx(r.centreH, 3) + "," + gx(s.amplitude) + "," +
            gx(r.amplitudeSd) + "," + fx(s.sigmaMajor, 4) + "," + fx(r.sigmaMajorSd, 4) + "," + fx(s.sigmaMinor, 4) + "," +
            fx(r.sigmaMinorSd, 4) + "," + fx(s.orientationRad / kDeg, 3) + "," + gx(s.background) + "," +
            std::to_string(r.used) + "," + std::to_string(r.dof) + "," + gx(r.chi2) + "," + gx(r.rmsResidual) + "," +
            std::to_string(r.iterations) + "\n";
        if (!core::writeFileAtomic(outs.stagingPath(out), csv, &err)) return fail(cmd, outs.unstaged(err));
    }
    if (a.has("--detectors") && !writeDetectorReportCsv(outs.stagingPath(a.value("--detectors")), arr, r, &err))
        return fail(cmd, outs.unstaged(err));
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a)) {
        std::cerr << "calib detector: " << r.used << " of " << arr.detectors.size() << " detectors used; centre E "
                  << fx(r.centreE, 3) << " m, N " << fx(r.centreN, 3) << " m; 1-sigma ellipse "
                  << fx(r.centreEllipse.semiMajor, 3) << " x " << fx(r.centreEllipse.semiMinor, 3) << " m at "
                  << fx(r.centreEllipse.orientationRad / kDeg, 1) << " deg";
        if (arr.geographic) std::cerr << "; lat " << fx(r.centreLatDeg, 8) << ", lon " << fx(r.centreLonDeg, 8);
        std::cerr << "\n";
    }
    return kOk;
}

int cmdCalibWaveform(int argc, char** argv) {
    const std::string cmd = "calib waveform";
    Args a(cmd, kWaveformUsage);
    for (const char* o : {"--dt", "--incidence", "--height", "--features", "--thred-h", "-o", "--output", "--model"})
        a.option(o, true);
    for (const char* o : {"--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (wantsHelp(a)) {
        std::cout << kWaveformUsage;
        return kOk;
    }
    WaveformParams wp;
    FeatureMatchParams mp;
    std::string err;
    double height = NAN;
    if (!a.getDouble("--dt", 1e-6, 1e6, &wp.sampleIntervalNs, &err) || !a.getDouble("--incidence", 0, 60, &wp.incidenceDeg, &err) ||
        !a.getDouble("--thred-h", 1e-9, 1e6, &mp.thresholdM, &err) || !a.getDouble("--height", -1e6, 1e6, &height, &err))
        return fail(cmd, err, kUsage);
    if (a.has("--height") == (a.positional().size() == 1) || a.positional().size() > 1)
        return fail(cmd, "give one waveform CSV or --height H (not both)", kUsage);
    if (a.has("--height") && !a.has("--features")) return fail(cmd, "--height needs --features to match against", kUsage);
    if (a.has("--model") && a.has("--height")) return fail(cmd, "--model needs a waveform file", kUsage);
    if (!outPath(a).empty() && !a.has("--features"))
        return fail(cmd, "-o writes the candidate ranking: give --features", kUsage);
    core::OutputSet outs;
    if (!a.has("--height")) outs.addInput(a.positional()[0]);
    outs.addInput(a.value("--features"));
    if (!outPath(a).empty()) outs.addOutput(outPath(a));
    if (a.has("--model")) outs.addOutput(a.value("--model"));
    if (int rc = checkOutputs(cmd, outs)) return rc;
    WaveformResult wr;
    Waveform w;
    if (!a.has("--height")) {
        if (!readWaveformCsv(a.positional()[0], wp.sampleIntervalNs, &w, &err)) return fail(cmd, err);
        wr = decomposeWaveform(w, wp);
        if (!wr.ok) return fail(cmd, a.positional()[0] + ": " + wr.error);
        warn(cmd, wr.warnings);
        height = wr.heightM;
        std::cout << "returns at " << fx(wr.first.centreNs, 3) << " and " << fx(wr.second.centreNs, 3) << " ns; dt "
                  << fx(wr.deltaTNs, 3) << " +- " << fx(wr.deltaTSdNs, 3) << " ns; h_waveform " << fx(wr.heightM, 3)
                  << " +- " << fx(wr.heightSdM, 3) << " m\n";
    }
    std::vector<FeatureCandidate> cands;
    FeatureMatchResult mr;
    if (a.has("--features")) {
        if (!readFeatureCsv(a.value("--features"), &cands, &err)) return fail(cmd, err);
        mr = matchFeature(cands, height, mp);
        if (!mr.ok) return fail(cmd, mr.error);
        warn(cmd, mr.warnings);
    }
    if (!outPath(a).empty()) {
        std::string s = "rank,id,h_m,delta_h_m,below_threshold,chosen\n";
        for (size_t k = 0; k < mr.ranking.size(); ++k) {
            const auto& d = mr.ranking[k];
            s += std::to_string(k + 1) + "," + core::csvEscape(cands[d.index].id) + "," + gx(cands[d.index].heightM) + "," +
                 fx(d.deltaHM, 4) + "," + (d.belowThreshold ? "1" : "0") + "," + (mr.found && k == 0 ? "1" : "0") + "\n";
        }
        if (!core::writeFileAtomic(outs.stagingPath(outPath(a)), s, &err)) return fail(cmd, outs.unstaged(err));
    }
    if (a.has("--model")) {
        std::string s = "time_ns,amplitude,model\n";
        for (size_t i = 0; i < w.timeNs.size(); ++i)
            s += gx(w.timeNs[i]) + "," + gx(w.amplitude[i]) + "," + gx(wr.model[i]) + "\n";
        if (!core::writeFileAtomic(outs.stagingPath(a.value("--model")), s, &err)) return fail(cmd, outs.unstaged(err));
    }
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (a.has("--features")) {
        if (!mr.found) {
            std::cout << "no candidate within thred_h " << core::formatDouble(mp.thresholdM, 4) << " m (closest: "
                      << cands[mr.best].id << ", dh " << fx(mr.bestDeltaHM, 3) << " m)\n";
            return kFailed;
        }
        std::cout << "footprint on feature " << cands[mr.best].id << " (h " << gx(cands[mr.best].heightM) << " m, dh "
                  << fx(mr.bestDeltaHM, 3) << " m)\n";
    }
    return kOk;
}

int cmdCalibPointing(int argc, char** argv) {
    const std::string cmd = "calib pointing";
    Args a(cmd, kPointingUsage);
    for (const char* o : {"--beams", "--model", "--sigma-h", "--sigma-v", "--sigma-range", "--sigma-attitude-urad",
                          "--sigma-orbit", "-o", "--output", "--params", "--residuals", "--iterations", "--beams-out"})
        a.option(o, true);
    for (const char* o : {"--no-range", "--fix-relative", "--scale-chi2", "--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (wantsHelp(a)) {
        std::cout << kPointingUsage;
        return kOk;
    }
    PointingCalibParams p;
    std::string err;
    if (a.has("--model")) {
        const std::string m = a.value("--model");
        if (m == "single") p.model = CalibModel::SingleBeam;
        else if (m == "dual") p.model = CalibModel::DualBeam;
        else return fail(cmd, "--model must be single or dual, not \"" + m + "\"", kUsage);
    }
    double attUrad = p.sigmaAttitudeRad * 1e6;
    if (!a.getDouble("--sigma-h", 1e-9, 1e6, &p.sigmaHorizontalM, &err) ||
        !a.getDouble("--sigma-v", 1e-9, 1e6, &p.sigmaVerticalM, &err) ||
        !a.getDouble("--sigma-range", 0, 1e6, &p.sigmaRangeM, &err) ||
        !a.getDouble("--sigma-attitude-urad", 0, 1e5, &attUrad, &err) || !a.getDouble("--sigma-orbit", 0, 1e6, &p.sigmaOrbitM, &err))
        return fail(cmd, err, kUsage);
    p.sigmaAttitudeRad = attUrad * 1e-6;
    p.solveRange = !a.has("--no-range");
    p.fixRelativeRotation = a.has("--fix-relative");
    p.scaleByChi2 = a.has("--scale-chi2");
    if (a.has("--fix-relative") && p.model != CalibModel::DualBeam) return fail(cmd, "--fix-relative goes with --model dual", kUsage);
    if (const std::string e = validate(p); !e.empty()) return fail(cmd, e, kUsage);
    if (a.positional().size() != 1) return fail(cmd, "give exactly one control-point CSV", kUsage);
    if (!a.has("--beams")) return fail(cmd, "no beam designs: give --beams BEAMS.json", kUsage);
    const std::string out = outPath(a);
    if (out.empty()) return fail(cmd, "no output file: give -o OUT.csv", kUsage);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    outs.addInput(a.value("--beams"));
    outs.addOutput(out);
    for (const char* o : {"--params", "--residuals", "--iterations", "--beams-out"})
        if (a.has(o)) outs.addOutput(a.value(o));
    if (int rc = checkOutputs(cmd, outs)) return rc;
    std::vector<BeamDesign> beams;
    if (!readBeamsJson(a.value("--beams"), &beams, &err)) return fail(cmd, err);
    std::vector<ControlPoint> pts;
    if (!readControlPointCsv(a.positional()[0], &pts, &err)) return fail(cmd, err);
    const PointingCalibResult r = calibratePointing(beams, pts, p);
    if (!r.ok) return fail(cmd, a.positional()[0] + ": " + r.error);
    warn(cmd, r.warnings);
    const double urad = 1e6, deg = 1 / kDeg;
    std::string s =
        "beam,points,solved,d_alpha_urad,d_alpha_sd_urad,d_beta_urad,d_beta_sd_urad,d_rho_m,d_rho_sd_m,alpha_deg,beta_deg,"
        "angle_x_design_deg,angle_y_design_deg,angle_z_design_deg,angle_x_deg,angle_y_deg,angle_z_deg,"
        "d_angle_x_deg,d_angle_y_deg,d_angle_z_deg,angle_x_sd_deg,angle_y_sd_deg,angle_z_sd_deg,plan_shift_m\n";
    for (const auto& b : r.beams) {
        s += std::to_string(b.id) + "," + std::to_string(b.points) + "," + (b.solved ? "1" : "0") + "," +
             fx(b.dAlphaRad * urad, 4) + "," + fx(b.dAlphaSdRad * urad, 4) + "," + fx(b.dBetaRad * urad, 3) + "," +
             fx(b.dBetaSdRad * urad, 3) + "," + (b.rangeSolved ? fx(b.dRhoM, 4) : "") + "," +
             (b.rangeSolved ? fx(b.dRhoSdM, 4) : "") + "," + fx(b.alphaRad * deg, 9) + "," + fx(b.betaRad * deg, 9) + "," +
             fx(b.designAngles.x * deg, 9) + "," + fx(b.designAngles.y * deg, 9) + "," + fx(b.designAngles.z * deg, 9) + "," +
             fx(b.calibratedAngles.x * deg, 9) + "," + fx(b.calibratedAngles.y * deg, 9) + "," +
             fx(b.calibratedAngles.z * deg, 9) + "," + fx((b.calibratedAngles.x - b.designAngles.x) * deg, 9) + "," +
             fx((b.calibratedAngles.y - b.designAngles.y) * deg, 9) + "," +
             fx((b.calibratedAngles.z - b.designAngles.z) * deg, 9) + "," + fx(b.angleXSdRad * deg, 9) + "," +
             fx(b.angleYSdRad * deg, 9) + "," + fx(b.angleZSdRad * deg, 9) + "," + fx(b.planShiftM, 3) + "\n";
    }
    std::string ps = "name,value,sd,unit\n";
    for (size_t j = 0; j < r.params.size(); ++j)
        ps += r.paramNames[j] + "," + gx(r.params[j]) + "," + gx(r.paramSd[j]) + "," +
              (r.paramNames[j].rfind("drho", 0) == 0 ? "m" : "rad") + "\n";
    std::string rs =
        "id,beam,before_e_m,before_n_m,before_u_m,before_along_m,before_across_m,before_plan_m,after_e_m,after_n_m,after_u_m,"
        "after_along_m,after_across_m,after_plan_m,normalized\n";
    for (const auto& c : r.residuals) {
        auto g = [](const GroundResidual& x) {
            return fx(x.e, 4) + "," + fx(x.n, 4) + "," + fx(x.u, 4) + "," + fx(x.along, 4) + "," + fx(x.across, 4) + "," +
                   fx(x.plan(), 4);
        };
        rs += core::csvEscape(c.id) + "," + std::to_string(c.beam) + "," + g(c.before) + "," + g(c.after) + "," +
              fx(c.normalized, 4) + "\n";
    }
    std::string is = "iteration,chi2,rms_plan_m,rms_height_m,rms_3d_m";
    for (const auto& n : r.paramNames) is += "," + n;
    is += "\n";
    for (const auto& it : r.iterations) {
        is += std::to_string(it.iteration) + "," + gx(it.chi2) + "," + fx(it.rmsPlanM, 4) + "," + fx(it.rmsHeightM, 4) + "," +
              fx(it.rms3dM, 4);
        for (double v : it.params) is += "," + gx(v);
        is += "\n";
    }
    std::vector<BeamDesign> calibrated = beams;
    for (size_t k = 0; k < beams.size(); ++k) {
        calibrated[k].alphaRad = r.beams[k].alphaRad;
        calibrated[k].betaRad = r.beams[k].betaRad;
    }
    auto write = [&](const std::string& path, const std::string& text) {
        return core::writeFileAtomic(outs.stagingPath(path), text, &err);
    };
    if (!write(out, s) || (a.has("--params") && !write(a.value("--params"), ps)) ||
        (a.has("--residuals") && !write(a.value("--residuals"), rs)) ||
        (a.has("--iterations") && !write(a.value("--iterations"), is)) ||
        (a.has("--beams-out") && !write(a.value("--beams-out"), beamsToJson(calibrated))))
        return fail(cmd, outs.unstaged(err));
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a)) {
        std::cerr << "calib pointing: " << calibModelName(r.model) << "-beam model, " << pts.size() << " control points, "
                  << r.iterations.size() - 1 << " iterations; RMS plan " << fx(r.iterations.front().rmsPlanM, 3) << " -> "
                  << fx(r.iterations.back().rmsPlanM, 3) << " m, height " << fx(r.iterations.front().rmsHeightM, 3)
                  << " -> " << fx(r.iterations.back().rmsHeightM, 3) << " m\n";
        for (const auto& b : r.beams) {
            if (!b.solved) continue;
            std::cerr << "  beam " << b.id << ": d_alpha " << fx(b.dAlphaRad * urad, 2) << " +- " << fx(b.dAlphaSdRad * urad, 2)
                      << " urad, d_beta " << fx(b.dBetaRad * urad, 1) << " +- " << fx(b.dBetaSdRad * urad, 1) << " urad";
            if (b.rangeSolved) std::cerr << ", d_rho " << fx(b.dRhoM, 3) << " +- " << fx(b.dRhoSdM, 3) << " m";
            std::cerr << "\n";
        }
    }
    return kOk;
}

int cmdCalibStats(int argc, char** argv) {
    const std::string cmd = "calib stats";
    Args a(cmd, kStatsUsage);
    for (const char* o : {"--group", "-o", "--output"}) a.option(o, true);
    for (const char* o : {"--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (wantsHelp(a)) {
        std::cout << kStatsUsage;
        return kOk;
    }
    if (a.positional().size() != 1) return fail(cmd, "give exactly one CSV of differences", kUsage);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    if (!outPath(a).empty()) outs.addOutput(outPath(a));
    if (int rc = checkOutputs(cmd, outs)) return rc;
    std::vector<DifferenceGroup> groups;
    std::string err;
    if (!readDifferencesCsv(a.positional()[0], a.value("--group"), &groups, &err)) return fail(cmd, err);
    std::string s = "group,n,mean,rms_about_zero,std_sample,std_population,min,max,median,mean_abs\n";
    for (const auto& g : groups) {
        const ElevationStatsResult r = elevationStats(g.d);
        if (!r.ok) return fail(cmd, a.positional()[0] + ": " + r.error);
        const auto& t = r.stats;
        s += core::csvEscape(g.group) + "," + std::to_string(t.n) + "," + fx(t.mean, 6) + "," + fx(t.rmsAboutZero, 6) + "," +
             fx(t.stdSample, 6) + "," + fx(t.stdPopulation, 6) + "," + fx(t.min, 6) + "," + fx(t.max, 6) + "," +
             fx(t.median, 6) + "," + fx(t.meanAbs, 6) + "\n";
        std::cout << (g.group.empty() ? std::string("all") : a.value("--group") + " " + g.group) << ":\n";
        for (const auto& lv : labelledStats(t))
            std::cout << "  " << lv.label << ": " << (lv.key == "n" ? std::to_string(t.n) : fx(lv.value, 4)) << "\n";
    }
    if (!outPath(a).empty() && !core::writeFileAtomic(outs.stagingPath(outPath(a)), s, &err))
        return fail(cmd, outs.unstaged(err));
    return commitOutputs(cmd, outs);
}

int cmdSimulateCalib(int argc, char** argv) {
    const std::string cmd = "simulate calib";
    Args a(cmd, kSimCalibUsage);
    for (const char* o : {"--seed", "--passes", "--saturation"}) a.option(o, true);
    for (const char* o : {"--single-beam", "--geographic", "--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (wantsHelp(a)) {
        std::cout << kSimCalibUsage;
        return kOk;
    }
    long long seed = 1, passes = 4;
    double saturation = 0;
    std::string err;
    if (!a.getInt("--seed", 0, 1LL << 62, &seed, &err) || !a.getInt("--passes", 1, 10000, &passes, &err) ||
        !a.getDouble("--saturation", 0, 1e300, &saturation, &err))
        return fail(cmd, err, kUsage);
    if (a.positional().size() != 1) return fail(cmd, "give exactly one output folder", kUsage);
    const std::string dir = a.positional()[0];
    const FolderForOutputs folder(dir);
    if (!folder.ok()) return fail(cmd, dir + ": cannot create the folder");
    core::OutputSet outs;
    for (const char* f : {"beams.json", "control_points.csv", "pointing_truth.csv", "detectors.csv", "detector_truth.csv",
                          "waveform.csv", "features.csv", "waveform_truth.csv"})
        outs.addOutput(dir + "/" + f);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    auto staged = [&](const char* name) { return outs.stagingPath(dir + "/" + name); };
    const uint64_t s0 = static_cast<uint64_t>(seed);
    // Pointing.
    sim::CalibSimParams cp;
    cp.passes = static_cast<int>(passes);
    cp.dualBeam = !a.has("--single-beam");
    const sim::CalibSimulation cs = sim::simulateCalibration(cp, sim::Rng::mix(s0, 0));
    std::string truth = "beam,d_alpha_urad,d_beta_urad,d_rho_m\n";
    for (int k = 0; k < (cp.dualBeam ? 2 : 1); ++k)
        truth += std::to_string(k + 1) + "," + fx(cs.dAlpha[k] * 1e6, 6) + "," + fx(cs.dBeta[k] * 1e6, 6) + "," +
                 fx(cs.dRho[k], 6) + "\n";
    std::vector<BeamDesign> beams = cs.beams;
    if (!cp.dualBeam) beams.resize(1);
    // Detector array.
    sim::DetectorSimParams dp;
    dp.geographic = a.has("--geographic");
    dp.saturationLevel = saturation;
    const sim::DetectorSimulation ds = sim::simulateDetectorArray(dp, sim::Rng::mix(s0, 1));
    const auto& t = ds.truth;
    const std::string dtruth = "centre_e_m,centre_n_m,sigma_major_m,sigma_minor_m,orientation_deg,amplitude,background,"
                               "rel_noise,noise_floor,trigger\n" +
                               fx(t.e0, 6) + "," + fx(t.n0, 6) + "," + fx(t.sigmaMajor, 6) + "," + fx(t.sigmaMinor, 6) + "," +
                               fx(t.orientationRad / kDeg, 4) + "," + gx(t.amplitude) + "," + gx(t.background) + "," +
                               gx(dp.relativeNoise) + "," + gx(dp.noiseFloor) + "," + gx(dp.triggerThreshold) + "\n";
    // Waveform and candidate features (one matching within 3 cm, the rest off by 0.3–3 m).
    sim::WaveformSimParams wp;
    sim::Rng rng(sim::Rng::mix(s0, 2));
    wp.heightM = rng.uniform(2, 20);
    wp.samples = static_cast<int>(std::ceil((wp.firstReturnNs + 2 * wp.heightM / 0.299792458 + 40) / wp.sampleIntervalNs));
    const sim::WaveformSimulation ws = sim::simulateWaveform(wp, sim::Rng::mix(s0, 3));
    std::string wave = "time_ns,amplitude\n";
    for (size_t i = 0; i < ws.waveform.timeNs.size(); ++i)
        wave += gx(ws.waveform.timeNs[i]) + "," + fx(ws.waveform.amplitude[i], 3) + "\n";
    std::string feats = "id,e,n,h\n";
    const int truthIndex = static_cast<int>(rng.uniform(0, 5));
    for (int i = 0; i < 5; ++i) {
        const double off = i == truthIndex ? rng.uniform(-0.03, 0.03) : (rng.uniform() < 0.5 ? -1 : 1) * rng.uniform(0.3, 3);
        feats += "F" + std::to_string(i + 1) + "," + fx(rng.uniform(-30, 30), 2) + "," + fx(rng.uniform(-30, 30), 2) + "," +
                 fx(wp.heightM + off, 3) + "\n";
    }
    const std::string wtruth = "height_m,delta_t_ns,feature\n" + fx(wp.heightM, 6) + "," + fx(ws.deltaTNs, 6) + ",F" +
                               std::to_string(truthIndex + 1) + "\n";
    if (!core::writeFileAtomic(staged("beams.json"), beamsToJson(beams), &err) ||
        !writeControlPointCsv(staged("control_points.csv"), cs.points, &err) ||
        !core::writeFileAtomic(staged("pointing_truth.csv"), truth, &err) ||
        !writeDetectorCsv(staged("detectors.csv"), ds.array, &err) ||
        !core::writeFileAtomic(staged("detector_truth.csv"), dtruth, &err) ||
        !core::writeFileAtomic(staged("waveform.csv"), wave, &err) || !core::writeFileAtomic(staged("features.csv"), feats, &err) ||
        !core::writeFileAtomic(staged("waveform_truth.csv"), wtruth, &err))
        return fail(cmd, outs.unstaged(err));
    if (int rc = commitOutputs(cmd, outs)) return rc;
    folder.keep();
    if (!quiet(a)) std::cerr << "simulate calib: wrote " << dir << "/{beams.json, control_points.csv, pointing_truth.csv, "
                             << "detectors.csv, detector_truth.csv, waveform.csv, features.csv, waveform_truth.csv}\n";
    return kOk;
}

}  // namespace lwb::cli
