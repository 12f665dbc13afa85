#include "core/common/text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
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

namespace {
// Decimal number syntax: [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. A point with
// no digit after it is accepted only when trailingPoint (FORTRAN F-format, "26.").
bool decimalSyntax(std::string_view s, bool trailingPoint) {
    size_t i = 0;
    const size_t n = s.size();
    auto digits = [&]() {
        const size_t b = i;
        while (i < n && s[i] >= '0' && s[i] <= '9') ++i;
        return i - b;
    };
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    const size_t intDigits = digits();
    if (i < n && s[i] == '.') {
        ++i;
        const size_t frac = digits();
        if (frac == 0 && (intDigits == 0 || !trailingPoint)) return false;
    } else if (intDigits == 0) {
        return false;
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
        if (digits() == 0) return false;
    }
    return i == n;
}

// Decimal exponent of the leading significant digit of a number of valid syntax (for telling
// overflow from underflow).
long decimalExponent(std::string_view s) {
    long exp = 0;
    if (const size_t ePos = s.find_first_of("eE"); ePos != std::string_view::npos) {
        long long x = 0;
        std::string_view t = s.substr(ePos + 1);
        if (!t.empty() && t[0] == '+') t.remove_prefix(1);
        const auto r = std::from_chars(t.data(), t.data() + t.size(), x);
        exp = r.ec == std::errc() ? static_cast<long>(std::clamp(x, -100000LL, 100000LL))
                                  : (!t.empty() && t[0] == '-' ? -100000 : 100000);
        s = s.substr(0, ePos);
    }
    const size_t point = s.find('.');
    const std::string_view ip = s.substr(0, point), fp = point == std::string_view::npos ? "" : s.substr(point + 1);
    const size_t firstInt = ip.find_first_of("123456789");
    if (firstInt != std::string_view::npos) return exp + static_cast<long>(ip.size() - firstInt) - 1;
    const size_t firstFrac = fp.find_first_of("123456789");
    return firstFrac == std::string_view::npos ? -100000 : exp - static_cast<long>(firstFrac) - 1;
}

bool parseNumber(std::string_view s, double* out, bool allowNonFinite, bool trailingPoint) {
    s = trim(s);
    if (s.empty() || s.size() > 64) return false;
    double v = 0;
    if (!decimalSyntax(s, trailingPoint)) {
        if (!allowNonFinite) return false;
        const std::string l = toLower(s[0] == '+' || s[0] == '-' ? s.substr(1) : s);
        if (l != "nan" && l != "inf" && l != "infinity") return false;
        v = l == "nan" ? NAN : (s[0] == '-' ? -INFINITY : INFINITY);
        *out = v;
        return true;
    }
    // from_chars: locale-independent (a GUI may set LC_NUMERIC to a decimal comma); no leading '+'.
    const char* b = s.data() + (s[0] == '+' ? 1 : 0);
    const char* e = s.data() + s.size();
    const auto r = std::from_chars(b, e, v, std::chars_format::general);
    if (r.ec == std::errc::result_out_of_range) {
        // Underflow to zero is harmless (1e-400 reads as 0); overflow is an error.
        if (decimalExponent(std::string_view(b, static_cast<size_t>(e - b))) > 0) return false;
        v = 0;
    } else if (r.ec != std::errc() || r.ptr != e) {
        return false;
    }
    if (!std::isfinite(v)) return false;
    *out = v;
    return true;
}
}  // namespace

bool parseDouble(std::string_view s, double* out, bool allowNonFinite) {
    return parseNumber(s, out, allowNonFinite, false);
}

bool parseFortranDouble(std::string_view s, double* out) { return parseNumber(s, out, false, true); }

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

std::string_view plainText(std::string_view text, std::string* storage) {
    if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
        static_cast<unsigned char>(text[2]) == 0xBF)
        text.remove_prefix(3);
    if (text.find('\n') != std::string_view::npos || text.find('\r') == std::string_view::npos) return text;
    storage->assign(text.begin(), text.end());
    std::replace(storage->begin(), storage->end(), '\r', '\n');
    return *storage;
}

std::string formatFixed(double v, int decimals) {
    if (std::isnan(v)) return "nan";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

namespace {
size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}
}  // namespace

std::string didYouMean(std::string_view given, const std::vector<std::string>& known) {
    const std::string* best = nullptr;
    size_t bestD = 0;
    for (const std::string& k : known) {
        size_t d = editDistance(given, k);
        if (given.size() >= 3 && k.find(given) != std::string::npos) d = std::min(d, size_t{1});
        if (!best || d < bestD) best = &k, bestD = d;
    }
    if (!best || bestD == 0 || bestD > std::max<size_t>(2, given.size() / 3)) return "";
    return " (did you mean " + *best + "?)";
}

std::string hmsRounded(double secondsOfDay) {
    const long s = std::lround(std::fmod(std::fmod(secondsOfDay, 86400.0) + 86400.0, 86400.0));
    char buf[16];
    std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600 % 24, s / 60 % 60, s % 60);
    return buf;
}

}  // namespace lwb::core
