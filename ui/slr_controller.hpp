#pragma once
// The SLR workspace's controller: the pass, the screening and post-fit parameters, manual
// edits (forced in / out, undoable, kept across reruns), per-satellite presets, and the
// background rerun on every change (generation-tagged; stale results dropped).
#include <QObject>
#include <QSet>
#include <QString>
#include <QTimer>
#include <memory>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/screen.hpp"

namespace lwb::ui {

/// One screening run and what follows from it.
struct SlrRun {
    quint64 generation = 0;
    core::slr::ScreenResult screen;
    std::vector<uint8_t> accepted;       ///< after manual edits
    core::slr::PostfitResult post;
    double latencyMs = 0;                ///< parameter change → result delivered
};

class SlrController : public QObject {
    Q_OBJECT
public:
    explicit SlrController(QObject* parent = nullptr);
    ~SlrController() override;

    const core::slr::PassData& pass() const { return m_pass; }
    const std::vector<core::slr::PassSummary>& passes() const { return m_passes; }
    /// The readers' warnings about the open pass's files ("FILE:LINE: ..."), empty for a simulation.
    const std::vector<std::string>& warnings() const { return m_warnings; }
    bool hasPass() const { return !m_pass.t.empty(); }
    const SlrRun& run() const { return m_run; }
    bool hasRun() const { return m_run.screen.ok; }
    const core::slr::ScreenParams& screenParams() const { return m_screen; }
    const core::slr::PostfitParams& postfitParams() const { return m_postfit; }
    const core::slr::PassInputParams& inputParams() const { return m_input; }
    /// Truth per point for simulated passes (1 = signal), empty otherwise.
    const std::vector<uint8_t>& truth() const { return m_truth; }

    /// Opens a CRD file (pass `passIndex`, -1 = first full-rate one) or an O-C CSV; the CPF and
    /// SINEX paths in `input` give O-C from the prediction. On error the previous pass stays.
    bool open(const QString& path, int passIndex, const core::slr::PassInputParams& input, QString* error);
    /// A simulated pass (the demo and the latency benchmark).
    void setSimulatedPass(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<double>& tof,
                          const std::vector<uint8_t>& truth, const QString& name, double altitudeKm);
    void setScreenParams(const core::slr::ScreenParams& p);
    /// When on, moving only the cosine constant keeps the scale the automatic mode chose (the
    /// effect of C alone, and a faster rerun); off, every change searches the scale again, as
    /// `laserwb-cli slr` does.
    void setReuseScaleForCosine(bool on) { m_reuseScaleForCosine = on; }
    bool reuseScaleForCosine() const { return m_reuseScaleForCosine; }
    /// True when the last run used a scale kept from an earlier automatic choice.
    bool scaleReused() const { return m_lastScaleReused; }
    void setPostfitParams(const core::slr::PostfitParams& p);

    // Manual edits: points forced in (accepted) or out; undoable; kept across reruns.
    void forcePoints(const std::vector<uint32_t>& indices, bool in);
    bool undoEdit();
    void clearEdits();
    int editCount() const { return int(m_edits.size()); }
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
    bool exportCrd(const QString& path, QString* error) const;
    bool exportNormalPoints(const QString& path, QString* error) const;

    bool waitIdle(int timeoutMs);

signals:
    void passChanged();
    void runReady(const lwb::ui::SlrRun& run);
    void runFailed(const QString& message);
    void editsChanged();
    void status(const QString& message);

private:
    void schedule();
    void start();

    core::slr::PassData m_pass;
    std::vector<core::slr::PassSummary> m_passes;
    std::vector<std::string> m_warnings;
    std::vector<uint8_t> m_truth;
    core::slr::PassInputParams m_input;
    core::slr::ScreenParams m_screen;
    core::slr::PostfitParams m_postfit;
    std::vector<int8_t> m_forced;
    struct Edit {
        std::vector<uint32_t> indices;
        std::vector<int8_t> before;
    };
    std::vector<Edit> m_edits;
    QString m_presetFile;
    SlrRun m_run;
    QTimer m_debounce;
    quint64 m_generation = 0;
    std::shared_ptr<core::Feedback> m_feedback;
    bool m_running = false;
    qint64 m_changedAt = 0;
    // The scale the automatic mode chose for this pass. Moving only C (which acts on the
    // recovery step) reuses it instead of searching again; any other change searches anew.
    struct CachedScale {
        bool valid = false;
        double magT = 0, magOc = 0;
        int areaLimit = 0, connectivity = 0;
    } m_autoScale;
    bool m_reuseScaleForCosine = true;
    bool m_lastScaleReused = false;
};

}  // namespace lwb::ui

Q_DECLARE_METATYPE(lwb::ui::SlrRun)
