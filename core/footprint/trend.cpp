#include "core/footprint/trend.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::footprint {

namespace {
// Days from 1970-01-01 of a proleptic Gregorian date, and back (Howard Hinnant's algorithms).
long long daysFromCivil(long long y, unsigned m, unsigned d) {
    y -= m <= 2;
    const long long era = (y >= 0 ? y : y - 399) / 400;
    const unsigned yoe = static_cast<unsigned>(y - era * 400);
    const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + static_cast<long long>(doe) - 719468;
}
void civilFromDays(long long z, long long* y, unsigned* m, unsigned* d) {
    z += 719468;
    const long long era = (z >= 0 ? z : z - 146096) / 146097;
    const unsigned doe = static_cast<unsigned>(z - era * 146097);
    const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const unsigned mp = (5 * doy + 2) / 153;
    *d = doy - (153 * mp + 2) / 5 + 1;
    *m = mp < 10 ? mp + 3 : mp - 9;
    *y = static_cast<long long>(yoe) + era * 400 + (*m <= 2);
}
int daysInMonth(long long y, unsigned m) {
    static const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    return m == 2 && leap ? 29 : days[m - 1];
}
const char* kMonthNames[] = {"January", "February", "March", "April", "May", "June", "July", "August", "September",
                             "October", "November", "December"};
// Exactly `n` digits at t[at..] into *v.
bool digits(const std::string& t, size_t at, size_t n, int* v) {
    if (at + n > t.size()) return false;
    int x = 0;
    for (size_t i = at; i < at + n; ++i) {
        if (!std::isdigit(static_cast<unsigned char>(t[i]))) return false;
        x = x * 10 + (t[i] - '0');
    }
    *v = x;
    return true;
}
}  // namespace

