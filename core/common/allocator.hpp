#pragma once
// Heap settings for the workbench's own executables (not called by the core itself: they are
// process-wide). glibc returns freed memory at the top of the heap to the system once more
// than 128 KiB lie free there, and serves blocks above a threshold that adapts from 128 KiB
// with mmap. A sparse SLR pass's scale search allocates and frees the same few hundred KiB
// thousands of times (binary images, sort buffers), so every round trip cost page faults:
// on an 18 000-point pass 112 000 minor faults, 0.8 s of system time and half the user time
// of a 2.2 s run (docs/benchmarks.md). Blocks up to 64 MiB now come from the heap, and the
// heap is given back only when 256 MiB lie free at its top.
namespace lwb::core {
/// Sets the thresholds above (glibc; does nothing elsewhere). Call once, early in main().
void tuneAllocator();
}  // namespace lwb::core
