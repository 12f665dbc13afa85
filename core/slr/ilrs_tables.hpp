#pragma once
// The ILRS tables shipped with the program (resources/ilrs/, compiled in; their sources are in
// the files' headers): per satellite the normal-point bin length, per station its approximate
// position. A pass's normal points take their bin from the missions table and the station's
// day or night from the stations table when no SINEX file is given.
#include <string>
#include <vector>

#include "core/slr/crd.hpp"

namespace lwb::core::slr {

struct IlrsMission {
    std::string name, ilrsId;  ///< "Jason-1", "0105501"
    long sic = -1, norad = -1;
    double altitudeKm = 0;     ///< nominal
    double npBinS = 0;         ///< normal-point bin length
    std::string source;        ///< where the bin length comes from (np_source)
};

struct IlrsStation {
    int pad = 0;               ///< 4-digit CDP pad id (CRD H2)
    std::string description;
    double latDeg = 0, lonDeg = 0, heightM = 0;
};

const std::vector<IlrsMission>& ilrsMissions();
const std::vector<IlrsStation>& ilrsStations();

/// The mission of a CRD H3 target: by ILRS id (as a number: "105501" is "0105501"), else SIC,
/// else NORAD, else name (letters and digits only, any case: "JASON1" is "Jason-1"). Null when
/// none; ids that are empty or not numbers are not compared.
const IlrsMission* findMission(const std::string& name, const std::string& ilrsId, long sic = -1, long norad = -1);
/// The same for a CRD H3 record (its absent SIC and NORAD not compared).
const IlrsMission* findMission(const CrdTarget& target);
/// The station of a CDP pad id; null when not listed.
const IlrsStation* findStation(int pad);

}  // namespace lwb::core::slr
