#pragma once
// One output discipline for every command and export: every output is checked before any work
// is done (a regular file or a new name, in a writable folder, not a folder, device, FIFO or
// socket, not the same file as an input or as another output — compared by device and inode,
// or by canonical folder + name for files that do not exist yet), written under a staging name
// beside its target, and renamed into place only when every output of the run is complete.
// A failure at any point leaves every target as it was.
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
    /// True when an output is standard output ("-").
    bool writesStandardOutput() const;
    /// Checks every output (see the file comment). Call before any computation. False with error().
    bool check();
    const std::string& error() const { return m_error; }
    /// True when check() failed because outputs name an input or each other (a usage error),
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
    struct Item {
        bool toStdout = false;  ///< "-"
        std::string path;     ///< as given
        std::string target;   ///< symbolic links resolved: the file that is replaced
        std::string staging;  ///< written by the run
    };
    std::vector<std::string> m_inputs;
    std::vector<Item> m_items;
    std::string m_error;
    bool m_checked = false, m_naming = false;
};

/// Where an output "-" goes: file descriptor 1 unless a program moved its own messages off
/// standard output (laserwb-cli does: its summary goes to standard error then) and says where
/// the data must go instead.
void setStandardOutputFd(int fd);
int standardOutputFd();

/// True when both paths exist and name the same file (same device and inode: "./x", "x", a
/// symbolic or hard link).
bool sameFile(const std::string& a, const std::string& b);

/// Fault injection for tests: when the environment variable LWB_FAULT_OUTPUT is
/// "write:NAME" or "rename:NAME", writing (AtomicFile) or renaming (OutputSet::commit) a file
/// whose name ends with NAME fails as a full disk would. Returns the phase's NAME or "".
std::string faultInjectedName(const char* phase);

}  // namespace lwb::core
