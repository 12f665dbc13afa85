#pragma once
// Writes that never leave a half file: content goes to a temporary file in the same
// folder, is flushed, and is renamed over the target only when complete.
#include <fstream>
#include <string>

namespace lwb::core {

class AtomicFile {
public:
    /// Opens a temporary beside `path`. Check ok() / error() before writing.
    explicit AtomicFile(std::string path);
    ~AtomicFile();  ///< removes the temporary unless commit() succeeded
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    bool ok() const { return m_error.empty(); }
    const std::string& error() const { return m_error; }
    std::ostream& stream() { return m_out; }

    /// Flushes, closes and renames the temporary over the target. False (with error()) on failure.
    bool commit();
    /// Drops the temporary; the target is left as it was.
    void abandon();

private:
    std::string m_path, m_tmp, m_error;
    std::ofstream m_out;
    bool m_done = false;
};

/// Whole-content convenience: true on success, else false and *error set.
bool writeFileAtomic(const std::string& path, const std::string& content, std::string* error);

/// Largest text input read by default (bytes): the biggest real inputs (a day of kHz CRD) are a
/// few hundred MB; anything larger is refused with its size rather than exhausting memory.
constexpr long long kMaxTextInputBytes = 2LL << 30;

/// True (with *error "FILE: why") when `path` is not an existing regular file: missing, a
/// folder, a device, FIFO or socket (reading those can block or never end). *size on success.
bool regularFileProblem(const std::string& path, std::string* error, long long* size = nullptr);

/// Reads a whole regular file of at most maxBytes (0 = no limit); false and *error
/// ("FILE: reason") on failure, including out of memory.
bool readFileText(const std::string& path, std::string* content, std::string* error,
                  long long maxBytes = kMaxTextInputBytes);

}  // namespace lwb::core
