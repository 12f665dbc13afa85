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
///  - "-" is standard input, read once and kept, so that a reader that looks at the start of an
///    input first (isCrdFile) and then reads it whole sees the same bytes; a terminal on standard
///    input is refused (it would wait for typing).
///  - A gzip-compressed input (by its magic bytes 1f 8b, whatever its name; several members are
///    read one after the other) is decompressed, and maxBytes applies to what it decompresses to.
///  - A NUL byte (after decompression) is refused where it comes, with its line: no text
///    input holds one, and a file of zeros is not read on (sparse files, /dev/zero piped in).
///  - Memory: the file's size once (reserved, filled in blocks); standard input is kept, so
///    "-" holds it twice.
bool readFileText(const std::string& path, std::string* content, std::string* error,
                  long long maxBytes = kMaxTextInputBytes);
/// "FILE:LINE: binary data (NUL byte): not a text file (not read further)": the one message of
/// readFileText and LineReader for a NUL byte in a text input.
std::string nulByteMessage(const std::string& path, long line);
/// readFileText for binary inputs (raw and PGM frames, images read whole): NUL bytes are data.
bool readFileBytes(const std::string& path, std::string* content, std::string* error,
                   long long maxBytes = kMaxTextInputBytes);

/// "-": standard input (or output, for an output).
inline bool isStandardStream(const std::string& path) { return path == "-"; }

/// The first bytes (up to `n`) of a text input as readFileText would give them: decompressed
/// when gzip, from the kept standard input for "-". False with *error when it cannot be read.
bool readFileHead(const std::string& path, size_t n, std::string* head, std::string* error);

/// The lower-case extension of an input's name without a trailing ".gz" ("pass.frd.gz" → "frd").
std::string inputExtension(const std::string& path);

/// Decompresses a gzip (or zlib) stream of `size` bytes into *out, at most maxBytes (0 = no
/// limit) of it; stops early once `stopAfter` bytes are out (0 = never). False with *error ("why").
bool gunzip(const char* data, size_t size, std::string* out, std::string* error, long long maxBytes,
            size_t stopAfter = 0);

}  // namespace lwb::core
