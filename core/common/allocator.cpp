#include "core/common/allocator.hpp"

#include <atomic>
#include <cstdint>
#include <cstdlib>  // defines __GLIBC__ on glibc
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace lwb::core {
namespace {
std::atomic<bool> gTuned{false};
constexpr uintptr_t kHuge = 2u << 20;

// Advises [p, p + size) for transparent huge pages, from its first 2 MiB boundary.
void adviseHuge(uintptr_t p, uintptr_t size) {
#if defined(__GLIBC__)
    const uintptr_t lo = (p + kHuge - 1) & ~(kHuge - 1), hi = (p + size) & ~uintptr_t(4095);
    // A kernel without transparent huge pages refuses the advice: nothing else changes.
    if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#else
    (void)p;
    (void)size;
#endif
}
}  // namespace

void tuneAllocator() {
#if defined(__GLIBC__)
    gTuned.store(true);
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    // Huge pages for the heap (allocator.hpp says why): it is grown once by kHugeReserve
    // (address space only: nothing is touched) and that range advised. It is given back to the
    // system only when more than 1 GiB lies free at its top, so the advised range is never
    // trimmed away. glibc's arenas per thread are kept (up to 8 per core): the worker threads'
    // arenas get their huge pages from adviseThreadHeap.
    constexpr long kHugeReserve = 256L << 20;
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, static_cast<int>(kHugeReserve));
    const uintptr_t before = reinterpret_cast<uintptr_t>(sbrk(0));
    void* volatile grow = malloc(1 << 20);  // volatile: the compiler may not drop the pair
    free(grow);
    const uintptr_t after = reinterpret_cast<uintptr_t>(sbrk(0));
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default from here on
    if (before != uintptr_t(-1) && after > before) adviseHuge(before, after - before);
#endif
}

void useOneArena() {
#if defined(__GLIBC__)
    mallopt(M_ARENA_MAX, 1);
#endif
}

void reexecWithHugePages(char** argv, const char* exe) {
#if defined(__GLIBC__)
    const char* now = std::getenv("GLIBC_TUNABLES");
    const std::string given = now ? now : "";
    if (given.find("glibc.malloc.hugetlb") != std::string::npos || !argv || !argv[0]) return;
    const std::string tunables = given.empty() ? "glibc.malloc.hugetlb=1" : given + ":glibc.malloc.hugetlb=1";
    if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
    execv(exe, argv);
    // (not executed: the program goes on with glibc's default, and says nothing of it)
    if (now) setenv("GLIBC_TUNABLES", now, 1);
    else unsetenv("GLIBC_TUNABLES");
#else
    (void)argv;
    (void)exe;
#endif
}

void adviseThreadHeap() {
#if defined(__GLIBC__)
    thread_local bool done = false;
    if (done || !gTuned.load(std::memory_order_relaxed)) return;
    done = true;
    // A block of kReserve from the thread's arena, advised and freed: it returns to the arena's
    // top, which stays mapped (the trim threshold above), so the arena's next kReserve bytes
    // are in advised pages. Address space only: the block is not touched.
    constexpr size_t kReserve = 32u << 20;
    void* volatile block = malloc(kReserve);
    if (block) adviseHuge(reinterpret_cast<uintptr_t>(block), kReserve);
    free(block);
#endif
}
}  // namespace lwb::core
