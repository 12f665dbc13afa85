#include "core/slr/crd.hpp"

#include <array>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>

#include <sys/stat.h>

#include "core/common/atomic_file.hpp"
#include "core/common/line_reader.hpp"
#include "core/common/text.hpp"
#include "core/slr/slr_time.hpp"

namespace lwb::core::slr {

namespace {

constexpr size_t kMaxTokens = 48;

/// Blank-separated fields of one line, without allocating.
struct Fields {
    std::string_view f[kMaxTokens];
    size_t n = 0;
    explicit Fields(std::string_view s) {
        size_t i = 0;
        while (i < s.size() && n < kMaxTokens) {
            while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
            if (i >= s.size()) break;
            size_t j = i;
            while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
            f[n++] = s.substr(i, j - i);
            i = j;
        }
    }
};

enum class Need { Required, Optional };

/// Field i (1 = first after the record id) as a finite double. Missing or "na" gives NaN,
/// which is an error only when required. *why describes the problem.
bool numberField(const Fields& fs, size_t i, const char* name, Need need, double* out, std::string* why) {
    if (i >= fs.n || isCrdNa(fs.f[i])) {
        if (need == Need::Required) {
            *why = "field " + std::to_string(i) + " (" + name + ") is " + (i >= fs.n ? "missing" : "\"na\"");
            return false;
        }
        *out = NAN;
        return true;
    }
    if (!parseFortranDouble(fs.f[i], out)) {
        *why = "field " + std::to_string(i) + " (" + name + ") is not a finite number: \"" + printableExcerpt(fs.f[i]) + "\"";
        return false;
    }
    return true;
}

/// Field i as an integer (a whole-valued decimal such as "2." is accepted). Missing or "na"
/// gives kCrdAbsent, an error only when required.
bool intField(const Fields& fs, size_t i, const char* name, Need need, long* out, std::string* why) {
    if (i >= fs.n || isCrdNa(fs.f[i])) {
        if (need == Need::Required) {
            *why = "field " + std::to_string(i) + " (" + name + ") is " + (i >= fs.n ? "missing" : "\"na\"");
            return false;
        }
        *out = kCrdAbsent;
        return true;
    }
    long long v = 0;
    if (parseLong(fs.f[i], &v) && v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max()) {
        *out = static_cast<long>(v);
        return true;
    }
    double d = 0;
    if (parseFortranDouble(fs.f[i], &d) && d == std::floor(d) && std::fabs(d) < 2e9) {
        *out = static_cast<long>(d);
        return true;
    }
    *why = "field " + std::to_string(i) + " (" + name + ") is not an integer: \"" + printableExcerpt(fs.f[i]) + "\"";
    return false;
}

bool intField(const Fields& fs, size_t i, const char* name, Need need, int* out, std::string* why) {
    long v = 0;
    if (!intField(fs, i, name, need, &v, why)) return false;
    *out = static_cast<int>(v);
    return true;
}

bool stringField(const Fields& fs, size_t i, const char* name, std::string* out, std::string* why) {
    if (i >= fs.n) {
        *why = "field " + std::to_string(i) + " (" + name + ") is missing";
        return false;
    }
    *out = std::string(fs.f[i]);
    return true;
}

bool secondsOfDay(const Fields& fs, double* out, std::string* why) {
    if (!numberField(fs, 1, "seconds of day", Need::Required, out, why)) return false;
    if (*out < 0 || *out >= 86401.0) {
        *why = "field 1 (seconds of day) is outside 0..86400: " + printableExcerpt(fs.f[1]);
        return false;
    }
    return true;
}

/// Record ids of CRD v1/v2: h1..h9, c0..c7, 00, the data records and 90..99 (user defined).
bool idIsValid(std::string_view id) {
    if (id.size() != 2) return false;
    if (id[0] == 'h') return id[1] >= '1' && id[1] <= '9';
    if (id[0] == 'c') return id[1] >= '0' && id[1] <= '7';
    if (id[0] == '9') return std::isdigit(static_cast<unsigned char>(id[1])) != 0;
    static const char* kData[] = {"00", "10", "11", "12", "20", "21", "30", "40", "41", "42", "50", "60"};
    for (const char* k : kData)
        if (id == k) return true;
    return false;
}

/// Start and end of blank-separated token k of a line (npos when absent).
bool tokenSpan(std::string_view s, size_t k, size_t* b, size_t* e) {
    size_t i = 0, idx = 0;
    while (i < s.size()) {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
        if (i >= s.size()) break;
        size_t j = i;
        while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
        if (idx == k) {
            *b = i;
            *e = j;
            return true;
        }
        ++idx;
        i = j;
    }
    return false;
}

bool replaceToken(std::string* s, size_t k, const std::string& value) {
    size_t b = 0, e = 0;
    if (!tokenSpan(*s, k, &b, &e)) return false;
    s->replace(b, e - b, value);
    return true;
}

/// Collects warnings with a cap.
struct Sink {
    std::vector<std::string>* out;
    size_t max;
    size_t dropped = 0;
    void add(std::string w) {
        if (out->size() < max) out->push_back(std::move(w));
        else ++dropped;
    }
    void close() {
        if (dropped) out->push_back("... and " + std::to_string(dropped) + " more warnings");
        dropped = 0;
    }
};

std::string crdWhere(const std::string& source, long line) {
    return (source.empty() ? std::string("crd") : source) + ":" + std::to_string(line) + ": ";
}

// ---- header records ------------------------------------------------------------------------

/// False (with *fatal) when the H1 names the other ILRS format: a prediction is no ranging data.
bool parseH1(const CrdRecord& r, const std::string& src, CrdFormatHeader* h, Sink* sink, std::string* fatal) {
    const Fields fs(r.text);
    h->text = r.text;
    h->line = r.line;
    h->version = 1;
    std::string why;
    if (fs.n >= 2 && toLower(fs.f[1]) == "cpf") {
        *fatal = "H1 names the format \"" + printableExcerpt(fs.f[1], 8) +
                 "\", not \"CRD\": a CPF prediction, not ranging data (or a damaged header)";
        return false;
    }
    if (fs.n < 3 || toLower(fs.f[1]) != "crd") {
        sink->add(crdWhere(src, r.line) + "H1 does not start with \"CRD <version>\"; read as CRD v1");
        return true;
    }
    int v = 1;
    if (!intField(fs, 2, "format version", Need::Required, &v, &why) || v < 0 || v > 9) {
        sink->add(crdWhere(src, r.line) + "H1 " + (why.empty() ? "format version out of range" : why) + "; read as CRD v1");
        v = 1;
    }
    h->version = v < 1 ? 1 : v;
    int y = 0, m = 0, d = 0, hh = 0;
    if (fs.n >= 7 && intField(fs, 3, "year", Need::Optional, &y, &why) && intField(fs, 4, "month", Need::Optional, &m, &why) &&
        intField(fs, 5, "day", Need::Optional, &d, &why) && intField(fs, 6, "hour", Need::Optional, &hh, &why)) {
        h->year = y;
        h->month = m;
        h->day = d;
        h->hour = hh;
    }
    return true;
}

void parseH2(const CrdRecord& r, const std::string& src, CrdStation* h, Sink* sink) {
    const Fields fs(r.text);
    *h = CrdStation();
    h->text = r.text;
    h->line = r.line;
    if (fs.n < 3) {
        sink->add(crdWhere(src, r.line) + "H2 needs the station name and CDP pad id");
        if (fs.n >= 2) h->name = std::string(fs.f[1]);
        return;
    }
    h->name = std::string(fs.f[1]);
    std::string why;
    int v = kCrdAbsent;
    if (!intField(fs, 2, "CDP pad id", Need::Optional, &v, &why)) sink->add(crdWhere(src, r.line) + "H2 " + why);
    else h->cdpPadId = v;
    if (intField(fs, 3, "CDP system number", Need::Optional, &v, &why)) h->cdpSystem = v;
    if (intField(fs, 4, "CDP occupancy", Need::Optional, &v, &why)) h->cdpOccupancy = v;
    if (intField(fs, 5, "epoch time scale", Need::Optional, &v, &why)) h->timeScale = v;
    if (fs.n > 6) h->network = std::string(fs.f[6]);
}

void parseH3(const CrdRecord& r, const std::string& src, CrdTarget* h, Sink* sink) {
    const Fields fs(r.text);
    *h = CrdTarget();
    h->text = r.text;
    h->line = r.line;
    if (fs.n < 3) {
        sink->add(crdWhere(src, r.line) + "H3 needs the target name and ILRS id");
        if (fs.n >= 2) h->name = std::string(fs.f[1]);
        return;
    }
    h->name = std::string(fs.f[1]);
    h->ilrsId = std::string(fs.f[2]);
    std::string why;
    long l = 0;
    int v = 0;
    if (intField(fs, 3, "SIC", Need::Optional, &l, &why)) h->sic = l;
    if (intField(fs, 4, "NORAD id", Need::Optional, &l, &why)) h->norad = l;
    if (intField(fs, 5, "epoch time scale", Need::Optional, &v, &why)) h->timeScale = v;
    if (intField(fs, 6, "target type", Need::Optional, &v, &why)) h->targetType = v;
    if (intField(fs, 7, "target class", Need::Optional, &v, &why)) h->targetClass = v;
    if (intField(fs, 8, "target location", Need::Optional, &v, &why)) h->targetLocation = v;
}

/// True when the six fields from `first` on are all "unknown" (-1 or na): how some stations write
/// an H4 end date-time they did not fill in.
bool allUnknown(const Fields& fs, size_t first) {
    for (size_t i = first; i < first + 6; ++i) {
        if (i >= fs.n) return false;
        long long v = 0;
        if (!isCrdNa(fs.f[i]) && !(parseLong(fs.f[i], &v) && v == kCrdAbsent)) return false;
    }
    return true;
}

bool validTime(int h, int m, int s) { return h >= 0 && h <= 23 && m >= 0 && m <= 59 && s >= 0 && s <= 60; }

/// H4 is required for the pass epochs: a bad data type or start date-time is an error (the
/// block cannot be a pass). An end date-time written as unknown is accepted with a note; flags
/// outside their ranges are read as unknown with a warning.
bool parseH4(const CrdRecord& r, const std::string& src, CrdSession* h, Sink* sink, std::string* why) {
    const Fields fs(r.text);
    *h = CrdSession();
    h->text = r.text;
    h->line = r.line;
    if (fs.n < 14) {
        *why = "H4 needs the data type and the start and end date-times (13 fields), found " + std::to_string(fs.n - 1);
        return false;
    }
    const bool endUnknown = allUnknown(fs, 8);
    int v[13];
    static const char* kNames[13] = {"data type", "start year", "start month", "start day", "start hour", "start minute",
                                     "start second", "end year", "end month", "end day", "end hour", "end minute",
                                     "end second"};
    for (int i = 0; i < (endUnknown ? 7 : 13); ++i)
        if (!intField(fs, static_cast<size_t>(i + 1), kNames[i], Need::Required, &v[i], why)) {
            *why = "H4 " + *why;
            return false;
        }
    if (endUnknown) std::fill(v + 7, v + 13, kCrdAbsent);
    h->dataType = v[0];
    h->startYear = v[1], h->startMonth = v[2], h->startDay = v[3], h->startHour = v[4], h->startMinute = v[5],
    h->startSecond = v[6];
    h->endYear = v[7], h->endMonth = v[8], h->endDay = v[9], h->endHour = v[10], h->endMinute = v[11], h->endSecond = v[12];
    if (h->dataType < 0 || h->dataType > 2) {
        *why = "H4 data type must be 0 (full rate), 1 (normal point) or 2 (sampled engineering), found " +
               std::to_string(h->dataType);
        return false;
    }
    if (!validDate(h->startYear, h->startMonth, h->startDay) || !validTime(h->startHour, h->startMinute, h->startSecond)) {
        *why = "H4 start date-time is not a valid date and time";
        return false;
    }
    if (endUnknown) {
        sink->add(crdWhere(src, r.line) + "H4 end date-time is not given (-1 or na in all six fields); the pass is read "
                                       "with its end unknown");
    } else if (!validDate(h->endYear, h->endMonth, h->endDay) || !validTime(h->endHour, h->endMinute, h->endSecond)) {
        *why = "H4 end date-time is not a valid date and time";
        return false;
    } else {
        // An end before the start: the header's span cannot be believed (said, not refused: the
        // records carry their own epochs).
        const std::array<double, 6> start{double(h->startYear), double(h->startMonth), double(h->startDay),
                                          double(h->startHour), double(h->startMinute), double(h->startSecond)};
        const std::array<double, 6> end{double(h->endYear), double(h->endMonth), double(h->endDay),
                                        double(h->endHour), double(h->endMinute), double(h->endSecond)};
        if (end < start)
            sink->add(crdWhere(src, r.line) + "H4 end date-time precedes its start date-time: the header's span of the pass is "
                                           "wrong (the records' epochs are used)");
    }
    struct Flag {
        int* field;
        const char* name;
        int max;  // valid 0..max
        const char* meaning;
    };
    const Flag flags[8] = {
        {&h->releaseFlag, "data release flag", 99, "0 first release, 1 first replacement, ..."},
        {&h->refractionApplied, "tropospheric refraction applied indicator", 1, "0 no, 1 yes"},
        {&h->comApplied, "centre-of-mass correction applied indicator", 1, "0 no, 1 yes"},
        {&h->receiveAmpApplied, "receive amplitude correction applied indicator", 1, "0 no, 1 yes"},
        {&h->stationDelayApplied, "station system delay applied indicator", 1, "0 no, 1 yes"},
        {&h->spacecraftDelayApplied, "spacecraft system delay applied indicator", 1, "0 no, 1 yes"},
        {&h->rangeType, "range type indicator", 4, "0 no ranges, 1 one-way, 2 two-way, 3 received only, 4 mixed"},
        {&h->qualityAlert, "data quality alert indicator", 2, "0 good, 1 suspect, 2 poor"}};
    for (int i = 0; i < 8; ++i) {
        int x = kCrdAbsent;
        std::string bad;
        if (!intField(fs, static_cast<size_t>(14 + i), flags[i].name, Need::Optional, &x, &bad)) {
            sink->add(crdWhere(src, r.line) + "H4 " + bad + "; read as unknown");
        } else if (x != kCrdAbsent && (x < 0 || x > flags[i].max)) {
            sink->add(crdWhere(src, r.line) + "H4 field " + std::to_string(14 + i) + " (" + flags[i].name + ") is " +
                      std::to_string(x) + ", outside 0.." + std::to_string(flags[i].max) + " (" + flags[i].meaning +
                      "); read as unknown");
        } else {
            *flags[i].field = x;
        }
    }
    return true;
}

// ---- data records --------------------------------------------------------------------------

bool parseC0(const Fields& fs, CrdSystemConfig* c, std::string* why) {
    if (!intField(fs, 1, "detail type", Need::Required, &c->detailType, why)) return false;
    if (!numberField(fs, 2, "transmit wavelength", Need::Optional, &c->wavelengthNm, why)) return false;
    if (!stringField(fs, 3, "system configuration id", &c->systemId, why)) return false;
    for (size_t i = 4; i < fs.n; ++i) c->componentIds.emplace_back(fs.f[i]);
    return true;
}

bool parse10(const Fields& fs, CrdRange* r, std::string* why) {
    if (!secondsOfDay(fs, &r->secOfDay, why)) return false;
    if (!numberField(fs, 2, "time of flight", Need::Required, &r->tofS, why)) return false;
    if (r->tofS < 0 || r->tofS > 100) {
        *why = "field 2 (time of flight) is outside 0..100 s: " + printableExcerpt(fs.f[2]);
        return false;
    }
    if (!stringField(fs, 3, "system configuration id", &r->configId, why)) return false;
    if (!intField(fs, 4, "epoch event", Need::Required, &r->epochEvent, why)) return false;
    if (r->epochEvent < 0 || r->epochEvent > 6) {
        *why = "field 4 (epoch event) must be 0..6, found " + std::to_string(r->epochEvent);
        return false;
    }
    if (!intField(fs, 5, "filter flag", Need::Required, &r->filterFlag, why)) return false;
    if (r->filterFlag < 0 || r->filterFlag > 2) {
        *why = "field 5 (filter flag) must be 0 (unknown), 1 (noise) or 2 (data), found " + std::to_string(r->filterFlag);
        return false;
    }
    return intField(fs, 6, "detector channel", Need::Optional, &r->detectorChannel, why) &&
           intField(fs, 7, "stop number", Need::Optional, &r->stopNumber, why) &&
           numberField(fs, 8, "receive amplitude", Need::Optional, &r->receiveAmplitude, why) &&
           numberField(fs, 9, "transmit amplitude", Need::Optional, &r->transmitAmplitude, why);
}

bool parse11(const Fields& fs, CrdNormalPoint* r, std::string* why) {
    if (!secondsOfDay(fs, &r->secOfDay, why)) return false;
    if (!numberField(fs, 2, "time of flight", Need::Required, &r->tofS, why)) return false;
    if (r->tofS < 0 || r->tofS > 100) {
        *why = "field 2 (time of flight) is outside 0..100 s: " + printableExcerpt(fs.f[2]);
        return false;
    }
    if (!stringField(fs, 3, "system configuration id", &r->configId, why)) return false;
    if (!intField(fs, 4, "epoch event", Need::Required, &r->epochEvent, why)) return false;
    if (r->epochEvent < 0 || r->epochEvent > 6) {
        *why = "field 4 (epoch event) must be 0..6, found " + std::to_string(r->epochEvent);
        return false;
    }
    r->numRanges = kCrdAbsent;
    r->detectorChannel = kCrdAbsent;
    return numberField(fs, 5, "window length", Need::Optional, &r->windowS, why) &&
           intField(fs, 6, "number of raw ranges", Need::Optional, &r->numRanges, why) &&
           numberField(fs, 7, "bin RMS", Need::Optional, &r->binRmsPs, why) &&
           numberField(fs, 8, "bin skew", Need::Optional, &r->skew, why) &&
           numberField(fs, 9, "bin kurtosis", Need::Optional, &r->kurtosis, why) &&
           numberField(fs, 10, "bin peak-mean", Need::Optional, &r->peakMinusMeanPs, why) &&
           numberField(fs, 11, "return rate", Need::Optional, &r->returnRatePct, why) &&
           intField(fs, 12, "detector channel", Need::Optional, &r->detectorChannel, why) &&
           numberField(fs, 13, "signal to noise", Need::Optional, &r->snr, why);
}

bool parse12(const Fields& fs, CrdRangeSupplement* r, std::string* why) {
    return secondsOfDay(fs, &r->secOfDay, why) && stringField(fs, 2, "system configuration id", &r->configId, why) &&
           numberField(fs, 3, "refraction correction", Need::Optional, &r->refractionPs, why) &&
           numberField(fs, 4, "target CofM correction", Need::Optional, &r->comCorrectionM, why) &&
           numberField(fs, 5, "ND value", Need::Optional, &r->ndValue, why) &&
           numberField(fs, 6, "time bias", Need::Optional, &r->timeBiasS, why) &&
           numberField(fs, 7, "range rate", Need::Optional, &r->rangeRate, why);
}

bool parse20(const Fields& fs, CrdMeteo* r, std::string* why) {
    return secondsOfDay(fs, &r->secOfDay, why) && numberField(fs, 2, "pressure", Need::Required, &r->pressureMbar, why) &&
           numberField(fs, 3, "temperature", Need::Required, &r->temperatureK, why) &&
           numberField(fs, 4, "humidity", Need::Required, &r->humidityPct, why) &&
           intField(fs, 5, "value origin", Need::Optional, &r->origin, why);
}

bool parse30(const Fields& fs, CrdPointing* r, std::string* why) {
    return secondsOfDay(fs, &r->secOfDay, why) && numberField(fs, 2, "azimuth", Need::Required, &r->azimuthDeg, why) &&
           numberField(fs, 3, "elevation", Need::Required, &r->elevationDeg, why) &&
           intField(fs, 4, "direction flag", Need::Optional, &r->directionFlag, why) &&
           intField(fs, 5, "angle origin", Need::Optional, &r->angleOrigin, why) &&
           intField(fs, 6, "refraction corrected", Need::Optional, &r->refractionCorrected, why) &&
           numberField(fs, 7, "azimuth rate", Need::Optional, &r->azimuthRate, why) &&
           numberField(fs, 8, "elevation rate", Need::Optional, &r->elevationRate, why);
}

bool parse40(const Fields& fs, CrdCalibration* r, std::string* why) {
    return secondsOfDay(fs, &r->secOfDay, why) && intField(fs, 2, "type of data", Need::Optional, &r->dataType, why) &&
           stringField(fs, 3, "system configuration id", &r->configId, why) &&
           intField(fs, 4, "points recorded", Need::Optional, &r->pointsRecorded, why) &&
           intField(fs, 5, "points used", Need::Optional, &r->pointsUsed, why) &&
           numberField(fs, 6, "target distance", Need::Optional, &r->targetDistanceM, why) &&
           numberField(fs, 7, "system delay", Need::Optional, &r->systemDelayPs, why) &&
           numberField(fs, 8, "delay shift", Need::Optional, &r->delayShiftPs, why) &&
           numberField(fs, 9, "RMS", Need::Optional, &r->rmsPs, why) &&
           numberField(fs, 10, "skew", Need::Optional, &r->skew, why) &&
           numberField(fs, 11, "kurtosis", Need::Optional, &r->kurtosis, why) &&
           numberField(fs, 12, "peak-mean", Need::Optional, &r->peakMinusMeanPs, why) &&
           intField(fs, 13, "calibration type", Need::Optional, &r->calType, why) &&
           intField(fs, 14, "shift type", Need::Optional, &r->shiftType, why) &&
           intField(fs, 15, "detector channel", Need::Optional, &r->detectorChannel, why) &&
           intField(fs, 16, "calibration span", Need::Optional, &r->span, why) &&
           numberField(fs, 17, "return rate", Need::Optional, &r->returnRatePct, why);
}

/// Parses data record r (index i of the pass) into `list` with `parse`; a record that does not
/// parse is skipped with a warning naming its line. `x` may carry preset fields.
// The record type of a list of parsed records, and erasing one of them.
template <class List> struct ItemOf;
template <class T> struct ItemOf<std::vector<T>> { using type = T; };
template <> struct ItemOf<CrdRanges> { using type = CrdRange; };
template <class T> void eraseAt(std::vector<T>& v, size_t k) { v.erase(v.begin() + static_cast<std::ptrdiff_t>(k)); }
void eraseAt(CrdRanges& v, size_t k) { v.erase(k); }

// A line to parse: a record's or a type-10 line's.
struct CrdLine {
    std::string_view text;
    long line = 0;
    CrdLine(std::string_view t, long l) : text(t), line(l) {}
    CrdLine(const CrdRecord& r) : text(r.text), line(r.line) {}
};

template <class List, class Parse, class Rec = typename ItemOf<List>::type>
void addRecord(Parse parse, const CrdLine& r, size_t i, const std::string& src, Sink* sink, const char* what,
               List& list, std::vector<long>& skipped, Rec x = Rec{}) {
    std::string why;
    if (!parse(Fields(r.text), &x, &why)) {
        sink->add(crdWhere(src, r.line) + what + " record skipped: " + why);
        skipped.push_back(r.line);
        return;
    }
    x.record = i;
    x.line = r.line;
    list.push_back(std::move(x));
}

void clearParsed(CrdPass* p) {
    p->configs.clear();
    p->ranges.clear();
    p->normalPoints.clear();
    p->supplements.clear();
    p->meteo.clear();
    p->pointing.clear();
    p->calibrations.clear();
    p->skippedLines.clear();
    p->predictionHeader.clear();
}

/// Fills the parsed lists of a pass from its records. Header values present in the records
/// override the inherited ones already in the pass. False (with *error, the lists left empty)
/// when the H4 is bad.
bool parsePassRecords(CrdPass* p, const std::string& src, Sink* sink, std::string* error, std::string_view fileBytes = {}) {
    clearParsed(p);
    p->problem.clear();
    // H1..H3 were read (and warned about) when the file was split into passes.
    std::vector<std::string> again;
    Sink quiet{&again, 0};
    bool sawH4 = false;
    // (the ranges allocated once: a pass of 10^6 ranges held up to 1.5 copies of its ranges while
    // the vector doubled)
    const CrdRangeLines& lines = p->rangeLines;
    p->ranges.reserve(lines.size());
    size_t k = 0;  // the type-10 lines, each parsed where it stands among the records
    CrdRangeLines::Reader rd(lines, fileBytes);
    std::string_view text;
    auto rangesBefore = [&](size_t slot) {
        for (; k < lines.size() && lines.slot(k) <= slot; ++k) {
            if (!rd.next(&text)) return false;
            addRecord(parse10, CrdLine{text, lines.line(k)}, k, src, sink, "type 10", p->ranges, p->skippedLines);
        }
        return true;
    };
    for (size_t i = 0; i <= p->records.size(); ++i) {
        if (!rangesBefore(i)) {
            *error = rd.error();
            clearParsed(p);
            return false;
        }
        if (i == p->records.size()) break;
        const CrdRecord& r = p->records[i];
        const std::string& id = r.id;
        if (id.empty() || id == "00" || id[0] == '9') continue;
        std::string why;
        if (id == "h1") {
            parseH1(r, src, &p->format, &quiet, &why);
        } else if (id == "h2") {
            parseH2(r, src, &p->station, &quiet);
        } else if (id == "h3") {
            parseH3(r, src, &p->target, &quiet);
        } else if (id == "h4") {
            if (!parseH4(r, src, &p->session, sink, &why)) {
                *error = crdWhere(src, r.line) + why;
                clearParsed(p);
                return false;
            }
            sawH4 = true;
        } else if (id == "h5") {
            p->predictionHeader = r.text;
        } else if (id == "c0") {
            addRecord(parseC0, r, i, src, sink, "C0", p->configs, p->skippedLines);
        } else if (id == "11") {
            addRecord(parse11, r, i, src, sink, "type 11", p->normalPoints, p->skippedLines);
        } else if (id == "12") {
            addRecord(parse12, r, i, src, sink, "type 12", p->supplements, p->skippedLines);
        } else if (id == "20") {
            addRecord(parse20, r, i, src, sink, "type 20", p->meteo, p->skippedLines);
        } else if (id == "30") {
            addRecord(parse30, r, i, src, sink, "type 30", p->pointing, p->skippedLines);
        } else if (id == "40" || id == "41") {
            CrdCalibration x;
            x.detail = id == "41";
            addRecord(parse40, r, i, src, sink, id == "41" ? "type 41" : "type 40", p->calibrations, p->skippedLines, std::move(x));
        }
    }
    if (!sawH4) {
        *error = crdWhere(src, p->records.empty() ? 0 : p->records.front().line) + "pass without an H4 session header";
        return false;
    }
    // 86 400 s and beyond is 23:59:60, a leap second: only on a day that ends with one. On another
    // day such a record is damaged (86400.5 s was taken as 0.5 s into the next day: a residual of
    // half an hour on a pass of the afternoon).
    const long day = p->startMjd();
    auto noLeap = [&](auto& list, const char* what) {
        for (size_t k = 0; k < list.size();) {
            const double sod = list[k].secOfDay;
            const long recDay = sod < p->session.startHour * 3600.0 - 43200.0 ? day + 1 : day;
            if (sod >= kSecondsPerDay && !leapSecondAtEndOf(recDay)) {
                int y = 0, mo = 0, d = 0;
                dateFromMjd(recDay, &y, &mo, &d);
                char date[16];
                std::snprintf(date, sizeof date, "%04d-%02d-%02d", y, mo, d);
                sink->add(crdWhere(src, list[k].line) + what + " record skipped: seconds of day " + formatFixed(sod, 6) +
                          " is 23:59:60, a leap second, but " + date + " ends without one");
                p->skippedLines.push_back(list[k].line);
                eraseAt(list, k);
                continue;
            }
            ++k;
        }
    };
    noLeap(p->ranges, "type 10");
    noLeap(p->normalPoints, "type 11");
    // A pass across the end of a leap-second day: epochs are UTC labels, 23:59:60 is not
    // counted, so in elapsed time the records after midnight are a second early.
    if (leapSecondAtEndOf(day)) {
        bool before = false, after = false;
        for (const auto& r : p->ranges) (r.secOfDay < p->session.startHour * 3600.0 - 43200.0 ? after : before) = true;
        if (before && after) {
            int y = 0, mo = 0, d = 0;
            dateFromMjd(day, &y, &mo, &d);
            char date[16];
            std::snprintf(date, sizeof date, "%04d-%02d-%02d", y, mo, d);
            sink->add(crdWhere(src, p->records.empty() ? 0 : p->records.front().line) + "the pass crosses the leap second " +
                      date + " 23:59:60: its epochs are UTC labels (as a CPF's), the records after midnight are 1 s "
                      "later in elapsed time than their labels say; O-C against the pass's own TOF trend steps by its "
                      "range rate x 1 s there (give a CPF prediction for this pass)");
        }
    }
    return true;
}

// The lines from an H4 to the next one (or the end), and their bytes (without line ends).
struct LinesAfterH4 {
    size_t lines = 0, bytes = 0;  // (of the type-10 lines: what CrdRangeLines holds)
    void count(std::string_view line) {
        size_t q = 0;
        while (q < line.size() && (line[q] == ' ' || line[q] == '\t' || line[q] == '\r')) ++q;
        if (line.substr(q, 2) != "10" || (line.size() > q + 2 && line[q + 2] != ' ' && line[q + 2] != '\t' && line[q + 2] != '\r'))
            return;
        ++lines;
        bytes += line.size();
    }
};

// parseCrd, stage 1: the records grouped into passes. A pass opens at H4 with the H1/H2/H3 in
// force and closes at H8 (or, with a warning, at the next header or at the end of the file);
// comments, blank lines and user records outside a pass go with what follows.
class PassSplitter {
public:
    PassSplitter(const std::string& src, Sink* sink, CrdFile* file) : src_(src), sink_(sink), file_(file) {}

