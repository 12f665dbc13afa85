#pragma once
// A declarative parameter schema: next to every ...Params struct, one table declares each field
// once — key, unit, valid range, typical UI range, default (the struct's own initialiser) and a
// one-line doc. Validation, JSON (configs, presets, sessions), the CLI's --config /
// --print-config / --set key=value and the GUI's ranges, units and tooltips all come from it.
// Modelled on QGIS Processing's parameter declarations and GEGL's property_double(...)
// value_range() ui_range() description().
//
// Declaring a table:
//     Schema<ScreenParams> s("slr");
//     s.real("cosine_c", LWB_FIELD(ScreenParams, cosineC), "", {0.5, 1, false, true}, {0.9, 0.999},
//            "cosine constant C of the recovery step (paper 004 eq. 3)");
// Keys may be dotted ("segment.threshold_factor"): JSON nests them as objects.
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/common/json.hpp"
#include "core/common/text.hpp"

/// Accessor of a (possibly nested) member for a schema row: LWB_FIELD(FootprintParams, segment.fillHoles).
#define LWB_FIELD(P, member) [](P & p_) -> decltype(auto) { return (p_.member); }

namespace lwb::core {

enum class FieldKind { Real, Integer, Boolean, Choice, Text, Range };

/// One parameter set by name, as a front end gathers it (the CLI's --set KEY=VALUE and its named
/// aliases, Python's {key: value}) for the core to apply (Schema::setFromText) in order.
struct ParamSetting {
    std::string key, value;
    std::string label;  ///< how messages name it ("--cos-c 1.2", "--set screen.cosine_c=1.2"); "" = "KEY=VALUE"
};

/// A valid interval: [lo, hi] with either end open.
struct Interval {
    double lo = -INFINITY, hi = INFINITY;
    bool loOpen = false, hiOpen = false;
    bool contains(double v) const {
        return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    }
    std::string text() const;  ///< "[0.5, 1)"
};

/// A value allowed outside the valid interval, with what it means (0 = "automatic", NaN =
/// "estimated from the data": JSON null).
struct SpecialValue {
    double value;
    std::string meaning;
    bool matches(double v) const { return std::isnan(value) ? std::isnan(v) : v == value; }
};

/// An optional interval parameter of the verdict ([lo, hi] or off).
struct RangeValue {
    bool enabled = true;
    double lo = 0, hi = 0;
};

/// What generic code (help, GUI, docs) reads about one field.
struct FieldInfo {
    std::string key;       ///< "segment.threshold_factor"
    FieldKind kind = FieldKind::Real;
    std::string unit;      ///< "px", "DN", "s", "%", "" for none
    Interval valid;        ///< hard range; values outside are errors (except specials)
    double uiLo = 0, uiHi = 1;  ///< typical range for a slider; values outside are kept, never clamped
    bool uiLog = false;    ///< slider on a log scale (magnifications)
    int decimals = 3;      ///< shown in fields
    std::string doc;       ///< one line
    std::vector<SpecialValue> specials;
    std::vector<std::string> choices;  ///< Choice: the names, stored as the enum's index
    /// The first stage of its task that reads this field (the task's own enum; 0 = the first):
    /// a change reruns from the earliest stage it touches and reuses what comes before.
    int stage = 0;
    std::string label() const;         ///< key's last part with spaces: "threshold factor"
    std::string rangeText() const;     ///< "[0.5, 1) (0 = automatic)"
    /// A value of this field is acceptable (finite and in range, or a special).
    bool accepts(double v) const;
};

template <class P>
class Schema {
public:
    struct Field : FieldInfo {
        std::function<double(const P&)> get;         // Real, Integer, Boolean, Choice
        std::function<void(P&, double)> set;
        std::function<std::string(const P&)> getText;  // Text
        std::function<void(P&, const std::string&)> setText;
        std::function<RangeValue(const P&)> getRange;  // Range
        std::function<void(P&, const RangeValue&)> setRange;
    };

