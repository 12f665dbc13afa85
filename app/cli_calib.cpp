// laserwb-cli calib detector | waveform | pointing | stats, and simulate calib (paper 002).
#include <cmath>
#include <iostream>
#include <sys/stat.h>

#include "cli_commands.hpp"
#include "cli_batch.hpp"
#include "cli_common.hpp"
#include "core/calib/calib_csv.hpp"
#include "core/calib/calib_params.hpp"
#include "core/calib/calib_run.hpp"
#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/calib/waveform.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/sim/calib_sim.hpp"
#include "core/common/rng.hpp"

namespace lwb::cli {

using namespace core::calib;
namespace sim = core::sim;

namespace {

// calib detector: the outputs are written but the centre is doubtful (see kDetectorUsage).

std::string fx(double v, int d) { return std::isfinite(v) ? core::formatFixed(v, d) : std::string(); }
std::string gx(double v) { return std::isfinite(v) ? core::formatDouble(v, 10) : std::string(); }
std::string outPath(const Args& a) { return a.has("-o") ? a.value("-o") : a.value("--output"); }
bool quiet(const Args& a) { return a.has("-q") || a.has("--quiet"); }
bool wantsHelp(const Args& a) { return a.has("--help") || a.has("-h"); }
void warn(const std::string& cmd, const std::vector<std::string>& ws, const Args& a) { warnings(cmd, ws, quiet(a)); }

// ------------------------------------------------------------------------------------------
const char* kDetectorUsage =
    "usage: laserwb-cli calib detector DETECTORS.csv [options] [-o CENTRE.csv] [--detectors REPORT.csv]\n"
    "Footprint centre from a ground detector array (paper 002 3.2.3): a 2D Gaussian surface fitted\n"
    "to the detector energies by Levenberg-Marquardt, with its 1-sigma and 95 % uncertainty ellipses.\n"
    "DETECTORS.csv: header id, e, n (metres) or lat, lon (degrees; projected to the local tangent\n"
    "plane at their mean), energy, and optionally h, triggered (0/1), saturated (0/1). Full reports\n"
    "(every detector, background and negative energies included) and trigger-style files (only\n"
    "triggered detectors, or untriggered ones marked triggered=0) are both read as they are.\n"
    "Noise: by default estimated from the array (floor, and a relative term when the residuals ask\n"
    "for it); give --rel-noise and/or --noise-floor to use a known noise model instead.\n"
    "Censoring: a saturated detector enters the fit as 'at least its level', a listed untriggered one\n"
    "as 'at most the trigger level'; detectors inconsistent with the fit are set aside as outliers.\n"
    "  --model auto|elliptical|circular  surface (default {default:detector.model}; auto: elliptical,\n"
    "                               7 parameters, when 10 or more detectors carry a measurement;\n"
    "                               circular, 5, below)\n"
    "  --fixed-background B         hold the background at B instead of fitting it\n"
    "  --trigger T                  energies <= T count as untriggered (default: no threshold)\n"
    "  --saturation S               energies >= S count as saturated (default: flags, or a clipped maximum)\n"
    "  --rel-noise R                known noise: sigma as a fraction of the energy (0 when only F is given)\n"
    "  --noise-floor F              known noise: additive sigma (0 when only R is given)\n"
    "  --scale-chi2                 with a known noise: scale the covariance by the reduced chi-square\n"
    "  --no-censoring               set saturated and untriggered detectors aside instead\n"
    "  --outlier-sigma Z            set aside detectors more than Z robust sigma off (default {default:detector.outlier_sigma}; 0 = off)\n"
    "  -o, --output CENTRE.csv      one row: centre, ellipses, lat/lon, height, surface, fit figures,\n"
    "                               noise model, doubtful (0/1) and the reasons\n"
    "  --detectors REPORT.csv       one row per detector: status, reason, model, residual, bound, sigma\n"

