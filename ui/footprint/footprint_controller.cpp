#include "ui/footprint/footprint_controller.hpp"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPointer>
#include <QThreadPool>
#include <QThread>
#include <QtConcurrent>
#include <mutex>
#include <thread>

#include "core/common/allocator.hpp"
#include "core/common/parallel.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/footprint/batch.hpp"
#include "core/footprint/footprint_run.hpp"
#include "core/footprint/image_io.hpp"
#include "core/footprint/shot_list.hpp"
#include "ui/footprint/footprint_export.hpp"
#include "ui/kit/frame_loader.hpp"

namespace lwb::ui {

using namespace core::footprint;

namespace {

// A job over indices 0..n-1 run on the thread pool: workers call work(i); the GUI thread
// polls finished() and drains results. Cancelling stops workers between items.
struct IndexedJob {
    explicit IndexedJob(size_t n) : total(n), done(n, 0) {}
    size_t total;
    std::vector<char> done;
    std::mutex mutex;
    std::atomic<size_t> next{0};
    std::atomic<int> running{0};
    core::Feedback feedback;
    bool finished() const { return running.load() == 0; }

    template <class Fn>
    void start(Fn work) {
        const int threads = loaderThreadCount();  // every core but one: the GUI keeps one
        running = threads;
        for (int t = 0; t < threads; ++t)
            (void)QtConcurrent::run(loaderPool(), [this, work]() {
                core::adviseThreadHeap();
                for (size_t i = next++; i < total && !feedback.isCancelled(); i = next++) {
                    work(i);
                    std::lock_guard<std::mutex> lock(mutex);
                    done[i] = 1;
                }
                --running;
            });
    }
};

// Reads the frame and cuts the ROI, as the batch does (core/footprint/footprint_run.hpp).
void loadShot(Shot& s, const FootprintParams& p) {
    ShotSpec spec;
    spec.file = s.file.toStdString();
    spec.hasCenter = s.hasCenter;
    spec.centerX = s.center.x();
    spec.centerY = s.center.y();
    BatchParams bp;
    bp.footprint = p;
    std::vector<ShotRoi> rois;
    std::string err;
    if (!loadShotRois(spec, bp, &rois, &err)) {
        s.loadError = QString::fromStdString(err);
        return;
    }
    const ShotRoi& roi = rois.front();  // (no nominal centres in the workbench: one ROI a shot)
    if (!roi.error.empty()) {
        s.loadError = s.file + ": " + QString::fromStdString(roi.error);
        return;
    }
    s.roi = roi.roi;
    s.origin = {roi.originX, roi.originY};
    s.fullFrame = !roi.wholeImage;
}

}  // namespace

struct LoadState : IndexedJob {
    using IndexedJob::IndexedJob;
    std::vector<Shot> results;
    size_t appended = 0;
};

FootprintController::FootprintController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<lwb::ui::ShotDetail>();
    // The current shot: each method's fit, for the overlays.
    m_currentJob.setWork<ShotDetail>(
        [this]() -> std::function<ShotDetail(core::Feedback&)> {
            const Shot* s = shot(m_current);
            if (!s) return {};
            if (s->roi.empty()) {
                ShotDetail d;
                d.index = m_current;
                d.selected.error = s->loadError.toStdString();
                emit currentDetailReady(d);
                return {};
            }
            const cv::Mat roi = s->roi;
            const QPoint origin = s->origin;
            const int index = m_current;
            const FootprintParams params = m_params;
            auto fits = m_fits;
            return [=](core::Feedback&) {
                ShotDetail d;
                d.index = index;
                d.roi = roi;
                d.origin = origin;
                d.selected = processRoi(roi, params);
                FootprintParams q = params;
                for (Method m : {Method::Gauss, Method::Tefm, Method::Gcm}) {
                    FootprintResult& r = m == Method::Gauss ? d.gauss : m == Method::Tefm ? d.tefm : d.gcm;
                    q.method = m;
                    r = params.method == m ? d.selected : processRoi(roi, q);
                }
                *fits += 3;
                return d;
            };
        },
        [this](ShotDetail d) {
            if (d.index != m_current || d.index >= count()) return;
            // Judged with the criteria of now (they may have moved while the fit ran).
            for (FootprintResult* r : {&d.selected, &d.gauss, &d.tefm, &d.gcm})
                judgeResult(r, d.roi.cols, d.roi.rows, m_params.verdict);
            d.latencyMs = double(QDateTime::currentMSecsSinceEpoch() - m_currentJob.changedAt());
            m_detail = d;
            applyResult(m_shots[size_t(d.index)], d.selected);
            emit shotsChanged(d.index, d.index);
            emit countsChanged();
            emit currentDetailReady(d);
        });
    // The whole list, refitted in the background after the current shot.
    m_listJob.bind(
        [this](TaskJob<ShotsTask>::Run* r) {
            if (m_loading || m_shots.empty()) return false;  // the loader refits when it is done
            auto in = std::make_shared<ShotsTask::Inputs>();
            in->rois.reserve(m_shots.size());
            for (const Shot& s : m_shots) in->rois.push_back(s.roi);
            r->inputs = std::move(in);
            r->params = m_params;
            return true;
        },
        [this](std::vector<FootprintResult> results) {
            if (results.size() != m_shots.size()) return;  // the list changed meanwhile
            for (size_t i = 0; i < m_shots.size(); ++i) {
                if (m_shots[i].roi.empty()) continue;
                ++*m_fits;
                FootprintResult& r = results[i];
                // Judged with the criteria of now (they may have moved while the fit ran).
                judgeResult(&r, m_shots[i].roi.cols, m_shots[i].roi.rows, m_params.verdict);
                applyResult(m_shots[i], r);
            }
            if (!m_shots.empty()) emit shotsChanged(0, count() - 1);
            emit countsChanged();
            emit rejudgeFinished();
        });
    // The list follows the current shot, so the shot in view is fitted first.
    connect(&m_currentJob, &LiveJob::idle, this, [this] {
        if (m_listDue) {
            m_listDue = false;
            m_listJob.schedule();
        }
    });
}

