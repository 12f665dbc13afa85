#pragma once
// The workbench's one undo history. Every user edit that changes data or parameters (verdict
// overrides, notes, SLR box edits, parameter changes) is pushed here as a QUndoCommand, so
// Edit ▸ Undo / Redo (Ctrl+Z / Ctrl+Shift+Z) acts on it whichever workspace made it.
// Loading new data (a new file, a session, the demo) clears it: commands refer to the data they
// were made on.
class QUndoStack;

namespace lwb::ui {

/// The application-wide undo stack (created on first use, owned by the application).
QUndoStack& appUndoStack();

}  // namespace lwb::ui
