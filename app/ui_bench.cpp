// laserwb-uibench: latency of the live rerun, slider change → new result painted on screen.
// Prints a Markdown table. Runs on any Qt platform (offscreen by default).
#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QTimer>
#include <QFileInfo>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

#include <sys/resource.h>

#include "ui/footprint/footprint_params_panel.hpp"
#include "ui/footprint/footprint_workspace.hpp"
#include "ui/kit/image_view.hpp"
#include "ui/shell/main_window.hpp"
#include "ui/kit/param_slider.hpp"
#include "core/common/allocator.hpp"
#include "core/slr/screen.hpp"
#include "ui/slr/slr_workspace.hpp"
#include <qcustomplot.h>

namespace {

// Waits in the event loop until done() or timeoutMs since t started, blocking between events (a
// timer wakes it every 5 ms to read the clock). The loop was processEvents(AllEvents, 1), which
// returns at once when nothing is pending: it spun a whole core while the job it waited for
// wanted both (the scale search's trials and the null model run side by side), so every
// measured latency included the benchmark's own spinning.
template <class Done>
void waitUntil(Done done, qint64 timeoutMs, const QElapsedTimer& t) {
    QTimer tick;
    tick.start(5);
    while (!done() && t.elapsed() < timeoutMs) QApplication::processEvents(QEventLoop::WaitForMoreEvents);
}

struct Stats {
    double median = 0, p95 = 0, max = 0;
};
Stats stats(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    Stats s;
    if (v.empty()) return s;
    s.median = v[v.size() / 2];
    s.p95 = v[std::min(v.size() - 1, size_t(0.95 * v.size()))];
    s.max = v.back();
    return s;
}

// The first screening of one real pass: the pass, its points and the median time (ms).
struct FirstRun {
    QString file;
    size_t points;
    double ms;
};

// The benchmark on one workbench window: its stages, in the order main runs them, and what they
// measure (times in ms). The counters are advanced by the controllers' signals, connected for
// the whole run.
struct UiBench {
    explicit UiBench(lwb::ui::MainWindow& window) : w(window) {}

    lwb::ui::MainWindow& w;
    lwb::ui::FootprintWorkspace* ws = nullptr;
    lwb::ui::FootprintController* c = nullptr;
    lwb::ui::SlrWorkspace* slr = nullptr;
    lwb::ui::SlrController* sc = nullptr;
    int arrived = 0, runs = 0;
    std::vector<double> fp, vj, vjCore, sl, sl2, cOnly;
    bool refitted = false;
    size_t simulatedPoints = 0;
    std::vector<FirstRun> first;

