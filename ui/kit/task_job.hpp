#pragma once
// The live job of a core task (core/common/task.hpp): a LiveJob (debounce, cancel, generation
// tag, progress) whose work is always Task::run. A workspace controller says what to run (a
// snapshot of inputs, parameters and what an earlier run can give, taken on the GUI thread) and
// what to do with the outputs; it never writes a processing loop of its own, so the workbench
// computes exactly what the CLI computes from the same inputs and parameters.
//
//     TaskJob<core::slr::PassTask> m_job;
//     m_job.bind([this](auto* run) { if (!hasPass()) return false; run->inputs = ...; run->params = m_params; return true; },
//                [this](core::slr::PassRunResult r) { ...show it... });
//     m_job.schedule();   // on every change
#include <functional>
#include <memory>

#include "ui/kit/live_job.hpp"

namespace lwb::ui {

template <class Task>
class TaskJob : public LiveJob {
public:
    using Inputs = typename Task::Inputs;
    using Params = typename Task::Params;
    using Reuse = typename Task::Reuse;
    using Outputs = typename Task::Outputs;

    /// One run's arguments, copied on the GUI thread (inputs shared, never changed after).
    struct Run {
        std::shared_ptr<const Inputs> inputs;
        Params params{};
        Reuse reuse{};
    };

    explicit TaskJob(QObject* parent = nullptr) : LiveJob(parent) {}

    /// `snapshot` fills a Run on the GUI thread when a run starts (false: nothing to run, e.g.
    /// no data yet); Task::run works on the thread pool; `deliver` gets the outputs on the GUI
    /// thread unless the run went stale or was cancelled.
    void bind(std::function<bool(Run*)> snapshot, std::function<void(Outputs)> deliver) {
        setWork<Outputs>(
            [snapshot = std::move(snapshot)]() -> std::function<Outputs(core::Feedback&)> {
                Run r;
                if (!snapshot(&r) || !r.inputs) return {};
                return [r = std::move(r)](core::Feedback& fb) { return Task::run(*r.inputs, r.params, r.reuse, &fb); };
            },
            std::move(deliver));
    }
};

}  // namespace lwb::ui
