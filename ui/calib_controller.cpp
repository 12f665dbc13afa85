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
#include "core/sim/calib_sim.hpp"

namespace lwb::ui {

using namespace core::calib;
namespace sim = core::sim;

namespace {

const QString kDemo = QStringLiteral("demo");

// The demo's fixed seeds and features (paper 002's beam-1 case: a 2.9 m wood).
constexpr uint64_t kDetectorSeed = 20230611, kPointingSeed = 20230612, kCheckSeed = 20230613, kWaveSeed = 20230614;
constexpr double kDemoFeatureHeight = 2.93;

sim::DetectorSimParams demoDetectorParams() {
    // The GF-7-like footprint of the simulator (1σ 3.75 m) over a 2.5 m grid, denser than the
    // simulator's 5 m default so the demo footprint covers a few dozen detectors.
    sim::DetectorSimParams p;
    p.rows = 61;
    p.columns = 41;
    p.spacingM = 2.5;
    p.triggerThreshold = 20;
    return p;
}

std::string fx(double v, int d) { return std::isfinite(v) ? core::formatFixed(v, d) : std::string(); }
std::string gx(double v) { return std::isfinite(v) ? core::formatDouble(v, 10) : std::string(); }

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
                const sim::DetectorSimulation s = sim::simulateDetectorArray(demoDetectorParams(), kDetectorSeed);
                d->array = s.array;
                d->array.source = "demo detector array";
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
                sim::CalibSimParams p;  // 4 passes, both beams, the paper's error magnitudes
                const sim::CalibSimulation s = sim::simulateCalibration(p, kPointingSeed);
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
                sim::CalibSimParams p;
                p.passes = 22;  // paper 002 validates on 22 and 24 points
                d->checkPoints = sim::simulateCalibration(p, kCheckSeed).points;
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
            return true;
        }
        case Part::Waveform: {
            d->waveform = {};
            d->trueHeightM = NAN;
            if (in.waveform.isEmpty()) return true;
            if (in.waveform == kDemo) {
                sim::WaveformSimParams p;
                p.heightM = kDemoFeatureHeight;
                d->waveform = sim::simulateWaveform(p, kWaveSeed).waveform;
                d->trueHeightM = p.heightM;
                return true;
            }
            // The sample interval is a waveform parameter; files with a time column ignore it.
            Waveform w;
            if (!readWaveformCsv(in.waveform.toStdString(), 0.5, &w, &err)) return fail(error, err);
            d->waveform = std::move(w);
            return true;
        }
        case Part::Features: {
            d->features.clear();
            if (in.features.isEmpty()) return true;
            if (in.features == kDemo) {
                const struct {
                    const char* id;
                    double e, n, h;
                } f[] = {{"wood W1", -12.5, 8.0, 2.90}, {"shed S2", 6.0, -14.5, 2.45}, {"hedge H3", 15.2, 3.1, 3.35},
                         {"wall M4", -3.4, -6.7, 1.60}, {"tree row T5", 21.0, 17.5, 4.20}, {"building B6", -25.0, -20.0, 6.40}};
                for (const auto& x : f) {
                    FeatureCandidate c;
                    c.id = x.id;
                    c.e = x.e;
                    c.n = x.n;
                    c.heightM = x.h;
                    d->features.push_back(c);
                }
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

// The statistics of the run: differences file > check points after calibration > the control
// points' own residuals after calibration.
void computeStats(const CalibData& d, CalibRun& run) {
    auto add = [&](const QString& name, std::vector<double> v) {
        StatsColumn c;
        c.name = name;
        c.d = std::move(v);
        c.stats = elevationStats(c.d);
        if (!c.stats.ok && run.statsError.isEmpty()) run.statsError = name + ": " + QString::fromStdString(c.stats.error);
        run.stats.push_back(std::move(c));
    };
    if (!d.differences.empty()) {
        run.statsSource = QObject::tr("Elevation differences from %1").arg(QFileInfo(d.inputs.differences).fileName());
        for (const auto& g : d.differences)
            add(g.group.empty() ? QObject::tr("all") : (d.inputs.groupColumn.isEmpty() ? QString() : d.inputs.groupColumn + " ") +
                                                           QString::fromStdString(g.group),
                g.d);
        return;
    }
    if (!run.hasPointing || !run.pointing.ok) {
        if (!d.checkPoints.empty() || !d.points.empty())
            run.statsError = QObject::tr("no statistics: the pointing calibration did not succeed");
        return;
    }
    std::vector<int> beamIds;
    for (const auto& b : d.beams) beamIds.push_back(b.id);
    if (!d.checkPoints.empty()) {
        run.check = checkCalibration(d.beams, run.pointing, d.checkPoints);
        run.hasCheck = true;
        if (!run.check.ok) {
            run.statsError = QObject::tr("check points: %1").arg(QString::fromStdString(run.check.error));
            return;
        }
        run.statsSource = QObject::tr("Height differences laser − control at %1 independent check points, calibrated")
                              .arg(run.check.points.size());
        for (int id : beamIds) {
            std::vector<double> v = heightDifferences(run.check, id);
            if (!v.empty()) add(QObject::tr("beam %1").arg(id), std::move(v));
        }
        return;
    }
    run.statsSource = QObject::tr("Height residuals of the %1 control points after calibration (not independent)")
                          .arg(run.pointing.residuals.size());
    for (int id : beamIds) {
        std::vector<double> v;
        for (const auto& r : run.pointing.residuals)
            if (r.beam == id) v.push_back(r.after.u);
        if (!v.empty()) add(QObject::tr("beam %1").arg(id), std::move(v));
    }
}

CalibRun compute(std::shared_ptr<const CalibData> data, const CalibParams& p) {
    const CalibData& d = *data;
    CalibRun run;
    run.data = data;
    run.params = p;
    if (!d.array.detectors.empty()) {
        run.hasDetector = true;
        run.detector = fitDetectorArray(d.array, p.detector);
    }
    if (!d.points.empty()) {
        run.hasPointing = true;
        run.pointing = calibratePointing(d.beams, d.points, p.pointing);
    }
    computeStats(d, run);
    if (!d.waveform.amplitude.empty()) {
        run.hasWaveform = true;
        run.waveform = decomposeWaveform(d.waveform, p.waveform);
        if (run.waveform.ok && !d.features.empty()) {
            run.hasMatch = true;
            run.match = matchFeature(d.features, run.waveform.heightM, p.match);
        }
    }
    return run;
}

// JSON helpers: a missing key keeps the default; a wrong type is an error naming the key.
struct JsonReader {
    QString section;
    QString* error;
    bool ok = true;
    void num(const QJsonObject& o, const char* key, double* v) {
        if (!ok || !o.contains(key)) return;
        if (!o[key].isDouble()) {
            *error = QObject::tr("%1.%2 must be a number").arg(section, key);
            ok = false;
            return;
        }
        *v = o[key].toDouble();
    }
    void integer(const QJsonObject& o, const char* key, int* v) {
        double x = *v;
        num(o, key, &x);
        if (ok && o.contains(key)) {
            if (x != std::floor(x) || std::fabs(x) > 1e9) {
                *error = QObject::tr("%1.%2 must be a whole number").arg(section, key);
                ok = false;
                return;
            }
            *v = int(x);
        }
    }
    void boolean(const QJsonObject& o, const char* key, bool* v) {
        if (!ok || !o.contains(key)) return;
        if (!o[key].isBool()) {
            *error = QObject::tr("%1.%2 must be true or false").arg(section, key);
            ok = false;
            return;
        }
        *v = o[key].toBool();
    }
    template <class E>
    void choice(const QJsonObject& o, const char* key, E* v, std::initializer_list<std::pair<const char*, E>> names) {
        if (!ok || !o.contains(key)) return;
        const QString s = o[key].toString();
        for (const auto& [n, e] : names)
            if (s == n) {
                *v = e;
                return;
            }
        QStringList all;
        for (const auto& [n, e] : names) all << n;
        *error = QObject::tr("%1.%2 must be one of %3, not \"%4\"").arg(section, key, all.join(", "), s);
        ok = false;
    }
};

}  // namespace

bool CalibInputs::operator==(const CalibInputs& o) const {
    return detectors == o.detectors && controlPoints == o.controlPoints && beams == o.beams && checkPoints == o.checkPoints &&
           differences == o.differences && groupColumn == o.groupColumn && waveform == o.waveform && features == o.features;
}

QString validateCalibParams(const CalibParams& p) {
    if (std::string e = validate(p.detector); !e.empty()) return QObject::tr("detector fit: %1").arg(QString::fromStdString(e));
    if (std::string e = validate(p.pointing); !e.empty()) return QObject::tr("pointing calibration: %1").arg(QString::fromStdString(e));
    if (std::string e = validate(p.waveform); !e.empty()) return QObject::tr("waveform: %1").arg(QString::fromStdString(e));
    if (std::string e = validate(p.match); !e.empty()) return QObject::tr("feature match: %1").arg(QString::fromStdString(e));
    if (p.pointing.fixRelativeRotation && p.pointing.model != CalibModel::DualBeam)
        return QObject::tr("pointing calibration: fixing the relative rotation needs the dual-beam model");
    return {};
}

QJsonObject calibParamsToJson(const CalibParams& p) {
    QJsonObject d;
    d["model"] = surfaceModelName(p.detector.model);
    d["noise"] = p.detector.noise == NoiseSource::Given ? "given" : "data";
    d["fit_background"] = p.detector.fitBackground;
    d["background"] = p.detector.background;
    d["trigger"] = p.detector.triggerThreshold;
    d["saturation"] = p.detector.saturationLevel;
    d["rel_noise"] = p.detector.relativeNoise;
    d["noise_floor"] = p.detector.noiseFloor;
    d["scale_chi2"] = p.detector.scaleByChi2;
    QJsonObject q;
    q["model"] = calibModelName(p.pointing.model);
    q["solve_range"] = p.pointing.solveRange;
    q["fix_relative"] = p.pointing.fixRelativeRotation;
    q["sigma_h"] = p.pointing.sigmaHorizontalM;
    q["sigma_v"] = p.pointing.sigmaVerticalM;
    q["sigma_range"] = p.pointing.sigmaRangeM;
    q["sigma_attitude_urad"] = p.pointing.sigmaAttitudeRad * 1e6;
    q["sigma_orbit"] = p.pointing.sigmaOrbitM;
    q["scale_chi2"] = p.pointing.scaleByChi2;
    QJsonObject w;
    w["sample_interval_ns"] = p.waveform.sampleIntervalNs;
    w["smooth_ns"] = p.waveform.smoothSigmaNs;
    w["min_separation_ns"] = p.waveform.minSeparationNs;
    w["min_second_peak"] = p.waveform.minSecondPeak;
    w["incidence_deg"] = p.waveform.incidenceDeg;
    w["thred_h"] = p.match.thresholdM;
    QJsonObject o;
    o["detector"] = d;
    o["pointing"] = q;
    o["waveform"] = w;
    return o;
}

bool calibParamsFromJson(const QJsonObject& o, CalibParams* out, QString* error) {
    CalibParams p;
    JsonReader r{"detector", error};
    const QJsonObject d = o["detector"].toObject();
    r.choice(d, "model", &p.detector.model,
             {{"auto", SurfaceModel::Auto}, {"elliptical", SurfaceModel::Elliptical}, {"circular", SurfaceModel::Circular}});
    r.choice(d, "noise", &p.detector.noise, {{"data", NoiseSource::FromData}, {"given", NoiseSource::Given}});
    r.boolean(d, "fit_background", &p.detector.fitBackground);
    r.num(d, "background", &p.detector.background);
    r.num(d, "trigger", &p.detector.triggerThreshold);
    r.num(d, "saturation", &p.detector.saturationLevel);
    r.num(d, "rel_noise", &p.detector.relativeNoise);
    r.num(d, "noise_floor", &p.detector.noiseFloor);
    r.boolean(d, "scale_chi2", &p.detector.scaleByChi2);
    r.section = "pointing";
    const QJsonObject q = o["pointing"].toObject();
    r.choice(q, "model", &p.pointing.model, {{"single", CalibModel::SingleBeam}, {"dual", CalibModel::DualBeam}});
    r.boolean(q, "solve_range", &p.pointing.solveRange);
    r.boolean(q, "fix_relative", &p.pointing.fixRelativeRotation);
    r.num(q, "sigma_h", &p.pointing.sigmaHorizontalM);
    r.num(q, "sigma_v", &p.pointing.sigmaVerticalM);
    r.num(q, "sigma_range", &p.pointing.sigmaRangeM);
    double att = p.pointing.sigmaAttitudeRad * 1e6;
    r.num(q, "sigma_attitude_urad", &att);
    p.pointing.sigmaAttitudeRad = att * 1e-6;
    r.num(q, "sigma_orbit", &p.pointing.sigmaOrbitM);
    r.boolean(q, "scale_chi2", &p.pointing.scaleByChi2);
    r.section = "waveform";
    const QJsonObject w = o["waveform"].toObject();
    r.num(w, "sample_interval_ns", &p.waveform.sampleIntervalNs);
    r.num(w, "smooth_ns", &p.waveform.smoothSigmaNs);
    r.num(w, "min_separation_ns", &p.waveform.minSeparationNs);
    r.num(w, "min_second_peak", &p.waveform.minSecondPeak);
    r.num(w, "incidence_deg", &p.waveform.incidenceDeg);
    r.num(w, "thred_h", &p.match.thresholdM);
    if (!r.ok) return false;
    if (const QString e = validateCalibParams(p); !e.isEmpty()) {
        *error = e;
        return false;
    }
    *out = p;
    return true;
}

// ---------------------------------------------------------------------------------------------

CalibController::CalibController(QObject* parent) : QObject(parent), m_data(std::make_shared<CalibData>()) {
    qRegisterMetaType<lwb::ui::CalibRun>();
    m_job.setWork<CalibRun>(
        [this]() -> std::function<CalibRun(core::Feedback&)> {
            const std::shared_ptr<const CalibData> data = m_data;
            const CalibParams params = m_params;
            return [data, params](core::Feedback&) { return compute(data, params); };
        },
        [this](CalibRun run) {
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

bool CalibController::openDetectors(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.detectors = path;
    auto d = std::make_shared<CalibData>(*m_data);
    if (!loadPart(Part::Detectors, in, d.get(), error)) return false;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    emit status(tr("%1: %2 detectors").arg(QFileInfo(path).fileName()).arg(d->array.detectors.size()));
    schedule();
    return true;
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
    auto d = std::make_shared<CalibData>(*m_data);
    if (!loadPart(Part::ControlPoints, in, d.get(), error)) return false;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    emit status(tr("%1: %2 control points, %3 beams").arg(QFileInfo(path).fileName()).arg(d->points.size()).arg(d->beams.size()));
    schedule();
    return true;
}

bool CalibController::openCheckPoints(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.checkPoints = path;
    in.differences.clear();  // the statistics follow the check points now
    in.groupColumn.clear();
    auto d = std::make_shared<CalibData>(*m_data);
    if (!loadPart(Part::CheckPoints, in, d.get(), error) || !loadPart(Part::Differences, in, d.get(), error)) return false;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    schedule();
    return true;
}

bool CalibController::openDifferences(const QString& path, const QString& groupColumn, QString* error) {
    CalibInputs in = inputs();
    in.differences = path;
    in.groupColumn = groupColumn;
    auto d = std::make_shared<CalibData>(*m_data);
    if (!loadPart(Part::Differences, in, d.get(), error)) return false;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    emit status(tr("%1: %2 group(s) of differences").arg(QFileInfo(path).fileName()).arg(d->differences.size()));
    schedule();
    return true;
}

bool CalibController::openWaveform(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.waveform = path;
    auto d = std::make_shared<CalibData>(*m_data);
    if (!loadPart(Part::Waveform, in, d.get(), error)) return false;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    schedule();
    return true;
}

bool CalibController::openFeatures(const QString& path, QString* error) {
    CalibInputs in = inputs();
    in.features = path;
    auto d = std::make_shared<CalibData>(*m_data);
    if (!loadPart(Part::Features, in, d.get(), error)) return false;
    d->inputs = in;
    m_data = d;
    emit inputsChanged();
    schedule();
    return true;
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
    if (!core::writeFileAtomic(path.toStdString(), s, &err)) return fail(error, err);
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
    const PointingCalibResult& r = m_run.pointing;
    std::string ps = "name,value,sd,unit\n";
    for (size_t j = 0; j < r.params.size(); ++j)
        ps += r.paramNames[j] + "," + gx(r.params[j]) + "," + gx(r.paramSd[j]) + "," +
              (r.paramNames[j].rfind("drho", 0) == 0 ? "m" : "rad") + "\n";
    return writeText(path, ps, error);
}

bool CalibController::exportIterations(const QString& path, QString* error) const {
    if (!m_run.hasPointing || !m_run.pointing.ok) return fail(error, "no pointing calibration to export");
    const PointingCalibResult& r = m_run.pointing;
    std::string is = "iteration,chi2,rms_plan_m,rms_height_m,rms_3d_m";
    for (const auto& n : r.paramNames) is += "," + n;
    is += "\n";
    for (const auto& it : r.iterations) {
        is += std::to_string(it.iteration) + "," + gx(it.chi2) + "," + fx(it.rmsPlanM, 4) + "," + fx(it.rmsHeightM, 4) + "," +
              fx(it.rms3dM, 4);
        for (double v : it.params) is += "," + gx(v);
        is += "\n";
    }
    return writeText(path, is, error);
}

bool CalibController::exportStats(const QString& path, QString* error) const {
    if (m_run.stats.empty()) return fail(error, "no validation statistics to export");
    std::string s = "group,n,mean,rms_about_zero,std_sample,std_population,min,max,median,mean_abs\n";
    for (const StatsColumn& c : m_run.stats) {
        if (!c.stats.ok) continue;
        const auto& t = c.stats.stats;
        s += core::csvEscape(c.name.toStdString()) + "," + std::to_string(t.n) + "," + fx(t.mean, 6) + "," +
             fx(t.rmsAboutZero, 6) + "," + fx(t.stdSample, 6) + "," + fx(t.stdPopulation, 6) + "," + fx(t.min, 6) + "," +
             fx(t.max, 6) + "," + fx(t.median, 6) + "," + fx(t.meanAbs, 6) + "\n";
    }
    return writeText(path, s, error);
}

bool CalibController::exportRanking(const QString& path, QString* error) const {
    if (!m_run.hasMatch || !m_run.match.ok) return fail(error, "no candidate ranking to export");
    const FeatureMatchResult& mr = m_run.match;
    const auto& cands = m_run.data->features;
    std::string s = "rank,id,h_m,delta_h_m,below_threshold,chosen\n";
    for (size_t k = 0; k < mr.ranking.size(); ++k) {
        const auto& d = mr.ranking[k];
        s += std::to_string(k + 1) + "," + core::csvEscape(cands[d.index].id) + "," + gx(cands[d.index].heightM) + "," +
             fx(d.deltaHM, 4) + "," + (d.belowThreshold ? "1" : "0") + "," + (mr.found && k == 0 ? "1" : "0") + "\n";
    }
    return writeText(path, s, error);
}

}  // namespace lwb::ui
