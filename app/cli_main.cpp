// laserwb-cli: the batch side of Laser Workbench. Every subcommand prints its own --help.
//
// Built twice. laserwb-cli runs the SLR commands itself and is linked without OpenCV; for the
// imaging commands (footprint, trend, calibration, radiometry, their simulate / eval / bench,
// demo) it executes laserwb-cli-imaging, built from this file with LWB_CLI_IMAGING, which lies
// beside it and runs them. Loading OpenCV and the libraries it pulls in (LAPACK, TBB, X11, ...)
// was 13 of the 19 ms an SLR run took to start.
#include <csignal>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <climits>
#include <cstring>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/common/allocator.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/common/install_paths.hpp"
#include "lwb_version.hpp"
#include "cli_commands.hpp"
#include "cli_common.hpp"

namespace {
const char* kMainUsage =
    "usage: laserwb-cli COMMAND [options]\n"
    "Laser Workbench batch tool (footprint spot centres, SLR signal extraction, calibration).\n"
    "\n"
    "Footprint camera:\n"
    "  footprint            spot centre + verdict for frames/ROIs -> CSV\n"
    "  footprint tune       verdict criteria tuned from the analyst's verdicts -> config JSON\n"
    "  trend                monthly centroid means, pointing change, beam distance -> CSV\n"
    "  simulate footprint   simulated shots with exact truth\n"
    "  simulate trend       a simulated centroid table (both beams, months) with exact truth\n"
    "  eval footprint       accuracy experiment on the simulator (Markdown table)\n"
    "  bench footprint      ROIs per second per method\n"
    "\n"
    "SLR signal extraction (paper 004):\n"
    "  slr                  screen a pass (CRD or O-C CSV): signal/noise per point, post-fit, normal\n"
    "                       points -> CSV, CRD with filter flags, CRD normal points\n"
    "  simulate slr         a simulated pass (O-C CSV or CRD) with exact truth per point\n"
    "  bench slr            parse + screen + post-fit times and peak memory, 10^4..10^6 points\n"
    "  crd check            check CRD files record by record against the format (FILE:LINE: reason)\n"
    "\n"
    "Altimeter calibration (paper 002):\n"
    "  calib detector       footprint centre from a ground detector array (Gaussian surface + ellipse)\n"
    "  calib waveform       feature height from a double-peak waveform; matching surveyed feature\n"
    "  calib pointing       pointing corrections and range biases from control points\n"
    "  calib stats          labelled validation statistics of elevation differences\n"
    "  simulate calib       simulated calibration inputs with exact truth\n"
    "\n"
    "Radiometry, zero stadia standard image (paper 003):\n"
    "  radiometry mosaic    stitch the overlapping frames of a row\n"
    "  radiometry gcp       geometric correction by ground control points\n"
    "  radiometry fit       DN -> reflectance line from marked regions, with uncertainty\n"
    "  radiometry apply     reflectance image (32-bit float TIFF) and relative-error check\n"
    "  radiometry check     relative errors of simulated vs measured reflectance\n"
    "  simulate radiometry  the frames of a row, grey panels, check surfaces and control points\n"
    "\n"
    "Other:\n"
    "  demo                 a short end-to-end run on simulated data\n"
    "  version              print the version\n"
    "\n"
    "'laserwb-cli COMMAND --help' (or 'laserwb-cli help COMMAND') describes each command;\n"
    "'laserwb-cli COMMAND --version' prints the version.\n";

#ifdef LWB_CLI_IMAGING
int demo(int argc, char** argv);
#else
// The commands laserwb-cli-imaging runs.
bool isImagingCommand(const std::string& cmd, const std::string& sub) {
    if (cmd == "footprint" || cmd == "trend" || cmd == "demo") return true;
    if (cmd == "simulate" || cmd == "eval" || cmd == "bench")
        return sub == "footprint" || (cmd == "simulate" && (sub == "calib" || sub == "trend" || sub == "radiometry"));
    if (cmd == "calib") return sub == "detector" || sub == "waveform" || sub == "pointing" || sub == "stats";
    if (cmd == "radiometry") return sub == "mosaic" || sub == "gcp" || sub == "fit" || sub == "apply" || sub == "check";
    return false;
}

// Runs laserwb-cli-imaging (beside this program in the build tree, in libexec/laserwb/ when
// installed) with the same arguments, in this process's place; returns only when it cannot be
// started.
int runImaging(int argc, char** argv) {
    std::vector<char*> args(argv, argv + argc);
    args.push_back(nullptr);
    std::cout.flush();
    std::string tried;
    for (const std::string& helper : lwb::core::helperCandidates("laserwb-cli-imaging")) {
        if (access(helper.c_str(), X_OK) != 0) {
            tried += (tried.empty() ? "" : ", ") + helper + " (" + std::strerror(errno) + ")";
            continue;
        }
        execv(helper.c_str(), args.data());
        tried += (tried.empty() ? "" : ", ") + helper + " (" + std::strerror(errno) + ")";
    }
    return lwb::cli::fail(argv[1], "this command runs laserwb-cli-imaging, which could not be started: tried " + tried +
                                       " (it is built beside laserwb-cli and installed in libexec/laserwb/)");
}
#endif
}  // namespace

