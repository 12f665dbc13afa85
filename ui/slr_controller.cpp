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

#include "core/slr/pass_output.hpp"
#include "core/slr/pass_run.hpp"

namespace lwb::ui {

using namespace core::slr;

SlrController::SlrController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<lwb::ui::SlrRun>();
    m_presetFile = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/slr-presets.json";
    m_job.bind(
        [this](TaskJob<PassTask>::Run* r) {
            if (!hasPass()) return false;
            auto in = std::make_shared<PassTask::Inputs>();
            in->pass = m_passData;
            in->forced = m_forced;
            r->inputs = std::move(in);
            r->params = m_params;
            // The pass's normal-point context, as the CLI gives it (core passNormalPointContext:
            // the C1 fire rate, the station from the SINEX file), over what the parameters leave
            // unknown: the same normal points in both (issue 28).
            passNormalPointContext(m_pass, m_sources && m_sources->haveStations ? &m_sources->stations : nullptr,
                                   &r->params.postfit);
            // What this run reuses: the last screening (only the post-fit or the edits changed),
            // or, when reuseScaleForCosine is set (off by default), the scale the automatic mode
            // chose while only C moved; else nothing. (A screening at a kept scale is not the one
            // laserwb-cli makes at that C: "one answer everywhere" wins over the 0.15 s of a
            // 10^5-point pass's scale search, docs/benchmarks.md.)
            if (!m_screenDue && m_run->screen.ok) r->reuse.screen = std::shared_ptr<const ScreenResult>(m_run, &m_run->screen);
            else if (m_screenDue && m_scaleValid && m_params.screen.automatic) r->reuse.scale = m_scale;
            return true;
        },
        [this](PassRunResult result) {
            SlrRun run;
            static_cast<PassRunResult&>(run) = std::move(result);
            run.generation = m_job.generation();
            run.latencyMs = double(QDateTime::currentMSecsSinceEpoch() - m_job.changedAt());
            if (!run.screen.ok) {
                notePassError(m_selected, tr("screening: %1").arg(QString::fromStdString(run.screen.error)));
                emit runFailed(QString::fromStdString(run.screen.error));
                return;
            }
            if (!run.screenReused) {
                ++m_screenings;
                m_screenDue = false;
                // The automatic choice: reused while only C moves.
                if (!run.scaleReused) {
                    m_scale = scaleChoice(run.screen);
                    m_scaleValid = m_params.screen.automatic;
                }
            }
            m_run = std::make_shared<const SlrRun>(std::move(run));
            emit runReady(*m_run);
        });
}

SlrController::~SlrController() { m_job.cancel(); }

void SlrController::passLoaded() {
    m_passData = std::make_shared<const PassData>(m_pass);
    m_screenDue = true;
    m_scaleValid = false;
    m_screenings = 0;
    m_run = std::make_shared<const SlrRun>();
    m_forced.assign(m_pass.t.size(), 0);
}

