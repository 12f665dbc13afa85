#include "core/slr/presets.hpp"

#include <cctype>
#include <cmath>
#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"

namespace lwb::core::slr {

namespace {

constexpr const char* kFormat = "laserwb-slr-presets";

// One key of a section: a double, an int or a bool member of the params struct.
struct Field {
    const char* key;
    double* d = nullptr;
    int* i = nullptr;
    bool* b = nullptr;
};

std::vector<Field> screenFields(ScreenParams& s) {
    return {{"automatic", nullptr, nullptr, &s.automatic},
            {"mag_t", &s.magT},
            {"mag_oc", &s.magOc},
            {"area_limit", nullptr, &s.areaLimit},
            {"connectivity", nullptr, &s.connectivity},
            {"cosine_c", &s.cosineC},
            {"slope_neighbours", nullptr, &s.slopeNeighbours},
            {"slope_bin_deg", &s.slopeBinDeg},
            {"slope_peak_fraction", &s.slopePeakFraction},
            {"slope_agree_fraction", &s.slopeAgreeFraction},
            {"max_slope_range_deg", &s.maxSlopeRangeDeg},
            {"slope_block_regions", nullptr, &s.slopeBlockRegions},
            {"piece_rows", nullptr, &s.pieceRows},
            {"recovery_gap_factor", &s.recoveryGapFactor},
            {"area_tolerance", &s.areaTolerance},
            {"auto_max_points", nullptr, &s.autoMaxPoints}};
}

std::vector<Field> postfitFields(PostfitParams& p) {
    return {{"degree", nullptr, &p.degree},
            {"reject_sigma", &p.rejectSigma},
            {"max_iterations", nullptr, &p.maxIterations},
            {"bin_length_s", &p.binLengthS},
            {"min_points", nullptr, &p.minPointsPerBin},
            {"daylight", nullptr, nullptr, &p.daylight},
            {"fire_rate_hz", &p.fireRateHz},
            {"normal_points", nullptr, nullptr, &p.normalPoints}};
}

// Reads a section's keys; unknown keys are errors. *error names the key.
bool readSection(const Json& sec, std::vector<Field> fields, std::string* error) {
    if (!sec.isObject()) {
        *error = "must be an object";
        return false;
    }
    for (const auto& [key, value] : sec.members()) {
        bool known = false;
        for (const Field& f : fields)
            if (key == f.key) {
                known = true;
                bool ok = true;
                if (f.d) ok = jsonNumber(sec, key, f.d, error);
                else if (f.i) ok = jsonInt(sec, key, f.i, error);
                else ok = jsonBool(sec, key, f.b, error);
                if (!ok) return false;
            }
        if (!known) {
            *error = "unknown key \"" + key + "\"";
            return false;
        }
    }
    return true;
}

Json sectionJson(const std::vector<Field>& fields) {
    Json j = Json::object();
    for (const Field& f : fields) {
        if (f.d) j.set(f.key, *f.d);
        else if (f.i) j.set(f.key, *f.i);
        else j.set(f.key, *f.b);
    }
    return j;
}

std::string normalName(const std::string& s) {
    std::string out;
    for (unsigned char c : s)
        if (!std::isspace(c) && c != '-' && c != '_') out.push_back(static_cast<char>(std::tolower(c)));
    return out;
}

}  // namespace

PresetsResult presetsFromJson(const Json& doc, const std::string& source) {
    PresetsResult res;
    auto fail = [&](const std::string& msg) {
        res.error = source + ": " + msg;
        res.presets.clear();
        return res;
    };
    if (!doc.isObject()) return fail("a presets file must be a JSON object");
    for (const auto& [key, value] : doc.members())
        if (key != "format" && key != "version" && key != "satellites") return fail("unknown key \"" + key + "\"");
    if (const Json* f = doc.find("format"); f && !(f->isString() && f->asString() == kFormat))
        return fail("\"format\" must be \"" + std::string(kFormat) + "\"");
    if (const Json* v = doc.find("version"); v && !(v->isNumber() && v->asNumber() == 1))
        return fail("\"version\" must be 1");
    const Json* sats = doc.find("satellites");
    if (!sats || !sats->isArray()) return fail("\"satellites\" must be an array of satellite entries");
    std::set<std::string> names, ids;
    for (size_t i = 0; i < sats->items().size(); ++i) {
        const Json& e = sats->items()[i];
        std::string where = "satellites[" + std::to_string(i) + "]";
        if (!e.isObject()) return fail(where + ": must be an object");
        SatellitePreset p;
        std::string err;
        if (!jsonString(e, "name", &p.name, &err) || !jsonString(e, "ilrs_id", &p.ilrsId, &err))
            return fail(where + ": " + err);
        p.name = std::string(trim(p.name));
        p.ilrsId = std::string(trim(p.ilrsId));
        if (!p.name.empty() || !p.ilrsId.empty()) where += " (" + (p.name.empty() ? p.ilrsId : p.name) + ")";
        if (p.name.empty() && p.ilrsId.empty()) return fail(where + ": needs a \"name\" or an \"ilrs_id\"");
        for (unsigned char c : p.ilrsId)
            if (!std::isdigit(c)) return fail(where + ": \"ilrs_id\" must be digits (e.g. \"7603901\")");
        for (const auto& [key, value] : e.members())
            if (key != "name" && key != "ilrs_id" && key != "altitude_km" && key != "screen" && key != "postfit")
                return fail(where + ": unknown key \"" + key + "\"");
        if (!jsonNumber(e, "altitude_km", &p.postfit.altitudeKm, &err)) return fail(where + ": " + err);
        if (p.postfit.altitudeKm < 0 || p.postfit.altitudeKm > 1e6) return fail(where + ": \"altitude_km\" must be 0..1e6");
        if (const Json* s = e.find("screen"); s && !readSection(*s, screenFields(p.screen), &err))
            return fail(where + ": \"screen\": " + err);
        if (const Json* s = e.find("postfit"); s && !readSection(*s, postfitFields(p.postfit), &err))
            return fail(where + ": \"postfit\": " + err);
        if (const std::string v = validate(p.screen); !v.empty()) return fail(where + ": \"screen\": " + v);
        PostfitParams pf = p.postfit;
        pf.normalPoints = false;  // the altitude may come with the pass
        if (const std::string v = validate(pf); !v.empty()) return fail(where + ": \"postfit\": " + v);
        if (!p.name.empty() && !names.insert(normalName(p.name)).second)
            return fail(where + ": the name \"" + p.name + "\" is used twice");
        if (!p.ilrsId.empty() && !ids.insert(p.ilrsId).second)
            return fail(where + ": the ILRS id \"" + p.ilrsId + "\" is used twice");
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
    return presetsFromJson(j.value, path);
}

Json presetsToJson(const std::vector<SatellitePreset>& presets) {
    Json doc = Json::object();
    doc.set("format", kFormat);
    doc.set("version", 1);
    Json arr = Json::array();
    for (const SatellitePreset& p : presets) {
        SatellitePreset c = p;
        Json e = Json::object();
        if (!c.name.empty()) e.set("name", c.name);
        if (!c.ilrsId.empty()) e.set("ilrs_id", c.ilrsId);
        e.set("altitude_km", c.postfit.altitudeKm);
        e.set("screen", sectionJson(screenFields(c.screen)));
        e.set("postfit", sectionJson(postfitFields(c.postfit)));
        arr.push(std::move(e));
    }
    doc.set("satellites", std::move(arr));
    return doc;
}

bool savePresets(const std::string& path, const std::vector<SatellitePreset>& presets, std::string* error) {
    const Json doc = presetsToJson(presets);
    const PresetsResult check = presetsFromJson(doc, path);
    if (!check.ok) {
        *error = check.error + " (nothing written)";
        return false;
    }
    return writeFileAtomic(path, doc.dump(2) + "\n", error);
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
