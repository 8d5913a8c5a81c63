// Running independent tasks on the machine's cores, with results that do not depend on the
// threads. Internal to src/mesh.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace ramus::detail {

/// Tasks per thread at least: fewer run on fewer threads (starting or waking one costs more).
constexpr std::size_t kTasksPerThread = 64;

/// How many threads n tasks run on, given the machine's `cores`: up to as many as it has, at
/// most 4, and one per kTasksPerThread tasks.
inline std::size_t workersFor(std::size_t n, std::size_t cores) {
    return std::min<std::size_t>({std::max<std::size_t>(1, cores), 4, n / kTasksPerThread + 1});
}

/// The machine's cores (a system call: glibc reads /sys each time).
inline std::size_t machineCores() { return std::thread::hardware_concurrency(); }

/// Tasks a thread claims at a time: small blocks, so that a thread that starts late (starting
/// or waking one takes tens of microseconds on the VM) or draws slow tasks does not hold the
/// others up, of consecutive tasks, so that threads seldom write to the same cache line.
constexpr std::size_t kClaimBlock = 16;

/// Runs the blocks of `claim` tasks of n that thread w claims from `next` (shared by the
/// threads of one batch) until none is left; a task taking two arguments also gets w.
template <class Task>
void runClaimed(std::size_t n, std::atomic<std::size_t>& next, std::size_t w, const Task& task,
                std::size_t claim = kClaimBlock) {
    for (;;) {
        const std::size_t block = next.fetch_add(claim, std::memory_order_relaxed);
        if (block >= n) return;
        for (std::size_t i = block; i < std::min(n, block + claim); ++i) {
            if constexpr (std::is_invocable_v<const Task&, std::size_t, std::size_t>) {
                task(i, w);
            } else {
                task(i);
            }
        }
    }
}

/// Calls task(i) for every i < n on `threads` threads, each claiming `claim` tasks at a time
/// (runClaimed; one for tasks of very different sizes, as the welded mesher's junctions): for
/// independent tasks whose results go to slot i, so the result does not depend on the threads. A
/// task taking two arguments also gets its thread's number w below `threads`, for scratch space
/// of its own. An exception from a task is passed on to the caller once every thread has
/// finished.
template <class Task>
void forEachOnThreads(std::size_t n, std::size_t threads, const Task& task,
                      std::size_t claim = kClaimBlock) {
    std::vector<std::exception_ptr> failures(threads);
    std::atomic<std::size_t> next{0};
    auto share = [&](std::size_t w) {
        try {
            runClaimed(n, next, w, task, claim);
        } catch (...) {
            failures[w] = std::current_exception();
        }
    };
    std::vector<std::thread> workers;
    for (std::size_t w = 1; w < threads; ++w) workers.emplace_back(share, w);
    share(0);
    for (std::thread& worker : workers) worker.join();
    for (const std::exception_ptr& failure : failures) {
        if (failure) std::rethrow_exception(failure);
    }
}

/// forEachOnThreads on workersFor(n, machineCores()) threads. The solid union's patch and piece
/// votes took 10–20 % of its time on one core (ABOP 1.24b: 1.4 s an attempt); the shrunk
/// junctions' rays most of the welding time of the dense ABOP plants.
template <class Task>
void forEachOnCores(std::size_t n, const Task& task) {
    forEachOnThreads(n, workersFor(n, machineCores()), task);
}

/// How many threads n coarse tasks run on (forEachCoarseOnCores): one per task, up to the
/// machine's `cores` (at most 4, as workersFor).
inline std::size_t coarseWorkersFor(std::size_t n, std::size_t cores) {
    return std::min<std::size_t>({std::max<std::size_t>(1, cores), 4, std::max<std::size_t>(1, n)});
}

/// forEachOnThreads for n coarse tasks, each worth far more than starting a thread (about
/// 0.1 ms on the VM), on coarseWorkersFor(n) threads, each claiming one task at a time. The box
/// searches of the solid union cut their work into tasks of a thousand boxes, which
/// forEachOnCores ran on one thread below 64 of them (a mesh of 64 k triangles): the unions of
/// the 23 k-triangle ABOP plants searched on one core (2.6b 45 → 35 ms, 2.8d 194 → 132 ms).
template <class Task>
void forEachCoarseOnCores(std::size_t n, const Task& task) {
    forEachOnThreads(n, coarseWorkersFor(n, machineCores()), task, 1);
}

/// Threads kept for many small batches of independent tasks: forEachOnCores starts its threads
/// anew on every call, about 0.1 ms each with jemalloc on the 2-core VM, more than a shrunk
/// junction's few hundred rays take. The helpers start with the first batch large enough to
/// share and wait between batches; forEach gives the same results as forEachOnCores.
class CoreTeam {
public:
    CoreTeam() : cores_(machineCores()) {}
    /// A team of at most `cores` threads (1: every batch on the calling thread).
    explicit CoreTeam(std::size_t cores) : cores_(cores) {}
    CoreTeam(const CoreTeam&) = delete;
    CoreTeam& operator=(const CoreTeam&) = delete;
    ~CoreTeam() {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        for (std::thread& helper : helpers_) helper.join();
    }

    /// How many threads forEach runs n tasks on.
    std::size_t workersFor(std::size_t n) const { return detail::workersFor(n, cores_); }

    /// Calls task(i, w) (or task(i)) for every i < n, w < workersFor(n) the number of the
    /// thread running it (for scratch space of its own), the threads claiming blocks of tasks
    /// as they go (runClaimed): for tasks whose results go to slot i, so the result does not
    /// depend on the threads. An exception from a task is passed on once every thread has
    /// finished (the others' tasks may have run or not).
    template <class Task>
    void forEach(std::size_t n, const Task& task) {
        const std::size_t threads = workersFor(n);
        std::atomic<std::size_t> next{0};
        auto share = [&](std::size_t w) { runClaimed(n, next, w, task); };
        if (threads == 1) {
            share(0);
            return;
        }
        while (helpers_.size() + 1 < threads) {
            // Only this thread changes generation_: the helper waits for the next batch.
            helpers_.emplace_back(
                [this, w = helpers_.size() + 1, seen = generation_] { help(w, seen); });
        }
        std::vector<std::exception_ptr> failures(threads);
        {
            const std::lock_guard lock(mutex_);
            batch_ = [&](std::size_t w) {
                try {
                    if (w < threads) share(w);
                } catch (...) {
                    failures[w] = std::current_exception();
                }
            };
            open_ = true;
            ++generation_;
        }
        wake_.notify_all();
        batch_(0);
        {
            // A helper not awake yet skips the batch: this thread claimed what it left.
            std::unique_lock lock(mutex_);
            open_ = false;
            done_.wait(lock, [&] { return running_ == 0; });
        }
        for (const std::exception_ptr& failure : failures) {
            if (failure) std::rethrow_exception(failure);
        }
    }

private:
    // Helper thread w: runs its share of every batch after the one numbered `seen` that is
    // still open when it wakes.
    void help(std::size_t w, std::size_t seen) {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
            if (!open_) continue;
            ++running_;
            lock.unlock();
            batch_(w);
            lock.lock();
            if (--running_ == 0 && !open_) done_.notify_one();
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::function<void(std::size_t)> batch_;  // runs thread w's share of the current batch
    std::size_t generation_ = 0;
    std::size_t running_ = 0;  // helpers in the current batch
    bool open_ = false;        // whether a helper waking up joins the current batch
    bool stop_ = false;
    std::vector<std::thread> helpers_;
    std::size_t cores_;
};

}  // namespace ramus::detail