namespace {
// The CPF (file or folder) and SINEX of `in`, read once for the passes of a file (the CPF is
// used with the SINEX only; the SINEX alone gives the station's position).
bool readSources(const PassInputParams& in, std::shared_ptr<const PassSources>* out, QString* error) {
    auto sources = std::make_shared<PassSources>();
    std::string err;
    // The SINEX file alone still places the station (day or night per normal-point bin), as
    // laserwb-cli slr --stations does.
    if (!in.sinexPath.empty() && !readPassSources(in, sources.get(), &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    *out = sources;
    return true;
}
}  // namespace

void SlrController::resetPassErrors() {
    // What is known from reading the file alone (blocks that cannot be a pass).
    m_passErrors.clear();
    for (const PassSummary& s : m_passes)
        if (!s.problem.empty()) m_passErrors[s.index] = QString::fromStdString(s.problem);
}

bool SlrController::open(const QString& path, int passIndex, const PassInputParams& input, QString* error) {
    PassInputParams in = input;
    in.cpfFallback = true;  // a CPF that does not fit the pass: its own TOF trend, with a note
    if (!isCrdFile(path.toStdString())) {
        const PassInputResult r = passFromOcTable(path.toStdString());
        if (!r.ok) {
            *error = QString::fromStdString(r.error);
            return false;
        }
        m_crd.reset();
        m_sources = std::make_shared<const PassSources>();
        m_input = in;
        m_path = path;
        m_passErrors.clear();
        m_passes = r.passes;
        m_selected = 0;
        m_passProblem.clear();
        m_warnings = r.warnings;
        m_pass = r.pass;
        passOpened();
        return true;
    }
    auto crd = std::make_shared<CrdReadResult>(readCrd(path.toStdString()));
    if (!crd->ok) {
        *error = QString::fromStdString(crd->error);
        for (size_t i = 0; i < crd->warnings.size() && i < 5; ++i) *error += "\n" + QString::fromStdString(crd->warnings[i]);
        return false;
    }
    std::shared_ptr<const PassSources> sources;
    if (!readSources(in, &sources, error)) return false;
    m_crd = crd;
    m_sources = sources;
    m_input = in;
    m_path = path;
    m_passes = summarisePasses(crd->file);
    resetPassErrors();
    // -1: the first pass with full-rate records (when none has any, passFromCrd says what the file holds).
    for (size_t i = 0; passIndex < 0 && i < crd->file.passes.size(); ++i)
        if (!crd->file.passes[i].ranges.empty()) passIndex = int(i);
    m_selected = passIndex;
    loadSelected(nullptr);
    return true;
}

bool SlrController::selectPass(int index, QString* error) {
    if (!m_crd) {
        if (error) *error = tr("no CRD file is open");
        return false;
    }
    m_selected = index;
    return loadSelected(error);
}

bool SlrController::setSources(const QString& cpfPath, const QString& sinexPath, QString* error) {
    PassInputParams in = m_input;
    in.cpfPath = cpfPath.toStdString();
    in.sinexPath = sinexPath.toStdString();
    in.cpfFallback = true;
    std::shared_ptr<const PassSources> sources;
    if (!readSources(in, &sources, error)) return false;
    m_input = in;
    m_sources = sources;
    if (m_crd) {
        // What was known against the passes may have been the old prediction's doing.
        resetPassErrors();
        loadSelected(nullptr);
    }
    return true;
}

void SlrController::notePassError(int index, const QString& why) {
    if (index < 0) return;
    m_passErrors[index] = why;
    emit passListChanged();
}

bool SlrController::loadSelected(QString* error) {
    const PassInputResult r = passFromCrd(m_crd, m_path.toStdString(), m_selected, m_input, *m_sources);
    m_warnings = r.warnings;
    if (!r.ok) {
        // No pass open, the list stays: the reason is shown in place and against the pass.
        m_passProblem = QString::fromStdString(r.error);
        notePassError(m_selected, m_passProblem.section('\n', 0, 0));
        m_job.cancel();  // a run of the previous pass is not delivered
        m_pass = PassData{};
        m_pass.source = m_path.toStdString();
        m_pass.passIndex = m_selected;
        m_truth.clear();
        passLoaded();
        emit passChanged();
        emit editsChanged();
        emit status(tr("Pass %1 cannot be processed: %2").arg(m_selected + 1).arg(m_passProblem.section('\n', 0, 0)));
        if (error) *error = m_passProblem;
        return false;
    }
    m_passProblem.clear();
    m_pass = r.pass;
    m_selected = m_pass.passIndex;
    if (m_passErrors.remove(m_selected)) emit passListChanged();
    passOpened();
    return true;
}

void SlrController::passOpened() {
    m_truth.clear();
    passLoaded();
    m_params.postfit.altitudeKm = m_pass.altitudeKm;
    m_params.postfit.binLengthS = 0;
    for (const auto& w : m_warnings) emit status(QString::fromStdString(w));
    const bool preset = applySatellitePreset();
    emit passChanged();
    emit editsChanged();
    emit status(tr("%1: %2 points, O-C from %3%4")
                    .arg(QFileInfo(m_path).fileName())
                    .arg(m_pass.t.size())
                    .arg(QString::fromStdString(m_pass.ocOrigin))
                    .arg(preset ? tr("; preset of %1 applied").arg(QString::fromStdString(m_pass.satellite)) : QString()));
    m_job.schedule();
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
    m_crd.reset();
    m_path.clear();
    m_passProblem.clear();
    m_passErrors.clear();
    m_selected = 0;
    m_truth = truth;
    passLoaded();
    m_params.postfit.altitudeKm = altitudeKm;
    applySatellitePreset();  // as for a pass read from a file
    emit passChanged();
    emit editsChanged();
    m_job.schedule();
}

void SlrController::setParams(const SlrParams& p) {
    // The earliest stage the change touches, from the schema rows' stage tags.
    const int stage = slrSchema().firstChangedStage(m_params, p);
    m_params = p;
    if (stage < 0) return;
    if (stage <= kStageRecovery) {
        m_screenDue = true;
        if (stage == kStageScale || !m_reuseScaleForCosine) m_scaleValid = false;
    }
    m_job.schedule();
}

void SlrController::forcePoints(const std::vector<uint32_t>& indices, bool in) {
    if (indices.empty()) return;
    for (uint32_t i : indices) m_forced[i] = in ? 1 : -1;
    emit editsChanged();
    m_job.schedule();
}

void SlrController::setForced(const std::vector<int8_t>& forced) {
    if (forced.size() != m_forced.size() || forced == m_forced) return;
    m_forced = forced;
    emit editsChanged();
    m_job.schedule();
}

void SlrController::clearEdits() {
    std::fill(m_forced.begin(), m_forced.end(), 0);
    emit editsChanged();
    m_job.schedule();
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
    // The settings as the analyst has them: the automatic mode stays on unless it was turned off
    // (then the panel holds the scale it had chosen). Storing the chosen scale with the automatic
    // mode off lost the refinement and the track following: STELLA reopened with 70 of 236
    // points accepted instead of 150 (issue 28).
    p.screen = m_params.screen;
    p.postfit = m_params.postfit;
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
    const double altitude = m_params.postfit.altitudeKm;
    m_params = {p->screen, p->postfit};
    if (!(m_params.postfit.altitudeKm > 0)) m_params.postfit.altitudeKm = altitude;
    m_screenDue = true;
    m_scaleValid = false;
    return true;
}

bool SlrController::exportCsv(const QString& path, QString* error) const {
    if (!hasRun()) {
        *error = tr("no screening result to export");
        return false;
    }
    std::string err;
    if (!writeScreenCsv(path.toStdString(), m_pass, m_run->screen, m_run->accepted, &m_run->post, &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrController::exportCrd(const QString& path, QString* error, bool wholeFile) const {
    if (!hasRun()) {
        *error = tr("no screening result to export");
        return false;
    }
    std::string err;
    PassData pass;
    const PassData* out = &m_pass;
    if (!wholeFile && m_pass.hasCrd && m_pass.passIndex >= 0 && size_t(m_pass.passIndex) < m_pass.crd->passes.size()) {
        // This pass alone: its headers and records, the file's trailer (H9).
        pass = m_pass;
        auto alone = std::make_shared<core::slr::CrdFile>(*m_pass.crd);
        alone->passes = {m_pass.crd->passes[size_t(m_pass.passIndex)]};
        pass.crd = alone;
        pass.passIndex = 0;
        out = &pass;
    }
    if (!writeScreenedCrd(path.toStdString(), *out, m_run->accepted, &err)) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrController::exportNormalPoints(const QString& path, QString* error) const {
    if (!hasRun() || !m_run->post.ok || m_run->post.normalPoints.empty()) {
        *error = hasRun() && !m_run->postNote.empty() ? QString::fromStdString(m_run->postNote) : tr("no normal points to export");
        return false;
    }
    std::string err;
    if (!writeNormalPointCrd(path.toStdString(), m_pass, m_run->post.normalPoints, &err,
                             normalPointProduct(&m_run->post, &m_run->screen, std::string()))) {
        *error = QString::fromStdString(err);
        return false;
    }
    return true;
}

bool SlrController::waitIdle(int timeoutMs) { return m_job.waitIdle(timeoutMs); }

}  // namespace lwb::ui
