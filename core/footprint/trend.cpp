#include "core/footprint/trend.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::footprint {

bool monthOf(const std::string& time, std::string* month) {
    const std::string t(trim(time));
    if (t.size() >= 7 && std::isdigit(static_cast<unsigned char>(t[0])) && (t[4] == '-' || t[4] == '/')) {
        long long y = 0, m = 0;
        if (!parseLong(t.substr(0, 4), &y) || !parseLong(t.substr(5, 2), &m) || m < 1 || m > 12) return false;
        if (t.size() > 7) {
            if (t[7] != t[4] || t.size() < 10) return false;
            long long d = 0;
            if (!parseLong(t.substr(8, 2), &d) || d < 1 || d > 31) return false;
            if (t.size() > 10 && t[10] != 'T' && t[10] != ' ') return false;
        }
        char buf[16];
        std::snprintf(buf, sizeof buf, "%04lld-%02lld", y, m);
        *month = buf;
        return true;
    }
    double secs = 0;
    if (!parseDouble(t, &secs) || secs < 0 || secs > 4e10) return false;
    const std::time_t tt = static_cast<std::time_t>(secs);
    std::tm tm {};
    if (!gmtime_r(&tt, &tm)) return false;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%04d-%02d", tm.tm_year + 1900, tm.tm_mon + 1);
    *month = buf;
    return true;
}

namespace {
// Centroids are pixel coordinates of a camera frame (550 px for GF-7); beyond a million pixels
// a value is a damaged field, and squaring it in the statistics would overflow.
constexpr double kMaxCentroidPx = 1e6;
}  // namespace

bool readCentroidCsv(const std::string& path, std::vector<CentroidRecord>* out, std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int ct = t.column("time"), cb = t.column("beam"), cx = t.column("x"), cy = t.column("y"),
              cc = t.column("camera");
    if (ct < 0 || cb < 0 || cx < 0 || cy < 0) {
        *error = path + ":1: header needs the columns time, beam, x, y (camera optional)";
        return false;
    }
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        const std::string where = whereInFile(path, t.lines[i]);
        CentroidRecord r;
        r.line = t.lines[i];
        if (!monthOf(row[ct], &r.month)) {
            *error = where + "unreadable time \"" + row[ct] + "\"";
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
    if (out->empty()) {
        *error = path + ": no centroid rows";
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
