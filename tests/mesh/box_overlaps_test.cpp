// The broad phase of the solid union's self-intersection and crossing tests
// (src/mesh/box_overlaps.hpp): every overlapping pair of boxes once, against testing all pairs.
#include "mesh/box_overlaps.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus {
namespace {

using detail::Box3;
using detail::BoxPair;

Box3 box(double x0, double y0, double z0, double x1, double y1, double z1) {
    Box3 b;
    b.add({x0, y0, z0});
    b.add({x1, y1, z1});
    return b;
}

// Every pair (i < j) that overlaps with a suspect among them, by testing all pairs.
std::vector<BoxPair> allPairsOverlapping(const std::vector<Box3>& boxes,
                                         const std::vector<char>& suspect) {
    std::vector<BoxPair> pairs;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
            const bool either = suspect.empty() || suspect[i] || suspect[j];
            if (either && boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
        }
    }
    return pairs;
}

std::vector<BoxPair> sorted(std::vector<BoxPair> pairs) {
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// Boxes like a mesh's triangles: many small ones, some 10–60 times larger (a trunk beside
// twigs), a few flat or thin ones, a few points, one empty, and two over everything.
std::vector<Box3> mixedBoxes(std::uint64_t seed) {
    Rng rng(seed);
    std::vector<Box3> boxes;
    for (int i = 0; i < 1500; ++i) {
        const double x = rng.uniform(0.0, 10.0), y = rng.uniform(0.0, 10.0),
                     z = rng.uniform(0.0, 3.0);
        double size = rng.uniform(0.05, 0.3);
        if (i % 50 == 0) size *= rng.uniform(10.0, 60.0);
        const double flat = i % 7 == 0 ? 0.0 : rng.uniform(0.1, 1.0) * size;
        boxes.push_back(i % 97 == 0 ? box(x, y, z, x, y, z)
                                    : box(x, y, z, x + size, y + flat, z + 0.5 * size));
    }
    boxes.push_back(Box3{});                                  // empty
    boxes.push_back(box(-1.0, -1.0, -1.0, 11.0, 11.0, 4.0));  // over everything
    boxes.push_back(box(-2.0, 4.0, -1.0, 12.0, 6.0, 4.0));
    return boxes;
}

TEST(BoxOverlaps, FindsEveryOverlappingPairOnce) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const std::vector<Box3> boxes = mixedBoxes(seed);
        const std::vector<BoxPair> found = detail::overlappingBoxes(boxes, {});
        const std::vector<BoxPair> expected = allPairsOverlapping(boxes, {});
        EXPECT_GT(expected.size(), boxes.size());
        EXPECT_EQ(sorted(found), expected) << "seed " << seed;  // so none twice
        for (const auto& [i, j] : found) EXPECT_LT(i, j);
    }
}

TEST(BoxOverlaps, OnlyPairsWithASuspect) {
    const std::vector<Box3> boxes = mixedBoxes(7);
    std::vector<char> suspect(boxes.size(), 0);
    for (std::size_t i = 0; i < boxes.size(); i += 13) suspect[i] = 1;
    suspect[boxes.size() - 2] = 1;  // one over everything
    const std::vector<BoxPair> expected = allPairsOverlapping(boxes, suspect);
    EXPECT_LT(expected.size(), allPairsOverlapping(boxes, {}).size());
    EXPECT_EQ(sorted(detail::overlappingBoxes(boxes, suspect)), expected);
}

// Few suspects (at most one box in 32) are looked up in a tree of their own, many (more than
// half) filtered from all pairs: the same pairs as any other share.
TEST(BoxOverlaps, OnlyPairsWithOneOfFewOrManySuspects) {
    const std::vector<Box3> boxes = mixedBoxes(5);
    for (const std::size_t every : {1, 40, 300}) {
        std::vector<char> suspect(boxes.size(), 0);
        for (std::size_t i = 3; i < boxes.size(); i += every) suspect[i] = 1;
        suspect[boxes.size() - 1] = 1;                                // a wide one
        if (every == 1) suspect[10] = suspect[boxes.size() - 2] = 0;  // all but a few
        const std::vector<BoxPair> expected = allPairsOverlapping(boxes, suspect);
        EXPECT_GT(expected.size(), 20u);
        const std::vector<BoxPair> found = detail::overlappingBoxes(boxes, suspect);
        EXPECT_EQ(sorted(found), expected) << "every " << every;  // so none twice
        for (const auto& [i, j] : found) EXPECT_LT(i, j);
        EXPECT_EQ(found, detail::overlappingBoxes(boxes, suspect));  // in the same order
    }
    // Boxes that are not finite are left out, suspects or not.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<Box3> odd(64, box(0, 0, 0, 1, 1, 1));
    odd[0].lo[2] = nan;
    odd[1].hi[0] = std::numeric_limits<double>::infinity();
    std::vector<char> suspect(odd.size(), 0);
    suspect[0] = suspect[2] = 1;
    const std::vector<BoxPair> found = sorted(detail::overlappingBoxes(odd, suspect));
    ASSERT_EQ(found.size(), 61u);  // box 2 with every finite box but itself
    EXPECT_EQ(found.front(), (BoxPair{2, 3}));
}

