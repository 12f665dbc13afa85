#include "ui/demo.hpp"

#include <QDate>
#include <cmath>

#include "core/sim/footprint_sim.hpp"
#include "core/sim/rng.hpp"

namespace lwb::ui {

std::vector<Shot> demoFootprintShots() {
    namespace sim = core::sim;
    std::vector<Shot> shots;
    sim::Rng rng(20200315);
    // Paper 001 Table 2's first-month LFI means; the demo drifts by up to ~1 px over the year.
    const QPointF nominal[2] = {{120.83, 263.71}, {216.32, 162.51}};
    const sim::Scene scenes[] = {sim::Scene::Weak, sim::Scene::Moderate, sim::Scene::Strong, sim::Scene::Night};
    const sim::SpotCase doubtful[] = {sim::SpotCase::NoSpot, sim::SpotCase::Saturated, sim::SpotCase::DoubleSpot,
                                      sim::SpotCase::Edge, sim::SpotCase::Elongated};
    int k = 0;
    for (int month = 0; month < 12; ++month) {
        const QDate date = QDate(2020, 3, 1).addMonths(month);
        for (int beam = 0; beam < 2; ++beam) {
            const double drift = month / 11.0;
            const QPointF c = nominal[beam] + QPointF(-0.4 * drift, (beam ? -1.4 : -1.0) * drift + 0.15 * std::sin(month));
            for (int i = 0; i < 10; ++i, ++k) {
                sim::FootprintSimParams p;
                p.scene = scenes[k % 4];
                p.spotCase = (k % 7 == 3) ? doubtful[(k / 7) % 5] : sim::SpotCase::Normal;
                p.centreJitterPx = 0.25;
                const QPoint origin(int(std::lround(c.x())) - 16, int(std::lround(c.y())) - 16);
                p.hasCenter = true;
                p.centerX = c.x() - origin.x();
                p.centerY = c.y() - origin.y();
                const auto shot = sim::simulateFootprint(p, rng.next());
                Shot s;
                s.file = QString("demo:b%1_%2_%3").arg(beam + 1).arg(date.toString("yyyy-MM")).arg(i, 2, 10, QChar('0'));
                s.time = QDate(date.year(), date.month(), 1 + 2 * i).toString(Qt::ISODate) + "T03:14:00Z";
                s.beam = QString::number(beam + 1);
                s.camera = "LFI";
                shot.image.convertTo(s.roi, CV_32F);
                s.origin = origin;
                shots.push_back(std::move(s));
            }
        }
    }
    return shots;
}

}  // namespace lwb::ui
