#include "ui/slr_controller.hpp"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPointer>
#include <QStandardPaths>
#include <QThreadPool>
#include <QtConcurrent>

namespace lwb::ui {

using namespace core::slr;

SlrController::SlrController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<lwb::ui::SlrRun>();
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(15);  // coalesces a burst of slider events; the screening itself is the latency
    connect(&m_debounce, &QTimer::timeout, this, &SlrController::start);
    m_presetFile = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/slr-presets.json";
}

SlrController::~SlrController() {
    if (m_feedback) m_feedback->cancel();
    QThreadPool::globalInstance()->waitForDone(10000);
}

bool SlrController::open(const QString& path, int passIndex, const PassInputParams& input, QString* error) {
    const PassInputResult r = loadPass(path.toStdString(), passIndex, input);
    if (!r.ok) {
        *error = QString::fromStdString(r.error);
        return false;
    }
    m_input = input;
    m_pass = r.pass;
    m_passes = r.passes;
    m_warnings = r.warnings;
    m_truth.clear();
    m_autoScale.valid = false;
    m_forced.assign(m_pass.t.size(), 0);
    m_edits.clear();
    m_postfit.altitudeKm = m_pass.altitudeKm;
    m_postfit.binLengthS = 0;
    for (const auto& w : r.warnings) emit status(QString::fromStdString(w));
    const bool preset = applySatellitePreset();
    emit passChanged();
    emit editsChanged();
    emit status(tr("%1: %2 points, O-C from %3%4")
                    .arg(QFileInfo(path).fileName())
                    .arg(m_pass.t.size())
                    .arg(QString::fromStdString(m_pass.ocOrigin))
                    .arg(preset ? tr("; preset of %1 applied").arg(QString::fromStdString(m_pass.satellite)) : QString()));
    schedule();
    return true;
}

void SlrController::setSimulatedPass(const std::vector<double>& t, const std::vector<double>& oc,
                                     const std::vector<double>& tof, const std::vector<uint8_t>& truth,
                                     const QString& name, double altitudeKm) {
    m_pass = PassData{};
    m_pass.source = name.toStdString();
    m_pass.satellite = name.toStdString();
    m_pass.ocOrigin = "simulation";
    m_pass.t = t;
    m_pass.oc = oc;
    m_pass.tof = tof;
    m_pass.altitudeKm = altitudeKm;
    m_passes.clear();
    m_warnings.clear();
    m_truth = truth;
    m_autoScale.valid = false;
    m_forced.assign(t.size(), 0);
    m_edits.clear();
    m_postfit.altitudeKm = altitudeKm;
    emit passChanged();
    emit editsChanged();
    schedule();
}

void SlrController::setScreenParams(const ScreenParams& p) {
    const ScreenParams& q = m_screen;
    const bool onlyCosine = p.automatic == q.automatic && p.magT == q.magT && p.magOc == q.magOc &&
                            p.areaLimit == q.areaLimit && p.connectivity == q.connectivity &&
                            p.slopeNeighbours == q.slopeNeighbours && p.slopeBinDeg == q.slopeBinDeg &&
                            p.slopePeakFraction == q.slopePeakFraction && p.slopeAgreeFraction == q.slopeAgreeFraction &&
                            p.maxSlopeRangeDeg == q.maxSlopeRangeDeg && p.slopeBlockRegions == q.slopeBlockRegions &&
                            p.pieceRows == q.pieceRows && p.recoveryGapFactor == q.recoveryGapFactor &&
                            p.areaTolerance == q.areaTolerance && p.autoMaxPoints == q.autoMaxPoints;
    if (!onlyCosine || !m_reuseScaleForCosine) m_autoScale.valid = false;
    m_screen = p;
    schedule();
}

void SlrController::setPostfitParams(const PostfitParams& p) {
    m_postfit = p;
    schedule();
}

void SlrController::schedule() {
    ++m_generation;
    m_changedAt = QDateTime::currentMSecsSinceEpoch();
    if (m_feedback) m_feedback->cancel();  // the running job is stale now
    m_debounce.start();
}

void SlrController::start() {
    if (!hasPass()) return;
    auto fb = std::make_shared<core::Feedback>();
    m_feedback = fb;
    m_running = true;
    const quint64 gen = m_generation;
    const qint64 t0 = m_changedAt;
    // Copies for the worker: the pass vectors are shared read-only through a snapshot.
    auto t = std::make_shared<const std::vector<double>>(m_pass.t);
    auto oc = std::make_shared<const std::vector<double>>(m_pass.oc);
    auto tof = std::make_shared<const std::vector<double>>(m_pass.tof);
    ScreenParams sp = m_screen;
    const bool reused = sp.automatic && m_autoScale.valid;
    if (reused) {
        sp.magT = m_autoScale.magT;
        sp.magOc = m_autoScale.magOc;
        sp.areaLimit = m_autoScale.areaLimit;
        sp.connectivity = m_autoScale.connectivity;
    }
    PostfitParams pp = m_postfit;
    const std::vector<int8_t> forced = m_forced;
    QPointer<SlrController> self(this);
    (void)QtConcurrent::run([=]() {
        SlrRun run;
        run.generation = gen;
        run.screen = screenSignal(*t, *oc, sp, fb.get());
        if (fb->isCancelled()) return;
        if (run.screen.ok) {
            run.accepted = acceptedMask(run.screen);
            for (size_t i = 0; i < run.accepted.size() && i < forced.size(); ++i)
                if (forced[i] > 0) run.accepted[i] = 1;
                else if (forced[i] < 0) run.accepted[i] = 0;
            run.post = postfit(*t, *oc, run.accepted, *tof, pp, fb.get());
        }
        if (fb->isCancelled()) return;
        QMetaObject::invokeMethod(
            qApp,
            [self, run, t0, reused]() mutable {
                if (!self || run.generation != self->m_generation) return;  // stale
                run.latencyMs = double(QDateTime::currentMSecsSinceEpoch() - t0);
                self->m_running = false;
                if (!run.screen.ok) {
                    emit self->runFailed(QString::fromStdString(run.screen.error));
                    return;
                }
                self->m_run = std::move(run);
                self->m_lastScaleReused = reused;
                const ScreenResult& r = self->m_run.screen;
                if (self->m_screen.automatic && !self->m_autoScale.valid && r.autoMagT && r.autoMagOc)
                    self->m_autoScale = {true, r.magT, r.magOc, r.areaLimit, r.connectivity};
                // The automatic choice becomes visible to the sliders (through runReady).
                emit self->runReady(self->m_run);
            },
            Qt::QueuedConnection);
    });
}

