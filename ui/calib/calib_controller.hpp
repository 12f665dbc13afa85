#pragma once
// The calibration workspace's controller (paper 002): the detector array, the control points
// with their beam designs, the independent check points or elevation differences for the
// validation statistics, the echo waveform with its candidate features, and the parameters of
// every step. Widgets never call the core: every change reruns the whole chain on the thread
// pool (detector fit, pointing calibration, validation statistics, waveform match); results
// are tagged with a generation number and stale ones are dropped.
//
// Inputs are immutable snapshots (CalibData behind a shared_ptr); each part is either a file
// (same formats as `laserwb-cli calib ...`) or the built-in simulation ("demo").
#include <QJsonObject>
#include <QObject>
#include <QString>
#include <memory>
#include <vector>

#include "core/calib/calib_check.hpp"
#include "core/calib/calib_params.hpp"
#include "core/calib/calib_run.hpp"
#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/calib/waveform.hpp"

#include "ui/kit/task_job.hpp"

namespace lwb::ui {

/// Where each input comes from: a path, "demo" (the simulation) or empty (none).
struct CalibInputs {
    QString detectors;      ///< detector CSV (calib detector)
    QString controlPoints;  ///< control-point CSV (calib pointing)
    QString beams;          ///< beam designs JSON (calib pointing --beams)
    QString checkPoints;    ///< independent check points, control-point CSV format (validation)
    QString differences;    ///< elevation differences CSV (calib stats)
    QString groupColumn;    ///< the differences' group column (e.g. beam); empty = one group
    QString waveform;       ///< waveform CSV (calib waveform)
    QString features;       ///< candidate features CSV (calib waveform --features)
    bool operator==(const CalibInputs& o) const;
};

/// The loaded inputs (one immutable snapshot per change): the core run layer's inputs and
/// where each part came from.
struct CalibData : core::calib::CalibInputData {
    CalibInputs inputs;
};

/// The parameters of every step: one schema table (core::calib::calibSchema()).
using CalibParams = core::calib::CalibParams;
/// Empty when every step's parameters are valid, else the first problem.
QString validateCalibParams(const CalibParams& p);
/// The session's parameter block: the schema's JSON (every field, always written).
QJsonObject calibParamsToJson(const CalibParams& p);
/// Through the schema: unknown keys, wrong types and invalid values are errors naming the key;
/// missing keys keep their defaults. With `doc` (the parsed session) a message starts with the
/// value's file:line:col; `at` is the block's path in the session.
bool calibParamsFromJson(const QJsonObject& o, CalibParams* p, QString* error, const core::JsonParseResult* doc = nullptr,
        const std::vector<std::string>& at = {});

/// One group of elevation differences and its statistics.
struct StatsColumn {
    QString name;
    std::string group;  ///< core::calib::StatsGroup::group
    std::vector<double> d;
    core::calib::ElevationStatsResult stats;
};

/// One run of the whole chain (core::calib::CalibTask) and what it ran on.
struct CalibRun {
    quint64 generation = 0;
    std::shared_ptr<const CalibData> data;    ///< the inputs this run used
    CalibParams params;
    bool hasDetector = false;
    core::calib::DetectorFitResult detector;
    bool hasPointing = false;
    core::calib::PointingCalibResult pointing;
    bool hasCheck = false;
    core::calib::CalibrationCheckResult check;  ///< the check points after calibration
    QString statsSource;                      ///< what the statistics are of
    QString statsError;
    std::vector<StatsColumn> stats;
    bool hasWaveform = false;
    core::calib::WaveformResult waveform;
    bool hasMatch = false;
    core::calib::FeatureMatchResult match;
    double latencyMs = 0;
};

class CalibController : public QObject {
    Q_OBJECT
public:
    explicit CalibController(QObject* parent = nullptr);
    ~CalibController() override;

    const CalibData& data() const { return *m_data; }
    const CalibInputs& inputs() const { return m_data->inputs; }
    const CalibParams& params() const { return m_params; }
    const CalibRun& run() const { return m_run; }
    bool hasRun() const { return m_run.generation != 0; }
    bool busy() const { return m_job.busy(); }

    /// Every part from the simulators (seeded, deterministic).
    void openDemo();
    /// Loads the given inputs ("demo", a path, or empty for none, per part) all or nothing: on
    /// an error (naming file and line) the previous inputs stay.
    bool setInputs(const CalibInputs& inputs, QString* error);
    /// setInputs in two steps: the inputs read (over a copy of the current ones, every part
    /// re-read when all are the same), nothing changed; null with *error. Then adopted.
    std::shared_ptr<const CalibData> readInputs(const CalibInputs& inputs, QString* error) const;
    void adoptInputs(std::shared_ptr<const CalibData> data);
    /// Single parts (the open buttons); the other parts stay.
    bool openDetectors(const QString& path, QString* error);
    /// beamsPath empty: beams.json beside the control points, else the current designs.
    bool openControlPoints(const QString& path, const QString& beamsPath, QString* error);
    bool openCheckPoints(const QString& path, QString* error);
    bool openDifferences(const QString& path, const QString& groupColumn, QString* error);
    bool openWaveform(const QString& path, QString* error);
    bool openFeatures(const QString& path, QString* error);

    /// New parameters; false (state unchanged) when invalid.
    bool setParams(const CalibParams& p, QString* error = nullptr);

    // Exports (atomic; the formats of the corresponding CLI outputs). False with *error.
    bool exportDetectorReport(const QString& path, QString* error) const;  ///< calib detector --detectors
    bool exportCentre(const QString& path, QString* error) const;          ///< calib detector -o
    bool exportPointing(const QString& path, QString* error) const;        ///< calib pointing --params
    bool exportIterations(const QString& path, QString* error) const;      ///< calib pointing --iterations
    bool exportStats(const QString& path, QString* error) const;           ///< calib stats -o
    bool exportRanking(const QString& path, QString* error) const;         ///< calib waveform -o

    /// Waits (processing events) until no run is pending, or timeoutMs passes.
    bool waitIdle(int timeoutMs);

signals:
    void inputsChanged();
    void runReady(const lwb::ui::CalibRun& run);
    void status(const QString& message);

private:
    void schedule() { m_job.schedule(); }
    /// Loads the parts (the .cpp's Part values) of `in` over the current inputs and adopts them.
    std::shared_ptr<const CalibData> replaceParts(const CalibInputs& in, std::initializer_list<int> parts, QString* error);

    std::shared_ptr<const CalibData> m_data;
    CalibParams m_params;
    CalibRun m_run;
    TaskJob<core::calib::CalibTask> m_job;  // the live rerun of the CLI's task (debounce, cancel, generation tag)
    std::shared_ptr<const CalibData> m_runData;  // what the run last started was given
    CalibParams m_runParams;
};

}  // namespace lwb::ui

Q_DECLARE_METATYPE(lwb::ui::CalibRun)
