#include "core/slr/station_day.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/parallel.hpp"
#include "core/common/text.hpp"
#include "core/slr/pass_output.hpp"

namespace lwb::core::slr {

namespace {

constexpr double kMmPerSecond = 0.5 * 299792458.0 * 1e3;  // one-way mm per second of two-way TOF

std::string fixedOrEmpty(double v, int decimals) { return std::isfinite(v) ? formatFixed(v, decimals) : std::string(); }

}  // namespace

std::string dayPassName(size_t k) {
    char name[32];
    std::snprintf(name, sizeof name, "pass%03zu", k);
    return name;
}

const std::vector<DayColumn>& dayColumns() {
    static const std::vector<DayColumn> columns = {
        {"pass", "", "the block's place in the file, from 1", [](const DayRow& r) { return std::to_string(r.pass); }},
        {"station", "", "the station's name (H2)", [](const DayRow& r) { return r.block.station; }},
        {"satellite", "", "the satellite's name (H3)", [](const DayRow& r) { return r.block.satellite; }},
        {"ilrs_id", "", "the satellite's ILRS id (H3)", [](const DayRow& r) { return r.block.ilrsId; }},
        {"start_utc", "", "the H4 start, YYYY-MM-DD hh:mm:ss UTC", [](const DayRow& r) { return r.block.start; }},
        {"duration_s", "s", "from the first to the last screened epoch",
         [](const DayRow& r) { return r.screened ? fixedOrEmpty(r.durationS, 1) : std::string(); }},
        {"points", "", "screened points (other blocks: their records)",
         [](const DayRow& r) {
             return std::to_string(r.screened ? r.points : r.block.ranges ? r.block.ranges : r.block.normalPoints);
         }},
        {"accepted", "", "points the screening accepted (signal or recovered)",
         [](const DayRow& r) { return r.screened ? std::to_string(r.accepted) : std::string(); }},
        {"rms_ps", "ps", "post-fit RMS of the kept residuals, two-way",
         [](const DayRow& r) { return r.screened ? fixedOrEmpty(r.rmsS * 1e12, 1) : std::string(); }},
        {"rms_mm", "mm", "post-fit RMS of the kept residuals, one-way",
         [](const DayRow& r) { return r.screened ? fixedOrEmpty(r.rmsS * kMmPerSecond, 2) : std::string(); }},
        {"normal_points", "", "normal points delivered (0 when doubtful)",
         [](const DayRow& r) { return r.screened ? std::to_string(r.normalPoints) : std::string(); }},
        {"station_precision", "", "precision of the screening against the station's flags (empty: 0/0 or no flags)",
         [](const DayRow& r) { return r.screened ? fixedOrEmpty(r.precision, 4) : std::string(); }},
        {"station_recall", "", "recall of the screening against the station's flags",
         [](const DayRow& r) { return r.screened ? fixedOrEmpty(r.recall, 4) : std::string(); }},
        {"oc_origin", "", "where the O-C came from", [](const DayRow& r) { return r.ocOrigin; }},
        {"status", "", "ok, no signal, doubtful, failed, station normal points or skipped",
         [](const DayRow& r) { return r.status; }},
        {"reason", "", "why (doubtful, failed, skipped), or a note", [](const DayRow& r) { return r.reason; }},
        {"output", "", "the pass's per-point CSV", [](const DayRow& r) { return r.output; }},
        {"range_bias_mm", "mm", "range bias against the prediction, one-way (CPF O-C only)",
         [](const DayRow& r) { return r.bias.ok ? formatFixed(r.bias.rangeBiasS * kMmPerSecond, 2) : std::string(); }},
        {"range_bias_sigma_mm", "mm", "its 1-sigma error",
         [](const DayRow& r) { return r.bias.ok ? formatFixed(r.bias.rangeBiasSigmaS * kMmPerSecond, 2) : std::string(); }},
        {"time_bias_us", "us", "time bias against the prediction",
         [](const DayRow& r) { return r.bias.ok ? formatFixed(r.bias.timeBiasS * 1e6, 3) : std::string(); }},
        {"time_bias_sigma_us", "us", "its 1-sigma error",
         [](const DayRow& r) { return r.bias.ok ? formatFixed(r.bias.timeBiasSigmaS * 1e6, 3) : std::string(); }},
    };
    return columns;
}

std::string dayCsv(const std::vector<DayRow>& rows) {
    const auto& cols = dayColumns();
    std::string s;
    for (size_t c = 0; c < cols.size(); ++c) s += (c ? "," : "") + cols[c].name;
    s += "\n";
    for (const DayRow& r : rows) {
        for (size_t c = 0; c < cols.size(); ++c) s += (c ? "," : "") + csvEscape(cols[c].cell(r));
        s += "\n";
    }
    return s;
}

namespace {

class StationDay {
public:
    StationDay(const SlrSetup& setup, const DayOptions& options, const DayObserver& observer)
        : m_setup(setup), m_opt(options), m_obs(observer), m_write(!options.outDir.empty()) {
        m_setup.sources.cpfFallback = true;  // a pass the CPF does not fit: its own TOF trend, with a note
        // A pass with damaged records is a failed row, as on the command line, whoever asks (the
        // workbench's own set-up opens such a pass to be looked at).
        m_setup.sources.openDamaged = false;
    }

