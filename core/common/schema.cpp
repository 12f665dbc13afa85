#include "core/common/schema.hpp"

namespace lwb::core {

namespace {
std::string bound(double v) {
    if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
    return formatShortest(v);
}
}  // namespace

std::string Interval::text() const {
    return std::string(loOpen ? "(" : "[") + bound(lo) + ", " + bound(hi) + (hiOpen ? ")" : "]");
}

std::string FieldInfo::label() const {
    std::string s = key.substr(key.find_last_of('.') == std::string::npos ? 0 : key.find_last_of('.') + 1);
    for (char& c : s)
        if (c == '_') c = ' ';
    return s;
}

std::string FieldInfo::rangeText() const {
    if (kind == FieldKind::Boolean) return "true or false";
    if (kind == FieldKind::Text) return "text";
    if (kind == FieldKind::Choice) {
        std::string s;
        for (const auto& c : choices) s += (s.empty() ? "" : " | ") + c;
        return s;
    }
    std::string s = valid.text();
    if (kind == FieldKind::Range) s += ", or off";
    for (const auto& sp : specials) s += " (" + (std::isnan(sp.value) ? std::string("null") : bound(sp.value)) + " = " + sp.meaning + ")";
    return s;
}

bool FieldInfo::accepts(double v) const {
    for (const auto& s : specials)
        if (s.matches(v)) return true;
    if (!std::isfinite(v)) return false;
    if (kind == FieldKind::Integer && v != std::floor(v)) return false;
    return valid.contains(v);
}

}  // namespace lwb::core
