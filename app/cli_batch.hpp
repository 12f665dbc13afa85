#pragma once
// What makes a command fit for array jobs (many machines, each a share of the inputs):
// --files-from FILE|- (the inputs listed one per line), --shard K/N (this run's share),
// --skip-existing (inputs whose outputs are complete are not run again), --summary-json FILE
// (a machine-readable account of the run), and the provenance sidecars of the outputs
// (core/common/provenance.hpp). The footprint and slr commands use them.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "cli_common.hpp"
#include "core/common/json.hpp"
#include "core/common/output_set.hpp"
#include "core/common/provenance.hpp"

namespace lwb::cli {

/// --shard K/N: this run takes the K-th of N contiguous blocks of the inputs (1 <= K <= N).
struct Shard {
    size_t k = 1, n = 1;
    bool given = false;
    /// [first, last) of `count` inputs: floor((K-1)*count/N) .. floor(K*count/N). The blocks of
    /// K = 1..N cover every input once, in order, so the shards' outputs put one after the other
    /// are the unsharded run's.
    std::pair<size_t, size_t> range(size_t count) const { return {(k - 1) * count / n, k * count / n}; }
    std::string text() const { return std::to_string(k) + "/" + std::to_string(n); }
};

/// The options of a command that takes many inputs.
struct BatchOptions {
    std::vector<std::string> listed;  ///< the inputs of --files-from, in order
    std::string filesFrom;            ///< the list's name ("" when not given)
    Shard shard;
    bool skipExisting = false;
    std::string summaryJson;          ///< "" when not given
};

/// The usage paragraph of these options.
extern const char* const kBatchOptionsHelp;
/// Declares --files-from, --shard, --skip-existing and --summary-json.
void declareBatchOptions(Args& a);
/// Reads them (and the --files-from list): kOk, or the exit code after saying why.
int loadBatchOptions(const std::string& cmd, const Args& a, BatchOptions* o);

/// A list of paths, one per line ('-': standard input): blank lines and lines starting with '#'
/// are skipped, a final CR is dropped, nothing else is changed (a path may hold spaces). Paths
/// are taken as they would be on the command line (relative to the current folder).
bool readPathList(const std::string& path, std::vector<std::string>* out, std::string* error);

/// The run summary (--summary-json): one entry per input with its status, outputs and time, the
/// outputs, the exit code and its meaning, the shard; written atomically when the run ends,
/// whatever the end (a failed run's summary says why). Times are measured: the one part of a run
/// that is not reproducible, which is why they are here and not in the outputs.
class RunSummary {
public:
    RunSummary(std::string command, const BatchOptions& options);
    /// One input's entry: "input", "status" and whatever else the command adds.
    void addInput(core::Json entry) { m_inputs.push_back(std::move(entry)); }
    void setInputsTotal(size_t n) { m_total = n; }
    void addOutput(const std::string& path) { m_outputs.push_back(path); }
    /// Before any work: the summary's file (when asked for) is no input of the run, none of
    /// `outputs`, no file a folder of `folders` will hold (`owns(name)`: the run writes a file
    /// of that name in each, e.g. summary.csv), not a folder or a device, and its folder
    /// exists. 0 when fine, else the exit code after saying why (2: the name; 1: where it goes).
    int checkTarget(const std::vector<std::string>& outputs, const std::vector<std::string>& folders = {},
                    const std::function<bool(const std::string& name)>& owns = {}) const;
    /// Writes the summary (when asked for) and returns `exitCode`, or kFailed when it cannot be written.
    int finish(int exitCode);

private:
    std::string m_command;
    const BatchOptions& m_options;
    std::vector<core::Json> m_inputs;
    std::vector<std::string> m_outputs;
    size_t m_total = 0;
    std::chrono::steady_clock::time_point m_start;
    mutable bool m_targetRefused = false;  ///< checkTarget said no: finish writes nothing
};

/// (core::stageProvenance, core/common/provenance.hpp, stages a sidecar.)
using core::stageProvenance;

/// The provenance of a single command's outputs (calib, radiometry): addProvenanceSidecar(),
/// after the outputs are added and before checkOutputs, adds FIRST.provenance.json beside the
/// first output written to a file and returns its path ("" when everything goes to standard
/// output); stageRunProvenance(), before commitOutputs, stages it with the command, the
/// parameters (the schema's JSON), the inputs and outputs the set lists and their SHA-256.
std::string addProvenanceSidecar(core::OutputSet& outs);
int stageRunProvenance(const std::string& command, core::OutputSet& outs, const std::string& sidecar, core::Json parameters);

/// --skip-existing: true when `sidecar` exists, records the same command, parameters, settings
/// and inputs as `p` (each input with the SHA-256 it has now), and lists exactly `outputs`
/// (empty: whatever it lists, at least one), each with the SHA-256 its file has now. Every
/// output is renamed into place whole (core::OutputSet) and the sidecar last, so a file that
/// exists is complete; the checksums also catch a set that a killed or later run left mixed.
/// *why (when given) says what differs.
bool outputsComplete(const core::Provenance& p, const std::vector<std::string>& outputs, const std::string& sidecar,
                     std::string* why = nullptr);

}  // namespace lwb::cli
