#include "core/common/atomic_file.hpp"

#include <functional>

#include "core/common/output_set.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>
#include <fstream>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>
#include <zlib.h>

#include "core/common/text.hpp"

namespace lwb::core {

namespace {
// A hidden name beside the target: ".lwb-tmp-PID-HEX-NAME" (removeLeftovers() removes those of
// killed runs).
std::string tempNameFor(const std::string& path) {
    std::random_device rd;
    const size_t slash = path.find_last_of('/');
    std::ostringstream s;
    s << (slash == std::string::npos ? std::string() : path.substr(0, slash + 1)) << ".lwb-tmp-" << ::getpid() << '-'
      << std::hex << rd() << '-' << (slash == std::string::npos ? path : path.substr(slash + 1));
    return s.str();
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)), m_tmp(tempNameFor(m_path)) {
    if (m_path.empty()) {
        m_error = "no output file name given";
        m_done = true;
        return;
    }
    struct stat st {};
    if (::stat(m_path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            m_error = m_path + ": is a folder, not a file";
            m_done = true;
            return;
        }
        if (!S_ISREG(st.st_mode)) {
            m_error = m_path + ": is not a regular file (a device, FIFO or socket); refusing to replace it";
            m_done = true;
            return;
        }
        // A symbolic link: replace the file it names, not the link.
        char buf[PATH_MAX];
        if (::realpath(m_path.c_str(), buf)) {
            m_path = buf;
            m_tmp = tempNameFor(m_path);
        }
    }
    m_out.open(m_tmp, std::ios::binary | std::ios::trunc);
    if (!m_out) {
        m_error = "cannot write " + m_path + ": " + std::strerror(errno);
        m_done = true;
    }
}

AtomicFile::~AtomicFile() { abandon(); }

void AtomicFile::abandon() {
    if (m_done) return;
    m_out.close();
    std::remove(m_tmp.c_str());
    m_done = true;
}

bool AtomicFile::commit() {
    if (m_done) return false;  // already committed, abandoned or failed to open
    m_out.flush();
    const std::string fault = faultInjectedName("write");
    const bool injected = !fault.empty() && m_path.size() >= fault.size() &&
                          m_path.compare(m_path.size() - fault.size(), fault.size(), fault) == 0;
    const bool good = m_out.good() && !injected;
    m_out.close();
    if (!good) {
        m_error = "write to " + m_path + " failed (disk full?)";
        std::remove(m_tmp.c_str());
        m_done = true;
        return false;
    }
    if (std::rename(m_tmp.c_str(), m_path.c_str()) != 0) {
        m_error = "cannot replace " + m_path + ": " + std::strerror(errno);
        std::remove(m_tmp.c_str());
        m_done = true;
        return false;
    }
    m_done = true;
    return true;
}

bool writeFileAtomic(const std::string& path, const std::string& content, std::string* error) {
    AtomicFile f(path);
    if (!f.ok()) {
        if (error) *error = f.error();
        return false;
    }
    f.stream() << content;
    if (!f.commit()) {
        if (error) *error = f.error();
        return false;
    }
    return true;
}

bool regularFileProblem(const std::string& path, std::string* error, long long* size) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (error) *error = path + ": " + std::strerror(errno);
        return true;
    }
    if (S_ISDIR(st.st_mode)) {
        if (error) *error = path + ": is a folder, not a file";
        return true;
    }
    if (!S_ISREG(st.st_mode)) {
        if (error)
            *error = path + ": is not a regular file (" +
                     (S_ISFIFO(st.st_mode) ? "a FIFO"
                      : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                      : S_ISSOCK(st.st_mode) ? "a socket" : "a special file") +
                     "); only regular files are read";
        return true;
    }
    if (size) *size = static_cast<long long>(st.st_size);
    return false;
}