FootprintController::~FootprintController() {
    if (m_loadFeedback) m_loadFeedback->cancel();
    m_currentJob.cancel();
    m_listJob.cancel();
    loaderPool()->waitForDone();  // (the loader's workers hold this controller's job state)
    QThreadPool::globalInstance()->waitForDone(5000);
}

void FootprintController::process(Shot& s, const FootprintParams& p) {
    if (!s.roi.empty()) applyResult(s, processRoi(s.roi, p));
}

void FootprintController::applyResult(Shot& s, const FootprintResult& r) {
    s.processed = true;
    s.result = r;
    s.reasons.clear();
    if (!r.ok) {
        s.verdict = Verdict::Rejected;
        s.reasons << QString::fromStdString(r.error);
        s.fit = {};
        return;
    }
    s.verdict = r.verdict;
    for (const auto& x : r.reasons) s.reasons << QString::fromStdString(x);
    s.noiseClass = noiseClassName(r.background.noiseClass);
    s.fit = r.fit;
}

void FootprintController::clear() {
    cancelLoading();
    // A load in flight is dropped with the list (its timer sees the new generation and stops):
    // it is no longer loading, and said finished (cancelled) so that its progress bar goes. It
    // stayed "loading" for ever when nothing was opened after (a session refused after its
    // footprint part was restored and undone: waitIdle never returned).
    const bool dropped = m_loading;
    const int droppedWith = int(m_shots.size());  // (its shots shown so far)
    m_loading = false;
    m_skipped.clear();  // (the dropped load's; open() sets the new one's after this)
    m_currentJob.cancel();
    m_listJob.cancel();
    m_listDue = false;
    emit shotsAboutToReset();
    m_shots.clear();
    m_inputs.clear();
    m_current = -1;
    m_detail = ShotDetail{};
    ++m_listGeneration;
    *m_fits = 0;
    emit shotsReset();
    emit countsChanged();
    if (dropped) emit loadFinished(droppedWith, 0, true);
}

void FootprintController::setShots(std::vector<Shot> shots) {
    clear();
    for (Shot& s : shots)
        if (!s.processed) {
            process(s, m_params);
            ++*m_fits;
        }
    emit shotsAboutToReset();
    m_shots = std::move(shots);
    emit shotsReset();
    emit countsChanged();
    setCurrent(m_shots.empty() ? -1 : 0);
}

void FootprintController::cancelLoading() {
    if (m_loadFeedback) m_loadFeedback->cancel();
}

