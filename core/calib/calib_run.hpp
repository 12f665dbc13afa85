#pragma once
// The calibration run layer (paper 002), like SLR's pass_input / pass_run: the loaded inputs and
// the parameters -> one run of every step that has its inputs (detector fit, pointing
// calibration, validation statistics, waveform decomposition and feature match). The workbench's
// controller and the CLI's calib commands run CalibTask, and write its results with the
// writers of core/calib/calib_csv.hpp.
#include <cmath>
#include <string>
#include <vector>

#include "core/calib/calib_check.hpp"
#include "core/calib/calib_params.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/common/task.hpp"

namespace lwb::core::calib {

/// The inputs of a run; any part may be empty (its step is skipped).
struct CalibInputData {
    DetectorArray array;
    bool hasDetectorTruth = false;  ///< simulated: the surface is known
    GaussSurface detectorTruth;
    std::vector<BeamDesign> beams;
    std::vector<ControlPoint> points;       ///< control points of the pointing calibration
    std::vector<ControlPoint> checkPoints;  ///< independent check points (validation)
    bool hasPointingTruth = false;          ///< simulated: the corrections are known
    double trueDAlpha[2] = {0, 0}, trueDBeta[2] = {0, 0}, trueDRho[2] = {0, 0};
    std::vector<DifferenceGroup> differences;  ///< elevation differences (calib stats)
    std::string differencesName;               ///< their file's name, for the statistics' source
    std::string groupColumn;                   ///< their group column ("" = one group)
    Waveform waveform;
    double trueHeightM = NAN;                  ///< simulated: the feature height
    /// No waveform: the height to match the features against (calib waveform --height).
    double givenHeightM = NAN;
    std::vector<FeatureCandidate> features;
};

/// Where a run's inputs come from (paths; "" = that part is not given). A front end gathers
/// them — the CLI's calib commands from their arguments, the workbench from its input row,
/// Python from its arguments — and the core reads them here, with one set of messages.
struct CalibSources {
    std::string detectors;      ///< detector CSV (calib detector)
    std::string controlPoints;  ///< control-point CSV (calib pointing); needs beams
    std::string beams;          ///< beam designs JSON (calib pointing --beams)
    std::string checkPoints;    ///< independent check points, control-point CSV format (validation)
    std::string differences;    ///< elevation differences CSV (calib stats)
    std::string groupColumn;    ///< the differences' group column (e.g. beam); "" = one group
    std::string waveform;       ///< waveform CSV (calib waveform)
    std::string features;       ///< candidate features CSV (calib waveform --features)
    double givenHeightM = NAN;  ///< no waveform: the height to match the features against
    std::vector<BeamDesign> givenBeams;  ///< beam designs in memory, where `beams` is "" (the workbench's GF-7 designs)
};

/// The parts of a run's inputs, each read on its own (the workbench reads again only what changed).
enum class CalibPart { Detectors, ControlPoints, CheckPoints, Differences, Waveform, Features };

/// Reads one part of the sources into *in, clearing that part first (an empty source leaves it
/// empty). A waveform without times is read at 1 ns a sample: the run puts
/// waveform.sample_interval_ns on it (withSampleInterval). False with *error ("FILE:LINE: ...").
bool loadCalibPart(CalibPart part, const CalibSources& sources, CalibInputData* in, std::string* error);
/// Every part of the sources (and the given height).
bool loadCalibInputs(const CalibSources& sources, CalibInputData* in, std::string* error);

/// One group of elevation differences and its statistics.
struct StatsGroup {
    std::string name;   ///< "beam 1", "beam 2", "all", or the group column and value (for display)
    std::string group;  ///< the `group` column of the statistics CSV: the group's value ("" for one group)
    std::vector<double> d;
    ElevationStatsResult stats;
};

struct CalibRunResult {
    bool hasDetector = false;
    DetectorFitResult detector;
    bool hasPointing = false;
    PointingCalibResult pointing;
    bool hasCheck = false;
    CalibrationCheckResult check;  ///< the check points after calibration
    std::string statsSource;       ///< what the statistics are of
    std::string statsError;
    std::vector<StatsGroup> stats;
    bool hasWaveform = false;
    Waveform waveformRun;          ///< the waveform as decomposed (at waveform.sample_interval_ns)
    WaveformResult waveform;
    bool hasMatch = false;
    FeatureMatchResult match;
};

/// The calibration task (core/common/task.hpp): every step that has its inputs. The statistics
/// are those of the differences when given, else of the check points after calibration, else of
/// the control points' own height residuals after calibration (not independent: the source says
/// so). The CLI's calib commands run it on the inputs they are given (detector, pointing, stats,
/// waveform); the workbench's calibration workspace runs it live (TaskJob<CalibTask>).
struct CalibTask {
    static constexpr const char* kName = "calibration";
    using Params = CalibParams;
    static const Schema<CalibParams>& schema() { return calibSchema(); }
    using Inputs = CalibInputData;
    using Reuse = NoReuse;  // every step takes well under 100 ms (docs/benchmarks.md)
    using Outputs = CalibRunResult;
    static CalibRunResult run(const CalibInputData& in, const CalibParams& params, const NoReuse&, Feedback* fb);
};


/// The statistics that succeeded, as rows for statsCsv (keyed by StatsGroup::group): what
/// `calib stats -o` and the workbench's export write.
std::vector<std::pair<std::string, ElevationStats>> statsRows(const std::vector<StatsGroup>& groups);

}  // namespace lwb::core::calib
