#include "ui/calib_controller.hpp"

#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonValue>
#include <QPointer>
#include <QThreadPool>
#include <QtConcurrent>
#include <cmath>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/calib/calib_csv.hpp"
#include "core/sim/demo_data.hpp"
#include "ui/session_json.hpp"

namespace lwb::ui {

using namespace core::calib;
namespace sim = core::sim;

namespace {

const QString kDemo = QStringLiteral("demo");

bool fail(QString* error, const std::string& msg) {
    if (error) *error = QString::fromStdString(msg);
    return false;
}

// Loads one part of the inputs into d ("demo", a path, or empty = none).
enum class Part { Detectors, ControlPoints, CheckPoints, Differences, Waveform, Features };

bool loadPart(Part part, const CalibInputs& in, CalibData* d, QString* error) {
    std::string err;
    switch (part) {
        case Part::Detectors: {
            d->array = {};
            d->hasDetectorTruth = false;
            if (in.detectors.isEmpty()) return true;
            if (in.detectors == kDemo) {
                const sim::DetectorSimulation s = sim::demoDetectorArray();
                d->array = s.array;
                d->detectorTruth = s.truth;
                d->hasDetectorTruth = true;
                return true;
            }
            DetectorArray a;
            if (!readDetectorCsv(in.detectors.toStdString(), &a, &err)) return fail(error, err);
            d->array = std::move(a);
            return true;
        }
        case Part::ControlPoints: {
            d->points.clear();
            d->beams.clear();
            d->hasPointingTruth = false;
            if (in.controlPoints.isEmpty()) return true;
            if (in.controlPoints == kDemo) {
                const sim::CalibSimulation s = sim::demoCalibrationPasses();
                d->beams = s.beams;
                d->points = s.points;
                d->hasPointingTruth = true;
                for (int k = 0; k < 2; ++k) {
                    d->trueDAlpha[k] = s.dAlpha[k];
                    d->trueDBeta[k] = s.dBeta[k];
                    d->trueDRho[k] = s.dRho[k];
                }
                return true;
            }
            std::vector<ControlPoint> pts;
            if (!readControlPointCsv(in.controlPoints.toStdString(), &pts, &err)) return fail(error, err);
            std::vector<BeamDesign> beams;
            if (in.beams.isEmpty()) {
                if (error) *error = in.controlPoints + ": the control points need beam designs (a beams JSON)";
                return false;
            }
            if (in.beams == kDemo) {
                beams = sim::gf7Beams();
            } else if (!readBeamsJson(in.beams.toStdString(), &beams, &err)) {
                return fail(error, err);
            }
            d->points = std::move(pts);
            d->beams = std::move(beams);
            return true;
        }
        case Part::CheckPoints: {
            d->checkPoints.clear();
            if (in.checkPoints.isEmpty()) return true;
            if (in.checkPoints == kDemo) {
                d->checkPoints = sim::demoCheckPoints();
                return true;
            }
            std::vector<ControlPoint> pts;
            if (!readControlPointCsv(in.checkPoints.toStdString(), &pts, &err)) return fail(error, err);
            d->checkPoints = std::move(pts);
            return true;
        }
        case Part::Differences: {
            d->differences.clear();
            if (in.differences.isEmpty()) return true;
            if (in.differences == kDemo) {
                if (error) *error = QObject::tr("the demo has no differences file (its statistics come from check points)");
                return false;
            }
            std::vector<DifferenceGroup> g;
            if (!readDifferencesCsv(in.differences.toStdString(), in.groupColumn.toStdString(), &g, &err))
                return fail(error, err);
            d->differences = std::move(g);
            d->differencesName = QFileInfo(in.differences).fileName().toStdString();
            d->groupColumn = in.groupColumn.toStdString();
            return true;
        }
        case Part::Waveform: {
            d->waveform = {};
            d->trueHeightM = NAN;
            if (in.waveform.isEmpty()) return true;
            if (in.waveform == kDemo) {
                d->waveform = sim::demoWaveform();
                d->trueHeightM = sim::kDemoFeatureHeightM;
                return true;
            }
            // The sample interval is a waveform parameter (files with a time column ignore it):
            // read at 1 ns per sample here, the run puts waveform.sample_interval_ns on it
            // (core withSampleInterval; it read a literal 0.5, which only the CLI's setting changed).
            Waveform w;
            if (!readWaveformCsv(in.waveform.toStdString(), 1.0, &w, &err)) return fail(error, err);
            d->waveform = std::move(w);
            return true;
        }
        case Part::Features: {
            d->features.clear();
            if (in.features.isEmpty()) return true;
            if (in.features == kDemo) {
                d->features = sim::demoFeatures();
                return true;
            }
            std::vector<FeatureCandidate> c;
            if (!readFeatureCsv(in.features.toStdString(), &c, &err)) return fail(error, err);
            d->features = std::move(c);
            return true;
        }
    }
    return true;
}

// Loads every part whose source differs from `have` (all when have is null).
bool loadChanged(const CalibInputs& in, const CalibData* have, CalibData* d, QString* error) {
    struct P {
        Part part;
        bool changed;
    } parts[] = {
        {Part::Detectors, !have || in.detectors != have->inputs.detectors},
        {Part::ControlPoints, !have || in.controlPoints != have->inputs.controlPoints || in.beams != have->inputs.beams},
        {Part::CheckPoints, !have || in.checkPoints != have->inputs.checkPoints},
        {Part::Differences, !have || in.differences != have->inputs.differences || in.groupColumn != have->inputs.groupColumn},
        {Part::Waveform, !have || in.waveform != have->inputs.waveform},
        {Part::Features, !have || in.features != have->inputs.features},
    };
    for (const P& p : parts)
        if (p.changed && !loadPart(p.part, in, d, error)) return false;
    d->inputs = in;
    return true;
}

// The task's outputs with the strings the views show, and what they were computed from.
CalibRun viewRun(core::calib::CalibRunResult r, std::shared_ptr<const CalibData> data, const CalibParams& p) {
    CalibRun run;
    run.data = std::move(data);
    run.params = p;
    run.hasDetector = r.hasDetector;
    run.detector = std::move(r.detector);
    run.hasPointing = r.hasPointing;
    run.pointing = std::move(r.pointing);
    run.hasCheck = r.hasCheck;
    run.check = std::move(r.check);
    run.statsSource = QString::fromStdString(r.statsSource);
    run.statsError = QString::fromStdString(r.statsError);
    for (auto& g : r.stats) run.stats.push_back({QString::fromStdString(g.name), g.group, std::move(g.d), std::move(g.stats)});
    run.hasWaveform = r.hasWaveform;
    run.waveform = std::move(r.waveform);
    run.hasMatch = r.hasMatch;
    run.match = std::move(r.match);
    return run;
}

}  // namespace

bool CalibInputs::operator==(const CalibInputs& o) const {
    return detectors == o.detectors && controlPoints == o.controlPoints && beams == o.beams && checkPoints == o.checkPoints &&
           differences == o.differences && groupColumn == o.groupColumn && waveform == o.waveform && features == o.features;
}

QString validateCalibParams(const CalibParams& p) { return QString::fromStdString(validate(p)); }

QJsonObject calibParamsToJson(const CalibParams& p) { return toQtJson(calibSchema().toJson(p)); }

bool calibParamsFromJson(const QJsonObject& o, CalibParams* out, QString* error, const core::JsonParseResult* doc,
        const std::vector<std::string>& at) {
    CalibParams p;
    std::string err;
    if (!calibSchema().fromJson(fromQtJson(o), &p, &err, doc, at)) return fail(error, err);
    if (const std::string e = validate(p); !e.empty()) return fail(error, (doc ? doc->where(at) : std::string()) + e);
    *out = p;
    return true;
}

// ---------------------------------------------------------------------------------------------

CalibController::CalibController(QObject* parent) : QObject(parent), m_data(std::make_shared<CalibData>()) {
    qRegisterMetaType<lwb::ui::CalibRun>();
    m_job.bind(
        [this](TaskJob<CalibTask>::Run* r) {
            r->inputs = m_runData = m_data;  // the latest snapshot is the only run delivered
            r->params = m_runParams = m_params;
            return true;
        },
        [this](core::calib::CalibRunResult r) {
            CalibRun run = viewRun(std::move(r), m_runData, m_runParams);
            run.generation = m_job.generation();
            run.latencyMs = double(QDateTime::currentMSecsSinceEpoch() - m_job.changedAt());
            m_run = std::move(run);
            emit runReady(m_run);
        });
}

CalibController::~CalibController() { m_job.cancel(); }

void CalibController::openDemo() {
    CalibInputs in;
    in.detectors = in.controlPoints = in.beams = in.checkPoints = in.waveform = in.features = kDemo;
    QString err;
    setInputs(in, &err);  // the demo cannot fail
}

bool CalibController::setInputs(const CalibInputs& in, QString* error) {
    auto d = std::make_shared<CalibData>(*m_data);
    const bool same = in == m_data->inputs;
    // Reload every part that changed (files are re-read when asked for the same path again).
    QString err;
    if (!loadChanged(in, same ? nullptr : m_data.get(), d.get(), &err)) {
        if (error) *error = err;
        emit status(err);
        return false;
    }
    m_data = d;
    emit inputsChanged();
    schedule();
    return true;
}

// Loads the given parts of `in` over a copy of the current inputs and adopts it; on an error
// the inputs stay. Returns the new data (null on error).
std::shared_ptr<const CalibData> CalibController::replaceParts(const CalibInputs& in, std::initializer_list<int> parts,
                                                              QString* error) {
    auto d = std::make_shared<CalibData>(*m_data);
    for (int p : parts)
        if (!loadPart(static_cast<Part>(p), in, d.get(), error)) return nullptr;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    schedule();
    return d;
}

bool CalibController::openDetectors(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.detectors = path;
    const auto d = replaceParts(in, {int(Part::Detectors)}, error);
    if (d) emit status(tr("%1: %2 detectors").arg(QFileInfo(path).fileName()).arg(d->array.detectors.size()));
    return d != nullptr;
}

bool CalibController::openControlPoints(const QString& path, const QString& beamsPath, QString* error) {
    CalibInputs in = inputs();
    in.controlPoints = path;
    if (!beamsPath.isEmpty()) {
        in.beams = beamsPath;
    } else {
        const QString beside = QFileInfo(path).absolutePath() + "/beams.json";
        if (QFileInfo::exists(beside)) {
            in.beams = beside;
        } else if (in.beams.isEmpty()) {
            if (error) *error = tr("%1: no beam designs (put beams.json beside the control points, or choose one)").arg(path);
            return false;
        }
    }
    const auto d = replaceParts(in, {int(Part::ControlPoints)}, error);
    if (d)
        emit status(tr("%1: %2 control points, %3 beams").arg(QFileInfo(path).fileName()).arg(d->points.size()).arg(d->beams.size()));
    return d != nullptr;
}

bool CalibController::openCheckPoints(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.checkPoints = path;
    in.differences.clear();  // the statistics follow the check points now
    in.groupColumn.clear();
    return replaceParts(in, {int(Part::CheckPoints), int(Part::Differences)}, error) != nullptr;
}

bool CalibController::openDifferences(const QString& path, const QString& groupColumn, QString* error) {
    CalibInputs in = inputs();
    in.differences = path;
    in.groupColumn = groupColumn;
    const auto d = replaceParts(in, {int(Part::Differences)}, error);
    if (d) emit status(tr("%1: %2 group(s) of differences").arg(QFileInfo(path).fileName()).arg(d->differences.size()));
    return d != nullptr;
}

bool CalibController::openWaveform(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.waveform = path;
    return replaceParts(in, {int(Part::Waveform)}, error) != nullptr;
}

bool CalibController::openFeatures(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.features = path;
    return replaceParts(in, {int(Part::Features)}, error) != nullptr;
}

bool CalibController::setParams(const CalibParams& p, QString* error) {
    if (const QString e = validateCalibParams(p); !e.isEmpty()) {
        if (error) *error = e;
        return false;
    }
    m_params = p;
    schedule();
    return true;
}

bool CalibController::waitIdle(int timeoutMs) {
    return waitUntilIdle([this] { return busy(); }, timeoutMs);
}

// ---------------------------------------------------------------------------------------------
// Exports

namespace {
bool writeText(const QString& path, const std::string& s, QString* error) {
    std::string err;
    if (!writeTextOutput(path.toStdString(), s, &err)) return fail(error, err);
    return true;
}
}  // namespace

bool CalibController::exportDetectorReport(const QString& path, QString* error) const {
    if (!m_run.hasDetector || !m_run.detector.ok) return fail(error, "no detector fit to export");
    std::string err;
    if (!writeDetectorReportCsv(path.toStdString(), m_run.data->array, m_run.detector, &err)) return fail(error, err);
    return true;
}

bool CalibController::exportCentre(const QString& path, QString* error) const {
    if (!m_run.hasDetector || !m_run.detector.ok) return fail(error, "no detector fit to export");
    std::string err;
    if (!writeDetectorCentreCsv(path.toStdString(), m_run.detector, &err)) return fail(error, err);
    return true;
}

bool CalibController::exportPointing(const QString& path, QString* error) const {
    if (!m_run.hasPointing || !m_run.pointing.ok) return fail(error, "no pointing calibration to export");
    return writeText(path, pointingParamsCsv(m_run.pointing), error);
}

bool CalibController::exportIterations(const QString& path, QString* error) const {
    if (!m_run.hasPointing || !m_run.pointing.ok) return fail(error, "no pointing calibration to export");
    return writeText(path, pointingIterationsCsv(m_run.pointing), error);
}

bool CalibController::exportStats(const QString& path, QString* error) const {
    if (m_run.stats.empty()) return fail(error, "no validation statistics to export");
    std::vector<core::calib::StatsGroup> groups;
    for (const StatsColumn& c : m_run.stats) groups.push_back({c.name.toStdString(), c.group, {}, c.stats});
    return writeText(path, statsCsv(core::calib::statsRows(groups)), error);
}

bool CalibController::exportRanking(const QString& path, QString* error) const {
    if (!m_run.hasMatch || !m_run.match.ok) return fail(error, "no candidate ranking to export");
    return writeText(path, rankingCsv(m_run.data->features, m_run.match), error);
}

}  // namespace lwb::ui