void FootprintController::open(const QStringList& paths, bool append) {
    // The shots as the CLI gathers them, but for what a file dialog picks besides frames
    // (set aside and listed: a folder's truth.csv, its notes).
    FootprintSources src;
    for (const QString& p : paths) src.inputs.push_back(p.toStdString());
    src.setAsideOthers = true;
    FootprintSetup setup;
    FootprintError fe;
    if (!gatherShots(src, &setup, &fe)) {
        emit error(QString::fromStdString(fe.message));
        return;
    }
    const std::vector<ShotSpec>& specs = setup.shots;
    QStringList skipped;
    for (const auto& f : setup.setAside) skipped << QString::fromStdString(f);
    if (!append) clear();
    m_skipped = skipped;
    m_inputs += paths;
    auto job = std::make_shared<LoadState>(specs.size());
    job->results.resize(specs.size());
    for (size_t i = 0; i < specs.size(); ++i) {
        Shot& s = job->results[i];
        s.file = QString::fromStdString(specs[i].file);
        s.time = QString::fromStdString(specs[i].time);
        s.beam = QString::fromStdString(specs[i].beam);
        s.camera = QString::fromStdString(specs[i].camera);
        s.hasCenter = specs[i].hasCenter;
        s.center = {specs[i].centerX, specs[i].centerY};
    }
    m_loadFeedback = std::shared_ptr<core::Feedback>(job, &job->feedback);
    m_loading = true;
    const FootprintParams params = m_params;
    auto fits = m_fits;
    job->start([job, params, fits](size_t i) {
        Shot& s = job->results[i];
        loadShot(s, params);
        if (s.loadError.isEmpty()) {
            process(s, params);
            ++*fits;
        }
    });
    const quint64 listGen = m_listGeneration;
    const quint64 fitGen = m_fitGeneration;
    auto* timer = new QTimer(this);
    timer->setInterval(40);
    auto started = std::make_shared<QElapsedTimer>();
    started->start();
    connect(timer, &QTimer::timeout, this, [this, job, timer, listGen, fitGen, started]() {
        if (listGen != m_listGeneration) {  // the list was replaced meanwhile: drop everything
            job->feedback.cancel();
            if (job->finished()) timer->deleteLater();
            return;
        }
        const int first = count();
        const bool refitDue = fitGen != m_fitGeneration;  // fit parameters changed during loading
        // Whether the workers were done is read before the results are drained: read after, a
        // worker finishing in between left its shots undrained and the load was reported as
        // cancelled short of them (194 of 200 shots under load; the flaky folder tests).
        const bool finishedBeforeDrain = job->finished();
        {
            std::lock_guard<std::mutex> lock(job->mutex);
            size_t ready = job->appended;
            while (ready < job->total && job->done[ready]) ++ready;
            if (ready > job->appended) {
                emit shotsAboutToAppend(first, first + int(ready - job->appended) - 1);
                while (job->appended < ready) {
                    Shot s = std::move(job->results[job->appended++]);
                    if (!refitDue && s.processed) {  // the criteria of now
                        judgeResult(&s.result, s.roi.cols, s.roi.rows, m_params.verdict);
                        applyResult(s, s.result);
                    }
                    m_shots.push_back(std::move(s));
                }
            }
        }
        if (count() > first) {
            emit shotsAppended(first, count() - 1);
            emit countsChanged();
            if (m_current < 0) setCurrent(0);
        }
        // Progress (and with it Cancel) once the load has lasted: short loads do not flash it.
        if (started->elapsed() >= kProgressDelayMs && !finishedBeforeDrain)
            emit loadProgress(int(job->appended), int(job->total));
        if (!finishedBeforeDrain) return;
        timer->stop();
        timer->deleteLater();
        m_loading = false;
        int failed = 0;
        for (const Shot& s : m_shots) failed += !s.loadError.isEmpty();
        const bool cancelled = job->appended < job->total;
        emit loadFinished(int(job->appended), failed, cancelled);
        if (refitDue) m_listJob.startNow();
    });
    timer->start();
}

void FootprintController::setParams(const FootprintParams& p) {
    // Results under the old parameters hold under the new ones but for the verdict: judge again.
    const bool verdictOnly = onlyVerdictDiffers(m_params, p) && validate(m_params).empty();
    m_params = p;
    if (verdictOnly) {
        rejudgeAll();
        return;
    }
    ++m_fitGeneration;
    m_listJob.cancel();     // a refit under the old parameters is of no use now
    m_listDue = true;       // refitted once the current shot is
    if (shot(m_current)) m_currentJob.schedule();
    else {
        m_listDue = false;
        m_listJob.schedule();
    }
}

void FootprintController::rejudgeAll() {
    QElapsedTimer t;
    t.start();
    const core::footprint::VerdictParams& v = m_params.verdict;
    // The shots task with the fits of now reused: judged again, not fitted again (a shot not
    // fitted yet is left to the list's refit).
    ShotsTask::Inputs in;
    auto fits = std::make_shared<std::vector<FootprintResult>>();
    in.rois.reserve(m_shots.size());
    fits->reserve(m_shots.size());
    for (const Shot& s : m_shots) {
        in.rois.push_back(s.processed ? s.roi : cv::Mat());
        fits->push_back(s.result);
    }
    const std::vector<FootprintResult> judged = ShotsTask::run(in, m_params, ShotsTask::Reuse{fits}, nullptr);
    for (size_t i = 0; i < m_shots.size(); ++i)
        if (!in.rois[i].empty()) applyResult(m_shots[i], judged[i]);
    const bool haveDetail = m_detail.index >= 0 && m_detail.index == m_current && !m_detail.roi.empty();
    if (haveDetail)
        for (FootprintResult* r : {&m_detail.selected, &m_detail.gauss, &m_detail.tefm, &m_detail.gcm})
            judgeResult(r, m_detail.roi.cols, m_detail.roi.rows, v);
    m_lastRejudgeMs = t.nsecsElapsed() / 1e6;
    if (!m_shots.empty()) emit shotsChanged(0, count() - 1);
    emit countsChanged();
    if (haveDetail) {
        m_detail.latencyMs = m_lastRejudgeMs;
        emit currentDetailReady(m_detail);
    }
    emit rejudgeFinished();
}

