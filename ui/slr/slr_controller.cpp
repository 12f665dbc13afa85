#include "ui/slr/slr_controller.hpp"

#include <algorithm>

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
#include "core/slr/pass_report.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/slr_run.hpp"

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
            // The parameters as every front end resolves them (core resolvePassParams): the
            // panel's, as a config, with what the pass tells (fire rate, ILRS bin, the station's
            // position) wherever they leave it unknown: the CLI's normal points (issue 28, 40).
            core::slr::SlrSetup setup = m_setup;
            setup.sources.config = slrSchema().toJson(m_params);
            PassSettings settings;
            SlrError e;
            if (!resolvePassParams(setup, *m_passData, &settings, &e)) {
                emit runFailed(QString::fromStdString(e.message));
                return false;
            }
            r->params = settings.params;
            m_settings = std::move(settings);
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
    // A run that threw (memory ran out) is said where a failed screening is.
    connect(&m_job, &LiveJob::failed, this, [this](const QString& why) {
        notePassError(m_selected, why);
        emit runFailed(why);
    });
}

SlrController::~SlrController() { m_job.cancel(); }

void SlrController::passLoaded() {
    m_screenDue = true;
    m_scaleValid = false;
    m_screenings = 0;
    m_run = std::make_shared<const SlrRun>();
    m_forced.assign(m_passData->t.size(), 0);
}

namespace {
// The workbench's sources for `path` (a CPF is used with a SINEX only; the SINEX alone gives the
// station's position), read by the core once for the passes of the file; the panel's parameters
// as the config (their oc.* rows make the pass's O-C).
SlrSources sourcesOf(const QString& path, const PassInputParams& in, const SlrParams& params) {
    // Files by their absolute paths: what the report, the copied command and the script name.
    auto absolute = [](const std::string& p) {
        return p.empty() ? p : QFileInfo(QString::fromStdString(p)).absoluteFilePath().toStdString();
    };
    SlrSources src;
    src.input = absolute(path.toStdString());
    src.config = slrSchema().toJson(params);
    src.stations = absolute(in.sinexPath);
    if (!in.sinexPath.empty()) src.cpf = absolute(in.cpfPath);
    src.cpfFallback = true;  // a CPF that does not fit the pass: its own TOF trend, with a note
    src.openDamaged = true;  // a pass with damaged records is shown (its exports are refused)
    return src;
}

bool setUp(const QString& path, const PassInputParams& in, const SlrParams& params, SlrSetup* out, QString* error) {
    SlrError e;
    if (!setUpSlrRun(sourcesOf(path, in, params), out, &e)) {
        *error = QString::fromStdString(e.message);
        return false;
    }
    return true;
}
}  // namespace

void SlrController::resetPassErrors() {
    // What is known from reading the file alone (blocks that cannot be a pass).
    m_passErrors.clear();
    for (const PassSummary& s : m_passes)
        if (!s.problem.empty()) m_passErrors[s.index] = QString::fromStdString(s.problem);
}

SlrOpening SlrController::readForOpen(const QString& path, int passIndex, const PassInputParams& input,
                                      const SlrParams& params, const core::Feedback* fb) {
    SlrOpening o;
    o.path = path;
    o.passIndex = passIndex;
    o.input = input;
    o.params = params;
    SlrSources src = sourcesOf(path, input, params);
    src.passNumber = passIndex + 1;  // (0: the file's first pass to screen, core isPassToScreen)
    LoadedSlrPass loaded = loadSlrPass(src, fb);  // the load Python's load_pass makes
    if (!loaded.setUp) {
        o.error = QString::fromStdString(loaded.error.message);
        return o;
    }
    o.setup = std::move(loaded.setup);
    o.opened = std::move(loaded.opened);
    if (!o.opened.ok && !o.opened.crd) {  // the file (or an O-C table) cannot be read at all
        o.error = QString::fromStdString(o.opened.error.message);
        return o;
    }
    o.read = true;
    return o;
}

bool SlrController::open(const QString& path, int passIndex, const PassInputParams& input, QString* error) {
    return adoptOpening(readForOpen(path, passIndex, input, m_params, nullptr), error);
}

bool SlrController::adoptOpening(SlrOpening o, QString* error) {
    if (!o.read) {  // the previous file stays
        if (error) *error = o.error;
        return false;
    }
    keepStationNormalPoints(&o.setup);
    m_setup = std::move(o.setup);
    m_input = o.input;
    // The O-C was made with the oc.* rows the file was read with (a session's, which may not be
    // the panel's yet): they are the controller's now, so that setting them opens nothing again.
    if (slrSchema().firstChangedStage(m_params, o.params) == kStageOc) {
        m_params.oc = o.params.oc;
        m_params.ownTrend = o.params.ownTrend;
        emit paramsSet();
    }
    m_path = o.path;
    m_crd = o.opened.crd;
    m_passes = o.opened.passes;
    resetPassErrors();
    if (!m_crd) m_passErrors.clear();
    // The block opened (the file's first pass to screen unless one was asked for); a block that
    // is not a pass, or cannot be used, leaves no pass open and its reason in place.
    m_selected = o.opened.ok ? o.opened.pass->passIndex : o.passIndex >= 0 ? o.passIndex : 0;
    showOpened(std::move(o.opened), nullptr);
    return true;
}

