#include "core/slr/np_context.hpp"

#include <cmath>

#include "core/common/text.hpp"
#include "core/slr/ilrs_tables.hpp"
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
    // The normal-point bin: the ILRS missions table when the satellite is listed and the
    // parameters leave the bin to the altitude (0).
    if (!(p->binLengthS > 0)) {
        const IlrsMission* m = findMission(pass.target);
        if (m && m->npBinS > 0) {
            p->binLengthS = m->npBinS;
            notes.push_back("normal-point bin " + formatDouble(m->npBinS, 6) + " s for " + m->name + " (ILRS missions table: " +
                            m->source + ")");
        } else {
            notes.push_back("satellite not in the ILRS missions table (resources/ilrs/missions.csv): normal-point bin from "
                            "its altitude");
        }
    }
    if (!sinex) {
        // The station's position from the shipped ILRS stations table (SLRF2014 SITE/ID).
        const IlrsStation* st = findStation(cdpPad);
        if (!st) {
            notes.push_back("station " + std::to_string(cdpPad) +
                            " not in the ILRS stations table and no SINEX: day or night not judged");
            return notes;
        }
        p->stationLatDeg = st->latDeg;
        p->stationLonDeg = st->lonDeg;
        p->dayStartMjd = static_cast<double>(pass.startMjd());
        notes.push_back("station " + std::to_string(cdpPad) + " (" + st->description + ") at " + formatFixed(st->latDeg, 3) +
                        "°, " + formatFixed(st->lonDeg, 3) + "° (ILRS stations table): day or night from the Sun's elevation");
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
