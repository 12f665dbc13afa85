#include "core/common/memory.hpp"

#include <sys/resource.h>

#include <fstream>
#include <sstream>

#include "core/common/text.hpp"

namespace lwb::core {
namespace {

// A "Name:   N kB" line of a /proc file, in bytes; 0 when absent.
uint64_t procKb(const char* file, const std::string& name) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line))
        if (line.compare(0, name.size() + 1, name + ":") == 0) {
            std::istringstream s(line.substr(name.size() + 1));
            uint64_t kb = 0;
            s >> kb;
            return kb * 1024;
        }
    return 0;
}

void tighten(AvailableMemory* a, uint64_t bytes, const char* why) {
    if (a->bytes == 0 || bytes < a->bytes) {
        a->bytes = bytes;
        a->limit = why;
    }
}

// A soft limit less what is in use (0 when nothing is left); false when the limit is not set.
bool limitLeft(int resource, uint64_t inUse, uint64_t* left) {
    struct rlimit r {};
    if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return false;
    const uint64_t lim = static_cast<uint64_t>(r.rlim_cur);
    *left = lim > inUse ? lim - inUse : 1;
    return true;
}

std::string gb(uint64_t bytes) { return formatFixed(static_cast<double>(bytes) / 1e9, 1) + " GB"; }

}  // namespace

AvailableMemory availableMemory() {
    AvailableMemory a;
    if (const uint64_t free = procKb("/proc/meminfo", "MemAvailable"); free > 0) tighten(&a, free, "MemAvailable");
    uint64_t left = 0;
    if (limitLeft(RLIMIT_AS, procKb("/proc/self/status", "VmSize"), &left))
        tighten(&a, left, "the address-space limit (ulimit -v)");
    if (limitLeft(RLIMIT_DATA, procKb("/proc/self/status", "VmData"), &left)) tighten(&a, left, "the data limit (ulimit -d)");
    return a;
}

std::string memoryShortfall(uint64_t needBytes, const AvailableMemory& available, const std::string& what) {
    if (available.bytes == 0 || needBytes <= available.bytes) return {};
    return "about " + gb(needBytes) + " of memory is needed for " + what + "; " + gb(available.bytes) + " is available (" +
           available.limit + ")";
}

}  // namespace lwb::core
