#pragma once
// One output discipline for every command and export: every output is checked before any work
// is done (a regular file or a new name, in a writable folder, not a folder, device, FIFO or
// socket, not the same file as an input or as another output — compared by device and inode,
// or by canonical folder + name for files that do not exist yet), written under a staging name
// beside its target, and renamed into place only when every output of the run is complete.
// A failure at any point leaves every target as it was.
#include <functional>
#include <string>
#include <vector>

namespace lwb::core {

class OutputSet {
public:
    OutputSet() = default;
    ~OutputSet();  ///< removes staged files that were not committed
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    /// A file the run reads: no output may replace it. Paths that do not exist are ignored.
    void addInput(const std::string& path);
    /// A file the run writes. Checked by check(). "-" is standard output: written to a staging
    /// file in the temporary folder like any output, and copied to standardOutputFd() at commit,
    /// after every file of the run is in place. At most one output may be "-".
    void addOutput(const std::string& path);
    /// A file the run reads and then replaces on purpose (an existing presets file that gets a
    /// satellite's entry): an output like addOutput's, which check() and commit() do not refuse
    /// for having been read. It must not be one of addInput's.
    void addUpdate(const std::string& path);
    /// True when an output is standard output ("-").
    bool writesStandardOutput() const;
    /// The inputs as added, and the outputs written to files (not "-"), as given.
    const std::vector<std::string>& inputs() const { return m_inputs; }
    std::vector<std::string> fileOutputs() const;
    /// A run that writes a set of files into one folder (simulate footprint, slr --all-passes):
    /// `manifest` (one of the outputs, e.g. truth.csv or summary.csv, that lists the set) is
    /// removed first and renamed into place last, so a run killed half-way leaves no manifest
    /// beside a mix of old and new files; files of `folder` whose names match one of
    /// `stalePatterns` (fnmatch, e.g. "pass[0-9]*.csv"), are not outputs of this run and are not
    /// inputs of it are earlier outputs of the same kind: removed before the manifest is renamed.
    /// A failure restores every file replaced or removed; a run killed during its commit leaves
    /// a journal from which the next run writing into the folder restores the earlier set.
    /// check() locks the folder (flock) until the set is committed or abandoned: a second run
    /// writing a set into it meanwhile is refused.
    void setManifest(const std::string& manifest, const std::string& folder, std::vector<std::string> stalePatterns);
    /// Checks every output (see the file comment). Call before any computation. False with error().
    bool check();
    const std::string& error() const { return m_error; }
    /// True when check() or commit() failed because outputs name an input or each other (a usage error),
    /// false for a file-system problem (missing folder, read-only file, device...).
    bool namingProblem() const { return m_naming; }
    /// `message` with every staging path replaced by the output it stands for.
    std::string unstaged(std::string message) const;

    /// Where to write `output` (a staging file in the target's folder, with the target's
    /// extension, so that writers choosing a format by extension still work). check() first.
    std::string stagingPath(const std::string& output) const;
    /// Forgets an output the run turned out not to produce (its staging file, if any, removed).
    void drop(const std::string& output);
    /// Renames every staged output into place. On failure the targets already replaced are
    /// restored, every staged file is removed, and error() says what failed.
    bool commit();
    /// Removes every staged file; the targets are left as they were.
    void abandon();

private:
    bool readyToCommit();
    std::vector<std::string> staleOutputs() const;
    bool lockFolder();
    void unlockFolder();
    struct Item {
        bool toStdout = false;  ///< "-"
        std::string path;     ///< as given
        std::string target;   ///< symbolic links resolved: the file that is replaced
        std::string staging;  ///< written by the run
        bool update = false;  ///< addUpdate: read by the run, replaced on purpose
    };
    std::vector<std::string> m_inputs;
    std::vector<Item> m_items;
    std::string m_manifest, m_setFolder;
    std::vector<std::string> m_stalePatterns;
    std::string m_error;
    bool m_checked = false, m_naming = false;
    int m_lockFd = -1;  ///< the set's folder, locked (flock) from check() to the end of commit()
};

/// Every file this process reads as an input is noted here (readFileText, readFileHead, image
/// and GeoTIFF reads do it): its device and inode, and the name it was read under. No OutputSet
/// replaces such a file: check() refuses an output that is one, and commit() checks again for the
/// inputs read since (a --config read before the outputs were checked, a CPF picked from a
/// folder during the run). Thread-safe. "-" and paths that are not regular files are ignored.
void noteInputRead(const std::string& path);
/// The name an input was read under when `path` is the same file as one (else "").
std::string inputReadAs(const std::string& path);

/// Where an output "-" goes: file descriptor 1 unless a program moved its own messages off
/// standard output (laserwb-cli does: its summary goes to standard error then) and says where
/// the data must go instead.
void setStandardOutputFd(int fd);
int standardOutputFd();

/// Removes what killed runs left in `folder`: staging, backup and temporary files of this
/// program (".lwb-stage-PID-…", ".lwb-backup-PID-…", ".lwb-tmp-PID-…") whose process PID no longer
/// runs. OutputSet::check() does it for every folder it writes in. Returns how many were removed.
int removeLeftovers(const std::string& folder);

/// True when both paths exist and name the same file (same device and inode: "./x", "x", a
/// symbolic or hard link).
bool sameFile(const std::string& a, const std::string& b);

/// Fault injection for tests: when the environment variable LWB_FAULT_OUTPUT is
/// "write:NAME" or "rename:NAME", writing (AtomicFile) or renaming (OutputSet::commit) a file
/// whose name ends with NAME fails as a full disk would; "kill:NAME": the process kills itself
/// (SIGKILL) just before renaming that file. Returns the phase's NAME or "".
std::string faultInjectedName(const char* phase);

/// An output folder for a run that writes several files into it: created when missing, and
/// removed again (when still empty) unless keep() is called, so a failed run leaves nothing.
class FolderForOutputs {
public:
    explicit FolderForOutputs(std::string dir);
    ~FolderForOutputs();
    FolderForOutputs(const FolderForOutputs&) = delete;
    FolderForOutputs& operator=(const FolderForOutputs&) = delete;
    bool ok() const { return m_ok; }
    void keep() const { m_keep = true; }

private:
    std::string m_dir;
    bool m_ok = false, m_created = false;
    mutable bool m_keep = false;
};

}  // namespace lwb::core
