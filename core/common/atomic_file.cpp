#include "core/common/atomic_file.hpp"

#include <cerrno>
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
    if (::stat(m_path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
        m_error = m_path + ": is a folder, not a file";
        m_done = true;
        return;
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
    const bool good = m_out.good();
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

bool readFileText(const std::string& path, std::string* content, std::string* error) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (error) *error = path + ": " + std::strerror(errno);
        return false;
    }
    if (S_ISDIR(st.st_mode)) {
        if (error) *error = path + ": is a folder, not a file";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (error) *error = path + ": cannot open: " + std::strerror(errno);
        return false;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    *content = ss.str();
    return true;
}

}  // namespace lwb::core