namespace {
bool isGzip(const std::string& s) {
    return s.size() >= 2 && static_cast<unsigned char>(s[0]) == 0x1f && static_cast<unsigned char>(s[1]) == 0x8b;
}

// Standard input, read once for the whole process (see readFileText).
struct StandardInput {
    std::once_flag once;
    bool ok = false;
    std::string data, error;
};
StandardInput& standardInput() {
    static StandardInput s;
    return s;
}

// Appends n bytes to `data` growing it at most to cap bytes (a string doubling past 2 GiB
// reserved 4 GiB for a stream refused at 2 GiB: `slr - < /dev/zero` peaked at 4.3 GB).
void appendCapped(std::string* data, const char* bytes, size_t n, size_t cap) {
    if (data->size() + n > data->capacity()) data->reserve(std::min(std::max(data->capacity() * 2, data->size() + n), cap));
    data->append(bytes, n);
}

const StandardInput& readStandardInput(long long maxBytes) {
    StandardInput& s = standardInput();
    std::call_once(s.once, [&] {
        if (::isatty(0)) {
            s.error = "-: standard input is a terminal; pipe a file into it (cat FILE | ...) or name the file";
            return;
        }
        const size_t cap = maxBytes > 0 ? static_cast<size_t>(maxBytes) + (1 << 16) : SIZE_MAX;
        try {
            char buf[1 << 16];
            for (;;) {
                const ssize_t n = ::read(0, buf, sizeof buf);
                if (n < 0 && errno == EINTR) continue;
                if (n < 0) {
                    s.error = std::string("-: cannot read standard input: ") + std::strerror(errno);
                    return;
                }
                if (n == 0) break;
                const size_t before = s.data.size();
                appendCapped(&s.data, buf, static_cast<size_t>(n), cap);
                // No input, text or image, starts with 64 KiB of NUL bytes (/dev/zero, a sparse
                // file piped in): refused there rather than read to the limit.
                constexpr size_t kLead = 1 << 16;
                if (before < kLead && s.data.size() >= kLead &&
                    std::all_of(s.data.begin(), s.data.begin() + kLead, [](char c) { return c == 0; })) {
                    s.error = "-: standard input starts with " + std::to_string(kLead) +
                              " NUL bytes (/dev/zero, or a file of zeros): not an input (not read further)";
                    std::string().swap(s.data);
                    return;
                }
                if (maxBytes > 0 && static_cast<long long>(s.data.size()) > maxBytes) {
                    s.error = "-: standard input is larger than the limit of " + std::to_string(maxBytes) +
                              " bytes for a text input";
                    std::string().swap(s.data);
                    return;
                }
            }
        } catch (const std::bad_alloc&) {
            std::string().swap(s.data);
            s.error = "-: out of memory reading standard input";
            return;
        }
        s.ok = true;
    });
    return s;
}

// A text input's first NUL byte: no CRD, CPF, SINEX, CSV, JSON or session file holds one, so a
// file of zeros (sparse, or extended after a crash) or binary data is refused where it starts,
// before a reader holds it whole (2 GiB sparse inputs peaked at 4-6 GB in the readers).
// `text` is what was read so far, `from` where the new bytes begin. False with *error.
bool noNulByte(const std::string& path, const std::string& text, size_t from, std::string* error) {
    const void* z = std::memchr(text.data() + from, 0, text.size() - from);
    if (!z) return true;
    const size_t at = static_cast<size_t>(static_cast<const char*>(z) - text.data());
    const long line = 1 + static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    if (error) *error = nulByteMessage(path, line);
    return false;
}
}  // namespace