    "Exit codes: 0 a trusted centre; 3 the outputs are written but the centre is doubtful (reasons on\n"
    "stderr and in CENTRE.csv): chi2 improbable under a given noise model, the centre outside the\n"
    "detectors that see the footprint or the array by more than the footprint's 1/e2 radius, a 95 %\n"
    "ellipse larger than the array, a footprint wider than the array or narrower than the spacing, a\n"
    "peak under 3 noise sigma; 1 refused (no centre, nothing written); 2 usage error.\n";

const char* kWaveformUsage =
    "usage: laserwb-cli calib waveform (WAVEFORM.csv | --height H) [--features CANDIDATES.csv] [options]\n"
    "Paper 002 2.1.1: the feature height from a double-peak waveform (two Gaussians + baseline,\n"
    "h = dt * c / 2 / cos(incidence)) and the surveyed feature that matches it (smallest |h_i - h|\n"
    "below thred_h).\n"
    "WAVEFORM.csv: amplitude [, time_ns | sample]; CANDIDATES.csv: id, h [, e, n | lat, lon].\n"
    "  --dt NS              sample interval when the file has no time column (default {default:waveform.sample_interval_ns})\n"
    "  --incidence DEG      beam incidence from the vertical (default {default:waveform.incidence_deg})\n"
    "  --height H           skip the waveform: match this height (m)\n"
    "  --thred-h M          height threshold (default {default:waveform.thred_h} m)\n"
    "  -o, --output OUT.csv candidates ranked: rank, id, h, delta_h, below_threshold, chosen\n"
    "  --model MODEL.csv    the fitted waveform: time_ns, amplitude, model\n"
    "Exit code 3 when no candidate lies within thred_h (the table is written, the closest is named).\n";

const char* kPointingUsage =
    "usage: laserwb-cli calib pointing CONTROL.csv --beams BEAMS.json [options] -o BEAMS_OUT.csv\n"
    "Pointing corrections and range biases from control points (paper 002 eq. 2-5), with their\n"
    "1-sigma uncertainties and the residuals of every iteration.\n"
    "CONTROL.csv: beam, [id,] sat_x, sat_y, sat_z (ECEF m), q_w, q_x, q_y, q_z (body->ECEF), range_m,\n"
    "  gcp_x, gcp_y, gcp_z (ECEF m) or gcp_lat, gcp_lon, gcp_h, [sigma_h, sigma_v, use_height].\n"
    "BEAMS.json: {\"beams\": [{\"id\": 1, \"alpha_deg\": 0.7, \"beta_deg\": 90}, ...]}.\n"
    "  --model single|dual      single: each beam on its own, dual: beam 2 = beam 1 rotated by dR(r,a,b)\n"
    "                           (default {default:pointing.model})\n"
    "  --no-range               pointing only (the coarse step)\n"
    "  --fix-relative           dual: hold the relative rotation at its design\n"
    "  --sigma-h M, --sigma-v M default control-point sigmas ({default:pointing.sigma_h}, {default:pointing.sigma_v} m)\n"
    "  --sigma-range M          range noise ({default:pointing.sigma_range} m)\n"
    "  --sigma-attitude-urad U  attitude noise per axis ({default:pointing.sigma_attitude_urad} urad)\n"
    "  --sigma-orbit M          orbit noise per axis ({default:pointing.sigma_orbit} m)\n"
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
    "waveform_truth.csv; diffs.csv (validation elevation differences per beam, for calib stats) and\n"
    "diffs_truth.csv.\n"
    "  --seed S        random seed (default 1)\n"
    "  -q, --quiet     no summary on stderr\n"
    "  --passes N      calibration passes (default 4)\n"
    "  --single-beam   only beam 1 fires\n"
    "  --geographic    detector positions as lat/lon\n"
    "  --saturation S  detector saturation level (default none)\n"
    "  --field-case    the detector array is one of the field population (17 x 9 detectors at 5 m,\n"
    "                  13-17 m footprint, noise 2-5 % of the peak, full or trigger-style report, dead\n"
    "                  and saturated detectors), drawn from the seed\n";



// The calibration parameters: one schema (core/calib/calib_params.hpp) for every calib command,
// so a workbench session's parameter block is a config file of any of them. Today's named
// options are aliases of --set (flags that set several fields are applied after the config).
std::string withParams(const char* usage) {
    return std::string(usage) + ParamOptions<CalibParams>::paramsHelp("calib", "detector.outlier_sigma=5");
}

// The whole table's check (rules between fields included).
std::string check(const CalibParams& p) { return validate(p); }

}  // namespace

int cmdCalibDetector(int argc, char** argv) {
    const std::string cmd = "calib detector";
    const std::string usage = withParams(kDetectorUsage);
    Args a(cmd, usage);
    const ParamOptions<CalibParams> params(calibSchema(), {{"--model", "detector.model"},
                                                           {"--trigger", "detector.trigger"},
                                                           {"--saturation", "detector.saturation"},
                                                           {"--rel-noise", "detector.rel_noise"},
                                                           {"--noise-floor", "detector.noise_floor"},
                                                           {"--outlier-sigma", "detector.outlier_sigma"}});
    for (const char* o : {"--fixed-background", "-o", "--output", "--detectors"}) a.option(o, true);
    for (const char* o : {"--scale-chi2", "--no-censoring"}) a.option(o, false);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    CalibParams cp;
    std::string err;
    if (int rc = params.load(cmd, a, &cp, check, [&](CalibParams* q) {
            std::string e;
            if (a.has("--fixed-background")) {
                q->detector.fitBackground = false;
                if (!calibSchema().setFromText(q, "detector.background", a.value("--fixed-background"), &e))
                    return fail(cmd, "--fixed-background " + a.value("--fixed-background") + ": " + e, kUsage);
            }
            if (a.has("--rel-noise") || a.has("--noise-floor")) q->detector.noise = NoiseSource::Given;
            if (a.has("--scale-chi2")) q->detector.scaleByChi2 = true;
            if (a.has("--no-censoring")) q->detector.censor = false;
            return int(kOk);
        });
        rc >= 0)
        return rc;
    if (a.positional().size() != 1) return fail(cmd, "give exactly one detector CSV", kUsage);
    const std::string out = outPath(a);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    if (!out.empty()) outs.addOutput(out);
    if (a.has("--detectors")) outs.addOutput(a.value("--detectors"));
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    CalibSources src;
    src.detectors = a.positional()[0];
    CalibInputData in;
    const DetectorArray& arr = in.array;
    if (!loadCalibInputs(src, &in, &err)) return fail(cmd, err);
    const CalibRunResult run = core::runTask<CalibTask>(in, cp);
    const DetectorFitResult& r = run.detector;
    if (!r.ok) return fail(cmd, a.positional()[0] + ": " + r.error);
    warn(cmd, r.warnings, a);
    if (!out.empty() && !writeDetectorCentreCsv(outs.stagingPath(out), r, &err)) return fail(cmd, outs.unstaged(err));
    if (a.has("--detectors") && !writeDetectorReportCsv(outs.stagingPath(a.value("--detectors")), arr, r, &err))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, calibSchema().toJson(cp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a)) {
        const auto& e = r.centreEllipse;
        std::cerr << "calib detector: " << r.used << " measurements and " << r.censored << " bounds of " << arr.detectors.size()
                  << " detectors in the fit (" << r.outliers << " outliers set aside), " << r.seeing << " see the footprint; "
                  << surfaceModelName(r.modelUsed) << " surface; centre E " << fx(r.centreE, 3) << " m, N " << fx(r.centreN, 3)
                  << " m; 1-sigma ellipse " << fx(e.semiMajor, 3) << " x " << fx(e.semiMinor, 3) << " m at "
                  << fx(e.orientationRad / kDeg, 1) << " deg (95 %: x" << fx(r.centreEllipse95Scale, 3) << ")";
        if (arr.geographic) std::cerr << "; lat " << fx(r.centreLatDeg, 8) << ", lon " << fx(r.centreLonDeg, 8);
        std::cerr << "\n  noise " << r.noise.description << "; chi2/dof " << fx(r.chi2Gof / std::max(r.gofDof, 1), 3)
                  << " on " << r.gofDof << " dof\n";
    }
    if (r.doubtful) {
        for (const auto& d : r.doubts) std::cerr << "laserwb-cli " << cmd << ": doubtful: " << d << "\n";
        return kDoubtful;
    }
    return kOk;
}

