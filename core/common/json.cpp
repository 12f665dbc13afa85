#include "core/common/json.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <unordered_set>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"

namespace lwb::core {

const Json* Json::find(const std::string& key) const {
    if (m_type != Type::Object) return nullptr;
    for (const auto& kv : m_obj)
        if (kv.first == key) return &kv.second;
    return nullptr;
}

Json& Json::set(const std::string& key, Json value) {
    if (m_type == Type::Null) m_type = Type::Object;
    for (auto& kv : m_obj)
        if (kv.first == key) {
            kv.second = std::move(value);
            return kv.second;
        }
    m_obj.emplace_back(key, std::move(value));
    return m_obj.back().second;
}

Json& Json::appendMember(std::string key, Json value) {
    if (m_type == Type::Null) m_type = Type::Object;
    m_obj.emplace_back(std::move(key), std::move(value));
    return m_obj.back().second;
}

Json& Json::push(Json value) {
    if (m_type == Type::Null) m_type = Type::Array;
    m_arr.push_back(std::move(value));
    return m_arr.back();
}

namespace {
void dumpString(std::string& out, const std::string& s) {
    out.push_back('"');
    for (unsigned char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out.push_back(static_cast<char>(c));
                }
        }
    }
    out.push_back('"');
}
void newline(std::string& out, int indent, int depth) {
    if (indent < 0) return;
    out.push_back('\n');
    out.append(static_cast<size_t>(indent * depth), ' ');
}
}  // namespace

void Json::dumpTo(std::string& out, int indent, int depth) const {
    switch (m_type) {
        case Type::Null: out += "null"; break;
        case Type::Bool: out += m_bool ? "true" : "false"; break;
        case Type::Number:
            // JSON has no NaN: write null, which the number readers reject.
            out += std::isfinite(m_num) ? formatShortest(m_num) : "null";
            break;
        case Type::String: dumpString(out, m_str); break;
        case Type::Array:
            out.push_back('[');
            for (size_t i = 0; i < m_arr.size(); ++i) {
                if (i) out.push_back(',');
                newline(out, indent, depth + 1);
                m_arr[i].dumpTo(out, indent, depth + 1);
            }
            if (!m_arr.empty()) newline(out, indent, depth);
            out.push_back(']');
            break;
        case Type::Object:
            out.push_back('{');
            for (size_t i = 0; i < m_obj.size(); ++i) {
                if (i) out.push_back(',');
                newline(out, indent, depth + 1);
                dumpString(out, m_obj[i].first);
                out += indent < 0 ? ":" : ": ";
                m_obj[i].second.dumpTo(out, indent, depth + 1);
            }
            if (!m_obj.empty()) newline(out, indent, depth);
            out.push_back('}');
            break;
    }
}

std::string Json::dump(int indent) const {
    std::string out;
    dumpTo(out, indent, 0);
    if (indent >= 0) out.push_back('\n');
    return out;
}

namespace {
class Parser {
public:
    Parser(const std::string& text, const std::string& source) : m_t(text), m_src(source) {}

