#pragma once
// From files to a pass ready for screening, and back: the layer the `slr` command and the SLR
// workspace share. A CRD full-rate pass gets its O-C from the CPF prediction and the SINEX
// station coordinates when both are given, else from a robust trend of its own time of flight
// (a warning says so); a plain O-C table (CSV, header epoch_s,oc_s) is used as it is. The
// writers of a screened pass (CRD full rate with filter flags, normal points, the per-point CSV)
// are in pass_output.hpp.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/cpf.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/oc.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"
#include "core/slr/sinex.hpp"

namespace lwb::core::slr {

struct PassInputParams {
    std::string cpfPath;      ///< CPF prediction; with sinexPath, O-C from the prediction
    std::string sinexPath;    ///< SINEX station coordinates
    OcParams oc;              ///< light time, refraction (default Mendes–Pavlis from the met records)
    TrendOcParams trend;      ///< the fallback without a prediction
    /// A CPF that does not fit the pass (another satellite, or a time span that misses it):
    /// false = an error; true = a warning and the pass's own TOF trend (as the GUI does). A
    /// folder of CPF files always falls back when none of them fits.
    bool cpfFallback = false;
};

/// Predictions and station coordinates, read once for the passes of a file.
struct PassSources {
    std::vector<CpfReadResult> cpfs;   ///< the CPF file, or every readable CPF of a folder (by name)
    bool cpfFolder = false;
    std::vector<std::string> skipped;  ///< files of the folder that are not readable CPF, with why
    bool haveStations = false;
    SinexFile stations;
    std::vector<std::string> stationWarnings;  ///< the SINEX reader's
};

struct PassSummary {
    int index = 0;                 ///< pass number in the file (0-based)
    std::string satellite, ilrsId, station;
    std::string start, end;        ///< H4 UTC, "YYYY-MM-DD hh:mm:ss"
    size_t ranges = 0;             ///< type-10 records
    size_t normalPoints = 0;       ///< type-11 records
    int dataType = 0;              ///< 0 full rate, 1 normal points
    std::string problem;           ///< why the block cannot be used as a pass (CrdPass::problem), else empty
};

/// The fewest points a pass is screened with, in every mode (an O-C table, a CRD pass with a
/// CPF, a CRD pass on its own TOF trend, one pass or --all-passes): 5. Fewer is not a pass to
/// judge (a trend of the TOF needs 2 degrees of freedom beyond its 3 coefficients); such a block
/// is listed and skipped, not failed.
inline constexpr size_t kMinPassPoints = 5;

/// What a block of a CRD file is called when a file's passes are screened (laserwb-cli slr
/// --all-passes and the workbench's "Screen all passes" table alike).
struct BlockStatus {
    std::string status;  ///< "" (a pass to screen), "station normal points", "skipped", "ok", "no signal", "doubtful"
    std::string reason;
};
/// Before screening: the station's own normal points (type-11 records in a block of H4 data type
/// 1, or only type-11 records; a data-type-1 block of type-10 records only is full rate),
/// sampled engineering data (data type 2) and blocks of fewer than kMinPassPoints full-rate
/// records are not passes to screen; anything else is ({"", ""}).
BlockStatus blockStatus(const PassSummary& s);

/// The one rule for what a pass is, used by the default pass choice, --pass, the workbench's
/// pass list and every batch: a block whose blockStatus is "" and that the reader could use.
inline bool isPassToScreen(const PassSummary& s) { return s.problem.empty() && blockStatus(s).status.empty(); }

struct PassData {
    std::string source;            ///< file the pass came from
    int passIndex = 0;
    std::string satellite, ilrsId, station;
    int cdpPad = -1;
    std::string ocOrigin;          ///< "CPF prediction", "fitted TOF trend (no prediction)" or "O-C table"
    std::string ocNote;            ///< why a given prediction was not used (the TOF trend instead), else ""
    /// The O-C's parameters (CRD passes: the O-C was computed with these; an O-C table's is given).
    bool ocComputed = false;
    OcParams ocParams;
    TrendOcParams ownTrendParams;
    /// The O-C is relative to a circular orbit fitted to the pass itself (OcResult::trendOrbit):
    /// the post-fit then models at most a bias and a drift over the whole pass (postfitForPass).
    bool orbitTrend = false;
    /// The O-C's own fitted trend's hat matrix (OcResult::trendHat; row-major, t.size()² values)
    /// on a short pass (at most 49 records) without a prediction; empty otherwise (a prediction
    /// is not fitted to the pass; PassTask judges the normal points' precision only here).
    std::vector<double> trendHat;
    std::vector<double> t;         ///< epoch (s since 0h UTC of the pass day for CRD input)
    std::vector<double> oc;        ///< O-C (s, two-way)
    std::vector<double> tof;       ///< observed two-way TOF (s); empty for O-C tables
    std::vector<int8_t> stationFlag;  ///< the station's filter flag per point (CRD, or an O-C table's column), empty otherwise
    /// CrdPass::ranges index per point (CRD; .at(i)): runs rising by one, so a pass whose every
    /// record has an O-C holds one run, not 4 bytes an event (issue 44).
    CrdStepColumn<uint32_t> rangeIndex;
    double altitudeKm = 0;         ///< satellite altitude estimate for the normal-point bin (0 = unknown)
    bool hasCrd = false;
    long startMjd = 0;             ///< MJD of the day the epochs count from (a CRD pass's H4 start day); 0 for an O-C table
    /// The file as read (for writing back), shared with every pass taken from the same reading:
    /// a file of 20 000 passes is not copied once per pass.
    std::shared_ptr<const CrdFile> crd;
    /// Non-empty when the reader skipped records of this pass as damaged: "FILE:LINE: why (N
    /// damaged record(s) ...)". The pass can be looked at, but its points are incomplete and the
    /// damaged lines would be written back as they are: every writer below refuses it.
    std::string damaged;
};

struct PassInputResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    std::vector<std::string> notes;   ///< what the O-C is relative to (OcResult::notes)
    std::vector<PassSummary> passes;  ///< every pass of the file (one entry for an O-C table)
    PassData pass;                    ///< the loaded pass
    /// The block asked for is not a pass to screen (the station's normal points, engineering
    /// data, too few records; isPassToScreen): the caller's choice, not the file's fault (exit 2).
    bool notAPass = false;
};

