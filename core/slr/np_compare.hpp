#pragma once
// A station's normal points beside ours (issue 29): the block of a station's CRD normal-point
// file that holds the open pass, each of its normal points matched with ours bin by bin, and
// the difference at the station's epoch. The workbench draws the station's points over the O-C
// and lists the differences; the tests compare the shared passes with it.
#include <memory>
#include <string>
#include <vector>

#include "core/slr/crd.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/postfit.hpp"

namespace lwb::core::slr {

/// One bin: a station normal point and ours, or one of them alone.
struct NpDifference {
    enum class Match { Both, StationOnly, OursOnly };
    Match match = Match::Both;
    double t = 0;                ///< the station's epoch, else ours (s since 0h UTC of the pass day)
    double stationT = NAN, ourT = NAN;
    int stationRanges = 0, ourRanges = 0;
    double stationRmsPs = NAN, ourRmsPs = NAN;
    /// The station's point on the pass's O-C axis: its TOF less the computed TOF (the
    /// prediction, or the fitted TOF trend: TOF − O-C of the pass's points) at its epoch. NaN
    /// when its epoch is outside the pass's points.
    double stationOcS = NAN;
    /// The station's point less our post-fit trend at its epoch (s, two-way); NaN as above.
    double stationResidualS = NAN;
    /// Ours less the station's, one-way (mm), at the station's epoch: our trend there plus our
    /// bin's mean residual, less stationOcS (the range changes by km/s: the epochs differ when
    /// the two picked different points of the bin). NaN unless Both.
    double deltaMm = NAN;
};

struct NpComparison {
    bool ok = false;
    std::string error;       ///< why nothing can be compared ("FILE: ...")
    size_t block = 0;        ///< the station file's block used (0-based)
    std::string stationName; ///< its H2 station name and satellite, for the display
    std::string satellite;
    double binLengthS = 0;   ///< the station's bin length (its records' window), else ours
    long dayMjd = 0;         ///< the pass day (its H4's start date, 0h UTC): rows' t are seconds from it
    std::vector<NpDifference> rows;  ///< by epoch
    size_t matched = 0, stationOnly = 0, oursOnly = 0;
    double meanMm = NAN, meanAbsMm = NAN, rmsMm = NAN;  ///< over the matched bins
    /// One line: "N station normal points, M ours: K in the same bins, mean ... mm, ...".
    std::string describe() const;
};

/// The comparison as CSV, one row a bin: utc (ISO 8601, date and time, "Z"), epoch_s (s from 0h
/// UTC of the pass day), match (both, station_only, ours_only), delta_mm (ours − station, one-way),
/// station_ranges, our_ranges, station_rms_ps, our_rms_ps, station_oc_s, station_residual_s;
/// empty fields where a side has no value. The workbench's Export CSV of the Station normal points
/// tab (issue 42: its table's cells had been written, "Δ (mm)" headers and a time of day only).
std::string npComparisonCsv(const NpComparison& c);

/// Reads a station's normal-point file for compareWithStation: a CRD file with at least one
/// type-11 record. False with *error ("FILE:LINE: ..." from the reader, or why it is not one).
bool loadStationNormalPoints(const std::string& path, CrdFile* out, std::string* error);

/// Compares `post`'s normal points (of `pass`, read from a CRD file: its day is the H4's) with
/// the station's in `station`. The block is the one of the pass's satellite (ILRS id or name)
/// with the most normal points within the pass's span (one bin beyond each end); bins are
/// floor(t / L) from 0h UTC with L the station's window. Errors: the pass is not from a CRD file,
/// no post-fit, no block of the satellite overlapping the pass.
NpComparison compareWithStation(const PassData& pass, const PostfitResult& post, const CrdFile& station,
                                const std::string& stationPath);

}  // namespace lwb::core::slr
