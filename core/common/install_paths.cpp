#include "core/common/install_paths.hpp"

#include <unistd.h>

namespace lwb::core {

std::string executableDir() {
    char buf[4096];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
    if (n <= 0) return {};
    const std::string p(buf, static_cast<size_t>(n));
    const size_t slash = p.rfind('/');
    return slash == std::string::npos ? std::string() : p.substr(0, slash);
}

std::vector<std::string> helperCandidates(const std::string& name) {
    const std::string d = executableDir();
    if (d.empty()) return {};
    return {d + "/" + name, d + "/../libexec/laserwb/" + name};
}

std::vector<std::string> installedDataCandidates(const std::string& sub) {
    const std::string d = executableDir();
    if (d.empty()) return {};
    return {d + "/../share/laserwb/" + sub, d + "/../../share/laserwb/" + sub};
}

}  // namespace lwb::core
