#pragma once
// ROI display like SAOImage DS9: limits (min–max, IRAF zscale, 99.5 %, manual), a stretch
// (linear, sqrt, log, asinh), a histogram of the ROI with the limits drawn, and a colour bar
// in DN. The math is core/common/display_stretch; these are the widgets and the rendering.
#include <QImage>
#include <QWidget>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/display_stretch.hpp"
#include "ui/color_maps.hpp"

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

signals:
    void changed();

private:
    QComboBox *m_limits, *m_stretch;
    QDoubleSpinBox *m_lo, *m_hi;
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

protected:
    void paintEvent(class QPaintEvent*) override;
    QSize sizeHint() const override { return {260, 44}; }

private:
    ColorMap m_map = ColorMap::Gray;
    core::StretchKind m_stretch = core::StretchKind::Linear;
    double m_lo = 0, m_hi = 1;
    bool m_valid = false;
};

}  // namespace lwb::ui
