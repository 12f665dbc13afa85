#include "core/slr/ilrs_tables.hpp"

#include <cctype>
#include <string_view>

#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::slr {

namespace {
#include "ilrs_tables.inc"

// The table's CSV without its '#' comment lines (its header says the source).
CsvTable table(const char* text, const char* source) {
    std::string body;
    for (std::string_view rest(text); !rest.empty();) {
        const size_t nl = rest.find('\n');
        const std::string_view line = rest.substr(0, nl);
        if (!line.empty() && line[0] != '#') (body += line) += '\n';
        rest = nl == std::string_view::npos ? std::string_view() : rest.substr(nl + 1);
    }
    CsvReadResult r = parseCsv(body, source);
    return r.ok ? r.table : CsvTable{};  // (a shipped table that does not parse is caught by test_slr_ilrs_tables)
}

std::string cell(const CsvTable& t, const std::vector<std::string>& row, const char* column) {
    const int c = t.column(column);
    return c >= 0 && size_t(c) < row.size() ? row[size_t(c)] : std::string();
}

double number(const std::string& s) {
    double v = 0;
    return parseDouble(s, &v) ? v : -1;
}

std::string letters(const std::string& s) {
    std::string out;
    for (char c : s)
        if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

long idNumber(const std::string& s) {
    long long v = 0;
    return !s.empty() && parseLong(trim(s), &v) && v >= 0 ? static_cast<long>(v) : -1;
}
}  // namespace

const std::vector<IlrsMission>& ilrsMissions() {
    static const std::vector<IlrsMission> missions = [] {
        std::vector<IlrsMission> v;
        const CsvTable t = table(kIlrsMissionsCsv, "resources/ilrs/missions.csv");
        for (const auto& row : t.rows) {
            IlrsMission m;
            m.name = cell(t, row, "name");
            m.ilrsId = cell(t, row, "ilrs_id");
            m.sic = idNumber(cell(t, row, "sic"));
            m.norad = idNumber(cell(t, row, "norad"));
            m.altitudeKm = number(cell(t, row, "altitude_km"));
            m.npBinS = number(cell(t, row, "np_bin_s"));
            m.source = cell(t, row, "np_source");
            v.push_back(m);
        }
        return v;
    }();
    return missions;
}

const std::vector<IlrsStation>& ilrsStations() {
    static const std::vector<IlrsStation> stations = [] {
        std::vector<IlrsStation> v;
        const CsvTable t = table(kIlrsStationsCsv, "resources/ilrs/stations.csv");
        for (const auto& row : t.rows) {
            IlrsStation s;
            s.pad = static_cast<int>(idNumber(cell(t, row, "pad")));
            s.description = cell(t, row, "description");
            s.latDeg = number(cell(t, row, "lat_deg"));
            s.lonDeg = number(cell(t, row, "lon_deg"));
            s.heightM = number(cell(t, row, "height_m"));
            v.push_back(s);
        }
        return v;
    }();
    return stations;
}

const IlrsMission* findMission(const CrdTarget& t) {
    return findMission(t.name, t.ilrsId, t.sic == kCrdAbsent ? -1 : t.sic, t.norad == kCrdAbsent ? -1 : t.norad);
}

const IlrsMission* findMission(const std::string& name, const std::string& ilrsId, long sic, long norad) {
    const auto& all = ilrsMissions();
    const long id = idNumber(ilrsId);
    for (const auto& m : all)
        if (id >= 0 && idNumber(m.ilrsId) == id) return &m;
    for (const auto& m : all)
        if ((sic >= 0 && m.sic == sic) || (norad >= 0 && m.norad == norad)) return &m;
    const std::string key = letters(name);
    for (const auto& m : all)
        if (!key.empty() && letters(m.name) == key) return &m;
    return nullptr;
}

const IlrsStation* findStation(int pad) {
    for (const auto& s : ilrsStations())
        if (s.pad == pad) return &s;
    return nullptr;
}

}  // namespace lwb::core::slr