    /// `name` prefixes keys in messages ("slr.cosine_c = 1.2: must be in [0.5, 1)").
    explicit Schema(std::string name) : m_name(std::move(name)) {}
    const std::string& name() const { return m_name; }
    const std::vector<Field>& fields() const { return m_fields; }
    const Field* find(const std::string& key) const {
        for (const auto& f : m_fields)
            if (f.key == key) return &f;
        return nullptr;
    }

    // ---- declaration ---------------------------------------------------------------------
    template <class Acc>
    Field& real(std::string key, Acc acc, std::string unit, Interval valid, std::pair<double, double> ui, std::string doc) {
        Field& f = add(std::move(key), FieldKind::Real, std::move(unit), valid, ui, std::move(doc));
        f.get = [acc](const P& p) { return static_cast<double>(acc(const_cast<P&>(p))); };
        f.set = [acc](P& p, double v) { acc(p) = v; };
        return f;
    }
    /// A real value behind a getter and a setter (a value plus an on/off flag, say).
    Field& real(std::string key, std::function<double(const P&)> get, std::function<void(P&, double)> set, std::string unit,
                Interval valid, std::pair<double, double> ui, std::string doc) {
        Field& f = add(std::move(key), FieldKind::Real, std::move(unit), valid, ui, std::move(doc));
        f.get = std::move(get);
        f.set = std::move(set);
        return f;
    }
    template <class Acc>
    Field& integer(std::string key, Acc acc, std::string unit, Interval valid, std::pair<double, double> ui, std::string doc) {
        Field& f = add(std::move(key), FieldKind::Integer, std::move(unit), valid, ui, std::move(doc));
        f.decimals = 0;
        f.get = [acc](const P& p) { return static_cast<double>(acc(const_cast<P&>(p))); };
        f.set = [acc](P& p, double v) { acc(p) = static_cast<std::remove_reference_t<decltype(acc(p))>>(std::llround(v)); };
        return f;
    }
    template <class Acc>
    Field& boolean(std::string key, Acc acc, std::string doc) {
        Field& f = add(std::move(key), FieldKind::Boolean, "", {0, 1}, {0, 1}, std::move(doc));
        f.decimals = 0;
        f.get = [acc](const P& p) { return acc(const_cast<P&>(p)) ? 1.0 : 0.0; };
        f.set = [acc](P& p, double v) { acc(p) = v != 0; };
        return f;
    }
    /// An enum stored as its index into `names`.
    template <class Acc>
    Field& choice(std::string key, Acc acc, std::vector<std::string> names, std::string doc) {
        const double n = static_cast<double>(names.size());
        Field& f = add(std::move(key), FieldKind::Choice, "", {0, n - 1}, {0, n - 1}, std::move(doc));
        f.decimals = 0;
        f.choices = std::move(names);
        f.get = [acc](const P& p) { return static_cast<double>(static_cast<int>(acc(const_cast<P&>(p)))); };
        f.set = [acc](P& p, double v) { acc(p) = static_cast<std::remove_reference_t<decltype(acc(p))>>(static_cast<int>(v)); };
        return f;
    }
    template <class Acc>
    Field& text(std::string key, Acc acc, std::string doc) {
        Field& f = add(std::move(key), FieldKind::Text, "", {}, {0, 1}, std::move(doc));
        f.getText = [acc](const P& p) { return std::string(acc(const_cast<P&>(p))); };
        f.setText = [acc](P& p, const std::string& v) { acc(p) = v; };
        return f;
    }
    /// A [lo, hi] interval that can be switched off. `enabled`, `lo`, `hi`: accessors.
    template <class AccOn, class AccLo, class AccHi>
    Field& range(std::string key, AccOn on, AccLo lo, AccHi hi, std::string unit, Interval valid,
                 std::pair<double, double> ui, std::string doc) {
        Field& f = add(std::move(key), FieldKind::Range, std::move(unit), valid, ui, std::move(doc));
        f.getRange = [on, lo, hi](const P& p) {
            P& q = const_cast<P&>(p);
            return RangeValue{static_cast<bool>(on(q)), static_cast<double>(lo(q)), static_cast<double>(hi(q))};
        };
        f.setRange = [on, lo, hi](P& p, const RangeValue& r) {
            on(p) = r.enabled;
            lo(p) = r.lo;
            hi(p) = r.hi;
        };
        return f;
    }
    /// A rule between fields ("weak_below must be below strong_above"): "" when it holds.
    /// `section` ("screen.") makes it part of that section's validation too. `onEachSet` false:
    /// a rule between independent options (a model and an option of that model), checked by
    /// validate() and fromJson() once every setting is in, not by each setFromText, so the
    /// order of --set options (or of a dict's keys) does not matter.
    /// An older spelling that files written before a rename still hold: `rewrite` turns a JSON
    /// document that has it into today's keys before fromJson reads it (it is not an unknown key).
    void legacy(std::function<void(Json&)> rewrite) { m_legacy.push_back(std::move(rewrite)); }

