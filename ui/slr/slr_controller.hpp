#pragma once
// The SLR workspace's controller: the pass, the screening and post-fit parameters, manual
// edits (forced in / out, undoable, kept across reruns), per-satellite presets, and the
// background rerun on every change (TaskJob<core::slr::PassTask>: the CLI's task, debounced,
// cancelled, generation-tagged). A run reruns only the stages a change affects (the schema rows'
// stage tags): the post-fit alone after a post-fit setting or a manual edit; the screening at
// the scale the automatic mode chose (core::slr::ScaleChoice, passed in) after a change of C
// alone when reuseScaleForCosine is on; everything after any other change.
#include <QHash>
#include <QObject>
#include <QSet>
#include <QString>
#include <functional>
#include <memory>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/np_compare.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/screen.hpp"
#include "core/slr/slr_params.hpp"
#include "core/slr/slr_run.hpp"
#include "ui/kit/task_job.hpp"

namespace lwb::ui {

/// One run of the pass task (accepted: after manual edits) and when it was delivered.
struct SlrRun : core::slr::PassRunResult {
    quint64 generation = 0;
    double latencyMs = 0;                ///< parameter change → result delivered
};

/// A file read for opening, not yet shown (SlrController::readForOpen; any thread).
struct SlrOpening {
    bool read = false;            ///< the file (and its CPF / SINEX) could be read; else `error`
    QString error;
    QString path;
    int passIndex = -1;           ///< asked for (-1: the file's first pass to screen)
    core::slr::PassInputParams input;
    core::slr::SlrParams params;            ///< read with these (its O-C made with their oc.* rows)
    core::slr::SlrSetup setup;
    core::slr::OpenedPass opened;
};

class SlrController : public QObject {
    Q_OBJECT
public:
    explicit SlrController(QObject* parent = nullptr);
    ~SlrController() override;

    const core::slr::PassData& pass() const { return *m_passData; }
    const std::vector<core::slr::PassSummary>& passes() const { return m_passes; }
    /// The readers' warnings about the open pass's files ("FILE:LINE: ..."), empty for a simulation.
    const std::vector<std::string>& warnings() const { return m_warnings; }
    /// What the O-C is relative to when not a prediction (information, not a warning).
    const std::vector<std::string>& notes() const { return m_notes; }
    /// The satellite preset applied when the pass was opened ("" none), as the CLI's "; preset NAME".
    QString appliedPreset() const { return m_appliedPreset; }
    /// The last run's resolved parameters (what its products were made with).
    const core::slr::PassSettings& settings() const { return m_settings; }
    bool hasPass() const { return !m_passData->t.empty(); }
    const SlrRun& run() const { return *m_run; }
    bool hasRun() const { return m_run->screen.ok; }
    const core::slr::SlrParams& params() const { return m_params; }
    const core::slr::ScreenParams& screenParams() const { return m_params.screen; }
    const core::slr::PostfitParams& postfitParams() const { return m_params.postfit; }
    const core::slr::PassInputParams& inputParams() const { return m_input; }
    /// Truth per point for simulated passes (1 = signal), empty otherwise.
    const std::vector<uint8_t>& truth() const { return m_truth; }

