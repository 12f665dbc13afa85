#pragma once
// Long-term spot-centroid monitoring (paper 001 §3): monthly mean centroid per camera and
// beam, planar change from the first month, pointing change in arcsec, and the distance
// between the two beams of a camera relative to the first month (the LSI frame check).
#include <string>
#include <vector>

#include "core/common/schema.hpp"

namespace lwb::core::footprint {

struct CentroidRecord {
    std::string month;   ///< "YYYY-MM" (UTC)
    std::string camera;  ///< e.g. "LFI", "LSI"; empty when the input has no camera column
    std::string beam;    ///< e.g. "1", "2"
    double x = 0, y = 0; ///< full-image px
    long line = 0;       ///< source line (for messages)
};

struct TrendParams;
/// The trend parameters' table (core/common/schema.hpp).
const Schema<TrendParams>& trendSchema();

struct TrendParams {
    double arcsecPerPx = 0.31;  ///< pointing change per px (paper 001: LFC 1.5 µrad/px ≈ 0.31″)
    double rejectSigma = 3.0;   ///< iterative k·σ rejection of shots within a month (0 = off)
    int minShots = 1;           ///< months with fewer shots (after rejection) are left out
};

struct TrendRow {
    std::string camera, beam, month;
    int n = 0;                  ///< shots used
    int rejected = 0;           ///< shots removed by the k·σ rejection
    double xMean = 0, yMean = 0, xStd = 0, yStd = 0;  ///< px
    double dx = 0, dy = 0;      ///< change of the mean from the first month (px)
    double planarPx = 0;        ///< sqrt(dx² + dy²)
    double pointingArcsec = 0;  ///< planarPx · arcsecPerPx
    double beamDistancePx = 0;  ///< distance between the camera's two beams that month (NaN if not two)
    double distanceChangePx = 0;///< beamDistancePx minus that of the first month with both beams
};

struct TrendResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    std::vector<TrendRow> rows;  ///< ordered by camera, beam, month
};

/// Parses a time into its UTC "YYYY-MM" month: "2020-03", ISO 8601 dates and date-times
/// ("2020-03-15", "2020-03-15T10:22:01.5Z", "2020-03-31T23:30-02:00", "/" for "-" and a space for
/// "T" too), or Unix seconds. Validated: the day exists in its month (2021-02-30 does not), the
/// time of day is 00:00:00 .. 23:59:60 with second 60 only at 23:59:60 UTC, a UTC offset moves
/// the time to UTC (and may change the month), nothing may follow. False with *why otherwise.
bool monthOf(const std::string& time, std::string* month, std::string* why = nullptr);

/// Reads per-shot centroids: CSV with header time,beam,x,y[,camera] (any order, extra columns
/// ignored). Errors name the file and line. A footprint report (`laserwb-cli footprint`'s
/// report.csv or the workbench's review export: a `verdict` column) is read as the workbench
/// makes its trend: only the shots judged good that have a position, a time and a beam; the
/// others are left out and *note (when given) says how many and why.
bool readCentroidCsv(const std::string& path, std::vector<CentroidRecord>* out, std::string* error,
                     std::string* note = nullptr);

TrendResult computeTrend(const std::vector<CentroidRecord>& records, const TrendParams& params);
std::string validate(const TrendParams& p);

/// Writes the trend table as CSV, atomically.
bool writeTrendCsv(const std::string& path, const std::vector<TrendRow>& rows, std::string* error);

}  // namespace lwb::core::footprint
