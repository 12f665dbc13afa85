#include "ui/kit/app_undo.hpp"

#include <QUndoGroup>
#include <QUndoStack>

namespace lwb::ui {

QUndoGroup& appUndoGroup() {
    static QUndoGroup* group = new QUndoGroup();  // lives as long as the process, like qApp
    return *group;
}

QUndoStack& undoStackOf(QObject* workspace) {
    if (auto* s = workspace->findChild<QUndoStack*>("workspaceUndo", Qt::FindDirectChildrenOnly)) return *s;
    auto* s = new QUndoStack(workspace);
    s->setObjectName("workspaceUndo");
    appUndoGroup().addStack(s);
    return *s;
}

}  // namespace lwb::ui