    DayResult run() {
        const std::string& input = m_setup.sources.input;
        if (!isCrdFile(input)) return failure({input + ": cannot be read or is not a CRD file (a station's file of passes is CRD)", false});
        const CrdStreamResult crd = streamCrd(
            input, {}, m_obs.fb, [this](size_t count) { return begin(count); },
            [this](CrdPass&& p) { return onPass(std::move(p)); });
        if (m_workers && m_res.error.empty() && !cancelled(m_obs.fb)) gather(m_workers->drain());
        m_workers.reset();
        if (!m_res.error.empty()) return failure(m_res.error);
        if (cancelled(m_obs.fb)) {
            m_res.cancelled = true;
            return failure({input + ": cancelled", false});
        }
        if (!crd.ok) return failure({crd.error, false});
        if (m_unreadable == crd.passes)  // (as readCrd: a file none of whose blocks is a pass is an error)
            return failure({m_firstProblem + (m_unreadable > 1 ? " (and the file's " + std::to_string(m_unreadable - 1) +
                                                                     " other pass" + (m_unreadable > 2 ? "es cannot" : " cannot") +
                                                                     " be used either)"
                                                               : std::string()),
                            false});
        return finish();
    }

private:
    // A pass read and resolved, waiting for its screening; then its result and the error of
    // writing its files ("" when written).
    struct Job {
        size_t i = 0;
        PassSummary ps;
        std::shared_ptr<const PassData> pass;
        PassSettings settings;
        PassRunResult r;
        std::string writeError;
        CrdPass npBlock;
        bool npsFormed = false;
        double seconds = 0;
    };

    DayResult failure(SlrError e) {
        DayResult r;
        r.error = std::move(e);
        r.cancelled = m_res.cancelled;
        r.rows = std::move(m_res.rows);
        return r;
    }

    std::string dir() const { return m_opt.outDir; }
    std::string out(size_t i, const char* ext) const { return dir() + "/" + dayPassName(i + 1) + ext; }
    std::string summaryPath() const { return dir() + "/summary.csv"; }
    std::string provenancePath() const { return dir() + "/provenance.json"; }
    std::string nptPath() const { return dir() + "/normal_points.npt"; }

    // The outputs' names, from the file's count of blocks, so that every one is checked before any work.
    bool begin(size_t count) {
        m_n = count;
        m_res.rows.assign(m_n, DayRow{});
        m_decided.assign(m_n, false);
        m_written.assign(m_n, false);
        if (m_obs.begin) m_obs.begin(m_n);
        if (m_write) {
            m_folder = std::make_unique<FolderForOutputs>(dir());
            if (!m_folder->ok()) {
                m_res.error = {dir() + ": cannot create the folder", false};
                return false;
            }
            m_outs.addInput(m_setup.sources.input);
            for (const std::string* in : {&m_setup.sources.cpf, &m_setup.sources.stations, &m_setup.sources.presets,
                                          &m_setup.sources.configFile})
                m_outs.addInput(*in);
            for (size_t i = 0; i < m_n; ++i)
                for (const char* ext : {".csv", ".frd", ".npt"}) m_outs.addOutput(out(i, ext));
            m_outs.addOutput(nptPath());
            m_outs.addOutput(provenancePath());
            m_outs.addOutput(summaryPath());
            // summary.csv lists the set: written last; an earlier run's pass files go.
            m_outs.setManifest(summaryPath(), dir(),
                               {"pass[0-9][0-9][0-9]*.csv", "pass[0-9][0-9][0-9]*.frd", "pass[0-9][0-9][0-9]*.npt",
                                "normal_points.npt"});
            if (!m_outs.check()) {
                m_res.error = {m_outs.error(), m_outs.namingProblem()};
                return false;
            }
        }
        const size_t cores = coresFor(m_opt.threads);
        // The passes fill the cores; each pass's scale search on one (the same trials and choice
        // on any number: test_slr_screen scaleSearchIsTheSameOnOneThreadAndMany).
        if (cores > 1 && m_n > 1) m_setup.sources.searchThreads = 1;
        m_workers = std::make_unique<OrderedWorkers<Job>>(cores, 4 * cores, [this](Job& j) { work(j); });
        return true;
    }