namespace {
// Inflates data (gzip or zlib, members one after another) through `take`, which gets each
// block out and the total so far; stops at stopAfter bytes (0: the whole stream) or when the
// total passes maxBytes (0: no limit: an error). False with *error.
bool inflateStream(const char* data, size_t size, long long maxBytes, size_t stopAfter,
                   const std::function<void(const char*, size_t)>& take, std::string* error) {
    z_stream zs{};
    if (inflateInit2(&zs, 15 + 32) != Z_OK) {  // 15 + 32: a gzip or a zlib header, told apart by zlib
        *error = "cannot start the gzip decoder";
        return false;
    }
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
    zs.avail_in = static_cast<uInt>(size);
    char buf[1 << 16];
    bool ok = true;
    long long total = 0;
    for (;;) {
        zs.next_out = reinterpret_cast<Bytef*>(buf);
        zs.avail_out = sizeof buf;
        const int rc = inflate(&zs, Z_NO_FLUSH);
        const size_t n = sizeof buf - zs.avail_out;
        total += static_cast<long long>(n);
        if (maxBytes > 0 && total > maxBytes) {
            *error = "decompresses to more than the limit of " + std::to_string(maxBytes) + " bytes for a text input";
            ok = false;
            break;
        }
        take(buf, n);
        if (stopAfter > 0 && static_cast<size_t>(total) >= stopAfter) break;
        if (rc == Z_STREAM_END) {
            if (zs.avail_in == 0) break;
            // Another gzip member may follow (cat a.gz b.gz > c.gz); anything else is an error.
            if (zs.avail_in >= 2 && zs.next_in[0] == 0x1f && zs.next_in[1] == 0x8b) {
                inflateReset(&zs);
                continue;
            }
            *error = "data after the end of the gzip stream";
            ok = false;
            break;
        }
        if (rc == Z_BUF_ERROR && zs.avail_in == 0) {
            // A head (stopAfter) may be cut out of a longer stream: what came out is enough.
            if (stopAfter > 0) break;
            *error = "the gzip stream is truncated (it ends before its end marker)";
            ok = false;
            break;
        }
        if (rc != Z_OK && rc != Z_BUF_ERROR) {
            *error = std::string("not a valid gzip stream: ") + (zs.msg ? zs.msg : "data error");
            ok = false;
            break;
        }
    }
    inflateEnd(&zs);
    return ok;
}
}  // namespace

bool gunzip(const char* data, size_t size, std::string* out, std::string* error, long long maxBytes, size_t stopAfter) {
    out->clear();
    if (size > UINT_MAX) {
        *error = "a compressed input of more than 4 GiB is not read";
        return false;
    }
    bool ok = true;
    try {
        // Memory bounded by construction: when the input could inflate past the limit (deflate
        // reaches about 1032:1; 2048 leaves room for any other stream), its size is counted
        // first without holding it, so a bomb is
        // refused at the limit with nothing but its compressed bytes in memory (a 4 GiB stream of
        // zeros took 4.2 GB before), and the text is then inflated into one allocation.
        if (maxBytes > 0 && stopAfter == 0 && static_cast<double>(size) * 2048 > static_cast<double>(maxBytes)) {
            size_t count = 0;
            if (!inflateStream(data, size, maxBytes, 0, [&](const char*, size_t n) { count += n; }, error)) return false;
            out->reserve(count);
        }
        ok = inflateStream(data, size, maxBytes, stopAfter, [&](const char* b, size_t n) { out->append(b, n); }, error);
    } catch (const std::bad_alloc&) {
        *error = "out of memory decompressing";
        ok = false;
    }
    if (!ok) out->clear();
    return ok;
}