    /// Opens a CRD file (pass `passIndex`, -1 = the first pass to screen, core isPassToScreen) or an O-C CSV; the CPF and
    /// SINEX paths in `input` (a CPF file or a folder of them) give O-C from the prediction. The
    /// file is read once and every pass is listed (passes()); a pass that cannot be processed
    /// leaves no pass open and its reason in passProblem(), the list stays. False (the previous
    /// file stays) only when the file or the CPF/SINEX cannot be read at all.
    bool open(const QString& path, int passIndex, const core::slr::PassInputParams& input, QString* error);
    /// open() in two halves, so that the reading can run on a worker with progress and Cancel
    /// (the workspace's ModalProgress; issue 42): readForOpen touches nothing of the controller
    /// (`params`: the panel's, whose oc.* rows make the O-C), adoptOpening shows what it read on
    /// the GUI thread, with open()'s result.
    static SlrOpening readForOpen(const QString& path, int passIndex, const core::slr::PassInputParams& input,
                                  const core::slr::SlrParams& params, const core::Feedback* fb);
    bool adoptOpening(SlrOpening o, QString* error);
    /// Opens pass `index` of the open CRD file; false with its reason (also in passProblem()).
    bool selectPass(int index, QString* error);
    /// selectPass() in two halves as open(): the reading of pass `index` (any thread; the file
    /// and sources are shared read-only), then showing it. No file open: an empty function.
    std::function<core::slr::OpenedPass(const core::Feedback*)> passReader(int index) const;
    bool showSelectedPass(int index, core::slr::OpenedPass o, QString* error);
    /// New CPF / SINEX paths ("" clears them): read again, the current pass reopened. A CPF that
    /// does not fit a pass leaves it on its own TOF trend with PassData::ocNote saying why.
    bool setSources(const QString& cpfPath, const QString& sinexPath, QString* error);
    /// The station's normal points of the run (core setStationNormalPoints on its set-up; ""
    /// clears them): what the Station NP tab shows, and what the report compares and the copied
    /// command names (--station-np). Kept when another file or prediction is opened. False with
    /// *error (FILE:LINE), the ones in use kept.
    bool setStationNormalPoints(const QString& path, QString* error);
    /// Why the selected pass could not be opened ("" when it is open).
    const QString& passProblem() const { return m_passProblem; }
    int selectedPass() const { return m_selected; }
    /// What is known of why pass `index` cannot be processed ("" = nothing known against it).
    QString passError(int index) const { return m_passErrors.value(index); }
    void notePassError(int index, const QString& why);
    /// The open CRD file and its prediction sources, shared read-only (null for an O-C table).
    std::shared_ptr<const core::slr::CrdReadResult> crd() const { return m_crd; }
    std::shared_ptr<const core::slr::PassSources> sources() const { return m_setup.predictions; }
    /// The run's sources as the core read them (the file, CPF, SINEX): what "Screen all passes" runs on.
    const core::slr::SlrSetup& setup() const { return m_setup; }
    QString path() const { return m_path; }
    /// Replaces the manual edits as a whole (the undo commands); one entry of the edit history.
    void setForced(const std::vector<int8_t>& forced);
    /// A simulated pass (the demo and the latency benchmark).
    void setSimulatedPass(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<double>& tof,
                          const std::vector<uint8_t>& truth, const QString& name, double altitudeKm);
    /// New parameters: reruns the stages the changed keys (slrSchema().changedKeys) affect.
    void setParams(const core::slr::SlrParams& p);
    void setScreenParams(const core::slr::ScreenParams& p) {
        core::slr::SlrParams q = m_params;
        q.screen = p;
        setParams(q);
    }
    void setPostfitParams(const core::slr::PostfitParams& p) {
        core::slr::SlrParams q = m_params;
        q.postfit = p;
        setParams(q);
    }
    /// When on, moving only the cosine constant keeps the scale the automatic mode chose (the
    /// effect of C alone, and a faster rerun); off, every change searches the scale again, as
    /// `laserwb-cli slr` does.
    void setReuseScaleForCosine(bool on) { m_reuseScaleForCosine = on; }
    bool reuseScaleForCosine() const { return m_reuseScaleForCosine; }
    /// True when the last run used a scale kept from an earlier automatic choice.
    bool scaleReused() const { return m_run->scaleReused; }
    /// Screenings run since the pass was opened (tests: a post-fit change must not screen).
    int screenCount() const { return m_screenings; }
    bool busy() const { return m_job.busy(); }

    // Manual edits: points forced in (accepted) or out; kept across reruns. Undone through the
    // workspace's undo stack (ForcedCommand with setForced), the one history of the edits.
    void forcePoints(const std::vector<uint32_t>& indices, bool in);
    void clearEdits();
    const std::vector<int8_t>& forced() const { return m_forced; }  ///< per point: +1 in, −1 out, 0 auto

    // Per-satellite presets (JSON file in the user's data folder unless set).
    void setPresetFile(const QString& path);
    QString presetFile() const { return m_presetFile; }
    /// Saves the current parameters as the preset of the pass's satellite.
    bool savePreset(QString* error);
    /// Loads the preset of the pass's satellite if there is one; true when one was applied.
    bool applySatellitePreset();

