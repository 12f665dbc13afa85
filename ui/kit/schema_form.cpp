#include "ui/kit/schema_form.hpp"

#include "ui/kit/i18n.hpp"

#include <QHash>
#include <QLabel>
#include <QStringList>
#include <QVBoxLayout>
#include <cmath>

namespace lwb::ui {

QString defaultLabel(const core::FieldInfo& info) {
    // Translated: the translation as it is (its words are not English ones to abbreviate).
    if (const QString t = schemaText(info.label()); t != QString::fromStdString(info.label())) return t;
    QStringList words = QString::fromStdString(info.label()).split(' ', Qt::SkipEmptyParts);
    // A last word that repeats the unit shown beside the field ("ring inner px" … px) goes.
    if (words.size() > 1 && !info.unit.empty() &&
        words.last().compare(QString::fromStdString(info.unit), Qt::CaseInsensitive) == 0)
        words.removeLast();
    // Abbreviations as the docs write them ("texture snr" → "Texture SNR").
    static const QHash<QString, QString> upper = {{"snr", "SNR"}, {"mse", "MSE"}, {"lm", "LM"},   {"rms", "RMS"},
                                                  {"np", "NP"},   {"crd", "CRD"}, {"cpf", "CPF"}, {"gcm", "GCM"},
                                                  {"tefm", "TEFM"}, {"dn", "DN"}, {"oc", "O-C"}};
    for (QString& w : words)
        if (const auto it = upper.constFind(w); it != upper.constEnd()) w = *it;
    QString s = words.join(' ');
    if (!s.isEmpty()) s[0] = s[0].toUpper();
    return s;
}

QWidget* sectionHeading(const QString& section) {
    // Translated: the name in the interface's language with the key's section beside it, as
    // --set and the JSON write it ("高斯拟合 gauss").
    const QString t = schemaText(section.toStdString());
    auto* l = new QLabel(t == section ? QString("<b>%1</b>").arg(section.toHtmlEscaped())
                                      : QString("<b>%1</b> <tt>%2</tt>").arg(t.toHtmlEscaped(), section.toHtmlEscaped()));
    l->setContentsMargins(0, 6, 0, 0);
    return l;
}

// ---------------------------------------------------------------------------------------------

RangeEdit::RangeEdit(const core::FieldInfo& info, const QString& label, QWidget* parent) : QWidget(parent) {
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->setSpacing(2);
    m_on = new QCheckBox(label, this);
    core::FieldInfo end = info;  // each end: a number in the row's valid range, no specials
    end.kind = core::FieldKind::Real;
    end.specials.clear();
    m_lo = new ParamSlider(end, tr("   min"), this);
    m_hi = new ParamSlider(end, tr("   max"), this);
    const QString tip = QString("<b>%1</b><br>%2<br>%3")
                            .arg(QString::fromStdString(info.key).toHtmlEscaped(), schemaText(info.doc).toHtmlEscaped(),
                                 QString::fromStdString(info.rangeText()).toHtmlEscaped());
    m_on->setToolTip(tip);
    lay->addWidget(m_on);
    lay->addWidget(m_lo);
    lay->addWidget(m_hi);
    connect(m_on, &QCheckBox::toggled, this, [this](bool on) {
        if (m_updating) return;
        m_value.enabled = on;
        m_lo->setEnabled(on);
        m_hi->setEnabled(on);
        emit valueChanged(m_value);
    });
    connect(m_lo, &ParamSlider::valueChanged, this, [this](double v) {
        m_value.lo = v;
        emit valueChanged(m_value);
    });
    connect(m_hi, &ParamSlider::valueChanged, this, [this](double v) {
        m_value.hi = v;
        emit valueChanged(m_value);
    });
}

void RangeEdit::setValue(const core::RangeValue& r) {
    m_updating = true;
    m_value = r;
    m_on->setChecked(r.enabled);
    m_lo->setValue(r.lo);
    m_hi->setValue(r.hi);
    m_lo->setEnabled(r.enabled);
    m_hi->setEnabled(r.enabled);
    m_updating = false;
}

// ---------------------------------------------------------------------------------------------

CollapsibleSection::CollapsibleSection(const QString& title, QWidget* parent) : QWidget(parent) {
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    m_toggle = new QToolButton(this);
    m_toggle->setText(title);
    m_toggle->setCheckable(true);
    m_toggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toggle->setAutoRaise(true);
    QFont f = m_toggle->font();
    f.setBold(true);
    m_toggle->setFont(f);
    m_body = new QWidget(this);
    m_form = new QFormLayout(m_body);
    m_form->setContentsMargins(8, 0, 0, 0);
    lay->addWidget(m_toggle);
    lay->addWidget(m_body);
    connect(m_toggle, &QToolButton::toggled, this, &CollapsibleSection::setExpanded);
    setExpanded(false);
}

void CollapsibleSection::setExpanded(bool on) {
    if (m_toggle->isChecked() != on) m_toggle->setChecked(on);  // comes back here through toggled
    m_toggle->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
    m_body->setVisible(on);
}

// ---------------------------------------------------------------------------------------------

ValueCombo::ValueCombo(const core::FieldInfo& info, std::vector<std::pair<double, QString>> values, QWidget* parent)
    : QComboBox(parent), m_info(info), m_values(std::move(values)) {
    rebuild();
    connect(this, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (m_updating || i < 0) return;
        m_value = itemData(i).toDouble();
        emit valueEdited(m_value);
    });
}

void ValueCombo::setValue(double v) {
    m_value = v;
    rebuild();
}

void ValueCombo::setSpecialHint(const QString& hint) {
    m_hint = hint;
    rebuild();
}

void ValueCombo::rebuild() {
    m_updating = true;
    clear();
    int current = -1;
    auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    for (const core::SpecialValue& s : m_info.specials) {
        QString text = schemaText(s.meaning);
        if (!m_hint.isEmpty()) text += QString(" (%1)").arg(m_hint);
        addItem(text, s.value);
        if (same(s.value, m_value)) current = count() - 1;
    }
    for (const auto& [v, text] : m_values) {
        addItem(text, v);
        if (same(v, m_value)) current = count() - 1;
    }
    if (current < 0) {  // a value the list does not hold: shown and kept as it is
        addItem(QString::number(m_value, 'g', 17), m_value);
        current = count() - 1;
    }
    setCurrentIndex(current);
    m_updating = false;
}

}  // namespace lwb::ui
