#pragma once
// Per-satellite screening presets: a JSON file of entries, each found by satellite name and/or
// ILRS id (as in the CRD H3 record), holding the screening parameters (automatic mode on/off
// included) and the post-fit / normal-point parameters.
//
//   {
//     "format": "laserwb-slr-presets", "version": 1,
//     "satellites": [
//       { "name": "lageos1", "ilrs_id": "7603901", "altitude_km": 5860,
//         "screen": { "automatic": false, "mag_t": 10, "mag_oc": 1e10, "area_limit": 4,
//                     "connectivity": 8, "cosine_c": 0.95 },
//         "postfit": { "degree": 10, "reject_sigma": 3, "bin_length_s": 0, "min_points": 0 } }
//     ]
//   }
// The "screen" and "postfit" sections are the SLR schema's (core/slr/slr_params.hpp): every
// key is listed by `laserwb-cli slr --print-config`. Every key but "name" or "ilrs_id" (one of
// them) is optional; missing ones keep the defaults. "altitude_km" may also be given at the
// entry's top level (older files).
// Unknown keys, wrong types, non-finite or out-of-range values and duplicate names or ids are
// errors that name the entry and the key.
#include <string>
#include <vector>

#include "core/common/json.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"

namespace lwb::core::slr {

struct SatellitePreset {
    std::string name;       ///< satellite name as in CRD H3 (matched ignoring case, blanks, '-' and '_')
    std::string ilrsId;     ///< ILRS satellite id (CRD H3 field 3, e.g. "7603901"); empty when none
    ScreenParams screen;    ///< the screening parameters (screen.automatic: auto on/off)
    PostfitParams postfit;  ///< trend, rejection, normal points (postfit.altitudeKm from "altitude_km")
};

struct PresetsResult {
    bool ok = false;
    std::string error;      ///< "SOURCE: satellites[i] (NAME): KEY: what is wrong"
    std::vector<SatellitePreset> presets;
};

/// Parses a presets document; `source` names it in errors, `parsed` (the parse result the
/// document came from) adds the line and column.
PresetsResult presetsFromJson(const Json& doc, const std::string& source = "presets", const JsonParseResult* parsed = nullptr);
/// Reads and parses a presets file.
PresetsResult loadPresets(const std::string& path);
/// The JSON document for the presets (every parameter written, so a file is self-describing).
Json presetsToJson(const std::vector<SatellitePreset>& presets);
/// Writes the presets atomically (temporary + rename). False with *error on failure or when
/// an entry is invalid (nothing written then).
bool savePresets(const std::string& path, const std::vector<SatellitePreset>& presets, std::string* error);

/// The preset for a pass: by ILRS id when given and present, else by name (normalised: lower
/// case, without blanks, '-' and '_'). nullptr when neither matches.
const SatellitePreset* findPreset(const std::vector<SatellitePreset>& presets, const std::string& name,
                                  const std::string& ilrsId = {});

}  // namespace lwb::core::slr
