#include "core/common/output_set.hpp"

#include <functional>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <dirent.h>
#include <fnmatch.h>
#include <mutex>
#include <set>
#include <signal.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace lwb::core {

namespace {

std::string folderOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string baseOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string realPath(const std::string& path) {
    char buf[PATH_MAX];
    return ::realpath(path.c_str(), buf) ? std::string(buf) : std::string();
}

// The file a path names, for comparisons: device and inode when it exists, else the
// canonical folder and the name.
struct Identity {
    bool exists = false;
    dev_t dev = 0;
    ino_t ino = 0;
    std::string canonical;
    bool same(const Identity& o) const {
        if (exists && o.exists) return dev == o.dev && ino == o.ino;
        return !exists && !o.exists && canonical == o.canonical;
    }
};

const char* kindOf(mode_t m) {
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISFIFO(m)) return "a FIFO (named pipe)";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}

std::atomic<int> g_stdoutFd{1};

struct InputRead {
    dev_t dev;
    ino_t ino;
    std::string path;
};
std::mutex g_inputsMutex;
std::vector<InputRead>& inputsRead() {
    static std::vector<InputRead> v;
    return v;
}

// The name of a noted input that is the file `st` describes, or "".
std::string noted(const struct stat& st) {
    std::lock_guard<std::mutex> lock(g_inputsMutex);
    for (const InputRead& r : inputsRead())
        if (r.dev == st.st_dev && r.ino == st.st_ino) return r.path;
    return {};
}

// Copies a staged file to a file descriptor; false with *why.
bool copyToFd(const std::string& path, int fd, std::string* why) {
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        *why = std::strerror(errno);
        return false;
    }
    char buf[1 << 16];
    bool ok = true;
    for (size_t n; ok && (n = std::fread(buf, 1, sizeof buf, f)) > 0;) {
        for (size_t off = 0; off < n;) {
            const ssize_t w = ::write(fd, buf + off, n - off);
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) {
                *why = std::strerror(errno);
                ok = false;
                break;
            }
            off += static_cast<size_t>(w);
        }
    }
    if (ok && std::ferror(f)) {
        *why = "cannot read the staged output";
        ok = false;
    }
    std::fclose(f);
    return ok;
}

}  // namespace

void noteInputRead(const std::string& path) {
    struct stat st {};
    if (path.empty() || path == "-" || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
    std::lock_guard<std::mutex> lock(g_inputsMutex);
    for (const InputRead& r : inputsRead())
        if (r.dev == st.st_dev && r.ino == st.st_ino) return;
    inputsRead().push_back({st.st_dev, st.st_ino, path});
}

std::string inputReadAs(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return {};
    return noted(st);
}

void setStandardOutputFd(int fd) { g_stdoutFd = fd; }

int removeLeftovers(const std::string& folder) {
    DIR* d = ::opendir(folder.c_str());
    if (!d) return 0;
    int removed = 0;
    std::vector<std::string> names;
    while (const dirent* e = ::readdir(d)) names.emplace_back(e->d_name);
    ::closedir(d);
    for (const std::string& name : names) {
        for (const char* prefix : {".lwb-stage-", ".lwb-backup-", ".lwb-tmp-", ".lwb-stdout-"}) {
            const size_t n = std::strlen(prefix);
            if (name.compare(0, n, prefix) != 0) continue;
            char* end = nullptr;
            const long pid = std::strtol(name.c_str() + n, &end, 10);
            if (pid <= 0 || !end || *end != '-') break;
            // A process that still runs (or one we may not signal: it exists) keeps its files.
            if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM) break;
            const std::string path = folder + "/" + name;
            struct stat st {};
            if (::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && std::remove(path.c_str()) == 0) ++removed;
            break;
        }
    }
    return removed;
}
int standardOutputFd() { return g_stdoutFd; }

std::string faultInjectedName(const char* phase) {
    const char* v = std::getenv("LWB_FAULT_OUTPUT");
    if (!v) return {};
    const std::string s = v, p = std::string(phase) + ":";
    return s.rfind(p, 0) == 0 ? s.substr(p.size()) : std::string();
}

