// laserwb-cli slr: screen one SLR pass (paper 004 binary image, automatic mode by default),
// post-fit with k-sigma rejection and ILRS normal points; per-point CSV, CRD full rate with
// filter flags and CRD normal points. The loading and writing is core/slr/pass_input.hpp, the
// layer the SLR workspace of the GUI uses too.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_commands.hpp"
#include "cli_common.hpp"
#include "core/common/text.hpp"
#include "core/slr/np_context.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/slr_params.hpp"
#include "core/slr/screen.hpp"

namespace lwb::cli {

namespace slr = core::slr;

namespace {

const char* kSlrUsage =
    "usage: laserwb-cli slr INPUT [options] -o OUT.csv [--crd-out FILE] [--npt-out FILE]\n"
    "Screens one SLR pass: signal extraction by binary image (paper 004; automatic scale by default),\n"
    "then a trend fit with k-sigma rejection and ILRS normal points. A summary goes to stderr.\n"
    "INPUT: a CRD file (v1 or v2; recognised by its H1 record, whatever the name) or an O-C CSV\n"
    "       (header with epoch_s,oc_s; epoch in s, O-C in s of two-way time of flight).\n"
    "  --cpf FILE --stations SINEX   O-C of a CRD pass from this CPF prediction and these station\n"
    "                        coordinates (--cpf needs --stations); without --cpf, O-C against a robust\n"
    "                        trend of the pass's own time of flight (a range bias and a smooth drift\n"
    "                        are absorbed). --stations alone: the station's position for day or night\n"
    "                        (the Sun's elevation per normal-point bin: at least 6 points by day, 3 by\n"
    "                        night); without it a CRD pass gets the day minimum of 6\n"
    "  --pass K              pass number in the CRD file, 1-based (1 = the first pass of the file);\n"
    "                        default: the first pass with full-rate (type 10) records\n"
    "Parameters (automatic screening by default; each option replaces only its own parameter; every\n"
    "parameter with its range and meaning: --help-params):\n"
    "  --config FILE.json    parameters (as --print-config writes them)\n"
    "  --set KEY=VALUE       one parameter (repeatable), e.g. --set screen.cosine_c=0.97\n"
    "  --print-config        print the effective parameters as JSON and exit\n"
    "  --mag-t X             pixels per second of epoch (paper table 1: 10 conventional, 1 diffuse)\n"
    "  --mag-oc Y            pixels per second of O-C (paper: 1e10 conventional, 1e7 diffuse)\n"
    "  --area-min N          area limit in pixels: regions at least this large are candidates\n"
    "  --connectivity 4|8    region connectivity (paper: 4 high echo rate, 8 low)\n"
    "  --cos-c C             cosine constant of the recovery step, 0.5..1 exclusive (default 0.95)\n"
    "  --preset FILE         per-satellite presets (JSON, the workbench's format): the entry of the\n"
    "                        pass's satellite (CRD H3 name or ILRS id, or --satellite) is applied\n"
    "                        (screening and post-fit); options given here override it\n"
    "  --satellite NAME      look the preset up under NAME (a name or an ILRS id) instead of the\n"
    "                        pass's H3; needed for an O-C CSV, which names no satellite\n"
    "Post-fit:\n"
    "  --reject K            k of the k-sigma rejection: 2.5 (single-photon) or 3 (multi-photon;\n"
    "                        default); any value 1..10, 0 = off\n"
    "  --np-bin S            normal-point bin length in s (default: the ILRS length for the\n"
    "                        satellite's altitude; an O-C CSV has no altitude: no normal points\n"
    "                        unless --np-bin or a preset's altitude_km is given)\n"
    "Outputs (each written whole or not at all; nothing is written when the run fails):\n"
    "  -o, --output OUT.csv  one row per input point, in input order:\n"
    "                        index,epoch_s,oc_s,class,region,residual_s,kept,station_flag\n"
    "                        index: 0-based row of the O-C CSV, or type-10 record of the CRD pass;\n"
    "                        class: signal | recovered | noise; residual_s: O-C minus the post-fit\n"
    "                        trend; kept: 1 when in the final post-fit; station_flag: the CRD's own\n"
    "                        filter flag (0 unknown, 1 noise, 2 data), empty for a CSV\n"
    "  --crd-out FILE        the CRD file with this pass's filter flags set: 2 accepted by the\n"
    "                        screening (signal or recovered), 1 noise; other passes unchanged\n"
    "  --npt-out FILE        the normal points as a CRD normal-point file (the pass's headers)\n"
    "                        (--crd-out and --npt-out need a CRD input)\n"
    "  -q, --quiet           no summary and no warnings on stderr (errors still)\n"
    "Exit codes: 0 done, 1 bad input or failed run, 2 usage error.\n";

std::string passList(const std::vector<slr::PassSummary>& passes) {
    std::string s;
    for (const auto& p : passes) {
        s += "\n  " + std::to_string(p.index + 1) + ": " + (p.satellite.empty() ? "?" : p.satellite) + " " + p.start +
             " .. " + p.end + ", " + std::to_string(p.ranges) + " full-rate, " + std::to_string(p.normalPoints) +
             " normal-point records";
    }
    return s;
}

// Prefixes the input file to a message that does not name it already.
std::string named(const std::string& path, const std::string& msg) {
    if (msg.rfind(path, 0) == 0) return msg;
    return path + ": " + msg;
}

// The command's defaults: the core's, with the multi-photon rejection of 3 sigma.
slr::SlrParams cliDefaults() {
    slr::SlrParams p;
    p.postfit.rejectSigma = 3;
    return p;
}

std::string ps(double s) { return core::formatFixed(s * 1e12, 1) + " ps"; }

}  // namespace

int cmdSlr(int argc, char** argv) {
    const std::string cmd = "slr";
    Args a(cmd, kSlrUsage);
    // Every screening and post-fit parameter: slr_params.hpp's schema; the named options are
    // aliases of --set with the schema's ranges.
    const ParamOptions<slr::SlrParams> params(slr::slrSchema(), {{"--mag-t", "screen.mag_t"},
                                                                 {"--mag-oc", "screen.mag_oc"},
                                                                 {"--area-min", "screen.area_limit"},
                                                                 {"--connectivity", "screen.connectivity"},
                                                                 {"--cos-c", "screen.cosine_c"},
                                                                 {"--reject", "postfit.reject_sigma"},
                                                                 {"--np-bin", "postfit.bin_length_s"}});
    params.declare(a);
    for (const char* o : {"--cpf", "--stations", "--satellite", "--preset", "--pass", "-o", "--output", "--crd-out", "--npt-out"})
        a.option(o, true);
    for (const char* o : {"--quiet", "-q", "--help", "-h", "--help-params"}) a.option(o, false);
    if (!a.parse(argc, argv, 2)) return fail(cmd, a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kSlrUsage;
        return kOk;
    }
    if (a.has("--help-params")) {
        std::cout << "slr parameters (key = default unit  valid range):\n" << slr::slrSchema().describe(cliDefaults());
        return kOk;
    }
    if (params.printRequested(a)) {  // the defaults with --config and the options applied (no preset: it needs the pass)
        slr::SlrParams p = cliDefaults();
        if (int rc = params.apply(cmd, a, &p)) return rc;
        std::cout << params.json(p);
        return kOk;
    }
    const bool quiet = a.has("--quiet") || a.has("-q");

    // ---- usage checks (exit 2, nothing read or written) ----
    if (a.positional().size() != 1)
        return fail(cmd, a.positional().empty() ? "no input file" : "give exactly one input file", kUsage);
    const std::string input = a.positional()[0];
    if (a.has("-o") && a.has("--output")) return fail(cmd, "give -o or --output, not both", kUsage);
    const std::string out = a.has("-o") ? a.value("-o") : a.value("--output");
    if (out.empty()) return fail(cmd, "no output file: give -o OUT.csv", kUsage);
    const std::string crdOut = a.value("--crd-out"), nptOut = a.value("--npt-out");
    // Every output is checked before anything is computed or written: none may replace an
    // input or another output (same device and inode, whatever the spelling), devices and
    // folders are refused, and all are renamed into place together at the end.
    core::OutputSet outs;
    for (const char* in : {"--cpf", "--stations", "--preset"}) outs.addInput(a.value(in));
    outs.addInput(input);
    for (const std::string* p : {&out, &crdOut, &nptOut})
        if (!p->empty()) outs.addOutput(*p);
    if (int rc = checkOutputs(cmd, outs)) return rc;
    if (a.has("--cpf") && !a.has("--stations"))
        return fail(cmd, "--cpf and --stations go together (O-C from the prediction needs both)", kUsage);
    if (a.has("--satellite") && !a.has("--preset"))
        return fail(cmd, "--satellite selects a preset entry; give --preset FILE with it", kUsage);
    std::string err;
    long long passK = 0;
    if (!a.getInt("--pass", 1, 1000000, &passK, &err)) return fail(cmd, err, kUsage);
    {  // Bad options and config are usage errors before anything is read.
        slr::SlrParams probe = cliDefaults();
        if (int rc = params.apply(cmd, a, &probe)) return rc;
    }
    const bool csvInput = !slr::isCrdFile(input);
    if (csvInput && (!crdOut.empty() || !nptOut.empty()))
        return fail(cmd,
                    std::string(!crdOut.empty() ? "--crd-out" : "--npt-out") +
                        " needs a CRD input (its headers and records are written back); " + input +
                        " is an O-C table",
                    kUsage);
    if (csvInput && (a.has("--cpf") || a.has("--pass")))
        return fail(cmd, std::string(a.has("--cpf") ? "--cpf/--stations" : "--pass") + " apply to a CRD input; " +
                             input + " is an O-C table",
                    kUsage);

    // ---- presets (read before the pass so that a bad file stops early) ----
    std::vector<slr::SatellitePreset> presets;
    if (a.has("--preset")) {
        const slr::PresetsResult pr = slr::loadPresets(a.value("--preset"));
        if (!pr.ok) return fail(cmd, named(a.value("--preset"), pr.error));
        presets = pr.presets;
    }

    // ---- the pass ----
    slr::PassInputParams in;
    in.cpfPath = a.value("--cpf");
    if (a.has("--cpf")) in.sinexPath = a.value("--stations");
    const int passIndex = a.has("--pass") ? static_cast<int>(passK - 1) : -1;
    const slr::PassInputResult loaded = slr::loadPass(input, passIndex, in);
    if (!loaded.ok) {
        std::string msg = named(input, loaded.error);
        if (!csvInput && passIndex >= 0 && !loaded.passes.empty() && passIndex >= static_cast<int>(loaded.passes.size()))
            msg = input + ": --pass " + std::to_string(passK) + " asked for, the file holds " +
                  std::to_string(loaded.passes.size()) + " pass" + (loaded.passes.size() == 1 ? "" : "es") +
                  " (numbered from 1):" + passList(loaded.passes);
        else if (!csvInput && loaded.passes.size() > 1)
            msg += "\nThe passes of the file (--pass K):" + passList(loaded.passes);
        return fail(cmd, msg);
    }
    const slr::PassData& pass = loaded.pass;
    // A record of the pass to screen that the reader had to skip ("FILE:LINE: ..."): the point is
    // missing from the screening and the damaged line would be written back as it is. Refused.
    if (!pass.damaged.empty()) return fail(cmd, pass.damaged + "; nothing written");
    if (!quiet)
        for (const auto& w : loaded.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";

    // ---- parameters: defaults (automatic), preset, config file, options ----
    slr::SlrParams run = cliDefaults();
    run.postfit.altitudeKm = pass.altitudeKm;
    std::string presetName;
    if (a.has("--preset")) {
        const std::string want = a.value("--satellite");
        const slr::SatellitePreset* p =
            want.empty() ? slr::findPreset(presets, pass.satellite, pass.ilrsId) : slr::findPreset(presets, want, want);
        if (!p) {
            std::string have;
            const size_t shown = std::min<size_t>(presets.size(), 20);  // a long file is not dumped whole
            for (size_t k = 0; k < shown; ++k) {
                const auto& q = presets[k];
                have += (have.empty() ? "" : ", ") + core::printableExcerpt(q.name.empty() ? q.ilrsId : q.name) +
                        (q.ilrsId.empty() || q.name.empty() ? "" : " (" + core::printableExcerpt(q.ilrsId) + ")");
            }
            if (presets.size() > shown) have += ", ... and " + std::to_string(presets.size() - shown) + " more";
            std::string who = !want.empty() ? "\"" + want + "\""
                              : pass.satellite.empty() && pass.ilrsId.empty()
                                  ? std::string("(none: an O-C table names no satellite; give --satellite NAME)")
                                  : "\"" + pass.satellite + "\"" + (pass.ilrsId.empty() ? "" : " (ILRS id " + pass.ilrsId + ")");
            return fail(cmd, a.value("--preset") + ": no preset for satellite " + who + "; the file holds: " +
                                 (have.empty() ? "no entries" : have));
        }
        presetName = p->name.empty() ? p->ilrsId : p->name;
        const double alt = run.postfit.altitudeKm;
        run = {p->screen, p->postfit};
        if (!(run.postfit.altitudeKm > 0)) run.postfit.altitudeKm = alt;
    }
    // Normal-point context of a CRD pass: fire rate (C1), day or night (station from SINEX).
    std::vector<std::string> npNotes;
    if (pass.hasCrd) {
        slr::SinexReadResult snx;
        if (a.has("--stations")) {
            snx = slr::readSinex(a.value("--stations"));
            if (!snx.ok) return fail(cmd, named(a.value("--stations"), snx.error));
        }
        npNotes = slr::fillNormalPointContext(pass.crd.passes[size_t(pass.passIndex)], pass.cdpPad,
                                              snx.ok ? &snx.file : nullptr, &run.postfit);
        // Day or night unknown: the day minimum (6), unless a preset or an option says which
        // (the options are applied next and override this).
        if (!std::isfinite(run.postfit.stationLatDeg) && presetName.empty()) run.postfit.daylight = true;
    }
    if (int rc = params.apply(cmd, a, &run)) return rc;
    const slr::ScreenParams& sp = run.screen;
    slr::PostfitParams& pp = run.postfit;
    if (const std::string e = slr::validate(sp); !e.empty())
        return fail(cmd, (presetName.empty() ? std::string() : "preset " + presetName + ": ") + e, kUsage);
    std::string npNote;
    if (!(pp.binLengthS > 0) && !(pp.altitudeKm > 0)) {
        pp.normalPoints = false;
        npNote = "no normal points: the satellite's altitude is unknown (give --np-bin S or a preset with altitude_km)";
        if (!nptOut.empty()) return fail(cmd, npNote, kUsage);
    }
    if (const std::string e = slr::validate(pp); !e.empty()) return fail(cmd, e, kUsage);

    // ---- screening and post-fit ----
    const slr::ScreenResult s = slr::screenSignal(pass.t, pass.oc, sp);
    const std::string what = csvInput ? input : input + " pass " + std::to_string(pass.passIndex + 1);
    if (!s.ok) return fail(cmd, what + ": screening failed: " + s.error);
    const std::vector<uint8_t> accepted = slr::acceptedMask(s);
    size_t nAcc = 0;
    for (uint8_t v : accepted) nAcc += v;
    slr::PostfitResult post;
    bool postOk = false;
    if (nAcc >= 2) {
        post = slr::postfit(pass.t, pass.oc, accepted, pass.tof, pp);
        postOk = post.ok;
        if (!post.ok && !quiet) std::cerr << "laserwb-cli slr: warning: post-fit not done: " << post.error << "\n";
    } else if (!quiet) {
        std::cerr << "laserwb-cli slr: warning: post-fit not done: " << nAcc << " point(s) accepted\n";
    }
    if (!nptOut.empty() && (!postOk || post.normalPoints.empty()))
        return fail(cmd, what + ": no normal points to write to " + nptOut +
                             (postOk ? " (no bin holds the minimum number of kept points)" : " (no post-fit)"));

    // ---- outputs: all or nothing ----
    if (!slr::writeScreenCsv(outs.stagingPath(out), pass, s, accepted, postOk ? &post : nullptr, &err))
        return fail(cmd, named(out, outs.unstaged(err)));
    if (!crdOut.empty() && !slr::writeScreenedCrd(outs.stagingPath(crdOut), pass, accepted, &err))
        return fail(cmd, named(crdOut, outs.unstaged(err)));
    if (!nptOut.empty() && !slr::writeNormalPointCrd(outs.stagingPath(nptOut), pass, post.normalPoints, &err))
        return fail(cmd, named(nptOut, outs.unstaged(err)));
    if (int rc = commitOutputs(cmd, outs)) return rc;

    // ---- summary ----
    if (quiet) return kOk;
    for (const auto& w : s.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";
    if (postOk)
        for (const auto& w : post.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";
    auto mark = [](bool automatic) { return automatic ? " (auto)" : ""; };
    std::cerr << "slr: " << what;
    if (!pass.satellite.empty()) std::cerr << " (" << pass.satellite << (pass.station.empty() ? "" : " from " + pass.station) << ")";
    std::cerr << ": O-C from " << pass.ocOrigin << (presetName.empty() ? "" : "; preset " + presetName) << "\n"
              << "  points " << pass.t.size() << ", accepted " << nAcc << " (" << s.signalPoints << " signal + "
              << s.recoveredPoints << " recovered), noise " << s.noisePoints << "\n"
              << "  scale: mag_T " << core::formatDouble(s.magT, 4) << mark(s.autoMagT) << ", mag_OC "
              << core::formatDouble(s.magOc, 4) << mark(s.autoMagOc) << ", area limit " << s.areaLimit << mark(s.autoArea)
              << ", connectivity " << s.connectivity << mark(s.autoConnectivity) << ", C "
              << core::formatDouble(sp.cosineC, 4);
    if (!s.trials.empty()) std::cerr << "; " << s.trials.size() << " scales tried";
    std::cerr << "\n";
    if (postOk) {
        std::cerr << "  post-fit: degree " << post.degree << ", " << core::formatDouble(pp.rejectSigma, 3)
                  << "-sigma rejection removed " << post.rejected << " of " << post.used << ", RMS "
                  << ps(post.stats.rms) << " (" << core::formatFixed(post.stats.rms * 0.5 * 299792458.0 * 1e3, 1)
                  << " mm one-way)\n";
        if (pp.normalPoints)
            std::cerr << "  normal points: " << post.normalPoints.size() << " (bins of "
                      << core::formatDouble(post.binLengthS, 4) << " s, at least " << post.minPointsPerBin << " points"
                      << (post.dayBins + post.nightBins ? " (" + std::to_string(post.dayBins) + " day, " +
                                                              std::to_string(post.nightBins) + " night bins)"
                                                        : std::string(pp.daylight ? " (day)" : " (night)"))
                      << (post.binsTooSmall ? ", " + std::to_string(post.binsTooSmall) + " bins too small" : "") << ")\n";
        else
            std::cerr << "  " << npNote << "\n";
        if (pp.normalPoints)
            for (const auto& note : npNotes) std::cerr << "  " << note << "\n";
    }
    // Against the station's own filter flags, when the file carries them.
    long long f1 = 0, f2 = 0;
    for (int f : pass.stationFlag) {
        f1 += f == 1;
        f2 += f == 2;
    }
    if (f2 > 0 && f1 + f2 == static_cast<long long>(pass.stationFlag.size())) {
        long long tp = 0, fp = 0, keptTp = 0, keptFp = 0;
        for (size_t i = 0; i < accepted.size(); ++i) {
            const bool sig = pass.stationFlag[i] == 2;
            tp += accepted[i] && sig;
            fp += accepted[i] && !sig;
            if (postOk) {
                keptTp += post.kept[i] && sig;
                keptFp += post.kept[i] && !sig;
            }
        }
        auto f4 = [](double v) { return core::formatFixed(v, 4); };
        std::cerr << "  against the station's filter flags (" << f2 << " data, " << f1 << " noise): screening precision "
                  << f4(tp + fp ? double(tp) / double(tp + fp) : 0) << ", recall " << f4(double(tp) / double(f2));
        if (postOk)
            std::cerr << "; after post-fit precision " << f4(keptTp + keptFp ? double(keptTp) / double(keptTp + keptFp) : 0)
                      << ", recall " << f4(double(keptTp) / double(f2));
        std::cerr << "\n";
    } else if (f2 > 0) {
        std::cerr << "  the station's filter flags are incomplete (some 0 = unknown): no comparison\n";
    }
    std::cerr << "  -> " << out << (crdOut.empty() ? "" : ", " + crdOut) << (nptOut.empty() ? "" : ", " + nptOut) << "\n";
    return kOk;
}

}  // namespace lwb::cli
