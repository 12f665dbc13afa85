#include "ui/shell/workspaces.hpp"

#include "ui/calib/calib_workspace.hpp"
#include "ui/footprint/footprint_workspace.hpp"
#include "ui/radiometry/radiometry_workspace.hpp"
#include "ui/slr/slr_workspace.hpp"

namespace lwb::ui {

QList<Workspace*> makeWorkspaces(QWidget* parent) {
    return {new FootprintWorkspace(parent), new SlrWorkspace(parent), new CalibWorkspace(parent), new RadiometryWorkspace(parent)};
}

}  // namespace lwb::ui