    void rule(std::function<std::string(const P&)> r, std::string section = {}, bool onEachSet = true) {
        m_rules.push_back({std::move(section), std::move(r), onEachSet});
    }

    // ---- use --------------------------------------------------------------------------------
    /// "" when every field is valid and every rule holds, else the first problem:
    /// "slr.cosine_c = 1.2: must be in [0.5, 1)". With a prefix ("roi."), only the fields of
    /// that section (rules are not checked).
    std::string validate(const P& p, const std::string& prefix = {}) const {
        for (const auto& f : m_fields)
            if (f.key.rfind(prefix, 0) == 0)
                if (std::string e = checkField(f, p); !e.empty()) return e;
        for (const auto& r : m_rules)
            if (prefix.empty() || r.section == prefix)
                if (std::string e = r.check(p); !e.empty()) return m_name + ": " + e;
        return {};
    }

    /// Every field, always written, nested by the dotted keys.
    Json toJson(const P& p) const {
        Json j = Json::object();
        for (const auto& f : m_fields) slot(j, f.key) = fieldJson(f, p);
        return j;
    }

    /// Reads `j` over *inout (missing keys keep *inout's values: start from P{} for defaults).
    /// Unknown keys, wrong types and invalid values are errors naming the key, with the file,
    /// line and column when `doc` (the parse result `j` came from) is given. *inout is left
    /// untouched on error.
    bool fromJson(const Json& given, P* inout, std::string* error, const JsonParseResult* doc = nullptr,
                  const std::vector<std::string>& at = {}) const {
        Json rewritten;
        if (!m_legacy.empty() && given.is_object()) {
            rewritten = given;
            for (const auto& l : m_legacy) l(rewritten);
        }
        const Json& j = m_legacy.empty() || !given.is_object() ? given : rewritten;
        auto where = [&](const std::vector<std::string>& rel) {
            std::vector<std::string> path = at;
            path.insert(path.end(), rel.begin(), rel.end());
            return doc ? doc->where(path) : std::string();
        };
        if (!j.is_object()) {
            *error = where({}) + m_name + " parameters must be a JSON object";
            return false;
        }
        const Json reference = toJson(*inout);
        if (const auto unknown = firstUnknownKey(j, reference); !unknown.empty()) {
            *error = where(unknown) + "unknown key \"" + printableExcerpt(joinPath(unknown)) + "\" in the " + m_name +
                     " parameters (known keys: see --print-config)";
            return false;
        }
        P p = *inout;
        for (const auto& f : m_fields) {
            const std::vector<std::string> path = splitKey(f.key);
            const Json* v = &j;
            for (const auto& part : path) {
                if (!v->is_object() || !v->contains(part)) {
                    v = nullptr;
                    break;
                }
                v = &(*v)[part];
            }
            if (!v) continue;
            if (std::string e = setFromJson(f, p, *v); !e.empty()) {
                *error = where(path) + m_name + "." + f.key + ": " + e;
                return false;
            }
            if (std::string e = checkField(f, p); !e.empty()) {
                *error = where(path) + e;
                return false;
            }
        }
        for (const auto& r : m_rules)
            if (std::string e = r.check(p); !e.empty()) {
                *error = where({}) + m_name + ": " + e;
                return false;
            }
        *inout = p;
        return true;
    }

