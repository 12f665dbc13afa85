#pragma once
// The layout the SLR, calibration and radiometry workspaces share: a centre column (a row of
// inputs, an information line, the body) and the parameter panel on the right in a scroll area,
// side by side in a splitter.
class QLayout;
class QWidget;

namespace lwb::ui {

void layoutWorkspace(QWidget* workspace, QLayout* top, QWidget* info, QWidget* body, QWidget* panel,
                     int panelMinWidth, int centreWidth);

}  // namespace lwb::ui