void FootprintController::setCurrent(int index) {
    if (index < -1 || index >= count()) return;
    m_current = index;
    if (index >= 0) m_currentJob.startNow();
}

void FootprintController::setOverride(int index, Verdict v, const QString& note) {
    if (index < 0 || index >= count()) return;
    Shot& s = m_shots[size_t(index)];
    s.overridden = true;
    s.overrideVerdict = v;
    if (!note.isNull()) s.note = note;
    emit shotsChanged(index, index);
    emit countsChanged();
}

void FootprintController::clearOverride(int index) {
    if (index < 0 || index >= count()) return;
    m_shots[size_t(index)].overridden = false;
    emit shotsChanged(index, index);
    emit countsChanged();
}

void FootprintController::setNote(int index, const QString& note) {
    if (index < 0 || index >= count()) return;
    m_shots[size_t(index)].note = note;
    emit shotsChanged(index, index);
}

void FootprintController::applyReviews(const std::vector<Review>& reviews) {
    int first = count(), last = -1;
    bool verdicts = false;
    for (const Review& r : reviews) {
        if (r.index < 0 || r.index >= count()) continue;
        Shot& s = m_shots[size_t(r.index)];
        if (r.setVerdict) {
            s.overridden = true;
            s.overrideVerdict = r.verdict;
            verdicts = true;
        }
        s.note = r.note;
        first = std::min(first, r.index);
        last = std::max(last, r.index);
    }
    if (last < first) return;
    emit shotsChanged(first, last);
    if (verdicts) emit countsChanged();
}

FootprintController::Counts FootprintController::counts() const {
    Counts c;
    for (const Shot& s : m_shots) {
        if (!s.loadError.isEmpty()) {
            ++c.unreadable;
            continue;
        }
        if (!s.processed) {
            ++c.pending;
            continue;
        }
        const Verdict v = s.effectiveVerdict();
        (v == Verdict::Good ? c.good : v == Verdict::Doubtful ? c.doubtful : c.rejected)++;
        c.overridden += s.overridden;
    }
    return c;
}

cv::Mat FootprintController::frameOf(const Shot& s) {
    ShotSpec spec;
    spec.file = s.file.toStdString();
    const ImageReadResult img = readShotFrame(spec, BatchParams{});
    return img.ok ? img.image : cv::Mat();
}

bool FootprintController::exportAccepted(const QString& path, QString* error, int* rows) const {
    return writeFootprintReview(m_shots, m_params.method, path, true, error, rows);
}

QString FootprintController::acceptedExportMessage(int rows, const QString& path) const {
    const int withoutPosition = counts().good - rows;
    QString msg = tr("Exported %n accepted shot(s) to %1", nullptr, rows).arg(path);
    if (withoutPosition > 0)
        msg += tr("; %n accepted shot(s) without a position (no fit) left out", nullptr, withoutPosition);
    return msg;
}

TrendResult FootprintController::trend(const TrendParams& tp, const std::function<bool(int)>& include) const {
    std::vector<CentroidRecord> recs;
    for (size_t i = 0; i < m_shots.size(); ++i) {
        const Shot& s = m_shots[i];
        if (include && !include(int(i))) continue;
        if (s.time.isEmpty() || s.beam.isEmpty() || s.effectiveVerdict() != Verdict::Good || !s.fit.ok) continue;
        CentroidRecord r;
        if (!monthOf(s.time.toStdString(), &r.month)) continue;
        r.camera = s.camera.toStdString();
        r.beam = s.beam.toStdString();
        r.x = s.fullX();
        r.y = s.fullY();
        recs.push_back(r);
    }
    if (recs.empty()) {
        TrendResult r;
        r.error = include ? "no accepted shots with a time and a beam in the filtered view"
                          : "no accepted shots with a time and a beam";
        return r;
    }
    return computeTrend(recs, tp);
}

bool FootprintController::waitIdle(int timeoutMs) {
    return waitUntilIdle([this] { return busy(); }, timeoutMs);
}

}  // namespace lwb::ui