    /// --set key=value: the value as text ("0.8", "true", "gauss", "1,1.5" or "off" for a
    /// range, "auto" or "null" for a special). False with *error; *p untouched on error.
    bool setFromText(P* p, const std::string& key, const std::string& value, std::string* error) const {
        const Field* f = find(key);
        if (!f) {
            std::vector<std::string> keys;
            for (const Field& g : m_fields) keys.push_back(g.key);
            const std::string near = didYouMean(key, keys);
            *error = "unknown parameter \"" + printableExcerpt(key) + "\" for " + m_name +
                     (near.empty() ? " (--print-config lists them)" : near);
            return false;
        }
        P q = *p;
        std::string e = setFromTextValue(*f, q, value);
        if (e.empty()) e = checkField(*f, q);
        else e = m_name + "." + key + " = " + printableExcerpt(value) + ": " + e;
        if (e.empty()) {
            for (const auto& r : m_rules) {
                if (!r.onEachSet) continue;  // (a whole-set rule: validate() checks it)
                if (e = r.check(q); !e.empty()) {
                    e = m_name + ": " + e;
                    break;
                }
            }
        }
        if (!e.empty()) {
            *error = e;
            return false;
        }
        *p = q;
        return true;
    }

    /// The field's value as text (for messages, tables and --set round trips).
    std::string valueText(const Field& f, const P& p) const {
        switch (f.kind) {
            case FieldKind::Text: return f.getText(p);
            case FieldKind::Boolean: return f.get(p) != 0 ? "true" : "false";
            case FieldKind::Choice: {
                const int i = static_cast<int>(f.get(p));
                return i >= 0 && i < static_cast<int>(f.choices.size()) ? f.choices[static_cast<size_t>(i)] : "?";
            }
            case FieldKind::Range: {
                const RangeValue r = f.getRange(p);
                return r.enabled ? formatShortest(r.lo) + "," + formatShortest(r.hi) : "off";
            }
            default: {
                const double v = f.get(p);
                for (const auto& s : f.specials)
                    if (s.matches(v)) return std::isnan(v) ? "null" : formatShortest(v);
                return formatShortest(v);
            }
        }
    }

    /// The keys of the fields whose values differ between a and b (NaN equals NaN), in table
    /// order: what a change touched, for running again only the stages it affects.
    std::vector<std::string> changedKeys(const P& a, const P& b) const {
        std::vector<std::string> keys;
        for (const auto& f : m_fields)
            if (differs(f, a, b)) keys.push_back(f.key);
        return keys;
    }

    /// The earliest stage (FieldInfo::stage, from the rows' tags) whose fields differ between a
    /// and b; -1 when none differs. A task reruns from there and reuses the stages before it.
    int firstChangedStage(const P& a, const P& b) const {
        int first = -1;
        for (const auto& f : m_fields)
            if ((first < 0 || f.stage < first) && differs(f, a, b)) first = f.stage;
        return first;
    }

    /// Rows declared from now on belong to `stage` (until the next call): the tag of
    /// FieldInfo::stage, set once where the rows are declared.
    void beginStage(int stage) { m_stage = stage; }

    /// `text` with every "{default:KEY}" replaced by KEY's value in `defaults` (valueText): help
    /// text that names a default takes it from the schema row, never restates it. An unknown key
    /// stays as "{default:KEY?}" (test_schema looks for it in every command's help).
    std::string fillDefaults(std::string text, const P& defaults) const {
        static const std::string open = "{default:";
        size_t at = text.find(open);
        while (at != std::string::npos) {
            const size_t close = text.find('}', at);
            if (close == std::string::npos) break;
            const std::string key = text.substr(at + open.size(), close - at - open.size());
            const Field* f = find(key);
            const std::string value = f ? valueText(*f, defaults) : "{default:" + key + "?}";
            text.replace(at, close + 1 - at, value);
            at = text.find(open, at + value.size());
        }
        return text;
    }

