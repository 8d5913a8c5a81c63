// The box tree of the solid union's rays (src/mesh/box_tree.hpp): every box a ray meets is
// visited, once, against testing every box. Coordinates are multiples of 1/64 and direction
// components powers of two (or 0), so the reference slab test is exact in doubles, and rays
// that only touch a box (along a face, through an edge or a corner) are common.
#include "mesh/box_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus {
namespace {

using detail::Box3;
using detail::BoxTree;
using Triple = std::array<double, 3>;

// Whether the ray meets the closed box `b` widened by `margin` (exact for the inputs here).
bool rayMeetsBox(const Box3& b, const Triple& origin, const Triple& direction, double margin) {
    double near = 0.0, far = std::numeric_limits<double>::infinity();
    for (int d = 0; d < 3; ++d) {
        const double lo = b.lo[d] - margin, hi = b.hi[d] + margin;
        if (direction[d] == 0.0) {
            if (origin[d] < lo || origin[d] > hi) return false;
            continue;
        }
        double t0 = (lo - origin[d]) / direction[d], t1 = (hi - origin[d]) / direction[d];
        if (t0 > t1) std::swap(t0, t1);
        near = std::max(near, t0);
        far = std::min(far, t1);
    }
    return near <= far;
}

double gridValue(Rng& rng, double range) {
    return std::round(rng.uniform(-range, range) * 64.0) / 64.0;
}

double directionComponent(Rng& rng) {
    constexpr double kChoices[] = {0.0, 1.0, -1.0, 2.0, -0.5, 0.25, -4.0};
    return kChoices[rng.uniformInt(7)];
}

std::vector<Box3> randomBoxes(Rng& rng, std::size_t n) {
    std::vector<Box3> boxes(n);
    for (Box3& b : boxes) {
        // Mostly small boxes, a few large ones (a trunk among twigs).
        const double size = rng.uniformInt(10) == 0 ? 4.0 : 0.25;
        for (int d = 0; d < 3; ++d) {
            b.lo[d] = gridValue(rng, 8.0);
            b.hi[d] = b.lo[d] + std::round(rng.uniform(0.0, size) * 64.0) / 64.0;
        }
    }
    return boxes;
}

void expectSameAsAllBoxes(const std::vector<Box3>& boxes, const Triple& origin,
                          const Triple& direction) {
    const BoxTree tree(boxes);
    std::vector<int> visits(boxes.size(), 0);
    tree.forEachAlongRay(origin, direction, [&](std::uint32_t i) { ++visits[i]; });
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        if (rayMeetsBox(boxes[i], origin, direction, 0.0) && !boxes[i].empty()) {
            EXPECT_EQ(visits[i], 1) << "box " << i << " met but visited " << visits[i];
        } else {
            // Visited only within the widening (1e-9 of the scene: far below 1e-6 here).
            EXPECT_LE(visits[i], rayMeetsBox(boxes[i], origin, direction, 1e-6) ? 1 : 0)
                << "box " << i;
        }
    }
}

TEST(BoxTree, EveryBoxARayMeetsIsVisitedOnce) {
    Rng rng(0xB0C5);
    for (int round = 0; round < 30; ++round) {
        SCOPED_TRACE(round);
        const std::vector<Box3> boxes = randomBoxes(rng, 1 + rng.uniformInt(600));
        for (int ray = 0; ray < 40; ++ray) {
            Triple direction{directionComponent(rng), directionComponent(rng),
                             directionComponent(rng)};
            if (direction == Triple{0.0, 0.0, 0.0}) direction[2] = 1.0;
            // From a box's corner or face now and then: rays that touch boxes.
            const Box3& from = boxes[rng.uniformInt(static_cast<std::uint32_t>(boxes.size()))];
            const Triple origin =
                rng.uniformInt(2) == 0
                    ? Triple{gridValue(rng, 9.0), gridValue(rng, 9.0), gridValue(rng, 9.0)}
                    : Triple{from.lo[0], rng.uniformInt(2) ? from.hi[1] : gridValue(rng, 9.0),
                             from.lo[2]};
            expectSameAsAllBoxes(boxes, origin, direction);
        }
    }
}

TEST(BoxTree, EmptyBoxesAndPointsAndNothing) {
    std::vector<Box3> boxes(5);  // empty
    Box3 point;
    point.add({1.0, 2.0, 3.0});
    boxes.push_back(point);
    boxes.push_back(point);  // the same point twice: a scene without extent
    const BoxTree tree(boxes);
    std::vector<std::uint32_t> visited;
    tree.forEachAlongRay({1.0, 2.0, 0.0}, {0.0, 0.0, 1.0},
                         [&](std::uint32_t i) { visited.push_back(i); });
    std::sort(visited.begin(), visited.end());
    EXPECT_EQ(visited, (std::vector<std::uint32_t>{5, 6}));
    visited.clear();
    tree.forEachAlongRay({1.0, 2.0, 4.0}, {0.0, 0.0, 1.0},
                         [&](std::uint32_t i) { visited.push_back(i); });
    EXPECT_TRUE(visited.empty());  // the points are behind the ray's start
    const BoxTree none(std::vector<Box3>{});
    none.forEachAlongRay({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
                         [&](std::uint32_t) { ADD_FAILURE() << "a box in an empty tree"; });
}

}  // namespace
}  // namespace ramus
