#include "ui/kit/param_slider.hpp"
#include "ui/kit/i18n.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QStyle>

#include <QApplication>
#include <QCheckBox>
#include <QEvent>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSlider>
#include <algorithm>
#include <cfloat>
#include <cmath>

namespace lwb::ui {

namespace {
constexpr int kSteps = 1000;

// Passes the wheel on to the panel (its scroll area) while the control has no focus.
class WheelGuard : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* e) override {
        if (e->type() != QEvent::Wheel) return false;
        auto* w = qobject_cast<QWidget*>(watched);
        if (!w || w->hasFocus()) return false;
        e->ignore();  // not accepted: QApplication offers it to the parents, the scroll area scrolls
        return true;
    }
};

// Shift+drag on a slider moves it ten times slower than the mouse: a logarithmic slider of
// seven decades at 14 px a decade took mag_T from 2 to 483 px/s in a 29 px drag (issue 42).
class FineDrag : public QObject {
public:
    using QObject::QObject;
    static constexpr int kSlowdown = 10;

protected:
    bool eventFilter(QObject* watched, QEvent* e) override {
        auto* s = qobject_cast<QSlider*>(watched);
        if (!s) return false;
        if (e->type() == QEvent::MouseButtonPress) {
            auto* me = static_cast<QMouseEvent*>(e);
            if (me->button() != Qt::LeftButton || !(me->modifiers() & Qt::ShiftModifier)) return false;
            m_active = true;
            m_x0 = me->position().x();
            m_s0 = s->value();
            s->setSliderDown(true);
            return true;
        }
        if (!m_active) return false;
        if (e->type() == QEvent::MouseMove) {
            const double dx = static_cast<QMouseEvent*>(e)->position().x() - m_x0;
            const double perPx = double(s->maximum() - s->minimum()) / std::max(1, s->width()) / kSlowdown;
            s->setValue(m_s0 + int(std::lround(dx * perPx)));
            return true;
        }
        if (e->type() == QEvent::MouseButtonRelease) {
            m_active = false;
            s->setSliderDown(false);
            return true;
        }
        return false;
    }

private:
    bool m_active = false;
    double m_x0 = 0;
    int m_s0 = 0;
};

double roundSignificant(double v, int digits) {
    if (v == 0 || !std::isfinite(v)) return v;
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::fabs(v))));
    return std::round(v * scale) / scale;
}

// The numeric field: accepts what the schema row accepts and never rounds what it is given;
// it shows the value with the digits its row asks for (issue 30: 0.1353352, 4.329739712682504
// and 11,482,396,630.7232 were shown whole and clipped), the exact value in its tooltip, and
// keeps the exact value when the text shown is left as it is.
class ValueField : public QDoubleSpinBox {
public:
    ValueField(const core::FieldInfo& info, QWidget* parent) : QDoubleSpinBox(parent), m_info(info) {
        const bool integer = info.kind == core::FieldKind::Integer;
        // QDoubleSpinBox rounds every value to `decimals`: the maximum keeps it exact.
        setDecimals(integer ? 0 : DBL_MAX_10_EXP + DBL_DIG);
        setRange(std::isfinite(info.valid.lo) ? info.valid.lo : -DBL_MAX, std::isfinite(info.valid.hi) ? info.valid.hi : DBL_MAX);
        const double span = info.uiHi - info.uiLo;
        setSingleStep(integer ? 1 : span > 0 ? std::pow(10.0, std::floor(std::log10(span / 100))) : 0.01);
        setKeyboardTracking(false);
        setMinimumWidth(86);
        setMaximumWidth(130);  // (four significant digits and the unit: "1.148e+10 px/s")
        if (!info.unit.empty()) setSuffix(" " + QString::fromStdString(info.unit));
        // Room for a short value and its unit ("1.345 sigma" showed as "1.345 sigm").
        setMinimumWidth(std::clamp(fontMetrics().horizontalAdvance("0.000" + suffix()) + 36, 86, 130));
        QLocale plain = locale();
        plain.setNumberOptions(plain.numberOptions() | QLocale::OmitGroupSeparator);  // "11482396630", not "11,482,…"
        setLocale(plain);
    }
    QString textFromValue(double v) const override {
        if (m_info.kind == core::FieldKind::Integer) return locale().toString(qlonglong(std::llround(v)));
        // Whole numbers as such (60000, not 6e+04); others with the row's digits, at least 4
        // significant ones (0.1353, 4.33, 1.148e+10, 0.03945).
        if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e6) return locale().toString(qlonglong(v));
        return lowerExponent(locale(), locale().toString(v, 'g', std::max(4, m_info.decimals)));
    }
    double valueFromText(const QString& text) const override {
        // The text as shown (rounded) stands for the exact value: leaving the field must not
        // round the parameter.
        QString shown = textFromValue(value());
        if (text.trimmed() == shown || text.trimmed() == shown + suffix()) return value();
        return parse(text, nullptr);
    }
    QValidator::State validate(QString& text, int&) const override {
        bool ok = false;
        const double v = parse(text, &ok);
        return ok && m_info.accepts(v) ? QValidator::Acceptable : QValidator::Intermediate;
    }
    void stepBy(int steps) override {
        double v = value();
        if (m_info.uiLog && v > 0) v = roundSignificant(v * std::pow(10.0, steps / 20.0), 3);
        else v += steps * singleStep();
        if (m_info.accepts(v)) setValue(v);
    }

