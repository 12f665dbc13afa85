#include "core/common/atomic_file.hpp"

#include "core/common/output_set.hpp"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace lwb::core {

namespace {
std::string tempNameFor(const std::string& path) {
    std::random_device rd;
    std::ostringstream s;
    s << path << ".tmp-" << ::getpid() << '-' << std::hex << rd();
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

bool readFileText(const std::string& path, std::string* content, std::string* error, long long maxBytes) {
    long long size = 0;
    if (regularFileProblem(path, error, &size)) return false;
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
        content->resize(static_cast<size_t>(size));
        in.read(content->data(), size);
        if (in.gcount() != size) {
            if (error) *error = path + ": read " + std::to_string(in.gcount()) + " of " + std::to_string(size) +
                                " bytes (the file changed while it was read?)";
            return false;
        }
    } catch (const std::bad_alloc&) {
        if (error) *error = path + ": out of memory reading " + std::to_string(size) + " bytes";
        return false;
    }
    return true;
}

}  // namespace lwb::core