    // One record; false (and *error) when the file cannot be read as CRD from here.
    bool add(CrdRecord rec, const Fields& fs, std::string* error, long long fileOffset = -1) {
        const std::string& id = rec.id;
        const long lineNo = rec.line;
        if (id.empty() || id == "00") {  // blank or comment: belongs to whatever is open
            current().push_back(std::move(rec));
            return true;
        }
        if (!idIsValid(id)) {
            if (!open_ && !haveH1_) {
                *error = crdWhere(src_, lineNo) + "not a CRD record: \"" + printableExcerpt(rec.text) + "\" (expected H1)";
                return false;
            }
            sink_->add(crdWhere(src_, lineNo) + "unknown record type \"" + printableExcerpt(fs.f[0], 8) + "\"; kept, not interpreted");
            current().push_back(std::move(rec));
            return true;
        }
        if (id == "h1" || id == "h2" || id == "h3") return formatHeader(std::move(rec), error);
        if (id == "h4") return openPass(std::move(rec), error);
        if (id == "h8") {
            if (!open_) {
                sink_->add(crdWhere(src_, lineNo) + "H8 without an open pass; kept");
                pending_.push_back(std::move(rec));
                return true;
            }
            open_->records.push_back(std::move(rec));
            open_->endedWithH8 = true;
            close("", lineNo);
            return true;
        }
        if (id == "h9") {
            close("pass ended without H8 (H9)", lineNo);
            pending_.push_back(std::move(rec));
            return true;
        }
        if (id[0] == 'h') {  // h5 (prediction header), h6/h7 (not defined): part of the pass or the next one
            current().push_back(std::move(rec));
            return true;
        }
        // Configuration, data and user records.
        if (!open_) {
            if (id[0] == '9') {  // user records outside a pass: keep with what follows
                pending_.push_back(std::move(rec));
                return true;
            }
            *error = crdWhere(src_, lineNo) + "record " + std::string(fs.f[0]) + " " +
                     (haveH1_ ? "outside a pass (no H4 session header before it)"
                              : "before the H1 format header (not a CRD file, or its header is missing)");
            return false;
        }
        if (id == "10") open_->rangeLines.add(rec.text, rec.line, open_->records.size(), fileOffset);
        else open_->records.push_back(std::move(rec));
        return true;
    }

