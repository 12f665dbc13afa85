#pragma once
// The built-in demo: simulated footprint shots (two beams, a year of months, day and night,
// with doubtful cases) and a simulated SLR pass, so the workbench is alive at first start.
#include <vector>

#include "ui/footprint_controller.hpp"

namespace lwb::ui {

/// About 240 shots, 32×32 ROIs placed at paper 001's LFI beam positions with a slow drift.
std::vector<Shot> demoFootprintShots();

}  // namespace lwb::ui
