// Helpers shared by the colonization tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "ramus/colonize.hpp"
#include "ramus/rng.hpp"

namespace ramus::testing {

/// n points uniform in the box [lo, hi]³ from `seed`.
inline std::vector<Vec3> randomPoints(std::size_t n, double lo, double hi, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = rng.uniform(lo, hi), y = rng.uniform(lo, hi), z = rng.uniform(lo, hi);
        points.emplace_back(x, y, z);
    }
    return points;
}

/// Expects two results to be identical: same trees, same nodes in the same order, bitwise.
inline void expectSameResult(const ColonizeResult& a, const ColonizeResult& b) {
    ASSERT_EQ(a.trees.size(), b.trees.size());
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.attractors, b.attractors);
    EXPECT_EQ(a.attractorsLeft, b.attractorsLeft);
    for (std::size_t t = 0; t < a.trees.size(); ++t) {
        const auto& na = a.trees[t].nodes();
        const auto& nb = b.trees[t].nodes();
        ASSERT_EQ(na.size(), nb.size()) << "tree " << t;
        for (std::size_t i = 0; i < na.size(); ++i) {
            ASSERT_EQ(na[i].parent, nb[i].parent) << "tree " << t << " node " << i;
            ASSERT_EQ(na[i].position, nb[i].position) << "tree " << t << " node " << i;
            ASSERT_EQ(na[i].branchDepth, nb[i].branchDepth) << "tree " << t << " node " << i;
        }
    }
}

/// All node positions of all trees.
inline std::vector<Vec3> allNodePositions(const ColonizeResult& r) {
    std::vector<Vec3> out;
    for (const BranchTree& t : r.trees) {
        for (const BranchNode& n : t.nodes()) out.push_back(n.position);
    }
    return out;
}

/// Directory for test outputs (RAMUS_TEST_OUTPUT), or empty.
inline std::string testOutputDirectory() {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    return dir && *dir ? std::string(dir) : std::string();
}

}  // namespace ramus::testing