    // At the end of the text: the open pass closes with a warning, what is left is the trailer.
    void finish(long lastLine) {
        close("file ends without H8 for the last pass", lastLine);
        file_->trailer = std::move(pending_);
    }

private:
    std::vector<CrdRecord>& current() { return open_ ? open_->records : pending_; }

    void close(const std::string& why, long atLine) {
        if (!open_) return;
        if (!why.empty()) sink_->add(crdWhere(src_, atLine) + why);
        open_ = nullptr;
    }

    bool formatHeader(CrdRecord rec, std::string* error) {
        const std::string& id = rec.id;
        close("pass ended without H8 (new H" + id.substr(1) + ")", rec.line);
        if (id == "h1") {
            std::string why;
            if (!parseH1(rec, src_, &h1_, sink_, &why)) {
                *error = crdWhere(src_, rec.line) + why;
                return false;
            }
            haveH1_ = true;
        } else if (id == "h2") {
            parseH2(rec, src_, &h2_, sink_);
            haveH2_ = true;
        } else {
            parseH3(rec, src_, &h3_, sink_);
            haveH3_ = true;
        }
        own_[id[1] - '1'] = true;
        pending_.push_back(std::move(rec));
        return true;
    }

    bool openPass(CrdRecord rec, std::string* error) {
        close("pass ended without H8 (new H4)", rec.line);
        if (!haveH1_) {
            *error = crdWhere(src_, rec.line) + "H4 before any H1 format header";
            return false;
        }
        if (!haveH2_ || !haveH3_) {
            *error = crdWhere(src_, rec.line) + "H4 before the " + std::string(!haveH2_ ? "H2 station" : "H3 target") + " header";
            return false;
        }
        file_->passes.emplace_back();
        open_ = &file_->passes.back();
        open_->format = h1_;
        open_->station = h2_;
        open_->target = h3_;
        open_->inheritsHeaders = !(own_[0] && own_[1] && own_[2]);
        own_[0] = own_[1] = own_[2] = false;
        open_->records = std::move(pending_);
        pending_.clear();
        if (origin_) open_->rangeLines.placesOnly(origin_);
        else if (opened_ < linesAfterH4_.size()) open_->rangeLines.reserve(linesAfterH4_[opened_].lines, linesAfterH4_[opened_].bytes);
        open_->ordinal = ++opened_;
        open_->records.push_back(std::move(rec));
        return true;
    }

public:
    /// The passes that have closed, moved out of the file (the open one stays): a reader that
    /// hands passes out one by one holds one at a time.
    std::vector<CrdPass> takeClosed() {
        std::vector<CrdPass> out;
        std::vector<CrdPass>& v = file_->passes;
        const size_t closed = open_ ? v.size() - 1 : v.size();
        if (closed == 0) return out;
        out.reserve(closed);
        for (size_t i = 0; i < closed; ++i) out.push_back(std::move(v[i]));
        v.erase(v.begin(), v.begin() + static_cast<long>(closed));
        if (open_) open_ = &v.back();
        return out;
    }