namespace {
// readFileText (text: a NUL byte refused) and readFileBytes.
bool readInput(const std::string& path, std::string* content, std::string* error, long long maxBytes, bool text) {
    std::string raw;
    if (isStandardStream(path)) {
        const StandardInput& in = readStandardInput(maxBytes);
        if (!in.ok) {
            if (error) *error = in.error;
            return false;
        }
        if (!isGzip(in.data)) {
            if (text && !noNulByte(path, in.data, 0, error)) return false;
            *content = in.data;
            return true;
        }
        std::string why;
        if (!gunzip(in.data.data(), in.data.size(), content, &why, maxBytes)) {
            if (error) *error = path + ": " + why;
            return false;
        }
        return !text || noNulByte(path, *content, 0, error);
    }
    long long size = 0;
    if (regularFileProblem(path, error, &size)) return false;
    noteInputRead(path);  // (no output of this run may replace it)
    if (maxBytes > 0 && size > maxBytes) {
        if (error)
            *error = path + ": " + std::to_string(size) + " bytes is larger than the limit of " + std::to_string(maxBytes) +
                     " bytes for a text input";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (error) *error = path + ": cannot open: " + std::strerror(errno);
        return false;
    }
    try {
        // In blocks, into one allocation that is not touched ahead of the data (a sparse file is
        // refused at its first zeros, with only what came before them in memory).
        content->clear();
        content->reserve(static_cast<size_t>(size));
        std::vector<char> block(std::min<size_t>(static_cast<size_t>(size), 4u << 20) + 1);
        while (static_cast<long long>(content->size()) < size) {
            in.read(block.data(), static_cast<std::streamsize>(std::min<long long>(size - static_cast<long long>(content->size()),
                                                                                  static_cast<long long>(block.size()))));
            const size_t got = static_cast<size_t>(in.gcount());
            if (got == 0) break;
            const size_t from = content->size();
            content->append(block.data(), got);
            if (text && !isGzip(*content) && !noNulByte(path, *content, from, error)) {
                std::string().swap(*content);
                return false;
            }
        }
        if (static_cast<long long>(content->size()) != size) {
            if (error) *error = path + ": read " + std::to_string(content->size()) + " of " + std::to_string(size) +
                                " bytes (the file changed while it was read?)";
            return false;
        }
    } catch (const std::bad_alloc&) {
        if (error) *error = path + ": out of memory reading " + std::to_string(size) + " bytes";
        return false;
    }
    if (!isGzip(*content)) return true;
    raw.swap(*content);
    std::string why;
    if (!gunzip(raw.data(), raw.size(), content, &why, maxBytes)) {
        if (error) *error = path + ": " + why;
        return false;
    }
    std::string().swap(raw);
    if (text && !noNulByte(path, *content, 0, error)) {
        std::string().swap(*content);
        return false;
    }
    return true;
}
}  // namespace

std::string nulByteMessage(const std::string& path, long line) {
    return whereInFile(path, line) + "binary data (NUL byte): not a text file (not read further)";
}

bool readFileText(const std::string& path, std::string* content, std::string* error, long long maxBytes) {
    return readInput(path, content, error, maxBytes, true);
}

bool readFileBytes(const std::string& path, std::string* content, std::string* error, long long maxBytes) {
    return readInput(path, content, error, maxBytes, false);
}

bool readFileHead(const std::string& path, size_t n, std::string* head, std::string* error) {
    std::string raw;
    if (isStandardStream(path)) {
        const StandardInput& in = readStandardInput(kMaxTextInputBytes);
        if (!in.ok) {
            if (error) *error = in.error;
            return false;
        }
        raw = in.data.substr(0, std::max<size_t>(n, 1 << 16));
    } else {
        if (regularFileProblem(path, error)) return false;
        noteInputRead(path);
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            if (error) *error = path + ": cannot open: " + std::strerror(errno);
            return false;
        }
        raw.resize(std::max<size_t>(n, 1 << 16));
        in.read(raw.data(), static_cast<std::streamsize>(raw.size()));
        raw.resize(static_cast<size_t>(in.gcount()));
    }
    if (isGzip(raw)) {
        std::string why;
        if (!gunzip(raw.data(), raw.size(), head, &why, 0, n)) {
            if (error) *error = path + ": " + why;
            return false;
        }
    } else {
        *head = std::move(raw);
    }
    if (head->size() > n) head->resize(n);
    return true;
}

std::string inputExtension(const std::string& path) {
    std::string name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
    std::string low = toLower(name);
    if (low.size() > 3 && low.compare(low.size() - 3, 3, ".gz") == 0) low.resize(low.size() - 3);
    const size_t dot = low.find_last_of('.');
    return dot == std::string::npos ? std::string() : low.substr(dot + 1);
}

}  // namespace lwb::core
