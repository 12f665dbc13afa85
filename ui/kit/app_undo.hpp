#pragma once
// Undo history per workspace (Tiled's model: one stack per document, all in one QUndoGroup).
// Every user edit that changes data or parameters (verdict overrides, notes, SLR box edits,
// parameter changes) is pushed as a QUndoCommand on the stack of the workspace it was made in;
// Edit ▸ Undo / Redo (Ctrl+Z / Ctrl+Shift+Z) acts on the group's active stack, which the main
// window keeps on the current workspace's. Loading new data into a workspace clears its stack
// only: commands refer to the data they were made on, and the other workspaces' histories are
// about theirs.
class QObject;
class QUndoGroup;
class QUndoStack;

namespace lwb::ui {

/// The application's undo group (created on first use, lives as long as the process).
QUndoGroup& appUndoGroup();

/// The undo stack of `workspace`: a child of it, created on first use and added to
/// appUndoGroup(); it goes with the workspace.
QUndoStack& undoStackOf(QObject* workspace);

}  // namespace lwb::ui