    void decide(size_t i, DayRow row) {
        row.pass = i + 1;
        m_res.rows[i] = std::move(row);
        m_decided[i] = true;
        // Rows go out in the file's order: each as soon as every row before it is decided.
        while (m_emitted < m_n && m_decided[m_emitted]) {
            if (m_obs.row) m_obs.row(m_res.rows[m_emitted]);
            ++m_emitted;
        }
    }

    void blockRow(const PassSummary& s, size_t i, const std::string& status, const std::string& reason) {
        DayRow r;
        r.block = s;
        r.status = status;
        r.reason = reason;
        decide(i, std::move(r));
    }

    void failedRow(const PassSummary& s, size_t i, const std::string& why) {
        blockRow(s, i, "failed", why.substr(0, why.find('\n')));
        ++m_res.failed;
    }

    bool onPass(CrdPass&& crdPass) {
        if (cancelled(m_obs.fb)) return false;
        const size_t i = crdPass.ordinal - 1;
        if (i >= m_n) {  // (the first read counted the passes: it cannot find fewer)
            m_res.error = {m_setup.sources.input + ": the file changed while it was read (more passes than counted)", false};
            return false;
        }
        if (!crdPass.problem.empty()) {
            if (m_firstProblem.empty()) m_firstProblem = crdPass.problem;
            ++m_unreadable;
        }
        auto one = std::make_shared<CrdReadResult>();
        one->ok = true;
        one->file = passAlone(crdPass);
        one->file.path = m_setup.sources.input;
        crdPass = CrdPass{};
        PassSummary ps = summarisePasses(one->file).front();
        ps.index = static_cast<int>(i);
        if (const BlockStatus b = blockStatus(ps); !b.status.empty()) {
            blockRow(ps, i, b.status, b.reason);
            ++(b.status == "skipped" ? m_res.skipped : m_res.stationNormalPoints);
            return true;
        }
        OpenedPass p = openPassOf(m_setup, std::shared_ptr<const CrdReadResult>(std::move(one)), 0);
        if (!p.ok) {
            failedRow(ps, i, p.error.message);
            return true;
        }
        Job job;
        job.i = i;
        job.ps = ps;
        job.pass = std::move(p.pass);
        job.settings = std::move(p.settings);
        m_workers->submit(std::move(job));
        return gather(m_workers->takeReady());
    }

    // Screening and writing a pass, on a worker thread. Nothing may leave it: a failure (memory
    // running out while a pass's files are written) is that pass's.
    void work(Job& j) const {
        const auto t0 = std::chrono::steady_clock::now();
        try {
            j.r = runOpenedPass(*j.pass, j.settings, m_setup, nullptr);
            if (j.r.ok) {
                // Its files, and its normal-point block kept for the day's file (nothing without a folder).
                if (m_write) {
                    const PassProductPaths paths{out(j.i, ".csv"), out(j.i, ".frd"), out(j.i, ".npt"), false, "", nullptr};
                    if (stagePassProducts(m_outs, *j.pass, j.r, paths, &j.npBlock, &j.writeError))
                        j.npsFormed = !deliveredNormalPoints(j.r).points.empty();
                    else if (j.writeError.empty())
                        j.writeError = out(j.i, ".npt") + ": not written";
                }
            }
        } catch (const std::exception& e) {
            j.r.ok = false;
            j.r.error = std::string("out of resources while screening the pass: ") + e.what();
        }
        j.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }

