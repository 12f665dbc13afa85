// laserwb-cli simulate slr | bench slr (paper 004 signal extraction, post-fit, normal points).
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_commands.hpp"
#include "cli_common.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/parallel.hpp"
#include "core/common/provenance.hpp"
#include "core/common/text.hpp"
#include "core/sim/slr_sim.hpp"
#include "core/slr/oc_csv.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"

namespace lwb::cli {

namespace sim = core::sim;
namespace slr = core::slr;

namespace {

// Shortest round-trip text of a double.
void putDouble(std::string& out, double v) {
    char buf[32];  // the shortest round-trip form of any double takes at most 24 characters
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    if (r.ec == std::errc()) out.append(buf, r.ptr);
}

// Writes a simulated pass as CSV, atomically. Columns: epoch_s,oc_s,truth[,track_oc_s,tof_s].
bool writePassCsv(const std::string& path, const sim::SlrSimPass& pass, bool full, std::string* error) {
    core::AtomicFile f(path);
    if (!f.ok()) {
        *error = f.error();
        return false;
    }
    std::string buf = full ? "epoch_s,oc_s,truth,track_oc_s,tof_s\n" : "epoch_s,oc_s,truth\n";
    for (size_t i = 0; i < pass.epochS.size(); ++i) {
        putDouble(buf, pass.epochS[i]);
        buf.push_back(',');
        putDouble(buf, pass.ocS[i]);
        buf += pass.isSignal[i] ? ",1" : ",0";
        if (full) {
            buf.push_back(',');
            putDouble(buf, pass.trackOcS[i]);
            buf.push_back(',');
            putDouble(buf, pass.tofS[i]);
        }
        buf.push_back('\n');
        if (buf.size() > (1u << 20)) {
            f.stream() << buf;
            buf.clear();
        }
    }
    f.stream() << buf;
    if (!f.commit()) {
        *error = f.error();
        return false;
    }
    return true;
}

const char* kSimUsage =
    "usage: laserwb-cli simulate slr [--kind khz|conventional|diffuse|leo|daylight|dayspad] [--points N]\n"
    "                                [--duration S] [--signal-fraction F] [--day|--night] [--drift NS_PER_S]\n"
    "                                [--curvature NS_PER_S2] [--gaps LIST] --seed S OUT.csv|OUT.frd\n"
    "Simulates one SLR pass with exact truth: O-C = b + (2/c)·rho'(t)·tau (range bias b, time bias tau,\n"
    "range rate of a straight-line flyby) + jitter, and noise uniform over the range gate.\n"
    "OUT.csv columns: epoch_s (s of day), oc_s (two-way O-C, s), truth (1 signal, 0 noise),\n"
    "track_oc_s (the exact model O-C at that epoch), tof_s (observed two-way time of flight, s).\n"
    "Readers of epoch_s,oc_s ignore the other columns. A summary of the pass goes to stderr.\n"
    "OUT.frd (or .fr2, .crd): the pass as a CRD v2 full-rate file instead (epoch, time of flight; the\n"
    "filter flag is the truth: 2 signal, 1 noise), of a simulated station ranging 'lageos1' (the\n"
    "conventional kind) or 'simsat-KIND'.\n"
    "  --kind K              khz (2 kHz single-photon, LEO; default), conventional (10 Hz, LAGEOS),\n"
    "                        diffuse (20 Hz debris ranging), leo (10 Hz multi-photon, Jason-class\n"
    "                        satellite, low pass, noisy station), daylight (20 Hz, 3 % returns,\n"
    "                        150 ps, 400 ns gate: low-SNR ranging to a LEO satellite; use --day),\n"
    "                        dayspad (the same class of another make: returns fading with range,\n"
    "                        a sky brightening 3x over the pass, noise 4x denser at the gate's\n"
    "                        start, a 40 ps tail, a 2 ms time bias; 800 km; use --day; not with --points)\n"
    "  --points N            exactly N points in the pass (the return probability follows)\n"
    "  --duration S          pass length in seconds (default: the kind's, 600 / 2400 / 300 / 600 /\n"
    "                        900 / 600)\n"
    "  --signal-fraction F   signal / all points, 0.001..1 (default: from the day or night noise rate)\n"
    "  --day, --night        noise rate of a day or night pass (default night)\n"
    "  --drift D             extra O-C drift of D ns per s about the pass middle (a steep track)\n"
    "  --curvature Q         extra O-C curvature: Q ns per s^2 (x^2 about the pass middle)\n"
    "  --gaps LIST           gaps in the track, comma-separated START:LENGTH[:SHIFT_NS][:nodata]\n"
    "                        (s from the first shot; no signal inside, noise goes on unless nodata;\n"
    "                        SHIFT_NS moves the track from the end of the gap on)\n"
    "  --seed S              random seed; the same seed gives the same file\n"
    "  -q, --quiet           no summary of the pass on stderr\n"
    "Example: laserwb-cli simulate slr --kind conventional --seed 3 pass.frd\n";

}  // namespace

int cmdSimulateSlr(int argc, char** argv) {
    const std::string cmd = "simulate slr";
    Args a(cmd, kSimUsage);
    for (const char* o : {"--kind", "--points", "--duration", "--signal-fraction", "--seed", "--drift", "--curvature", "--gaps"})
        a.option(o, true);
    for (const char* o : {"--day", "--night", "--help", "-h", "-q", "--quiet"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kSimUsage;
        return kOk;
    }
    sim::SlrKind kind = sim::SlrKind::Khz;
    if (a.has("--kind") && !sim::parseSlrKind(a.value("--kind"), &kind))
        return fail(cmd, "--kind must be " + sim::slrKindList() + ", not \"" + a.value("--kind") + "\"", kUsage);
    sim::SlrSimParams p = sim::slrSimPreset(kind);
    std::string err;
    long long points = 0, seed = 0;
    double duration = p.durationS, fraction = 0, driftNs = 0, curvNs = 0;
    if (!a.getInt("--points", 1, 50000000, &points, &err) || !a.getDouble("--duration", 1, 172800, &duration, &err) ||
        !a.getDouble("--signal-fraction", 0.001, 1, &fraction, &err) || !a.getInt("--seed", 0, (1LL << 62), &seed, &err) ||
        !a.getDouble("--drift", -1e6, 1e6, &driftNs, &err) || !a.getDouble("--curvature", -1e6, 1e6, &curvNs, &err))
        return fail(cmd, err, kUsage);
    if (a.has("--gaps") && !sim::parseSlrGaps(a.value("--gaps"), &p.gaps, &err)) return fail(cmd, "--gaps: " + err, kUsage);
    p.driftSPerS = driftNs * 1e-9;
    p.driftSPerS2 = curvNs * 1e-9;
    if (a.has("--day") && a.has("--night")) return fail(cmd, "give --day or --night, not both", kUsage);
    if (!a.has("--seed")) return fail(cmd, "--seed is required (the same seed gives the same pass)", kUsage);
    if (a.positional().size() != 1) return fail(cmd, "give exactly one output file OUT.csv", kUsage);
    p.points = points;
    p.durationS = duration;
    p.signalFraction = fraction;
    p.daylight = a.has("--day");
    const sim::SlrSimPass pass = sim::simulateSlrPass(p, static_cast<uint64_t>(seed));
    if (!pass.ok) return fail(cmd, pass.error);
    const std::string out = a.positional()[0];
    const std::string ext = core::inputExtension(out);
    if (ext == "frd" || ext == "fr2" || ext == "crd") {
        if (!core::writeFileAtomic(out, sim::slrPassCrd(p, pass), &err)) return fail(cmd, err);
    } else if (!writePassCsv(out, pass, true, &err)) {
        return fail(cmd, err);
    }
    if (!(a.has("-q") || a.has("--quiet")))
        std::cerr << "simulate slr: " << sim::slrKindName(kind) << (p.daylight ? " day" : " night") << " pass, "
                  << pass.epochS.size() << " points (" << pass.signalCount << " signal, " << pass.noiseCount
                  << " noise, fraction " << core::formatFixed(pass.signalFraction, 4) << "), "
                  << core::formatFixed(pass.durationS, 1) << " s from " << core::formatFixed(p.startSod, 2)
                  << " s of day; range bias " << core::formatFixed(pass.rangeBiasS * 1e9, 3) << " ns, time bias "
                  << core::formatFixed(pass.timeBiasS * 1e3, 4) << " ms, closest approach at "
                  << core::formatFixed(pass.tcaSod, 2) << " s; gate " << core::formatFixed(pass.gateS * 1e9, 1)
                  << " ns; jitter " << core::formatFixed(p.jitterS * 1e12, 1) << " ps; altitude "
                  << core::formatFixed(p.altitudeKm, 0) << " km (normal points "
                  << core::formatFixed(slr::normalPointBinS(p.altitudeKm), 0) << " s) -> " << out << "\n";
    return kOk;
}

namespace {

const char* kBenchUsage =
    "usage: laserwb-cli bench slr [--points N] [--kind K] [--signal-fraction F] [--seed S]\n"
    "End-to-end SLR screening benchmark: for 10^4, 10^5 and 10^6 points (or N), a simulated pass is\n"
    "written to a temporary CSV (epoch_s,oc_s,truth); a fresh process then parses it, screens it\n"
    "(automatic mode) and runs the post-fit with normal points, and reports the times and its peak\n"
    "resident memory (getrusage). Prints a Markdown table. Defaults: kind khz, signal fraction 0.1.\n"
    "  --day N    instead: a station's day of N simulated passes (khz, leo and conventional in turn,\n"
    "             --points each, default 20000) in one CRD file, screened by 'slr --all-passes' in a\n"
    "             fresh process on 1 thread and on every core: wall and CPU time, peak memory, and\n"
    "             whether the products are the same.\n"
    "  --end-to-end  instead: for 10^5, 10^6, 4*10^6 and 10^7 events (or N) a simulated pass as CRD\n"
    "             and as O-C CSV, 'slr FILE -o OUT.csv -q' on each in a fresh process: wall time, its\n"
    "             ratio to a plain read of the same file, peak memory and bytes per event.\n";

struct BenchRow {
    double parse = 0, screen = 0, autoScale = 0, postfit = 0, total = 0;
    double peakKb = 0, startKb = 0;
    double precision = 0, recall = 0;
    long long points = 0, nps = 0;
    int ok = 0;
};

// The pass CSV through the shared O-C table reader (core/slr/oc_csv.hpp), with the truth column.
bool readBenchCsv(const std::string& path, std::vector<double>* t, std::vector<double>* oc, std::vector<uint8_t>* truth,
                  std::string* error) {
    slr::OcCsvParams p;
    p.extraColumns = {"truth"};
    slr::OcCsvReadResult r = slr::readOcCsv(path, p);
    if (!r.ok) {
        *error = r.error;
        return false;
    }
    *t = std::move(r.table.epoch_s);
    *oc = std::move(r.table.oc_s);
    const std::vector<double>& tr = r.table.extra.front();
    truth->resize(tr.size());
    for (size_t i = 0; i < tr.size(); ++i) (*truth)[i] = tr[i] == 1;
    return true;
}

double rssKb() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    long pages = 0, resident = 0;
    if (f) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1024.0;
}

// Runs fn in a forked child; the child writes a BenchRow to a pipe. False when the child failed.
template <class Fn>
bool inChild(Fn fn, BenchRow* row) {
    int fd[2];
    if (pipe(fd) != 0) return false;
    const pid_t pid = fork();
    if (pid < 0) return false;
    if (pid == 0) {
        close(fd[0]);
        BenchRow r = fn();
        const ssize_t w = write(fd[1], &r, sizeof r);
        close(fd[1]);
        _exit(w == static_cast<ssize_t>(sizeof r) && r.ok ? 0 : 1);
    }
    close(fd[1]);
    BenchRow r;
    const ssize_t got = read(fd[0], &r, sizeof r);
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (got != static_cast<ssize_t>(sizeof r) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return false;
    *row = r;
    return true;
}


// One CRD file of several simulated passes: the first file's H1 and H2, each pass's H3 .. H8, one H9.
std::string dayFile(const std::vector<std::string>& passes) {
    std::string day;
    for (size_t k = 0; k < passes.size(); ++k) {
        const std::string& text = passes[k];
        const size_t h3 = text.find("\nH3");
        const size_t h9 = text.find("\nH9");
        if (h3 == std::string::npos || h9 == std::string::npos) return {};
        if (k == 0) day += text.substr(0, h3 + 1);
        day += text.substr(h3 + 1, h9 - h3);
    }
    return day + "H9\n";
}

struct DayRun {
    double wall = 0, cpu = 0, peakMb = 0;
    int exitCode = -1;
};

// laserwb-cli ARGS... in a child process: wall and CPU time, peak RSS, exit code.
DayRun runCliChild(const std::vector<std::string>& args) {
    DayRun r;
    std::vector<char*> argv = {const_cast<char*>("laserwb-cli")};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) return r;
    if (pid == 0) {
        execv("/proc/self/exe", argv.data());
        _exit(127);
    }
    int status = 0;
    struct rusage ru {};
    if (wait4(pid, &status, 0, &ru) != pid) return r;
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.cpu = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
    r.peakMb = static_cast<double>(ru.ru_maxrss) / 1024.0;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// laserwb-cli slr DAY --all-passes --out-dir DIR --threads T in a child process.
DayRun runDay(const std::string& day, const std::string& dir, int threads) {
    return runCliChild({"slr", day, "--all-passes", "--out-dir", dir, "--threads", std::to_string(threads), "-q"});
}

// The products of two runs, byte for byte.
bool sameProducts(const std::string& a, const std::string& b, size_t passes) {
    auto read = [](const std::string& path) {
        std::ifstream f(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(f), {});
    };
    std::vector<std::string> names = {"summary.csv"};
    if (read(a + "/summary.csv").empty()) return false;
    names.push_back("normal_points.npt");
    for (size_t i = 1; i <= passes; ++i) {
        char n[16];
        std::snprintf(n, sizeof n, "pass%03zu", i);
        for (const char* ext : {".csv", ".frd", ".npt"}) names.push_back(n + std::string(ext));
    }
    for (const std::string& n : names)
        if (read(a + "/" + n) != read(b + "/" + n)) return false;
    return true;
}

// bench slr --day N: a day of N passes on one thread and on every core.
int benchDay(const std::string& cmd, long long passes, long long points, long long seed) {
    std::string dir = "/tmp/laserwb-bench-day-XXXXXX";
    if (!mkdtemp(dir.data())) return fail(cmd, "cannot create a temporary folder");
    const sim::SlrKind kinds[] = {sim::SlrKind::Khz, sim::SlrKind::Leo, sim::SlrKind::Conventional};
    std::vector<std::string> texts;
    for (long long k = 0; k < passes; ++k) {
        sim::SlrSimParams p = sim::slrSimPreset(kinds[k % 3]);
        p.points = points;
        const sim::SlrSimPass pass = sim::simulateSlrPass(p, static_cast<uint64_t>(seed + k));
        if (!pass.ok) return fail(cmd, pass.error);
        texts.push_back(sim::slrPassCrd(p, pass));
    }
    const std::string day = dir + "/day.frd", one = dir + "/one", all = dir + "/all";
    std::string err;
    const std::string text = dayFile(texts);
    texts.clear();
    if (text.empty() || !core::writeFileAtomic(day, text, &err)) return fail(cmd, err.empty() ? "cannot build the day file" : err);
    const DayRun r1 = runDay(day, one, 1), rn = runDay(day, all, 0);
    const bool same = sameProducts(one, all, static_cast<size_t>(passes));
    std::cout << "A station's day: " << passes << " simulated passes of " << points << " points (khz, leo, conventional in turn), "
              << core::formatFixed(static_cast<double>(text.size()) / 1e6, 1) << " MB of CRD; 'slr --all-passes' on "
              << core::coresFor(0) << " cores.\n\n"
              << "| passes | wall (s) | CPU (s) | cores busy | peak RSS (MB) | exit |\n|---|---|---|---|---|---|\n";
    for (const auto& [label, r] : {std::pair<std::string, DayRun>{"one at a time (--threads 1; its scale search on every core)", r1},
                                   {"side by side (default; each search on one core)", rn}})
        std::cout << "| " << label << " | " << core::formatFixed(r.wall, 3) << " | " << core::formatFixed(r.cpu, 3) << " | "
                  << core::formatFixed(r.cpu / r.wall, 2) << " | " << core::formatFixed(r.peakMb, 1) << " | " << r.exitCode << " |\n";
    std::cout << "\nspeed-up " << core::formatFixed(r1.wall / rn.wall, 2) << "x; products "
              << (same ? "identical" : "DIFFERENT") << "\n";
    const int rc = std::system(("rm -rf '" + dir + "'").c_str());
    (void)rc;
    if (r1.exitCode != 0 || rn.exitCode != 0) return fail(cmd, "a run of the day failed (exit " + std::to_string(r1.exitCode) + ", " + std::to_string(rn.exitCode) + ")");
    return same ? kOk : fail(cmd, "the products on 1 thread and on every core differ");
}

// ---- bench slr --end-to-end: the command on CRD and CSV passes against a plain read ------------

// A plain read of the file as issue 44 measured it: awk summing each data line's first two
// numbers (CRD: type-10 records; CSV: every line after the header), in a child process. NaN
// when awk cannot be run.
double plainReadSeconds(const std::string& path) {
    const bool crd = path.size() > 4 && path.compare(path.size() - 4, 4, ".frd") == 0;
    const char* program = crd ? "$1 == \"10\" { s += $2 + $3 } END { print s > \"/dev/null\" }"
                              : "NR > 1 { s += $1 + $2 } END { print s > \"/dev/null\" }";
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) return NAN;
    if (pid == 0) {
        if (crd) execlp("awk", "awk", program, path.c_str(), static_cast<char*>(nullptr));
        else execlp("awk", "awk", "-F,", program, path.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return NAN;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The bench's simulated pass of n points written to csv, and to crd when given (run in a child by
// inChild).
BenchRow simulatePassFiles(const sim::SlrSimParams& base, long long n, double fraction, long long seed,
                           const std::string& csv, const std::string& crd = {}) {
    BenchRow r;
    sim::SlrSimParams p = base;
    p.points = n;
    p.signalFraction = fraction;
    const sim::SlrSimPass pass = sim::simulateSlrPass(p, static_cast<uint64_t>(seed));
    std::string e;
    r.ok = pass.ok && (crd.empty() || core::writeFileAtomic(crd, sim::slrPassCrd(p, pass), &e)) &&
           writePassCsv(csv, pass, false, &e);
    return r;
}

// bench slr --end-to-end: for each size a simulated pass written as CRD and as an O-C CSV, then
// `laserwb-cli slr FILE -o OUT.csv -q` on each in a fresh process (wall, peak RSS, bytes per
// event) beside a plain read of the same file in the same run (issue 44's table).
int benchEndToEnd(const std::string& cmd, const std::vector<long long>& sizes, sim::SlrKind kind, double fraction,
                  long long seed) {
    std::string dir = "/tmp/laserwb-bench-e2e-XXXXXX";
    if (!mkdtemp(dir.data())) return fail(cmd, "cannot create a temporary folder");
    const sim::SlrSimParams base = sim::slrSimPreset(kind);
    std::cout << "laserwb-cli slr FILE -o OUT.csv -q in a fresh process, " << sim::slrKindName(kind)
              << " passes (signal fraction " << core::formatFixed(fraction, 3)
              << ", no prediction: the O-C of a CRD pass is its own TOF trend); plain read = awk summing each data line's "
                 "first two numbers, in the same run (the file in the page cache).\n\n"
              << "| events | input | file (MB) | plain read (s) | slr wall (s) | over the read | CPU (s) | peak RSS (MB) | "
                 "bytes/event | exit |\n|---|---|---|---|---|---|---|---|---|---|\n"
              << std::flush;
    int rc = kOk;
    for (long long n : sizes) {
        const std::string crd = dir + "/pass.frd", csv = dir + "/pass.csv", out = dir + "/out.csv";
        BenchRow made;
        const bool simOk = inChild([&]() { return simulatePassFiles(base, n, fraction, seed, csv, crd); }, &made);
        if (!simOk) {
            rc = fail(cmd, "simulating " + std::to_string(n) + " events failed");
            break;
        }
        for (const std::string* in : {&crd, &csv}) {
            const double read = plainReadSeconds(*in);
            const DayRun r = runCliChild({"slr", *in, "-o", out, "-q"});
            std::FILE* f = std::fopen(in->c_str(), "rb");
            double mb = 0;
            if (f) {
                std::fseek(f, 0, SEEK_END);
                mb = static_cast<double>(std::ftell(f)) / 1e6;
                std::fclose(f);
            }
            std::cout << "| " << n << " | " << (in == &crd ? "CRD" : "CSV") << " | " << core::formatFixed(mb, 1) << " | "
                      << core::formatFixed(read, 3) << " | " << core::formatFixed(r.wall, 3) << " | "
                      << core::formatFixed(r.wall / read, 1) << "x | " << core::formatFixed(r.cpu, 3) << " | "
                      << core::formatFixed(r.peakMb, 1) << " | " << core::formatFixed(r.peakMb * 1048576.0 / static_cast<double>(n), 0)
                      << " | " << r.exitCode << " |\n"
                      << std::flush;
            if (r.exitCode != 0 && r.exitCode != 3) rc = fail(cmd, "slr on " + std::to_string(n) + " events failed (exit " + std::to_string(r.exitCode) + ")");
            std::remove(out.c_str());
            std::remove(core::provenancePathFor(out).c_str());
        }
        std::remove(crd.c_str());
        std::remove(csv.c_str());
    }
    ::rmdir(dir.c_str());
    return rc;
}


// The pass CSV read, screened (automatic mode) and post-fitted with normal points, timed, with the
// peak memory and the precision and recall against the truth column (run in a child by inChild).
BenchRow screenPassCsv(const std::string& csv, sim::SlrKind kind, const sim::SlrSimParams& base) {
    using Clock = std::chrono::steady_clock;
    auto sec = [](Clock::time_point a0) { return std::chrono::duration<double>(Clock::now() - a0).count(); };
    BenchRow r;
    r.startKb = rssKb();
    const auto t0 = Clock::now();
    std::vector<double> t, oc;
    std::vector<uint8_t> truth;
    std::string e;
    if (!readBenchCsv(csv, &t, &oc, &truth, &e)) {
        std::cerr << "bench slr: " << e << "\n";
        return r;
    }
    r.parse = sec(t0);
    const auto t1 = Clock::now();
    const slr::ScreenResult s = slr::screenSignal(t, oc, slr::ScreenParams{});
    r.screen = sec(t1);
    r.autoScale = s.autoMs / 1000.0;
    if (!s.ok) {
        std::cerr << "bench slr: " << s.error << "\n";
        return r;
    }
    const auto t2 = Clock::now();
    slr::PostfitParams pp;
    pp.rejectSigma = kind == sim::SlrKind::Khz ? 2.5 : 3.0;
    pp.altitudeKm = base.altitudeKm;
    pp.fireRateHz = base.fireRateHz;
    const slr::PostfitResult f = slr::postfit(t, oc, slr::acceptedMask(s), {}, pp);
    r.postfit = sec(t2);
    r.total = sec(t0);
    if (!f.ok) {
        std::cerr << "bench slr: " << f.error << "\n";
        return r;
    }
    struct rusage ru {};
    getrusage(RUSAGE_SELF, &ru);
    r.peakKb = static_cast<double>(ru.ru_maxrss);
    long long tp = 0, fp = 0, fn = 0;
    for (size_t i = 0; i < t.size(); ++i) {
        const bool acc = s.accepted(i);
        tp += acc && truth[i];
        fp += acc && !truth[i];
        fn += !acc && truth[i];
    }
    r.precision = tp + fp ? static_cast<double>(tp) / static_cast<double>(tp + fp) : 0;
    r.recall = tp + fn ? static_cast<double>(tp) / static_cast<double>(tp + fn) : 0;
    r.points = static_cast<long long>(t.size());
    r.nps = static_cast<long long>(f.normalPoints.size());
    r.ok = 1;
    return r;
}

// One row of the table.
void printBenchRow(const BenchRow& row) {
    auto f3 = [](double v) { return core::formatFixed(v, 3); };
    std::cout << "| " << row.points << " | " << f3(row.parse) << " | " << f3(row.screen) << " | " << f3(row.autoScale)
              << " | " << f3(row.postfit) << " | " << f3(row.total) << " | " << core::formatFixed(row.peakKb / 1024, 1)
              << " | " << core::formatFixed(row.peakKb * 1024 / static_cast<double>(row.points), 0) << " | "
              << core::formatFixed(row.precision, 4) << " | " << core::formatFixed(row.recall, 4) << " | " << row.nps
              << " |\n"
              << std::flush;
}
}  // namespace

int cmdBenchSlr(int argc, char** argv) {
    const std::string cmd = "bench slr";
    Args a(cmd, kBenchUsage);
    for (const char* o : {"--points", "--kind", "--signal-fraction", "--seed", "--day"}) a.option(o, true);
    for (const char* o : {"--help", "-h", "--end-to-end"}) a.option(o, false);
    if (!a.parse(argc, argv, 3)) return fail(cmd, a.error(), kUsage);
    if (a.has("--help") || a.has("-h")) {
        std::cout << kBenchUsage;
        return kOk;
    }
    std::string err;
    long long points = 0, seed = 11;
    double fraction = 0.1;
    sim::SlrKind kind = sim::SlrKind::Khz;
    if (a.has("--kind") && !sim::parseSlrKind(a.value("--kind"), &kind))
        return fail(cmd, "--kind must be " + sim::slrKindList(), kUsage);
    if (sim::slrSimPreset(kind).returnRangePower > 0)
        return fail(cmd, std::string("the ") + sim::slrKindName(kind) +
                             " kind's returns fade with range over its pass's length: it cannot be made of a given number of "
                             "points, which the benchmark needs",
                    kUsage);
    if (!a.getInt("--points", 1000, 20000000, &points, &err) || !a.getInt("--seed", 0, 1LL << 62, &seed, &err) ||
        !a.getDouble("--signal-fraction", 0.001, 1, &fraction, &err))
        return fail(cmd, err, kUsage);
    if (!a.positional().empty()) return fail(cmd, "no positional arguments expected", kUsage);
    long long day = 0;
    if (!a.getInt("--day", 1, 10000, &day, &err)) return fail(cmd, err, kUsage);
    if (day > 0) return benchDay(cmd, day, points > 0 ? points : 20000, seed);
    if (a.has("--end-to-end"))
        return benchEndToEnd(cmd, points > 0 ? std::vector<long long>{points} : std::vector<long long>{100000, 1000000, 4000000, 10000000},
                             kind, fraction, seed);
    std::vector<long long> sizes = {10000, 100000, 1000000};
    if (points > 0) sizes = {points};
    std::string dir = "/tmp/laserwb-bench-slr-XXXXXX";
    if (!mkdtemp(dir.data())) return fail(cmd, "cannot create a temporary folder");
    const sim::SlrSimParams base = sim::slrSimPreset(kind);
    std::cout << "SLR screening, " << sim::slrKindName(kind) << " passes, signal fraction "
              << core::formatFixed(fraction, 3) << ", automatic mode, post-fit "
              << (kind == sim::SlrKind::Khz ? "2.5" : "3") << "-sigma with normal points; one core.\n\n"
              << "| points | parse (s) | screen (s) | of which scale search (s) | post-fit + NP (s) | total (s) | "
                 "peak RSS (MB) | bytes/point | precision | recall | normal points |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|\n"
              << std::flush;
    int rc = kOk;
    for (long long n : sizes) {
        const std::string csv = dir + "/pass_" + std::to_string(n) + ".csv";
        BenchRow sr;
        const bool simOk = inChild([&]() { return simulatePassFiles(base, n, fraction, seed, csv); }, &sr);
        if (!simOk) {
            rc = fail(cmd, "simulating " + std::to_string(n) + " points failed");
            break;
        }
        BenchRow row;
        const bool runOk = inChild([&]() { return screenPassCsv(csv, kind, base); }, &row);
        std::remove(csv.c_str());
        if (!runOk) {
            rc = fail(cmd, "the run on " + std::to_string(n) + " points failed");
            break;
        }
        printBenchRow(row);
        if (sizes.back() == n)
            std::cerr << "(peak RSS includes the process baseline of about " << core::formatFixed(row.startKb / 1024, 1)
                      << " MB before reading; bytes/point = peak RSS / points)\n";
    }
    ::rmdir(dir.c_str());
    return rc;
}

}  // namespace lwb::cli
