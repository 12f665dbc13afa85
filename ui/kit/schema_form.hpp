#pragma once
// Parameter widgets generated from a schema table (core/common/schema.hpp). A SchemaForm<P>
// holds one P and creates bound widgets by key — a ParamSlider for numbers, a check box for
// booleans, a combo box for choices (or for a numeric field's list of values), a RangeEdit for
// [min, max]-or-off rows, a line edit for text. Each widget writes only its own field into the
// held P; refresh() shows P in every widget without emitting anything. An edit that breaks a rule
// of the table is refused (the widget shows the held value again and onRefused gets the message).
//
//     SchemaForm<SlrParams> form(slrSchema(), this);
//     form.onChanged = [this](const std::string& key) { m_controller->setParams(form.params()); };
//     groupLayout->addRow(form.add("screen.cosine_c", tr("Cosine C")));
//     form.addRemaining(advancedLayout);   // every row not placed yet: nothing is unreachable
#include <QCheckBox>
#include <QCoreApplication>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QToolButton>
#include <QWidget>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/common/schema.hpp"
#include "ui/kit/i18n.hpp"
#include "ui/kit/param_slider.hpp"

namespace lwb::ui {

/// A [min, max] row that can be switched off (a schema Range field): a check box with the
/// label, and a slider for each end. Edits change only the part touched.
class RangeEdit : public QWidget {
    Q_OBJECT
public:
    RangeEdit(const core::FieldInfo& info, const QString& label, QWidget* parent = nullptr);
    core::RangeValue value() const { return m_value; }
    /// Shows r without emitting.
    void setValue(const core::RangeValue& r);
    QCheckBox* enabledBox() const { return m_on; }
    ParamSlider* loSlider() const { return m_lo; }
    ParamSlider* hiSlider() const { return m_hi; }

signals:
    void valueChanged(const lwb::core::RangeValue& value);

private:
    QCheckBox* m_on;
    ParamSlider *m_lo, *m_hi;
    core::RangeValue m_value;
    bool m_updating = false;
};

/// A section that folds open and shut (the "Advanced" rows).
class CollapsibleSection : public QWidget {
    Q_OBJECT
public:
    CollapsibleSection(const QString& title, QWidget* parent = nullptr);
    QFormLayout* form() const { return m_form; }
    QToolButton* toggle() const { return m_toggle; }
    void setExpanded(bool on);

private:
    QToolButton* m_toggle;
    QWidget* m_body;
    QFormLayout* m_form;
};

/// A combo box over a numeric field's listed values (connectivity 4 / 8) plus the row's special
/// values; a value not in the list gets an entry of its own, so it is shown and kept as it is.
class ValueCombo : public QComboBox {
    Q_OBJECT
public:
    ValueCombo(const core::FieldInfo& info, std::vector<std::pair<double, QString>> values, QWidget* parent = nullptr);
    double value() const { return m_value; }
    void setValue(double v);
    /// Appended to the special entries' text, e.g. the automatic choice of the last run.
    void setSpecialHint(const QString& hint);

signals:
    void valueEdited(double value);

private:
    void rebuild();
    core::FieldInfo m_info;
    std::vector<std::pair<double, QString>> m_values;
    double m_value = 0;
    QString m_hint;
    bool m_updating = false;
};

/// The label a row gets by default: its key's last part with a capital ("Threshold factor").
QString defaultLabel(const core::FieldInfo& info);
/// A bold heading row for a section of keys ("gauss").
QWidget* sectionHeading(const QString& section);

template <class P>
class SchemaForm {
public:
    using Schema = core::Schema<P>;
    using Field = typename Schema::Field;

    /// `owner` parents the widgets and scopes their connections.
    SchemaForm(const Schema& schema, QWidget* owner) : m_schema(schema), m_owner(owner), m_p() {}

    const P& params() const { return m_p; }
    const Schema& schema() const { return m_schema; }
    /// Holds p and shows it; emits nothing.
    void setParams(const P& p) {
        m_p = p;
        refresh();
    }
    /// Shows the held P in every widget without emitting.
    void refresh() {
        m_refreshing = true;
        for (auto& b : m_bindings) b.show(m_p);
        m_refreshing = false;
    }

    /// Called after an edit became part of params(), with the key of the field edited.
    std::function<void(const std::string& key)> onChanged;
    /// Called when an edit was refused because the result breaks the table's rules.
    std::function<void(const QString& message)> onRefused;
    /// Called after a widget wrote its field into a copy of params() and before that copy is
    /// checked: a panel may complete a change the user asked for with this very widget (turning
    /// the automatic mode off fills the scale it chose, say). Never used to touch other values.
    std::function<void(const std::string& key, P& p)> adjust;

