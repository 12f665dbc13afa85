#include "core/slr/crd_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/line_reader.hpp"
#include "core/common/text.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/slr_time.hpp"

namespace lwb::core::slr {

const char* severityName(CrdSeverity s) { return s == CrdSeverity::Error ? "error" : "warning"; }

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
constexpr CrdSeverity kE = CrdSeverity::Error;
constexpr CrdSeverity kW = CrdSeverity::Warning;

// ---- the specification's records ------------------------------------------------------------

enum class K {
    Int,  ///< an integer (a whole-valued decimal such as "2." is read as one, as the reader does)
    Num,  ///< a number (FORTRAN F format: "26." accepted)
    Str,  ///< text (any token)
    Sod,  ///< seconds of day of the record's epoch
    Cfg,  ///< a system configuration id (defined by a C0 of the session)
};

/// One field of a record.
struct F {
    const char* name;
    K kind;
    bool na = false;        ///< may be "not available": "na" (v2), -1 (v1, and read so in v2 too)
    double lo = kNone, hi = kNone;  ///< valid range (NaN: none)
    CrdSeverity outside = kE;       ///< outside the range: an error (codes, flags) or a warning (implausible values)
    const char* meaning = nullptr;  ///< the codes, for the message
};

F str(const char* n) { return {n, K::Str}; }
F cfg() { return {"system configuration id", K::Cfg}; }
F sod() { return {"seconds of day", K::Sod}; }
F code(const char* n, double lo, double hi, const char* meaning, bool na = false) { return {n, K::Int, na, lo, hi, kE, meaning}; }
F integer(const char* n, bool na = true, double lo = kNone, double hi = kNone, CrdSeverity s = kW) {
    return {n, K::Int, na, lo, hi, s, nullptr};
}
F num(const char* n, bool na = true, double lo = kNone, double hi = kNone, CrdSeverity s = kW) {
    return {n, K::Num, na, lo, hi, s, nullptr};
}

/// A record type: its fields (in the v2 layout, which extends v1's at the end) and how many of
/// them each version defines.
struct RecordSpec {
    const char* id;          ///< lower case
    int count[3];            ///< fields after the id in the drafts ("version 0"), v1, v2; 0: no such record
    bool variadic = false;   ///< count is a minimum (C0: as many component ids as the station has)
    std::vector<F> f;
};

const char* kEpochEvent =
    "0 ground receive, 1 spacecraft bounce, 2 ground transmit (two-way); 3 spacecraft receive, 4 spacecraft "
    "transmit, 5 ground transmit and spacecraft receive, 6 spacecraft transmit and ground receive (one-way)";

const std::vector<RecordSpec>& specs() {
    static const std::vector<RecordSpec> s = {
        {"h1", {6, 6, 6}, false,
         {str("format"), integer("format version", false), integer("year of file production", false, 1950, 2100, kE),
          integer("month of file production", false, 1, 12, kE), integer("day of file production", false, 1, 31, kE),
          integer("hour of file production", false, 0, 23, kE)}},
        {"h2", {5, 5, 6}, false,
         {str("station name"), integer("CDP pad identifier", false, 1000, 9999, kW),
          integer("CDP system number", false, 0, 99, kE), integer("CDP occupancy sequence number", false, 0, 99, kE),
          integer("station epoch time scale", false), str("station network")}},
        {"h3", {6, 6, 7}, false,
         {str("target name"), str("ILRS satellite id"), integer("SIC", true, 0, 9999), integer("NORAD id", true, 0, 99999999),
          code("spacecraft epoch time scale", 0, 2, "0 not applicable, 1 UTC, 2 spacecraft time scale"),
          integer("target type", false),
          code("target location", 0, 10,
               "0 other, 1 Earth orbit, 2 lunar orbit, 3 lunar surface, 4 Mars orbit, 5 Mars surface, 6 Venus orbit, 7 "
               "Mercury orbit, 8 asteroid orbit, 9 asteroid surface, 10 solar or transfer orbit",
               true)}},
        {"h4", {21, 21, 21}, false,
         {code("data type", 0, 2, "0 full rate, 1 normal point, 2 sampled engineering"), integer("start year", false),
          integer("start month", false), integer("start day", false), integer("start hour", false),
          integer("start minute", false), integer("start second", false), integer("end year", true),
          integer("end month", true), integer("end day", true), integer("end hour", true), integer("end minute", true),
          integer("end second", true), code("data release flag", 0, 99, "0 first release, 1 first replacement, ..."),
          code("tropospheric refraction applied indicator", 0, 1, "0 no, 1 yes"),
          code("centre-of-mass correction applied indicator", 0, 1, "0 no, 1 yes"),
          code("receive amplitude correction applied indicator", 0, 1, "0 no, 1 yes"),
          code("station system delay applied indicator", 0, 1, "0 no, 1 yes"),
          code("spacecraft system delay applied indicator", 0, 1, "0 no, 1 yes"),
          code("range type indicator", 0, 4, "0 no ranges (transmit times only), 1 one-way, 2 two-way, 3 receive times only, 4 mixed"),
          code("data quality alert indicator", 0, 2, "0 good, 1 suspect, 2 poor or unknown")}},
        {"h5", {0, 0, 5}, false,
         {code("prediction type", 1, 2, "1 CPF, 2 TLE"), integer("year of century of the prediction", false, 0, 99, kE),
          str("prediction date and time"), str("prediction provider"), integer("prediction sequence number", true)}},
        {"h8", {0, 0, 0}, false, {}},
        {"h9", {0, 0, 0}, false, {}},
        {"c0", {3, 3, 3}, true,
         {integer("detail type", false, 0, 0, kW), num("transmit wavelength", false, 200, 2500), str("system configuration id")}},
        {"c1", {9, 9, 9}, false,
         {integer("detail type", false, 0, 0, kW), str("laser configuration id"), str("laser type"),
          num("primary wavelength", true, 200, 2500), num("nominal fire rate", true, 0), num("pulse energy", true, 0),
          num("pulse width", true, 0), num("beam divergence", true, 0), integer("pulses in outgoing semi-train", true, 0)}},
        {"c2", {13, 13, 16}, false,
         {integer("detail type", false, 0, 0, kW), str("detector configuration id"), str("detector type"),
          num("applicable wavelength", true, 200, 2500), num("quantum efficiency", true, 0, 100), num("applied voltage"),
          num("dark count"), str("output pulse type"), num("output pulse width", true, 0), num("spectral filter", true, 0),
          num("transmission of spectral filter", true, 0, 100), num("spatial filter", true, 0), str("external signal processing"),
          num("amplifier gain"), num("amplifier bandwidth", true, 0), code("amplifier in use", 0, 1, "0 no, 1 yes", true)}},
        {"c3", {7, 7, 7}, false,
         {integer("detail type", false, 0, 0, kW), str("timing configuration id"), str("time source"),
          str("frequency source"), str("timer"), str("timer serial number"), num("epoch delay correction")}},
        {"c4", {10, 10, 10}, false,
         {integer("detail type", false, 0, 0, kW), str("transponder configuration id"),
          num("estimated station UTC offset"), num("estimated station oscillator drift"),
          num("estimated transponder UTC offset"), num("estimated transponder oscillator drift"),
          num("transponder clock reference time"), integer("station clock offset and drift applied indicator"),
          integer("spacecraft clock offset and drift applied indicator"), integer("spacecraft time simplified flag")}},
        {"c5", {0, 0, 6}, false,
         {integer("detail type", false, 0, 0, kW), str("software configuration id"), str("tracking software"),
          str("tracking software version"), str("processing software"), str("processing software version")}},
        {"c6", {0, 0, 11}, false,
         {integer("detail type", false, 0, 0, kW), str("meteorological configuration id"),
          str("pressure sensor manufacturer"), str("pressure sensor model"), str("pressure sensor serial number"),
          str("temperature sensor manufacturer"), str("temperature sensor model"), str("temperature sensor serial number"),
          str("humidity sensor manufacturer"), str("humidity sensor model"), str("humidity sensor serial number")}},
        {"c7", {0, 0, 9}, false,
         {integer("detail type", false, 0, 0, kW), str("calibration target configuration id"), str("target name"),
          num("surveyed target distance", true, 0), num("survey error", true, 0), num("sum of constant delays"),
          num("pulse energy", true, 0), str("processing software name"), str("processing software version")}},
        {"10", {8, 8, 9}, false,
         {sod(), num("time of flight", false), cfg(), code("epoch event", 0, 6, kEpochEvent),
          code("filter flag", 0, 2, "0 unknown, 1 noise, 2 data"), integer("detector channel", true, 0, kNone, kE),
          integer("stop number", true, 0, kNone, kE), num("receive amplitude", true, 0), num("transmit amplitude", true, 0)}},
        {"11", {11, 12, 13}, false,
         {sod(), num("time of flight", false), cfg(), code("epoch event", 0, 6, kEpochEvent),
          num("normal point window length", true, 0), integer("number of raw ranges", true, 0, kNone, kE),
          num("bin RMS", true, 0), num("bin skew"), num("bin kurtosis"), num("bin peak - mean"),
          num("return rate", true, 0, 100), integer("detector channel", true, 0, kNone, kE),
          num("signal to noise ratio", true, 0)}},
        {"12", {6, 6, 7}, false,
         {sod(), cfg(), num("tropospheric refraction correction"), num("target centre-of-mass correction"),
          num("neutral density filter value"), num("time bias applied"), num("range rate")}},
        {"20", {5, 5, 5}, false,
         {sod(), num("surface pressure", false, 400, 1100), num("surface temperature", false, 200, 350),
          num("relative humidity", false, 0, 100), code("origin of values", 0, 1, "0 measured, 1 interpolated")}},
        {"21", {8, 8, 9}, false,
         {sod(), num("wind speed", true, 0), num("wind direction", true, 0, 360), str("weather conditions"),
          num("visibility", true, 0), num("sky clarity"), num("atmospheric seeing"), num("cloud cover", true, 0, 100),
          num("sky temperature", true, 0)}},
        {"30", {6, 6, 8}, false,
         {sod(), num("azimuth", false, 0, 360, kE), num("elevation", false, -90, 90, kE),
          code("direction flag", 0, 2, "0 transmit and receive, 1 transmit, 2 receive"),
          code("angle origin indicator", 0, 3, "0 unknown, 1 computed, 2 commanded (predictions), 3 measured (encoders)"),
          code("refraction corrected indicator", 0, 1, "0 no, 1 yes"), num("azimuth rate"), num("elevation rate")}},
        {"40", {14, 15, 17}, false,
         {sod(),
          code("type of data", 0, 5,
               "0 station combined, 1 station transmit, 2 station receive, 3 target combined, 4 target transmit, 5 target "
               "receive"),
          cfg(), integer("number of points recorded", true, 0, kNone, kE), integer("number of points used", true, 0, kNone, kE),
          num("one-way target distance", true, 0), num("calibration system delay", false), num("calibration delay shift"),
          num("RMS", true, 0), num("skew"), num("kurtosis"), num("peak - mean"),
          code("calibration type indicator", 0, 6,
               "0 undefined, 1 nominal, 2 external, 3 internal telescope, 4 internal building, 5 burst, 6 other"),
          code("calibration shift type indicator", 0, 4, "0 undefined, 1 nominal, 2 pre- to post-pass, 3 minimum to maximum, 4 other"),
          integer("detector channel", true, 0, kNone, kE),
          code("calibration span", 0, 4, "0 not applicable, 1 pre-pass, 2 post-pass, 3 combined pre- and post-pass, 4 real time", true),
          num("return rate", true, 0, 100)}},
        {"42", {0, 0, 13}, false, {sod(), num("time of flight", false), cfg()}},
        {"50", {6, 6, 6}, false,
         {cfg(), num("session RMS", true, 0), num("session skew"), num("session kurtosis"), num("session peak - mean"),
          code("data quality assessment indicator", 0, 5,
               "0 undefined, 1 clear with little noise, 2 clear with some noise, 3 clear with much noise or weak, 4 "
               "unclear, 5 no data apparent")}},
        {"60", {3, 3, 3}, false,
         {cfg(), code("system change indicator", 0, 9, "0..9"), code("system configuration indicator", 0, 9, "0..9")}},
    };
    return s;
}

const RecordSpec* specOf(std::string_view id) {
    if (id == "41") id = "40";  // (the same fields; 41 is v2 only, said by the caller)
    for (const RecordSpec& s : specs())
        if (id == s.id) return &s;
    return nullptr;
}

// ---- small helpers ---------------------------------------------------------------------------

constexpr size_t kMaxCheckTokens = 64;

/// Blank-separated fields of a line (text.hpp splitBlanks); n counts them all, [] gives "" past
/// the last (and past kMaxCheckTokens, which the per-record checks size their arrays by).
struct Tokens {
    std::vector<std::string_view> t;
    size_t n = 0;
    explicit Tokens(std::string_view s) : t(splitBlanks(s)), n(t.size()) {}
    std::string_view operator[](size_t i) const { return i < kMaxCheckTokens && i < n ? t[i] : std::string_view(); }
};

bool intValue(std::string_view s, double* out) {
    long long v = 0;
    if (parseLong(s, &v)) {
        *out = static_cast<double>(v);
        return true;
    }
    double d = 0;
    if (parseFortranDouble(s, &d) && d == std::floor(d) && std::fabs(d) < 1e15) {
        *out = d;
        return true;
    }
    return false;
}

std::string q(std::string_view s) { return "\"" + printableExcerpt(s, 30) + "\""; }

/// A number as the message shows it: as few digits as say it.
std::string num2s(double v) { return formatShortest(v); }

std::string hms(double sod) {
    if (!std::isfinite(sod)) return "?";
    const double d = std::fmod(sod, kSecondsPerDay);
    const long s = static_cast<long>(std::floor(d));
    char b[32];
    std::snprintf(b, sizeof b, "%02ld:%02ld:%06.3f", s / 3600, s / 60 % 60, d - 3600.0 * (s / 3600) - 60.0 * (s / 60 % 60));
    return b;
}

/// How a record is named in a message: "H4", "C0", "record 10".
std::string label(std::string_view id) {
    if (!id.empty() && (id[0] == 'h' || id[0] == 'c')) {
        std::string s(id);
        s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
        return s;
    }
    return "record " + std::string(id);
}

/// "type-10 records", "H4 record", "blank lines".
std::string recordsName(const std::string& written, size_t n) {
    const std::string id = toLower(written);
    std::string s = id.empty() ? "blank line" : std::isdigit(static_cast<unsigned char>(id[0])) ? "type-" + id + " record" : label(id) + " record";
    return n == 1 ? s : s + "s";
}

int layoutOf(int version) { return version <= 0 ? 0 : version == 1 ? 1 : 2; }
std::string versionName(int version) { return version <= 0 ? "the CRD drafts (version 0)" : "CRD v" + std::to_string(version); }

// The v1 header records are in fixed columns (CRD v1.01, section 2; the Operation Center checks
// them): each field within its columns (1-based, right-justified numbers), blanks between fields.
struct FixedLayout {
    const char* id;
    std::vector<std::pair<int, int>> cols;  // 1-based first and last column of each field
    const char* text;
};

const std::vector<FixedLayout>& fixedLayouts() {
    static const std::vector<FixedLayout> l = {
        {"h1", {{4, 6}, {8, 9}, {11, 14}, {16, 17}, {19, 20}, {22, 23}}, "format 4-6, version 8-9, date 11-20, hour 22-23"},
        {"h2", {{4, 13}, {15, 18}, {20, 21}, {23, 24}, {26, 27}},
         "station name 4-13, CDP pad 15-18, system 20-21, occupancy 23-24, time scale 26-27"},
        {"h3", {{4, 13}, {15, 22}, {24, 27}, {29, 36}, {38, 38}, {40, 40}},
         "target name 4-13, ILRS id 15-22, SIC 24-27, NORAD 29-36, time scale 38, target type 40"},
        {"h4", {{4, 5},   {7, 10},  {12, 13}, {15, 16}, {18, 19}, {21, 22}, {24, 25}, {27, 30}, {32, 33}, {35, 36}, {38, 39},
                {41, 42}, {44, 45}, {47, 48}, {50, 50}, {52, 52}, {54, 54}, {56, 56}, {58, 58}, {60, 60}, {62, 62}},
         "data type 4-5, start 7-25, end 27-45, release 47-48, indicators at 50, 52, ..., 62"},
    };
    return l;
}

std::string fixedLayoutText(std::string_view id) {
    for (const auto& l : fixedLayouts())
        if (id == l.id) return l.text;
    return {};
}

/// "" when the line is in its v1 fixed columns, else which field is not.
std::string fixedColumnProblem(std::string_view id, std::string_view line) {
    const FixedLayout* lay = nullptr;
    for (const auto& l : fixedLayouts())
        if (id == l.id) lay = &l;
    if (!lay) return {};
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.remove_suffix(1);
    if (Tokens(line).n != lay->cols.size() + 1) return {};  // (the field-count rule speaks)
    const int last = lay->cols.back().second;
    if (static_cast<int>(line.size()) > last)
        return "it is " + std::to_string(line.size()) + " characters long, " + std::to_string(last) + " in the fixed layout";
    std::vector<bool> inField(static_cast<size_t>(last) + 1, false);
    for (size_t k = 0; k < lay->cols.size(); ++k) {
        const auto [a, b] = lay->cols[k];
        for (int c = a; c <= b; ++c) inField[static_cast<size_t>(c)] = true;
        const std::string_view cell = static_cast<size_t>(a - 1) < line.size()
                                          ? trim(line.substr(static_cast<size_t>(a - 1), static_cast<size_t>(b - a + 1)))
                                          : std::string_view();
        if (cell.empty() || cell.find_first_of(" \t") != std::string_view::npos)
            return "field " + std::to_string(k + 1) + " is not within columns " + std::to_string(a) + "-" + std::to_string(b);
    }
    for (int c = 3; c <= static_cast<int>(line.size()); ++c)
        if (!inField[static_cast<size_t>(c)] && line[static_cast<size_t>(c - 1)] != ' ')
            return "column " + std::to_string(c) + " should be blank";
    return {};
}

// ---- the checker -----------------------------------------------------------------------------

/// Data record types whose epochs are kept in order within a session.
int orderedIndex(std::string_view id) {
    static const char* k[] = {"10", "11", "12", "20", "21", "30"};
    for (int i = 0; i < 6; ++i)
        if (id == k[i]) return i;
    return -1;
}

class Checker {
public:
    Checker(std::string source, const CrdCheckParams& params, CrdCheckResult* out)
        : src_(std::move(source)), params_(params), out_(out) {
        ext_ = inputExtension(src_);
    }