int cmdCalibWaveform(int argc, char** argv) {
    const std::string cmd = "calib waveform";
    const std::string usage = withParams(kWaveformUsage);
    Args a(cmd, usage);
    const ParamOptions<CalibParams> params(calibSchema(), {{"--dt", "waveform.sample_interval_ns"},
                                                           {"--incidence", "waveform.incidence_deg"},
                                                           {"--thred-h", "waveform.thred_h"}});
    for (const char* o : {"--height", "--features", "-o", "--output", "--model"}) a.option(o, true);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    CalibParams cp;
    std::string err;
    double height = NAN;
    if (!a.getDouble("--height", -1e6, 1e6, &height, &err)) return fail(cmd, err, kUsage);
    if (int rc = params.load(cmd, a, &cp, check); rc >= 0) return rc;
    const FeatureMatchParams& mp = cp.match;
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
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    // The waveform (or the given height) and the candidates through the run layer.
    CalibSources src;
    src.givenHeightM = height;
    if (!a.has("--height")) src.waveform = a.positional()[0];
    src.features = a.value("--features");
    CalibInputData in;
    if (!loadCalibInputs(src, &in, &err)) return fail(cmd, err);
    const CalibRunResult run = core::runTask<CalibTask>(in, cp);
    const Waveform& w = run.waveformRun;
    const WaveformResult& wr = run.waveform;
    if (run.hasWaveform) {
        if (!wr.ok) return fail(cmd, a.positional()[0] + ": " + wr.error);
        warn(cmd, wr.warnings, a);
        std::cout << "returns at " << fx(wr.first.centreNs, 3) << " and " << fx(wr.second.centreNs, 3) << " ns; dt "
                  << fx(wr.deltaTNs, 3) << " +- " << fx(wr.deltaTSdNs, 3) << " ns; h_waveform " << fx(wr.heightM, 3)
                  << " +- " << fx(wr.heightSdM, 3) << " m\n";
    }
    const std::vector<FeatureCandidate>& cands = in.features;
    const FeatureMatchResult& mr = run.match;
    if (a.has("--features")) {
        if (!run.hasMatch) return fail(cmd, a.value("--features") + ": no candidate features");
        if (!mr.ok) return fail(cmd, mr.error);
        warn(cmd, mr.warnings, a);
    }
    if ((!outPath(a).empty() && !writeTextOutput(outs.stagingPath(outPath(a)), rankingCsv(cands, mr), &err)) ||
        (a.has("--model") && !writeTextOutput(outs.stagingPath(a.value("--model")), waveformModelCsv(w, wr), &err)))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, calibSchema().toJson(cp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (a.has("--features")) {
        if (!mr.found) {
            std::cout << "no candidate within thred_h " << core::formatDouble(mp.thresholdM, 4) << " m (closest: "
                      << cands[mr.best].id << ", dh " << fx(mr.bestDeltaHM, 3) << " m)\n";
            std::cerr << "laserwb-cli " << cmd << ": doubtful: no candidate feature within thred_h (exit 3)\n";
            return kDoubtful;
        }
        std::cout << "footprint on feature " << cands[mr.best].id << " (h " << gx(cands[mr.best].heightM) << " m, dh "
                  << fx(mr.bestDeltaHM, 3) << " m)\n";
    }
    return kOk;
}

int cmdCalibPointing(int argc, char** argv) {
    const std::string cmd = "calib pointing";
    const std::string usage = withParams(kPointingUsage);
    Args a(cmd, usage);
    const ParamOptions<CalibParams> params(calibSchema(), {{"--model", "pointing.model"},
                                                           {"--sigma-h", "pointing.sigma_h"},
                                                           {"--sigma-v", "pointing.sigma_v"},
                                                           {"--sigma-range", "pointing.sigma_range"},
                                                           {"--sigma-attitude-urad", "pointing.sigma_attitude_urad"},
                                                           {"--sigma-orbit", "pointing.sigma_orbit"}});
    for (const char* o : {"--beams", "-o", "--output", "--params", "--residuals", "--iterations", "--beams-out"})
        a.option(o, true);
    for (const char* o : {"--no-range", "--fix-relative", "--scale-chi2"}) a.option(o, false);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    CalibParams cp;
    std::string err;
    if (int rc = params.load(cmd, a, &cp, check, [&](CalibParams* q) {
            if (a.has("--no-range")) q->pointing.solveRange = false;
            if (a.has("--fix-relative")) q->pointing.fixRelativeRotation = true;
            if (a.has("--scale-chi2")) q->pointing.scaleByChi2 = true;
            return int(kOk);
        });
        rc >= 0)
        return rc;
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
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    CalibSources src;
    src.controlPoints = a.positional()[0];
    src.beams = a.value("--beams");
    CalibInputData in;
    const std::vector<BeamDesign>& beams = in.beams;
    const std::vector<ControlPoint>& pts = in.points;
    if (!loadCalibInputs(src, &in, &err)) return fail(cmd, err);
    const CalibRunResult run = core::runTask<CalibTask>(in, cp);
    const PointingCalibResult& r = run.pointing;
    if (!r.ok) return fail(cmd, a.positional()[0] + ": " + r.error);
    warn(cmd, r.warnings, a);
    auto write = [&](const std::string& path, const std::string& text) {
        return writeTextOutput(outs.stagingPath(path), text, &err);
    };
    if (!write(out, pointingBeamsCsv(r)) || (a.has("--params") && !write(a.value("--params"), pointingParamsCsv(r))) ||
        (a.has("--residuals") && !write(a.value("--residuals"), pointingResidualsCsv(r))) ||
        (a.has("--iterations") && !write(a.value("--iterations"), pointingIterationsCsv(r))) ||
        (a.has("--beams-out") && !write(a.value("--beams-out"), beamsToJson(calibratedBeams(beams, r)))))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, calibSchema().toJson(cp))) return rc;
    if (int rc = commitOutputs(cmd, outs)) return rc;
    if (!quiet(a)) {
        const double urad = 1e6;
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
    const std::string usage = withParams(kStatsUsage);
    Args a(cmd, usage);
    const ParamOptions<CalibParams> params(calibSchema());  // none of its own: accepted for one config everywhere
    for (const char* o : {"--group", "-o", "--output"}) a.option(o, true);
    if (int rc = params.parseWithHelp(a, argc, argv, 3); rc >= 0) return rc;
    CalibParams cp;
    if (int rc = params.load(cmd, a, &cp, check); rc >= 0) return rc;
    if (a.positional().size() != 1) return fail(cmd, "give exactly one CSV of differences", kUsage);
    core::OutputSet outs;
    outs.addInput(a.positional()[0]);
    if (!outPath(a).empty()) outs.addOutput(outPath(a));
    const std::string sidecar = addProvenanceSidecar(outs);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    // The task the workbench runs (CalibTask), on the differences alone.
    CalibSources src;
    src.differences = a.positional()[0];
    src.groupColumn = a.value("--group");
    CalibInputData in;
    std::string err;
    if (!loadCalibInputs(src, &in, &err)) return fail(cmd, err);
    const CalibRunResult run = core::runTask<CalibTask>(in, cp);
    for (const StatsGroup& g : run.stats) {
        if (!g.stats.ok) return fail(cmd, a.positional()[0] + ": " + g.stats.error);
        const auto& t = g.stats.stats;
        std::cout << g.name << ":\n";
        for (const auto& lv : labelledStats(t))
            std::cout << "  " << lv.label << ": " << (lv.key == "n" ? std::to_string(t.n) : fx(lv.value, 4)) << "\n";
    }
    if (!outPath(a).empty() && !writeTextOutput(outs.stagingPath(outPath(a)), statsCsv(statsRows(run.stats)), &err))
        return fail(cmd, outs.unstaged(err));
    if (int rc = stageRunProvenance(cmd, outs, sidecar, calibSchema().toJson(cp))) return rc;
    return commitOutputs(cmd, outs);
}

