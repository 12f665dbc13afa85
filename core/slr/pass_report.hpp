#pragma once
// A one-page PDF report of a screened pass for the station log (issue 42): what was screened
// (satellite, station, day, file, points), the verdict and its reason, the O-C with the
// screening's classes, the post-fit residuals with the normal-point bins, the binary image,
// the residual histogram, the parameters used (the automatic mode's choices marked), the normal
// points, the station comparison when one was made, and the provenance (program, inputs with
// their SHA-256, the command that makes the same products). Drawn with cairo's PDF surface; the
// plots are rasters inside vector axes, so that a pass of 10^6 points is still a page of a few
// hundred kB. `laserwb-cli slr --report-out` and the workbench's File > Report... both write it
// through stagePassProducts (slr_run.hpp): the same bytes for the same run and the same
// production date (SOURCE_DATE_EPOCH when set, else now).
#include <memory>
#include <string>
#include <vector>

#include "core/slr/np_compare.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/slr_run.hpp"

namespace lwb::core::slr {

struct PassReport {
    const PassSettings* settings = nullptr;  ///< the parameters the pass ran with (required)
    std::vector<std::string> inputs;         ///< the files read (pass, CPF, stations, presets), as named
    std::vector<std::string> notes;          ///< what opening the pass said (O-C origin, warnings)
    /// The station's normal points (SlrSetup::stationNormalPoints, named by stationPath): the
    /// report compares them with the run's (compareWithStation) as the Station NP tab does.
    std::shared_ptr<const CrdFile> stationFile;
    std::string stationPath;
    std::string command;                     ///< the laserwb-cli command that reproduces the run ("" = none)
};

/// The report of a pass opened and resolved from `setup` (every front end's): its files in the
/// order pass, prediction, stations, presets, as the sources name them; the laserwb-cli command of
/// the run (slrCommandArgs with the pass's number and its resolved parameters); the station's
/// normal points of the setup when given; `notes`: what
/// opening it said (warnings first). `settings` must outlive the report.
PassReport passReportOf(const SlrSetup& setup, const PassData& pass, const PassSettings& settings,
                        std::vector<std::string> notes);

/// The report of a pass loaded with the sources `opened` and run later with the set-up `run`
/// (Python's load_pass, then run): passReportOf with the prediction the pass was opened with
/// named as the CLI's --cpf where the run has the same stations (else a note says the command
/// cannot carry it), and the station's normal points `stationNp` ("" = the run's) read by the core.
/// False with *error (FILE:LINE).
bool passReportOfLoaded(const SlrSetup& run, const SlrSources& opened, const PassData& pass, const PassSettings& settings,
                        std::vector<std::string> notes, const std::string& stationNp, PassReport* out, SlrError* error);

/// Writes the report of `pass` screened as `run` to `path` (the caller's staging file) as a
/// one-page A4 PDF. False with *error when cairo cannot write it.
bool writePassReport(const std::string& path, const PassData& pass, const PassRunResult& run, const PassReport& report,
                     std::string* error);

}  // namespace lwb::core::slr