// A filter drops pairs as they are found, from both searches; it sees each pair once, i < j.
TEST(BoxOverlaps, AFilterKeepsOnlyThePairsItWants) {
    const std::vector<Box3> boxes = mixedBoxes(11);
    std::vector<char> suspect(boxes.size(), 0);
    for (std::size_t i = 0; i < boxes.size(); i += 7) suspect[i] = 1;
    const detail::PairFilter odd = [](std::uint32_t i, std::uint32_t j) {
        EXPECT_LT(i, j);
        return (i + j) % 2 == 1;
    };
    for (const std::vector<char>& which : {std::vector<char>{}, suspect}) {
        std::vector<BoxPair> expected;
        for (const BoxPair& p : allPairsOverlapping(boxes, which)) {
            if ((p.first + p.second) % 2 == 1) expected.push_back(p);
        }
        EXPECT_GT(expected.size(), 10u);
        EXPECT_EQ(sorted(detail::overlappingBoxes(boxes, which, odd)), expected);
    }
}

// Once `stop` is set the search looks at no more boxes (a bucket of the grid's cells or 64 boxes
// on each thread, at most, after it is set) and returns the pairs found so far: the solid
// union's work limit sets it from its filter. Each kind of search: all pairs, few suspects (a
// tree of them), some and many suspects (the grids).
TEST(BoxOverlaps, AStopEndsTheSearch) {
    const std::vector<Box3> boxes = mixedBoxes(13);
    for (const std::size_t every : {0, 100, 5, 1}) {
        std::vector<char> suspect;
        if (every > 0) {
            suspect.assign(boxes.size(), 0);
            for (std::size_t i = 0; i < boxes.size(); i += every) suspect[i] = 1;
        }
        const std::vector<BoxPair> expected = allPairsOverlapping(boxes, suspect);
        ASSERT_GT(expected.size(), 200u) << every;

        std::atomic<bool> stop{true};  // set before: nothing is looked at
        std::atomic<std::size_t> calls{0};
        const detail::PairFilter count = [&](std::uint32_t, std::uint32_t) {
            ++calls;
            return true;
        };
        EXPECT_TRUE(detail::overlappingBoxes(boxes, suspect, count, &stop).empty()) << every;
        EXPECT_EQ(calls.load(), 0u) << every;

        stop = false;  // set by the filter at its tenth pair
        const detail::PairFilter tenth = [&](std::uint32_t, std::uint32_t) {
            if (++calls >= 10) stop = true;
            return true;
        };
        calls = 0;
        const std::vector<BoxPair> found =
            sorted(detail::overlappingBoxes(boxes, suspect, tenth, &stop));
        EXPECT_GE(found.size(), 10u) << every;
        EXPECT_LT(found.size(), expected.size() / 2) << every;
        EXPECT_TRUE(std::includes(expected.begin(), expected.end(), found.begin(), found.end()))
            << every;

        stop = false;  // never set: every pair
        EXPECT_EQ(sorted(detail::overlappingBoxes(boxes, suspect, count, &stop)), expected)
            << every;
    }
}

TEST(BoxOverlaps, TouchingBoxesOverlapAndCornersOnCellBordersCount) {
    // Unit cubes side by side on a lattice: each touches its 26 neighbours (faces, edges,
    // corners), all on the borders of the grid's cells.
    std::vector<Box3> boxes;
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 4; ++y) {
            for (int z = 0; z < 4; ++z) boxes.push_back(box(x, y, z, x + 1, y + 1, z + 1));
        }
    }
    const std::vector<BoxPair> found = detail::overlappingBoxes(boxes, {});
    EXPECT_EQ(sorted(found), allPairsOverlapping(boxes, {}));
    // Cubes at most one step apart along every axis: ((4 + 2·3)^3 - 4^3) / 2 = 468 pairs, 144
    // across a face, 216 across an edge and 108 at a corner.
    EXPECT_EQ(found.size(), 144u + 216u + 108u);
}

TEST(BoxOverlaps, DegenerateInputs) {
    EXPECT_TRUE(detail::overlappingBoxes({}, {}).empty());
    EXPECT_TRUE(detail::overlappingBoxes({Box3{}, Box3{}}, {}).empty());
    // Points all at one place: every pair.
    const std::vector<Box3> points(5, box(1.0, 2.0, 3.0, 1.0, 2.0, 3.0));
    EXPECT_EQ(detail::overlappingBoxes(points, {}).size(), 10u);
    // Coordinates that are not numbers or infinite leave their box out, not the others.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<Box3> odd(4, box(0, 0, 0, 1, 1, 1));
    odd[1].lo[0] = nan;
    odd[2].hi[1] = inf;
    odd[3] = box(0.5, 0.5, 0.5, 2, 2, 2);
    EXPECT_EQ(detail::overlappingBoxes(odd, {}), (std::vector<BoxPair>{{0, 3}}));
}

TEST(BoxOverlaps, TheSameBoxesGiveTheSamePairsInTheSameOrder) {
    const std::vector<Box3> boxes = mixedBoxes(11);
    EXPECT_EQ(detail::overlappingBoxes(boxes, {}), detail::overlappingBoxes(boxes, {}));
}

}  // namespace
}  // namespace ramus