    /// The exports refuse a pass with damaged records (PassData::damaged), as the CLI does.
    bool exportCsv(const QString& path, QString* error) const;
    /// The pass's records with the screening's filter flags: `wholeFile` writes every pass of
    /// the file (the others unchanged), else this pass alone (its headers and records).
    bool exportCrd(const QString& path, QString* error, bool wholeFile = true) const;
    /// The normal points as the CLI's --npt-out writes them: the reason in their place when there
    /// are none; refused when neither the bin length nor the altitude is known.
    bool exportNormalPoints(const QString& path, QString* error) const;
    /// The pass's one-page PDF report (core pass_report.hpp, as slr --report-out writes it), with
    /// the station comparison when the run has the station's normal points.
    bool exportReport(const QString& path, QString* error) const;

    bool waitIdle(int timeoutMs);

    /// What a sweep of one parameter over the open pass starts from (the sliders' strips, issue
    /// 45): the set-up, the task's inputs (the pass, the edits), what a rerun after a change would
    /// reuse (the last screening; the automatic mode's scale where it is kept while C moves), the
    /// panel's parameters, and the labels where there are any: a simulation's truth, else the
    /// station's filter flags (1 where data) when it flagged some point data.
    struct SweepBase {
        core::slr::SlrSetup setup;
        core::slr::PassTask::Inputs inputs;
        core::slr::PassTask::Reuse reuse;
        core::slr::SlrParams params;
        std::vector<uint8_t> labels;
        QString labelsName;  ///< "the simulation's truth", "the station's filter flags"; "" none
    };
    SweepBase sweepBase() const;

signals:
    void passChanged();
    void runReady(const lwb::ui::SlrRun& run);
    void runFailed(const QString& message);
    void editsChanged();
    /// New parameters were set (setParams, from the panel, an undo, a tuning's Apply or a
    /// session): what was computed for the ones before is stale.
    void paramsSet();
    /// What is known against the passes changed (passError()).
    void passListChanged();
    void status(const QString& message);

private:
    void passLoaded();
    void passOpened();
    void resetPassErrors();
    /// A new set-up keeps the station's normal points of the one it replaces.
    void keepStationNormalPoints(core::slr::SlrSetup* setup) const;
    bool loadSelected(QString* error);
    bool showOpened(core::slr::OpenedPass o, QString* error);
    /// Every export: the core's products writer (stagePassProducts), as the CLI writes them.
    bool exportProducts(const core::slr::PassProductPaths& paths, QString* error) const;

    QString m_path, m_passProblem;
    int m_selected = -1;
    QHash<int, QString> m_passErrors;
    std::shared_ptr<const core::slr::CrdReadResult> m_crd;
    core::slr::SlrSetup m_setup;        ///< the sources as read (file, CPF, SINEX)
    core::slr::PassSettings m_settings; ///< the last run's resolved parameters (what the exports check)
    std::vector<core::slr::PassSummary> m_passes;
    std::vector<std::string> m_warnings, m_notes;
    QString m_appliedPreset;
    std::vector<uint8_t> m_truth;
    core::slr::PassInputParams m_input;
    core::slr::SlrParams m_params;
    std::vector<int8_t> m_forced;
    QString m_presetFile;
    std::shared_ptr<const SlrRun> m_run = std::make_shared<const SlrRun>();
    TaskJob<core::slr::PassTask> m_job;
    // The pass for the workers, shared read-only.
    std::shared_ptr<const core::slr::PassData> m_passData = std::make_shared<const core::slr::PassData>();  ///< never null
    // Stages: the screening is due again (a screening parameter or the pass changed); the
    // scale the automatic mode chose may be passed in (only C changed since it was chosen).
    bool m_screenDue = true;
    bool m_scaleValid = false;
    core::slr::ScaleChoice m_scale;
    bool m_reuseScaleForCosine = false;  ///< off: the CLI's screening at every C (tests/ui movingC...)
    int m_screenings = 0;
};

}  // namespace lwb::ui

Q_DECLARE_METATYPE(lwb::ui::SlrRun)
