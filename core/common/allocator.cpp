#include "core/common/allocator.hpp"

#include <cstdint>
#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace lwb::core {
void tuneAllocator() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    // Huge pages for the heap (allocator.hpp says why). One arena, so that the worker threads
    // allocate from the advised heap too; the heap is grown once by kHugeReserve (address space
    // only: nothing is touched) and that range advised. It is given back to the system only
    // when more than 1 GiB lies free at its top, so the advised range is never trimmed away.
    constexpr long kHugeReserve = 256L << 20;
    constexpr uintptr_t kHuge = 2u << 20;
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_ARENA_MAX, 1);
    mallopt(M_TOP_PAD, static_cast<int>(kHugeReserve));
    const uintptr_t before = reinterpret_cast<uintptr_t>(sbrk(0));
    void* volatile grow = malloc(1 << 20);  // volatile: the compiler may not drop the pair
    free(grow);
    const uintptr_t after = reinterpret_cast<uintptr_t>(sbrk(0));
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default from here on
    const uintptr_t lo = (before + kHuge - 1) & ~(kHuge - 1);
    // A kernel without transparent huge pages refuses the advice: nothing else changes.
    if (before != uintptr_t(-1) && after > lo) madvise(reinterpret_cast<void*>(lo), after - lo, MADV_HUGEPAGE);
#endif
}
}  // namespace lwb::core
