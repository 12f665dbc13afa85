#pragma once
// A small JSON value with a strict parser (errors carry line and column) and a writer.
// Used for configs and presets so that core stays std + Eigen + OpenCV only.
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lwb::core {

class Json {
public:
    enum class Type { Null, Bool, Number, String, Array, Object };
    using Array = std::vector<Json>;
    using Object = std::vector<std::pair<std::string, Json>>;  ///< keeps key order

    Json() = default;
    Json(std::nullptr_t) {}
    Json(bool b) : m_type(Type::Bool), m_bool(b) {}
    Json(double d) : m_type(Type::Number), m_num(d) {}
    Json(int i) : m_type(Type::Number), m_num(i) {}
    Json(long long i) : m_type(Type::Number), m_num(static_cast<double>(i)) {}
    Json(const char* s) : m_type(Type::String), m_str(s) {}
    Json(std::string s) : m_type(Type::String), m_str(std::move(s)) {}
    static Json array() { Json j; j.m_type = Type::Array; return j; }
    static Json object() { Json j; j.m_type = Type::Object; return j; }

    Type type() const { return m_type; }
    bool isNull() const { return m_type == Type::Null; }
    bool isBool() const { return m_type == Type::Bool; }
    bool isNumber() const { return m_type == Type::Number; }
    bool isString() const { return m_type == Type::String; }
    bool isArray() const { return m_type == Type::Array; }
    bool isObject() const { return m_type == Type::Object; }

    bool asBool() const { return m_bool; }
    double asNumber() const { return m_num; }
    const std::string& asString() const { return m_str; }
    const Array& items() const { return m_arr; }
    Array& items() { return m_arr; }
    const Object& members() const { return m_obj; }

    /// Object member or nullptr.
    const Json* find(const std::string& key) const;
    /// Sets (or replaces) an object member; turns a Null into an Object.
    Json& set(const std::string& key, Json value);
    /// Appends a member without looking for an existing one (the caller knows the key is new).
    Json& appendMember(std::string key, Json value);
    /// Appends to an array; turns a Null into an Array.
    Json& push(Json value);

    /// Serialises; indent < 0 gives one line.
    std::string dump(int indent = 2) const;

private:
    void dumpTo(std::string& out, int indent, int depth) const;
    Type m_type = Type::Null;
    bool m_bool = false;
    double m_num = 0;
    std::string m_str;
    Array m_arr;
    Object m_obj;
};

struct JsonParseResult {
    bool ok = false;
    std::string error;  ///< "SOURCE:LINE:COL: what is wrong"
    Json value;
};

/// Parses RFC 8259 JSON (no NaN/Infinity literals, no comments, no trailing commas).
JsonParseResult parseJson(const std::string& text, const std::string& source = "json");
JsonParseResult readJsonFile(const std::string& path);

/// Reads a number member into *out when present. False (with *error naming the key) when the
/// member is present but not a finite number; true and untouched when absent.
bool jsonNumber(const Json& obj, const std::string& key, double* out, std::string* error);
bool jsonInt(const Json& obj, const std::string& key, int* out, std::string* error);
bool jsonBool(const Json& obj, const std::string& key, bool* out, std::string* error);
bool jsonString(const Json& obj, const std::string& key, std::string* out, std::string* error);

/// The first member of `given` (an object, searched recursively through nested objects) whose
/// key `reference` does not have, as a dotted path ("gauss.lm_max_iter"); "" when every key is
/// known. Used to refuse misspelt keys in configs instead of ignoring them.
std::string firstUnknownKey(const Json& given, const Json& reference);

}  // namespace lwb::core