namespace {
int dispatch(int argc, char** argv);
}

// Last resort: an exception escaping a command (out of memory, say) is reported, not a crash.
int main(int argc, char** argv) {
    lwb::core::reexecWithHugePages(argv);
    lwb::core::tuneAllocator();
    // A reader of standard output that went away is an error the output set reports (and rolls
    // the run's files back for), not a signal that kills the process half-way (exit 141).
    std::signal(SIGPIPE, SIG_IGN);
    try {
        return dispatch(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "laserwb-cli: internal error: " << e.what() << " (nothing more was written)\n";
        return lwb::cli::kFailed;
    }
}

namespace {
// The commands and the kinds of those that take one (for "did you mean").
const std::vector<std::string> kCommands = {"footprint", "trend", "slr", "crd", "simulate", "eval", "bench",
                                            "calib", "radiometry", "demo", "version", "help"};
const char* kindsOf(const std::string& cmd) {
    if (cmd == "calib") return "detector, waveform, pointing, stats";
    if (cmd == "radiometry") return "mosaic, gcp, fit, apply, check";
    if (cmd == "simulate") return "footprint, trend, slr, calib, radiometry";
    if (cmd == "bench") return "footprint, slr";
    if (cmd == "eval") return "footprint";
    return nullptr;
}

// "unknown kind "X" (a, b, c)" with the nearest kind when one is near.
std::string unknownKind(const std::string& sub, const char* kinds) {
    std::vector<std::string> names;
    for (std::string_view rest = kinds; !rest.empty();) {
        const size_t comma = rest.find(',');
        names.emplace_back(lwb::core::trim(rest.substr(0, comma)));
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    }
    return "unknown kind \"" + sub + "\" (" + kinds + ")" + lwb::core::didYouMean(sub, names);
}

int dispatch(int argc, char** argv) {
    using namespace lwb::cli;
    // help CMD [KIND]: CMD [KIND] --help.
    if (argc >= 3 && !std::strcmp(argv[1], "help")) {
        std::vector<char*> again{argv[0]};
        for (int i = 2; i < argc && i < 4; ++i) again.push_back(argv[i]);
        static char helpFlag[] = "--help";
        again.push_back(helpFlag);
        again.push_back(nullptr);
        return dispatch(static_cast<int>(again.size()) - 1, again.data());
    }
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
        std::cout << kMainUsage;
        return argc < 2 ? kUsage : kOk;
    }
    // CMD --version, CMD KIND --version: the program's version (every command is of one build).
    for (int i = 2; i < argc && i < 4 && argv[i][0] != '\0'; ++i) {
        if (!std::strcmp(argv[i], "--version")) {
            std::cout << "laserwb-cli " LWB_VERSION "\n";
            return kOk;
        }
        if (argv[i][0] == '-') break;
    }
    const std::string cmd = argv[1];
    const std::string sub = argc > 2 ? argv[2] : "";
#ifndef LWB_CLI_IMAGING
    if (cmd == "slr") return cmdSlr(argc, argv);
    if (cmd == "simulate" && sub == "slr") return cmdSimulateSlr(argc, argv);
    if (cmd == "bench" && sub == "slr") return cmdBenchSlr(argc, argv);
    if (cmd == "crd") return cmdCrd(argc, argv);
    if (isImagingCommand(cmd, sub)) return runImaging(argc, argv);
#else
    if (cmd == "footprint") return cmdFootprint(argc, argv);
    if (cmd == "trend") return cmdTrend(argc, argv);
    if (cmd == "simulate" && sub == "footprint") return cmdSimulateFootprint(argc, argv);
    if (cmd == "eval" && sub == "footprint") return cmdEvalFootprint(argc, argv);
    if (cmd == "bench" && sub == "footprint") return cmdBenchFootprint(argc, argv);
    if (cmd == "calib" && sub == "detector") return cmdCalibDetector(argc, argv);
    if (cmd == "calib" && sub == "waveform") return cmdCalibWaveform(argc, argv);
    if (cmd == "calib" && sub == "pointing") return cmdCalibPointing(argc, argv);
    if (cmd == "calib" && sub == "stats") return cmdCalibStats(argc, argv);
    if (cmd == "simulate" && sub == "calib") return cmdSimulateCalib(argc, argv);
    if (cmd == "simulate" && sub == "trend") return cmdSimulateTrend(argc, argv);
    if (cmd == "simulate" && sub == "radiometry") return cmdSimulateRadiometry(argc, argv);
    if (cmd == "radiometry" && sub == "mosaic") return cmdRadiometryMosaic(argc, argv);
    if (cmd == "radiometry" && sub == "gcp") return cmdRadiometryGcp(argc, argv);
    if (cmd == "radiometry" && sub == "fit") return cmdRadiometryFit(argc, argv);
    if (cmd == "radiometry" && sub == "apply") return cmdRadiometryApply(argc, argv);
    if (cmd == "radiometry" && sub == "check") return cmdRadiometryCheck(argc, argv);
    if (cmd == "demo") return demo(argc, argv);
    if (cmd == "slr" || cmd == "crd" || ((cmd == "simulate" || cmd == "bench") && sub == "slr"))
        return fail(cmd, "the SLR commands are run by laserwb-cli itself, not by laserwb-cli-imaging", kUsage);
#endif
    if (cmd == "version" || cmd == "--version") {
        std::cout << "laserwb-cli " LWB_VERSION "\n";
        return kOk;
    }
    if (const char* kinds = kindsOf(cmd)) {
        if (sub == "--help" || sub == "-h") {
            std::cout << "usage: laserwb-cli " << cmd << " (" << kinds << ") [options]; each has --help\n";
            return kOk;
        }
        return fail(cmd, sub.empty() ? std::string("which one? (") + kinds + ")" : unknownKind(sub, kinds), kUsage);
    }
    std::cerr << "laserwb-cli: unknown command \"" << cmd << "\"" << lwb::core::didYouMean(cmd, kCommands) << "\n\n"
              << kMainUsage;
    return kUsage;
}
}  // namespace

