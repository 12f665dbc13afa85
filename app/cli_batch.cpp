#include "cli_batch.hpp"

#include <sys/stat.h>

#include <filesystem>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <iostream>
#include <unistd.h>

#include "core/common/atomic_file.hpp"
#include "core/common/sha256.hpp"
#include "core/common/text.hpp"
#include "lwb_version.hpp"

namespace lwb::cli {

const char* const kBatchOptionsHelp =
    "Many inputs, many machines:\n"
    "  --files-from FILE     more inputs, one path per line (- = standard input; blank lines and\n"
    "                        lines starting with # skipped; relative to the current folder)\n"
    "  --shard K/N           run only the K-th of N shares (1 <= K <= N): the inputs, in the order\n"
    "                        given (folders sorted, shot lists row by row), cut into N contiguous\n"
    "                        blocks; block K is floor((K-1)n/N) .. floor(Kn/N)-1 of the n inputs. The N\n"
    "                        shards' outputs, one after the other, are the unsharded run's\n"
    "  --skip-existing       do nothing for an input whose outputs are complete and up to date: its\n"
    "                        provenance sidecar exists, has the same parameters and settings, the\n"
    "                        same inputs with the SHA-256 they have now, and every output with the\n"
    "                        SHA-256 the file has now\n"
    "  --summary-json FILE   a JSON account of the run, written (atomically) however it ends: per\n"
    "                        input its status, outputs and seconds; the outputs; the exit code and\n"
    "                        its meaning\n";

void declareBatchOptions(Args& a) {
    for (const char* o : {"--files-from", "--shard", "--summary-json"}) a.option(o, true);
    a.option("--skip-existing", false);
}

bool readPathList(const std::string& path, std::vector<std::string>* out, std::string* error) {
    std::string text;
    if (!core::readFileText(path, &text, error)) return false;
    size_t from = 0;
    long line = 0;
    while (from < text.size()) {
        size_t to = text.find('\n', from);
        if (to == std::string::npos) to = text.size();
        std::string l = text.substr(from, to - from);
        from = to + 1;
        ++line;
        if (!l.empty() && l.back() == '\r') l.pop_back();
        if (l.find('\0') != std::string::npos) {
            *error = core::whereInFile(path == "-" ? "<stdin>" : path, line) + "a NUL byte: not a list of paths";
            return false;
        }
        if (core::trim(l).empty() || l[0] == '#') continue;
        out->push_back(l);
    }
    return true;
}

int loadBatchOptions(const std::string& cmd, const Args& a, BatchOptions* o) {
    if (a.has("--shard")) {
        const std::string t = a.value("--shard");
        const size_t slash = t.find('/');
        long long k = 0, n = 0;
        if (slash == std::string::npos || !core::parseLong(t.substr(0, slash), &k) ||
            !core::parseLong(t.substr(slash + 1), &n) || n < 1 || k < 1 || k > n || n > 1000000)
            return fail(cmd, "--shard must be K/N with 1 <= K <= N (e.g. 3/8: the third of eight shares), not \"" + t + "\"",
                        kUsage);
        o->shard = {size_t(k), size_t(n), true};
    }
    o->skipExisting = a.has("--skip-existing");
    o->summaryJson = a.value("--summary-json");
    if (a.has("--summary-json") && o->summaryJson.empty()) return fail(cmd, "--summary-json needs a file name", kUsage);
    if (a.has("--files-from")) {
        o->filesFrom = a.value("--files-from");
        std::string err;
        if (!readPathList(o->filesFrom, &o->listed, &err)) return fail(cmd, "--files-from: " + err);
    }
    return kOk;
}

namespace {
const char* exitMeaning(int code) {
    switch (code) {
        case kOk: return "done";
        case kFailed: return "bad input or failed run: nothing written";
        case kUsage: return "usage error: nothing read or written";
        case kDoubtful: return "outputs written, some result doubtful";
        case kSomeFailed: return "outputs written, some inputs failed";
        default: return "other";
    }
}
}  // namespace

RunSummary::RunSummary(std::string command, const BatchOptions& options)
    : m_command(std::move(command)), m_options(options), m_start(std::chrono::steady_clock::now()) {}

namespace {
// `path` as an absolute path with . and .. resolved, and symbolic links of what exists.
std::string absolutePath(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
    return ec ? path : p.lexically_normal().string();
}
}  // namespace

int RunSummary::checkTarget(const std::vector<std::string>& outputs, const std::vector<std::string>& folders,
                            const std::function<bool(const std::string&)>& owns) const {
    const std::string& path = m_options.summaryJson;
    if (path.empty()) return kOk;
    m_targetRefused = true;  // (until every check passed)
    const std::string prefix = "--summary-json " + path;
    if (const std::string in = core::inputReadAs(path); !in.empty())
        return fail(m_command, prefix + " is " + in + ", a file of this run (an input); nothing run", kUsage);
    for (const auto& o : outputs)
        if (o == path || core::sameFile(o, path) || absolutePath(o) == absolutePath(path))
            return fail(m_command, prefix + " is " + o + ", a file of this run (an output); nothing run", kUsage);
    const std::filesystem::path target(absolutePath(path));
    for (const auto& d : folders)
        if (target.parent_path() == std::filesystem::path(absolutePath(d)) && owns && owns(target.filename().string()))
            return fail(m_command, prefix + " is a file this run writes in " + d + "/; nothing run", kUsage);
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        return fail(m_command, prefix + ": not a regular file (a folder or a device); nothing run", kFailed);
    const std::string parent = std::filesystem::path(absolutePath(path)).parent_path().string();
    bool made = false;  // (a folder the run makes)
    for (const auto& d : folders) made |= std::filesystem::path(absolutePath(d)) == std::filesystem::path(parent);
    if (!made && (::stat(parent.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)))
        return fail(m_command, prefix + ": the folder " + parent + " does not exist; nothing run", kFailed);
    m_targetRefused = false;
    return kOk;
}

int RunSummary::finish(int exitCode) {
    if (m_options.summaryJson.empty() || m_targetRefused) return exitCode;
    core::Json j = core::Json::object();
    j["software"] = "laserwb";
    j["version"] = LWB_VERSION;
    j["command"] = m_command;
    j["exit_code"] = exitCode;
    j["exit_meaning"] = exitMeaning(exitCode);
    j["error"] = exitCode == kOk || exitCode == kDoubtful ? std::string() : lastFailure();
    j["shard"] = m_options.shard.text();
    j["files_from"] = m_options.filesFrom;
    j["skip_existing"] = m_options.skipExisting;
    j["inputs_total"] = m_total;
    j["inputs_in_shard"] = m_inputs.size();
    std::map<std::string, size_t> counts;
    for (const auto& e : m_inputs) ++counts[e.value("status", std::string())];
    j["status_counts"] = counts;
    j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    j["outputs"] = m_outputs;
    j["inputs"] = m_inputs;
    // Never over an input of the run or one of its outputs.
    const std::string& path = m_options.summaryJson;
    std::string clash = core::inputReadAs(path);
    for (const auto& o : m_outputs)
        if (clash.empty() && (o == path || core::sameFile(o, path))) clash = o;
    if (!clash.empty()) {
        std::cerr << "laserwb-cli " << m_command << ": --summary-json " << path << " is " << clash
                  << ", a file of this run; no summary written\n";
        return exitCode == kOk ? kUsage : exitCode;
    }
    std::string err;
    if (!core::writeFileAtomic(path, core::dumpJson(j), &err)) {
        std::cerr << "laserwb-cli " << m_command << ": --summary-json: " << err << "\n";
        return exitCode == kOk ? kFailed : exitCode;
    }
    return exitCode;
}

namespace {
std::string folderOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}
// The file a name recorded in a sidecar stands for (core::recordedName).
std::string recordedFile(const std::string& name, const std::string& sidecar) {
    return name.find('/') == std::string::npos ? folderOf(sidecar) + name : name;
}
}  // namespace

