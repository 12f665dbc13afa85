#pragma once
// Test helpers over the schema tables (core/common/schema.hpp): for any field, a valid value
// other than the default, so a round trip that drops or rewrites the field fails.
#include <cmath>
#include <string>
#include <vector>

#include <QtTest>

#include "core/common/schema.hpp"

namespace lwb::test {

/// Sets field f of *p to a valid value that differs from its current one (and from every
/// special value), preferring the UI range, and returns true; false when no candidate is
/// accepted by the field and the table's rules.
template <class P>
bool setOtherValue(const core::Schema<P>& schema, const typename core::Schema<P>::Field& f, P* p) {
    using core::FieldKind;
    P q = *p;
    switch (f.kind) {
        case FieldKind::Boolean: f.set(q, f.get(q) != 0 ? 0 : 1); break;
        case FieldKind::Choice: f.set(q, std::fmod(f.get(q) + 1, double(f.choices.size()))); break;
        case FieldKind::Text:
            // The footprint preset names known criteria (a rule); other text fields take any text.
            if (f.key == "preset") f.setText(q, f.getText(q) == "yao2021" ? "wu2021" : "yao2021");
            else f.setText(q, f.getText(q) + "_x");
            break;
        case FieldKind::Range: {
            core::RangeValue r = f.getRange(q);
            const core::RangeValue was = r;
            r.enabled = true;
            // Move the ends inside the UI range, keeping lo < hi.
            r.lo = f.uiLo + 0.25 * (f.uiHi - f.uiLo);
            r.hi = f.uiLo + 0.75 * (f.uiHi - f.uiLo);
            if (was.enabled && r.lo == was.lo && r.hi == was.hi) r.hi = f.uiLo + 0.6 * (f.uiHi - f.uiLo);
            f.setRange(q, r);
            break;
        }
        default: {
            const double now = f.get(q);
            const double lo = f.uiLo, hi = f.uiHi;
            std::vector<double> candidates = {lo + 0.37 * (hi - lo), lo + 0.61 * (hi - lo), lo, hi,
                                              std::isfinite(f.valid.lo) ? f.valid.lo + 1 : 1.0, now * 1.5, now + 1};
            bool found = false;
            for (double v : candidates) {
                if (f.kind == FieldKind::Integer) v = std::round(v);
                bool special = false;
                for (const auto& s : f.specials) special = special || s.matches(v);
                if (special || !std::isfinite(v) || v == now || !f.valid.contains(v)) continue;
                P t = q;
                f.set(t, v);
                if (!schema.validate(t).empty()) continue;
                q = t;
                found = true;
                break;
            }
            if (!found) return false;
        }
    }
    if (!schema.validate(q).empty()) return false;
    *p = q;
    return true;
}

/// "a, b, c" (messages about keys).
inline std::string joined(const std::vector<std::string>& keys) {
    std::string s;
    for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
    return s;
}

/// *base with field f set to another valid value (the footprint's preset name: the other named
/// preset); fails the test when there is none. When no other value of f is valid with *base as
/// it is (a rule ties f to other fields: automatic off needs a fixed scale), the fields of *base
/// left at a special value (0 = automatic) get regular values first: *base is changed then, and
/// the result differs from it in f alone.
template <class P>
P otherValue(const core::Schema<P>& schema, const typename core::Schema<P>::Field& f, P* base) {
    P p = *base;
    if (f.kind == core::FieldKind::Text && f.key == "preset") {
        f.setText(p, f.getText(p) == "yao2021" ? "wu2021" : "yao2021");
        return p;
    }
    if (setOtherValue(schema, f, &p)) return p;
    P b = *base;
    for (const auto& g : schema.fields()) {
        if (&g == &f || g.specials.empty() || (g.kind != core::FieldKind::Real && g.kind != core::FieldKind::Integer)) continue;
        bool special = false;
        for (const auto& s : g.specials) special = special || s.matches(g.get(b));
        if (special) setOtherValue(schema, g, &b);
    }
    p = b;
    if (!setOtherValue(schema, f, &p)) {
        // A rule between f and a choice (scale_chi2 applies to a given noise model): the
        // choices of *base tried in turn until f has another valid value.
        for (const auto& g : schema.fields()) {
            if (&g == &f || g.kind != core::FieldKind::Choice) continue;
            for (size_t k = 0; k < g.choices.size(); ++k) {
                P c = b;
                g.set(c, double(k));
                if (!schema.validate(c).empty()) continue;
                P t = c;
                if (setOtherValue(schema, f, &t)) {
                    *base = c;
                    return t;
                }
            }
        }
        QTest::qFail(("no other valid value for " + f.key).c_str(), __FILE__, __LINE__);
    }
    *base = b;
    return p;
}
}  // namespace lwb::test
