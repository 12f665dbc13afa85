#pragma once
// A task: one family's processing as one object, run the same way by the CLI (a thin runner:
// parse -> task -> writers -> commit), by the workbench (ui/task_job.hpp: TaskJob<Task>, the
// live rerun) and by the tests. QGIS Processing's algorithm object is the model: one
// declaration from which every front end is driven. Every task is a struct of this shape:
//
//     struct SomeTask {
//         static constexpr const char* kName = "slr pass";      // what messages and docs call it
//         using Params = ...;                                    // the parameters ...
//         static const Schema<Params>& schema();                 // ... and their one schema
//         struct Inputs { ... };                                 // typed, already read and checked
//         struct Reuse { ... };                                  // what an earlier run may give
//         using Outputs = ...;                                   // typed results; writers beside them
//         static Outputs run(const Inputs&, const Params&, const Reuse&, Feedback*);
//     };
//
// Reuse carries the results of the stages an earlier run already made (empty: run everything).
// Which stages a parameter change touches comes from the schema rows' stage tags
// (Schema::firstChangedStage), never from key strings. run() never throws; a failure is a field
// of Outputs. The writers of Outputs live beside them (e.g. core/slr/pass_output.hpp).
#include "core/common/feedback.hpp"

namespace lwb::core {

/// The Reuse of a task that has no stage to reuse.
struct NoReuse {};

/// Runs `Task` from scratch (no earlier run to reuse): what the CLI and the tests call.
template <class Task>
typename Task::Outputs runTask(const typename Task::Inputs& in, const typename Task::Params& params,
                               Feedback* fb = nullptr) {
    return Task::run(in, params, typename Task::Reuse{}, fb);
}

}  // namespace lwb::core
