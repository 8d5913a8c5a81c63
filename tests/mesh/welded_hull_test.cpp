// The welded mesher's incremental convex hull (src/mesh/welded_hull.hpp): points added to a
// built hull give the hull of all of them.
#include "mesh/welded_hull.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus::detail {
namespace {

// Faces as sorted triples of their corners, each rotated to start at its smallest corner (the
// winding kept), so two hulls of the same points compare equal.
std::vector<std::array<std::uint32_t, 3>> canonicalFaces(
    const std::vector<std::array<std::uint32_t, 3>>& faces) {
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::array<std::uint32_t, 3> f : faces) {
        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
        out.push_back(f);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Random points in general position (no four coplanar), so their hull's faces are unique.
TEST(ConvexHull, ExtendingAHullGivesTheHullOfAllThePoints) {
    Rng rng(7);
    std::vector<Vec3> points;
    for (int i = 0; i < 60; ++i) {
        points.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    }
    ConvexHull whole;
    ASSERT_TRUE(whole.build(points, 1e-12));
    ConvexHull grown;
    ASSERT_TRUE(grown.build(std::span<const Vec3>(points).first(20), 1e-12));
    const std::size_t before = grown.faces().size();
    ASSERT_TRUE(grown.extend(points, 20, 1e-12));
    EXPECT_NE(grown.faces().size(), before);
    EXPECT_EQ(canonicalFaces(grown.faces()), canonicalFaces(whole.faces()));
    // Closed: Euler's formula for a triangulated sphere, F = 2V − 4 over the hull's vertices.
    std::vector<std::uint32_t> corners;
    for (const auto& f : whole.faces()) corners.insert(corners.end(), f.begin(), f.end());
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    EXPECT_EQ(whole.faces().size(), 2 * corners.size() - 4);
}

// The builder keeps its scratch arrays (the faces alive among those made, too) between calls:
// a hull built after another is the one a fresh builder makes.
TEST(ConvexHull, AReusedBuilderGivesTheHullOfTheNewPoints) {
    Rng rng(11);
    auto randomPoints = [&](int n, double scale) {
        std::vector<Vec3> points;
        for (int i = 0; i < n; ++i) {
            points.emplace_back(scale * rng.uniform(-1, 1), scale * rng.uniform(-1, 1),
                                scale * rng.uniform(-1, 1));
        }
        return points;
    };
    const std::vector<Vec3> first = randomPoints(80, 1.0), second = randomPoints(25, 3.0);
    ConvexHull reused;
    ASSERT_TRUE(reused.build(first, 1e-12));
    ASSERT_TRUE(reused.build(second, 1e-12));
    ConvexHull fresh;
    ASSERT_TRUE(fresh.build(second, 1e-12));
    EXPECT_EQ(reused.faces(), fresh.faces());
    for (const auto& f : reused.faces()) {
        for (const std::uint32_t v : f) EXPECT_LT(v, second.size());
    }
}

}  // namespace
}  // namespace ramus::detail