    void line(std::string_view text, long no);
    void finish(long lastLine, bool endsWithLineEnd);
    /// The text stops here (binary data): what was counted and not yet listed is listed.
    void stop() { flushRepeats(); }

private:
    struct Session {
        size_t ordinal = 0;
        long firstLine = 0, h4Line = 0;
        bool h4ok = false;             ///< its start date-time could be read
        int dataType = -1, rangeType = -1;
        long startMjd = 0;
        double startSod = 0;
        bool endKnown = false;
        double endT = 0;               ///< end, s from the start day's 0h
        bool sawData = false, sawConfig = false, c0AfterData = false;
        long firstDataLine = 0;
        size_t records = 0, n10 = 0, n11 = 0;
        std::map<std::string, long> c0;                   ///< lower-case system config id -> line
        std::map<std::string, long> components;           ///< lower-case C1..C7 ids -> line
        std::vector<std::pair<std::string, long>> named;  ///< components a C0 names, with its line
        struct Use {
            long first = 0;
            size_t count = 0;
            std::string record;
        };
        std::map<std::string, Use> undefined;             ///< ids used before (or without) their C0
        /// A problem of many records of the session, said once at its first record when it closes.
        struct Many {
            long first = 0, last = 0;
            size_t count = 0;
            std::string record, text;
            double worst = 0;
            void add(long line, std::string_view rec, double by, const std::function<std::string()>& what) {
                if (count++ == 0) {
                    first = line;
                    record = std::string(rec);
                    text = what();
                }
                last = line;
                worst = std::max(worst, by);
            }
        };
        Many wrongType, outsideSpan;
        double lastT[6];
        long lastLine[6];
        Session() {
            for (int i = 0; i < 6; ++i) lastT[i] = -1e300, lastLine[i] = 0;
        }
    };