    JsonParseResult run() {
        JsonParseResult r;
        skipWs();
        if (!parseValue(r.value, 0)) {
            r.error = m_err;
            return r;
        }
        skipWs();
        if (m_i != m_t.size()) {
            fail("unexpected text after the JSON value");
            r.error = m_err;
            return r;
        }
        r.ok = true;
        return r;
    }

private:
    bool fail(const std::string& what) {
        if (m_err.empty()) {
            long line = 1, col = 1;
            for (size_t k = 0; k < m_i && k < m_t.size(); ++k) {
                if (m_t[k] == '\n') {
                    ++line;
                    col = 1;
                } else {
                    ++col;
                }
            }
            m_err = m_src + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + what;
        }
        return false;
    }
    void skipWs() {
        while (m_i < m_t.size() &&
               (m_t[m_i] == ' ' || m_t[m_i] == '\t' || m_t[m_i] == '\n' || m_t[m_i] == '\r'))
            ++m_i;
    }
    bool literal(const char* word, size_t n) {
        if (m_t.compare(m_i, n, word) != 0) return fail("unknown word (expected a JSON value)");
        m_i += n;
        return true;
    }
    bool parseValue(Json& v, int depth) {
        if (depth > 200) return fail("nesting deeper than 200 levels");
        if (m_i >= m_t.size()) return fail("unexpected end of text");
        const char c = m_t[m_i];
        if (c == '{') return parseObject(v, depth);
        if (c == '[') return parseArray(v, depth);
        if (c == '"') {
            std::string s;
            if (!parseString(s)) return false;
            v = Json(std::move(s));
            return true;
        }
        if (c == 't') { if (!literal("true", 4)) return false; v = Json(true); return true; }
        if (c == 'f') { if (!literal("false", 5)) return false; v = Json(false); return true; }
        if (c == 'n') { if (!literal("null", 4)) return false; v = Json(); return true; }
        if (c == '-' || (c >= '0' && c <= '9')) return parseNumber(v);
        if (c == 'N' || c == 'I') return fail("NaN and Infinity are not JSON numbers");
        return fail(std::string("unexpected character '") + c + "'");
    }
    bool parseNumber(Json& v) {
        const size_t b = m_i;
        if (m_t[m_i] == '-') ++m_i;
        if (m_i < m_t.size() && (m_t[m_i] == 'I' || m_t[m_i] == 'N'))
            return fail("NaN and Infinity are not JSON numbers");
        while (m_i < m_t.size() && (std::isdigit(static_cast<unsigned char>(m_t[m_i])) ||
                                    m_t[m_i] == '.' || m_t[m_i] == 'e' || m_t[m_i] == 'E' ||
                                    m_t[m_i] == '+' || m_t[m_i] == '-'))
            ++m_i;
        double d = 0;
        if (!parseDouble(std::string_view(m_t).substr(b, m_i - b), &d)) {
            m_i = b;
            return fail("malformed or out-of-range number");
        }
        v = Json(d);
        return true;
    }
    bool parseString(std::string& s) {
        ++m_i;  // opening quote
        while (m_i < m_t.size()) {
            const char c = m_t[m_i++];
            if (c == '"') return true;
            if (static_cast<unsigned char>(c) < 0x20) return fail("control character in a string");
            if (c != '\\') {
                s.push_back(c);
                continue;
            }
            if (m_i >= m_t.size()) break;
            const char e = m_t[m_i++];
            switch (e) {
                case '"': s.push_back('"'); break;
                case '\\': s.push_back('\\'); break;
                case '/': s.push_back('/'); break;
                case 'b': s.push_back('\b'); break;
                case 'f': s.push_back('\f'); break;
                case 'n': s.push_back('\n'); break;
                case 'r': s.push_back('\r'); break;
                case 't': s.push_back('\t'); break;
                case 'u': {
                    if (m_i + 4 > m_t.size()) return fail("short \\u escape");
                    unsigned cp = 0;
                    for (int k = 0; k < 4; ++k) {
                        const char h = m_t[m_i++];
                        cp <<= 4;
                        if (h >= '0' && h <= '9') cp |= unsigned(h - '0');
                        else if (h >= 'a' && h <= 'f') cp |= unsigned(h - 'a' + 10);
                        else if (h >= 'A' && h <= 'F') cp |= unsigned(h - 'A' + 10);
                        else return fail("bad \\u escape");
                    }
                    if (cp < 0x80) {
                        s.push_back(static_cast<char>(cp));
                    } else if (cp < 0x800) {
                        s.push_back(static_cast<char>(0xC0 | (cp >> 6)));
                        s.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
                    } else {
                        s.push_back(static_cast<char>(0xE0 | (cp >> 12)));
                        s.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
                        s.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
                    }
                    break;
                }
                default: return fail("unknown escape in a string");
            }
        }
        return fail("string is not closed");
    }
    bool parseArray(Json& v, int depth) {
        v = Json::array();
        ++m_i;
        skipWs();
        if (m_i < m_t.size() && m_t[m_i] == ']') { ++m_i; return true; }
        while (true) {
            skipWs();
            Json item;
            if (!parseValue(item, depth + 1)) return false;
            v.push(std::move(item));
            skipWs();
            if (m_i >= m_t.size()) return fail("array is not closed");
            if (m_t[m_i] == ',') { ++m_i; continue; }
            if (m_t[m_i] == ']') { ++m_i; return true; }
            return fail("expected ',' or ']' in an array");
        }
    }
    bool parseObject(Json& v, int depth) {
        v = Json::object();
        std::unordered_set<std::string> seen;  // duplicate keys in O(1), not a scan per key
        ++m_i;
        skipWs();
        if (m_i < m_t.size() && m_t[m_i] == '}') { ++m_i; return true; }
        while (true) {
            skipWs();
            if (m_i >= m_t.size() || m_t[m_i] != '"') return fail("expected a quoted key");
            std::string key;
            if (!parseString(key)) return false;
            if (!seen.insert(key).second) return fail("key \"" + key + "\" appears twice");
            skipWs();
            if (m_i >= m_t.size() || m_t[m_i] != ':') return fail("expected ':' after a key");
            ++m_i;
            skipWs();
            Json item;
            if (!parseValue(item, depth + 1)) return false;
            v.appendMember(std::move(key), std::move(item));
            skipWs();
            if (m_i >= m_t.size()) return fail("object is not closed");
            if (m_t[m_i] == ',') { ++m_i; continue; }
            if (m_t[m_i] == '}') { ++m_i; return true; }
            return fail("expected ',' or '}' in an object");
        }
    }

