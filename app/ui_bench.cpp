// laserwb-uibench: latency of the live rerun, slider change → new result painted on screen.
// Prints a Markdown table. Runs on any Qt platform (offscreen by default).
#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "ui/footprint_params_panel.hpp"
#include "ui/footprint_workspace.hpp"
#include "ui/image_view.hpp"
#include "ui/main_window.hpp"
#include "ui/param_slider.hpp"

namespace {
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
}  // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setApplicationName("laserwb-uibench");
    lwb::ui::MainWindow w;
    w.resize(1480, 900);
    w.show();
    w.openDemo();
    w.waitIdle(60000);
    auto* ws = w.footprint();
    auto* c = ws->controller();
    ws->selectRow(5);
    w.waitIdle(10000);
    // Footprint: drag the threshold factor through 60 values; each change must produce a new
    // result for the current shot, painted.
    std::vector<double> fp;
    int arrived = 0;
    QObject::connect(c, &lwb::ui::FootprintController::currentDetailReady, [&arrived] { ++arrived; });
    for (int i = 0; i < 60; ++i) {
        const double v = 0.08 + 0.004 * (i % 30);
        arrived = 0;
        QElapsedTimer t;
        t.start();
        ws->paramsPanel()->thresholdSlider()->field()->setValue(v);
        while (arrived == 0 && t.elapsed() < 5000) QApplication::processEvents(QEventLoop::AllEvents, 1);
        ws->roiView()->repaint();
        fp.push_back(t.nsecsElapsed() / 1e6);
    }
    w.waitIdle(30000);
    const Stats f = stats(fp);
    std::printf("| interaction | n | median (ms) | p95 (ms) | max (ms) |\n|---|---|---|---|---|\n");
    std::printf("| footprint: threshold slider → current shot re-fitted (3 methods) and painted | %zu | %.1f | %.1f | %.1f |\n",
                fp.size(), f.median, f.p95, f.max);
    return 0;
}
