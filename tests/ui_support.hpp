#pragma once
// Helpers the ui tests share (header only; the ui tests link Qt Widgets).
#include <QApplication>
#include <QMouseEvent>
#include <QWidget>

namespace lwbtest {

/// A mouse drag with `button` held from `from` to `to` in five moves (events sent directly, so
/// that the moves carry the button, which QTest::mouseMove does not).
inline void mouseDrag(QWidget* w, Qt::MouseButton button, Qt::KeyboardModifiers mods, QPointF from, QPointF to) {
    auto send = [&](QEvent::Type t, QPointF pos, Qt::MouseButton b, Qt::MouseButtons held) {
        QMouseEvent e(t, pos, w->mapToGlobal(pos), b, held, mods);
        QApplication::sendEvent(w, &e);
    };
    send(QEvent::MouseButtonPress, from, button, button);
    for (int k = 1; k <= 5; ++k) send(QEvent::MouseMove, from + (to - from) * (k / 5.0), Qt::NoButton, button);
    send(QEvent::MouseButtonRelease, to, button, Qt::NoButton);
}

}  // namespace lwbtest