    struct Repeat {
        size_t shown = 0, hidden = 0;
        long first = 0, last = 0;
        CrdSeverity sev = kE;
        std::string rule, record;
    };

    void report(long line, std::string_view rec, CrdSeverity sev, const char* rule, std::string msg,
                const std::string& repeatKey = {});
    void flushRepeats();
    /// One problem for many records of a session (counted once; its lines are those it covers).
    template <class Many>
    void reportMany(const Many& m, CrdSeverity sev, const char* rule, std::string msg) {
        add({m.first, m.record, sev, rule, std::move(msg), 1, m.count > 1 ? m.last : 0});
    }
    void add(CrdProblem p) {
        (p.severity == kE ? out_->errors : out_->warnings) += p.count;
        out_->problems.push_back(std::move(p));
    }

    bool checkFields(const RecordSpec& spec, std::string_view id, std::string_view written, const Tokens& tk, long no,
                     double* v, bool* have);
    void onHeader(std::string_view id, std::string_view written, const Tokens& tk, long no, std::string_view text);
    void onH4(std::string_view written, const Tokens& tk, long no, const double* v, const bool* have);
    void onSessionRecord(std::string_view id, std::string_view written, const Tokens& tk, long no);
    void closeSession(long lastLine, bool withH8);
    void useConfig(std::string_view written, std::string_view cfgId, long no);
    std::string where() const;

    std::string src_, ext_;
    const CrdCheckParams& params_;
    CrdCheckResult* out_;

