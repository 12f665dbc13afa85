#include "ui/calib/calib_controller.hpp"

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
#include "ui/kit/session_json.hpp"

namespace lwb::ui {

using namespace core::calib;
namespace sim = core::sim;

namespace {

const QString kDemo = QStringLiteral("demo");

bool fail(QString* error, const std::string& msg) {
    if (error) *error = QString::fromStdString(msg);
    return false;
}

// The sources of a part as the core reads them (core/calib/calib_run.hpp: loadCalibPart).
CalibSources sourcesOf(const CalibInputs& in) {
    CalibSources s;
    s.detectors = in.detectors.toStdString();
    s.controlPoints = in.controlPoints.toStdString();
    s.beams = in.beams.toStdString();
    s.checkPoints = in.checkPoints.toStdString();
    s.differences = in.differences.toStdString();
    s.groupColumn = in.groupColumn.toStdString();
    s.waveform = in.waveform.toStdString();
    s.features = in.features.toStdString();
    return s;
}

// The built-in demo's part ("demo" as its source): simulated inputs with their truth. False
// when the part's source is not the demo.
bool loadDemoPart(CalibPart part, const CalibInputs& in, CalibData* d, QString* error) {
    switch (part) {
        case CalibPart::Detectors: {
            if (in.detectors != kDemo) return false;
            const sim::DetectorSimulation s = sim::demoDetectorArray();
            d->array = s.array;
            d->detectorTruth = s.truth;
            d->hasDetectorTruth = true;
            return true;
        }
        case CalibPart::ControlPoints: {
            if (in.controlPoints != kDemo) return false;
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
        case CalibPart::CheckPoints:
            if (in.checkPoints != kDemo) return false;
            d->checkPoints = sim::demoCheckPoints();
            return true;
        case CalibPart::Differences:
            if (in.differences != kDemo) return false;
            if (error) *error = QObject::tr("the demo has no differences file (its statistics come from check points)");
            return true;
        case CalibPart::Waveform:
            if (in.waveform != kDemo) return false;
            d->waveform = sim::demoWaveform();
            d->trueHeightM = sim::kDemoFeatureHeightM;
            return true;
        case CalibPart::Features:
            if (in.features != kDemo) return false;
            d->features = sim::demoFeatures();
            return true;
    }
    return false;
}

// Loads one part of the inputs into d ("demo", a path, or empty = none): the demo's here, a
// file's by the core.
bool loadPart(CalibPart part, const CalibInputs& in, CalibData* d, QString* error) {
    std::string err;
    (void)loadCalibPart(part, CalibSources{}, d, &err);  // the part cleared
    QString demoError;
    if (loadDemoPart(part, in, d, &demoError)) return demoError.isEmpty() ? true : fail(error, demoError.toStdString());
    CalibSources src = sourcesOf(in);
    if (src.beams == kDemo.toStdString()) {  // control points of a file with the demo's (GF-7's) beam designs
        src.beams.clear();
        src.givenBeams = sim::gf7Beams();
    }
    return loadCalibPart(part, src, d, &err) || fail(error, err);
}

// Loads every part whose source differs from `have` (all when have is null).
bool loadChanged(const CalibInputs& in, const CalibData* have, CalibData* d, QString* error) {
    struct P {
        CalibPart part;
        bool changed;
    } parts[] = {
        {CalibPart::Detectors, !have || in.detectors != have->inputs.detectors},
        {CalibPart::ControlPoints, !have || in.controlPoints != have->inputs.controlPoints || in.beams != have->inputs.beams},
        {CalibPart::CheckPoints, !have || in.checkPoints != have->inputs.checkPoints},
        {CalibPart::Differences, !have || in.differences != have->inputs.differences || in.groupColumn != have->inputs.groupColumn},
        {CalibPart::Waveform, !have || in.waveform != have->inputs.waveform},
        {CalibPart::Features, !have || in.features != have->inputs.features},
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
    QString err;
    std::shared_ptr<const CalibData> d = readInputs(in, &err);
    if (!d) {
        if (error) *error = err;
        emit status(err);
        return false;
    }
    adoptInputs(std::move(d));
    return true;
}

std::shared_ptr<const CalibData> CalibController::readInputs(const CalibInputs& in, QString* error) const {
    auto d = std::make_shared<CalibData>(*m_data);
    const bool same = in == m_data->inputs;
    // Reload every part that changed (files are re-read when asked for the same path again).
    if (!loadChanged(in, same ? nullptr : m_data.get(), d.get(), error)) return nullptr;
    return d;
}

void CalibController::adoptInputs(std::shared_ptr<const CalibData> data) {
    m_data = std::move(data);
    emit inputsChanged();
    schedule();
}

// Loads the given parts of `in` over a copy of the current inputs and adopts it; on an error
// the inputs stay. Returns the new data (null on error).
std::shared_ptr<const CalibData> CalibController::replaceParts(const CalibInputs& in, std::initializer_list<int> parts,
                                                              QString* error) {
    auto d = std::make_shared<CalibData>(*m_data);
    for (int p : parts)
        if (!loadPart(static_cast<CalibPart>(p), in, d.get(), error)) return nullptr;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    schedule();
    return d;
}

bool CalibController::openDetectors(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.detectors = path;
    const auto d = replaceParts(in, {int(CalibPart::Detectors)}, error);
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
    const auto d = replaceParts(in, {int(CalibPart::ControlPoints)}, error);
    if (d)
        emit status(tr("%1: %2 control points, %3 beams").arg(QFileInfo(path).fileName()).arg(d->points.size()).arg(d->beams.size()));
    return d != nullptr;
}

bool CalibController::openCheckPoints(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.checkPoints = path;
    in.differences.clear();  // the statistics follow the check points now
    in.groupColumn.clear();
    return replaceParts(in, {int(CalibPart::CheckPoints), int(CalibPart::Differences)}, error) != nullptr;
}

bool CalibController::openDifferences(const QString& path, const QString& groupColumn, QString* error) {
    CalibInputs in = inputs();
    in.differences = path;
    in.groupColumn = groupColumn;
    const auto d = replaceParts(in, {int(CalibPart::Differences)}, error);
    if (d) emit status(tr("%1: %2 group(s) of differences").arg(QFileInfo(path).fileName()).arg(d->differences.size()));
    return d != nullptr;
}

bool CalibController::openWaveform(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.waveform = path;
    return replaceParts(in, {int(CalibPart::Waveform)}, error) != nullptr;
}

bool CalibController::openFeatures(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.features = path;
    return replaceParts(in, {int(CalibPart::Features)}, error) != nullptr;
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
