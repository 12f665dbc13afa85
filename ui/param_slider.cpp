#include "ui/param_slider.hpp"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QValidator>
#include <cmath>

namespace lwb::ui {

namespace {
constexpr int kSteps = 1000;

// A spin box that shows small values in scientific notation (MSE limits and the like).
class SciSpinBox : public QDoubleSpinBox {
public:
    using QDoubleSpinBox::QDoubleSpinBox;
    QString textFromValue(double v) const override { return QString::number(v, 'g', 3); }
    double valueFromText(const QString& text) const override { return text.toDouble(); }
    QValidator::State validate(QString& text, int&) const override {
        bool ok = false;
        text.toDouble(&ok);
        return ok ? QValidator::Acceptable : QValidator::Intermediate;
    }
    void stepBy(int steps) override { setValue(value() * std::pow(1.25, steps)); }
};
}  // namespace

ParamSlider::ParamSlider(const QString& label, double lo, double hi, double value, int decimals, bool logScale,
                         const QString& unit, QWidget* parent)
    : QWidget(parent), m_lo(lo), m_hi(hi), m_value(value), m_log(logScale && lo > 0) {
    auto* lay = new QHBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    m_label = new QLabel(label, this);
    m_label->setMinimumWidth(120);
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setRange(0, kSteps);
    m_slider->setMinimumWidth(90);
    m_field = m_log ? new SciSpinBox(this) : new QDoubleSpinBox(this);
    m_field->setDecimals(m_log ? 12 : decimals);
    m_field->setRange(lo, hi);
    m_field->setSingleStep(m_log ? value / 10 : (hi - lo) / 100);
    m_field->setKeyboardTracking(false);
    m_field->setMinimumWidth(104);
    if (!unit.isEmpty()) m_field->setSuffix(" " + unit);
    lay->addWidget(m_label);
    lay->addWidget(m_slider, 1);
    lay->addWidget(m_field);
    setValue(value);
    connect(m_slider, &QSlider::valueChanged, this, [this](int s) {
        if (m_updating) return;
        m_value = fromSlider(s);
        QSignalBlocker b(m_field);
        m_field->setValue(m_value);
        emit valueChanged(m_value);
    });
    connect(m_field, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (m_updating) return;
        m_value = v;
        QSignalBlocker b(m_slider);
        m_slider->setValue(toSlider(v));
        emit valueChanged(m_value);
    });
}

void ParamSlider::setValue(double v) {
    m_updating = true;
    m_value = std::clamp(v, m_lo, m_hi);
    m_slider->setValue(toSlider(m_value));
    m_field->setValue(m_value);
    m_updating = false;
}

void ParamSlider::setToolTipText(const QString& tip) {
    m_label->setToolTip(tip);
    m_slider->setToolTip(tip);
    m_field->setToolTip(tip);
}

int ParamSlider::toSlider(double v) const {
    const double t = m_log ? (std::log10(v) - std::log10(m_lo)) / (std::log10(m_hi) - std::log10(m_lo))
                           : (v - m_lo) / (m_hi - m_lo);
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSteps));
}

double ParamSlider::fromSlider(int s) const {
    const double t = double(s) / kSteps;
    return m_log ? std::pow(10.0, std::log10(m_lo) + t * (std::log10(m_hi) - std::log10(m_lo))) : m_lo + t * (m_hi - m_lo);
}

}  // namespace lwb::ui
