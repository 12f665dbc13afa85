#include "ui/footprint/review_commands.hpp"

#include <QFileInfo>

#include "ui/footprint/shot_table_model.hpp"

namespace lwb::ui {

namespace {
QString shotName(const FootprintController* c, int row) {
    const Shot* s = c ? c->shot(row) : nullptr;
    return s ? QFileInfo(s->file).fileName() : QString::number(row);
}
}  // namespace

ShotVerdictCommand::ShotVerdictCommand(FootprintController* c, int row, bool overridden, Verdict v)
    : m_c(c), m_row(row), m_afterOverridden(overridden), m_after(v) {
    const Shot* s = c->shot(row);
    m_beforeOverridden = s && s->overridden;
    m_before = s ? s->overrideVerdict : Verdict::Good;
    setText(overridden ? QObject::tr("%1 %2").arg(v == Verdict::Good ? QObject::tr("accept") : v == Verdict::Rejected ? QObject::tr("reject") : QObject::tr("mark doubtful"),
                                                  shotName(c, row))
                       : QObject::tr("automatic verdict for %1").arg(shotName(c, row)));
}

void ShotVerdictCommand::apply(bool overridden, Verdict v) {
    if (!m_c) return;
    if (overridden)
        m_c->setOverride(m_row, v, QString());  // a null note keeps the shot's note
    else
        m_c->clearOverride(m_row);
}

void ShotVerdictCommand::redo() { apply(m_afterOverridden, m_after); }
void ShotVerdictCommand::undo() { apply(m_beforeOverridden, m_before); }

ShotNoteCommand::ShotNoteCommand(FootprintController* c, int row, const QString& note)
    : m_c(c), m_row(row), m_after(note) {
    const Shot* s = c->shot(row);
    m_before = s ? s->note : QString();
    setText(QObject::tr("note on %1").arg(shotName(c, row)));
}

void ShotNoteCommand::redo() {
    if (m_c) m_c->setNote(m_row, m_after);
}

void ShotNoteCommand::undo() {
    if (m_c) m_c->setNote(m_row, m_before);
}

}  // namespace lwb::ui
