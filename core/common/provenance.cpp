#include "core/common/provenance.hpp"

#include <cerrno>

#include <set>
#include <sys/stat.h>

#include "core/common/atomic_file.hpp"
#include "core/common/folder.hpp"
#include "core/common/sha256.hpp"
#include "lwb_version.hpp"

namespace lwb::core {

bool provenanceText(const Provenance& p, const std::vector<std::string>& outputs, const std::vector<std::string>& files,
                    std::string* text, std::string* error) {
    Json j = Json::object();
    j["software"] = "laserwb";
    j["version"] = LWB_VERSION;
    j["command"] = p.command;
    j["parameters"] = p.parameters;
    j["settings"] = p.settings;
    auto listed = [&](const std::string& name, const std::string& file) -> Json {
        Json e = Json::object();
        e["path"] = name;
        struct stat st {};
        const bool exists = isStandardStream(file) || ::stat(file.c_str(), &st) == 0;
        if (!exists && errno == ENOENT) {  // (a frame named but missing, reported as a rejected row: --keep-going)
            e["sha256"] = nullptr;
            e["missing"] = true;
            return e;
        }
        if (isStandardStream(file) || (exists && S_ISDIR(st.st_mode))) {
            e["sha256"] = nullptr;  // (standard input, read once; a folder, such as a CPF folder)
            return e;
        }
        std::string hex;
        if (!sha256File(file, &hex, error)) return Json();
        e["sha256"] = hex;
        return e;
    };
    Json in = Json::array();
    std::set<std::string> seen;
    for (const std::string& f : p.inputs) {
        if (f.empty() || !seen.insert(f).second) continue;
        Json e = listed(f, f);
        if (e.is_null()) return false;
        in.push_back(std::move(e));
    }
    j["inputs"] = std::move(in);
    Json out = Json::array();
    for (size_t i = 0; i < outputs.size() && i < files.size(); ++i) {
        Json e = listed(outputs[i], files[i]);
        if (e.is_null()) return false;
        out.push_back(std::move(e));
    }
    j["outputs"] = std::move(out);
    *text = dumpJson(j);
    return true;
}

std::string recordedName(const std::string& output, const std::string& sidecar) {
    if (folderWithSlash(output) == folderWithSlash(sidecar)) return output.substr(folderWithSlash(output).size());
    return output.find('/') == std::string::npos ? "./" + output : output;
}

bool stageProvenance(OutputSet& outs, const Provenance& p, const std::vector<std::string>& outputs,
                     const std::string& sidecar, std::string* error) {
    std::vector<std::string> staged, names;
    for (const auto& o : outputs) {
        staged.push_back(outs.stagingPath(o));
        names.push_back(recordedName(o, sidecar));
    }
    std::string text;
    if (!provenanceText(p, names, staged, &text, error)) {
        *error = outs.unstaged(*error);
        return false;
    }
    if (!writeFileAtomic(outs.stagingPath(sidecar), text, error)) {
        *error = outs.unstaged(*error);
        return false;
    }
    return true;
}

bool writeWithProvenance(const Provenance& p, const std::string& path,
                         const std::function<bool(const std::string&, std::string*)>& write, std::string* error,
                         bool update) {
    if (isStandardStream(path)) return write(path, error);
    OutputSet outs;
    for (const std::string& in : p.inputs) outs.addInput(in);
    const std::string sidecar = provenancePathFor(path);
    if (update) outs.addUpdate(path);
    else outs.addOutput(path);
    outs.addOutput(sidecar);
    if (!outs.check()) {
        *error = outs.error();
        return false;
    }
    if (!write(outs.stagingPath(path), error)) {
        *error = outs.unstaged(*error);
        return false;
    }
    if (!stageProvenance(outs, p, {path}, sidecar, error)) return false;
    if (!outs.commit()) {
        *error = outs.error();
        return false;
    }
    return true;
}

}  // namespace lwb::core