void SlrController::forcePoints(const std::vector<uint32_t>& indices, bool in) {
    if (indices.empty()) return;
    Edit e;
    e.indices = indices;
    for (uint32_t i : indices) {
        e.before.push_back(m_forced[i]);
        m_forced[i] = in ? 1 : -1;
    }
    m_edits.push_back(std::move(e));
    emit editsChanged();
    schedule();
}

bool SlrController::undoEdit() {
    if (m_edits.empty()) return false;
    const Edit e = m_edits.back();
    m_edits.pop_back();
    for (size_t k = 0; k < e.indices.size(); ++k) m_forced[e.indices[k]] = e.before[k];
    emit editsChanged();
    schedule();
    return true;
}

void SlrController::clearEdits() {
    std::fill(m_forced.begin(), m_forced.end(), 0);
    m_edits.clear();
    emit editsChanged();
    schedule();
}

void SlrController::setPresetFile(const QString& path) { m_presetFile = path; }

bool SlrController::savePreset(QString* error) {
    if (m_pass.satellite.empty() && m_pass.ilrsId.empty()) {
        *error = tr("the pass names no satellite (H3 record) to key a preset on");
        return false;
    }
    std::vector<SatellitePreset> presets;
    if (QFileInfo::exists(m_presetFile)) {
        const PresetsResult r = loadPresets(m_presetFile.toStdString());
        if (!r.ok) {
            *error = QString::fromStdString(r.error);
            return false;
        }
        presets = r.presets;
    }
    SatellitePreset p;
    p.name = m_pass.satellite;
    p.ilrsId = m_pass.ilrsId;
    p.screen = m_screen;
    // Keep the scale the automatic mode chose, so the preset reproduces this screening.
    if (hasRun() && m_screen.automatic) {
        p.screen.automatic = false;
        p.screen.magT = m_run.screen.magT;
        p.screen.magOc = m_run.screen.magOc;
        p.screen.areaLimit = m_run.screen.areaLimit;
        p.screen.connectivity = m_run.screen.connectivity;
    }
    p.postfit = m_postfit;
    bool replaced = false;
    for (auto& q : presets)
        if ((!p.ilrsId.empty() && q.ilrsId == p.ilrsId) || (p.ilrsId.empty() && q.name == p.name)) {
            q = p;
            replaced = true;
        }
    if (!replaced) presets.push_back(p);
    QDir().mkpath(QFileInfo(m_presetFile).absolutePath());
    std::string err;
    if (!savePresets(m_presetFile.toStdString(), presets, &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrController::applySatellitePreset() {
    if (!QFileInfo::exists(m_presetFile)) return false;
    const PresetsResult r = loadPresets(m_presetFile.toStdString());
    if (!r.ok) {
        emit status(tr("Presets not read: %1").arg(QString::fromStdString(r.error)));
        return false;
    }
    const SatellitePreset* p = findPreset(r.presets, m_pass.satellite, m_pass.ilrsId);
    if (!p) return false;
    m_screen = p->screen;
    const double altitude = m_postfit.altitudeKm;
    m_postfit = p->postfit;
    if (!(m_postfit.altitudeKm > 0)) m_postfit.altitudeKm = altitude;
    return true;
}

bool SlrController::exportCsv(const QString& path, QString* error) const {
    if (!hasRun()) {
        *error = tr("no screening result to export");
        return false;
    }
    std::string err;
    if (!writeScreenCsv(path.toStdString(), m_pass, m_run.screen, m_run.accepted, &m_run.post, &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrController::exportCrd(const QString& path, QString* error) const {
    if (!hasRun()) {
        *error = tr("no screening result to export");
        return false;
    }
    std::string err;
    if (!writeScreenedCrd(path.toStdString(), m_pass, m_run.accepted, &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrController::exportNormalPoints(const QString& path, QString* error) const {
    if (!hasRun() || !m_run.post.ok) {
        *error = tr("no normal points to export");
        return false;
    }
    std::string err;
    if (!writeNormalPointCrd(path.toStdString(), m_pass, m_run.post.normalPoints, &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrController::waitIdle(int timeoutMs) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (!m_running && !m_debounce.isActive()) return true;
    }
    return false;
}

}  // namespace lwb::ui