    // The passes screened so far, in the file's order: their rows.
    bool gather(std::vector<Job> finished) {
        for (Job& j : finished) {
            if (!j.r.ok) {
                failedRow(j.ps, j.i, j.r.error);
                continue;
            }
            if (!j.writeError.empty()) {
                m_res.error = {m_outs.unstaged(j.writeError), false};
                return false;
            }
            m_written[j.i] = m_write;
            if (j.npsFormed) m_dayNps.push_back(std::move(j.npBlock));
            screenedRow(j);
        }
        return true;
    }

    void screenedRow(const Job& j) {
        const PassRunResult& r = j.r;
        const BlockStatus st = runStatus(*j.pass, r);
        ++(st.status == "doubtful" ? m_res.doubtful : m_res.screened);
        DayRow row;
        row.block = j.ps;
        row.screened = true;
        row.status = st.status;
        row.reason = st.reason;
        row.durationS = j.pass->t.empty() ? 0 : j.pass->t.back() - j.pass->t.front();
        row.points = j.pass->t.size();
        row.accepted = r.acceptedCount;
        row.rmsS = r.postOk ? r.post.stats.rms : NAN;
        row.normalPoints = deliveredNormalPoints(r).points.size();
        row.precision = r.agreement.precision;
        row.recall = r.agreement.recall;
        row.ocOrigin = j.pass->ocOrigin;
        row.output = dayPassName(j.i + 1) + ".csv";
        row.bias = r.bias;
        row.seconds = j.seconds;
        decide(j.i, std::move(row));
    }

    DayResult finish() {
        m_res.ok = true;
        if (!m_write) return std::move(m_res);
        std::string err;
        for (size_t i = 0; i < m_n; ++i)  // passes with no result have no files
            if (!m_written[i])
                for (const char* ext : {".csv", ".frd", ".npt"}) m_outs.drop(out(i, ext));
        m_res.dayNormalPoints = !m_dayNps.empty();
        if (m_res.dayNormalPoints) {
            if (!writeNormalPointFile(m_outs.stagingPath(nptPath()), std::move(m_dayNps), &err))
                return failure({m_outs.unstaged(err), false});
        } else {
            m_outs.drop(nptPath());  // (no pass formed a normal point: summary.csv says why)
        }
        if (!writeFileAtomic(m_outs.stagingPath(summaryPath()), dayCsv(m_res.rows), &err))
            return failure({m_outs.unstaged(err), false});
        // The folder's provenance: every file of the set with its checksum.
        std::vector<std::string> written;
        for (size_t i = 0; i < m_n; ++i)
            if (m_written[i])
                for (const char* ext : {".csv", ".frd", ".npt"}) written.push_back(out(i, ext));
        if (m_res.dayNormalPoints) written.push_back(nptPath());
        written.push_back(summaryPath());
        if (!stageProvenance(m_outs, slrProvenance(m_setup, true), written, provenancePath(), &err)) return failure({err, false});
        if (!m_outs.commit()) return failure({m_outs.error(), m_outs.namingProblem()});
        m_folder->keep();
        written.push_back(provenancePath());
        m_res.written = std::move(written);
        return std::move(m_res);
    }

    SlrSetup m_setup;  // (a copy: the batch sets its own fallback and search threads)
    const DayOptions& m_opt;
    const DayObserver& m_obs;
    const bool m_write;
    DayResult m_res;
    std::unique_ptr<FolderForOutputs> m_folder;
    OutputSet m_outs;
    std::vector<bool> m_decided, m_written;
    size_t m_n = 0, m_emitted = 0, m_unreadable = 0;
    std::string m_firstProblem;
    std::vector<CrdPass> m_dayNps;
    // Passes screened side by side while the file is read (a station's day is many passes, most
    // too small to fill the cores alone); each pass is screened alone and what is gathered is
    // gathered in the file's order. At most four passes per core are held. (Last: its threads
    // stop before the rest goes.)
    std::unique_ptr<OrderedWorkers<Job>> m_workers;
};

}  // namespace

DayResult runStationDay(const SlrSetup& setup, const DayOptions& options, const DayObserver& observer) {
    try {
        return StationDay(setup, options, observer).run();
    } catch (const std::exception& e) {
        DayResult r;
        r.error = {setup.sources.input + ": internal error: " + e.what(), false};
        return r;
    }
}

DayResult runStationDay(const SlrSources& sources, const DayOptions& options, const DayObserver& observer) {
    SlrSetup setup;
    DayResult r;
    if (!setUpSlrRun(sources, &setup, &r.error)) return r;
    return runStationDay(setup, options, observer);
}

}  // namespace lwb::core::slr
