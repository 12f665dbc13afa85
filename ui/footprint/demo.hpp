#pragma once
// The built-in demo: simulated footprint shots (two beams, a year of months, day and night,
// with doubtful cases) and a simulated SLR pass, so the workbench is alive at first start.
#include <vector>

#include "ui/footprint/footprint_controller.hpp"

namespace lwb::ui {

/// The footprint demo of core/sim/demo_data.hpp as workbench shots ("demo:NAME").
std::vector<Shot> demoFootprintShots();

}  // namespace lwb::ui