/// True when the file is to be read as CRD, by its content first: a first record (after blank
/// lines and 00 comments) H1 ("H1 CRD ..." in any case) is CRD whatever the file is called
/// (.v2C, no ending, ...); a first line with a comma or starting with '#' is a CSV. Otherwise,
/// and for a file that cannot be looked into (missing, not a regular file, unreadable), the
/// name decides: the CRD endings frd fr2 npt np2 crd, any case. False means an O-C CSV.
bool isCrdFile(const std::string& path);

/// Reads params.cpfPath — a CPF file, or a folder whose readable CPF files are all kept — and
/// params.sinexPath. False with *error.
bool readPassSources(const PassInputParams& params, PassSources* out, std::string* error);
/// One pass of an already-read CRD file (passIndex −1: the first pass to screen, isPassToScreen). O-C
/// against the prediction of `sources` that fits the pass (satellite ids and time span; picked
/// from a folder), else against the pass's own TOF trend (see PassInputParams::cpfFallback).
/// The pass shares `crd` (no copy); PassInputResult::passes is filled only when the pass cannot be
/// taken (to list what the file holds): callers that show the file's passes call summarisePasses.
PassInputResult passFromCrd(const std::shared_ptr<const CrdReadResult>& crd, const std::string& path, int passIndex,
                            const PassInputParams& params, const PassSources& sources, const Feedback* fb = nullptr);
/// An O-C table (CSV) as a pass.
PassInputResult passFromOcTable(const std::string& path);
/// Epochs and O-C (s) as a pass, as an O-C table's columns are (`source` names it in messages
/// and writers; Python's laserwb.slr.Pass.from_arrays): every value finite, at least
/// kMinPassPoints points.
PassInputResult passFromOc(std::vector<double> t, std::vector<double> oc, const std::string& source);
/// One summary per pass of a CRD file.
std::vector<PassSummary> summarisePasses(const CrdFile& file);

/// Loads pass `passIndex` (0-based; -1 = the first pass to screen) of a CRD file, or an O-C CSV
/// (told apart by isCrdFile). With a CPF, the CPF must be for the pass's satellite (the ids of
/// the CPF H2 and the CRD H3 that both give must agree). An error names what is wrong and ends
/// with the first of the readers' warnings (the damaged lines that may explain it).
PassInputResult loadPass(const std::string& path, int passIndex, const PassInputParams& params,
                         const Feedback* fb = nullptr);

}  // namespace lwb::core::slr