bool SlrController::selectPass(int index, QString* error) {
    const auto read = passReader(index);
    if (!read) {
        if (error) *error = tr("no CRD file is open");
        return false;
    }
    return showSelectedPass(index, read(nullptr), error);
}

std::function<OpenedPass(const core::Feedback*)> SlrController::passReader(int index) const {
    if (!m_crd) return {};
    return [setup = m_setup, crd = m_crd, index](const core::Feedback* fb) { return openPassOf(setup, crd, index, fb); };
}

bool SlrController::showSelectedPass(int index, OpenedPass o, QString* error) {
    m_selected = index;
    return showOpened(std::move(o), error);
}

bool SlrController::setSources(const QString& cpfPath, const QString& sinexPath, QString* error) {
    PassInputParams in = m_input;
    in.cpfPath = cpfPath.toStdString();
    in.sinexPath = sinexPath.toStdString();
    SlrSetup setup;
    if (!setUp(m_path, in, m_params, &setup, error)) return false;
    keepStationNormalPoints(&setup);
    m_input = in;
    m_setup = std::move(setup);
    if (m_crd) {
        // What was known against the passes may have been the old prediction's doing.
        resetPassErrors();
        loadSelected(nullptr);
    }
    return true;
}

bool SlrController::setStationNormalPoints(const QString& path, QString* error) {
    SlrError e;
    const std::string p = path.isEmpty() ? std::string() : QFileInfo(path).absoluteFilePath().toStdString();
    if (!core::slr::setStationNormalPoints(&m_setup, p, &e)) {
        if (error) *error = QString::fromStdString(e.message);
        return false;
    }
    return true;
}

void SlrController::keepStationNormalPoints(SlrSetup* setup) const {
    setup->sources.stationNormalPoints = m_setup.sources.stationNormalPoints;
    setup->stationNormalPoints = m_setup.stationNormalPoints;
}

void SlrController::notePassError(int index, const QString& why) {
    if (index < 0) return;
    m_passErrors[index] = why;
    emit passListChanged();
}

bool SlrController::loadSelected(QString* error) { return showOpened(openPassOf(m_setup, m_crd, m_selected), error); }

bool SlrController::showOpened(OpenedPass o, QString* error) {
    m_warnings = o.warnings;
    m_notes = o.notes;
    if (!o.ok) {
        // No pass open, the list stays: the reason is shown in place and against the pass.
        m_passProblem = QString::fromStdString(o.error.message);
        notePassError(m_selected, m_passProblem.section('\n', 0, 0));
        m_job.cancel();  // a run of the previous pass is not delivered
        auto none = std::make_shared<PassData>();
        none->source = m_path.toStdString();
        none->passIndex = m_selected;
        m_passData = std::move(none);
        m_truth.clear();
        passLoaded();
        emit passChanged();
        emit editsChanged();
        emit status(tr("Pass %1 cannot be processed: %2").arg(m_selected + 1).arg(m_passProblem.section('\n', 0, 0)));
        if (error) *error = m_passProblem;
        return false;
    }
    m_passProblem.clear();
    m_passData = o.pass;  // (shared with the opened pass, not copied: a kHz pass's columns are 29 bytes an event)
    m_selected = m_passData->passIndex;
    if (m_passErrors.remove(m_selected)) emit passListChanged();
    passOpened();
    return true;
}

void SlrController::passOpened() {
    m_truth.clear();
    passLoaded();
    m_params.postfit.altitudeKm = m_passData->altitudeKm;
    m_params.postfit.binLengthS = 0;
    for (const auto& w : m_warnings) emit status(QString::fromStdString(w));
    const bool preset = applySatellitePreset();
    emit passChanged();
    emit editsChanged();
    emit status(tr("%1: %2 points, O-C from %3%4")
                    .arg(QFileInfo(m_path).fileName())
                    .arg(m_passData->t.size())
                    .arg(QString::fromStdString(m_passData->ocOrigin))
                    .arg(preset ? tr("; preset of %1 applied").arg(QString::fromStdString(m_passData->satellite)) : QString()));
    m_job.schedule();
}

