// Running independent tasks on the machine's cores, with results that do not depend on the
// threads. Internal to src/mesh.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace ramus::detail {

/// Calls task(i) for every i < n, on up to as many threads as the machine has cores (at most
/// 4), each thread taking every k-th block of 64 consecutive i (blocks, so that threads do not
/// write to the same cache line): for independent tasks whose results go to slot i, so the
/// result does not depend on the threads. The solid union's patch and piece votes took 10–20 %
/// of its time on one core (ABOP 1.24b: 1.4 s an attempt).
/// An exception from a task is passed on to the caller once every thread has finished.
template <class Task>
void forEachOnCores(std::size_t n, const Task& task) {
    constexpr std::size_t kBlock = 64;
    const std::size_t threads = std::min<std::size_t>(
        {std::max(1u, std::thread::hardware_concurrency()), 4, n / kBlock + 1});
    std::vector<std::exception_ptr> failures(threads);
    auto share = [&](std::size_t w) {
        try {
            for (std::size_t block = w * kBlock; block < n; block += threads * kBlock) {
                for (std::size_t i = block; i < std::min(n, block + kBlock); ++i) task(i);
            }
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

}  // namespace ramus::detail
