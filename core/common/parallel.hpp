#pragma once
// A parallel loop for the core's few data-parallel steps: job(0) … job(n − 1) on up to
// `threads` threads, the calling one included, each thread taking the next index as it
// finishes one (the two cores of a virtual machine can run at different speeds, so a fixed
// split waits for the slower one). Returns when all are done. An exception in a job is rethrown
// here, after every thread has joined. Jobs must not share written memory: a job's output in a
// cache line of its own (alignas(64)) is not slowed by another's writes.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/common/allocator.hpp"
#include "core/common/feedback.hpp"

namespace lwb::core {

/// The cores to use: `want` when > 0, else every hardware thread (at least 1).
inline size_t coresFor(int want) {
    return want > 0 ? static_cast<size_t>(want) : std::max(1u, std::thread::hardware_concurrency());
}

/// loop(k) on `threads` threads at once, k = 0 on the calling thread and 1 … threads − 1 on new
/// ones; returns when every one has returned. Each new thread first gives its malloc arena
/// advised (huge) pages (adviseThreadHeap, allocator.hpp). loop must not throw out of a new
/// thread (catch inside it, as parallelFor does).
template <class Loop>
void runOnThreads(size_t threads, Loop&& loop) {
    std::vector<std::thread> pool;
    for (size_t k = 1; k < threads; ++k)
        pool.emplace_back([&loop, k] {
            adviseThreadHeap();
            loop(k);
        });
    loop(size_t{0});
    for (auto& t : pool) t.join();
}

template <class Job>
void parallelFor(size_t n, size_t threads, Job&& job) {
    const size_t workers = std::min(n, threads);
    if (workers <= 1) {
        for (size_t i = 0; i < n; ++i) job(i);
        return;
    }
    std::atomic<size_t> next{0};
    std::exception_ptr failure;
    std::mutex failureLock;
    runOnThreads(workers, [&](size_t) {
        for (size_t i; (i = next.fetch_add(1)) < n;) {
            try {
                job(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(failureLock);
                if (!failure) failure = std::current_exception();
            }
        }
    });
    if (failure) std::rethrow_exception(failure);
}

/// job(i) for i in [0, n) on `threads` threads (0 = every core), stopping early when fb is
/// cancelled, with progress every 64 items and at the end; returns how many items ran. job must
/// not throw (it handles its own failures: one bad item is that item's result).
template <class Job>
size_t parallelForEach(size_t n, int threads, Feedback* fb, Job&& job) {
    std::atomic<size_t> next{0}, done{0};
    runOnThreads(std::max<size_t>(1, std::min(coresFor(threads), n)), [&](size_t) {
        for (size_t i; !cancelled(fb) && (i = next.fetch_add(1)) < n;) {
            job(i);
            const size_t d = ++done;
            if (fb && (d == n || d % 64 == 0)) fb->setProgress(static_cast<double>(d) / static_cast<double>(n));
        }
    });
    return done;
}

}  // namespace lwb::core
