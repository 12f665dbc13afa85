#pragma once
// Wires DS9's contrast / bias gestures (a middle or Ctrl+drag on image views, a drag on the
// colour bar, a double-click on the bar or the views' menu to reset) to the display controls
// whose limits they change.
#include <QList>

namespace lwb::ui {

class DisplayControls;
class ImageView;
class ColorBar;

void wireContrastBias(DisplayControls* display, const QList<ImageView*>& views, ColorBar* bar);

}  // namespace lwb::ui
