#include "core/common/output_set.hpp"

#include <functional>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <map>
#include <unordered_map>
#include <fnmatch.h>
#include <mutex>
#include <set>
#include <signal.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

#include "core/common/atomic_file.hpp"

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


// A commit's journal, one in each folder the commit changes: ".lwb-journal-PID-ID". Each line
// is "old\tBACKUP\tNAME" (NAME is replaced or removed by the commit and kept as BACKUP, a hard
// link beside it) or "new\tNAME" (NAME does not exist before the commit). It is written, whole,
// before the first rename and removed once the last one is done (the commit point). A run killed
// in between leaves it, and the next run that writes into the folder puts every BACKUP back over
// its NAME and removes every new NAME (rollBackJournal): the folder holds the earlier set again,
// never a mix of two runs' files.
std::string journalEscape(const std::string& name) {
    std::string out;
    for (char c : name) {
        if (c == '\\') out += "\\\\";
        else if (c == '\t') out += "\\t";
        else if (c == '\n') out += "\\n";
        else out += c;
    }
    return out;
}

std::string journalUnescape(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '\\' || i + 1 == s.size()) {
            out += s[i];
            continue;
        }
        const char c = s[++i];
        out += c == 't' ? '\t' : c == 'n' ? '\n' : c;
    }
    return out;
}

// Rolls back the commit a dead process left journalled in `folder`; the journal is removed.
// Returns how many files were put back or removed.
int rollBackJournal(const std::string& folder, const std::string& journalName) {
    const std::string path = folder + "/" + journalName;
    std::string text, err;
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return 0;
    char buf[1 << 16];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    int undone = 0;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        start = end + 1;
        const size_t t1 = line.find('\t');
        if (t1 == std::string::npos) continue;
        const std::string kind = line.substr(0, t1);
        if (kind == "old") {
            const size_t t2 = line.find('\t', t1 + 1);
            if (t2 == std::string::npos) continue;
            const std::string backup = folder + "/" + journalUnescape(line.substr(t1 + 1, t2 - t1 - 1));
            const std::string name = folder + "/" + journalUnescape(line.substr(t2 + 1));
            struct stat st {};
            if (::lstat(backup.c_str(), &st) == 0 && std::rename(backup.c_str(), name.c_str()) == 0) ++undone;
        } else if (kind == "new") {
            const std::string name = folder + "/" + journalUnescape(line.substr(t1 + 1));
            if (::unlink(name.c_str()) == 0) ++undone;
        }
    }
    std::remove(path.c_str());
    return undone;
}

std::atomic<long> g_backupCounter{0};

