#include "core/common/text.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lwb::core {

std::string_view trim(std::string_view s) {
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

bool parseDouble(std::string_view s, double* out, bool allowNonFinite) {
    s = trim(s);
    if (s.empty() || s.size() > 64) return false;
    char buf[72];
    s.copy(buf, s.size());
    buf[s.size()] = '\0';
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(buf, &end);
    if (end != buf + s.size()) return false;
    if (errno == ERANGE && std::isinf(v)) return false;
    if (!allowNonFinite && !std::isfinite(v)) return false;
    *out = v;
    return true;
}

bool parseLong(std::string_view s, long long* out) {
    s = trim(s);
    if (s.empty() || s.size() > 24) return false;
    char buf[32];
    s.copy(buf, s.size());
    buf[s.size()] = '\0';
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(buf, &end, 10);
    if (end != buf + s.size() || errno == ERANGE) return false;
    *out = v;
    return true;
}

std::vector<std::string_view> splitBlanks(std::string_view s) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
        if (i >= s.size()) break;
        size_t j = i;
        while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
        out.push_back(s.substr(i, j - i));
        i = j;
    }
    return out;
}

std::string toLower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
}

std::string formatDouble(double v, int significant) {
    if (std::isnan(v)) return "nan";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", significant, v);
    return buf;
}

std::string formatShortest(double v) {
    if (!std::isfinite(v)) return formatDouble(v);
    for (int p = 6; p < 17; ++p) {
        const std::string t = formatDouble(v, p);
        if (std::strtod(t.c_str(), nullptr) == v) return t;
    }
    return formatDouble(v, 17);
}

std::string printableExcerpt(std::string_view s, size_t maxLen) {
    std::string out;
    for (size_t i = 0; i < s.size() && i < maxLen; ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (c >= 32 && c < 127) {
            out += static_cast<char>(c);
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        }
    }
    if (s.size() > maxLen) out += "...";
    return out;
}

std::string whereInFile(const std::string& source, long line) { return source + ":" + std::to_string(line) + ": "; }

std::string textFileProblem(std::string_view text, const std::string& source, const char* kind) {
    if (trim(text).empty()) return source + ": empty file";
    const size_t nul = text.find('\0');
    if (nul == std::string_view::npos) return {};
    const long line = 1 + static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(nul), '\n'));
    return whereInFile(source, line) + "binary data (NUL byte): not a " + kind + " text file";
}

std::string formatFixed(double v, int decimals) {
    if (std::isnan(v)) return "nan";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

}  // namespace lwb::core
