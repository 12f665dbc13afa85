#include "core/calib/validation_stats.hpp"

#include <algorithm>
#include <cmath>

#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::calib {

namespace {
// Laser minus control heights: metres at most for a working altimeter, never kilometres. A
// larger value is a damaged field (and 1e308 would overflow the sums into inf).
constexpr double kMaxElevationDifferenceM = 1e4;
}  // namespace

ElevationStatsResult elevationStats(const std::vector<double>& d) {
    ElevationStatsResult r;
    if (d.empty()) {
        r.error = "no elevation differences";
        return r;
    }
    for (size_t i = 0; i < d.size(); ++i)
        if (!std::isfinite(d[i]) || std::fabs(d[i]) > kMaxElevationDifferenceM) {
            r.error = "elevation difference " + std::to_string(i + 1) + " (" + formatShortest(d[i]) +
                      " m) is not plausible: |d| must be at most 10 km";
            return r;
        }
    ElevationStats& s = r.stats;
    s.n = static_cast<int>(d.size());
    // Two-pass sums keep the small spreads of centimetre-level data exact enough.
    double sum = 0, sum2 = 0, sumAbs = 0;
    for (double v : d) {
        sum += v;
        sum2 += v * v;
        sumAbs += std::fabs(v);
    }
    s.mean = sum / s.n;
    double ss = 0;
    for (double v : d) ss += (v - s.mean) * (v - s.mean);
    s.rmsAboutZero = std::sqrt(sum2 / s.n);
    s.stdPopulation = std::sqrt(ss / s.n);
    s.stdSample = s.n > 1 ? std::sqrt(ss / (s.n - 1)) : NAN;
    s.min = *std::min_element(d.begin(), d.end());
    s.max = *std::max_element(d.begin(), d.end());
    std::vector<double> sorted = d;
    std::sort(sorted.begin(), sorted.end());
    s.median = s.n % 2 ? sorted[s.n / 2] : 0.5 * (sorted[s.n / 2 - 1] + sorted[s.n / 2]);
    s.meanAbs = sumAbs / s.n;
    r.ok = true;
    return r;
}

std::vector<LabelledValue> labelledStats(const ElevationStats& s) {
    return {
        {"n", "number of differences", static_cast<double>(s.n)},
        {"mean", "mean (sum d / n), m", s.mean},
        {"rms_about_zero", "RMS about zero, sqrt(sum d^2 / n), m (paper 002 beam 2 'RMSE')", s.rmsAboutZero},
        {"std_sample", "sample standard deviation about the mean, n-1, m (paper 002 beam 1 'RMSE', lake std)",
         s.stdSample},
        {"std_population", "population standard deviation about the mean, n, m", s.stdPopulation},
        {"min", "minimum, m", s.min},
        {"max", "maximum, m", s.max},
        {"median", "median, m", s.median},
        {"mean_abs", "mean absolute difference, m", s.meanAbs},
    };
}

bool readDifferencesCsv(const std::string& path, const std::string& groupColumn, std::vector<DifferenceGroup>* out,
                        std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int cd = t.firstColumn({"d", "diff", "dh", "difference", "d_m"});
    const int cl = t.column("laser"), cc = t.column("control");
    if (cd < 0 && (cl < 0 || cc < 0)) {
        *error = path + ":1: header needs a difference column (d) or the columns laser and control";
        return false;
    }
    int cg = -1;
    if (!groupColumn.empty()) {
        cg = t.column(groupColumn);
        if (cg < 0) {
            *error = path + ":1: no column named " + groupColumn;
            return false;
        }
    }
    std::vector<DifferenceGroup> groups;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        const std::string where = whereInFile(path, t.lines[i]);
        double v = 0;
        if (cd >= 0) {
            if (!parseDouble(row[cd], &v)) {
                *error = where + "difference must be a finite number, not \"" + printableExcerpt(row[cd]) + "\"";
                return false;
            }
        } else {
            double a = 0, b = 0;
            if (!parseDouble(row[cl], &a) || !parseDouble(row[cc], &b)) {
                *error = where + "laser and control must be finite numbers";
                return false;
            }
            v = a - b;
        }
        if (std::fabs(v) > kMaxElevationDifferenceM) {
            *error = where + "difference " + formatShortest(v) + " m is not plausible (|d| must be at most 10 km)";
            return false;
        }
        const std::string g = cg >= 0 ? std::string(trim(row[cg])) : std::string();
        auto it = std::find_if(groups.begin(), groups.end(), [&](const DifferenceGroup& x) { return x.group == g; });
        if (it == groups.end()) {
            groups.push_back({g, {}});
            it = groups.end() - 1;
        }
        it->d.push_back(v);
    }
    if (groups.empty()) {
        *error = path + ": no data rows";
        return false;
    }
    *out = std::move(groups);
    return true;
}

}  // namespace lwb::core::calib