    int version_ = 1;
    bool versionKnown_ = false;
    long h1Line_ = 0;
    bool haveH1_ = false, haveH2_ = false, haveH3_ = false;
    long sinceH4_[3] = {0, 0, 0};  ///< lines of H1/H2/H3 seen since the last H4 (0: none)
    int prodY_ = 0, prodM_ = 0, prodD_ = 0;
    std::string station_, target_;
    std::map<std::string, long> targets_;  ///< lower-case target -> first H3 line
    bool inSession_ = false;
    Session s_;
    size_t sessions_ = 0;
    long lastH8_ = 0, h9Line_ = 0, anyRecord_ = 0;
    bool afterH9Said_ = false;
    std::map<std::string, Repeat> repeats_;
};

std::string Checker::where() const {
    if (lastH8_) return "after the H8 at line " + std::to_string(lastH8_) + " that ended the session";
    return "no H4 session header before it";
}

void Checker::report(long line, std::string_view rec, CrdSeverity sev, const char* rule, std::string msg,
                     const std::string& repeatKey) {
    if (!repeatKey.empty() && params_.maxRepeats > 0) {
        Repeat& r = repeats_[repeatKey + (sev == kE ? "|e" : "|w")];  // (one count per severity)
        if (r.shown >= params_.maxRepeats) {
            if (r.hidden++ == 0) r.first = line;
            r.last = line;
            r.sev = sev;
            r.rule = rule;
            r.record = std::string(rec);
            (sev == kE ? out_->errors : out_->warnings) += 1;
            return;
        }
        ++r.shown;
    }
    add({line, std::string(rec), sev, rule, std::move(msg), 1});
}

void Checker::flushRepeats() {
    for (auto& [key, r] : repeats_) {
        if (r.hidden == 0) continue;
        CrdProblem p{r.first, r.record, r.sev, r.rule,
                     std::to_string(r.hidden) + " more " + recordsName(r.record, r.hidden) +
                         " with the problem above (lines " + std::to_string(r.first) + ".." + std::to_string(r.last) +
                         "), not listed one by one",
                     r.hidden, r.last};
        out_->problems.push_back(std::move(p));  // (counted when found)
    }
    repeats_.clear();
}

bool Checker::checkFields(const RecordSpec& spec, std::string_view id, std::string_view written, const Tokens& tk, long no,
                          double* v, bool* have) {
    const int lay = layoutOf(version_);
    int count = spec.count[lay];
    if (count == 0 && spec.count[2] > 0) count = spec.count[2];  // (a v2 record in a v1 file: said by the caller)
    const size_t n = tk.n - 1;
    const std::string rec = label(id);
    const std::string key = std::string(id) + "|";
    bool ok = true;
    if (n < static_cast<size_t>(count)) {
        std::string missing;
        for (size_t i = n; i < static_cast<size_t>(count) && i < spec.f.size(); ++i)
            missing += (missing.empty() ? "" : ", ") + std::string(spec.f[i].name);
        if (spec.variadic && missing.empty()) missing = "the fields after field " + std::to_string(n);
        report(no, written, kE, "field-count",
               rec + " has " + std::to_string(n) + " field" + (n == 1 ? "" : "s") + "; " + versionName(version_) +
                   (spec.variadic ? " needs at least " : " defines ") + std::to_string(count) +
                   (missing.empty() ? std::string() : " (missing: " + missing + ")"),
               key + "count");
        ok = false;
    } else if (n > static_cast<size_t>(count) && !spec.variadic) {
        std::string extra = "\"" + printableExcerpt(tk[static_cast<size_t>(count) + 1], 20) + "\"";
        if (n > static_cast<size_t>(count) + 1) extra += ", ...";
        std::string why;
        if (lay < 2 && n == static_cast<size_t>(spec.count[2])) why = " (the v2 layout in a " + versionName(version_) + " file?)";
        else if (lay == 0 && n == static_cast<size_t>(spec.count[1])) why = " (the v1 layout in a version-0 file?)";
        report(no, written, kW, "field-count",
               rec + " has " + std::to_string(n) + " fields; " + versionName(version_) + " defines " +
                   std::to_string(count) + " (extra: " + extra + ")" + why,
               key + "count");
    }
    const size_t m = std::min({n, spec.f.size(), kMaxCheckTokens - 1});
    bool naV1Said = false;
    for (size_t i = 0; i < m; ++i) {
        const F& f = spec.f[i];
        const std::string_view t = tk[i + 1];
        auto fname = [&] { return rec + " field " + std::to_string(i + 1) + " (" + f.name + ")"; };
        v[i] = kNone;
        have[i] = false;
        if (f.kind == K::Str || f.kind == K::Cfg) {
            have[i] = true;
            continue;
        }
        if (isCrdNa(t)) {
            if (!f.na)
                report(no, written, kE, "na", fname() + " is " + q(t) + ": the specification requires a value here",
                       key + "na" + f.name);
            else if (version_ < 2 && !naV1Said) {  // (once a record)
                naV1Said = true;
                report(no, written, kW, "na", fname() + " is " + q(t) + ": \"na\" is CRD v2 (a v1 file writes -1)",
                       key + "na-v1");
            }
            continue;
        }
        double x = 0;
        const bool parsed = f.kind == K::Int ? intValue(t, &x) : parseFortranDouble(t, &x);
        if (!parsed) {
            report(no, written, kE, "field-format",
                   fname() + " is " + q(t) + ", not " + (f.kind == K::Int ? "an integer" : "a number"), key + "format" + f.name);
            ok = false;
            continue;
        }
        v[i] = x;
        have[i] = true;
        if (f.kind == K::Sod) continue;  // (checked by the caller, with the day)
        if (f.na && x == -1) {           // "not available" in v1's way
            have[i] = false;
            v[i] = kNone;
            continue;
        }
        const bool low = !std::isnan(f.lo) && x < f.lo, high = !std::isnan(f.hi) && x > f.hi;
        if (low || high) {
            std::string range;
            if (f.meaning) range = "the codes are " + std::string(f.meaning);
            else if (!std::isnan(f.lo) && !std::isnan(f.hi)) range = "outside " + num2s(f.lo) + ".." + num2s(f.hi);
            else if (!std::isnan(f.lo)) range = "below " + num2s(f.lo);
            else range = "above " + num2s(f.hi);
            report(no, written, f.outside, "range", fname() + " is " + std::string(t) + "; " + range, key + "range" + f.name);
        }
    }
    return ok;
}

void Checker::closeSession(long lastLine, bool withH8) {
    if (!inSession_) return;
    Session& s = s_;
    const char* typeName[] = {"full-rate", "normal-point", "sampled engineering"};
    if (s.dataType == 0 || s.dataType == 2) {
        if (s.n10 == 0)
            report(s.h4Line, "H4", kE, "data-type",
                   std::string("the ") + typeName[s.dataType] + " session (H4 data type " + std::to_string(s.dataType) +
                       ") has no range record 10");
    } else if (s.dataType == 1 && s.n11 == 0) {
        report(s.h4Line, "H4", kE, "data-type", "the normal-point session (H4 data type 1) has no normal-point record 11");
    }
    if (const auto& m = s.wrongType; m.count) {
        std::string more;
        if (m.count > 1)
            more = "; " + std::to_string(m.count) + " such records in the session (lines " + std::to_string(m.first) + ".." +
                   std::to_string(m.last) + ")";
        reportMany(m, kE, "data-type", m.text + more);
    }
    if (const auto& m = s.outsideSpan; m.count) {
        std::string more;
        if (m.count > 1)
            more = "; " + std::to_string(m.count) + " epochs of the session lie outside the H4 start and end, by up to " +
                   num2s(std::round(m.worst * 1e3) / 1e3) + " s";
        reportMany(m, kW, "h4-span", m.text + more);
    }
    for (const auto& [id, use] : s.undefined) {
        const auto c = s.c0.find(id);
        if (c != s.c0.end())
            report(c->second, "C0", kW, "order",
                   "C0 of system configuration " + q(id) + " comes after its first use at line " + std::to_string(use.first) +
                       " (configuration records go before the data)");
        else
            report(use.first, use.record, kE, "config-id",
                   "system configuration id " + q(id) + " is not defined by a C0 record of the session of the H4 at line " +
                       std::to_string(s.h4Line) + " (" + std::to_string(use.count) + " record" + (use.count == 1 ? "" : "s") +
                       " use it" + (use.count == 1 ? "" : ", from this line on") + ")");
    }
    for (const auto& [comp, line] : s.named)
        if (!s.components.count(comp))
            report(line, "C0", kW, "config-id",
                   "C0 names the component configuration " + q(comp) + ", which no C1..C7 record of the session defines");
    flushRepeats();  // (repeats are counted per session, and between sessions)
    CrdCheckPass p;
    p.ordinal = s.ordinal;
    p.firstLine = s.firstLine;
    p.h4Line = s.h4Line;
    p.lastLine = lastLine;
    p.endedWithH8 = withH8;
    p.version = version_;
    p.dataType = s.dataType;
    p.station = station_;
    p.target = target_;
    if (s.h4ok) {
        int y = 0, mo = 0, d = 0;
        dateFromMjd(s.startMjd, &y, &mo, &d);
        char b[40];
        const long t = static_cast<long>(s.startSod);
        std::snprintf(b, sizeof b, "%04d-%02d-%02d %02ld:%02ld:%02ld", y, mo, d, t / 3600, t / 60 % 60, t % 60);
        p.start = b;
    }
    p.records = s.records;
    p.ranges = s.n10;
    p.normalPoints = s.n11;
    out_->passes.push_back(std::move(p));
    inSession_ = false;
    s_ = Session();
}

void Checker::useConfig(std::string_view written, std::string_view cfgId, long no) {
    if (cfgId.empty()) return;
    const std::string key = toLower(cfgId);
    if (s_.c0.count(key)) return;
    Session::Use& u = s_.undefined[key];
    if (u.count++ == 0) {
        u.first = no;
        u.record = std::string(written);
    }
}

void Checker::line(std::string_view text, long no) {
    out_->lines = no;
    while (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    const Tokens tk(text);
    if (tk.n == 0) {
        report(no, "", kE, "blank-line",
               "blank line: every line of a CRD file is a record (the ILRS Operation Center rejects blank lines)", "blank");
        return;
    }
    const std::string_view written = tk[0];
    const std::string id = toLower(written);
    anyRecord_ = anyRecord_ ? anyRecord_ : no;
    for (size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80 || (c < 0x20 && c != '\t')) {
            report(no, written, id == "00" ? kW : kE, "ascii",
                   std::string(c >= 0x80 ? "non-ASCII" : "control") + " character at column " + std::to_string(i + 1) +
                       ": CRD files are ASCII text",
                   "ascii");
            break;
        }
    }
    if (id == "00") return;  // a comment
    if (h9Line_ && !afterH9Said_) {  // (once: what follows is checked as records of their own)
        afterH9Said_ = true;
        report(no, written, kE, "order", label(id) + " after the H9 (end of file) at line " + std::to_string(h9Line_));
    }
    if (id.size() == 2 && id[0] == '9' && std::isdigit(static_cast<unsigned char>(id[1]))) return;  // user defined
    if (id.size() == 2 && id[0] == 'h' && id[1] >= '1' && id[1] <= '9' && id[1] != '6' && id[1] != '7') {
        onHeader(id, written, tk, no, text);
        return;
    }
    const RecordSpec* spec = specOf(id);
    if (!spec || id[0] == 'h') {
        report(no, written, kE, "record-type",
               "unknown record type " + q(written) +
                   " (CRD records: H1-H5, H8, H9, C0-C7, 00, 10, 11, 12, 20, 21, 30, 40, 41, 42, 50, 60, 90-99)",
               "unknown");
        return;
    }
    onSessionRecord(id, written, tk, no);
}

void Checker::onHeader(std::string_view id, std::string_view written, const Tokens& tk, long no, std::string_view text) {
    const RecordSpec* spec = specOf(id);
    double v[kMaxCheckTokens];
    bool have[kMaxCheckTokens] = {};
    const int k = id[1] - '1';  // 0 H1, 1 H2, 2 H3, 3 H4, 4 H5, 7 H8, 8 H9
    if (k <= 3 && inSession_) {
        report(no, written, kE, "order",
               label(id) + " inside the session of the H4 at line " + std::to_string(s_.h4Line) +
                   ": that session has no H8 (H1, H2, H3 and H4 go before a session, H8 ends it)");
        closeSession(no - 1, false);
    }
    if (id == "h1") {
        // The version decides the layout of every record after it: read it first.
        double ver = 0;
        if (tk.n > 2 && intValue(tk[2], &ver) && ver >= 0 && ver <= 99) {
            version_ = static_cast<int>(ver);
            versionKnown_ = true;
        } else {
            versionKnown_ = false;
            version_ = 1;
        }
    }
    checkFields(*spec, id, written, tk, no, v, have);  // (the fields that could be read are looked at below)
    if (version_ <= 1 && k <= 3) {  // (v2 headers are free format)
        const std::string why = fixedColumnProblem(id, text);
        if (!why.empty())
            report(no, written, kW, "fixed-format",
                   label(id) + " is not in the fixed columns of CRD v1 (" + fixedLayoutText(id) + "): " + why,
                   std::string(id) + "|fixed");
    }
    if (id == "h1") {
        if (tk.n > 1 && toLower(tk[1]) != "crd")
            report(no, written, kE, "h1",
                   "H1 names the format " + q(tk[1]) + ", not \"CRD\"" +
                       (toLower(tk[1]) == "cpf" ? ": a CPF prediction, not ranging data" : ""));
        // (a version that is not an integer is said by checkFields)
        if (versionKnown_ && version_ == 0) {
            report(no, written, kW, "version",
                   "CRD version 0: a draft of the format before v1.00 (2008); its records are checked with the "
                   "drafts' field counts (11: 11 fields, 40: 14, C2: 13)");
        } else if (versionKnown_ && version_ > 2) {
            report(no, written, kE, "version",
                   "CRD version " + std::to_string(version_) + " is not one this checker knows (1 or 2); checked as v2");
            version_ = 2;
        }
        if (versionKnown_ && version_ != 2 && (ext_ == "fr2" || ext_ == "np2" || ext_ == "ql2"))
            report(no, written, kW, "file-name",
                   "the file is named ." + ext_ + " (CRD v2) but its H1 says version " + std::to_string(version_));
        if (out_->version < 0 && versionKnown_) out_->version = version_;
        if (have[2] && have[3] && have[4]) {
            prodY_ = static_cast<int>(v[2]), prodM_ = static_cast<int>(v[3]), prodD_ = static_cast<int>(v[4]);
            if (!validDate(prodY_, prodM_, prodD_)) {
                char b[40];
                std::snprintf(b, sizeof b, "%04d-%02d-%02d", prodY_, prodM_, prodD_);
                report(no, written, kE, "range", std::string("H1 production date ") + b + " is not a date");
                prodY_ = 0;
            }
        } else {
            prodY_ = 0;
        }
        if (sinceH4_[0])
            report(no, written, kE, "order",
                   "a second H1 with no session since the H1 at line " + std::to_string(sinceH4_[0]) +
                       " (each H1 begins the headers of a session: H1 H2 H3 H4 ... H8)");
        else if (sinceH4_[1] || sinceH4_[2])
            report(no, written, kW, "order", "H1 after the H" + std::string(sinceH4_[2] ? "3" : "2") + " at line " +
                                                 std::to_string(sinceH4_[2] ? sinceH4_[2] : sinceH4_[1]) +
                                                 ": the headers go H1, H2, H3, H4");
        h1Line_ = no;
        haveH1_ = true;
        sinceH4_[0] = no;
        return;
    }
    if (id == "h2" || id == "h3") {
        const int idx = id == "h2" ? 1 : 2;
        if (idx == 1 && !haveH1_) report(no, written, kE, "order", "H2 before any H1 format header");
        if (idx == 2 && !haveH2_) report(no, written, kE, "order", "H3 before any H2 station header");
        if (sinceH4_[idx])
            report(no, written, kE, "order",
                   "a second " + label(id) + " with no session since the " + label(id) + " at line " +
                       std::to_string(sinceH4_[idx]));
        else if (idx == 1 && sinceH4_[2])
            report(no, written, kW, "order",
                   "H2 after the H3 at line " + std::to_string(sinceH4_[2]) + ": the headers go H1, H2, H3, H4");
        sinceH4_[idx] = no;
        if (idx == 1) {
            haveH2_ = true;
            station_ = tk.n > 1 ? std::string(tk[1]) : std::string();
            if (have[4]) {
                const int ts = static_cast<int>(v[4]);
                if (ts != 3 && ts != 4 && ts != 7)
                    report(no, written, kE, "range",
                           "H2 field 5 (station epoch time scale) is " + std::to_string(ts) +
                               "; it must be 3 (UTC (USNO)), 4 (UTC (GPS)) or 7 (UTC (BIH/BIPM))");
            }
            if (version_ >= 2 && tk.n > 6) {
                static const char* kNets[] = {"na", "ilrs", "eurolas", "nasa", "wpltn"};
                const std::string net = toLower(tk[6]);
                if (std::none_of(std::begin(kNets), std::end(kNets), [&](const char* x) { return net == x; }))
                    report(no, written, kW, "h2",
                           "H2 station network " + q(tk[6]) +
                               " is none of those the ILRS Operation Center knows (na, ILRS, EUROLAS, NASA, WPLTN)");
            }
        } else {
            haveH3_ = true;
            target_ = tk.n > 1 ? std::string(tk[1]) : std::string();
            if (tk.n > 2) {
                const std::string_view ilrs = tk[2];
                const bool digits = !ilrs.empty() && std::all_of(ilrs.begin(), ilrs.end(), [](char c) {
                    return std::isdigit(static_cast<unsigned char>(c)) != 0;
                });
                if (!digits && !(version_ >= 2 && isCrdNa(ilrs)))
                    report(no, written, kE, "range",
                           "H3 field 2 (ILRS satellite id) is " + q(ilrs) + ": the ILRS id is up to 7 digits (YYXXXPP, from "
                           "the COSPAR id)");
                else if (digits && ilrs.size() > 8)
                    report(no, written, kE, "range", "H3 field 2 (ILRS satellite id) " + q(ilrs) + " has more than 8 digits");
            }
            if (have[5]) {
                const int t = static_cast<int>(v[5]);
                if (version_ >= 2) {
                    if (t < 0 || t > 5)
                        report(no, written, kE, "range",
                               "H3 field 6 (target class) is " + std::to_string(t) +
                                   "; it must be 0 (no retro-reflector, debris), 1 (passive retro-reflector), 3 "
                                   "(synchronous transponder), 4 (asynchronous transponder) or 5 (other)");
                    else if (t == 2)
                        report(no, written, kW, "range",
                               "H3 field 6 (target class) is 2, which CRD v2 deprecates (it was the lunar retro-reflector "
                               "of v1; v2 says where the target is in field 7)");
                } else if (t < 0 || t > 4) {
                    report(no, written, kE, "range",
                           "H3 field 6 (target type) is " + std::to_string(t) +
                               "; it must be 1 (passive retro-reflector), 2 (lunar retro-reflector), 3 (synchronous "
                               "transponder) or 4 (asynchronous transponder)");
                } else if (t == 0) {
                    report(no, written, kW, "range",
                           "H3 field 6 (target type) is 0, not a CRD v1 target type (1 passive retro-reflector, 2 lunar, 3 "
                           "synchronous, 4 asynchronous transponder)");
                }
            }
            const std::string name = toLower(target_);
            if (!name.empty() && !targets_.count(name)) targets_[name] = no;
        }
        return;
    }
    if (id == "h4") {
        onH4(written, tk, no, v, have);
        return;
    }
    if (id == "h5") {
        if (version_ < 2)
            report(no, written, kW, "version", "H5 (prediction header) is a CRD v2 record; this file is " + versionName(version_));
        if (!inSession_)
            report(no, written, kE, "order", "H5 outside a session: it follows the H4 (" + where() + ")");
        else if (s_.sawConfig || s_.sawData)
            report(no, written, kW, "order", "H5 after configuration or data records: it follows the H4 directly");
        return;
    }
    if (id == "h8") {
        if (!inSession_) {
            report(no, written, kE, "order", "H8 without a session to end (" + where() + ")");
            return;
        }
        closeSession(no, true);
        lastH8_ = no;
        return;
    }
    if (id == "h9") {
        if (inSession_) {
            report(no, written, kE, "session-end",
                   "the session of the H4 at line " + std::to_string(s_.h4Line) + " ends without H8 (H9 here)");
            closeSession(no - 1, false);
        }
        if (!h9Line_) h9Line_ = no;
        return;
    }
}

void Checker::onH4(std::string_view written, const Tokens& tk, long no, const double* v, const bool* have) {
    if (!haveH1_ || !haveH2_ || !haveH3_)
        report(no, written, kE, "order",
               std::string("H4 before any ") + (!haveH1_ ? "H1 format" : !haveH2_ ? "H2 station" : "H3 target") +
                   " header (a session needs H1, H2 and H3 before its H4, from it or from an earlier session)");
    flushRepeats();
    inSession_ = true;
    s_ = Session();
    s_.ordinal = ++sessions_;
    s_.h4Line = no;
    long first = no;
    for (long l : sinceH4_)
        if (l && l < first) first = l;
    s_.firstLine = first;
    sinceH4_[0] = sinceH4_[1] = sinceH4_[2] = 0;
    s_.dataType = have[0] && v[0] >= 0 && v[0] <= 2 ? static_cast<int>(v[0]) : -1;
    s_.rangeType = have[19] && v[19] >= 0 && v[19] <= 4 ? static_cast<int>(v[19]) : -1;
    if (s_.dataType >= 0 && !ext_.empty()) {
        const char* want = nullptr;
        if (ext_ == "frd" || ext_ == "fr2") want = "0 (full rate)";
        else if (ext_ == "npt" || ext_ == "np2") want = "1 (normal point)";
        else if (ext_ == "qlk" || ext_ == "ql2") want = "2 (sampled engineering)";
        if (want && want[0] - '0' != s_.dataType)
            report(no, written, kW, "file-name",
                   "H4 data type is " + std::to_string(s_.dataType) + ", but a ." + ext_ + " file holds data type " + want);
    }
    // Start and end date-times.
    auto dateTime = [&](size_t from, int* y, int* mo, int* d, double* sec) -> int {  // 1 ok, 0 bad, -1 absent
        bool allAbsent = true, allHave = true;
        for (size_t i = from; i < from + 6; ++i) {
            const std::string_view t = tk[i + 1];
            const bool absent = i + 1 >= tk.n || isCrdNa(t) || t == "-1";
            allAbsent = allAbsent && absent;
            allHave = allHave && have[i];
        }
        if (allAbsent) return -1;
        if (!allHave) return 0;
        *y = static_cast<int>(v[from]), *mo = static_cast<int>(v[from + 1]), *d = static_cast<int>(v[from + 2]);
        const double h = v[from + 3], mi = v[from + 4], s = v[from + 5];
        if (!validDate(*y, *mo, *d) || h < 0 || h > 23 || mi < 0 || mi > 59 || s < 0 || s > 60) return 0;
        *sec = h * 3600 + mi * 60 + s;
        return 1;
    };
    int y = 0, mo = 0, d = 0, ey = 0, emo = 0, ed = 0;
    double sec = 0, esec = 0;
    const int st = tk.n > 7 ? dateTime(1, &y, &mo, &d, &sec) : 0;
    if (st != 1) {
        report(no, written, kE, "h4", "H4 start date-time (fields 2-7) is not a valid date and time");
    } else {
        s_.h4ok = true;
        s_.startMjd = mjdFromDate(y, mo, d);
        s_.startSod = sec;
        if (prodY_ && validDate(prodY_, prodM_, prodD_) && mjdFromDate(prodY_, prodM_, prodD_) < s_.startMjd)
            report(no, written, kW, "h4",
                   "the session starts on a later day than the file was produced (H1 at line " + std::to_string(h1Line_) + ")");
    }
    const int en = tk.n > 13 ? dateTime(7, &ey, &emo, &ed, &esec) : 0;
    if (en == 0) {
        report(no, written, kE, "h4",
               "H4 end date-time (fields 8-13) is not a valid date and time (an unknown end is written with all six "
               "fields " + std::string(version_ >= 2 ? "na" : "-1") + ")");
    } else if (en == 1 && s_.h4ok) {
        s_.endKnown = true;
        s_.endT = static_cast<double>(mjdFromDate(ey, emo, ed) - s_.startMjd) * kSecondsPerDay + esec;
        if (s_.endT < s_.startSod)
            report(no, written, kE, "h4", "H4 end date-time precedes its start date-time");
        else if (s_.endT - s_.startSod > kSecondsPerDay)
            report(no, written, kW, "h4",
                   "the session lasts more than a day by its H4 (" + num2s(s_.endT - s_.startSod) +
                       " s): the records' seconds of day cannot be placed in it");
    }
}

void Checker::onSessionRecord(std::string_view id, std::string_view written, const Tokens& tk, long no) {
    const RecordSpec* spec = specOf(id);
    if (!inSession_) {
        report(no, written, kE, "order",
               label(id) + " outside a session (" + where() + "): configuration and data records go between an H4 and its H8",
               std::string("outside|") + std::string(id));
        return;
    }
    const bool config = id[0] == 'c';
    const bool v2only = id == "41" || id == "42" || id == "c5" || id == "c6" || id == "c7";
    if (v2only && version_ < 2)
        report(no, written, kW, "version", label(id) + " is a CRD v2 record; this file is " + versionName(version_),
               std::string(id) + "|v2only");
    ++s_.records;
    if (config) {
        s_.sawConfig = true;
        if (s_.sawData && !s_.c0AfterData) {
            s_.c0AfterData = true;
            report(no, written, kW, "order",
                   label(id) + " after the data records that begin at line " + std::to_string(s_.firstDataLine) +
                       ": configuration records go before the data");
        }
    } else if (!s_.sawData) {
        s_.sawData = true;
        s_.firstDataLine = no;
    }
    double v[kMaxCheckTokens];
    bool have[kMaxCheckTokens] = {};
    checkFields(*spec, id, written, tk, no, v, have);
    const std::string key = std::string(id) + "|";

    if (config) {
        if (id == "c0") {
            if (tk.n > 3) {
                const std::string cid = toLower(tk[3]);
                if (!s_.c0.emplace(cid, no).second)
                    report(no, written, kE, "config-id",
                           "a second C0 of system configuration " + q(tk[3]) + " in the session (the first at line " +
                               std::to_string(s_.c0[cid]) + ")");
            }
            for (size_t i = 4; i < tk.n && i < kMaxCheckTokens; ++i)
                if (!isCrdNa(tk[i])) s_.named.emplace_back(toLower(tk[i]), no);
        } else if (tk.n > 2) {
            const std::string cid = toLower(tk[2]);
            s_.components.emplace(cid, no);
        }
        return;
    }

    // Seconds of day, within the day (a leap second's 86400..86401 only on its day); the epoch as
    // seconds from the H4 start day's 0h (a record more than 12 h before the start is the next day's).
    const bool hasSod = !spec->f.empty() && spec->f[0].kind == K::Sod;
    double t = kNone;
    if (hasSod && have[0]) {
        const double s = v[0];
        const long recDay = s_.h4ok && s < s_.startSod - 43200.0 ? s_.startMjd + 1 : s_.startMjd;
        if (s < 0 || s >= kSecondsPerDay + 1) {
            report(no, written, kE, "range", label(id) + " field 1 (seconds of day) is " + std::string(tk[1]) + "; outside 0..86400",
                   key + "sod");
        } else if (s >= kSecondsPerDay && s_.h4ok && !leapSecondAtEndOf(recDay)) {
            int yy = 0, mm = 0, dd = 0;
            dateFromMjd(recDay, &yy, &mm, &dd);
            char b[16];
            std::snprintf(b, sizeof b, "%04d-%02d-%02d", yy, mm, dd);
            report(no, written, kE, "leap-second",
                   label(id) + " seconds of day " + std::string(tk[1]) + " is 23:59:60, a leap second, but " + b +
                       " ends without one",
                   key + "leap");
        } else {
            t = s_.h4ok && s < s_.startSod - 43200.0 ? s + kSecondsPerDay : s;
        }
    }
    // Time order within the session, per record type.
    if (const int oi = orderedIndex(id); oi >= 0 && std::isfinite(t)) {
        if (t < s_.lastT[oi] - 1e-9) {
            const bool main = id == "10" || id == "11";
            report(no, written, main ? kE : kW, "epoch-order",
                   label(id) + " epoch " + num2s(v[0]) + " s (" + hms(t) + ") is before that of the " + label(id) +
                       " at line " + std::to_string(s_.lastLine[oi]) + " (" + hms(s_.lastT[oi]) +
                       "): records go in time order within a session",
                   key + "order");
        }
        if (t >= s_.lastT[oi]) {  // (the latest epoch so far is what the next record is held to)
            s_.lastT[oi] = t;
            s_.lastLine[oi] = no;
        }
    }
    if (id == "10" || id == "11") {
        (id == "10" ? s_.n10 : s_.n11)++;
        const bool fr = id == "10";
        if ((s_.dataType == 1 && fr) || ((s_.dataType == 0 || s_.dataType == 2) && !fr))
            s_.wrongType.add(no, written, 0, [&] {
                return std::string(fr ? "range record 10 in a normal-point session" : "normal-point record 11 in a ") +
                       (fr ? "" : s_.dataType == 0 ? "full-rate session" : "sampled engineering session") + " (H4 at line " +
                       std::to_string(s_.h4Line) + ", data type " + std::to_string(s_.dataType) + ")";
            });
        // Within the H4 span (its times are whole seconds: a second's slack).
        if (std::isfinite(t) && s_.h4ok) {
            const double before = s_.startSod - t, after = s_.endKnown ? t - s_.endT : 0;
            if (before > 1.0 || after > 1.0)
                s_.outsideSpan.add(no, written, std::max(before, after), [&] {
                    return label(id) + " epoch " + hms(t) + " is " +
                           (before > 1.0 ? "before the H4 start " + hms(s_.startSod) : "after the H4 end " + hms(s_.endT)) +
                           " (by " + num2s(std::round(std::max(before, after) * 1e3) / 1e3) + " s)";
                });
        }
        // The time of flight: two-way, at most the Moon's 2.6 s (the reader refuses beyond 100 s).
        if (have[1] && (v[1] < 0 || v[1] > 100))
            report(no, written, kE, "range",
                   label(id) + " field 2 (time of flight) is " + std::string(tk[2]) + " s; outside 0..100 s", key + "tof");
        // The epoch event against the H4 range type.
        if (have[3] && s_.rangeType >= 0) {
            const int ev = static_cast<int>(v[3]);
            if ((s_.rangeType == 2 && ev > 2) || (s_.rangeType == 1 && ev >= 0 && ev <= 2))
                report(no, written, kW, "h4-flags",
                       label(id) + " epoch event " + std::to_string(ev) + " is " + (ev > 2 ? "one-way" : "two-way") +
                           ", but the H4 range type is " + std::to_string(s_.rangeType) +
                           (s_.rangeType == 2 ? " (two-way)" : " (one-way)"),
                       key + "event");
        }
    }
    if ((id == "40" || id == "41") && have[3] && have[4] && v[4] > v[3])
        report(no, written, kW, "range",
               label(id) + " uses more points (" + num2s(v[4]) + ") than it recorded (" + num2s(v[3]) + ")", key + "used");
    // The system configuration the record names.
    for (size_t i = 0; i < spec->f.size() && i + 1 < tk.n; ++i)
        if (spec->f[i].kind == K::Cfg) useConfig(written, tk[i + 1], no);
}

void Checker::finish(long lastLine, bool endsWithLineEnd) {
    out_->lines = lastLine;
    if (!anyRecord_) {
        report(0, "", kE, "empty", lastLine ? "no record in the file (blank lines only)" : "empty file");
        return;
    }
    if (inSession_) {
        report(lastLine, "", kE, "session-end",
               "the file ends inside the session of the H4 at line " + std::to_string(s_.h4Line) + ": no H8 (cut short?)");
        closeSession(lastLine, false);
    }
    for (int k = 0; k < 3; ++k)
        if (sinceH4_[k]) {
            report(sinceH4_[k], k == 0 ? "H1" : k == 1 ? "H2" : "H3", kE, "order",
                   "H" + std::to_string(k + 1) + " begins no session: no H4 after it");
            break;
        }
    if (sessions_ == 0) report(0, "", kE, "order", "no H4 session header: the file holds no session");
    if (!h9Line_) report(lastLine, "", kE, "file-end", "the file ends without H9 (the end-of-file record)");
    if (!endsWithLineEnd)
        report(lastLine, "", kW, "line-end", "the last line has no line end: the file may be cut short");
    if (targets_.size() > 1) {
        std::string names;
        size_t k = 0;
        for (const auto& [name, line] : targets_) {
            if (k++ == 4) {
                names += ", ...";
                break;
            }
            names += (names.empty() ? "" : ", ") + name;
        }
        report(0, "", kW, "targets",
               "the file holds sessions of " + std::to_string(targets_.size()) + " targets (" + names +
                   "): the ILRS Operation Center takes one target per file");
    }
    flushRepeats();
}

// ---- the reader's word ------------------------------------------------------------------------

/// "SRC:LINE: message" -> line and message (line 0 when the message names none).
long splitWhere(const std::string& msg, const std::string& src, std::string* rest) {
    const std::string p = src + ":";
    if (msg.rfind(p, 0) == 0) {
        size_t i = p.size();
        long line = 0;
        const size_t digits = i;
        while (i < msg.size() && std::isdigit(static_cast<unsigned char>(msg[i]))) line = line * 10 + (msg[i++] - '0');
        if (i > digits && msg.compare(i, 2, ": ") == 0) {
            *rest = msg.substr(i + 2);
            return line;
        }
        *rest = std::string(trim(std::string_view(msg).substr(p.size())));
        return 0;
    }
    *rest = msg;
    return 0;
}

/// Adds what the reader said (warnings; passes it cannot use and an error as errors) where the
/// checker said nothing of that line.
void mergeReader(CrdCheckResult* r, const std::string& src, const std::vector<std::string>& warnings,
                 const std::vector<std::string>& passProblems, const std::string& error) {
    std::set<long> said;
    std::vector<std::pair<long, long>> spans;  // lines a "N more" problem stands for
    for (const CrdProblem& p : r->problems) {
        said.insert(p.line);
        if (p.lastLine > p.line) spans.emplace_back(p.line, p.lastLine);
    }
    auto spoken = [&](long line) {
        if (said.count(line)) return true;
        for (const auto& [a, b] : spans)
            if (line >= a && line <= b) return true;
        return false;
    };
    const bool anyError = r->errors > 0;
    std::vector<CrdProblem> more;
    auto take = [&](const std::string& msg, CrdSeverity sev) {
        if (msg.rfind("... and ", 0) == 0) return;  // (the reader's cap; the checker lists its own)
        // (the reader's notes on how it reads a sound file, not problems of the file: an end
        // written as unknown, which the format allows; a pass across a leap second)
        if (msg.find("end date-time is not given") != std::string::npos || msg.find("crosses the leap second") != std::string::npos)
            return;
        std::string rest;
        const long line = splitWhere(msg, src, &rest);
        if (line > 0 ? spoken(line) : anyError) return;
        said.insert(line);
        more.push_back({line, "", sev, "reader", "the workbench's reader: " + rest, 1});
    };
    for (const std::string& p : passProblems) take(p, kE);
    for (const std::string& w : warnings) {
        bool ofPass = false;  // (parseCrd repeats a pass's problem as a warning)
        for (const std::string& p : passProblems) ofPass = ofPass || w.rfind(p, 0) == 0;
        if (!ofPass) take(w, kW);
    }
    if (!error.empty()) take(error, kE);
    for (CrdProblem& p : more) {
        (p.severity == kE ? r->errors : r->warnings) += 1;
        r->problems.push_back(std::move(p));
    }
}

/// Sorts the problems by line and counts them per pass.
void conclude(CrdCheckResult* r) {
    std::stable_sort(r->problems.begin(), r->problems.end(),
                     [](const CrdProblem& a, const CrdProblem& b) { return a.line < b.line; });
    for (CrdCheckPass& p : r->passes)
        for (const CrdProblem& x : r->problems)
            if (x.line >= p.firstLine && x.line <= p.lastLine) (x.severity == kE ? p.errors : p.warnings) += x.count;
    r->ok = true;
}

/// Whether an input's text ends with a line end (LineReader gives lines without theirs): the last
/// byte of a plain file; a gzip file or the standard input decompressed or read (held) whole, up
/// to 256 MiB (larger: taken as ending with one).
bool endsWithLineEnd(const std::string& path) {
    if (!isStandardStream(path)) {
        std::FILE* f = std::fopen(path.c_str(), "rb");
        if (!f) return true;
        unsigned char magic[2] = {0, 0};
        const bool gz = std::fread(magic, 1, 2, f) == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
        int last = '\n';
        if (!gz && std::fseek(f, -1, SEEK_END) == 0) last = std::fgetc(f);
        std::fclose(f);
        if (!gz) return last == '\n' || last == '\r';
    }
    std::string all, err;
    if (!readFileText(path, &all, &err, 256LL << 20)) return true;
    return all.empty() || all.back() == '\n' || all.back() == '\r';
}

CrdReadParams readerParams() {
    CrdReadParams rp;
    rp.maxWarnings = 100000;
    return rp;
}

}  // namespace

