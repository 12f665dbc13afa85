#pragma once
// A parallel loop for the core's few data-parallel steps: job(0) … job(n − 1) on up to
// `threads` threads, the calling one included, each thread taking the next index as it
// finishes one (the two cores of a virtual machine can run at different speeds, so a fixed
// split waits for the slower one). Returns when all are done. An exception in a job is rethrown
// here, after every thread has joined. Jobs must not share written memory: a job's output in a
// cache line of its own (alignas(64)) is not slowed by another's writes.
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <cstddef>
#include <exception>
#include <functional>
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


/// Items of a stream worked on side by side while the stream is still being read, and handed
/// back in the order they came: the reader submit()s each item, work(item) runs on one of
/// `threads` worker threads, and takeReady() returns the finished items at the head of the order
/// (drain() waits for all). At most `window` items are held: submit waits, when the window is
/// full, until the oldest is finished (the reader then takes it). work must not throw (an item
/// records its own failure). The destructor stops the workers after their current item; items
/// not started are dropped.
template <class Item>
class OrderedWorkers {
public:
    template <class Work>
    OrderedWorkers(size_t threads, size_t window, Work work)
        : m_window(std::max<size_t>(1, window)), m_work(std::move(work)) {
        for (size_t k = 0; k < std::max<size_t>(1, threads); ++k)
            m_threads.emplace_back([this] {
                adviseThreadHeap();
                loop();
            });
    }
    ~OrderedWorkers() {
        {
            const std::lock_guard<std::mutex> lock(m_lock);
            m_stop = true;
        }
        m_wake.notify_all();
        for (auto& t : m_threads) t.join();
    }
    OrderedWorkers(const OrderedWorkers&) = delete;
    OrderedWorkers& operator=(const OrderedWorkers&) = delete;

    void submit(Item item) {
        std::unique_lock<std::mutex> lock(m_lock);
        m_done.wait(lock, [this] { return m_slots.size() < m_window || m_slots.front().finished; });
        m_slots.push_back(Slot{std::move(item), false, false});
        m_wake.notify_one();
    }

    std::vector<Item> takeReady() {
        const std::lock_guard<std::mutex> lock(m_lock);
        return popFinished();
    }

    std::vector<Item> drain() {
        std::unique_lock<std::mutex> lock(m_lock);
        m_done.wait(lock, [this] {
            return std::all_of(m_slots.begin(), m_slots.end(), [](const Slot& s) { return s.finished; });
        });
        return popFinished();
    }

private:
    struct Slot {
        Item item;
        bool started, finished;
    };

    std::vector<Item> popFinished() {
        std::vector<Item> out;
        while (!m_slots.empty() && m_slots.front().finished) {
            out.push_back(std::move(m_slots.front().item));
            m_slots.pop_front();  // (a deque keeps the other slots where they are)
        }
        return out;
    }

    void loop() {
        std::unique_lock<std::mutex> lock(m_lock);
        for (;;) {
            Slot* next = nullptr;
            m_wake.wait(lock, [&] {
                for (Slot& s : m_slots)
                    if (!s.started) {
                        next = &s;
                        return true;
                    }
                return m_stop;
            });
            if (m_stop) return;
            next->started = true;
            lock.unlock();
            m_work(next->item);
            lock.lock();
            next->finished = true;
            m_done.notify_all();
        }
    }

    size_t m_window;
    std::function<void(Item&)> m_work;
    std::mutex m_lock;
    std::condition_variable m_wake, m_done;
    std::deque<Slot> m_slots;
    bool m_stop = false;
    std::vector<std::thread> m_threads;  // (last: they start once the rest is built)
};

}  // namespace lwb::core
