#include "ui/kit/live_job.hpp"

#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>

namespace lwb::ui {

LiveJob::LiveJob(QObject* parent) : QObject(parent) {
    m_timer.setSingleShot(true);
    m_timer.setInterval(kDebounceMs);
    connect(&m_timer, &QTimer::timeout, this, &LiveJob::run);
}

LiveJob::~LiveJob() {
    ++m_generation;
    if (m_feedback) m_feedback->cancel();
    for (QFuture<void>& f : m_futures) f.waitForFinished();
}

void LiveJob::schedule() {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const bool quiet = !busy() && now - m_changedAt >= kDebounceMs;
    ++m_generation;
    m_changedAt = now;
    if (m_feedback) m_feedback->cancel();  // the running work is stale now
    if (quiet) {
        run();
    } else {
        m_running = false;  // whatever runs is stale; the timer's run takes over
        m_timer.start();
    }
}

void LiveJob::startNow() {
    ++m_generation;
    m_changedAt = QDateTime::currentMSecsSinceEpoch();
    if (m_feedback) m_feedback->cancel();
    m_timer.stop();
    run();
}

void LiveJob::cancel() {
    ++m_generation;
    if (m_feedback) m_feedback->cancel();
    m_timer.stop();
    const bool was = m_running;
    m_running = false;
    if (was) emit idle();
}

void LiveJob::run() {
    m_timer.stop();
    if (!m_start) return;
    m_running = true;
    m_start();
}

void LiveJob::finished(quint64 gen) {
    if (gen != m_generation) return;
    m_running = false;
    if (!m_timer.isActive()) emit idle();
}

std::shared_ptr<core::Feedback> LiveJob::newFeedback(quint64 gen) {
    QPointer<LiveJob> self(this);
    m_feedback = std::make_shared<core::Feedback>([self, gen](double f) {
        QMetaObject::invokeMethod(
            qApp,
            [self, gen, f] {
                if (self && gen == self->m_generation) emit self->progress(f);
            },
            Qt::QueuedConnection);
    });
    return m_feedback;
}

void LiveJob::track(QFuture<void> f) {
    std::vector<QFuture<void>> kept;
    for (QFuture<void>& g : m_futures)
        if (!g.isFinished()) kept.push_back(g);
    kept.push_back(std::move(f));
    m_futures = std::move(kept);
}

bool waitUntilIdle(const std::function<bool()>& busy, int timeoutMs) {
    QElapsedTimer t;
    t.start();
    for (;;) {  // events first: a result may be queued for delivery
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (!busy()) return true;
        if (t.elapsed() >= timeoutMs) return false;
    }
}

bool LiveJob::waitIdle(int timeoutMs) {
    return waitUntilIdle([this] { return busy(); }, timeoutMs);
}

}  // namespace lwb::ui