std::string validate(const CrdCheckParams& p) {
    if (p.maxRepeats > 100000000) return "crd check: maximum repeats must be 0 (all) .. 100000000";
    return {};
}

CrdCheckResult checkCrdText(std::string_view given, const std::string& source, const CrdCheckParams& params) {
    CrdCheckResult r;
    r.path = source;
    const std::string src = source.empty() ? "crd" : source;
    try {
        if (std::string e = validate(params); !e.empty()) {
            r.error = std::move(e);
            return r;
        }
        std::string storage;
        const std::string_view text = plainText(given, &storage);
        Checker c(src, params, &r);
        size_t pos = 0;
        long no = 0;
        bool nul = false;
        while (pos < text.size()) {
            size_t end = text.find('\n', pos);
            const bool nl = end != std::string_view::npos;
            if (!nl) end = text.size();
            const std::string_view line = text.substr(pos, end - pos);
            ++no;
            if (line.find('\0') != std::string_view::npos) {
                c.stop();
                r.lines = no;
                r.problems.push_back({no, "", kE, "text", "binary data (NUL byte): not a CRD text file; not checked further", 1});
                ++r.errors;
                nul = true;
                break;
            }
            c.line(line, no);
            pos = nl ? end + 1 : end;
        }
        if (!nul) c.finish(no, text.empty() || text.back() == '\n');
        if (params.readerMessages && !nul && !text.empty()) {
            const CrdReadResult rd = parseCrd(given, source, readerParams());
            std::vector<std::string> passProblems;
            for (const CrdPass& p : rd.file.passes)
                if (!p.problem.empty()) passProblems.push_back(p.problem);
            mergeReader(&r, src, rd.warnings, passProblems, rd.ok ? std::string() : rd.error);
        }
        conclude(&r);
    } catch (const std::exception& e) {
        r = CrdCheckResult();
        r.path = source;
        r.error = src + ": internal error: " + e.what();
    }
    return r;
}

