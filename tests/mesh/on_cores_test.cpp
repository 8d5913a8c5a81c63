// Tasks on the machine's cores (src/mesh/on_cores.hpp): every task runs once, on a thread number
// below workersFor(n, cores), results land where the tasks put them whatever the threads,
// exceptions reach the caller, and a CoreTeam serves many batches of different sizes in a row.
#include "mesh/on_cores.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace ramus {
namespace {

using detail::coarseWorkersFor;
using detail::CoreTeam;
using detail::forEachCoarseOnCores;
using detail::forEachOnCores;
using detail::workersFor;

TEST(OnCores, WorkersGrowWithTheTasksUpToTheCores) {
    EXPECT_EQ(workersFor(0, 8), 1u);
    EXPECT_EQ(workersFor(63, 8), 1u);  // one block of 64: not worth a thread
    EXPECT_EQ(workersFor(64, 8), 2u);
    EXPECT_EQ(workersFor(1 << 20, 8), 4u);
    EXPECT_EQ(workersFor(1 << 20, 2), 2u);
    EXPECT_EQ(workersFor(1 << 20, 0), 1u);  // cores unknown
    for (std::size_t n = 1; n < 1000; n += 37) EXPECT_LE(workersFor(n, 3), workersFor(n + 64, 3));
    EXPECT_EQ(CoreTeam().workersFor(1 << 20), workersFor(1 << 20, detail::machineCores()));
}

TEST(OnCores, CoarseTasksEachGetAThreadUpToTheCores) {
    EXPECT_EQ(coarseWorkersFor(0, 8), 1u);
    EXPECT_EQ(coarseWorkersFor(1, 8), 1u);
    EXPECT_EQ(coarseWorkersFor(2, 8), 2u);  // where workersFor gives one thread for 63 tasks
    EXPECT_EQ(coarseWorkersFor(23, 2), 2u);
    EXPECT_EQ(coarseWorkersFor(23, 8), 4u);
    EXPECT_EQ(coarseWorkersFor(23, 0), 1u);  // cores unknown
}

// Runs `forEach` over sizes around the block size and well beyond, and checks that every slot
// was written once, by a thread whose number is below workers(n, cores).
template <class ForEach>
void expectEveryTaskOnce(ForEach forEach,
                         std::size_t (*workersOf)(std::size_t, std::size_t) = workersFor) {
    for (const std::size_t n : {0u, 1u, 2u, 63u, 64u, 65u, 200u, 1000u, 4097u}) {
        SCOPED_TRACE(n);
        const std::size_t workers = workersOf(n, detail::machineCores());
        std::vector<std::uint32_t> runs(n, 0), squares(n, 0);
        std::vector<std::size_t> worker(n, 99);
        forEach(n, [&](std::size_t i, std::size_t w) {
            ++runs[i];
            squares[i] = static_cast<std::uint32_t>(i * i);
            worker[i] = w;
        });
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_EQ(runs[i], 1u);
            ASSERT_EQ(squares[i], i * i);
            ASSERT_LT(worker[i], workers);
        }
    }
}

TEST(OnCores, ForEachOnCoresRunsEveryTaskOnce) {
    expectEveryTaskOnce([](std::size_t n, const auto& task) { forEachOnCores(n, task); });
    std::vector<int> plain(500, 0);  // a task taking the index alone
    forEachOnCores(plain.size(), [&](std::size_t i) { plain[i] = static_cast<int>(i) + 1; });
    for (std::size_t i = 0; i < plain.size(); ++i) EXPECT_EQ(plain[i], static_cast<int>(i) + 1);
}

TEST(OnCores, ForEachCoarseOnCoresRunsEveryTaskOnce) {
    expectEveryTaskOnce([](std::size_t n, const auto& task) { forEachCoarseOnCores(n, task); },
                        coarseWorkersFor);
}

TEST(OnCores, TeamRunsEveryTaskOnceOverManyBatches) {
    CoreTeam team;
    for (int round = 0; round < 50; ++round) {
        expectEveryTaskOnce([&](std::size_t n, const auto& task) { team.forEach(n, task); });
    }
}

// Per-thread scratch space gives the same sums as one thread: what the shrunk junctions rely on.
TEST(OnCores, TeamScratchPerThreadGivesTheSequentialResult) {
    CoreTeam team;
    const std::size_t n = 3000;
    std::vector<std::vector<double>> scratch(team.workersFor(n));
    std::vector<double> result(n);
    team.forEach(n, [&](std::size_t i, std::size_t w) {
        std::vector<double>& s = scratch[w];
        s.assign(i % 17 + 1, 0.5 * static_cast<double>(i));
        double sum = 0.0;
        for (const double x : s) sum += x;
        result[i] = sum;
    });
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(result[i], static_cast<double>(i % 17 + 1) * 0.5 * static_cast<double>(i));
    }
}

TEST(OnCores, ExceptionsReachTheCallerAndTheTeamGoesOn) {
    CoreTeam team;
    for (const std::size_t failing : {0u, 100u, 999u}) {
        EXPECT_THROW(team.forEach(1000,
                                  [&](std::size_t i, std::size_t) {
                                      if (i == failing) throw std::runtime_error("task failed");
                                  }),
                     std::runtime_error);
    }
    std::vector<int> after(1000, 0);
    team.forEach(after.size(), [&](std::size_t i, std::size_t) { after[i] = 1; });
    for (const int a : after) EXPECT_EQ(a, 1);
    EXPECT_THROW(forEachOnCores(1000,
                                [](std::size_t i) {
                                    if (i == 500) throw std::runtime_error("task failed");
                                }),
                 std::runtime_error);
}

}  // namespace
}  // namespace ramus