private:
    double parse(QString text, bool* ok) const {
        if (!suffix().isEmpty() && text.endsWith(suffix())) text.chop(suffix().size());
        bool good = false;
        double v = locale().toDouble(text.trimmed(), &good);
        if (!good) v = QLocale::c().toDouble(text.trimmed(), &good);
        if (ok) *ok = good && std::isfinite(v);
        return v;
    }
    core::FieldInfo m_info;
};

core::FieldInfo plainInfo(const QString& label, double lo, double hi, int decimals, bool logScale, const QString& unit) {
    core::FieldInfo f;
    f.key = label.toStdString();
    f.kind = core::FieldKind::Real;
    f.unit = unit.toStdString();
    f.valid = {lo, hi};
    f.uiLo = lo;
    f.uiHi = hi;
    f.uiLog = logScale && lo > 0;
    f.decimals = decimals;
    return f;
}

QString firstUpper(QString s) {
    if (!s.isEmpty()) s[0] = s[0].toUpper();
    return s;
}
}  // namespace

// Draws a ParamSlider's strip on its track before the slider paints its groove and handle.
class StripPainter : public QObject {
public:
    StripPainter(ParamSlider* owner) : QObject(owner), m_owner(owner) {}

protected:
    bool eventFilter(QObject* watched, QEvent* e) override {
        if (e->type() != QEvent::Paint) return false;
        auto* s = qobject_cast<QSlider*>(watched);
        const std::vector<double>&a = m_owner->m_stripArea, &l = m_owner->m_stripLine;
        if (!s || (a.size() < 2 && l.size() < 2)) return false;
        // The handle's centre runs from half its length in to half its length from the end.
        const int len = s->style()->pixelMetric(QStyle::PM_SliderLength, nullptr, s);
        const double x0 = 0.5 * len, x1 = s->width() - 0.5 * len, h = s->height();
        QPainter p(s);
        p.setRenderHint(QPainter::Antialiasing);
        auto path = [&](const std::vector<double>& v, bool closed) {
            QPainterPath pp;
            for (size_t i = 0; i < v.size(); ++i) {
                const QPointF pt(x0 + (x1 - x0) * double(i) / double(v.size() - 1), h - 1 - (h - 2) * std::clamp(v[i], 0.0, 1.0));
                if (i == 0 && closed) pp.moveTo(x0, h - 1);
                if (i == 0 && !closed) pp.moveTo(pt);
                else pp.lineTo(pt);
            }
            if (closed) pp.lineTo(x1, h - 1), pp.closeSubpath();
            return pp;
        };
        // (the active colour also on a slider disabled while its value is automatic: the strip
        // says what setting it by hand would do)
        const QColor accent = s->palette().color(QPalette::Active, QPalette::Highlight);
        const bool stale = m_owner->m_stripStale;
        if (a.size() >= 2) {
            QColor fill = accent;
            fill.setAlpha(stale ? 40 : 110);
            p.fillPath(path(a, true), fill);
        }
        if (l.size() >= 2) p.strokePath(path(l, false), QPen(QColor(230, 120, 20, stale ? 70 : 255), 1.5));
        return false;  // the slider paints its groove and handle over it
    }

private:
    ParamSlider* m_owner;
};

std::vector<double> ParamSlider::trackValues(int n) const {
    std::vector<double> v;
    for (int i = 0; i < n && n > 1; ++i)
        v.push_back(fromSlider(m_slider->minimum() +
                               int(std::lround(double(m_slider->maximum() - m_slider->minimum()) * i / (n - 1)))));
    return v;
}

void ParamSlider::setStrip(std::vector<double> area, std::vector<double> line, const QString& tip) {
    if (!m_slider->property("stripPainter").toBool()) {
        m_slider->installEventFilter(new StripPainter(this));
        m_slider->setProperty("stripPainter", true);
    }
    m_stripArea = std::move(area);
    m_stripLine = std::move(line);
    m_stripTip = tip;
    m_stripStale = false;
    m_slider->setToolTip(m_tip + (m_tip.isEmpty() || tip.isEmpty() ? "" : "<br>") + tip);
    m_slider->update();
}

