#pragma once
// A load the caller waits for, without a frozen window (issue 42: a 10^6-point pass showed
// empty axes for 1.5-3 s with no progress and no Cancel). The work runs on the thread pool
// with a core::Feedback; the GUI thread keeps painting, user input held back, and after
// kShowAfterMs a window-modal progress dialog with Cancel appears (the window behind it takes
// no input, so nothing re-enters the caller mid-load). The caller gets the work's result as if
// it had called it directly: the synchronous API of a controller's open stays.
//
//     bool cancelled = false;
//     SlrOpening o = runModal<SlrOpening>(this, tr("Opening %1…").arg(name),
//                                         [=](const core::Feedback* fb) { return readForOpen(..., fb); }, &cancelled);
#include <QFuture>
#include <QString>
#include <QtConcurrent>
#include <atomic>
#include <functional>

#include "core/common/feedback.hpp"

class QWidget;

namespace lwb::ui {

class ModalProgress {
public:
    /// The dialog appears when the work takes longer than this (ms).
    static constexpr int kShowAfterMs = 400;

    ModalProgress(QWidget* parent, QString label);
    /// The work's cancel token and progress sink (progress in [0, 1] from any thread).
    const core::Feedback& feedback() const { return m_fb; }
    /// Returns when `work` has finished (after a Cancel too: the work is asked to stop and
    /// waited for, so nothing it holds outlives the call).
    void wait(const QFuture<void>& work);
    bool cancelled() const { return m_fb.isCancelled(); }

    /// How many progress dialogs have been shown since the program started (ui tests).
    static int dialogsShown();

private:
    QWidget* m_parent;
    QString m_label;
    std::atomic<int> m_permille{0};
    core::Feedback m_fb;
};

/// Runs `work` on the thread pool under a ModalProgress and returns its result; *cancelled
/// (when given) says whether the analyst pressed Cancel (the result is then whatever the work
/// returned when it noticed).
template <class R>
R runModal(QWidget* parent, const QString& label, std::function<R(const core::Feedback*)> work, bool* cancelled = nullptr) {
    ModalProgress progress(parent, label);
    R out{};
    progress.wait(QtConcurrent::run([&out, &work, &progress] { out = work(&progress.feedback()); }));
    if (cancelled) *cancelled = progress.cancelled();
    return out;
}

}  // namespace lwb::ui
