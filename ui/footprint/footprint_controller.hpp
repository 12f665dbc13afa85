#pragma once
// The footprint workspace's controller: owns the shot list, the parameters and every job that
// runs the core (loading, live rerun of the current shot, background refit of the list).
// Widgets never call the core; they talk to this object. The current shot and the list are each
// a LiveJob (ui/live_job.hpp: debounce, cancel, generation tag). A change of the verdict criteria
// alone re-judges the cached fits at once (core::footprint::judgeResult), with no refit.
#include <QObject>
#include <QPointF>
#include <QStringList>
#include <QTimer>
#include <atomic>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/footprint/batch.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/footprint/trend.hpp"
#include "ui/kit/task_job.hpp"

namespace lwb::ui {

using core::footprint::Verdict;

/// One shot (one ROI of one frame) in the review list.
struct Shot {
    QString file;              ///< path, or "demo:NAME" for built-in demo shots
    QString time;              ///< ISO date/time (for the trend), may be empty
    QString beam;              ///< beam label, may be empty
    QString camera;            ///< camera label (LFI, LSI...), may be empty
    bool hasCenter = false;    ///< nominal centre given (full-image px)
    QPointF center;
    // Loaded data
    cv::Mat roi;               ///< CV_32FC1 ROI (cached: re-judging needs no file I/O)
    QPoint origin;             ///< full-image position of the ROI's pixel (0, 0)
    bool fullFrame = false;    ///< the input was a full frame (the ROI was cut from it)
    QString loadError;         ///< why the frame could not be read
    // Result under the current parameters
    bool processed = false;
    core::footprint::FootprintResult result;  ///< the pipeline's result (ROI coordinates)
    // Shown in the table (from result).
    Verdict verdict = Verdict::Rejected;
    QStringList reasons;
    QString noiseClass;
    core::footprint::SpotFit fit;  ///< ROI coordinates
    // The analyst's decision
    bool overridden = false;
    Verdict overrideVerdict = Verdict::Good;
    QString note;

    Verdict effectiveVerdict() const { return overridden ? overrideVerdict : verdict; }
    double fullX() const { return fit.ok ? fit.x + origin.x() : qQNaN(); }
    double fullY() const { return fit.ok ? fit.y + origin.y() : qQNaN(); }
};

/// Everything the ROI view draws for the current shot: each method's result.
struct ShotDetail {
    int index = -1;
    cv::Mat roi;
    QPoint origin;
    core::footprint::FootprintResult selected;  ///< the chosen method
    core::footprint::FootprintResult gauss, tefm, gcm;
    double latencyMs = 0;                       ///< parameter change → result (for the benchmark)
};

class FootprintController : public QObject {
    Q_OBJECT
public:
    explicit FootprintController(QObject* parent = nullptr);
    ~FootprintController() override;

    const std::vector<Shot>& shots() const { return m_shots; }
    const Shot* shot(int i) const { return i >= 0 && i < int(m_shots.size()) ? &m_shots[i] : nullptr; }
    int count() const { return int(m_shots.size()); }
    const core::footprint::FootprintParams& params() const { return m_params; }
    int current() const { return m_current; }
    bool busy() const { return m_loading || m_listJob.busy() || m_currentJob.busy(); }

    /// Files and folders (every image inside), or a CSV list (file,time,beam[,camera][,center_x,center_y]).
    /// Loading runs in the background; rows appear as results arrive. Replaces the list unless append.
    void open(const QStringList& paths, bool append = false);
    /// In-memory shots (the built-in demo).
    void setShots(std::vector<Shot> shots);
    void cancelLoading();
    void clear();

    /// New parameters. A change of the verdict criteria only: every cached fit (the list and the
    /// current shot's methods) is judged again at once, no refit. Any other change: the current
    /// shot is refitted (live job), then the whole list in the background.
    void setParams(const core::footprint::FootprintParams& p);
    /// Fits made since the list was last replaced (tests: a verdict change must not refit).
    long long fitCount() const { return *m_fits; }
    /// ms the last re-judging of cached fits took (the latency benchmark).
    double lastRejudgeMs() const { return m_lastRejudgeMs; }
    void setCurrent(int index);