    /// "key  unit  range  default  doc" lines for --help and docs.
    std::string describe(const P& defaults) const {
        std::string s;
        for (const auto& f : m_fields) {
            s += "  " + f.key + " = " + valueText(f, defaults);
            if (!f.unit.empty()) s += " " + f.unit;
            s += "  " + f.rangeText() + "\n      " + f.doc + "\n";
        }
        return s;
    }

private:
    static bool differs(const Field& f, const P& a, const P& b) {
        auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
        switch (f.kind) {
            case FieldKind::Text: return f.getText(a) != f.getText(b);
            case FieldKind::Range: {
                const RangeValue x = f.getRange(a), y = f.getRange(b);
                return !(x.enabled == y.enabled && same(x.lo, y.lo) && same(x.hi, y.hi));
            }
            default: return !same(f.get(a), f.get(b));
        }
    }

    Field& add(std::string key, FieldKind kind, std::string unit, Interval valid, std::pair<double, double> ui, std::string doc) {
        Field f;
        f.key = std::move(key);
        f.stage = m_stage;
        f.kind = kind;
        f.unit = std::move(unit);
        f.valid = valid;
        f.uiLo = ui.first;
        f.uiHi = ui.second;
        f.doc = std::move(doc);
        m_fields.push_back(std::move(f));
        return m_fields.back();
    }

    static std::vector<std::string> splitKey(const std::string& key) {
        std::vector<std::string> parts;
        size_t b = 0;
        for (size_t dot; (dot = key.find('.', b)) != std::string::npos; b = dot + 1) parts.push_back(key.substr(b, dot - b));
        parts.push_back(key.substr(b));
        return parts;
    }
    static Json& slot(Json& j, const std::string& key) {
        Json* cur = &j;
        for (const auto& part : splitKey(key)) {
            if (!cur->is_object()) *cur = Json::object();
            cur = &(*cur)[part];
        }
        return *cur;
    }

    Json fieldJson(const Field& f, const P& p) const {
        switch (f.kind) {
            case FieldKind::Text: return f.getText(p);
            case FieldKind::Boolean: return f.get(p) != 0;
            case FieldKind::Choice: return valueText(f, p);
            case FieldKind::Integer: return static_cast<long long>(std::llround(f.get(p)));
            case FieldKind::Range: {
                const RangeValue r = f.getRange(p);
                if (!r.enabled) return nullptr;
                return Json::array({r.lo, r.hi});
            }
            case FieldKind::Real: {
                const double v = f.get(p);
                if (!std::isfinite(v)) return nullptr;
                return v;
            }
        }
        return nullptr;
    }

    std::string checkField(const Field& f, const P& p) const {
        auto bad = [&](const std::string& v, const std::string& why) { return m_name + "." + f.key + " = " + v + ": " + why; };
        switch (f.kind) {
            case FieldKind::Text: return {};
            case FieldKind::Range: {
                const RangeValue r = f.getRange(p);
                if (!r.enabled) return {};
                if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || !(r.lo <= r.hi))
                    return bad(valueText(f, p), "needs min <= max");
                if (!f.valid.contains(r.lo) || !f.valid.contains(r.hi)) return bad(valueText(f, p), "must be within " + f.valid.text());
                return {};
            }
            default: {
                const double v = f.get(p);
                if (f.accepts(v)) return {};
                return bad(formatShortest(v), "must be " + (f.kind == FieldKind::Integer ? std::string("a whole number ") : std::string()) +
                                                  "in " + f.rangeText());
            }
        }
    }