int cmdSimulateCalib(int argc, char** argv) {
    const std::string cmd = "simulate calib";
    Args a(cmd, kSimCalibUsage);
    for (const char* o : {"--seed", "--passes", "--saturation"}) a.option(o, true);
    for (const char* o : {"--single-beam", "--geographic", "--field-case", "--help", "-h", "-q", "--quiet"}) a.option(o, false);
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
                          "waveform.csv", "features.csv", "waveform_truth.csv", "diffs.csv", "diffs_truth.csv"})
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
    if (a.has("--field-case")) dp = sim::drawDetectorFieldCase(sim::Rng::mix(s0, 4));
    dp.geographic = a.has("--geographic");
    if (a.has("--saturation")) dp.saturationLevel = saturation;
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
        double off = 0;
        if (i == truthIndex) {
            off = rng.uniform(-0.03, 0.03);
        } else {
            const double sign = rng.uniform() < 0.5 ? -1 : 1;
            off = sign * rng.uniform(0.3, 3);
        }
        // Named draws: the operands of a chain of + are evaluated in an unspecified order.
        const double fn = rng.uniform(-30, 30), fe = rng.uniform(-30, 30);
        feats += "F" + std::to_string(i + 1) + "," + fx(fe, 2) + "," + fx(fn, 2) + "," + fx(wp.heightM + off, 3) + "\n";
    }
    const std::string wtruth = "height_m,delta_t_ns,feature\n" + fx(wp.heightM, 6) + "," + fx(ws.deltaTNs, 6) + ",F" +
                               std::to_string(truthIndex + 1) + "\n";
    // Validation differences (laser minus reference elevation, m) of each beam after calibration,
    // as paper 002 checks them on flat ground: 24 points a beam about a small residual bias.
    sim::Rng drng(sim::Rng::mix(s0, 5));
    std::string diffs = "beam,d\n", dtruthStats = "beam,mean_m,sd_m,n\n";
    for (int beam = 1; beam <= 2; ++beam) {
        const double bias = drng.uniform(-0.05, 0.05), sd = drng.uniform(0.08, 0.14);
        for (int i = 0; i < 24; ++i) diffs += std::to_string(beam) + "," + fx(bias + sd * drng.normal(), 3) + "\n";
        dtruthStats += std::to_string(beam) + "," + fx(bias, 4) + "," + fx(sd, 4) + ",24\n";
    }
    if (!core::writeFileAtomic(staged("diffs.csv"), diffs, &err) ||
        !core::writeFileAtomic(staged("diffs_truth.csv"), dtruthStats, &err))
        return fail(cmd, outs.unstaged(err));
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
                             << "detectors.csv, detector_truth.csv, waveform.csv, features.csv, waveform_truth.csv, diffs.csv, "
                             << "diffs_truth.csv}\n";
    return kOk;
}

}  // namespace lwb::cli
