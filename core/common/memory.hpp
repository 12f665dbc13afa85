#pragma once
// What memory this process can still take, so that an input too large for it is refused with
// the figures before it is read, not half-read until the allocator fails (issue 44: "limits
// said, not hit").
#include <cstdint>
#include <string>

namespace lwb::core {

struct AvailableMemory {
    uint64_t bytes = 0;  ///< 0: not known (no /proc): nothing is refused for memory
    std::string limit;   ///< what sets it: "MemAvailable", "the address-space limit (ulimit -v)", "the data limit (ulimit -d)"
};

/// The least of the system's available memory (/proc/meminfo MemAvailable) and, where soft
/// limits are set, RLIMIT_AS less the address space in use (VmSize) and RLIMIT_DATA less the
/// data in use (VmData), from /proc/self/status.
AvailableMemory availableMemory();

/// "" when `needBytes` fits `available` (or it is not known), else "about X GB of memory is
/// needed for WHAT; Y GB is available (LIMIT)" in decimal units with one decimal.
std::string memoryShortfall(uint64_t needBytes, const AvailableMemory& available, const std::string& what);

}  // namespace lwb::core
