#pragma once
// Undo for a workspace's parameters: one parameter change (or several at once) as a
// QUndoCommand on the workspace's stack (ui/app_undo.hpp). The first redo (on push) is the change
// already made; successive changes of the same single parameter (a slider drag) merge into one
// step. Undo and redo put the parameters back through `apply` (the panel and the controller).
#include <QObject>
#include <QPointer>
#include <QUndoCommand>
#include <QUndoStack>
#include <functional>
#include <string>
#include <vector>

#include "core/common/schema.hpp"
#include "ui/kit/app_undo.hpp"

namespace lwb::ui {

template <class P>
class ParamsCommand : public QUndoCommand {
public:
    using Apply = std::function<void(const P&)>;
    ParamsCommand(QObject* owner, const core::Schema<P>& schema, const P& before, const P& after, Apply apply,
                  const QString& what)
        : m_owner(owner), m_before(before), m_after(after), m_keys(schema.changedKeys(before, after)), m_apply(std::move(apply)) {
        // The field's key as words ("Redo Change verdict major axis px", not "Redo Change
        // verdict.major_axis_px": issue 42).
        QString one = m_keys.size() == 1 ? QString::fromStdString(m_keys[0]) : what;
        if (m_keys.size() == 1) one.replace('.', ' ').replace('_', ' ');
        setText(QObject::tr("Change %1").arg(one));
    }
    int id() const override { return 0x511; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = dynamic_cast<const ParamsCommand*>(other);
        if (!o || o->m_owner != m_owner || m_keys.size() != 1 || o->m_keys != m_keys) return false;
        m_after = o->m_after;
        return true;
    }
    void undo() override {
        if (m_owner) m_apply(m_before);
    }
    void redo() override {
        if (m_first) m_first = false;
        else if (m_owner) m_apply(m_after);
    }

private:
    QPointer<QObject> m_owner;
    P m_before, m_after;
    std::vector<std::string> m_keys;
    Apply m_apply;
    bool m_first = true;
};

/// Pushes the change before → after on `workspace`'s undo stack (nothing when no key changed).
template <class P>
void pushParamsChange(QObject* workspace, const core::Schema<P>& schema, const P& before, const P& after,
                      typename ParamsCommand<P>::Apply apply, const QString& what) {
    if (schema.changedKeys(before, after).empty()) return;
    undoStackOf(workspace).push(new ParamsCommand<P>(workspace, schema, before, after, std::move(apply), what));
}

}  // namespace lwb::ui
