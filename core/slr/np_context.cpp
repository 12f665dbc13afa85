#include "core/slr/np_context.hpp"

#include <cmath>

#include "core/common/text.hpp"
#include "core/slr/solar.hpp"

namespace lwb::core::slr {

double crdFireRateHz(const CrdPass& pass) {
    for (const CrdRecord& r : pass.records) {
        if (r.id != "c1") continue;
        const std::vector<std::string_view> f = splitBlanks(r.text);
        double hz = NAN;
        if (f.size() > 5 && parseDouble(f[5], &hz) && hz > 0 && std::isfinite(hz)) return hz;
    }
    return NAN;
}

std::vector<std::string> fillNormalPointContext(const CrdPass& pass, int cdpPad, const SinexFile* sinex,
                                                PostfitParams* p) {
    std::vector<std::string> notes;
    if (!(p->fireRateHz > 0)) {
        const double hz = crdFireRateHz(pass);
        if (std::isfinite(hz)) {
            p->fireRateHz = hz;
            notes.push_back("fire rate " + formatDouble(hz, 6) + " Hz (C1 record)");
        } else {
            notes.push_back("no C1 fire rate: return rate unknown");
        }
    }
    if (!sinex) {
        notes.push_back("station position unknown (no SINEX): day or night not judged");
        return notes;
    }
    const long mjd = pass.startMjd();
    const StationPositionResult pos = stationPositionByPad(*sinex, cdpPad, mjd, 0);
    if (!pos.ok) {
        notes.push_back("station " + std::to_string(cdpPad) + " not found in the SINEX file: day or night not judged (" +
                        pos.error + ")");
        return notes;
    }
    double lat = 0, lon = 0, h = 0;
    geodeticFromEcef(pos.position.x(), pos.position.y(), pos.position.z(), &lat, &lon, &h);
    p->stationLatDeg = lat;
    p->stationLonDeg = lon;
    p->dayStartMjd = static_cast<double>(mjd);
    notes.push_back("station " + std::to_string(cdpPad) + " at " + formatFixed(lat, 3) + "°, " + formatFixed(lon, 3) +
                    "° (SINEX): day or night from the Sun's elevation");
    return notes;
}

}  // namespace lwb::core::slr
