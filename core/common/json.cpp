#include "core/common/json.hpp"

#include <cmath>
#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"

namespace lwb::core {

namespace {

constexpr int kMaxDepth = 64;

// Line and column (1-based) of a byte offset.
std::string lineCol(std::string_view text, size_t offset) {
    long line = 1, col = 1;
    for (size_t k = 0; k < offset && k < text.size(); ++k) {
        if (text[k] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return std::to_string(line) + ":" + std::to_string(col);
}

// Finds the byte offset of a member's key (or of an array element) by path, walking the text
// with a small scanner that knows strings, objects and arrays. npos when absent. The text is
// known to be valid JSON (it parsed).
size_t locate(std::string_view t, const std::vector<std::string>& path) {
    struct Level {
        bool object;
        std::string key;   // object: the current member's key
        long index = 0;    // array: the current element
        bool matched;      // every level above and this one's entry so far match the path
    };
    std::vector<Level> stack;
    auto depthMatches = [&]() {
        // The path prefix up to the current depth matches the open containers.
        if (stack.size() > path.size()) return false;
        for (size_t d = 0; d + 1 < stack.size(); ++d) {
            const Level& l = stack[d];
            const std::string here = l.object ? l.key : "[" + std::to_string(l.index) + "]";
            if (here != path[d]) return false;
        }
        return true;
    };
    bool expectKey = false;
    for (size_t i = 0; i < t.size(); ++i) {
        const char c = t[i];
        if (c == '"') {
            const size_t start = i;
            std::string s;
            for (++i; i < t.size() && t[i] != '"'; ++i) {
                if (t[i] == '\\' && i + 1 < t.size()) ++i;
                s.push_back(t[i]);
            }
            if (expectKey && !stack.empty() && stack.back().object) {
                stack.back().key = s;
                expectKey = false;
                if (stack.size() == path.size() && depthMatches() && s == path.back()) return start;
            }
            continue;
        }
        if (c == '{' || c == '[') {
            if (!stack.empty() && !stack.back().object && stack.size() == path.size() && depthMatches() &&
                "[" + std::to_string(stack.back().index) + "]" == path.back())
                return i;
            stack.push_back({c == '{', {}, 0, false});
            expectKey = c == '{';
        } else if (c == '}' || c == ']') {
            if (!stack.empty()) stack.pop_back();
        } else if (c == ',') {
            if (!stack.empty()) {
                if (stack.back().object) expectKey = true;
                else ++stack.back().index;
            }
        } else if (!stack.empty() && !stack.back().object && stack.size() == path.size() && depthMatches() &&
                   !std::isspace(static_cast<unsigned char>(c)) && "[" + std::to_string(stack.back().index) + "]" == path.back()) {
            return i;  // a scalar array element
        }
    }
    return std::string_view::npos;
}

struct DuplicateKey {
    std::vector<std::string> path;
};
struct TooDeep {};

}  // namespace

std::string JsonParseResult::where(const std::vector<std::string>& path) const {
    const size_t at = path.empty() ? std::string_view::npos : locate(text, path);
    if (at == std::string_view::npos) return source + ": ";
    return source + ":" + lineCol(text, at) + ": ";
}

namespace {
struct NumberOverflow {
    std::string text;
};

// Builds the document as nlohmann's own DOM parser does, with the checks of parseJson (depth,
// duplicate keys with the member's path), but appends an object's members to its vector
// directly: ordered_json's insertion looked every new key up in the members so far, so an
// object of 10^5 members (a session's overrides) took minutes. Duplicates are found by a set.
class DomBuilder {
public:
    Json root;

    bool null() { return value(Json(nullptr)); }
    bool boolean(bool v) { return value(Json(v)); }
    bool number_integer(Json::number_integer_t v) { return value(Json(v)); }
    bool number_unsigned(Json::number_unsigned_t v) { return value(Json(v)); }
    bool number_float(Json::number_float_t v, const Json::string_t& s) {
        if (!std::isfinite(v)) throw NumberOverflow{s};  // (the DOM parser's out_of_range 406)
        return value(Json(v));
    }
    bool string(Json::string_t& v) { return value(Json(std::move(v))); }
    bool binary(Json::binary_t& v) { return value(Json::binary(std::move(v))); }
    bool start_object(std::size_t) { return open(Json::object(), true); }
    bool end_object() { return close(); }
    bool start_array(std::size_t) { return open(Json::array(), false); }
    bool end_array() { return close(); }
    bool key(Json::string_t& k) {
        Level& l = m_levels.back();
        l.key = k;
        if (!l.keys.insert(k).second) throw DuplicateKey{pathHere()};
        auto& members = static_cast<Json::object_t::Container&>(m_stack.back()->get_ref<Json::object_t&>());
        members.emplace_back(k, nullptr);
        m_member = &members.back().second;
        return true;
    }
    bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& e) {
        // (nlohmann reports a float beyond double range here too, as out_of_range 406)
        if (const auto* pe = dynamic_cast<const Json::parse_error*>(&e)) throw *pe;
        throw NumberOverflow{token};
    }

private:
    struct Level {
        bool object;
        std::set<std::string> keys;
        std::string key;
        long count = 0;
    };
    std::vector<Json*> m_stack;
    std::vector<Level> m_levels;
    Json* m_member = nullptr;

    std::vector<std::string> pathHere() const {
        std::vector<std::string> path;
        for (const Level& l : m_levels) path.push_back(l.object ? l.key : "[" + std::to_string(l.count) + "]");
        return path;
    }
    // Where a new value goes: the root, the end of the open array, or the member just keyed.
    Json* place(Json&& v) {
        if (m_stack.empty()) {
            root = std::move(v);
            return &root;
        }
        Json* top = m_stack.back();
        if (top->is_array()) {
            top->get_ref<Json::array_t&>().push_back(std::move(v));
            return &top->get_ref<Json::array_t&>().back();
        }
        *m_member = std::move(v);
        return m_member;
    }
    void elementDone() {
        if (!m_levels.empty() && !m_levels.back().object) ++m_levels.back().count;
    }
    bool value(Json&& v) {
        place(std::move(v));
        elementDone();
        return true;
    }
    bool open(Json&& v, bool object) {
        if (static_cast<int>(m_stack.size()) >= kMaxDepth) throw TooDeep{};
        m_stack.push_back(place(std::move(v)));
        m_levels.push_back({object, {}, {}, 0});
        return true;
    }
    bool close() {
        m_stack.pop_back();
        m_levels.pop_back();
        elementDone();
        return true;
    }
};
}  // namespace

JsonParseResult parseJson(std::string_view text, const std::string& source) {
    JsonParseResult r;
    r.source = source;
    r.text = std::string(text);
    try {
        DomBuilder dom;
        Json::sax_parse(text.begin(), text.end(), &dom);
        r.value = std::move(dom.root);
        r.ok = true;
    } catch (const Json::parse_error& e) {
        // "[json.exception.parse_error.101] parse error at line 2, column 7: syntax error ..."
        std::string what = e.what();
        const size_t at = what.find(" at line ");
        const size_t colon = at == std::string::npos ? std::string::npos : what.find(": ", at);
        std::string msg = colon == std::string::npos ? what : what.substr(colon + 2);
        r.error = source + ":" + lineCol(text, e.byte > 0 ? e.byte - 1 : 0) + ": " + msg;
    } catch (const Json::out_of_range& e) {  // a number beyond double range: "... parsing '1e999'"
        std::string what = e.what();
        const size_t sp = what.find("] ");
        what = sp == std::string::npos ? what : what.substr(sp + 2);
        const size_t q1 = what.find('\''), q2 = q1 == std::string::npos ? q1 : what.find('\'', q1 + 1);
        const size_t at = q2 == std::string::npos ? std::string_view::npos : text.find(what.substr(q1 + 1, q2 - q1 - 1));
        r.error = source + (at == std::string_view::npos ? std::string() : ":" + lineCol(text, at)) + ": " + what;
    } catch (const NumberOverflow& n) {  // "number overflow parsing '1e999'", where it stands
        const size_t at = text.find(n.text);
        r.error = source + (at == std::string_view::npos ? std::string() : ":" + lineCol(text, at)) +
                  ": number overflow parsing '" + n.text + "'";
    } catch (const DuplicateKey& d) {
        r.value = Json();
        r.error = r.where(d.path) + "the key \"" + printableExcerpt(d.path.back()) + "\" appears twice in one object";
    } catch (const TooDeep&) {
        r.error = source + ": nested deeper than " + std::to_string(kMaxDepth) + " levels";
    } catch (const std::exception& e) {
        r.error = source + ": " + e.what();
    }
    if (!r.ok) r.value = Json();
    return r;
}

JsonParseResult readJsonFile(const std::string& path) {
    JsonParseResult r;
    std::string text;
    if (!readFileText(path, &text, &r.error)) {
        r.source = path;
        return r;
    }
    return parseJson(text, path);
}

namespace {
Json finiteOnly(const Json& j) {
    if (j.is_number_float() && !std::isfinite(j.get<double>())) return nullptr;
    if (j.is_structured()) {
        Json c = j;
        for (auto& v : c) v = finiteOnly(v);
        return c;
    }
    return j;
}
}  // namespace

std::string dumpJson(const Json& j, int indent) {
    std::string s = finiteOnly(j).dump(indent < 0 ? -1 : indent, ' ', false, Json::error_handler_t::replace);
    if (indent >= 0) s.push_back('\n');
    return s;
}

bool jsonNumber(const Json& obj, const std::string& key, double* out, std::string* error) {
    const auto it = obj.find(key);
    if (it == obj.end()) return true;
    if (!it->is_number() || !std::isfinite(it->get<double>())) {
        *error = "\"" + key + "\" must be a finite number";
        return false;
    }
    *out = it->get<double>();
    return true;
}

bool jsonInt(const Json& obj, const std::string& key, int* out, std::string* error) {
    const auto it = obj.find(key);
    if (it == obj.end()) return true;
    const double v = it->is_number() ? it->get<double>() : NAN;
    if (!(v == std::floor(v) && std::fabs(v) <= 2147483647.0)) {
        *error = "\"" + key + "\" must be a whole number";
        return false;
    }
    *out = static_cast<int>(v);
    return true;
}

bool jsonString(const Json& obj, const std::string& key, std::string* out, std::string* error) {
    const auto it = obj.find(key);
    if (it == obj.end()) return true;
    if (!it->is_string()) {
        *error = "\"" + key + "\" must be a string";
        return false;
    }
    *out = it->get<std::string>();
    return true;
}

std::vector<std::string> firstUnknownKey(const Json& given, const Json& reference) {
    if (!given.is_object() || !reference.is_object()) return {};
    for (auto it = given.begin(); it != given.end(); ++it) {
        const auto ref = reference.find(it.key());
        if (ref == reference.end()) return {it.key()};
        if (it->is_object() && ref->is_object()) {
            std::vector<std::string> inner = firstUnknownKey(*it, *ref);
            if (!inner.empty()) {
                inner.insert(inner.begin(), it.key());
                return inner;
            }
        }
    }
    return {};
}

std::string joinPath(const std::vector<std::string>& path) {
    std::string s;
    for (const auto& p : path) {
        if (!s.empty() && p.rfind("[", 0) != 0) s += ".";
        s += p;
    }
    return s;
}

}  // namespace lwb::core
