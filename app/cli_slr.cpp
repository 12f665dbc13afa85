// laserwb-cli slr: screen one SLR pass (paper 004 binary image, automatic mode by default),
// post-fit with k-sigma rejection and ILRS normal points; per-point CSV, CRD full rate with
// filter flags and CRD normal points. The loading and writing is core/slr/pass_input.hpp, the
// layer the SLR workspace of the GUI uses too.
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
#include "core/slr/screen.hpp"

namespace lwb::cli {

namespace slr = core::slr;

namespace {

const char* kSlrUsage =
    "usage: laserwb-cli slr INPUT [options] -o OUT.csv [--crd-out FILE] [--npt-out FILE]\n"
    "Screens one SLR pass: signal extraction by binary image (paper 004; automatic scale by default),\n"
    "then a trend fit with k-sigma rejection and ILRS normal points. A summary goes to stderr.\n"
    "INPUT: a CRD file (.frd .fr2 .npt .np2 .crd; v1 or v2) or an O-C CSV (header with epoch_s,oc_s;\n"
    "       epoch in s, O-C in s of two-way time of flight).\n"
    "  --cpf FILE --stations SINEX   O-C of a CRD pass from this CPF prediction and these station\n"
    "                        coordinates (--cpf needs --stations); without --cpf, O-C against a robust\n"
    "                        trend of the pass's own time of flight (a range bias and a smooth drift\n"
    "                        are absorbed). --stations alone: the station's position for day or night\n"
    "                        (the Sun's elevation per normal-point bin: at least 6 points by day, 3 by\n"
    "                        night); without it a CRD pass gets the day minimum of 6\n"
    "  --pass K              pass number in the CRD file, 1-based (1 = the first pass of the file);\n"
    "                        default: the first pass with full-rate (type 10) records\n"
    "Screening (automatic by default; each option below replaces only its own parameter):\n"
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

struct Staged {
    std::string finalPath, stagePath;
};

// Output files are first written (each atomically) under a staging name beside the target and
// renamed into place only when every one of them was written: a failed run leaves none.
// An output path that can be created or replaced: not a folder, in a folder that exists and
// that we may write to. False with *why.
bool outputWritable(const std::string& path, std::string* why) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        *why = "is a folder";
        return false;
    }
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    if (::access(dir.c_str(), W_OK) != 0) {
        *why = "cannot write in " + dir + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

class Outputs {
public:
    std::string stage(const std::string& finalPath) {
        const size_t slash = finalPath.find_last_of('/');
        const std::string dir = slash == std::string::npos ? "" : finalPath.substr(0, slash + 1);
        const std::string base = slash == std::string::npos ? finalPath : finalPath.substr(slash + 1);
        const std::string st = dir + "." + base + ".lwb-stage-" + std::to_string(::getpid());
        m_files.push_back({finalPath, st});
        return st;
    }
    bool commit(std::string* error) {
        for (size_t i = 0; i < m_files.size(); ++i) {
            if (std::rename(m_files[i].stagePath.c_str(), m_files[i].finalPath.c_str()) != 0) {
                *error = "cannot write " + m_files[i].finalPath + ": " + std::strerror(errno);
                for (size_t j = i; j < m_files.size(); ++j) std::remove(m_files[j].stagePath.c_str());
                m_files.clear();
                return false;
            }
        }
        m_files.clear();
        return true;
    }
    ~Outputs() {
        for (const auto& f : m_files) std::remove(f.stagePath.c_str());
    }

private:
    std::vector<Staged> m_files;
};

std::string ps(double s) { return core::formatFixed(s * 1e12, 1) + " ps"; }

}  // namespace

int cmdSlr(int argc, char** argv) {
    const std::string cmd = "slr";
    Args a(cmd, kSlrUsage);
    for (const char* o : {"--cpf", "--stations", "--satellite", "--mag-t", "--mag-oc", "--area-min", "--connectivity",
                          "--cos-c", "--preset", "--pass", "--reject", "--np-bin", "-o", "--output", "--crd-out",
                          "--npt-out"})
        a.option(o, true);
    for (const char* o : {"--quiet", "-q", "--help", "-h"}) a.option(o, false);
    if (!a.parse(argc, argv, 2)) return fail(cmd, a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kSlrUsage;
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
    {
        std::set<std::string> seen = {input};
        for (const std::string* p : {&out, &crdOut, &nptOut}) {
            if (p->empty() && p != &out) continue;
            if (!seen.insert(*p).second)
                return fail(cmd, *p == input ? "an output would overwrite the input " + input
                                             : "two outputs name the same file " + *p,
                            kUsage);
        }
    }
    // Every output must be writable before anything is computed or written, so that a failure
    // cannot leave one output renamed into place and another missing.
    for (const std::string* p : {&out, &crdOut, &nptOut}) {
        if (p->empty()) continue;
        std::string why;
        if (!outputWritable(*p, &why)) return fail(cmd, *p + ": " + why + " (nothing written)");
    }
    if (a.has("--cpf") && !a.has("--stations"))
        return fail(cmd, "--cpf and --stations go together (O-C from the prediction needs both)", kUsage);
    if (a.has("--satellite") && !a.has("--preset"))
        return fail(cmd, "--satellite selects a preset entry; give --preset FILE with it", kUsage);
    std::string err;
    long long passK = 0, area = 0, conn = 0;
    double magT = 0, magOc = 0, cosC = 0, reject = 3, npBin = 0;
    if (!a.getInt("--pass", 1, 1000000, &passK, &err) || !a.getDouble("--mag-t", 1e-9, 1e15, &magT, &err) ||
        !a.getDouble("--mag-oc", 1e-9, 1e18, &magOc, &err) || !a.getInt("--area-min", 1, 1000000, &area, &err) ||
        !a.getDouble("--cos-c", 0.5, 0.999999999, &cosC, &err) || !a.getDouble("--reject", 0, 10, &reject, &err) ||
        !a.getDouble("--np-bin", 0.1, 86400, &npBin, &err))
        return fail(cmd, err, kUsage);
    if (a.has("--connectivity")) {
        const std::string c = a.value("--connectivity");
        if (c != "4" && c != "8") return fail(cmd, "--connectivity must be 4 or 8, not \"" + c + "\"", kUsage);
        conn = c == "4" ? 4 : 8;
    }
    if (a.has("--reject") && reject > 0 && reject < 1)
        return fail(cmd, "--reject must be 0 (off) or 1..10 (2.5 single-photon, 3 multi-photon), not " + a.value("--reject"),
                    kUsage);
    const bool csvInput = !slr::isCrdPath(input);
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
    if (pass.hasCrd) {
        // The reader lists the skipped lines of each pass whether or not its warning list is full.
        const auto& skipped = pass.crd.passes[static_cast<size_t>(pass.passIndex)].skippedLines;
        if (!skipped.empty()) {
            std::string why = input + ":" + std::to_string(skipped.front()) + ": a damaged record";
            for (const auto& w : loaded.warnings)
                if (w.rfind(input + ":" + std::to_string(skipped.front()) + ":", 0) == 0) why = w;
            return fail(cmd, why + " (" + std::to_string(skipped.size()) +
                                 " damaged record(s) in the pass to screen: repair or remove them; nothing written)");
        }
    }
    if (!quiet)
        for (const auto& w : loaded.warnings) std::cerr << "laserwb-cli slr: warning: " << w << "\n";

    // ---- parameters: defaults (automatic), preset, explicit options ----
    slr::ScreenParams sp;
    slr::PostfitParams pp;
    pp.rejectSigma = 3;
    pp.altitudeKm = pass.altitudeKm;
    std::string presetName;
    if (a.has("--preset")) {
        const std::string want = a.value("--satellite");
        const slr::SatellitePreset* p =
            want.empty() ? slr::findPreset(presets, pass.satellite, pass.ilrsId) : slr::findPreset(presets, want, want);
        if (!p) {
            std::string have;
            for (const auto& q : presets)
                have += (have.empty() ? "" : ", ") + (q.name.empty() ? q.ilrsId : q.name) +
                        (q.ilrsId.empty() || q.name.empty() ? "" : " (" + q.ilrsId + ")");
            std::string who = !want.empty() ? "\"" + want + "\""
                              : pass.satellite.empty() && pass.ilrsId.empty()
                                  ? std::string("(none: an O-C table names no satellite; give --satellite NAME)")
                                  : "\"" + pass.satellite + "\"" + (pass.ilrsId.empty() ? "" : " (ILRS id " + pass.ilrsId + ")");
            return fail(cmd, a.value("--preset") + ": no preset for satellite " + who + "; the file holds: " +
                                 (have.empty() ? "no entries" : have));
        }
        presetName = p->name.empty() ? p->ilrsId : p->name;
        sp = p->screen;
        const double alt = pp.altitudeKm;
        pp = p->postfit;
        if (!(pp.altitudeKm > 0)) pp.altitudeKm = alt;
    }
    if (a.has("--mag-t")) sp.magT = magT;
    if (a.has("--mag-oc")) sp.magOc = magOc;
    if (a.has("--area-min")) sp.areaLimit = static_cast<int>(area);
    if (a.has("--connectivity")) sp.connectivity = static_cast<int>(conn);
    if (a.has("--cos-c")) sp.cosineC = cosC;
    if (a.has("--reject")) pp.rejectSigma = reject;
    if (a.has("--np-bin")) pp.binLengthS = npBin;
    // Normal-point context of a CRD pass: fire rate (C1), day or night (station from SINEX).
    std::vector<std::string> npNotes;
    if (pass.hasCrd) {
        slr::SinexReadResult snx;
        if (a.has("--stations")) {
            snx = slr::readSinex(a.value("--stations"));
            if (!snx.ok) return fail(cmd, named(a.value("--stations"), snx.error));
        }
        npNotes = slr::fillNormalPointContext(pass.crd.passes[size_t(pass.passIndex)], pass.cdpPad,
                                              snx.ok ? &snx.file : nullptr, &pp);
        // Day or night unknown: the day minimum (6), unless a preset says which.
        if (!std::isfinite(pp.stationLatDeg) && presetName.empty()) pp.daylight = true;
    }
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
    Outputs outs;
    if (!slr::writeScreenCsv(outs.stage(out), pass, s, accepted, postOk ? &post : nullptr, &err))
        return fail(cmd, out + ": " + err);
    if (!crdOut.empty() && !slr::writeScreenedCrd(outs.stage(crdOut), pass, accepted, &err))
        return fail(cmd, crdOut + ": " + err);
    if (!nptOut.empty() && !slr::writeNormalPointCrd(outs.stage(nptOut), pass, post.normalPoints, &err))
        return fail(cmd, nptOut + ": " + err);
    if (!outs.commit(&err)) return fail(cmd, err);

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
