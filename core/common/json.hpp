#pragma once
// JSON for configs, presets, sessions and beam files: nlohmann-json (Debian's
// nlohmann-json3-dev) with key order kept, plus what our messages need on top of it — errors as
// "SOURCE:LINE:COL: what", duplicate keys and absurd nesting refused, and the position of any
// member for messages about its value.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace lwb::core {

using Json = nlohmann::ordered_json;

struct JsonParseResult {
    bool ok = false;
    std::string error;   ///< "SOURCE:LINE:COL: what is wrong"
    Json value;
    std::string source;  ///< the name given (a file path)
    std::string text;    ///< the text parsed, for where()
    /// "SOURCE:LINE:COL: " of the member at `path` (object keys; array indices as "[3]"), or
    /// "SOURCE: " when it cannot be found (a value built in memory, say).
    std::string where(const std::vector<std::string>& path) const;
};

/// Parses RFC 8259 JSON (no NaN/Infinity literals, comments or trailing commas); duplicate keys
/// in an object and nesting deeper than 64 levels are errors.
JsonParseResult parseJson(std::string_view text, const std::string& source = "json");
/// Reads (a regular file, size-limited like every text input) and parses.
JsonParseResult readJsonFile(const std::string& path);

/// Serialises with `indent` spaces (< 0: one line) and a final newline when indented. Numbers
/// that are not finite are written as null (JSON has no NaN).
std::string dumpJson(const Json& j, int indent = 2);

/// Reads a number member into *out when present. False (with *error naming the key) when the
/// member is present but not a finite number; true and untouched when absent.
bool jsonNumber(const Json& obj, const std::string& key, double* out, std::string* error);
bool jsonInt(const Json& obj, const std::string& key, int* out, std::string* error);
bool jsonString(const Json& obj, const std::string& key, std::string* out, std::string* error);

/// The first member of `given` (searched recursively through nested objects) whose key
/// `reference` does not have, as a path; empty when every key is known.
std::vector<std::string> firstUnknownKey(const Json& given, const Json& reference);
/// "a.b.c" from a path.
std::string joinPath(const std::vector<std::string>& path);

}  // namespace lwb::core