bool monthOf(const std::string& time, std::string* month, std::string* why) {
    std::string dummy;
    std::string& err = why ? *why : dummy;
    const std::string t(trim(time));
    auto bad = [&](const std::string& w) {
        err = w;
        return false;
    };
    int y = 0, mo = 0;
    if (t.size() >= 7 && digits(t, 0, 4, &y) && (t[4] == '-' || t[4] == '/')) {
        if (!digits(t, 5, 2, &mo) || mo < 1 || mo > 12) return bad("the month must be 01 to 12");
        if (t.size() == 7) {
            char buf[16];
            std::snprintf(buf, sizeof buf, "%04d-%02d", y, mo);
            *month = buf;
            return true;
        }
        int d = 0;
        if (t.size() < 10 || t[7] != t[4] || !digits(t, 8, 2, &d)) return bad("expected YYYY-MM, YYYY-MM-DD or an ISO 8601 date and time");
        if (d < 1 || d > daysInMonth(y, static_cast<unsigned>(mo)))
            return bad(std::string(kMonthNames[mo - 1]) + " " + std::to_string(y) + " has " +
                       std::to_string(daysInMonth(y, static_cast<unsigned>(mo))) + " days");
        long long minutes = daysFromCivil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d)) * 1440;
        if (t.size() > 10) {
            // [T or space] hh:mm[:ss[.frac]] [Z | +hh[:mm] | -hh[:mm]]
            if (t[10] != 'T' && t[10] != ' ') return bad("expected T or a space between the date and the time");
            int hh = 0, mm = 0, ss = 0;
            size_t i = 11;
            if (!digits(t, i, 2, &hh) || i + 2 >= t.size() || t[i + 2] != ':' || !digits(t, i + 3, 2, &mm))
                return bad("expected hh:mm after the date");
            i += 5;
            if (i < t.size() && t[i] == ':') {
                if (!digits(t, i + 1, 2, &ss)) return bad("expected hh:mm:ss");
                i += 3;
                if (i < t.size() && (t[i] == '.' || t[i] == ',')) {
                    size_t j = i + 1;
                    while (j < t.size() && std::isdigit(static_cast<unsigned char>(t[j]))) ++j;
                    if (j == i + 1) return bad("expected digits after the decimal point of the seconds");
                    i = j;
                }
            }
            if (hh > 23 || mm > 59 || ss > 60) return bad("the time of day must be within 00:00:00 and 23:59:60");
            int offset = 0;  // minutes east of UTC
            if (i < t.size()) {
                if (t[i] == 'Z' && i + 1 == t.size()) {
                    ++i;
                } else if (t[i] == '+' || t[i] == '-') {
                    int oh = 0, om = 0;
                    size_t j = i + 1;
                    if (!digits(t, j, 2, &oh)) return bad("expected a UTC offset +hh, +hh:mm or +hhmm");
                    j += 2;
                    if (j < t.size() && t[j] == ':') ++j;
                    if (j < t.size()) {
                        if (!digits(t, j, 2, &om)) return bad("expected a UTC offset +hh, +hh:mm or +hhmm");
                        j += 2;
                    }
                    if (j != t.size() || oh > 23 || om > 59) return bad("expected a UTC offset +hh, +hh:mm or +hhmm");
                    offset = (t[i] == '-' ? -1 : 1) * (oh * 60 + om);
                    i = j;
                } else {
                    return bad("unexpected text after the time");
                }
            }
            minutes += hh * 60 + mm - offset;
            // A leap second is 23:59:60 UTC (local time: that minus the offset).
            if (ss == 60 && ((minutes % 1440) + 1440) % 1440 != 23 * 60 + 59)
                return bad("second 60 exists only as 23:59:60 UTC (a leap second)");
        }
        long long yy = 0;
        unsigned mm2 = 0, dd = 0;
        const long long day = minutes >= 0 ? minutes / 1440 : (minutes - 1439) / 1440;
        civilFromDays(day, &yy, &mm2, &dd);
        char buf[24];
        std::snprintf(buf, sizeof buf, "%04lld-%02u", yy, mm2);
        *month = buf;
        return true;
    }
    double secs = 0;
    if (!parseDouble(t, &secs)) return bad("not a time: expected YYYY-MM, YYYY-MM-DD, an ISO 8601 date and time, or Unix seconds");
    if (secs < 0 || secs > 4e10) return bad("Unix seconds out of range (0 .. 4e10)");
    long long yy = 0;
    unsigned mm2 = 0, dd = 0;
    civilFromDays(static_cast<long long>(std::floor(secs / 86400)), &yy, &mm2, &dd);
    char buf[24];
    std::snprintf(buf, sizeof buf, "%04lld-%02u", yy, mm2);
    *month = buf;
    return true;
}

namespace {
// Centroids are pixel coordinates of a camera frame (550 px for GF-7); beyond a million pixels
// a value is a damaged field, and squaring it in the statistics would overflow.
constexpr double kMaxCentroidPx = 1e6;
}  // namespace

