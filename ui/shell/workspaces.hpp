#pragma once
// The workbench's workspaces, in tab order: the one place that names them (the window holds
// them as Workspace, ui/kit/workspace.hpp). Adding a workspace: its folder under ui/ and a
// line in workspaces.cpp.
#include <QList>

class QWidget;

namespace lwb::ui {

class Workspace;

/// Makes every workspace, parented to `parent`, in tab order.
QList<Workspace*> makeWorkspaces(QWidget* parent);

}  // namespace lwb::ui
