// laserwb-cli slr tune: a satellite's screening and post-fit parameters chosen from a station's
// own decisions (its filter flags), written as that satellite's preset entry (core/slr/tune).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli_commands.hpp"
#include "cli_common.hpp"
#include "core/common/text.hpp"
#include "core/slr/tune.hpp"

namespace lwb::cli {

namespace slr = core::slr;

namespace {

const char* kTuneUsage =
    "usage: laserwb-cli slr tune [options] PASS... --preset-out FILE.json\n"
    "Chooses a satellite's parameters from the station's own decisions: every pass of the CRD files\n"
    "(their filter flags, 2 data and 1 noise, are the labels), and every O-C table with a station_flag\n"
    "column (what `laserwb-cli slr CRD -o OUT.csv` writes; with --satellite: a table does not name its\n"
    "satellite) is screened with each candidate, the\n"
    "starting point (the command's defaults, or the satellite's entry of --preset) and a grid over the\n"
    "screening's cosine constant (0.90-0.99), the post-fit's rejection k (2.5, 3, 3.5) and whether its\n"
    "band takes the image's leftovers. The candidate with the best mean F1 of the delivered flags\n"
    "against the labels is chosen (another than the starting point only when it is better by more than\n"
    "0.001 and worse on no pass by more than 0.002); leave-one-pass-out says how the choice holds on a\n"
    "pass it was not chosen on, and a choice that holds out no better than the starting point is not\n"
    "made (the starting point stays, with a note). The choice is\n"
    "written as the satellite's entry of FILE.json (the workbench's presets format: other entries kept),\n"
    "with FILE.json.provenance.json (the passes, their labels, F1 before, after and held out).\n"
    "A pass without labels (every flag 0, or none flagged data) is refused with the reason.\n"
    "PASS may be a folder (a station's archive): its CRD files are read, and a file that does not read or\n"
    "a pass without labels there is left out with its reason (a note) instead of refused.\n"
    "  --preset-out FILE.json  the presets file to write the entry into (required)\n"
    "  --session FILE.json     a workbench session (repeatable): its SLR pass, labelled with the analyst's\n"
    "                          decisions (the session's run with the points forced in or out by hand)\n"
    "  --cpf FILE|DIR          the O-C of the CRD passes from this prediction (a file or a folder of them),\n"
    "  --stations FILE.snx     with the station's coordinates (needed with --cpf), as for slr: the passes are\n"
    "                          tuned on the O-C they are screened on\n"
    "  --cpf-fallback          a CPF that does not fit a pass: its own TOF trend, with a note (as for slr)\n"
    "  --satellite NAME        only the passes of this satellite (required when the files hold several)\n"
    "  --preset FILE.json      start from the satellite's entry of this presets file\n"
    "  --threads N             threads of the scale search (0: every core, the default)\n"
    "  -q, --quiet             no table, no progress\n"
    "Then: laserwb-cli slr PASS --preset FILE.json applies it.\n"
    "Exit status: 0 written, 1 a file could not be read or written, 2 usage (no passes, no labels' source).\n";

}  // namespace

int cmdSlrTune(int argc, char** argv) {
    const std::string cmd = "slr tune";
    Args a(cmd, kTuneUsage);
    for (const char* o : {"--preset-out", "--satellite", "--preset", "--threads", "--cpf", "--stations"}) a.option(o, true);
    a.option("--session", true, true);
    for (const char* o : {"--quiet", "-q", "--help", "-h", "--cpf-fallback"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kTuneUsage;
        return kOk;
    }
    const bool quiet = a.has("--quiet") || a.has("-q");
    slr::TuneSources src;
    src.files = a.positional();
    src.sessions = a.values("--session");
    src.satellite = a.value("--satellite");
    src.presets = a.value("--preset");
    src.cpf = a.value("--cpf");
    src.stations = a.value("--stations");
    src.cpfFallback = a.has("--cpf-fallback");
    if (a.has("--cpf") && !a.has("--stations"))
        return fail(cmd, "--cpf and --stations go together (O-C from the prediction needs both)", kUsage);
    const std::string out = a.value("--preset-out");
    long long threads = 0;
    std::string err;
    if (!a.getInt("--threads", 0, 256, &threads, &err)) return fail(cmd, err, kUsage);
    src.threads = static_cast<int>(threads);
    if (src.files.empty() && src.sessions.empty())
        return fail(cmd, "no CRD files or sessions given (the passes whose station flags, or the analyst's edits, are the labels)",
                    kUsage);
    if (out.empty()) return fail(cmd, "--preset-out FILE.json is required (where the tuned entry is written)", kUsage);
    Progress progress("slr tune", 1000, quiet);
    core::Feedback fb([&](double f) { progress.update(static_cast<size_t>(f * 1000)); });
    const slr::TuneResult r = slr::tuneSlr(src, &fb);
    progress.finish();
    if (!r.ok) return fail(cmd, r.error.message, r.error.usage ? kUsage : kFailed);
    if (!quiet) {
        for (const std::string& n : r.notes) std::cerr << "laserwb-cli slr tune: note: " << n << "\n";
        const slr::TuneCandidate& best = r.candidates[r.best];
        std::cout << r.satellite << ": " << r.passes.size() << " labelled pass" << (r.passes.size() == 1 ? "" : "es") << ", "
                  << r.candidates.size() << " candidates\n"
                  << "  chosen: " << best.label << "\n"
                  << "  mean F1 against the station's flags: " << core::formatFixed(r.candidates[0].meanF1, 4) << " before, "
                  << core::formatFixed(best.meanF1, 4) << " after, " << core::formatFixed(r.heldOutMeanF1, 4)
                  << " held out (leave one pass out)\n";
        std::vector<size_t> order(r.candidates.size());
        for (size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return r.candidates[x].meanF1 > r.candidates[y].meanF1; });
        std::cout << "  the best candidates (mean F1):\n";
        for (size_t i = 0; i < std::min<size_t>(5, order.size()); ++i)
            std::cout << "    " << core::formatFixed(r.candidates[order[i]].meanF1, 4) << "  " << r.candidates[order[i]].label << "\n";
        for (const slr::TunedPass& p : r.passes)
            std::cout << "  " << p.name << ": " << p.points << " points, " << p.labelledSignal << " flagged data; F1 "
                      << core::formatFixed(p.scores[0].f1, 4) << " -> " << core::formatFixed(p.scores[r.best].f1, 4)
                      << ", held out " << core::formatFixed(p.heldOutF1, 4) << "\n";
    }
    std::string note;
    if (!slr::writeTunedPreset(r, src, out, &err, &note)) return fail(cmd, err);
    if (!quiet) std::cerr << "  -> " << out << ": " << note << "\n";
    return kOk;
}

}  // namespace lwb::cli