bool readCentroidCsv(const std::string& path, std::vector<CentroidRecord>* out, std::string* error, std::string* note) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int ct = t.column("time"), cb = t.column("beam"), cx = t.column("x"), cy = t.column("y"),
              cc = t.column("camera"), cv = t.column("verdict");
    if (ct < 0 || cb < 0 || cx < 0 || cy < 0) {
        *error = path + ":1: header needs the columns time, beam, x, y (camera optional)";
        return false;
    }
    // A footprint report: the good shots with a position, a time and a beam.
    size_t notGood = 0, noPosition = 0, noTimeOrBeam = 0;
    auto leftOut = [&](const std::vector<std::string>& row) {
        if (cv < 0) return false;
        if (trim(row[size_t(cv)]) != "good") return ++notGood, true;
        if (trim(row[size_t(cx)]).empty() || trim(row[size_t(cy)]).empty()) return ++noPosition, true;
        if (trim(row[size_t(ct)]).empty() || trim(row[size_t(cb)]).empty()) return ++noTimeOrBeam, true;
        return false;
    };
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        if (leftOut(row)) continue;
        const std::string where = whereInFile(path, t.lines[i]);
        CentroidRecord r;
        r.line = t.lines[i];
        std::string why;
        if (!monthOf(row[ct], &r.month, &why)) {
            *error = where + "time \"" + printableExcerpt(row[ct]) + "\": " + why;
            return false;
        }
        if (!parseDouble(row[cx], &r.x) || !parseDouble(row[cy], &r.y)) {
            *error = where + "x and y must be finite numbers, not \"" + printableExcerpt(row[cx]) + "\", \"" +
                     printableExcerpt(row[cy]) + "\"";
            return false;
        }
        if (std::fabs(r.x) > kMaxCentroidPx || std::fabs(r.y) > kMaxCentroidPx) {
            *error = where + "x = " + formatShortest(r.x) + ", y = " + formatShortest(r.y) +
                     " is not a plausible spot centroid (|x|, |y| <= 1e6 px)";
            return false;
        }
        r.beam = std::string(trim(row[cb]));
        if (r.beam.empty()) {
            *error = where + "empty beam";
            return false;
        }
        if (cc >= 0) r.camera = std::string(trim(row[cc]));
        out->push_back(std::move(r));
    }
    std::string why;
    if (cv >= 0) {
        auto part = [&](size_t n, const char* what) {
            if (n) why += (why.empty() ? "" : ", ") + std::to_string(n) + " " + what;
        };
        part(notGood, "not judged good");
        part(noPosition, "good without a position");
        part(noTimeOrBeam, "good without a time or a beam");
        if (!why.empty()) why = "a footprint report: " + why + " left out of " + std::to_string(t.rows.size()) + " rows";
    }
    if (note) *note = why;
    if (out->empty()) {
        *error = path + ": no centroid rows" + (why.empty() ? "" : " (" + why + ")") +
                 (noTimeOrBeam ? "; give the frames' times and beams with a shot list or --metadata" : "");
        return false;
    }
    return true;
}

const Schema<TrendParams>& trendSchema() {
    static const Schema<TrendParams> schema = [] {
        using T = TrendParams;
        Schema<T> s("trend");
        s.real("arcsec_per_px", LWB_FIELD(T, arcsecPerPx), "arcsec/px", {0, 1e6, true, true}, {0.1, 2},
               "pointing change per pixel (paper 001 LFC: 1.5 urad/px = 0.31 arcsec)");
        s.real("reject_sigma", LWB_FIELD(T, rejectSigma), "sigma", {1, 100}, {2, 5},
               "iterative k-sigma rejection of shots within a month; 0 = off")
            .specials = {{0, "off"}};
        s.integer("min_shots", LWB_FIELD(T, minShots), "", {1, 1000000000}, {1, 100}, "months with fewer shots are left out");
        return s;
    }();
    return schema;
}

std::string validate(const TrendParams& p) { return trendSchema().validate(p); }