    /// The bound widget of `key`, created on the first call: ParamSlider (Real, Integer),
    /// QCheckBox (Boolean), QComboBox (Choice: `choiceLabels` replace the names shown),
    /// RangeEdit (Range) or QLineEdit (Text). Place it with place() or by hand.
    QWidget* add(const std::string& key, const QString& label = {}, const QStringList& choiceLabels = {}) {
        if (QWidget* w = widget(key)) return w;
        const Field* f = field(key);
        const QString text = label.isEmpty() ? defaultLabel(*f) : label;
        switch (f->kind) {
            case core::FieldKind::Real:
            case core::FieldKind::Integer: {
                auto* s = new ParamSlider(*f, text, m_owner);
                QObject::connect(s, &ParamSlider::valueChanged, m_owner,
                                 [this, f](double v) { edited(*f, [f, v](P& p) { f->set(p, v); }); });
                bind(f, s, text, [f, s](const P& p) { s->setValue(f->get(p)); });
                return s;
            }
            case core::FieldKind::Boolean: {
                auto* c = new QCheckBox(text, m_owner);
                c->setToolTip(tooltip(*f));
                QObject::connect(c, &QCheckBox::toggled, m_owner,
                                 [this, f](bool on) { edited(*f, [f, on](P& p) { f->set(p, on ? 1 : 0); }); });
                bind(f, c, text, [f, c](const P& p) { c->setChecked(f->get(p) != 0); });
                return c;
            }
            case core::FieldKind::Choice: {
                auto* c = new QComboBox(m_owner);
                for (size_t i = 0; i < f->choices.size(); ++i)
                    c->addItem(int(i) < choiceLabels.size() ? choiceLabels[int(i)] : QString::fromStdString(f->choices[i]), int(i));
                c->setToolTip(tooltip(*f));
                // A long choice text ("Auto (elliptical from 10 measured detectors)") does not set
                // the panel's width: the combo takes the width the panel has, the list shows all.
                c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
                c->setMinimumContentsLength(12);
                guardWheel(c);
                QObject::connect(c, &QComboBox::currentIndexChanged, m_owner, [this, f, c](int i) {
                    const double v = c->itemData(i).toInt();
                    edited(*f, [f, v](P& p) { f->set(p, v); });
                });
                bind(f, c, text, [f, c](const P& p) { c->setCurrentIndex(c->findData(int(f->get(p)))); });
                return c;
            }
            case core::FieldKind::Range: {
                auto* r = new RangeEdit(*f, text, m_owner);
                QObject::connect(r, &RangeEdit::valueChanged, m_owner, [this, f](const core::RangeValue& v) {
                    edited(*f, [f, v](P& p) { f->setRange(p, v); });
                });
                bind(f, r, text, [f, r](const P& p) { r->setValue(f->getRange(p)); });
                return r;
            }
            case core::FieldKind::Text: {
                auto* e = new QLineEdit(m_owner);
                e->setToolTip(tooltip(*f));
                QObject::connect(e, &QLineEdit::editingFinished, m_owner, [this, f, e] {
                    const std::string v = e->text().toStdString();
                    if (v != f->getText(m_p)) edited(*f, [f, v](P& p) { f->setText(p, v); });
                });
                bind(f, e, text, [f, e](const P& p) { e->setText(QString::fromStdString(f->getText(p))); });
                return e;
            }
        }
        return nullptr;
    }

    /// A numeric field shown as a list of values (plus its specials), e.g. connectivity 4 / 8.
    ValueCombo* addValues(const std::string& key, std::vector<std::pair<double, QString>> values, const QString& label = {}) {
        if (QWidget* w = widget(key)) return qobject_cast<ValueCombo*>(w);
        const Field* f = field(key);
        auto* c = new ValueCombo(*f, std::move(values), m_owner);
        c->setToolTip(tooltip(*f));
        guardWheel(c);
        QObject::connect(c, &ValueCombo::valueEdited, m_owner,
                         [this, f](double v) { edited(*f, [f, v](P& p) { f->set(p, v); }); });
        bind(f, c, label.isEmpty() ? defaultLabel(*f) : label, [f, c](const P& p) { c->setValue(f->get(p)); });
        return c;
    }

    /// Adds the widget of `key` (created if needed) to a form layout, with its label where the
    /// widget does not show one itself.
    QWidget* place(QFormLayout* form, const std::string& key, const QString& label = {}) {
        QWidget* w = add(key, label);
        const Binding& b = *binding(key);
        if (qobject_cast<QComboBox*>(w) || qobject_cast<QLineEdit*>(w)) form->addRow(b.label, w);
        else form->addRow(w);
        return w;
    }