CrdCheckResult checkCrd(const std::string& path, const CrdCheckParams& params, const Feedback* feedback) {
    CrdCheckResult r;
    r.path = path;
    const std::string src = path.empty() ? "crd" : path;
    try {
        if (std::string e = validate(params); !e.empty()) {
            r.error = std::move(e);
            return r;
        }
        LineReader lr;
        if (!lr.open(path)) {
            r.error = lr.error();
            return r;
        }
        Checker c(src, params, &r);
        std::string_view line;
        while (lr.next(&line)) {
            if ((lr.lineNumber() & 0x3fff) == 0 && feedback) {
                if (feedback->isCancelled()) {
                    r = CrdCheckResult();
                    r.path = path;
                    r.error = src + ": cancelled";
                    return r;
                }
                feedback->setProgress(0.5 * lr.fraction());
            }
            c.line(line, lr.lineNumber());
        }
        if (!lr.error().empty()) {
            // A NUL byte or an endless line: the text ends there (said as the problem of its line).
            std::string rest;
            const long at = splitWhere(lr.error(), src, &rest);
            if (at == 0 && lr.lineNumber() == 0 && rest.find("NUL") == std::string::npos) {
                r.error = lr.error();  // (could not be read at all)
                return r;
            }
            c.stop();
            r.lines = std::max(r.lines, at);
            r.problems.push_back({at, "", kE, "text", rest + "; not checked further", 1});
            ++r.errors;
            conclude(&r);
            return r;
        }
        const bool lastHadLineEnd = lr.lineNumber() == 0 || endsWithLineEnd(path);
        c.finish(lr.lineNumber(), lastHadLineEnd);
        if (params.readerMessages && r.lines > 0) {
            std::vector<std::string> passProblems;
            const CrdStreamResult sr = streamCrd(
                path, readerParams(), nullptr, [](size_t) { return true; },
                [&](CrdPass&& p) {
                    if (!p.problem.empty()) passProblems.push_back(p.problem);
                    if (feedback) feedback->setProgress(0.75);
                    return !cancelled(feedback);
                });
            if (cancelled(feedback)) {
                r = CrdCheckResult();
                r.path = path;
                r.error = src + ": cancelled";
                return r;
            }
            mergeReader(&r, src, sr.warnings, passProblems, sr.ok ? std::string() : sr.error);
        }
        conclude(&r);
        if (feedback) feedback->setProgress(1.0);
    } catch (const std::bad_alloc&) {
        r = CrdCheckResult();
        r.path = path;
        r.error = src + ": out of memory";
    } catch (const std::exception& e) {
        r = CrdCheckResult();
        r.path = path;
        r.error = src + ": internal error: " + e.what();
    }
    return r;
}

std::string formatCrdProblem(const std::string& source, const CrdProblem& p) {
    const std::string src = source.empty() ? "crd" : source;
    return src + (p.line > 0 ? ":" + std::to_string(p.line) : std::string()) + ": " + severityName(p.severity) + " " + p.rule +
           ": " + p.message;
}

std::string crdCheckSummary(const CrdCheckResult& r, const std::string& source) {
    const std::string src = source.empty() ? "crd" : source;
    if (!r.ok) return src + ": not checked: " + r.error;
    size_t records = 0;
    for (const auto& p : r.passes) records += p.records;
    std::string s = src + ": ";
    if (r.errors == 0 && r.warnings == 0) s += "clean";
    else
        s += std::to_string(r.errors) + " error" + (r.errors == 1 ? "" : "s") + ", " + std::to_string(r.warnings) +
             " warning" + (r.warnings == 1 ? "" : "s");
    s += " (" + std::to_string(r.passes.size()) + " session" + (r.passes.size() == 1 ? "" : "s") + ", " +
         std::to_string(records) + " records, " + std::to_string(r.lines) + " lines" +
         (r.version >= 0 ? ", CRD v" + std::to_string(r.version) : std::string()) + ")";
    return s;
}

}  // namespace lwb::core::slr