    std::string setFromJson(const Field& f, P& p, const Json& v) const {
        switch (f.kind) {
            case FieldKind::Text:
                if (!v.is_string()) return "must be a string";
                f.setText(p, v.get<std::string>());
                return {};
            case FieldKind::Boolean:
                if (!v.is_boolean()) return "must be true or false";
                f.set(p, v.get<bool>() ? 1 : 0);
                return {};
            case FieldKind::Choice:
                if (v.is_string()) return setFromTextValue(f, p, v.get<std::string>());
                return "must be one of: " + choiceList(f);
            case FieldKind::Range:
                if (v.is_null()) {
                    RangeValue r = f.getRange(p);
                    r.enabled = false;
                    f.setRange(p, r);
                    return {};
                }
                if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) return "must be [min, max] or null (off)";
                f.setRange(p, {true, v[0].get<double>(), v[1].get<double>()});
                return {};
            default:
                if (v.is_null()) {
                    for (const auto& s : f.specials)
                        if (std::isnan(s.value)) {
                            f.set(p, NAN);
                            return {};
                        }
                    return "must be a number (null is not allowed here)";
                }
                if (!v.is_number()) return "must be a number";
                {
                    const double d = v.get<double>();
                    if (f.kind == FieldKind::Integer && d != std::floor(d)) return "must be a whole number";
                    if (!std::isfinite(d)) return "must be a finite number";
                    if (f.kind == FieldKind::Integer && std::fabs(d) > 2e9) return "must be in " + f.rangeText();
                    f.set(p, d);
                }
                return {};
        }
        return {};
    }

    static std::string choiceList(const Field& f) {
        std::string s;
        for (const auto& c : f.choices) s += (s.empty() ? "" : ", ") + c;
        return s;
    }

    std::string setFromTextValue(const Field& f, P& p, const std::string& text) const {
        const std::string t = toLower(trim(text));
        switch (f.kind) {
            case FieldKind::Text: f.setText(p, std::string(trim(text))); return {};
            case FieldKind::Boolean:
                if (t == "true" || t == "1" || t == "yes" || t == "on") f.set(p, 1);
                else if (t == "false" || t == "0" || t == "no" || t == "off") f.set(p, 0);
                else return "must be true or false";
                return {};
            case FieldKind::Choice:
                for (size_t i = 0; i < f.choices.size(); ++i)
                    if (t == f.choices[i]) {
                        f.set(p, static_cast<double>(i));
                        return {};
                    }
                return "must be one of: " + choiceList(f);
            case FieldKind::Range: {
                if (t == "off" || t == "null") {
                    RangeValue r = f.getRange(p);
                    r.enabled = false;
                    f.setRange(p, r);
                    return {};
                }
                const size_t c = t.find(',');
                double lo = 0, hi = 0;
                if (c == std::string::npos || !parseDouble(t.substr(0, c), &lo) || !parseDouble(t.substr(c + 1), &hi))
                    return "must be MIN,MAX or off";
                f.setRange(p, {true, lo, hi});
                return {};
            }
            default: {
                for (const auto& s : f.specials)
                    if ((std::isnan(s.value) && (t == "null" || t == "nan" || t == toLower(s.meaning))) ||
                        (!std::isnan(s.value) && t == toLower(s.meaning))) {
                        f.set(p, s.value);
                        return {};
                    }
                double d = 0;
                if (!parseDouble(t, &d)) return "not a number";
                if (f.kind == FieldKind::Integer && d != std::floor(d)) return "must be a whole number";
                if (f.kind == FieldKind::Integer && std::fabs(d) > 2e9) return "must be in " + f.rangeText();
                f.set(p, d);
                return {};
            }
        }
        return {};
    }

    std::string m_name;
    int m_stage = 0;
    std::vector<Field> m_fields;
    struct Rule {
        std::string section;
        std::function<std::string(const P&)> check;
        bool onEachSet = true;
    };
    std::vector<Rule> m_rules;
    std::vector<std::function<void(Json&)>> m_legacy;
};

}  // namespace lwb::core
