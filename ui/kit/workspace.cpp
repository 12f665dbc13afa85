#include "ui/kit/workspace.hpp"

#include <QAction>
#include <QMenu>
#include <QPushButton>
#include <QToolButton>

namespace lwb::ui {

QList<QAction*> Workspace::openActions() {
    // The "…" buttons of its input rows (not the exports), as they stand (a disabled one is left out).
    QList<QAction*> out;
    for (QPushButton* b : findChildren<QPushButton*>()) {
        const QString t = b->text();
        if (!t.endsWith(QStringLiteral("…")) || t.startsWith(tr("Export")) || !b->isEnabled()) continue;
        auto* a = new QAction(t, this);
        a->setToolTip(b->toolTip());
        connect(a, &QAction::triggered, b, &QPushButton::click);
        out << a;
    }
    return out;
}

QList<QAction*> Workspace::exportActions() {
    // Its "Export…" buttons and the entries of its Export menus.
    QList<QAction*> out;
    for (QWidget* w : findChildren<QWidget*>()) {
        if (auto* tb = qobject_cast<QToolButton*>(w); tb && tb->menu() && tb->text().startsWith(tr("Export"))) {
            for (QAction* a : tb->menu()->actions())
                if (!a->isSeparator()) out << a;
        } else if (auto* pb = qobject_cast<QPushButton*>(w); pb && pb->text().startsWith(tr("Export"))) {
            auto* a = new QAction(pb->text(), this);
            a->setEnabled(pb->isEnabled());
            connect(a, &QAction::triggered, pb, &QPushButton::click);
            out << a;
        }
    }
    return out;
}

}  // namespace lwb::ui
