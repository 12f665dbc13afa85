#include "ui/footprint_controller.hpp"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPointer>
#include <QThreadPool>
#include <QtConcurrent>
#include <mutex>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/footprint/batch.hpp"
#include "core/footprint/image_io.hpp"
#include "ui/footprint_export.hpp"
#include "ui/frame_loader.hpp"

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
                for (size_t i = next++; i < total && !feedback.isCancelled(); i = next++) {
                    work(i);
                    std::lock_guard<std::mutex> lock(mutex);
                    done[i] = 1;
                }
                --running;
            });
    }
};

struct Spec {
    QString file, time, beam, camera;
    bool hasCenter = false;
    QPointF center;
};

// Expands the inputs into shot specs: folders (their images) and image files, or CSV shot
// lists. A CSV given with image files (a folder's truth.csv selected with its frames) and any
// other non-image file are left out and listed in *skipped.
bool expandSpecs(const QStringList& inputs, std::vector<Spec>* out, QStringList* skipped, QString* error) {
    bool anyImage = false;
    for (const QString& in : inputs) anyImage |= QFileInfo(in).isDir() || isFrameFile(in.toStdString());
    for (const QString& in : inputs) {
        const bool csvList = QFileInfo(in).suffix().compare("csv", Qt::CaseInsensitive) == 0;
        if (!QFileInfo(in).isDir() && !isFrameFile(in.toStdString()) && (!csvList || anyImage)) {
            if (QFileInfo(in).exists()) {
                skipped->append(in);
                continue;
            }
        }
        if (csvList && !anyImage) {
            const core::CsvReadResult csv = core::readCsv(in.toStdString());
            if (!csv.ok) {
                *error = QString::fromStdString(csv.error);
                return false;
            }
            const auto& t = csv.table;
            const int cf = t.column("file"), ct = t.column("time"), cb = t.column("beam"), cc = t.column("camera"),
                      cx = t.column("center_x"), cy = t.column("center_y");
            if (cf < 0) {
                *error = in + ":1: a shot list needs a 'file' column (optional: time, beam, camera, center_x, center_y)";
                return false;
            }
            const QString base = QFileInfo(in).absolutePath();
            for (size_t r = 0; r < t.rows.size(); ++r) {
                Spec s;
                const QString f = QString::fromStdString(t.rows[r][cf]);
                s.file = QFileInfo(f).isAbsolute() ? f : base + "/" + f;
                if (ct >= 0) s.time = QString::fromStdString(t.rows[r][ct]);
                if (cb >= 0) s.beam = QString::fromStdString(t.rows[r][cb]);
                if (cc >= 0) s.camera = QString::fromStdString(t.rows[r][cc]);
                if (cx >= 0 && cy >= 0 && !t.rows[r][cx].empty()) {
                    double x = 0, y = 0;
                    if (!core::parseDouble(t.rows[r][cx], &x) || !core::parseDouble(t.rows[r][cy], &y)) {
                        *error = QString("%1:%2: center_x/center_y must be numbers").arg(in).arg(t.lines[r]);
                        return false;
                    }
                    s.hasCenter = true;
                    s.center = {x, y};
                }
                out->push_back(s);
            }
            continue;
        }
        if (QFileInfo(in).isDir())  // a folder: its files that are not images are left out too
            for (const QString& f : QDir(in).entryList(QDir::Files, QDir::Name))
                if (!isFrameFile(f.toStdString())) skipped->append(QDir(in).filePath(f));
        std::vector<std::string> files;
        std::string err;
        if (!expandInputs({in.toStdString()}, &files, &err)) {
            *error = QString::fromStdString(err);
            return false;
        }
        for (const auto& f : files) out->push_back({QString::fromStdString(f), {}, {}, {}, false, {}});
    }
    return true;
}