// The plan of a commit, journalled before anything moves (see rollBackJournal): the backup name
// of every target that exists, and in each folder a journal listing its targets. False with
// *error; *journalFiles lists what was written either way.
bool journalCommit(const std::vector<std::string>& targets, std::map<std::string, std::string>* backupOf,
                   std::vector<std::string>* journalFiles, std::string* error) {
    std::map<std::string, std::string> journals;  // folder → journal text
    for (const std::string& target : targets) {
        struct stat st {};
        std::string& j = journals[folderOf(target)];
        if (::lstat(target.c_str(), &st) != 0) {
            j += "new\t" + journalEscape(baseOf(target)) + "\n";
            continue;
        }
        const std::string b = ".lwb-backup-" + std::to_string(::getpid()) + "-" + std::to_string(g_backupCounter++) + "-" +
                              baseOf(target);
        (*backupOf)[target] = folderOf(target) + "/" + b;
        j += "old\t" + journalEscape(b) + "\t" + journalEscape(baseOf(target)) + "\n";
    }
    static std::atomic<long> journalCounter{0};
    const std::string name = ".lwb-journal-" + std::to_string(::getpid()) + "-" + std::to_string(journalCounter++);
    for (const auto& [folder, text] : journals) {
        std::string err;
        journalFiles->push_back(folder + "/" + name);
        if (!writeFileAtomic(journalFiles->back(), text, &err)) {
            *error = "cannot start writing the outputs in " + folder + ": " + err + " (nothing written)";
            return false;
        }
    }
    return true;
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
    auto deadPid = [](const char* digits) {  // the PID a leftover's name starts with, when it no longer runs
        char* end = nullptr;
        const long pid = std::strtol(digits, &end, 10);
        if (pid <= 0 || !end || *end != '-') return false;
        // A process that still runs (or one we may not signal: it exists) keeps its files.
        return !(pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
    };
    // A commit killed half-way: its journal puts the earlier files back first (before the loop
    // below removes the backups that hold them).
    static const std::string kJournal = ".lwb-journal-";
    for (const std::string& name : names)
        if (name.compare(0, kJournal.size(), kJournal) == 0 && deadPid(name.c_str() + kJournal.size()))
            removed += rollBackJournal(folder, name);
    for (const std::string& name : names) {
        for (const char* prefix : {".lwb-stage-", ".lwb-backup-", ".lwb-tmp-", ".lwb-stdout-"}) {
            const size_t n = std::strlen(prefix);
            if (name.compare(0, n, prefix) != 0) continue;
            if (!deadPid(name.c_str() + n)) break;
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

// Two runs writing a set into one folder at once would mix their files (two simulations, two
// days' --all-passes into one out-dir): the second is refused while the first holds the lock.
bool OutputSet::lockFolder() {
    if (m_setFolder.empty() || m_lockFd >= 0) return true;
    m_lockFd = ::open(m_setFolder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (m_lockFd < 0) return true;  // (a missing folder is said by the outputs' own checks)
    if (::flock(m_lockFd, LOCK_EX | LOCK_NB) == 0) {
        removeLeftovers(m_setFolder);  // (every time: a run killed since this process last looked)
        return true;
    }
    const int e = errno;
    ::close(m_lockFd);
    m_lockFd = -1;
    if (e != EWOULDBLOCK) return true;  // a file system without locks: nothing to hold
    m_error = m_setFolder + ": another run is writing its files into this folder now; wait for it to end or choose "
                            "another folder (nothing written)";
    return false;
}

void OutputSet::unlockFolder() {
    if (m_lockFd < 0) return;
    ::close(m_lockFd);  // (releases the flock)
    m_lockFd = -1;
}

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
    m_items.push_back({path == "-", path, {}, {}, false});
    m_checked = false;
}

void OutputSet::addUpdate(const std::string& path) {
    m_items.push_back({false, path, {}, {}, true});
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
    if (!lockFolder()) return false;
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
    std::unordered_map<std::string, size_t> outputs;  // an output's identity → its item
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
        {
            static std::mutex cleanedMutex;  // (sets are checked on several threads in the workbench)
            static std::set<std::string> cleaned;  // each folder once per process
            std::lock_guard<std::mutex> lock(cleanedMutex);
            if (cleaned.insert(targetDir).second) removeLeftovers(targetDir);
        }
        for (const auto& in : inputs)
            if (id.same(in)) {
                m_error = p + ": an output would overwrite the input (the same file); nothing written";
                m_naming = true;
                return false;
            }
        if (id.exists && !it.update) {
            const std::string as = noted(st);
            if (!as.empty()) {
                m_error = p + ": an output would overwrite an input of this run (the same file as " + as + "); nothing written";
                m_naming = true;
                return false;
            }
        }
        // (hashed: a simulation of 10^6 shots is 10^6 outputs, not 10^12 comparisons)
        const std::string key = id.exists ? std::to_string(id.dev) + ":" + std::to_string(id.ino) : "/" + id.canonical;
        const auto seen = outputs.emplace(key, static_cast<size_t>(&it - m_items.data()));
        if (!seen.second) {
            m_error = "two outputs name the same file: " + m_items[seen.first->second].path + " and " + p + " (nothing written)";
            m_naming = true;
            return false;
        }
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
        if (it.toStdout || it.update) continue;
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

// Earlier outputs of the same kind in the set's folder that this run does not write again
// (removed by the commit).
std::vector<std::string> OutputSet::staleOutputs() const {
    std::vector<std::string> names, stale;
    if (m_setFolder.empty() || m_stalePatterns.empty()) return stale;
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
        stale.push_back(path);
    }
    return stale;
}

bool OutputSet::commit() {
    if (!readyToCommit()) return false;
    // The plan, journalled before anything moves (see rollBackJournal): every file replaced or
    // removed keeps a hard link (a backup) until the end, so that a failure half-way through, or
    // the next run after a kill, can put it back; a new file is removed again. Order: the
    // manifest's old file first, the new files, the stale files of the set, the manifest last.
    const std::string faultName = faultInjectedName("rename"), killName = faultInjectedName("kill");
    const Item* manifest = nullptr;
    for (const auto& it : m_items)
        if (!m_manifest.empty() && it.path == m_manifest) manifest = &it;
    const std::vector<std::string> stale = staleOutputs();
    std::vector<std::string> targets = stale;
    for (const auto& it : m_items)
        if (!it.toStdout) targets.push_back(it.target);
    std::map<std::string, std::string> backupOf;  // target → its backup
    std::vector<std::string> journalFiles;
    auto removeJournals = [&] {
        for (const std::string& j : journalFiles) std::remove(j.c_str());
    };
    if (!journalCommit(targets, &backupOf, &journalFiles, &m_error)) {
        removeJournals();
        abandon();
        return false;
    }
    std::vector<std::pair<std::string, std::string>> restore;  // (backup, original)
    std::vector<std::string> created;
    auto setAside = [&](const std::string& target) {  // false when it cannot be kept
        const auto b = backupOf.find(target);
        if (b == backupOf.end()) return true;  // nothing there
        if (::link(target.c_str(), b->second.c_str()) != 0) return false;
        restore.emplace_back(b->second, target);
        return true;
    };
    auto put = [&](const Item& it) {
        // (the manifest's old file was set aside and removed first: nothing to keep then)
        const bool existed = backupOf.count(it.target) > 0, present = existed && ::access(it.target.c_str(), F_OK) == 0;
        if (present && !setAside(it.target)) {
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
    bool ok = true;
    if (manifest && backupOf.count(manifest->target)) {
        ok = setAside(manifest->target) && ::unlink(manifest->target.c_str()) == 0;
        if (!ok) m_error = "cannot replace " + manifest->path + ": " + std::strerror(errno) + " (nothing written)";
    }
    for (size_t i = 0; ok && i < m_items.size(); ++i)
        if (!m_items[i].toStdout && &m_items[i] != manifest) ok = put(m_items[i]);
    for (size_t i = 0; ok && i < stale.size(); ++i)
        if (!setAside(stale[i]) || ::unlink(stale[i].c_str()) != 0) {
            m_error = "cannot remove the earlier output " + stale[i] + ": " + std::strerror(errno) + " (nothing written)";
            ok = false;
        }
    if (ok && manifest) ok = put(*manifest);
    auto rollBack = [&] {
        for (const std::string& c : created) std::remove(c.c_str());
        // (rename() of a hard link over the same file does nothing: a backup of a file never
        // replaced is simply removed)
        for (auto r = restore.rbegin(); r != restore.rend(); ++r) {
            if (sameFile(r->first, r->second)) std::remove(r->first.c_str());
            else std::rename(r->first.c_str(), r->second.c_str());
        }
        removeJournals();
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
    removeJournals();  // the commit point: from here on the new set stands
    for (const auto& r : restore) std::remove(r.first.c_str());
    for (const auto& it : m_items)
        if (it.toStdout) std::remove(it.staging.c_str());
    m_items.clear();
    m_checked = false;
    unlockFolder();
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
    unlockFolder();
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