bool sameFile(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

OutputSet::~OutputSet() { abandon(); }

void OutputSet::addInput(const std::string& path) {
    if (!path.empty()) m_inputs.push_back(path);
}

std::vector<std::string> OutputSet::fileOutputs() const {
    std::vector<std::string> out;
    for (const Item& it : m_items)
        if (!it.toStdout) out.push_back(it.path);
    return out;
}

void OutputSet::addOutput(const std::string& path) {
    m_items.push_back({path == "-", path, {}, {}});
    m_checked = false;
}

void OutputSet::setManifest(const std::string& manifest, const std::string& folder, std::vector<std::string> stalePatterns) {
    m_manifest = manifest;
    m_setFolder = folder;
    m_stalePatterns = std::move(stalePatterns);
}

bool OutputSet::writesStandardOutput() const {
    for (const auto& it : m_items)
        if (it.toStdout) return true;
    return false;
}

bool OutputSet::check() {
    m_error.clear();
    m_naming = false;
    std::vector<Identity> inputs;
    for (const auto& in : m_inputs) {
        struct stat st {};
        if (::stat(in.c_str(), &st) != 0) continue;
        Identity id;
        id.exists = true;
        id.dev = st.st_dev;
        id.ino = st.st_ino;
        inputs.push_back(id);
    }
    std::vector<Identity> outputs;
    static std::atomic<int> counter{0};
    bool stdoutTaken = false;
    for (auto& it : m_items) {
        const std::string& p = it.path;
        if (p.empty()) {
            m_error = "an output file name is empty";
            return false;
        }
        if (it.toStdout) {
            if (stdoutTaken) {
                m_error = "two outputs are standard output (-); give one of them a file name (nothing written)";
                m_naming = true;
                return false;
            }
            stdoutTaken = true;
            const char* tmp = std::getenv("TMPDIR");
            std::string stage = std::string(tmp && *tmp ? tmp : "/tmp") + "/.lwb-stdout-XXXXXX";
            const int fd = ::mkstemp(stage.data());
            if (fd < 0) {
                m_error = "-: cannot stage standard output in " + stage.substr(0, stage.rfind('/')) + ": " +
                          std::strerror(errno) + " (set TMPDIR; nothing written)";
                return false;
            }
            ::close(fd);
            it.staging = stage;
            it.target = "-";
            continue;
        }
        Identity id;
        struct stat st {}, lst {};
        const bool linkExists = ::lstat(p.c_str(), &lst) == 0;
        if (::stat(p.c_str(), &st) == 0) {
            if (S_ISDIR(st.st_mode)) {
                m_error = p + ": is a folder, not a file (nothing written)";
                return false;
            }
            if (!S_ISREG(st.st_mode)) {
                m_error = p + ": is " + kindOf(st.st_mode) + "; refusing to replace it (nothing written)";
                return false;
            }
            id.exists = true;
            id.dev = st.st_dev;
            id.ino = st.st_ino;
            it.target = realPath(p);
            if (it.target.empty()) it.target = p;
            if (::access(it.target.c_str(), W_OK) != 0) {
                m_error = p + ": is read-only; refusing to replace it (nothing written)";
                return false;
            }
        } else if (linkExists && S_ISLNK(lst.st_mode)) {
            m_error = p + ": is a symbolic link to a missing file (nothing written)";
            return false;
        } else {
            const std::string dir = folderOf(p);
            const std::string realDir = realPath(dir);
            struct stat ds {};
            if (realDir.empty() || ::stat(realDir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode)) {
                m_error = p + ": the folder " + dir + " does not exist (nothing written)";
                return false;
            }
            it.target = (realDir == "/" ? "" : realDir) + "/" + baseOf(p);
            id.canonical = it.target;
        }
        const std::string targetDir = folderOf(it.target);
        if (::access(targetDir.c_str(), W_OK) != 0) {
            m_error = p + ": cannot write in " + targetDir + ": " + std::strerror(errno) + " (nothing written)";
            return false;
        }
        static std::vector<std::string> cleaned;  // (each folder once per process)
        if (std::find(cleaned.begin(), cleaned.end(), targetDir) == cleaned.end()) {
            removeLeftovers(targetDir);
            cleaned.push_back(targetDir);
        }
        for (const auto& in : inputs)
            if (id.same(in)) {
                m_error = p + ": an output would overwrite the input (the same file); nothing written";
                m_naming = true;
                return false;
            }
        if (id.exists) {
            const std::string as = noted(st);
            if (!as.empty()) {
                m_error = p + ": an output would overwrite an input of this run (the same file as " + as + "); nothing written";
                m_naming = true;
                return false;
            }
        }
        for (size_t k = 0; k < outputs.size(); ++k)
            if (id.same(outputs[k])) {
                m_error = "two outputs name the same file: " + m_items[k].path + " and " + p + " (nothing written)";
                m_naming = true;
                return false;
            }
        outputs.push_back(id);
        it.staging = targetDir + "/.lwb-stage-" + std::to_string(::getpid()) + "-" + std::to_string(++counter) + "-" +
                     baseOf(it.target);
    }
    m_checked = true;
    return true;
}

std::string OutputSet::stagingPath(const std::string& output) const {
    if (!m_checked) return {};
    for (const auto& it : m_items)
        if (it.path == output) return it.staging;
    return {};
}

std::string OutputSet::unstaged(std::string message) const {
    for (const auto& it : m_items) {
        if (it.staging.empty()) continue;
        for (size_t pos; (pos = message.find(it.staging)) != std::string::npos;)
            message.replace(pos, it.staging.size(), it.path);
    }
    return message;
}

// Before anything is renamed: the set was checked, every output was staged, and no output is an
// input read since check(). False with m_error, the set abandoned.
bool OutputSet::readyToCommit() {
    if (!m_checked) {
        m_error = "internal error: outputs committed before they were checked";
        abandon();
        return false;
    }
    for (const auto& it : m_items) {
        struct stat st {};
        if (::stat(it.staging.c_str(), &st) != 0) {
            m_error = it.path + ": was not written (nothing written)";
            abandon();
            return false;
        }
    }
    // Inputs read since check() (a file picked from a folder, a config read late) are protected too.
    for (const auto& it : m_items) {
        if (it.toStdout) continue;
        const std::string as = inputReadAs(it.target);
        if (!as.empty()) {
            m_error = it.path + ": an output would overwrite an input of this run (the same file as " + as +
                      "); nothing written";
            m_naming = true;
            abandon();
            return false;
        }
    }
    return true;
}

// Earlier outputs of the same kind in the set's folder that this run did not write again: each
// kept aside (setAside) and removed. False with m_error.
bool OutputSet::removeStaleOutputs(const std::function<bool(const std::string&)>& setAside) {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(m_setFolder.c_str())) {
        while (const dirent* e = ::readdir(d)) names.emplace_back(e->d_name);
        ::closedir(d);
    }
    std::sort(names.begin(), names.end());
    // This run's outputs by (device, inode), each stat'ed once: a folder of 20 000 pass files
    // is one pass over the folder, not one per file and output.
    std::set<std::pair<dev_t, ino_t>> ours;
    for (const auto& it : m_items) {
        struct stat st {};
        if (!it.toStdout && ::stat(it.target.c_str(), &st) == 0) ours.emplace(st.st_dev, st.st_ino);
    }
    for (const std::string& name : names) {
        bool match = false;
        for (const std::string& pat : m_stalePatterns) match = match || ::fnmatch(pat.c_str(), name.c_str(), 0) == 0;
        const std::string path = m_setFolder + "/" + name;
        struct stat st {};
        if (!match || ::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        if (ours.count({st.st_dev, st.st_ino}) || !inputReadAs(path).empty()) continue;
        if (!setAside(path) || ::unlink(path.c_str()) != 0) {
            m_error = "cannot remove the earlier output " + path + ": " + std::strerror(errno) + " (nothing written)";
            return false;
        }
    }
    return true;
}

bool OutputSet::commit() {
    if (!readyToCommit()) return false;
    // Every file replaced or removed keeps a hard link (a backup) until the end, so that a failure
    // half-way through can put it back; a new file is removed again. Order: the manifest's old
    // file first, the new files, the stale files of the set, the manifest last.
    const std::string faultName = faultInjectedName("rename"), killName = faultInjectedName("kill");
    std::vector<std::pair<std::string, std::string>> restore;  // (backup, original)
    std::vector<std::string> created;
    int backupCount = 0;
    auto setAside = [&](const std::string& target) {  // false when it cannot be kept
        struct stat st {};
        if (::lstat(target.c_str(), &st) != 0) return true;  // nothing there
        const std::string b = folderOf(target) + "/.lwb-backup-" + std::to_string(::getpid()) + "-" +
                              std::to_string(backupCount++) + "-" + baseOf(target);
        if (::link(target.c_str(), b.c_str()) != 0) return false;
        restore.emplace_back(b, target);
        return true;
    };
    auto put = [&](const Item& it) {
        const bool existed = ::access(it.target.c_str(), F_OK) == 0;
        if (existed && !setAside(it.target)) {
            m_error = "cannot write " + it.path + ": cannot keep the file it replaces: " + std::strerror(errno) +
                      " (nothing written)";
            return false;
        }
        auto endsWith = [&](const std::string& name) {
            return !name.empty() && it.target.size() >= name.size() &&
                   it.target.compare(it.target.size() - name.size(), name.size(), name) == 0;
        };
        if (endsWith(killName)) ::raise(SIGKILL);  // (tests: killed half-way through the commit)
        const bool injected = endsWith(faultName);
        if (injected || std::rename(it.staging.c_str(), it.target.c_str()) != 0) {
            m_error = "cannot write " + it.path + ": " + (injected ? "injected fault" : std::strerror(errno)) +
                      " (nothing written; the files already replaced were restored)";
            return false;
        }
        if (!existed) created.push_back(it.target);
        return true;
    };
    const Item* manifest = nullptr;
    for (const auto& it : m_items)
        if (!m_manifest.empty() && it.path == m_manifest) manifest = &it;
    bool ok = true;
    if (manifest && ::access(manifest->target.c_str(), F_OK) == 0) {
        ok = setAside(manifest->target) && ::unlink(manifest->target.c_str()) == 0;
        if (!ok) m_error = "cannot replace " + manifest->path + ": " + std::strerror(errno) + " (nothing written)";
    }
    for (size_t i = 0; ok && i < m_items.size(); ++i)
        if (!m_items[i].toStdout && &m_items[i] != manifest) ok = put(m_items[i]);
    if (ok && !m_setFolder.empty() && !m_stalePatterns.empty()) ok = removeStaleOutputs(setAside);
    if (ok && manifest) ok = put(*manifest);
    auto rollBack = [&] {
        for (const std::string& c : created) std::remove(c.c_str());
        // (rename() of a hard link over the same file does nothing: a backup of a file never
        // replaced is simply removed)
        for (auto r = restore.rbegin(); r != restore.rend(); ++r) {
            if (sameFile(r->first, r->second)) std::remove(r->first.c_str());
            else std::rename(r->first.c_str(), r->second.c_str());
        }
        abandon();
    };
    if (!ok) {
        rollBack();
        return false;
    }
    // Standard output once the files are in place, streamed from its completed staging copy,
    // while the files replaced are still kept: a reader that went away (a closed pipe) or a
    // full device rolls the set back (--npt-out was left written beside a failed -o -).
    for (const auto& it : m_items) {
        if (!it.toStdout || !ok) continue;
        std::string why;
        if (!copyToFd(it.staging, standardOutputFd(), &why)) {
            m_error = "cannot write standard output: " + why + " (the files of this run were not written)";
            ok = false;
        }
    }
    if (!ok) {
        rollBack();
        return false;
    }
    for (const auto& r : restore) std::remove(r.first.c_str());
    for (const auto& it : m_items)
        if (it.toStdout) std::remove(it.staging.c_str());
    m_items.clear();
    m_checked = false;
    return ok;
}

void OutputSet::drop(const std::string& output) {
    for (size_t i = 0; i < m_items.size(); ++i)
        if (m_items[i].path == output) {
            if (!m_items[i].staging.empty()) std::remove(m_items[i].staging.c_str());
            m_items.erase(m_items.begin() + static_cast<long>(i));
            return;
        }
}

void OutputSet::abandon() {
    for (const auto& it : m_items)
        if (!it.staging.empty()) std::remove(it.staging.c_str());
    m_items.clear();
    m_checked = false;
}

FolderForOutputs::FolderForOutputs(std::string dir) : m_dir(std::move(dir)) {
    m_created = ::mkdir(m_dir.c_str(), 0755) == 0;
    struct stat st {};
    m_ok = ::stat(m_dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

FolderForOutputs::~FolderForOutputs() {
    if (m_created && !m_keep) ::rmdir(m_dir.c_str());  // only succeeds when empty
}

}  // namespace lwb::core
