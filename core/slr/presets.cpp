#include "core/slr/presets.hpp"

#include <cctype>
#include <cmath>
#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"
#include "core/slr/slr_params.hpp"

namespace lwb::core::slr {

namespace {

constexpr const char* kFormat = "laserwb-slr-presets";

std::string normalName(const std::string& s) {
    std::string out;
    for (unsigned char c : s)
        if (!std::isspace(c) && c != '-' && c != '_') out.push_back(static_cast<char>(std::tolower(c)));
    return out;
}

}  // namespace

PresetsResult presetsFromJson(const Json& doc, const std::string& source, const JsonParseResult* parsed) {
    PresetsResult res;
    auto at = [&](const std::vector<std::string>& path) { return parsed ? parsed->where(path) : source + ": "; };
    auto fail = [&](const std::vector<std::string>& path, const std::string& msg) {
        res.error = at(path) + msg;
        res.presets.clear();
        return res;
    };
    if (!doc.is_object()) return fail({}, "a presets file must be a JSON object");
    for (auto it = doc.begin(); it != doc.end(); ++it)
        if (it.key() != "format" && it.key() != "version" && it.key() != "satellites")
            return fail({it.key()}, "unknown key \"" + printableExcerpt(it.key()) + "\"");
    if (doc.contains("format") && !(doc["format"].is_string() && doc["format"].get<std::string>() == kFormat))
        return fail({"format"}, "\"format\" must be \"" + std::string(kFormat) + "\"");
    if (doc.contains("version") && !(doc["version"].is_number() && doc["version"].get<double>() == 1))
        return fail({"version"}, "\"version\" must be 1");
    if (!doc.contains("satellites") || !doc["satellites"].is_array())
        return fail({}, "\"satellites\" must be an array of satellite entries");
    const Json& sats = doc["satellites"];
    std::set<std::string> names, ids;
    for (size_t i = 0; i < sats.size(); ++i) {
        const Json& e = sats[i];
        const std::string index = "[" + std::to_string(i) + "]";
        const std::vector<std::string> path{"satellites", index};
        std::string where = "satellites" + index;
        if (!e.is_object()) return fail(path, where + ": must be an object");
        SatellitePreset p;
        std::string err;
        if (!jsonString(e, "name", &p.name, &err) || !jsonString(e, "ilrs_id", &p.ilrsId, &err)) return fail(path, where + ": " + err);
        p.name = std::string(trim(p.name));
        p.ilrsId = std::string(trim(p.ilrsId));
        if (!p.name.empty() || !p.ilrsId.empty())
            where += " (" + printableExcerpt(p.name.empty() ? p.ilrsId : p.name) + ")";
        if (p.name.empty() && p.ilrsId.empty()) return fail(path, where + ": needs a \"name\" or an \"ilrs_id\"");
        for (unsigned char c : p.ilrsId)
            if (!std::isdigit(c)) return fail(path, where + ": \"ilrs_id\" must be digits (e.g. \"7603901\")");
        // The parameters: the SLR schema's sections; "altitude_km" at the entry's top level is
        // the older spelling of postfit.altitude_km.
        Json params = Json::object();
        for (auto it = e.begin(); it != e.end(); ++it) {
            if (it.key() == "name" || it.key() == "ilrs_id") continue;
            if (it.key() == "altitude_km") params["postfit"]["altitude_km"] = *it;
            else if (it.key() == "oc")  // (computed when the pass is opened, before a preset applies)
                return fail(path, where + ": \"oc\": the O-C's parameters are not a satellite's; give them in the config or with --set");
            else params[it.key()] = *it;
        }
        SlrParams sp;  // parameter ranges only: whether the altitude is known is settled with the pass
        if (!slrSchema().fromJson(params, &sp, &err, parsed, path)) {
            // fromJson prefixes the position when it has the parse result; without it, the entry.
            return fail({}, (parsed ? std::string() : where + ": ") + err);
        }
        p.screen = sp.screen;
        p.postfit = sp.postfit;
        if (!p.name.empty() && !names.insert(normalName(p.name)).second)
            return fail(path, where + ": the name \"" + printableExcerpt(p.name) + "\" is used twice");
        if (!p.ilrsId.empty() && !ids.insert(p.ilrsId).second)
            return fail(path, where + ": the ILRS id \"" + p.ilrsId + "\" is used twice");
        res.presets.push_back(std::move(p));
    }
    res.ok = true;
    return res;
}

PresetsResult loadPresets(const std::string& path) {
    const JsonParseResult j = readJsonFile(path);
    if (!j.ok) {
        PresetsResult r;
        r.error = j.error;
        return r;
    }
    return presetsFromJson(j.value, path, &j);
}

Json presetsToJson(const std::vector<SatellitePreset>& presets) {
    Json arr = Json::array();
    for (const SatellitePreset& p : presets) {
        Json e = Json::object();
        if (!p.name.empty()) e["name"] = p.name;
        if (!p.ilrsId.empty()) e["ilrs_id"] = p.ilrsId;
        SlrParams sp;
        sp.screen = p.screen;
        sp.postfit = p.postfit;
        Json params = slrSchema().toJson(sp);
        params.erase("oc");  // (a preset holds the screening and the post-fit)
        for (auto it = params.begin(); it != params.end(); ++it) e[it.key()] = *it;
        arr.push_back(std::move(e));
    }
    return Json{{"format", kFormat}, {"version", 1}, {"satellites", arr}};
}

bool savePresets(const std::string& path, const std::vector<SatellitePreset>& presets, std::string* error) {
    const Json doc = presetsToJson(presets);
    const PresetsResult check = presetsFromJson(doc, path);
    if (!check.ok) {
        *error = check.error + " (nothing written)";
        return false;
    }
    return writeFileAtomic(path, dumpJson(doc), error);
}

const SatellitePreset* findPreset(const std::vector<SatellitePreset>& presets, const std::string& name,
                                  const std::string& ilrsId) {
    const std::string id(trim(ilrsId));
    if (!id.empty())
        for (const auto& p : presets)
            if (p.ilrsId == id) return &p;
    const std::string key = normalName(name);
    if (!key.empty())
        for (const auto& p : presets)
            if (normalName(p.name) == key) return &p;
    return nullptr;
}

}  // namespace lwb::core::slr