std::string addProvenanceSidecar(core::OutputSet& outs) {
    const std::vector<std::string> files = outs.fileOutputs();
    if (files.empty()) return {};
    const std::string sidecar = core::provenancePathFor(files.front());
    outs.addOutput(sidecar);
    return sidecar;
}

int stageRunProvenance(const std::string& command, core::OutputSet& outs, const std::string& sidecar, core::Json parameters) {
    if (sidecar.empty()) return kOk;
    core::Provenance p;
    p.command = command;
    p.parameters = std::move(parameters);
    p.inputs = outs.inputs();
    std::vector<std::string> outputs;
    for (const std::string& o : outs.fileOutputs())
        if (o != sidecar) outputs.push_back(o);
    std::string err;
    return stageProvenance(outs, p, outputs, sidecar, &err) ? kOk : fail(command, err);
}

bool outputsComplete(const core::Provenance& p, const std::vector<std::string>& outputs, const std::string& sidecar,
                     std::string* why) {
    std::string dummy;
    std::string& w = why ? *why : dummy;
    if (::access(sidecar.c_str(), F_OK) != 0) return w = sidecar + " does not exist", false;
    // A folder, FIFO or device there is not a sidecar (reading a folder threw "basic_filebuf::
    // underflow ... Is a directory" out of the command); the run then refuses it as an output.
    if (core::regularFileProblem(sidecar, &w)) return false;
    // (read directly, not as an input of the run: the run may write it again)
    std::ifstream f(sidecar, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const core::JsonParseResult j = core::parseJson(text, sidecar);
    if (!j.ok || !j.value.is_object()) return w = sidecar + ": not a provenance file", false;
    const core::Json& v = j.value;
    if (v.value("command", std::string()) != p.command || !v.contains("parameters") ||
        core::dumpJson(v["parameters"]) != core::dumpJson(p.parameters) || !v.contains("settings") ||
        core::dumpJson(v["settings"]) != core::dumpJson(p.settings))
        return w = sidecar + ": made with other parameters or settings", false;
    // The same inputs, unchanged: their names in order and the checksums they have now.
    std::vector<std::string> inputs;
    for (const auto& f : p.inputs)
        if (!f.empty() && std::find(inputs.begin(), inputs.end(), f) == inputs.end()) inputs.push_back(f);
    const auto ins = v.find("inputs");
    if (ins == v.end() || !ins->is_array() || ins->size() != inputs.size())
        return w = sidecar + ": made from other inputs", false;
    for (size_t i = 0; i < inputs.size(); ++i) {
        const core::Json& e = (*ins)[i];
        if (!e.is_object() || e.value("path", std::string()) != inputs[i]) return w = sidecar + ": made from other inputs", false;
        if (!e.contains("sha256") || !e["sha256"].is_string()) continue;  // (standard input, a folder)
        std::string hex, err;
        if (!core::sha256File(inputs[i], &hex, &err)) return w = err, false;
        if (e["sha256"].get<std::string>() != hex) return w = inputs[i] + ": changed since the outputs were made", false;
    }
    const auto it = v.find("outputs");
    if (it == v.end() || !it->is_array() || it->empty() || (!outputs.empty() && it->size() != outputs.size()))
        return w = sidecar + ": lists other outputs", false;
    for (size_t i = 0; i < it->size(); ++i) {
        const core::Json& e = (*it)[i];
        if (!e.is_object() || !e.contains("path") || !e["path"].is_string() ||
            (!outputs.empty() && e["path"].get<std::string>() != core::recordedName(outputs[i], sidecar)))
            return w = sidecar + ": lists other outputs", false;
        const std::string out = recordedFile(e["path"].get<std::string>(), sidecar);
        std::string hex, err;
        if (!core::sha256File(out, &hex, &err)) return w = err, false;
        if (e.value("sha256", std::string()) != hex) return w = out + ": changed since it was written", false;
    }
    return true;
}

}  // namespace lwb::cli