#ifdef LWB_CLI_IMAGING
namespace {
// Simulates a few shots into a temporary folder, runs the footprint command on them and
// prints the report (a quick check of an installation without a display).
int demo(int argc, char** argv) {
    using namespace lwb::cli;
    Args a("demo",
           "usage: laserwb-cli demo\n"
           "Simulates 12 footprint shots (weak, moderate, strong and night ground) in a new temporary folder,\n"
           "finds their spot centres with the default method and prints the truth beside the report: a quick\n"
           "check of an installation without a display. Writes nothing outside that folder.\n");
    if (int rc = a.parseWithHelp(argc, argv, 2); rc >= 0) return rc;
    if (!a.positional().empty()) return fail("demo", "takes no arguments", kUsage);
    std::string dir = "/tmp/laserwb-demo-XXXXXX";
    if (!mkdtemp(dir.data())) return fail("demo", "cannot create a temporary folder");
    std::cout << "Simulating 12 footprint shots (weak, moderate, strong, night) in " << dir << " ...\n";
    std::string a0 = "laserwb-cli", a1 = "simulate", a2 = "footprint", a3 = "--count", a4 = "12", a5 = "--case",
                a6 = "mixed", a7 = "-q";
    char* sim[] = {a0.data(), a1.data(), a2.data(), a3.data(), a4.data(), a5.data(), a6.data(), a7.data(), dir.data()};
    if (int rc = cmdSimulateFootprint(9, sim)) return rc;
    std::string out = dir + "/report.csv", o = "-o", fp = "footprint";
    char* run[] = {a0.data(), fp.data(), dir.data(), o.data(), out.data()};
    if (int rc = cmdFootprint(5, run)) return rc;
    // Truth beside the report, shot by shot (the report's quoted reasons may hold commas: read
    // as CSV, not cut at commas).
    const lwb::core::CsvReadResult truth = lwb::core::readCsv(dir + "/truth.csv"), report = lwb::core::readCsv(out);
    if (!truth.ok || !report.ok) return fail("demo", !truth.ok ? truth.error : report.error);
    const lwb::core::CsvTable& t = truth.table;
    const lwb::core::CsvTable& r = report.table;
    const int tf = t.column("file"), tx = t.column("x"), ty = t.column("y"), tc = t.column("case"), ts = t.column("scene");
    const int rx = r.column("x"), ry = r.column("y"), rv = r.column("verdict"), rr = r.column("reasons");
    std::printf("\n%-16s %-9s %-11s %-20s %-20s %-9s %s\n", "shot", "ground", "case", "true centre", "found centre",
                "error px", "verdict (reasons)");
    for (size_t i = 0; i < t.rows.size() && i < r.rows.size(); ++i) {
        const auto& a = t.rows[i];
        const auto& b = r.rows[i];
        auto centre = [](const std::string& x, const std::string& y) { return x.empty() ? std::string("-") : x + ", " + y; };
        double e = NAN;
        try {
            if (!a[tx].empty() && !b[rx].empty()) e = std::hypot(std::stod(a[tx]) - std::stod(b[rx]), std::stod(a[ty]) - std::stod(b[ry]));
        } catch (const std::exception&) {
        }
        std::string why = b[rr].size() > 60 ? b[rr].substr(0, 57) + "..." : b[rr];
        std::printf("%-16s %-9s %-11s %-20s %-20s %-9s %s%s\n", a[tf].c_str(), a[ts].c_str(), a[tc].c_str(),
                    centre(a[tx], a[ty]).c_str(), centre(b[rx], b[ry]).c_str(),
                    std::isfinite(e) ? lwb::core::formatFixed(e, 3).c_str() : "-", b[rv].c_str(),
                    why.empty() ? "" : (" (" + why + ")").c_str());
    }
    std::printf("\nThe shots, truth.csv and report.csv stay in %s (remove it when done).\n", dir.c_str());
    return kOk;
}
}  // namespace
#endif
