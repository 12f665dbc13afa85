#pragma once
// Cancellation token and progress sink that long core loops poll (the QgsFeedback idea).
#include <atomic>
#include <functional>
#include <mutex>

namespace lwb::core {

class Feedback {
public:
    /// progress(fraction in [0,1]); called from the worker thread, throttled by the caller.
    using ProgressFn = std::function<void(double)>;

    Feedback() = default;
    explicit Feedback(ProgressFn fn) : m_progress(std::move(fn)) {}

    void cancel() { m_cancelled.store(true, std::memory_order_relaxed); }
    bool isCancelled() const { return m_cancelled.load(std::memory_order_relaxed); }
    void setProgress(double fraction) const {
        if (m_progress) m_progress(fraction);
    }

private:
    std::atomic<bool> m_cancelled{false};
    ProgressFn m_progress;
};

/// True when fb is given and cancelled: the idiom every long loop uses.
inline bool cancelled(const Feedback* fb) { return fb && fb->isCancelled(); }

}  // namespace lwb::core