// Reads the frame and cuts the ROI.
void loadShot(Shot& s, const FootprintParams& p) {
    ImageReadResult img = readFrame(s.file.toStdString());
    if (!img.ok) {
        s.loadError = QString::fromStdString(img.error);
        return;
    }
    RoiParams rp = p.roi;
    rp.hasCenter = s.hasCenter;
    rp.centerX = s.center.x();
    rp.centerY = s.center.y();
    const RoiResult roi = extractRoi(img.image, rp);
    if (!roi.ok) {
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

struct RejudgeState : IndexedJob {
    using IndexedJob::IndexedJob;
    std::vector<FootprintResult> results;
};

FootprintController::FootprintController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<lwb::ui::ShotDetail>();
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(150);
    connect(&m_debounce, &QTimer::timeout, this, &FootprintController::startRejudge);
}

FootprintController::~FootprintController() {
    if (m_loadFeedback) m_loadFeedback->cancel();
    if (m_rejudgeFeedback) m_rejudgeFeedback->cancel();
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
    if (m_rejudgeFeedback) m_rejudgeFeedback->cancel();
    emit shotsAboutToReset();
    m_shots.clear();
    m_inputs.clear();
    m_current = -1;
    m_rejudgeRunning = false;
    ++m_listGeneration;
    emit shotsReset();
    emit countsChanged();
}

void FootprintController::setShots(std::vector<Shot> shots) {
    clear();
    for (Shot& s : shots)
        if (!s.processed) process(s, m_params);
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
    std::vector<Spec> specs;
    QString err;
    QStringList skipped;
    if (!expandSpecs(paths, &specs, &skipped, &err)) {
        emit error(err);
        return;
    }
    if (specs.empty()) {
        emit error(tr("No image files (png, tif, tiff, pgm, raw, bin) in: %1").arg(paths.join(", ")));
        return;
    }
    if (!append) clear();
    m_skipped = skipped;
    m_inputs += paths;
    auto job = std::make_shared<LoadState>(specs.size());
    job->results.resize(specs.size());
    for (size_t i = 0; i < specs.size(); ++i) {
        Shot& s = job->results[i];
        s.file = specs[i].file;
        s.time = specs[i].time;
        s.beam = specs[i].beam;
        s.camera = specs[i].camera;
        s.hasCenter = specs[i].hasCenter;
        s.center = specs[i].center;
    }
    m_loadFeedback = std::shared_ptr<core::Feedback>(job, &job->feedback);
    m_loading = true;
    const FootprintParams params = m_params;
    job->start([job, params](size_t i) {
        Shot& s = job->results[i];
        loadShot(s, params);
        if (s.loadError.isEmpty()) process(s, params);
    });
    const quint64 listGen = m_listGeneration;
    const quint64 gen = m_generation;
    auto* timer = new QTimer(this);
    timer->setInterval(40);
    auto started = std::make_shared<QElapsedTimer>();
    started->start();
    connect(timer, &QTimer::timeout, this, [this, job, timer, listGen, gen, started]() {
        if (listGen != m_listGeneration) {  // the list was replaced meanwhile: drop everything
            job->feedback.cancel();
            if (job->finished()) timer->deleteLater();
            return;
        }
        const int first = count();
        {
            std::lock_guard<std::mutex> lock(job->mutex);
            size_t ready = job->appended;
            while (ready < job->total && job->done[ready]) ++ready;
            if (ready > job->appended) {
                emit shotsAboutToAppend(first, first + int(ready - job->appended) - 1);
                while (job->appended < ready) m_shots.push_back(std::move(job->results[job->appended++]));
            }
        }
        const bool stale = gen != m_generation;  // parameters changed during loading
        if (count() > first) {
            emit shotsAppended(first, count() - 1);
            emit countsChanged();
            if (m_current < 0) setCurrent(0);
        }
        // Progress (and with it Cancel) once the load has lasted: short loads do not flash it.
        if (started->elapsed() >= kProgressDelayMs && !job->finished())
            emit loadProgress(int(job->appended), int(job->total));
        if (!job->finished()) return;
        timer->stop();
        timer->deleteLater();
        m_loading = false;
        int failed = 0;
        for (const Shot& s : m_shots) failed += !s.loadError.isEmpty();
        const bool cancelled = job->appended < job->total;
        emit loadFinished(int(job->appended), failed, cancelled);
        if (stale) startRejudge();
    });
    timer->start();
}

void FootprintController::setParams(const FootprintParams& p) {
    m_params = p;
    ++m_generation;
    m_paramChangedAt = QDateTime::currentMSecsSinceEpoch();
    runCurrent();
    m_debounce.start();
}

void FootprintController::setCurrent(int index) {
    if (index < -1 || index >= count()) return;
    m_current = index;
    m_paramChangedAt = QDateTime::currentMSecsSinceEpoch();
    runCurrent();
}

void FootprintController::runCurrent() {
    const Shot* s = shot(m_current);
    if (!s) return;
    if (s->roi.empty()) {
        ShotDetail d;
        d.index = m_current;
        d.selected.error = s->loadError.toStdString();
        emit currentDetailReady(d);
        return;
    }
    const cv::Mat roi = s->roi;
    const QPoint origin = s->origin;
    const int index = m_current;
    const quint64 gen = m_generation;
    const quint64 listGen = m_listGeneration;
    const FootprintParams params = m_params;
    const qint64 t0 = m_paramChangedAt;
    QPointer<FootprintController> self(this);
    (void)QtConcurrent::run([=]() {
        ShotDetail d;
        d.index = index;
        d.roi = roi;
        d.origin = origin;
        d.selected = processRoi(roi, params);
        FootprintParams q = params;
        q.method = Method::Gauss;
        d.gauss = params.method == Method::Gauss ? d.selected : processRoi(roi, q);
        q.method = Method::Tefm;
        d.tefm = params.method == Method::Tefm ? d.selected : processRoi(roi, q);
        q.method = Method::Gcm;
        d.gcm = params.method == Method::Gcm ? d.selected : processRoi(roi, q);
        QMetaObject::invokeMethod(
            qApp,
            [self, d, gen, listGen, t0]() mutable {
                if (!self || gen != self->m_generation || listGen != self->m_listGeneration || d.index != self->m_current)
                    return;  // stale
                d.latencyMs = double(QDateTime::currentMSecsSinceEpoch() - t0);
                Shot& s = self->m_shots[size_t(d.index)];
                self->applyResult(s, d.selected);
                emit self->shotsChanged(d.index, d.index);
                emit self->countsChanged();
                emit self->currentDetailReady(d);
            },
            Qt::QueuedConnection);
    });
}

void FootprintController::startRejudge() {
    if (m_loading) return;  // the loader re-judges when it is done
    if (m_rejudgeFeedback) m_rejudgeFeedback->cancel();
    if (m_shots.empty()) {
        m_rejudgeRunning = false;
        return;
    }
    auto job = std::make_shared<RejudgeState>(m_shots.size());
    job->results.resize(m_shots.size());
    std::vector<cv::Mat> rois;
    rois.reserve(m_shots.size());
    for (const Shot& s : m_shots) rois.push_back(s.roi);
    m_rejudgeFeedback = std::shared_ptr<core::Feedback>(job, &job->feedback);
    m_rejudgeRunning = true;
    const FootprintParams params = m_params;
    job->start([job, params, rois](size_t i) {
        if (!rois[i].empty()) job->results[i] = processRoi(rois[i], params);
    });
    const quint64 gen = m_generation, listGen = m_listGeneration;
    auto* timer = new QTimer(this);
    timer->setInterval(60);
    connect(timer, &QTimer::timeout, this, [this, job, timer, gen, listGen]() {
        const bool stale = gen != m_generation || listGen != m_listGeneration;
        if (stale) job->feedback.cancel();
        if (!stale) {
            int first = -1, last = -1;
            std::lock_guard<std::mutex> lock(job->mutex);
            for (size_t i = 0; i < job->total; ++i) {
                if (job->done[i] != 1 || i >= m_shots.size()) continue;
                job->done[i] = 2;  // applied
                if (!m_shots[i].roi.empty()) applyResult(m_shots[i], job->results[i]);
                if (first < 0) first = int(i);
                last = int(i);
            }
            if (first >= 0) {
                emit shotsChanged(first, last);
                emit countsChanged();
            }
        }
        if (!job->finished()) return;
        timer->stop();
        timer->deleteLater();
        if (!stale) {
            m_rejudgeRunning = false;
            emit rejudgeFinished();
        }
    });
    timer->start();
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

bool FootprintController::exportAccepted(const QString& path, QString* error) const {
    return writeFootprintReview(m_shots, m_params.method, path, true, error);
}

TrendResult FootprintController::trend(const TrendParams& tp) const {
    std::vector<CentroidRecord> recs;
    for (const Shot& s : m_shots) {
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
        r.error = "no accepted shots with a time and a beam";
        return r;
    }
    return computeTrend(recs, tp);
}

bool FootprintController::waitIdle(int timeoutMs) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (!m_loading && !m_rejudgeRunning && !m_debounce.isActive()) return true;
    }
    return false;
}

}  // namespace lwb::ui
