#include "ui/app_undo.hpp"

#include <QUndoStack>

namespace lwb::ui {

QUndoStack& appUndoStack() {
    static QUndoStack* stack = new QUndoStack();  // lives as long as the process, like qApp
    return *stack;
}

}  // namespace lwb::ui
