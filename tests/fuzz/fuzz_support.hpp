#pragma once
// Shared by the libFuzzer targets in tests/fuzz: a trap when an invariant breaks, and the input
// handed to readers that take only a path, through one file per process and file ending in
// /dev/shm (memory; $TMPDIR or /tmp when /dev/shm is missing). The file is rewritten for every
// input and removed when the process exits. Readers keep their signatures: nothing here knows
// how they read.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <map>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>

namespace lwb::fuzz {

/// Stops the fuzzer with a crash report (and the input saved) when `condition` is false.
inline void check(bool condition) {
    if (!condition) __builtin_trap();
}

/// A reader that fails must say why: `ok` or a non-empty message.
inline void checkReported(bool ok, const std::string& error) { check(ok || !error.empty()); }

inline std::string_view asText(const uint8_t* data, size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

namespace detail {
inline std::map<std::string, std::string>& files() {
    static std::map<std::string, std::string> paths;  // ending -> path
    return paths;
}
inline void removeFiles() {
    for (const auto& [ext, path] : files()) ::unlink(path.c_str());
}
inline std::string scratchFolder() {
    struct stat st {};
    if (::stat("/dev/shm", &st) == 0 && S_ISDIR(st.st_mode) && ::access("/dev/shm", W_OK) == 0) return "/dev/shm";
    const char* tmp = std::getenv("TMPDIR");
    return tmp && *tmp ? tmp : "/tmp";
}
}  // namespace detail

/// Writes the bytes to this process's scratch file ending in `.ext` and returns its path.
inline const std::string& inputFile(std::string_view bytes, const std::string& ext) {
    auto& paths = detail::files();
    auto it = paths.find(ext);
    if (it == paths.end()) {
        if (paths.empty()) std::atexit(detail::removeFiles);
        const std::string path = detail::scratchFolder() + "/laserwb-fuzz-" + std::to_string(::getpid()) + "." + ext;
        it = paths.emplace(ext, path).first;
    }
    const int fd = ::open(it->second.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    check(fd >= 0);
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        check(n > 0);
        done += size_t(n);
    }
    ::close(fd);
    return it->second;
}

}  // namespace lwb::fuzz

namespace lwb::fuzz {

/// Calls a path reader of the form `bool read(path, T* out, std::string* error)` on the bytes
/// (through inputFile with ending `ext`); checks that a failure says why. True when it read.
template <class T, class Reader>
bool readThroughFile(std::string_view bytes, const std::string& ext, Reader read, T* out) {
    std::string error;
    const bool ok = read(inputFile(bytes, ext), out, &error);
    checkReported(ok, error);
    return ok;
}

/// Records read from a file carry their source line: after the header (line >= 2) and in file
/// order (strictly increasing), so that messages point at the right line.
template <class Records>
void checkLines(const Records& records) {
    long previous = 1;
    for (const auto& r : records) {
        check(r.line > previous);
        previous = r.line;
    }
}

}  // namespace lwb::fuzz