void ParamSlider::setStripStale(bool stale) {
    if (stale == m_stripStale) return;
    m_stripStale = stale;
    m_slider->update();
}

void ParamSlider::clearStrip() {
    m_stripStale = false;
    if (m_stripArea.empty() && m_stripLine.empty()) return;
    m_stripArea.clear();
    m_stripLine.clear();
    m_stripTip.clear();
    m_slider->setToolTip(m_tip);
    m_slider->update();
}

ParamSlider::ParamSlider(const core::FieldInfo& info, const QString& label, QWidget* parent)
    : QWidget(parent), m_info(info) {
    build(label.isEmpty() ? firstUpper(schemaText(info.label())) : label);
    QString tip = QString("<b>%1</b>").arg(QString::fromStdString(info.key).toHtmlEscaped());
    if (!info.unit.empty()) tip += QString(" (%1)").arg(QString::fromStdString(info.unit).toHtmlEscaped());
    tip += "<br>" + schemaText(info.doc).toHtmlEscaped();
    tip += "<br>" + tr("Valid: %1").arg(QString::fromStdString(info.rangeText()).toHtmlEscaped());
    tip += "<br>" + tr("Slider: %1 – %2%3 (values outside are kept; the slider then sits at its end)")
                        .arg(info.uiLo)
                        .arg(info.uiHi)
                        .arg(info.uiLog ? tr(", logarithmic") : QString());
    setToolTipText(tip);
}

ParamSlider::ParamSlider(const QString& label, double lo, double hi, double value, int decimals, bool logScale,
                         const QString& unit, QWidget* parent)
    : QWidget(parent), m_info(plainInfo(label, lo, hi, decimals, logScale, unit)) {
    build(label);
    setValue(value);
}

void ParamSlider::build(const QString& label) {
    const core::FieldInfo& f = m_info;
    m_intSlider = f.kind == core::FieldKind::Integer && !f.uiLog && f.uiHi - f.uiLo <= kSteps;
    auto* lay = new QHBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->setSpacing(4);
    m_label = new QLabel(label, this);
    // At least 100 px so that the sliders of a panel line up; a longer label keeps its text
    // (up to 130 px) rather than being cut when the panel is at its narrowest.
    m_label->setMinimumWidth(std::clamp(m_label->sizeHint().width(), 100, 130));
    m_slider = new QSlider(Qt::Horizontal, this);
    if (m_intSlider) m_slider->setRange(int(std::ceil(f.uiLo)), int(std::floor(f.uiHi)));
    else m_slider->setRange(0, kSteps);
    // A logarithmic slider gets at least 14 px a decade: mag_T's seven decades in 48 px moved
    // 4.33 → 3680 px/s in a 20 px drag (issue 30).
    const double decades = f.uiLog && f.uiLo > 0 && f.uiHi > f.uiLo ? std::log10(f.uiHi / f.uiLo) : 0;
    m_slider->setMinimumWidth(std::max(48, int(std::ceil(14 * decades))));
    m_field = new ValueField(f, this);
    lay->addWidget(m_label);
    lay->addWidget(m_slider, 1);
    lay->addWidget(m_field);
    guardWheel(m_slider);
    guardWheel(m_field);
    m_slider->installEventFilter(new FineDrag(m_slider));
    for (const core::SpecialValue& s : f.specials) {
        auto* box = new QCheckBox(schemaText(s.meaning), this);
        box->setToolTip(tr("%1 = %2").arg(std::isnan(s.value) ? QString("null") : QString::number(s.value),
                                          schemaText(s.meaning)));
        lay->addWidget(box);
        m_specials.push_back(box);
        const double special = s.value;
        connect(box, &QCheckBox::toggled, this, [this, special](bool on) {
            if (m_updating) return;
            if (on) {
                m_value = special;
            } else {
                m_value = std::isfinite(m_hint) && m_info.accepts(m_hint) && specialIndex(m_hint) < 0 ? m_hint : m_regular;
                m_regular = m_value;
            }
            show();
            emit valueChanged(m_value);
        });
    }
    // A regular value to start from while a special one is on: the middle of the UI range.
    double mid = f.uiLog && f.uiLo > 0 ? std::sqrt(f.uiLo * f.uiHi) : 0.5 * (f.uiLo + f.uiHi);
    mid = f.kind == core::FieldKind::Integer ? std::round(mid) : roundSignificant(mid, 3);
    m_regular = f.accepts(mid) && specialIndex(mid) < 0 ? mid : f.uiLo;
    m_value = m_regular;
    connect(m_slider, &QSlider::valueChanged, this, [this](int s) { userValue(fromSlider(s)); });
    connect(m_field, &QDoubleSpinBox::valueChanged, this, [this](double v) { userValue(v); });
    show();
}

