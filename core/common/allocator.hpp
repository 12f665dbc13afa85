#pragma once
// Heap settings for the workbench's own executables (not called by the core itself: they are
// process-wide). glibc returns freed memory at the top of the heap to the system once more
// than 128 KiB lie free there, and serves blocks above a threshold that adapts from 128 KiB
// with mmap. A sparse SLR pass's scale search allocates and frees the same few hundred KiB
// thousands of times (binary images, sort buffers), so every round trip cost page faults:
// on an 18 000-point pass 112 000 minor faults, 0.8 s of system time and half the user time
// of a 2.2 s run (docs/benchmarks.md). Blocks up to 64 MiB now come from the heap, and the
// heap is given back only when 1 GiB lies free at its top.
// Page faults stayed the largest cost after that: on this project's 2-core VM each first touch
// of a 4 KiB page costs about 11 µs, and a 59 680-point sparse pass touched 5 000 pages (55 ms
// of a 0.31 s run), a 10^6-point kHz pass 45 000 (half of 1.55 s). The heap is therefore
// advised for transparent huge pages (madvise; the kernel's default mode): faults fell to
// about 1 300 on both, the runs to 0.27 s and 0.8–1.0 s; peak memory rose by 1.5 MB and by
// 20–27 MB (135–141 B/point).
// Worker threads allocate from arenas of their own (glibc's default; the workbench gives that up,
// useOneArena below). With one arena for every
// thread, a block one core had just freed, still in that core's cache, was handed to the other
// core's next allocation, and each of the scale search's trials allocates about 13 MB: the same
// trials took 27 % more CPU time run on two threads than on one (170 → 216 ms for the ladders of
// a 10^5-point sparse pass). Those arenas are not the advised heap, so each worker thread
// advises a block of its own arena at its start (adviseThreadHeap).
//
// Blocks above the mmap threshold (64 MiB: a column of 8.4 million doubles) are mapped apart from
// the heap and were not advised: a 10^7-event kHz pass, every column of it such a block, spent
// half its 37 s in page faults (4·10^6 events: 12 s). glibc advises them itself, and the heap's
// every growth, with its tunable glibc.malloc.hugetlb=1, which is read from the environment at
// the start of a process only: reexecWithHugePages starts the program again with it set.
namespace lwb::core {
/// Sets the thresholds above (glibc; does nothing elsewhere). Call once, early in main().
void tuneAllocator();
/// First thing in main(): unless GLIBC_TUNABLES already says glibc.malloc.hugetlb (set, or set
/// to 0 to keep glibc's default), executes `exe` (the program itself) again with argv and it
/// appended (glibc only). Returns when it cannot (no /proc, exec refused): the program runs as
/// it is, its environment as it was.
/// The measured effect: the 10^7-event pass 36.7 -> 17.2 s, 10^6 events 1.37 -> 1.27 s, the
/// same peak memory (docs/benchmarks.md).
void reexecWithHugePages(char** argv, const char* exe = "/proc/self/exe");
/// The workbench's setting, after tuneAllocator: every thread allocates from one malloc arena
/// (glibc; nothing elsewhere). The workbench keeps a run on screen while its worker computes the
/// next; with an arena per thread the worker's and the GUI thread's each kept their own high-water
/// mark (freed memory stays in its arena), and a 10^7-event kHz pass's slider session peaked at
/// 223 bytes an event; with one, 174. The price is the contention above: the workbench's slider
/// medians 3-8 % slower on the 2-core VM (a 10^5-point pass 118.6 -> 122.5 ms, the footprint's
/// threshold 60.8 -> 65.4 ms; docs/benchmarks.md), likely more with more cores. adviseThreadHeap
/// then advises the shared arena again (harmless). The command line keeps an arena per thread.
void useOneArena();
/// Gives the calling thread's malloc arena advised (huge) pages, once per thread; does nothing
/// unless the executable called tuneAllocator. Called first by the core's worker threads.
void adviseThreadHeap();
}  // namespace lwb::core