    void footprintThreshold();
    void footprintVerdict();
    void slrCosineKeptScale();
    void slrCosineSearched();
    void slrCoreOnly();
    void slrRealPasses();
    void printTable() const;
};

// The threshold factor dragged on the footprint workspace's sixth shot.
void UiBench::footprintThreshold() {
    ws = w.workspace<lwb::ui::FootprintWorkspace>();
    c = ws->controller();
    ws->selectRow(5);
    w.waitIdle(10000);
    // Footprint: drag the threshold factor through 60 values; each change must produce a new
    // result for the current shot, painted.
    QObject::connect(c, &lwb::ui::FootprintController::currentDetailReady, [this] { ++arrived; });
    for (int i = 0; i < 60; ++i) {
        const double v = 0.08 + 0.004 * (i % 30);
        arrived = 0;
        QElapsedTimer t;
        t.start();
        ws->paramsPanel()->thresholdSlider()->field()->setValue(v);
        waitUntil([&] { return arrived != 0; }, 5000, t);
        ws->roiView()->repaint();
        fp.push_back(t.nsecsElapsed() / 1e6);
    }
    w.waitIdle(30000);
}

// A verdict criterion alone moved: every shot judged again, no refit.
void UiBench::footprintVerdict() {
    // Footprint: a verdict criterion alone (axis-ratio max) moved through 40 values: the cached
    // fits of every shot of the demo are judged again, no refit (the fit count must not move).
    const long long fitsBefore = c->fitCount();
    lwb::ui::ParamSlider* axisMax = ws->paramsPanel()->axisRatioMaxSlider();
    for (int i = 0; i < 40; ++i) {
        arrived = 0;
        QElapsedTimer t;
        t.start();
        axisMax->field()->setValue(1.2 + 0.02 * (i % 20));
        waitUntil([&] { return arrived != 0; }, 5000, t);
        vj.push_back(t.nsecsElapsed() / 1e6);
        vjCore.push_back(c->lastRejudgeMs());
    }
    refitted = c->fitCount() != fitsBefore;
}

// The cosine constant dragged on the SLR workspace's simulated pass, its scale kept.
void UiBench::slrCosineKeptScale() {
    // SLR: a 10⁵-point simulated kHz pass; drag the cosine constant through 20 values; each
    // change reruns the screening and the post-fit off the GUI thread, then the three plots are
    // redrawn.
    slr = w.workspace<lwb::ui::SlrWorkspace>();
    w.showWorkspace("slr");
    slr->openDemo(100000);
    w.waitIdle(60000);
    sc = slr->controller();
    sc->setReuseScaleForCosine(true);  // first: the scale kept while C moves (off by default since issue 28)
    QObject::connect(sc, &lwb::ui::SlrController::runReady, [this] { ++runs; });
    for (int i = 0; i < 20; ++i) {
        runs = 0;
        QElapsedTimer t;
        t.start();
        slr->cosineSlider()->field()->setValue(0.93 + 0.003 * (i % 20));
        waitUntil([&] { return runs != 0; }, 20000, t);
        slr->ocPlot()->replot(QCustomPlot::rpImmediateRefresh);
        slr->imagePlot()->replot(QCustomPlot::rpImmediateRefresh);
        sl.push_back(t.nsecsElapsed() / 1e6);
    }
}

// The cosine constant dragged again, the scale searched on every change.
void UiBench::slrCosineSearched() {
    // The same with the scale searched again on every change (what the CLI does for each run, and
    // the workbench's default).
    sc->setReuseScaleForCosine(false);
    for (int i = 0; i < 10; ++i) {
        runs = 0;
        QElapsedTimer t;
        t.start();
        slr->cosineSlider()->field()->setValue(0.95 + 0.003 * i);
        waitUntil([&] { return runs != 0; }, 20000, t);
        slr->ocPlot()->replot(QCustomPlot::rpImmediateRefresh);
        slr->imagePlot()->replot(QCustomPlot::rpImmediateRefresh);
        sl2.push_back(t.nsecsElapsed() / 1e6);
    }
}

// The core alone screening the simulated pass at the kept scale.
void UiBench::slrCoreOnly() {
    // The core alone on the same pass: a C-only change screened at the scale the automatic
    // mode chose (core::slr::ScaleChoice passed in), best of 10.
    const lwb::core::slr::ScaleChoice scale = lwb::core::slr::scaleChoice(sc->run().screen);
    lwb::core::slr::ScreenParams p = sc->screenParams();
    for (int i = 0; i < 10; ++i) {
        p.cosineC = 0.93 + 0.005 * i;
        QElapsedTimer t;
        t.start();
        const auto r = lwb::core::slr::screenSignal(sc->pass().t, sc->pass().oc, p, scale);
        cOnly.push_back(t.nsecsElapsed() / 1e6);
        if (!r.ok) std::fprintf(stderr, "screening failed: %s\n", r.error.c_str());
    }
}

// The first screening of the shared real passes that are present.
void UiBench::slrRealPasses() {
    // SLR: the first screening of real passes (the shared ILRS files, when ../shared/data/slr or
    // $LWB_SHARED_SLR has them): open the file's first pass → automatic screening, post-fit and
    // the plots painted. What an analyst waits for after opening a pass.
    const QString shared = qEnvironmentVariableIsEmpty("LWB_SHARED_SLR") ? QString("../shared/data/slr")
                                                                         : qEnvironmentVariable("LWB_SHARED_SLR");
    simulatedPoints = sc->pass().t.size();
    const struct {
        const char* file;
        int pass;  // 0-based; hy2c's first pass has 5 ranges and is refused, its third is screened
    } real[] = {{"7080_STELLA_crd_071220_2128_0.frd", 0}, {"7080_Beacon-C_crd_071220_1715_0.frd", 0},
                {"7080_JASON1_crd_071220_2033_0.frd", 0}, {"beaconc_20070511.frd", 0},
                {"blits_201206.frd", 0},                  {"hy2c_202109.fr2", 2}};
    for (const auto& [f, passIndex] : real) {
        const QString path = shared + "/" + f;
        if (!QFileInfo::exists(path)) continue;
        std::vector<double> ms;
        for (int rep = 0; rep < 3; ++rep) {  // opened three times: the median
            runs = 0;
            QElapsedTimer t;
            t.start();
            QString err;
            if (!slr->openPath(path, passIndex, &err)) {
                std::fprintf(stderr, "%s: %s\n", qPrintable(path), qPrintable(err));
                break;
            }
            waitUntil([&] { return runs != 0; }, 60000, t);
            slr->ocPlot()->replot(QCustomPlot::rpImmediateRefresh);
            slr->imagePlot()->replot(QCustomPlot::rpImmediateRefresh);
            ms.push_back(t.nsecsElapsed() / 1e6);
        }
        if (ms.size() == 3)
            first.push_back({QString("%1 pass %2").arg(f).arg(passIndex + 1), sc->pass().t.size(), stats(ms).median});
    }
}

// The Markdown table of every stage's timings.
void UiBench::printTable() const {
    const Stats f = stats(fp);
    const Stats v = stats(vj), vc = stats(vjCore);
    const Stats s = stats(sl);
    const Stats s2 = stats(sl2);
    const double cBest = *std::min_element(cOnly.begin(), cOnly.end());
    std::printf("| interaction | n | median (ms) | p95 (ms) | max (ms) |\n|---|---|---|---|---|\n");
    std::printf("| footprint: threshold slider → current shot re-fitted (3 methods) and painted | %zu | %.1f | %.1f | %.1f |\n",
                fp.size(), f.median, f.p95, f.max);
    std::printf("| footprint, %d shots: axis-ratio max (verdict only) → every shot re-judged, %s, and painted | %zu | %.1f | %.1f | %.1f |\n",
                c->count(), refitted ? "REFITTED (regression)" : "no refit", vj.size(), v.median, v.p95, v.max);
    std::printf("| footprint, %d shots: the re-judging itself (core::footprint::judgeResult on the cached fits) | %zu | %.3f | %.3f | %.3f |\n",
                c->count(), vjCore.size(), vc.median, vc.p95, vc.max);
    std::printf("| SLR, 10⁵-point pass: cosine slider → screened, post-fitted and both plots redrawn | %zu | %.1f | %.1f | %.1f |\n",
                sl.size(), s.median, s.p95, s.max);
    std::printf("| SLR, 10⁵ points, same, scale searched again on every change | %zu | %.1f | %.1f | %.1f |\n",
                sl2.size(), s2.median, s2.p95, s2.max);
    std::printf("| SLR, %zu-point pass: C-only change screened at the kept scale (core, no GUI), best of %zu | %zu | best %.1f | | |\n",
                simulatedPoints, cOnly.size(), cOnly.size(), cBest);
    for (const FirstRun& r : first)
        std::printf("| SLR, real pass %s (%zu points): opened → first screening, post-fit and plots painted | 3 | %.1f | | |\n",
                    qPrintable(r.file), r.points, r.ms);
}

// Resident memory now and at its peak (MB), from /proc/self/statm and getrusage.
void residentMb(double* now, double* peak) {
    long pages = 0, resident = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    *now = static_cast<double>(resident) * 4096.0 / 1048576.0;
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    *peak = static_cast<double>(ru.ru_maxrss) / 1024.0;
}

// Issue 44's workbench benchmark: one large pass (a CRD or O-C file) opened in the SLR workspace,
// then the cosine constant and the O-C magnification moved (each change to its result painted),
// then the O-C plot zoomed and panned (one immediate replot a frame). Prints a Markdown table.
int largePass(lwb::ui::MainWindow& w, const QString& path, int changes) {
    auto* slr = w.workspace<lwb::ui::SlrWorkspace>();
    w.showWorkspace("slr");
    lwb::ui::SlrController* sc = slr->controller();
    int runs = 0;
    QObject::connect(sc, &lwb::ui::SlrController::runReady, [&runs] { ++runs; });
    auto waitRun = [&](QElapsedTimer& t) {
        waitUntil([&] { return runs != 0; }, 600000, t);
        slr->ocPlot()->replot(QCustomPlot::rpImmediateRefresh);
        slr->imagePlot()->replot(QCustomPlot::rpImmediateRefresh);
        return t.nsecsElapsed() / 1e6;
    };
    QElapsedTimer t;
    t.start();
    QString err;
    if (!slr->openPath(path, 0, &err)) {
        std::fprintf(stderr, "%s: %s\n", qPrintable(path), qPrintable(err));
        return 1;
    }
    const double openMs = waitRun(t);
    double rssNow = 0, rssPeak = 0;
    residentMb(&rssNow, &rssPeak);
    const size_t n = sc->pass().t.size();
    if (!sc->hasRun() || n == 0) {
        std::fprintf(stderr, "%s: no run after opening\n", qPrintable(path));
        return 1;
    }
    auto drag = [&](lwb::ui::ParamSlider* s, double from, double step) {
        std::vector<double> ms;
        for (int i = 0; i < changes; ++i) {
            runs = 0;
            QElapsedTimer c;
            c.start();
            s->field()->setValue(from + step * i);
            ms.push_back(waitRun(c));
        }
        return stats(ms);
    };
    const Stats cosine = drag(slr->cosineSlider(), 0.93, 0.004);
    sc->setReuseScaleForCosine(true);  // the scale the automatic mode chose kept while C moves
    const Stats cosineKept = drag(slr->cosineSlider(), 0.95, 0.004);
    sc->setReuseScaleForCosine(false);
    const double mag = slr->magOcSlider()->field()->value();
    const Stats magOc = drag(slr->magOcSlider(), mag * 0.8, mag * 0.1);
    // Zoom in by halves about the middle, then pan by a tenth: one immediate replot a frame.
    QCPAxis* x = slr->ocPlot()->xAxis;
    const QCPRange whole = x->range();
    std::vector<double> frames;
    for (int i = 0; i < 2 * changes; ++i) {
        const QCPRange r = x->range();
        if (i < changes) x->setRange(r.center() - r.size() / 4, r.center() + r.size() / 4);
        else x->setRange(r.lower + r.size() / 10, r.upper + r.size() / 10);
        QElapsedTimer f;
        f.start();
        slr->ocPlot()->replot(QCustomPlot::rpImmediateRefresh);
        frames.push_back(f.nsecsElapsed() / 1e6);
    }
    x->setRange(whole);
    QElapsedTimer f;
    f.start();
    slr->ocPlot()->replot(QCustomPlot::rpImmediateRefresh);
    const double wholeFrame = f.nsecsElapsed() / 1e6;
    double rssEnd = 0, peakEnd = 0;
    residentMb(&rssEnd, &peakEnd);
    const Stats pan = stats(frames);
    std::printf("%s: %zu events (the workbench, offscreen, window 1480x900)\n\n", qPrintable(QFileInfo(path).fileName()), n);
    std::printf("| interaction | n | median (ms) | p95 (ms) | max (ms) |\n|---|---|---|---|---|\n");
    std::printf("| opened → automatic screening, post-fit and both plots painted | 1 | %.0f | | |\n", openMs);
    std::printf("| cosine constant → screened, post-fitted, both plots redrawn | %d | %.0f | %.0f | %.0f |\n", changes, cosine.median,
                cosine.p95, cosine.max);
    std::printf("| the same, the scale kept while C moves (setReuseScaleForCosine) | %d | %.0f | %.0f | %.0f |\n", changes,
                cosineKept.median, cosineKept.p95, cosineKept.max);
    std::printf("| O-C magnification → the same | %d | %.0f | %.0f | %.0f |\n", changes, magOc.median, magOc.p95, magOc.max);
    std::printf("| O-C plot zoomed or panned → one frame | %d | %.1f | %.1f | %.1f |\n", 2 * changes, pan.median, pan.p95, pan.max);
    std::printf("| O-C plot, the whole pass → one frame | 1 | %.1f | | |\n", wholeFrame);
    std::printf("\nresident after opening %.0f MB (peak %.0f MB, %.0f bytes an event); at the end %.0f MB (peak %.0f MB, %.0f bytes an event)\n",
                rssNow, rssPeak, rssPeak * 1048576.0 / double(n), rssEnd, peakEnd, peakEnd * 1048576.0 / double(n));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    lwb::core::reexecWithHugePages(argv);
    lwb::core::tuneAllocator();
    lwb::core::useOneArena();
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setApplicationName("laserwb-uibench");
    lwb::ui::MainWindow w;
    w.resize(1480, 900);
    w.show();
    // --large-pass FILE [--changes N]: issue 44's benchmark of one large pass instead of the table.
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--large-pass") == 0) {
            int changes = 10;
            for (int j = 1; j + 1 < argc; ++j)
                if (std::strcmp(argv[j], "--changes") == 0) changes = std::max(1, std::atoi(argv[j + 1]));
            return largePass(w, QString::fromLocal8Bit(argv[i + 1]), changes);
        }
    w.openDemo();
    w.waitIdle(60000);
    UiBench b(w);
    b.footprintThreshold();
    b.footprintVerdict();
    b.slrCosineKeptScale();
    b.slrCosineSearched();
    b.slrCoreOnly();
    b.slrRealPasses();
    b.printTable();
    return b.refitted ? 1 : 0;
}