    /// The file the lines are read from, when they are its own bytes at the offsets given: the
    /// passes keep their type-10 lines' places in it, not their texts (CrdRangeLines::placesOnly).
    void setOrigin(std::shared_ptr<const CrdFileOrigin> origin) { origin_ = std::move(origin); }

    /// A type-10 line of the open pass (the only record kept by place, not as a CrdRecord);
    /// false when no pass is open (the caller gives it to add(), which says what is wrong).
    bool addRange(std::string_view text, long line, long long fileOffset) {
        if (!open_) return false;
        open_->rangeLines.add(text, line, open_->records.size(), fileOffset);
        return true;
    }

    /// Capacity hints: the lines (and their bytes) from each H4 to the next (countLinesAfterH4),
    /// so that a pass's type-10 lines are allocated once instead of doubling (a 3·10^6-record
    /// pass held 1.5 copies).
    void setCapacityHints(std::vector<LinesAfterH4> linesAfterH4) { linesAfterH4_ = std::move(linesAfterH4); }

private:
    std::vector<LinesAfterH4> linesAfterH4_;
    size_t opened_ = 0;
    std::shared_ptr<const CrdFileOrigin> origin_;

    const std::string& src_;
    Sink* sink_;
    CrdFile* file_;
    CrdFormatHeader h1_;
    CrdStation h2_;
    CrdTarget h3_;
    bool haveH1_ = false, haveH2_ = false, haveH3_ = false;
    bool own_[3] = {false, false, false};  // H1/H2/H3 seen since the last pass
    std::vector<CrdRecord> pending_;       // records since the last pass closed
    CrdPass* open_ = nullptr;
};

// Whether a line is an H4 record (the start of a pass).
// (blanks as the reader's Fields takes them: spaces, tabs and CRs, so that a line of an LF-CR
// text, which starts with the CR, is counted as the reader reads it)
bool isH4Line(std::string_view line) {
    size_t q = 0;
    while (q < line.size() && (line[q] == ' ' || line[q] == '\t' || line[q] == '\r')) ++q;
    return q + 1 < line.size() && (line[q] == 'h' || line[q] == 'H') && line[q + 1] == '4' &&
           (q + 2 == line.size() || line[q + 2] == ' ' || line[q + 2] == '\t' || line[q + 2] == '\r');
}

// The number of lines from each line that starts an H4 record to the next such line (or the end).
std::vector<LinesAfterH4> countLinesAfterH4(std::string_view text) {
    std::vector<LinesAfterH4> counts;
    size_t pos = 0;
    while (pos < text.size()) {
        const size_t end = text.find('\n', pos);
        const std::string_view line = text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
        if (isH4Line(line)) counts.emplace_back();
        if (!counts.empty()) counts.back().count(line);
        pos = end == std::string_view::npos ? text.size() : end + 1;
    }
    return counts;
}

// One line of the text (without its LF) as a record through the splitter. Every trailing CR goes
// (so a text never ends with one and LF/CRLF writing is unambiguous).
// fileOffset: where the line starts in its file (-1: not a plain file's line).
bool feedLine(PassSplitter& splitter, std::string_view line, long lineNo, CrdReadResult* res, long long fileOffset = -1) {
    if (!line.empty() && line.back() == '\r' && lineNo == 1) res->file.crlf = true;
    while (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const Fields fs(line);
    // A range record of the open pass, most of a kHz pass's lines: kept without a CrdRecord's
    // strings (an allocation of its text each).
    if (fs.n && fs.f[0] == "10" && splitter.addRange(line, lineNo, fileOffset)) return true;
    CrdRecord rec;
    rec.text = std::string(line);
    rec.line = lineNo;
    rec.id = fs.n ? toLower(fs.f[0]) : std::string();
    return splitter.add(std::move(rec), fs, &res->error, fileOffset);
}

// Stage 1: the text's lines through the splitter (progress: the first half). False with
// res->error on a line that cannot be CRD, on cancel, or without any pass.
// fileStart: where the file's first byte is when `text` is a plain file's content (the lines'
// offsets in the file are their distance from it), else nullptr.
bool splitPasses(std::string_view text, const std::string& src, const Feedback* feedback, Sink* sink, CrdReadResult* res,
                 const char* fileStart, const std::shared_ptr<const CrdFileOrigin>& origin) {
    PassSplitter splitter(src, sink, &res->file);
    if (fileStart && origin) splitter.setOrigin(origin);
    else splitter.setCapacityHints(countLinesAfterH4(text));
    size_t pos = 0;
    long lineNo = 0;
    while (pos < text.size()) {
        if ((lineNo & 0x3fff) == 0 && feedback) {
            if (feedback->isCancelled()) {
                res->error = src + ": cancelled";
                return false;
            }
            feedback->setProgress(0.5 * static_cast<double>(pos) / static_cast<double>(text.size()));
        }
        size_t end = text.find('\n', pos);
        const bool hadNewline = end != std::string_view::npos;
        if (!hadNewline) end = text.size();
        const std::string_view line = text.substr(pos, end - pos);
        pos = hadNewline ? end + 1 : end;
        if (!feedLine(splitter, line, ++lineNo, res, fileStart ? static_cast<long long>(line.data() - fileStart) : -1))
            return false;
    }
    splitter.finish(lineNo);
    if (res->file.passes.empty()) {
        res->error = src + ": no CRD pass (no H4 session header) in " + std::to_string(lineNo) + " lines";
        return false;
    }
    return true;
}

// A pass's records parsed; a pass that cannot be read, or has no range record, gets its problem.
void parseOnePass(CrdPass& p, size_t k, const std::string& src, Sink* sink, std::string_view fileBytes = {}) {
    std::string err;
    if (!parsePassRecords(&p, src, sink, &err, fileBytes)) {
        p.problem = err;
    } else if (p.ranges.empty() && p.normalPoints.empty()) {
        p.problem = crdWhere(src, p.session.line) + "pass " + std::to_string(k + 1) + " (" + p.station.name + ", " +
                    p.target.name + ") has no readable range record (type 10 or 11)";
        clearParsed(&p);
    }
}

// Stage 2: the records of each pass parsed; a pass that cannot be read, or has no range record,
// gets its problem (progress: the second half). False on cancel.
bool parsePasses(const std::string& src, const Feedback* feedback, Sink* sink, CrdReadResult* res, std::string_view fileBytes) {
    std::vector<CrdPass>& passes = res->file.passes;
    for (size_t k = 0; k < passes.size(); ++k) {
        if (cancelled(feedback)) {
            res->error = src + ": cancelled";
            return false;
        }
        parseOnePass(passes[k], k, src, sink, fileBytes);
        if (feedback) feedback->setProgress(0.5 + 0.5 * static_cast<double>(k + 1) / static_cast<double>(passes.size()));
    }
    return true;
}

// Stage 3: a block that cannot be a pass does not cost the file its other passes: it is kept (for
// writing back) and named in a warning. False (res->error) when no pass is usable.
bool setAsideUnusablePasses(Sink* sink, CrdReadResult* res) {
    const std::vector<CrdPass>& passes = res->file.passes;
    size_t unusable = 0;
    const CrdPass* firstBad = nullptr;
    for (const CrdPass& p : passes) {
        if (p.problem.empty()) continue;
        if (!firstBad) firstBad = &p;
        ++unusable;
    }
    if (unusable == passes.size()) {
        res->error = firstBad->problem;
        if (unusable > 1)
            res->error += " (and the file's " + std::to_string(unusable - 1) + " other pass" +
                          (unusable > 2 ? "es cannot" : " cannot") + " be used either)";
        return false;
    }
    for (size_t k = 0; k < passes.size(); ++k)
        if (!passes[k].problem.empty())
            sink->add(passes[k].problem + "; pass " + std::to_string(k + 1) +
                      " skipped (its lines are kept as they are), the file's other passes are read");
    return true;
}

}  // namespace

// ---- CrdPass ---------------------------------------------------------------------------------

void CrdRanges::reserve(size_t n) {
    for (auto* v : {&m_sod, &m_tof}) v->reserve(n);
    for (auto* v : {&m_event, &m_flag}) v->reserve(n);
}

void CrdRanges::clear() {
    *this = CrdRanges();
}

CrdRange CrdRanges::operator[](size_t i) const {
    CrdRange r;
    r.secOfDay = m_sod[i];
    r.tofS = m_tof[i];
    r.configId = m_configIds[m_config.at(i)];
    r.epochEvent = m_event[i];
    r.filterFlag = m_flag[i];
    r.detectorChannel = m_channel.at(i);
    r.stopNumber = m_stop.at(i);
    r.receiveAmplitude = m_rxAmp.at(i);
    r.transmitAmplitude = m_txAmp.at(i);
    r.record = m_record.at(i);
    r.line = static_cast<long>(m_line.at(i));
    return r;
}

void CrdRanges::push_back(const CrdRange& r) {
    const size_t n = size();
    m_sod.push_back(r.secOfDay);
    m_tof.push_back(r.tofS);
    // (a pass has a few configuration ids; the last one used is the likeliest)
    uint32_t id = 0;
    if (n > 0 && m_configIds[m_lastConfig] == r.configId) {
        id = m_lastConfig;
    } else {
        while (id < m_configIds.size() && m_configIds[id] != r.configId) ++id;
        if (id == m_configIds.size()) m_configIds.push_back(r.configId);
    }
    m_config.push(id, n);
    m_lastConfig = id;
    m_event.push_back(static_cast<int8_t>(r.epochEvent));  // (0..6, checked by the reader)
    m_flag.push_back(static_cast<int8_t>(r.filterFlag));   // (0..2)
    m_channel.push(r.detectorChannel, n);
    m_stop.push(r.stopNumber, n);
    m_rxAmp.push(r.receiveAmplitude, n);
    m_txAmp.push(r.transmitAmplitude, n);
    // (a record index or line beyond 2^32 would be a file of hundreds of GB: refused before it
    // is read, inputMemoryProblem)
    m_record.push(static_cast<uint32_t>(r.record));
    m_line.push(static_cast<uint32_t>(r.line));
}

void CrdRanges::erase(size_t i) {
    auto at = [i](auto& v) { v.erase(v.begin() + static_cast<std::ptrdiff_t>(i)); };
    at(m_sod), at(m_tof), at(m_event), at(m_flag);
    m_record.erase(i), m_line.erase(i);
    m_config.erase(i), m_channel.erase(i), m_stop.erase(i), m_rxAmp.erase(i), m_txAmp.erase(i);
}

size_t CrdRanges::bytes() const {
    size_t b = (m_sod.capacity() + m_tof.capacity()) * sizeof(double) +
               m_record.bytes() + m_line.bytes() + m_event.capacity() + m_flag.capacity() +
               m_config.bytes() + m_channel.bytes() + m_stop.bytes() + m_rxAmp.bytes() + m_txAmp.bytes();
    for (const auto& s : m_configIds) b += sizeof(s) + s.capacity();
    return b;
}

// ---- CrdRangeLines ---------------------------------------------------------------------------

size_t CrdRangeLines::runOf(size_t k) const {
    // (the last run whose first line is at or before k)
    const auto it = std::upper_bound(m_runs.begin(), m_runs.end(), k, [](size_t v, const Run& r) { return v < r.first; });
    return static_cast<size_t>(it - m_runs.begin()) - 1;
}

std::string_view CrdRangeLines::text(size_t k) const {
    if (m_origin) return {};
    const size_t b = m_runs[runOf(k)].base + m_start[k];
    const size_t e = k + 1 < m_start.size() ? m_runs[runOf(k + 1)].base + m_start[k + 1] : m_text.size();
    return std::string_view(m_text).substr(b, e - b);
}

long CrdRangeLines::line(size_t k) const {
    const Run& r = m_runs[runOf(k)];
    return r.firstLine + static_cast<long>(k - r.first);
}

size_t CrdRangeLines::slot(size_t k) const { return m_runs[runOf(k)].slot; }

void CrdRangeLines::add(std::string_view text, long line, size_t slot, long long fileOffset) {
    // A line that is not the file's own bytes (a reader that finds the file's lines end in CR
    // only says so at its first line): the lines so far read back, and the texts kept from here.
    if (m_origin && fileOffset < 0 && m_allInFile) {
        std::string ignored;  // (a file changed meanwhile: the Reader says so when the pass is parsed)
        if (!load(&ignored)) m_allInFile = false;
    }
    const size_t k = m_size;
    if (m_origin) {  // places only: a line is added after the others where it follows them in the file
        if (!m_allInFile) return;
        if (m_runs.empty() || m_runs.back().slot != slot || this->line(k - 1) + 1 != line)
            m_runs.push_back(Run{k, slot, line, 0, fileOffset, fileOffset});
        m_runs.back().fileEnd = fileOffset + static_cast<long long>(text.size());
        ++m_size;
        return;
    }
    const size_t at = m_text.size();
    // A new run where the line is not the next one of the last run, or its offset would not fit
    // in 32 bits.
    if (m_runs.empty() || m_runs.back().slot != slot || this->line(k - 1) + 1 != line ||
        at - m_runs.back().base > UINT32_MAX)
        m_runs.push_back(Run{k, slot, line, at, fileOffset, fileOffset});
    Run& run = m_runs.back();
    m_allInFile = m_allInFile && fileOffset >= 0 && run.fileBegin >= 0;
    run.fileEnd = fileOffset >= 0 ? fileOffset + static_cast<long long>(text.size()) : -1;
    m_start.push_back(static_cast<uint32_t>(at - run.base));
    m_text.append(text);
    ++m_size;
}

void CrdRangeLines::reserve(size_t lines, size_t bytes) {
    if (m_origin) return;
    m_start.reserve(lines);
    m_text.reserve(bytes);
}

void CrdRangeLines::placesOnly(const std::shared_ptr<const CrdFileOrigin>& origin) {
    if (!origin || m_size != 0) return;
    m_origin = origin;
}

void CrdRangeLines::keepInFile(const std::shared_ptr<const CrdFileOrigin>& origin) {
    if (!origin || m_origin || !m_allInFile || m_size == 0) return;
    std::string().swap(m_text);
    std::vector<uint32_t>().swap(m_start);
    m_origin = origin;
}

namespace {
// The file as it is now, to compare with what it was when read.
bool sameAsRead(const CrdFileOrigin& o, std::string* error) {
    struct stat st {};
    if (::stat(o.openPath.c_str(), &st) != 0) {
        *error = o.path + ": cannot read the file's type-10 records again (" + std::strerror(errno) +
                 "): it was read from there and its records are written from it; open it again";
        return false;
    }
    const long long mtime = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
    if (static_cast<long long>(st.st_size) != o.size || mtime != o.mtimeNs || st.st_ino != o.inode ||
        st.st_dev != o.device) {
        *error = o.path + ": the file changed since it was read; its type-10 records are written from it, so "
                          "nothing is written: open it again";
        return false;
    }
    return true;
}
}  // namespace

namespace {
// The file at `path` as it is (nullptr for the standard input, or what is not a regular file).
std::shared_ptr<const CrdFileOrigin> crdFileOrigin(const std::string& path) {
    struct stat st {};
    if (path.empty() || isStandardStream(path) || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return nullptr;
    {  // (a gzip file's lines are not at offsets of the file)
        std::ifstream in(path, std::ios::binary);
        char magic[2] = {0, 0};
        in.read(magic, 2);
        if (!in || (static_cast<unsigned char>(magic[0]) == 0x1f && static_cast<unsigned char>(magic[1]) == 0x8b))
            return nullptr;
    }
    auto o = std::make_shared<CrdFileOrigin>();
    o->path = path;
    // (opened again by its absolute name: the working folder may change before the lines are read)
    if (char* abs = ::realpath(path.c_str(), nullptr)) {
        o->openPath = abs;
        std::free(abs);
    } else {
        o->openPath = path;
    }
    o->size = static_cast<long long>(st.st_size);
    o->mtimeNs = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
    o->inode = st.st_ino;
    o->device = st.st_dev;
    return o;
}
}  // namespace

struct CrdRangeLines::Reader::File {
    std::ifstream in;
    std::string buf;
    std::string_view mem;   // the file's bytes as read (then no stream)
    std::string_view span;  // the current run's bytes at hand: in buf, or in mem
    size_t pos = 0;
    long long left = 0;  // bytes of the run not read yet
};

CrdRangeLines::Reader::Reader(const CrdRangeLines& lines, std::string_view fileBytes) : m_lines(lines) {
    if (!lines.m_origin || lines.m_size == 0) return;
    if (!lines.m_allInFile) {
        m_error = lines.m_origin->path + ": the file changed while it was read: open it again";
        return;
    }
    if (!fileBytes.empty()) {
        m_file = std::make_unique<File>();
        m_file->mem = fileBytes;
        return;
    }
    if (!sameAsRead(*lines.m_origin, &m_error)) return;
    m_file = std::make_unique<File>();
    m_file->in.open(lines.m_origin->openPath, std::ios::binary);
    if (!m_file->in) m_error = lines.m_origin->path + ": cannot open it again to read its type-10 records: " + std::strerror(errno);
}

CrdRangeLines::Reader::~Reader() = default;

// The next block of the current run into the buffer (what is left of the last moved to the front).
bool CrdRangeLines::Reader::fill() {
    File& f = *m_file;
    f.buf.erase(0, f.pos);
    f.pos = 0;
    const size_t want = static_cast<size_t>(std::min<long long>(f.left, 1 << 20));
    const size_t old = f.buf.size();
    f.buf.resize(old + want);
    f.in.read(f.buf.data() + old, static_cast<std::streamsize>(want));
    const size_t got = static_cast<size_t>(f.in.gcount());
    f.buf.resize(old + got);
    f.left -= static_cast<long long>(got);
    f.span = f.buf;
    return got == want;
}

bool CrdRangeLines::Reader::next(std::string_view* text) {
    if (!m_error.empty() || m_k >= m_lines.m_size) return false;
    if (!m_file) {
        *text = m_lines.text(m_k++);
        return true;
    }
    File& f = *m_file;
    const std::string& path = m_lines.m_origin->path;
    auto changed = [&](const std::string& what) {
        m_error = path + ":" + std::to_string(m_lines.line(m_k)) + ": " + what +
                  ": the file changed since it was read; nothing is written from it: open it again";
        return false;
    };
    if (m_inRun == 0) {  // a run starts: its span read from the file (or taken from its bytes)
        const Run& r = m_lines.m_runs[m_run];
        f.pos = 0;
        if (!f.mem.empty()) {
            if (r.fileEnd > static_cast<long long>(f.mem.size())) return changed("it ends earlier");
            f.span = f.mem.substr(static_cast<size_t>(r.fileBegin), static_cast<size_t>(r.fileEnd - r.fileBegin));
            f.left = 0;
        } else {
            f.buf.clear();
            f.span = f.buf;
            f.left = r.fileEnd - r.fileBegin;
            f.in.clear();
            f.in.seekg(r.fileBegin);
            if (!f.in) return changed("cannot seek to the line");
        }
    }
    const bool last = m_inRun + 1 == m_lines.runSize(m_run);
    size_t end = std::string::npos;
    for (;;) {
        end = last ? (f.left == 0 ? f.span.size() : std::string::npos) : f.span.find('\n', f.pos);
        if (end != std::string::npos) break;
        if (f.left == 0) return changed("fewer lines than it had");
        if (!fill()) return changed("it ends earlier");
    }
    std::string_view t = f.span.substr(f.pos, end - f.pos);
    f.pos = end + 1;
    while (!t.empty() && t.back() == '\r') t.remove_suffix(1);
    if (last && t.find('\n') != std::string_view::npos) return changed("more lines than it had");
    // (the record's first field as the reader's Fields takes it: blanks are spaces, tabs and CRs)
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    size_t q = 0;
    while (q < t.size() && blank(t[q])) ++q;
    if (t.substr(q, 2) != "10" || (t.size() > q + 2 && !blank(t[q + 2])))
        return changed("not the type-10 record it was");
    *text = t;
    ++m_k;
    if (last) {
        ++m_run;
        m_inRun = 0;
    } else {
        ++m_inRun;
    }
    return true;
}

bool CrdRangeLines::load(std::string* error) {
    if (!m_origin) return true;
    CrdRangeLines mem;
    {
        Reader rd(*this);
        std::string_view t;
        for (size_t k = 0; k < m_size; ++k) {
            if (!rd.next(&t)) {
                *error = rd.error();
                return false;
            }
            mem.add(t, line(k), slot(k));
        }
    }
    *this = std::move(mem);
    return true;
}

bool CrdRangeLines::replaceField(size_t field, const std::function<std::optional<std::string>(size_t k)>& value,
                                 std::string* error) {
    if (!load(error)) return false;
    // In place where every new value is as long as the old one (a flag for a flag); else the
    // buffer written anew.
    std::vector<std::optional<std::string>> values(size());
    bool sameLength = true;
    for (size_t k = 0; k < size(); ++k) {
        values[k] = value(k);
        if (!values[k]) continue;
        size_t b = 0, e = 0;
        if (!tokenSpan(text(k), field, &b, &e)) {
            *error = "line " + std::to_string(line(k)) + ": a type-10 record without field " + std::to_string(field + 1);
            return false;
        }
        sameLength = sameLength && values[k]->size() == e - b;
    }
    if (sameLength) {
        for (size_t k = 0; k < size(); ++k) {
            if (!values[k]) continue;
            const std::string_view t = text(k);
            size_t b = 0, e = 0;
            tokenSpan(t, field, &b, &e);
            const size_t at = static_cast<size_t>(t.data() - m_text.data()) + b;
            m_text.replace(at, e - b, *values[k]);
        }
        return true;
    }
    CrdRangeLines out;
    out.reserve(size(), m_text.size() + size());
    for (size_t k = 0; k < size(); ++k) {
        std::string t(text(k));
        if (values[k]) replaceToken(&t, field, *values[k]);
        out.add(t, line(k), slot(k));
    }
    *this = std::move(out);
    return true;
}

size_t CrdRangeLines::textBytes() const {
    if (!m_origin) return m_text.size();
    size_t b = 0;
    for (const Run& r : m_runs) b += static_cast<size_t>(r.fileEnd - r.fileBegin);
    return b;
}

size_t CrdRangeLines::bytes() const {
    return m_text.capacity() + m_start.capacity() * sizeof(uint32_t) + m_runs.capacity() * sizeof(Run);
}

std::vector<CrdRecord> allRecords(const CrdPass& pass, std::string* error) {
    std::vector<CrdRecord> out;
    out.reserve(pass.records.size() + pass.rangeLines.size());
    const CrdRangeLines& L = pass.rangeLines;
    CrdRangeLines::Reader rd(L);
    std::string_view t;
    size_t k = 0;
    for (size_t i = 0; i <= pass.records.size(); ++i) {
        for (; k < L.size() && L.slot(k) <= i; ++k) {
            if (!rd.next(&t)) {
                if (error) *error = rd.error();
                return {};
            }
            out.push_back(CrdRecord{std::string(t), "10", L.line(k)});
        }
        if (i < pass.records.size()) out.push_back(pass.records[i]);
    }
    return out;
}

void setAllRecords(CrdPass* pass, std::vector<CrdRecord> lines) {
    pass->records.clear();
    pass->rangeLines.clear();
    for (CrdRecord& r : lines) {
        if (r.id == "10") pass->rangeLines.add(r.text, r.line, pass->records.size());
        else pass->records.push_back(std::move(r));
    }
}

long CrdPass::startMjd() const { return mjdFromDate(session.startYear, session.startMonth, session.startDay); }

double CrdPass::passSeconds(double secOfDay) const {
    const double start = session.startHour * 3600.0 + session.startMinute * 60.0 + session.startSecond;
    // (UTC labels: 23:59:60 of a leap-second day is 86 400 s and the next day's 0h is 86 400 s
    // too, as in a CPF's epochs; parsePassRecords warns about a pass that crosses one)
    return secOfDay < start - 43200.0 ? secOfDay + kSecondsPerDay : secOfDay;
}

const CrdSystemConfig* CrdPass::config(const std::string& systemId) const {
    const std::string want = toLower(systemId);
    for (const auto& c : configs)
        if (toLower(c.systemId) == want) return &c;
    return nullptr;
}

// ---- reading ---------------------------------------------------------------------------------

std::string validate(const CrdReadParams& p) {
    if (p.maxWarnings < 1) return "maximum number of warnings must be >= 1";
    return {};
}

namespace {

// parseCrd; `owned`, when given, holds `given` and is released once the records hold their own
// copies (after the split into passes): the file's text is not kept beside them while the
// passes are parsed.
CrdReadResult parseCrdText(std::string_view given, std::string* owned, const std::string& source, const CrdReadParams& params,
                           const Feedback* feedback, const std::shared_ptr<const CrdFileOrigin>& origin = nullptr) {
    CrdReadResult res;
    std::string storage;
    std::string_view text = plainText(given, &storage);
    // The lines' offsets in the file: when the text is the file's own bytes (not rewritten).
    const bool inFile = origin && storage.empty() && static_cast<long long>(given.size()) == origin->size;
    try {
        res.file.path = source;
        const std::string src = source.empty() ? "crd" : source;
        if (const std::string e = validate(params); !e.empty()) {
            res.error = e;
            return res;
        }
        if (std::string e = textFileProblem(text, src, "CRD"); !e.empty()) {
            res.error = std::move(e);
            return res;
        }
        Sink sink{&res.warnings, params.maxWarnings};
        if (!splitPasses(text, src, feedback, &sink, &res, inFile ? given.data() : nullptr, inFile ? origin : nullptr)) {
            res.file.passes.clear();
            return res;
        }
        // The text is released before the passes are parsed (the records hold their own
        // copies), except a plain file's, whose type-10 lines are parsed from it by place.
        text = {};
        std::string().swap(storage);
        if (owned && !inFile) std::string().swap(*owned);
        const bool parsed = parsePasses(src, feedback, &sink, &res, inFile ? given : std::string_view());
        if (owned) std::string().swap(*owned);
        if (!parsed || !setAsideUnusablePasses(&sink, &res)) {
            res.file.passes.clear();
            return res;
        }
        sink.close();
        for (CrdPass& p : res.file.passes) {
            p.crlf = res.file.crlf;
            if (inFile) p.rangeLines.keepInFile(origin);
        }
        res.ok = true;
    } catch (const std::exception& e) {
        res = CrdReadResult();
        res.error = (source.empty() ? std::string("crd") : source) + ": internal error: " + e.what();
    }
    return res;
}

}  // namespace

CrdReadResult parseCrd(std::string_view given, const std::string& source, const CrdReadParams& params,
                       const Feedback* feedback) {
    return parseCrdText(given, nullptr, source, params, feedback);
}

CrdReadResult readCrd(const std::string& path, const CrdReadParams& params, const Feedback* feedback) {
    std::string text, err;
    const std::shared_ptr<const CrdFileOrigin> origin = crdFileOrigin(path);  // (as it is before it is read)
    if (!readFileText(path, &text, &err)) {
        CrdReadResult r;
        r.error = err;
        return r;
    }
    return parseCrdText(text, &text, path, params, feedback, origin);
}

CrdStreamResult streamCrd(const std::string& path, const CrdReadParams& params, const Feedback* feedback,
                          const std::function<bool(size_t passCount)>& begin,
                          const std::function<bool(CrdPass&& pass)>& onPass) {
    CrdStreamResult out;
    const std::string src = path.empty() ? "crd" : path;
    try {
        if (std::string e = validate(params); !e.empty()) {
            out.error = std::move(e);
            return out;
        }
        // Read 1 (the first 10 % of the progress): the passes counted, the lines of each (capacity
        // hints), and what makes the whole file unreadable found before any pass is handed out:
        // binary data, nothing but blank lines.
        std::vector<LinesAfterH4> linesAfterH4;
        {
            core::LineReader lr;
            if (!lr.open(path)) {
                out.error = lr.error();
                return out;
            }
            std::string_view line;
            bool anyText = false;
            while (lr.next(&line)) {
                if (line.find('\0') != std::string_view::npos) {
                    out.error = crdWhere(src, lr.lineNumber()) + "binary data (NUL byte): not a CRD text file";
                    return out;
                }
                anyText = anyText || !core::trim(line).empty();
                if (isH4Line(line)) linesAfterH4.emplace_back();
                if (!linesAfterH4.empty()) linesAfterH4.back().count(line);
                if ((lr.lineNumber() & 0x3fff) == 0 && feedback) {
                    if (feedback->isCancelled()) {
                        out.error = src + ": cancelled";
                        return out;
                    }
                    feedback->setProgress(0.1 * lr.fraction());
                }
            }
            if (!lr.error().empty()) {
                out.error = lr.error();
                return out;
            }
            if (!anyText) {
                out.error = src + ": empty file";
                return out;
            }
        }
        if (begin && !begin(linesAfterH4.size())) {
            out.error = src + ": cancelled";
            return out;
        }
        // Read 2: the records through the splitter; each pass that closes is parsed and handed out.
        CrdReadResult held;  // the splitter's file: the open pass (and the trailer) only
        held.file.path = path;
        Sink sink{&out.warnings, params.maxWarnings};
        PassSplitter splitter(src, &sink, &held.file);
        // (the lines' texts kept while a pass is open and parsed, then dropped for their places:
        // parsed from the file read again, a file still being written would lose passes)
        splitter.setCapacityHints(std::move(linesAfterH4));
        const std::shared_ptr<const CrdFileOrigin> origin = crdFileOrigin(path);
        auto handOut = [&]() {
            for (CrdPass& p : splitter.takeClosed()) {
                parseOnePass(p, p.ordinal - 1, src, &sink);
                p.crlf = held.file.crlf;
                p.rangeLines.keepInFile(origin);
                ++out.passes;
                if (!onPass(std::move(p))) return false;
            }
            return true;
        };
        core::LineReader lr;
        if (!lr.open(path)) {
            out.error = lr.error();
            return out;
        }
        std::string_view line;
        while (lr.next(&line)) {
            if ((lr.lineNumber() & 0x3fff) == 0 && feedback) {
                if (feedback->isCancelled()) {
                    out.error = src + ": cancelled";
                    return out;
                }
                feedback->setProgress(0.1 + 0.9 * lr.fraction());
            }
            if (!feedLine(splitter, line, lr.lineNumber(), &held, lr.lineOffset())) {
                out.error = held.error;
                return out;
            }
            if (!handOut()) {
                out.error = src + ": cancelled";
                return out;
            }
        }
        if (!lr.error().empty()) {
            out.error = lr.error();
            return out;
        }
        splitter.finish(lr.lineNumber());
        if (!handOut()) {
            out.error = src + ": cancelled";
            return out;
        }
        if (out.passes == 0) {
            out.error = src + ": no CRD pass (no H4 session header) in " + std::to_string(lr.lineNumber()) + " lines";
            return out;
        }
        sink.close();
        out.ok = true;
    } catch (const std::bad_alloc&) {
        out = CrdStreamResult();
        out.error = src + ": out of memory (one pass is held at a time: the largest pass does not fit)";
    } catch (const std::exception& e) {
        out = CrdStreamResult();
        out.error = src + ": internal error: " + e.what();
    }
    return out;
}

// ---- writing ---------------------------------------------------------------------------------

namespace {

// The type-10 lines' new flags from one flag a range (as setFilterFlags takes them): -1 where a
// line has no range (the reader could not parse it: it keeps its text). False with *error when
// the flags do not fit the pass.
bool lineFlagsOf(const CrdPass& pass, const std::vector<int>& flags, std::vector<int8_t>* lineFlag, std::string* error) {
    if (flags.size() != pass.ranges.size()) {
        *error = "setFilterFlags: " + std::to_string(flags.size()) + " flags for " + std::to_string(pass.ranges.size()) +
                 " type-10 records";
        return false;
    }
    lineFlag->assign(pass.rangeLines.size(), -1);
    for (size_t i = 0; i < flags.size(); ++i) {
        if (flags[i] < 0 || flags[i] > 2) {
            *error = "setFilterFlags: flag " + std::to_string(flags[i]) + " at index " + std::to_string(i) +
                     " (must be 0 unknown, 1 noise or 2 data)";
            return false;
        }
        const size_t k = pass.ranges.record(i);
        if (k >= lineFlag->size()) {
            *error = "setFilterFlags: type-10 record " + std::to_string(i) + " has no line";
            return false;
        }
        (*lineFlag)[k] = static_cast<int8_t>(flags[i]);
    }
    return true;
}

// The lines of a pass in order (its records with its type-10 lines in their slots) to emit(text);
// where lineFlag (when given) has a flag for a type-10 line, the line is emitted with it as its
// filter flag. False (*error) when such a line has no flag field.
template <class Emit>
bool emitPass(const CrdPass& p, const std::vector<int8_t>* lineFlag, Emit&& emit, std::string* error) {
    const CrdRangeLines& L = p.rangeLines;
    CrdRangeLines::Reader rd(L);
    std::string buf;
    std::string_view t;
    size_t k = 0;
    for (size_t i = 0; i <= p.records.size(); ++i) {
        for (; k < L.size() && L.slot(k) <= i; ++k) {
            if (!rd.next(&t)) {
                *error = rd.error();
                return false;
            }
            if (!lineFlag || (*lineFlag)[k] < 0) {
                emit(t);
                continue;
            }
            buf.assign(t);
            if (!replaceToken(&buf, 5, std::to_string((*lineFlag)[k]))) {
                *error = "line " + std::to_string(L.line(k)) + ": a type-10 record without a filter flag field";
                return false;
            }
            emit(std::string_view(buf));
        }
        if (i < p.records.size()) emit(std::string_view(p.records[i].text));
    }
    return true;
}

}  // namespace

std::string formatCrd(const CrdFile& file) {
    std::string out, error;
    if (!formatCrd(file, &out, &error)) return {};
    return out;
}

bool formatCrd(const CrdFile& file, std::string* text, std::string* error) {
    const std::string eol = file.crlf ? "\r\n" : "\n";
    size_t n = 0;
    for (const auto& p : file.passes) {
        for (const auto& r : p.records) n += r.text.size() + 2;
        n += p.rangeLines.textBytes() + 2 * p.rangeLines.size();
    }
    for (const auto& r : file.trailer) n += r.text.size() + 2;
    std::string out;
    out.reserve(n);
    auto put = [&](std::string_view t) {
        out += t;
        out += eol;
    };
    for (const auto& p : file.passes)
        if (!emitPass(p, nullptr, put, error)) return false;
    for (const auto& r : file.trailer) put(r.text);
    *text = std::move(out);
    return true;
}

bool writeCrdWithFlags(const std::string& path, const CrdFile& file, size_t passIndex, const std::vector<int>& flags,
                       bool alone, std::string* error) {
    try {
        if (passIndex >= file.passes.size()) {
            *error = path + ": no pass " + std::to_string(passIndex + 1) + " in the file";
            return false;
        }
        const CrdPass& pass = file.passes[passIndex];
        std::vector<int8_t> lineFlag;
        if (!lineFlagsOf(pass, flags, &lineFlag, error)) return false;
        AtomicFile f(path);
        if (!f.ok()) {
            *error = f.error();
            return false;
        }
        std::ostream& o = f.stream();
        const std::string eol = (alone ? pass.crlf : file.crlf) ? "\r\n" : "\n";
        auto put = [&](std::string_view t) {
            o.write(t.data(), static_cast<std::streamsize>(t.size()));
            o.write(eol.data(), static_cast<std::streamsize>(eol.size()));
        };
        bool ok = true;
        std::string why;
        for (size_t k = 0; k < file.passes.size() && ok; ++k)
            if (!alone || k == passIndex) ok = emitPass(file.passes[k], k == passIndex ? &lineFlag : nullptr, put, &why);
        if (!ok) {
            *error = path + ": " + why;
            return false;  // (the AtomicFile removes its temporary)
        }
        if (alone) put(trailerFor(pass).text);
        else
            for (const auto& r : file.trailer) put(r.text);
        if (!f.commit()) {
            *error = f.error();
            return false;
        }
        return true;
    } catch (const std::exception& e) {
        *error = path + ": " + e.what();
        return false;
    }
}

CrdRecord trailerFor(const CrdPass& pass) {
    bool lower = false;
    for (const CrdRecord& r : pass.records)
        if (r.id == "h4") {
            lower = !r.text.empty() && r.text[0] == 'h';
            break;
        }
    return CrdRecord{lower ? "h9" : "H9", "h9", 0};
}

CrdFile passAlone(const CrdPass& pass) {
    CrdFile f;
    f.crlf = pass.crlf;
    f.passes.push_back(pass);
    f.trailer.push_back(trailerFor(pass));
    return f;
}

bool writeCrd(const std::string& path, const CrdFile& file, std::string* error) {
    try {
        std::string text;
        if (!formatCrd(file, &text, error)) return false;
        return writeFileAtomic(path, text, error);
    } catch (const std::exception& e) {
        if (error) *error = path + ": " + e.what();
        return false;
    }
}

bool setFilterFlags(CrdPass* pass, const std::vector<int>& flags, std::string* error) {
    std::vector<int8_t> lineFlag;
    if (!lineFlagsOf(*pass, flags, &lineFlag, error)) return false;
    std::string why;
    const bool ok = pass->rangeLines.replaceField(5, [&](size_t k) -> std::optional<std::string> {
        if (lineFlag[k] < 0) return std::nullopt;
        return std::to_string(lineFlag[k]);
    }, &why);
    if (!ok) {
        *error = "setFilterFlags: " + why;
        return false;
    }
    for (size_t i = 0; i < flags.size(); ++i) pass->ranges.setFilterFlag(i, flags[i]);
    return true;
}

std::string formatNormalPointRecord(const CrdNormalPoint& np, int version) {
    const bool v2 = version >= 2;
    auto num = [&](double v, int decimals) {
        if (!std::isfinite(v)) return std::string(v2 ? "na" : "-1");
        return formatFixed(v, decimals);
    };
    auto integer = [&](int v) { return v == kCrdAbsent && v2 ? std::string("na") : std::to_string(v); };
    std::string s = "11 " + formatFixed(np.secOfDay, 12) + " " + formatFixed(np.tofS, 12) + " " +
                    (np.configId.empty() ? std::string("std") : np.configId) + " " + std::to_string(np.epochEvent) + " " +
                    (std::isfinite(np.windowS) ? formatShortest(np.windowS) : num(np.windowS, 1)) + " " +
                    integer(np.numRanges) + " " + num(np.binRmsPs, 1) + " " + num(np.skew, 3) + " " +
                    num(np.kurtosis, 3) + " " + num(np.peakMinusMeanPs, 1) + " " + num(np.returnRatePct, 2) + " " +
                    integer(np.detectorChannel);
    if (v2) s += " " + num(np.snr, 1);
    return s;
}

namespace {
// Record 50, session statistics: "50 CONFIG RMS SKEW KURTOSIS PEAK-MEAN QUALITY".
std::string sessionRecord(const NormalPointProduct& p, const std::string& configId, int version) {
    const bool v2 = version >= 2;
    auto num = [&](double v, int decimals) { return std::isfinite(v) ? formatFixed(v, decimals) : std::string(v2 ? "na" : "-1"); };
    return "50 " + (configId.empty() ? std::string("std") : configId) + " " + num(p.rmsPs, 1) + " " + num(p.skew, 3) + " " +
           num(p.kurtosis, 3) + " " + num(p.peakMinusMeanPs, 1) + " " + std::to_string(p.quality);
}

// The H1's production date, and (v2) a C5 software record after the last configuration record.
void stampProduct(const NormalPointProduct& product, CrdPass* p) {
    for (CrdRecord& r : p->records) {
        if (r.id != "h1" || product.year <= 0) continue;
        const int v[4] = {product.year, product.month, product.day, product.hour};
        for (size_t k = 0; k < 4; ++k) replaceToken(&r.text, 3 + k, std::to_string(v[k]));
    }
    if (product.softwareVersion.empty() || p->format.version < 2) return;
    size_t lastC = std::string::npos;
    for (size_t i = 0; i < p->records.size(); ++i)
        if (p->records[i].id.size() == 2 && p->records[i].id[0] == 'c') lastC = i;
    if (lastC == std::string::npos) return;
    const CrdRecord c5{"C5 0 lwbsw na na laserwb " + product.softwareVersion, "c5", 0};
    p->records.insert(p->records.begin() + static_cast<long>(lastC + 1), c5);
}

bool checkNormalPoints(const std::vector<CrdNormalPoint>& nps, std::string* error) {
    for (size_t i = 0; i < nps.size(); ++i) {
        const CrdNormalPoint& n = nps[i];
        std::string what;
        if (!(n.secOfDay >= 0 && n.secOfDay < 86401)) what = "seconds of day outside 0..86400";
        else if (!(n.tofS >= 0 && n.tofS <= 100)) what = "time of flight outside 0..100 s";
        else if (n.epochEvent < 0 || n.epochEvent > 6) what = "epoch event outside 0..6";
        else if (n.numRanges < 0 && n.numRanges != kCrdAbsent) what = "negative number of ranges";
        else if (n.configId.find_first_of(" \t\r\n") != std::string::npos) what = "configuration id with blanks";
        if (!what.empty()) {
            *error = "normal point " + std::to_string(i) + ": " + what;
            return false;
        }
    }
    return true;
}

bool reparse(CrdPass* pass, std::string* error) {
    std::vector<std::string> warnings;
    Sink sink{&warnings, 50};
    if (!parsePassRecords(pass, "", &sink, error)) return false;
    return true;
}
}  // namespace

bool setNormalPoints(CrdPass* pass, const std::vector<CrdNormalPoint>& nps, NormalPointMode mode, std::string* error) {
    try {
        if (!checkNormalPoints(nps, error)) return false;
        CrdPass work = *pass;  // the pass changes only when everything succeeded
        std::string why;
        std::vector<CrdRecord> recs = allRecords(work, &why);
        if (!why.empty()) {
            *error = "setNormalPoints: " + why;
            return false;
        }
        size_t insertAt = std::string::npos;
        if (mode == NormalPointMode::Replace) {
            std::vector<CrdRecord> kept;
            kept.reserve(recs.size());
            for (auto& r : recs) {
                if (r.id == "11") {
                    if (insertAt == std::string::npos) insertAt = kept.size();
                    continue;
                }
                kept.push_back(std::move(r));
            }
            recs = std::move(kept);
        } else {
            for (size_t i = 0; i < recs.size(); ++i)
                if (recs[i].id == "11") insertAt = i + 1;
        }
        if (insertAt == std::string::npos) {
            insertAt = recs.size();
            for (size_t i = 0; i < recs.size(); ++i)
                if (recs[i].id == "h8") {
                    insertAt = i;
                    break;
                }
        }
        std::vector<CrdRecord> add;
        for (const auto& n : nps) add.push_back(CrdRecord{formatNormalPointRecord(n, work.format.version), "11", 0});
        recs.insert(recs.begin() + static_cast<long>(insertAt), add.begin(), add.end());
        setAllRecords(&work, std::move(recs));
        size_t expected = nps.size();
        if (mode == NormalPointMode::Append) expected += pass->normalPoints.size();
        if (!reparse(&work, error)) return false;
        if (work.normalPoints.size() != expected) {
            *error = "setNormalPoints: " + std::to_string(expected) + " normal points expected, " +
                     std::to_string(work.normalPoints.size()) + " read back";
            return false;
        }
        *pass = std::move(work);
        return true;
    } catch (const std::exception& e) {
        *error = std::string("setNormalPoints: ") + e.what();
        return false;
    }
}

bool makeNormalPointPass(const CrdPass& fullRate, const std::vector<CrdNormalPoint>& nps, CrdPass* out,
                         std::string* error, const NormalPointProduct& product) {
    const std::string& noneReason = product.noneReason;
    try {
        if (!checkNormalPoints(nps, error)) return false;
        if (nps.empty() && noneReason.empty()) {
            *error = "makeNormalPointPass: no normal points and no reason to write in their place";
            return false;
        }
        CrdPass p;
        p.format = fullRate.format;
        p.station = fullRate.station;
        p.target = fullRate.target;
        p.session = fullRate.session;
        if (fullRate.inheritsHeaders) {
            bool has[3] = {false, false, false};
            for (const auto& r : fullRate.records) {
                if (r.id == "h1") has[0] = true;
                if (r.id == "h2") has[1] = true;
                if (r.id == "h3") has[2] = true;
            }
            if (!has[0] && !fullRate.format.text.empty()) p.records.push_back(CrdRecord{fullRate.format.text, "h1", 0});
            if (!has[1] && !fullRate.station.text.empty()) p.records.push_back(CrdRecord{fullRate.station.text, "h2", 0});
            if (!has[2] && !fullRate.target.text.empty()) p.records.push_back(CrdRecord{fullRate.target.text, "h3", 0});
        }
        size_t h8 = std::string::npos;
        for (const auto& r : fullRate.records) {
            const std::string& id = r.id;
            if (id == "10" || id == "11" || id == "12" || id == "30" || id == "42" || (id.size() == 2 && id[0] == '9'))
                continue;
            CrdRecord c = r;
            c.line = 0;
            if (id == "h4") replaceToken(&c.text, 1, "1");
            if (id == "h8") h8 = p.records.size();
            p.records.push_back(std::move(c));
        }
        std::vector<CrdRecord> add;
        for (const auto& n : nps) add.push_back(CrdRecord{formatNormalPointRecord(n, p.format.version), "11", 0});
        if (nps.empty()) {  // one line, printable: the reason with line breaks and controls as blanks
            std::string why = "00 no normal points: " + noneReason;
            for (char& ch : why)
                if (static_cast<unsigned char>(ch) < 0x20) ch = ' ';
            add.push_back(CrdRecord{why, "00", 0});
        }
        if (product.session && !nps.empty()) add.push_back(CrdRecord{sessionRecord(product, nps.front().configId, p.format.version), "50", 0});
        const size_t at = h8 == std::string::npos ? p.records.size() : h8;
        p.records.insert(p.records.begin() + static_cast<long>(at), add.begin(), add.end());
        stampProduct(product, &p);
        if (h8 == std::string::npos) p.records.push_back(CrdRecord{"H8", "h8", 0});
        p.endedWithH8 = true;
        if (!reparse(&p, error)) return false;
        if (p.normalPoints.size() != nps.size()) {
            *error = "makeNormalPointPass: normal points could not be read back";
            return false;
        }
        *out = std::move(p);
        return true;
    } catch (const std::exception& e) {
        *error = std::string("makeNormalPointPass: ") + e.what();
        return false;
    }
}

bool isCrdNa(std::string_view s) {
    if (!s.empty() && (s[0] == '-' || s[0] == '+')) s.remove_prefix(1);
    return s.size() == 2 && (s[0] == 'n' || s[0] == 'N') && (s[1] == 'a' || s[1] == 'A');
}

}  // namespace lwb::core::slr