TrendResult computeTrend(const std::vector<CentroidRecord>& records, const TrendParams& params) {
    TrendResult res;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    if (records.empty()) {
        res.error = "no centroid records";
        return res;
    }
    using Key = std::tuple<std::string, std::string, std::string>;  // camera, beam, month
    std::map<Key, std::vector<const CentroidRecord*>> groups;
    for (const auto& r : records) groups[{r.camera, r.beam, r.month}].push_back(&r);
    std::map<std::pair<std::string, std::string>, std::pair<double, double>> first;  // camera/beam → first mean
    for (auto& [key, recs] : groups) {
        TrendRow row;
        std::tie(row.camera, row.beam, row.month) = key;
        std::vector<char> keep(recs.size(), 1);
        double mx = 0, my = 0, sx = 0, sy = 0;
        int n = 0;
        for (int pass = 0; pass < 20; ++pass) {
            mx = my = 0;
            n = 0;
            for (size_t i = 0; i < recs.size(); ++i)
                if (keep[i]) {
                    mx += recs[i]->x;
                    my += recs[i]->y;
                    ++n;
                }
            mx /= n;
            my /= n;
            sx = sy = 0;
            for (size_t i = 0; i < recs.size(); ++i)
                if (keep[i]) {
                    sx += (recs[i]->x - mx) * (recs[i]->x - mx);
                    sy += (recs[i]->y - my) * (recs[i]->y - my);
                }
            sx = n > 1 ? std::sqrt(sx / (n - 1)) : 0;
            sy = n > 1 ? std::sqrt(sy / (n - 1)) : 0;
            if (params.rejectSigma <= 0 || n < 5) break;
            bool changed = false;
            for (size_t i = 0; i < recs.size(); ++i) {
                if (!keep[i]) continue;
                const double zx = sx > 0 ? std::fabs(recs[i]->x - mx) / sx : 0;
                const double zy = sy > 0 ? std::fabs(recs[i]->y - my) / sy : 0;
                if (zx > params.rejectSigma || zy > params.rejectSigma) {
                    keep[i] = 0;
                    changed = true;
                }
            }
            if (!changed) break;
        }
        row.n = n;
        row.rejected = static_cast<int>(recs.size()) - n;
        if (n < params.minShots) {
            res.warnings.push_back(row.camera + " beam " + row.beam + " " + row.month + ": only " + std::to_string(n) +
                                   " shots, month left out");
            continue;
        }
        row.xMean = mx;
        row.yMean = my;
        row.xStd = sx;
        row.yStd = sy;
        const auto cb = std::make_pair(row.camera, row.beam);
        if (!first.count(cb)) first[cb] = {mx, my};
        row.dx = mx - first[cb].first;
        row.dy = my - first[cb].second;
        row.planarPx = std::hypot(row.dx, row.dy);
        row.pointingArcsec = row.planarPx * params.arcsecPerPx;
        row.beamDistancePx = row.distanceChangePx = NAN;
        res.rows.push_back(row);
    }
    // Beam distance per camera and month, when the camera has exactly two beams that month.
    std::map<std::pair<std::string, std::string>, std::vector<TrendRow*>> byCamMonth;
    for (auto& r : res.rows) byCamMonth[{r.camera, r.month}].push_back(&r);
    std::map<std::string, double> firstDistance;
    for (auto& [key, rows] : byCamMonth) {  // months sort as text "YYYY-MM"
        if (rows.size() != 2) continue;
        const double d = std::hypot(rows[0]->xMean - rows[1]->xMean, rows[0]->yMean - rows[1]->yMean);
        if (!firstDistance.count(key.first)) firstDistance[key.first] = d;
        for (TrendRow* r : rows) {
            r->beamDistancePx = d;
            r->distanceChangePx = d - firstDistance[key.first];
        }
    }
    res.ok = true;
    return res;
}

bool writeTrendCsv(const std::string& path, const std::vector<TrendRow>& rows, std::string* error) {
    std::string s =
        "camera,beam,month,n,rejected,x_mean,y_mean,x_std,y_std,dx_px,dy_px,planar_change_px,"
        "pointing_change_arcsec,beam_distance_px,distance_change_px\n";
    auto f = [](double v, int d) { return std::isfinite(v) ? formatFixed(v, d) : std::string(); };
    for (const auto& r : rows)
        s += csvEscape(r.camera) + "," + csvEscape(r.beam) + "," + r.month + "," + std::to_string(r.n) + "," +
             std::to_string(r.rejected) + "," + f(r.xMean, 4) + "," + f(r.yMean, 4) + "," + f(r.xStd, 4) + "," +
             f(r.yStd, 4) + "," + f(r.dx, 4) + "," + f(r.dy, 4) + "," + f(r.planarPx, 4) + "," +
             f(r.pointingArcsec, 4) + "," + f(r.beamDistancePx, 4) + "," + f(r.distanceChangePx, 4) + "\n";
    return writeFileAtomic(path, s, error);
}

}  // namespace lwb::core::footprint
