#pragma once
// A station's file of passes (a day's, say) as one batch task over the pass task: every block of
// the CRD file gets a row (isPassToScreen decides which are screened), every pass is opened,
// resolved, run and written exactly as one pass alone is (core/slr/slr_run.hpp), the passes side
// by side on an ordered, cancellable runner whose products do not depend on the number of
// threads. laserwb-cli slr --all-passes, the workbench's "Screen all passes" and Python's
// laserwb.slr.process_file run it; summary.csv's columns are declared once, below, and are the
// workbench's table too.
//
// With an output folder DIR: per screened pass DIR/passNNN.csv, .frd (the block alone, flags as
// delivered) and .npt (its normal points, or why there are none), DIR/normal_points.npt (every
// pass's normal points: the file a station sends), DIR/summary.csv and DIR/provenance.json, all
// committed together at the end (a failed or cancelled run writes nothing). The file is read
// pass by pass (streamCrd): one pass is held at a time per worker, whatever the file's size.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/common/provenance.hpp"
#include "core/slr/slr_run.hpp"

namespace lwb::core::slr {

/// One block of the file as the batch judged it.
struct DayRow {
    size_t pass = 0;             ///< its place in the file, 1-based
    PassSummary block;           ///< what the file says of it
    std::string status, reason;  ///< blockStatus, runStatus, or "failed" with why
    bool screened = false;       ///< screened (the numbers below, and files when written)
    double durationS = NAN;
    size_t points = 0, accepted = 0, normalPoints = 0;
    double rmsS = NAN;           ///< post-fit RMS (s, two-way)
    double precision = NAN, recall = NAN;  ///< against the station's flags
    std::string ocOrigin;
    std::string output;          ///< "passNNN.csv" when written
    PassBias bias;
    double seconds = 0;          ///< wall time of the screening (not in summary.csv: not reproducible)
};

/// A column of summary.csv (and of the workbench's table).
struct DayColumn {
    std::string name, unit, doc;
    std::function<std::string(const DayRow&)> cell;  ///< the cell's text (dayCsv escapes it)
};
/// summary.csv's columns, in order.
const std::vector<DayColumn>& dayColumns();
/// summary.csv: the header and one row per block.
std::string dayCsv(const std::vector<DayRow>& rows);

struct DayOptions {
    std::string outDir;  ///< "" = the rows only, nothing written
    int threads = 0;     ///< passes screened side by side (0: every core); the products are the same for any number
};

struct DayObserver {
    std::function<void(size_t blocks)> begin;    ///< the file's count of blocks, before any work
    std::function<void(const DayRow&)> row;      ///< each row once decided, in the file's order
    const Feedback* fb = nullptr;                ///< cancel
};

struct DayResult {
    bool ok = false;             ///< the file was read and (with outDir) its products committed
    SlrError error;
    bool cancelled = false;
    std::vector<DayRow> rows;
    size_t screened = 0, doubtful = 0, failed = 0, skipped = 0, stationNormalPoints = 0;
    bool dayNormalPoints = false;        ///< DIR/normal_points.npt written
    std::vector<std::string> written;    ///< the files committed (outDir)
};

/// Runs every block of setup.sources.input (a CRD file). Passes the prediction does not fit are
/// screened on their own TOF trend with a note, whatever setup.sources.cpfFallback says.
/// DIR/provenance.json records slrProvenance(setup, true), whoever runs it.
DayResult runStationDay(const SlrSetup& setup, const DayOptions& options, const DayObserver& observer = {});
/// The same from the sources a front end gathered: setUpSlrRun, then the run (a set-up that
/// fails is the result's error). Python's process_file and the workbench's "Screen all passes";
/// the CLI sets up once for many files and runs each with the setup above.
DayResult runStationDay(const SlrSources& sources, const DayOptions& options, const DayObserver& observer = {});

/// "passNNN" for block k (1-based): the products' names.
std::string dayPassName(size_t k);

}  // namespace lwb::core::slr