    void setOverride(int index, Verdict v, const QString& note);
    void clearOverride(int index);
    void setNote(int index, const QString& note);
    /// Many shots' reviews at once (a session's overrides as their rows arrive): one
    /// shotsChanged over their span and one countsChanged, not one each (10^5 overrides took
    /// 170 s, every one recounting every shot).
    struct Review {
        int index = -1;
        bool setVerdict = false;  ///< false: the note only
        Verdict verdict = Verdict::Good;
        QString note;
    };
    void applyReviews(const std::vector<Review>& reviews);

    struct Counts {
        int good = 0, doubtful = 0, rejected = 0, pending = 0, overridden = 0;
        int unreadable = 0;  ///< frames that could not be read (not in good/doubtful/rejected)
    };
    Counts counts() const;

    /// Accepted shots (effective verdict good) as CSV through the core writer of the
    /// `footprint` command's report (core::footprint::writeFootprintCsv, every column), plus
    /// time, beam, camera, override and note. Atomic. False with *error; *rows (when given) is
    /// the number of shots written.
    /// The whole frame of shot `s`, read as its ROI was (empty when it cannot be read).
    static cv::Mat frameOf(const Shot& s);
    bool exportAccepted(const QString& path, QString* error, int* rows = nullptr) const;
    /// The status line after exporting `rows` accepted shots to `path`: says how many accepted
    /// shots have no position (accepted by hand, their fit failed) and were left out.
    QString acceptedExportMessage(int rows, const QString& path) const;
    /// Monthly trend of the accepted shots that have a time and a beam (and, when `include` is
    /// given, for which include(row) holds: the shot list's filter).
    core::footprint::TrendResult trend(const core::footprint::TrendParams& tp,
                                       const std::function<bool(int)>& include = {}) const;

    /// Inputs as given to open() (for the session).
    const QStringList& inputs() const { return m_inputs; }
    /// Files of the last open() that are not images and were left out (a truth.csv among
    /// frames, notes...).
    const QStringList& skippedInputs() const { return m_skipped; }
    /// Waits (processing events) until loading and re-judging are done, or timeoutMs passes.
    bool waitIdle(int timeoutMs);

signals:
    void shotsAboutToReset();             ///< the list is about to be replaced
    void shotsReset();                    ///< the list was replaced
    void shotsAboutToAppend(int first, int last);
    void shotsAppended(int first, int last);
    void shotsChanged(int first, int last);  ///< results or overrides changed in that range
    void countsChanged();
    void currentDetailReady(const lwb::ui::ShotDetail& detail);
    void loadProgress(int done, int total);
    void loadFinished(int loaded, int failed, bool cancelled);
    void rejudgeFinished();
    void error(const QString& message);

private:
    void rejudgeAll();
    static void applyResult(Shot& s, const core::footprint::FootprintResult& r);
    static void process(Shot& s, const core::footprint::FootprintParams& p);

    std::vector<Shot> m_shots;
    QStringList m_inputs, m_skipped;
    core::footprint::FootprintParams m_params;
    int m_current = -1;
    ShotDetail m_detail;             // the current shot's last result (re-judged in place)
    LiveJob m_currentJob;                             // the shot in view, every method (ShotDetail)
    TaskJob<core::footprint::ShotsTask> m_listJob;    // the whole list: the core task, as the CLI's per-ROI stage
    quint64 m_fitGeneration = 0;     // bumps on every change that needs a refit
    quint64 m_listGeneration = 0;    // bumps when the list is replaced
    std::shared_ptr<core::Feedback> m_loadFeedback;
    bool m_loading = false;
    bool m_listDue = false;          // refit the list once the current shot is done
    std::shared_ptr<std::atomic<long long>> m_fits = std::make_shared<std::atomic<long long>>(0);  // workers count too
    double m_lastRejudgeMs = 0;
};

}  // namespace lwb::ui

Q_DECLARE_METATYPE(lwb::ui::ShotDetail)
