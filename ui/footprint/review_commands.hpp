#pragma once
// The footprint review's edits as undoable commands on the footprint workspace's undo stack: a manual verdict (or its
// removal) and a note on one shot. They refer to a row of the current list; loading a new list
// clears the stack.
#include <QPointer>
#include <QString>
#include <QUndoCommand>

#include "ui/footprint/footprint_controller.hpp"

namespace lwb::ui {

class ShotVerdictCommand : public QUndoCommand {
public:
    /// overridden false: back to the computed verdict.
    ShotVerdictCommand(FootprintController* c, int row, bool overridden, Verdict v);
    void redo() override;
    void undo() override;

private:
    void apply(bool overridden, Verdict v);
    QPointer<FootprintController> m_c;
    int m_row;
    bool m_beforeOverridden, m_afterOverridden;
    Verdict m_before, m_after;
};

class ShotNoteCommand : public QUndoCommand {
public:
    ShotNoteCommand(FootprintController* c, int row, const QString& note);
    void redo() override;
    void undo() override;

private:
    QPointer<FootprintController> m_c;
    int m_row;
    QString m_before, m_after;
};

}  // namespace lwb::ui