    /// Places a widget for every field that has none yet, in table order, except `skip`
    /// (fields a panel shows in its own way). Returns how many were added.
    /// Each section of the keys ("gauss" of "gauss.lm_tolerance_px") gets a heading.
    int addRemaining(QFormLayout* form, const std::set<std::string>& skip = {}) {
        int n = 0;
        std::string section = "\n";
        for (const auto& f : m_schema.fields()) {
            if (widget(f.key) || skip.count(f.key)) continue;
            const size_t dot = f.key.rfind('.');
            const std::string sec = dot == std::string::npos ? std::string() : f.key.substr(0, dot);
            if (sec != section && !sec.empty()) form->addRow(sectionHeading(QString::fromStdString(sec)));
            section = sec;
            place(form, f.key);
            ++n;
        }
        m_refreshing = true;
        for (auto& b : m_bindings) b.show(m_p);
        m_refreshing = false;
        return n;
    }

    /// A label for refused edits ("Not applied: why"), hidden until an edit is refused and again
    /// after an accepted one; sets onRefused and onChanged (which then calls `changed`).
    QLabel* addMessageLabel(std::function<void()> changed) {
        auto* label = new QLabel(m_owner);
        label->setWordWrap(true);
        label->setStyleSheet("color: #b00000");
        label->hide();
        onChanged = [label, changed = std::move(changed)](const std::string&) {
            label->hide();
            changed();
        };
        onRefused = [label](const QString& why) {
            label->setText(QObject::tr("Not applied: %1").arg(why));
            label->show();
        };
        return label;
    }

    QWidget* widget(const std::string& key) const {
        const Binding* b = binding(key);
        return b ? b->widget : nullptr;
    }
    /// The label of `key`'s row ("" when it has no widget).
    QString label(const std::string& key) const {
        const Binding* b = binding(key);
        return b ? b->label : QString();
    }
    /// The keys that have a widget, in the order they were added.
    std::vector<std::string> boundKeys() const {
        std::vector<std::string> keys;
        for (const auto& b : m_bindings) keys.push_back(b.field->key);
        return keys;
    }
    /// What a special value stands for just now (the automatic choice of the last run): shown on
    /// the field's slider or combo while the special is on.
    void setHint(const std::string& key, double v) {
        if (auto* s = qobject_cast<ParamSlider*>(widget(key))) s->setSpecialHint(v);
        else if (auto* c = qobject_cast<ValueCombo*>(widget(key)))
            c->setSpecialHint(std::isfinite(v) ? QString::number(v, 'g', 6) : QString());
    }

private:
    struct Binding {
        const Field* field;
        QWidget* widget;
        QString label;
        std::function<void(const P&)> show;
    };

    const Field* field(const std::string& key) const {
        const Field* f = m_schema.find(key);
        Q_ASSERT_X(f, "SchemaForm", key.c_str());
        return f;
    }
    const Binding* binding(const std::string& key) const {
        for (const auto& b : m_bindings)
            if (b.field->key == key) return &b;
        return nullptr;
    }
    void bind(const Field* f, QWidget* w, const QString& label, std::function<void(const P&)> show) {
        m_bindings.push_back({f, w, label, show});
        m_refreshing = true;
        show(m_p);
        m_refreshing = false;
    }
    // The key, the row's doc in the language of the window (as the sliders' tooltips), and what it
    // takes.
    static QString tooltip(const core::FieldInfo& f) {
        const QString range = f.kind == core::FieldKind::Boolean
                                  ? QCoreApplication::translate("lwb::ui::SchemaForm", "true or false")
                                  : QString::fromStdString(f.rangeText());
        return QString("<b>%1</b><br>%2<br>%3")
            .arg(QString::fromStdString(f.key).toHtmlEscaped(), schemaText(f.doc).toHtmlEscaped(), range.toHtmlEscaped());
    }

    void edited(const Field& f, const std::function<void(P&)>& write) {
        if (m_refreshing) return;
        P q = m_p;
        write(q);
        if (adjust) adjust(f.key, q);
        if (const std::string e = m_schema.validate(q); !e.empty()) {
            refresh();
            if (onRefused) onRefused(QString::fromStdString(e));
            return;
        }
        m_p = q;
        if (adjust) refresh();  // the adjustment may show elsewhere
        if (onChanged) onChanged(f.key);
    }

    const Schema& m_schema;
    QWidget* m_owner;
    P m_p;
    std::vector<Binding> m_bindings;
    bool m_refreshing = false;
};

}  // namespace lwb::ui
