#pragma once
// A labelled slider with a numeric field, built from a schema row (core::FieldInfo): the label,
// unit and tooltip (doc, valid range, special values) come from the row; the field accepts the
// row's valid range, the slider covers its typical UI range (log10 when uiLog). A value outside
// the UI range is kept exactly — the slider pins at its end, the field shows the true value —
// and changes only when the user changes it. A special value of the row (0 = "auto", NaN =
// "estimated" or "off") gets a check box beside the slider.
#include <QWidget>
#include <vector>

#include "core/common/schema.hpp"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace lwb::ui {

/// A value control in a scrolling panel changes on the wheel only once it has the focus (a click
/// or Tab); before that the wheel scrolls the panel. Without it, scrolling a panel with the
/// mouse over a slider, field or combo box silently changed the parameter under the pointer.
void guardWheel(QWidget* control);

class ParamSlider : public QWidget {
    Q_OBJECT
public:
    /// label: shown instead of the row's own (its key's last part).
    explicit ParamSlider(const core::FieldInfo& info, const QString& label = {}, QWidget* parent = nullptr);
    /// A slider without a schema row: the valid range is the slider's [lo, hi].
    ParamSlider(const QString& label, double lo, double hi, double value, int decimals, bool logScale = false,
                const QString& unit = {}, QWidget* parent = nullptr);

    /// The value exactly as set or edited (a special's value while its box is checked).
    double value() const { return m_value; }
    /// Shows v without emitting valueChanged; never clamped or rounded.
    void setValue(double v);
    /// What the slider and field show while a special value is on, e.g. the scale the automatic
    /// mode chose in the last run; unchecking the special box starts from it. NaN: none.
    void setSpecialHint(double v);
    void setToolTipText(const QString& tip);

    const core::FieldInfo& info() const { return m_info; }
    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* field() const { return m_field; }
    QLabel* label() const { return m_label; }
    /// The check box of the row's first special value, nullptr when it has none.
    QCheckBox* specialBox() const { return m_specials.empty() ? nullptr : m_specials.front(); }
    /// The value lies outside the slider's range (the slider sits at its end).
    bool pinned() const;

    /// The values at n positions spread evenly along the slider's track, from its left end to
    /// its right: where a strip's outcomes are computed.
    std::vector<double> trackValues(int n) const;
    /// A strip of outcomes along the track, drawn under the groove so that the plateau and the
    /// cliff are seen before the handle moves: `area` filled from the bottom, `line` as a line
    /// (each one number in [0, 1] per trackValues position; empty: not drawn); `tip` joins the
    /// slider's tooltip. clearStrip() takes it away.
    void setStrip(std::vector<double> area, std::vector<double> line, const QString& tip);
    void clearStrip();
    /// The strip describes parameters no longer set (a new one is being computed): drawn faint
    /// until setStrip or clearStrip.
    void setStripStale(bool stale);
    bool stripStale() const { return m_stripStale; }
    const std::vector<double>& stripArea() const { return m_stripArea; }
    const std::vector<double>& stripLine() const { return m_stripLine; }

signals:
    void valueChanged(double value);

private:
    void build(const QString& label);
    void show();
    void userValue(double v);
    int toSlider(double v) const;
    double fromSlider(int s) const;
    int specialIndex(double v) const;
    void showExactValue();

    core::FieldInfo m_info;
    QSlider* m_slider = nullptr;
    QDoubleSpinBox* m_field = nullptr;
    QLabel* m_label = nullptr;
    std::vector<QCheckBox*> m_specials;
    double m_value = 0;
    double m_regular = 0;        ///< the last value that is not a special one
    double m_hint = NAN;
    bool m_intSlider = false;    ///< the slider's positions are the integers of the UI range
    bool m_updating = false;
    QString m_tip;               ///< the row's tooltip (the exact value is added to it)
    std::vector<double> m_stripArea, m_stripLine;  ///< setStrip's
    QString m_stripTip;
    bool m_stripStale = false;
    friend class StripPainter;
};

}  // namespace lwb::ui
