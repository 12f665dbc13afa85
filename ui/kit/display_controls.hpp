#pragma once
// ROI display like SAOImage DS9: limits (min–max, IRAF zscale, 99.5 %, manual), a stretch
// (linear, sqrt, log, asinh), a histogram of the ROI with the limits drawn, and a colour bar
// in DN. The math is core/common/display_stretch; these are the widgets and the rendering.
#include <QImage>
#include <QWidget>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/display_stretch.hpp"
#include "ui/kit/color_maps.hpp"

class QComboBox;
class QDoubleSpinBox;

namespace lwb::ui {

enum class LimitsMode { MinMax, ZScale, Percentile, Manual };

struct DisplaySettings {
    /// Min–max by default: zscale suits the ground around the spot but clips the spot's peak.
    LimitsMode limits = LimitsMode::MinMax;
    core::StretchKind stretch = core::StretchKind::Linear;
    double manualLo = 0, manualHi = 1;
};

/// The limits of a CV_32FC1 image under the settings (hi > lo always).
core::DisplayLimits displayLimits(const cv::Mat& img, const DisplaySettings& s);
/// Renders a CV_32FC1 image between lo and hi through the stretch and the colour map.
QImage renderStretched(const cv::Mat& img, ColorMap map, core::StretchKind k, double lo, double hi);

/// SAOImage DS9's contrast and bias as display limits. DS9 maps a value v (0..1 between the
/// limits) to the colour at (v − bias)·contrast + ½; here the limits move instead, so that the
/// low and high fields say what is shown: the middle colour goes to lo + bias·(hi − lo) and the
/// width becomes (hi − lo) / contrast. A drag sets them as DS9's right-drag does: x the bias
/// (right: the window moves up, the image darkens), y the contrast (down: more contrast, ×10 for
/// a drag of the full height `dyFraction` = 1; up: less). dxFraction = dy... = 0 leaves them.
core::DisplayLimits contrastBiasLimits(double lo, double hi, double dxFraction, double dyFraction);

/// The limits and stretch selectors and the low / high fields (editable in manual mode; they
/// show the computed limits otherwise).
class DisplayControls : public QWidget {
    Q_OBJECT
public:
    explicit DisplayControls(QWidget* parent = nullptr);
    DisplaySettings settings() const;
    void setSettings(const DisplaySettings& s);
    /// Shows the limits in use (from the current image) in the fields when not manual.
    void showLimits(double lo, double hi);
    QComboBox* limitsBox() const { return m_limits; }
    QComboBox* stretchBox() const { return m_stretch; }
    /// The limits in the fields (those in use, or the manual ones).
    double low() const;
    double high() const;

    /// A contrast / bias drag (on an image view or the colour bar): begin() takes the limits in
    /// use; drag() sets Manual with contrastBiasLimits() of them (one changed()). The settings
    /// before the first drag are kept for reset(), which goes back to them (a change of the
    /// limits by hand forgets them).
    void beginContrastBias();
    void dragContrastBias(double dxFraction, double dyFraction);
    void resetContrastBias();
    bool contrastBiasChanged() const { return m_cbBaseSet; }

signals:
    void changed();

private:
    QComboBox *m_limits, *m_stretch;
    QDoubleSpinBox *m_lo, *m_hi;
    void keepManual();
    double m_cbLo = 0, m_cbHi = 1;  // the limits when the drag began
    // The analyst's manual limits: what settings() gives (and a session keeps) whatever the
    // boxes show in an automatic mode (showLimits: the image's own limits, which followed the
    // last image shown into sessions, and into a refused session's rollback).
    double m_manualLo = DisplaySettings{}.manualLo, m_manualHi = DisplaySettings{}.manualHi;
    DisplaySettings m_cbBase;       // the settings before the first drag
    bool m_cbBaseSet = false;
};

/// Histogram of the ROI's values (log counts) over their range, with the display limits drawn.
class HistogramView : public QWidget {
    Q_OBJECT
public:
    explicit HistogramView(QWidget* parent = nullptr);
    void setData(const cv::Mat& img, double lo, double hi);
    void clear();
    const std::vector<size_t>& bins() const { return m_bins; }
    double rangeLo() const { return m_min; }
    double rangeHi() const { return m_max; }
    double limitLo() const { return m_lo; }
    double limitHi() const { return m_hi; }
    /// Widget x of a DN value (for tests and the limit markers).
    double xOf(double dn) const;

protected:
    void paintEvent(class QPaintEvent*) override;
    QSize sizeHint() const override { return {260, 80}; }

private:
    std::vector<size_t> m_bins;
    double m_min = 0, m_max = 1, m_lo = 0, m_hi = 1;
};

/// The colour map between the limits through the stretch, with DN ticks.
class ColorBar : public QWidget {
    Q_OBJECT
public:
    explicit ColorBar(QWidget* parent = nullptr);
    void setScale(ColorMap map, core::StretchKind k, double lo, double hi);
    /// No scale (nothing drawn, no ticks): there is no image to read it against.
    void clear();
    /// Tick values (DN) of the current scale, left to right.
    std::vector<double> ticks() const;
    double lo() const { return m_lo; }
    double hi() const { return m_hi; }
    /// Where the colour bar and its unit ("DN") are drawn, in widget pixels.
    QRect barRect() const;
    QRect unitRect() const;

signals:
    /// A drag on the bar (any button): DS9's contrast (vertical, per 150 px) and bias
    /// (horizontal, per the bar's width), as ImageView's; a double-click resets.
    void contrastBiasStarted();
    void contrastBiasDragged(double dxFraction, double dyFraction);
    void contrastBiasResetRequested();

protected:
    void paintEvent(class QPaintEvent*) override;
    void mousePressEvent(class QMouseEvent*) override;
    void mouseMoveEvent(class QMouseEvent*) override;
    void mouseReleaseEvent(class QMouseEvent*) override;
    void mouseDoubleClickEvent(class QMouseEvent*) override;
    QSize sizeHint() const override { return {260, 44}; }

private:
    ColorMap m_map = ColorMap::Gray;
    core::StretchKind m_stretch = core::StretchKind::Linear;
    double m_lo = 0, m_hi = 1;
    bool m_valid = false;
    bool m_dragging = false;
    QPointF m_dragStart;
};

}  // namespace lwb::ui
