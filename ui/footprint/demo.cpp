#include "ui/footprint/demo.hpp"

#include "core/sim/demo_data.hpp"

namespace lwb::ui {

std::vector<Shot> demoFootprintShots() {
    std::vector<Shot> shots;
    for (const core::sim::DemoShot& d : core::sim::demoFootprintShots()) {
        Shot s;
        s.file = "demo:" + QString::fromStdString(d.name);
        s.time = QString::fromStdString(d.time);
        s.beam = QString::number(d.beam);
        s.camera = QString::fromStdString(d.camera);
        s.roi = d.roi;
        s.origin = QPoint(d.origin.x, d.origin.y);
        shots.push_back(std::move(s));
    }
    return shots;
}

}  // namespace lwb::ui