void SlrController::setSimulatedPass(const std::vector<double>& t, const std::vector<double>& oc,
                                     const std::vector<double>& tof, const std::vector<uint8_t>& truth,
                                     const QString& name, double altitudeKm) {
    auto simulated = std::make_shared<PassData>();
    simulated->source = name.toStdString();
    simulated->satellite = name.toStdString();
    simulated->ocOrigin = "simulation";
    simulated->t = t;
    simulated->oc = oc;
    simulated->tof = tof;
    simulated->altitudeKm = altitudeKm;
    m_passData = std::move(simulated);
    m_setup.sources.input.clear();  // (no file: its products record none, and no command reruns it)
    m_passes.clear();
    m_warnings.clear();
    m_notes.clear();
    m_appliedPreset.clear();
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

SlrController::SweepBase SlrController::sweepBase() const {
    SweepBase b;
    b.setup = m_setup;
    b.inputs.pass = m_passData;
    b.inputs.forced = m_forced;
    // (as the next rerun would: the last screening only while it is the one of the parameters
    // of now, i.e. no screening is due, after a failed run either)
    if (!m_screenDue && m_run->screen.ok) b.reuse.screen = std::shared_ptr<const ScreenResult>(m_run, &m_run->screen);
    if (m_reuseScaleForCosine && m_scaleValid && m_params.screen.automatic) b.reuse.scale = m_scale;
    b.params = m_params;
    if (!m_truth.empty() && m_truth.size() == m_passData->t.size()) {
        b.labels = m_truth;
        b.labelsName = tr("the simulation's truth");
    } else if (std::count(m_passData->stationFlag.begin(), m_passData->stationFlag.end(), 2) > 0) {
        b.labels.resize(m_passData->stationFlag.size());
        for (size_t i = 0; i < b.labels.size(); ++i) b.labels[i] = m_passData->stationFlag[i] == 2;
        b.labelsName = tr("the station's filter flags");
    }
    return b;
}

void SlrController::setParams(const SlrParams& p) {
    // The earliest stage the change touches, from the schema rows' stage tags.
    const int stage = slrSchema().firstChangedStage(m_params, p);
    m_params = p;
    if (stage < 0) return;
    emit paramsSet();
    if (stage == kStageOc) {  // the O-C is the pass's own: the pass is opened again with it
        QString err;
        if (!m_path.isEmpty() && !setSources(QString::fromStdString(m_input.cpfPath), QString::fromStdString(m_input.sinexPath), &err))
            emit runFailed(err);
        return;
    }
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
    if (m_passData->satellite.empty() && m_passData->ilrsId.empty()) {
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
    p.name = m_passData->satellite;
    p.ilrsId = m_passData->ilrsId;
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
    m_appliedPreset.clear();
    if (!QFileInfo::exists(m_presetFile)) return false;
    const PresetsResult r = loadPresets(m_presetFile.toStdString());
    if (!r.ok) {
        emit status(tr("Presets not read: %1").arg(QString::fromStdString(r.error)));
        return false;
    }
    // The core's lookup and application (applyPreset), as --preset on the command line.
    SlrParams p;
    std::string name, err;
    if (!applyPreset(*m_passData, r.presets, std::string(), &p, &name, &err)) return false;
    m_appliedPreset = QString::fromStdString(name.empty() ? m_passData->satellite : name);
    const double altitude = m_params.postfit.altitudeKm;
    m_params = p;
    if (!(m_params.postfit.altitudeKm > 0)) m_params.postfit.altitudeKm = altitude;
    m_screenDue = true;
    m_scaleValid = false;
    return true;
}

bool SlrController::exportProducts(const PassProductPaths& paths, QString* error) const {
    if (!hasRun()) {
        *error = tr("no screening result to export");
        return false;
    }
    // The writer every front end uses (core writeScreenedPass): the CLI's products, report and
    // provenance sidecars, all or nothing, never over an input. What opening the pass said goes
    // in the report, as the CLI gathers it; the edits by hand, which no command makes, are said
    // in the report and recorded in the provenance.
    ScreenedPass screened{&m_setup, nullptr, m_passData.get(), &m_settings, m_run.get(), m_warnings};
    screened.notes.insert(screened.notes.end(), m_notes.begin(), m_notes.end());
    for (int8_t f : m_forced) screened.forcedByHand += f != 0;
    SlrError e;
    if (!writeScreenedPass(screened, paths, std::string(), &e)) {
        *error = QString::fromStdString(e.message);
        return false;
    }
    return true;
}

bool SlrController::exportCsv(const QString& path, QString* error) const {
    PassProductPaths paths;
    paths.csv = path.toStdString();
    return exportProducts(paths, error);
}

bool SlrController::exportCrd(const QString& path, QString* error, bool wholeFile) const {
    PassProductPaths paths;
    paths.crd = path.toStdString();
    paths.crdWholeFile = wholeFile;
    return exportProducts(paths, error);
}

bool SlrController::exportNormalPoints(const QString& path, QString* error) const {
    PassProductPaths paths;
    paths.npt = path.toStdString();
    return exportProducts(paths, error);
}

bool SlrController::exportReport(const QString& path, QString* error) const {
    PassProductPaths paths;
    paths.report = path.toStdString();
    return exportProducts(paths, error);
}

bool SlrController::waitIdle(int timeoutMs) { return m_job.waitIdle(timeoutMs); }

}  // namespace lwb::ui