int ParamSlider::specialIndex(double v) const {
    for (size_t i = 0; i < m_info.specials.size(); ++i)
        if (m_info.specials[i].matches(v)) return int(i);
    return -1;
}

void ParamSlider::setValue(double v) {
    m_value = v;
    if (specialIndex(v) < 0 && std::isfinite(v)) m_regular = v;
    show();
}

void ParamSlider::setSpecialHint(double v) {
    m_hint = v;
    if (specialIndex(m_value) >= 0) show();
}

void guardWheel(QWidget* control) {
    static WheelGuard* guard = new WheelGuard(qApp);
    control->setFocusPolicy(Qt::StrongFocus);  // a wheel over it does not take the focus either
    control->installEventFilter(guard);
}

bool ParamSlider::pinned() const {
    const double shown = specialIndex(m_value) >= 0 ? (std::isfinite(m_hint) ? m_hint : m_regular) : m_value;
    return shown < m_info.uiLo || shown > m_info.uiHi;
}

void ParamSlider::show() {
    m_updating = true;
    const int sp = specialIndex(m_value);
    for (size_t i = 0; i < m_specials.size(); ++i) m_specials[i]->setChecked(int(i) == sp);
    const double shown = sp >= 0 ? (std::isfinite(m_hint) ? m_hint : m_regular) : m_value;
    if (std::isfinite(shown)) {
        m_slider->setValue(toSlider(shown));
        m_field->setValue(shown);
        showExactValue();
    }
    m_slider->setEnabled(sp < 0);
    m_field->setEnabled(sp < 0);
    // A value beyond the slider's typical range: the field says so (bold, and in its tooltip).
    const bool out = sp < 0 && pinned();
    QFont font = m_field->font();
    if (font.bold() != out) {
        font.setBold(out);
        m_field->setFont(font);
    }
    m_field->setProperty("outsideSlider", out);
    m_updating = false;
}

void ParamSlider::userValue(double v) {
    if (m_updating) return;
    if (m_info.kind == core::FieldKind::Integer) v = std::round(v);
    if (!m_info.accepts(v)) {  // e.g. the open end of a range: show the value kept
        show();
        return;
    }
    m_value = v;
    if (specialIndex(v) < 0) m_regular = v;
    show();
    emit valueChanged(m_value);
}

void ParamSlider::setToolTipText(const QString& tip) {
    m_tip = tip;
    m_label->setToolTip(tip);
    m_slider->setToolTip(tip + (tip.isEmpty() || m_stripTip.isEmpty() ? "" : "<br>") + m_stripTip);
    showExactValue();
}

// The field shows the value rounded to its row's digits; its tooltip gives it exactly.
void ParamSlider::showExactValue() {
    const double v = m_field->value();
    m_field->setToolTip(m_tip + (m_tip.isEmpty() ? "" : "<br>") +
                        tr("Value: %1").arg(lowerExponent(QLocale(), QLocale().toString(v, 'g', QLocale::FloatingPointShortest))));
}

int ParamSlider::toSlider(double v) const {
    const core::FieldInfo& f = m_info;
    if (m_intSlider) return int(std::lround(std::clamp(v, double(m_slider->minimum()), double(m_slider->maximum()))));
    double t = 0;
    if (f.uiLog && f.uiLo > 0) t = v > 0 ? (std::log10(v) - std::log10(f.uiLo)) / (std::log10(f.uiHi) - std::log10(f.uiLo)) : 0;
    else if (f.uiHi > f.uiLo) t = (v - f.uiLo) / (f.uiHi - f.uiLo);
    return int(std::lround(std::clamp(t, 0.0, 1.0) * kSteps));
}

double ParamSlider::fromSlider(int s) const {
    const core::FieldInfo& f = m_info;
    if (m_intSlider) return s;
    const double t = double(s) / kSteps;
    if (f.uiLog && f.uiLo > 0) {
        const double v = std::pow(10.0, std::log10(f.uiLo) + t * (std::log10(f.uiHi) - std::log10(f.uiLo)));
        return f.kind == core::FieldKind::Integer ? std::round(v) : roundSignificant(v, 3);
    }
    const double v = f.uiLo + t * (f.uiHi - f.uiLo);
    if (f.kind == core::FieldKind::Integer) return std::round(v);
    const double step = std::pow(10.0, -std::max(0, f.decimals));
    return std::round(v / step) * step;
}

}  // namespace lwb::ui