    const std::string& m_t;
    const std::string& m_src;
    size_t m_i = 0;
    std::string m_err;
};
}  // namespace

JsonParseResult parseJson(const std::string& text, const std::string& source) {
    return Parser(text, source).run();
}

JsonParseResult readJsonFile(const std::string& path) {
    JsonParseResult r;
    std::string text;
    if (!readFileText(path, &text, &r.error)) return r;
    return parseJson(text, path);
}

bool jsonNumber(const Json& obj, const std::string& key, double* out, std::string* error) {
    const Json* v = obj.find(key);
    if (!v) return true;
    if (!v->isNumber() || !std::isfinite(v->asNumber())) {
        *error = "\"" + key + "\" must be a finite number";
        return false;
    }
    *out = v->asNumber();
    return true;
}

bool jsonInt(const Json& obj, const std::string& key, int* out, std::string* error) {
    double d = *out;
    if (!jsonNumber(obj, key, &d, error)) return false;
    if (d != std::floor(d) || std::fabs(d) > 2e9) {
        *error = "\"" + key + "\" must be a whole number";
        return false;
    }
    *out = static_cast<int>(d);
    return true;
}

bool jsonBool(const Json& obj, const std::string& key, bool* out, std::string* error) {
    const Json* v = obj.find(key);
    if (!v) return true;
    if (!v->isBool()) {
        *error = "\"" + key + "\" must be true or false";
        return false;
    }
    *out = v->asBool();
    return true;
}

bool jsonString(const Json& obj, const std::string& key, std::string* out, std::string* error) {
    const Json* v = obj.find(key);
    if (!v) return true;
    if (!v->isString()) {
        *error = "\"" + key + "\" must be a string";
        return false;
    }
    *out = v->asString();
    return true;
}

std::string firstUnknownKey(const Json& given, const Json& reference) {
    if (!given.isObject() || !reference.isObject()) return {};
    for (const auto& [key, value] : given.members()) {
        const Json* ref = reference.find(key);
        if (!ref) return key;
        if (value.isObject() && ref->isObject())
            if (std::string inner = firstUnknownKey(value, *ref); !inner.empty()) return key + "." + inner;
    }
    return {};
}

}  // namespace lwb::core
