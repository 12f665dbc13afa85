#include "ui/kit/contrast_bias.hpp"

#include "ui/kit/display_controls.hpp"
#include "ui/kit/image_view.hpp"

namespace lwb::ui {

void wireContrastBias(DisplayControls* display, const QList<ImageView*>& views, ColorBar* bar) {
    for (ImageView* v : views) {
        QObject::connect(v, &ImageView::contrastBiasStarted, display, &DisplayControls::beginContrastBias);
        QObject::connect(v, &ImageView::contrastBiasDragged, display, &DisplayControls::dragContrastBias);
        QObject::connect(v, &ImageView::contrastBiasResetRequested, display, &DisplayControls::resetContrastBias);
    }
    if (!bar) return;
    QObject::connect(bar, &ColorBar::contrastBiasStarted, display, &DisplayControls::beginContrastBias);
    QObject::connect(bar, &ColorBar::contrastBiasDragged, display, &DisplayControls::dragContrastBias);
    QObject::connect(bar, &ColorBar::contrastBiasResetRequested, display, &DisplayControls::resetContrastBias);
}

}  // namespace lwb::ui
