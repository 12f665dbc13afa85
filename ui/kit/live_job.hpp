#pragma once
// The live rerun every workspace controller uses (ARCHITECTURE.md rule 4): a change schedules a
// run; a burst of changes is coalesced by one debounce time; the run copies its inputs on the
// GUI thread, works on the thread pool with a cancel token and progress (core::Feedback), and
// its result is delivered on the GUI thread only when no newer change came meanwhile
// (generation tag). A change while a run works cancels that run.
//
//     m_job.setWork<SlrRun>([this] { ...copy params and inputs...; return [=](core::Feedback& fb) { return compute(...); }; },
//                           [this](SlrRun r) { m_run = std::move(r); emit runReady(m_run); });
//     m_job.schedule();   // on every change
#include <QFuture>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QtConcurrent>
#include <functional>
#include <memory>
#include <new>
#include <optional>
#include <vector>

#include "core/common/allocator.hpp"
#include "core/common/feedback.hpp"

namespace lwb::ui {

/// Processes events until busy() is false or timeoutMs passes; false on timeout (the
/// controllers' waitIdle for tests and benchmarks).
bool waitUntilIdle(const std::function<bool()>& busy, int timeoutMs);

class LiveJob : public QObject {
    Q_OBJECT
public:
    /// The one debounce time of the workbench (ms): a burst of slider events closer than this
    /// runs once, after the burst.
    static constexpr int kDebounceMs = 60;

    explicit LiveJob(QObject* parent = nullptr);
    /// Cancels the running work and waits for it (the work holds copies, never the controller).
    ~LiveJob() override;

    /// The work. `prepare` runs on the GUI thread when a run starts: it copies what the run
    /// needs and returns the task (an empty function: nothing to run, e.g. no data yet); the task
    /// runs on the thread pool and polls the Feedback; `deliver` gets its result on the GUI thread
    /// unless the run went stale (a newer change) or was cancelled.
    template <class R>
    void setWork(std::function<std::function<R(core::Feedback&)>()> prepare, std::function<void(R)> deliver) {
        m_start = [this, prepare = std::move(prepare), deliver = std::move(deliver)]() {
            std::function<R(core::Feedback&)> task = prepare();
            if (!task) {
                finished(m_generation);
                return;
            }
            const quint64 gen = m_generation;
            auto fb = newFeedback(gen);
            QPointer<LiveJob> self(this);
            track(QtConcurrent::run([self, task = std::move(task), deliver, fb, gen]() {
                core::adviseThreadHeap();  // the pool thread's malloc arena (allocator.hpp)
                // An exception out of the task (memory ran out under a limit, say) is said, not
                // lost in the future nobody reads: before this the run ended silently and the
                // window stayed empty and idle (a 10^6-event pass under ulimit -d 600000).
                std::optional<R> done;
                QString failure;
                try {
                    done.emplace(task(*fb));
                } catch (const std::bad_alloc&) {
                    failure = QObject::tr("out of memory: the run needs more memory than this process may take");
                } catch (const std::exception& e) {
                    failure = QObject::tr("internal error: %1").arg(QString::fromUtf8(e.what()));
                }
                if (fb->isCancelled()) return;
                if (!done) {
                    QMetaObject::invokeMethod(
                        qApp,
                        [self, gen, failure]() {
                            if (!self || gen != self->m_generation) return;
                            self->finished(gen);
                            emit self->failed(failure);
                        },
                        Qt::QueuedConnection);
                    return;
                }
                R result = std::move(*done);
                QMetaObject::invokeMethod(
                    qApp,
                    [self, deliver, gen, result = std::move(result)]() mutable {
                        if (!self || gen != self->m_generation) return;  // stale: a newer run is on its way
                        self->finished(gen);
                        deliver(std::move(result));
                    },
                    Qt::QueuedConnection);
            }));
        };
    }

    /// Something changed: any running work is stale (cancelled) and a new run starts after the
    /// debounce time. When the job has been idle for longer than that, it starts at once (a
    /// single edit is not delayed; the rest of a burst is coalesced).
    void schedule();
    /// Starts a run now (no debounce), e.g. when new data arrive.
    void startNow();
    /// Drops any pending or running work without a new run.
    void cancel();

    /// Bumps on every schedule(); a result is delivered only for the latest.
    quint64 generation() const { return m_generation; }
    /// A run is pending (debounce) or working.
    bool busy() const { return m_timer.isActive() || m_running; }
    /// ms since the epoch of the last schedule() (latency measurements).
    qint64 changedAt() const { return m_changedAt; }
    /// Processes events until the job is idle or timeoutMs passes; false on timeout.
    bool waitIdle(int timeoutMs);

signals:
    /// Progress of the current run in [0, 1] (from the worker's Feedback, on the GUI thread).
    void progress(double fraction);
    /// The job went idle (its latest run delivered, or there was nothing to run).
    void idle();
    /// The latest run threw instead of returning (out of memory, an internal error): why. The
    /// job is idle; nothing was delivered.
    void failed(const QString& reason);

private:
    void run();
    void finished(quint64 gen);
    std::shared_ptr<core::Feedback> newFeedback(quint64 gen);
    void track(QFuture<void> f);

    std::function<void()> m_start;
    QTimer m_timer;
    quint64 m_generation = 0;
    qint64 m_changedAt = 0;
    bool m_running = false;
    std::shared_ptr<core::Feedback> m_feedback;
    std::vector<QFuture<void>> m_futures;
};

}  // namespace lwb::ui
