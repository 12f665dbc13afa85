#pragma once
// Statistics of elevation differences (laser − control, or heights over a still lake) used to
// validate a calibration (paper 002 §3.3, tables 5 and 6). Every figure carries its own label,
// because the paper's "RMSE" (中误差) is not one statistic throughout:
//   flat ground, beam 1 (22 points): published RMSE 0.097 m = the sample standard deviation
//     about the mean (n − 1); the RMS about zero would be 0.103 m.
//   flat ground, beam 2 (24 points): published RMSE 0.104 m = the RMS about zero (0.1040 m);
//     the sample standard deviation would be 0.106 m (the population one, 0.1038 m, also rounds
//     to 0.104).
//   lake heights (relative accuracy): published "standard deviation" 0.047 / 0.057 m = the
//     sample standard deviation (n − 1).
// So report them all, labelled, and never call one of them "RMSE" without saying which.
#include <cmath>
#include <string>
#include <vector>

namespace lwb::core::calib {

struct ElevationStats {
    int n = 0;
    double mean = 0;           ///< Σd / n (m)
    double rmsAboutZero = 0;   ///< √(Σd² / n) (m): the RMSE against the control
    double stdSample = 0;      ///< √(Σ(d − mean)² / (n − 1)) (m); NaN when n < 2
    double stdPopulation = 0;  ///< √(Σ(d − mean)² / n) (m)
    double min = 0, max = 0;   ///< (m)
    double median = 0;         ///< (m)
    double meanAbs = 0;        ///< Σ|d| / n (m)
};

struct ElevationStatsResult {
    bool ok = false;
    std::string error;
    ElevationStats stats;
};

/// Computes the statistics of a list of elevation differences (m). Error on an empty list or
/// a non-finite value (naming its position).
ElevationStatsResult elevationStats(const std::vector<double>& d);

struct LabelledValue {
    std::string key;           ///< machine name, e.g. "rms_about_zero"
    std::string label;         ///< human label with the formula
    double value = 0;
};
/// The statistics as labelled rows (n, mean, RMS about zero, sample std, population std,
/// min, max, median, mean |d|) for tables, CSV and plots.
std::vector<LabelledValue> labelledStats(const ElevationStats& s);

/// Reads differences from a CSV: a column named d, diff, dh or difference; or the two columns
/// laser and control (difference = laser − control); an optional group column (e.g. beam)
/// splits the rows. Errors name the file and line.
struct DifferenceGroup {
    std::string group;         ///< empty when the file has no group column
    std::vector<double> d;
};
bool readDifferencesCsv(const std::string& path, const std::string& groupColumn, std::vector<DifferenceGroup>* out,
                        std::string* error);

}  // namespace lwb::core::calib
