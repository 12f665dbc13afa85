#pragma once
// A labelled slider with a numeric field, linear or logarithmic; the unit of parameter panels.
#include <QWidget>

class QSlider;
class QDoubleSpinBox;
class QLabel;

namespace lwb::ui {

class ParamSlider : public QWidget {
    Q_OBJECT
public:
    /// decimals: shown in the field; logScale: the slider moves in log10(value) (lo > 0).
    ParamSlider(const QString& label, double lo, double hi, double value, int decimals, bool logScale = false,
                const QString& unit = {}, QWidget* parent = nullptr);
    double value() const { return m_value; }
    /// Sets the value without emitting valueChanged (for loading presets/sessions).
    void setValue(double v);
    void setToolTipText(const QString& tip);
    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* field() const { return m_field; }

signals:
    void valueChanged(double value);

private:
    int toSlider(double v) const;
    double fromSlider(int s) const;
    QSlider* m_slider;
    QDoubleSpinBox* m_field;
    QLabel* m_label;
    double m_lo, m_hi, m_value;
    bool m_log;
    bool m_updating = false;
};

}  // namespace lwb::ui
