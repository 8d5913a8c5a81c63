// The solid union's last step (src/mesh/crossing_repair.hpp): triangle pairs that cross by a
// few float steps, as rounding the cut leaves them where surfaces graze, are separated by
// moving corners a few float steps; real crossings stay, and nothing moves farther than allowed.
#include "mesh/crossing_repair.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "box_mesh.hpp"
#include "ramus/rng.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

// Two closed surfaces: the unit cube (12 triangles, outward) and a tetrahedron standing on its
// apex above the cube's top face, the apex at height `apexZ` over (apexX, apexY).
detail::CrossingSurface cubeAndTetrahedron(float apexZ, float apexX = 0.3f, float apexY = 0.4f) {
    detail::CrossingSurface s;
    for (int i = 0; i < 8; ++i) {
        s.points.emplace_back(static_cast<float>(i & 1), static_cast<float>((i >> 1) & 1),
                              static_cast<float>((i >> 2) & 1));
    }
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        s.triangles.push_back({q[0], q[1], q[2]});
        s.triangles.push_back({q[0], q[2], q[3]});
    }
    s.points.emplace_back(apexX, apexY, apexZ);  // 8: apex
    s.points.emplace_back(0.0f, 0.0f, 2.0f);     // 9, 10, 11: the base above
    s.points.emplace_back(0.9f, 0.1f, 2.0f);
    s.points.emplace_back(0.2f, 0.9f, 2.0f);
    // Base facing up (counter-clockwise from above), sides facing out.
    s.triangles.push_back({9, 10, 11});
    s.triangles.push_back({8, 10, 9});
    s.triangles.push_back({8, 11, 10});
    s.triangles.push_back({8, 9, 11});
    return s;
}

Mesh meshOf(const detail::CrossingSurface& s) {
    Mesh mesh;
    mesh.positions = s.points;
    for (const auto& t : s.triangles) mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
    return mesh;
}

// Every pair of a cube triangle and a tetrahedron triangle (separateCrossings works on the
// ones that cross).
std::vector<detail::TrianglePair> cubeTetrahedronPairs() {
    std::vector<detail::TrianglePair> pairs;
    for (std::uint32_t f = 0; f < 12; ++f) {
        for (std::uint32_t g = 12; g < 16; ++g) pairs.emplace_back(f, g);
    }
    return pairs;
}

double largestMove(const detail::CrossingSurface& before, const detail::CrossingSurface& after) {
    double largest = 0.0;
    for (std::size_t v = 0; v < before.points.size(); ++v) {
        largest = std::max(largest, (after.points[v] - before.points[v]).cast<double>().norm());
    }
    return largest;
}

constexpr double kMaxMove = 2e-5;  // 1e-5 of the extent, as the solid union allows

// The apex reaches 3 float steps through the cube's top face: one corner moves a few steps
// and nothing crosses any more; the surfaces keep their volumes.
TEST(CrossingRepair, GrazingCrossingIsSeparatedByFloatSteps) {
    const float ulp = std::nextafter(1.0f, 2.0f) - 1.0f;
    const detail::CrossingSurface start = cubeAndTetrahedron(1.0f - 3.0f * ulp);
    ASSERT_GT(test::countSelfIntersections(meshOf(start), 100), 0u);
    detail::CrossingSurface s = start;
    const std::vector<detail::TrianglePair> pairs = cubeTetrahedronPairs();
    const detail::CrossingRepair repair = detail::separateCrossings(s, pairs, kMaxMove);
    EXPECT_EQ(repair.pairsLeft, 0u);
    EXPECT_GE(repair.movedVertices, 1u);
    EXPECT_EQ(test::countSelfIntersections(meshOf(s), 100), 0u);
    const double moved = largestMove(start, s);
    EXPECT_GT(moved, 0.0);
    EXPECT_LE(moved, 32.0 * ulp);  // a few float steps, far below the allowed move
    const test::Topology top = test::analyzeTopology(meshOf(s));
    EXPECT_TRUE(top.closedOriented);
    EXPECT_NEAR(test::signedVolume(meshOf(s)), test::signedVolume(meshOf(start)), 1e-5);
}

// Grazes at random places of the top face (both of its triangles and near their shared
// diagonal), 1–8 float steps deep: every one is separated, within a hundred steps.
TEST(CrossingRepair, RandomGrazesAreSeparated) {
    const float ulp = std::nextafter(1.0f, 2.0f) - 1.0f;
    Rng rng(17);
    for (int trial = 0; trial < 40; ++trial) {
        SCOPED_TRACE(trial);
        const auto x = static_cast<float>(rng.uniform(0.15, 0.85));
        const auto y = static_cast<float>(rng.uniform(0.15, 0.85));
        const auto depth = static_cast<float>(1 + rng.uniformInt(8));
        const detail::CrossingSurface start = cubeAndTetrahedron(1.0f - depth * ulp, x, y);
        ASSERT_GT(test::countSelfIntersections(meshOf(start), 100), 0u);
        detail::CrossingSurface s = start;
        const detail::CrossingRepair repair =
            detail::separateCrossings(s, cubeTetrahedronPairs(), kMaxMove);
        EXPECT_EQ(repair.pairsLeft, 0u);
        EXPECT_EQ(test::countSelfIntersections(meshOf(s), 100), 0u);
        EXPECT_LE(largestMove(start, s), 100.0 * ulp);  // a cube corner may need 64 steps
        EXPECT_TRUE(test::analyzeTopology(meshOf(s)).closedOriented);
    }
}

// A real crossing (the apex 0.1 deep in the cube) is not the rounding's: no move within the
// allowed distance separates it, and no corner moves farther than allowed.
TEST(CrossingRepair, RealCrossingStaysAndNothingMovesFarther) {
    const detail::CrossingSurface start = cubeAndTetrahedron(0.9f);
    detail::CrossingSurface s = start;
    const std::vector<detail::TrianglePair> pairs = cubeTetrahedronPairs();
    const detail::CrossingRepair repair = detail::separateCrossings(s, pairs, kMaxMove);
    EXPECT_GE(repair.pairsLeft, 3u);  // the three sides through the top face, at least
    EXPECT_LE(largestMove(start, s), kMaxMove);
    EXPECT_GT(test::countSelfIntersections(meshOf(s), 100), 0u);
}

// Vertices marked fixed stay where they are, even where moving them would separate a pair.
TEST(CrossingRepair, FixedVerticesStay) {
    const float ulp = std::nextafter(1.0f, 2.0f) - 1.0f;
    const detail::CrossingSurface start = cubeAndTetrahedron(1.0f - 3.0f * ulp);
    detail::CrossingSurface s = start;
    s.fixed.assign(s.points.size(), 1);
    const std::vector<detail::TrianglePair> pairs = cubeTetrahedronPairs();
    const detail::CrossingRepair repair = detail::separateCrossings(s, pairs, kMaxMove);
    EXPECT_EQ(repair.movedVertices, 0u);
    EXPECT_GT(repair.pairsLeft, 0u);
    EXPECT_EQ(largestMove(start, s), 0.0);
}

// Two neighbouring triangles of one sheet that share corner 0: A flat in z = 0, B upright
// through (0.3, 0.3) with its lower corner `depth` float steps below A's plane, so B's far edge
// runs through A beside the corner they share, as rounding the cut leaves a few such folds on
// the dense plants (docs/welded.md, Solid union, session 35).
detail::CrossingSurface neighboursFoldedBy(float depth) {
    const float ulp = std::nextafter(0.0625f, 1.0f) - 0.0625f;  // at |z| < 0.0625
    detail::CrossingSurface s;
    s.points = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0), Vec3f(0.3f, 0.3f, 0.5f),
                Vec3f(0.3f, 0.3f, -depth * ulp)};
    s.triangles = {{0, 1, 2}, {0, 3, 4}};
    return s;
}

// Whether B's far edge meets A or A's far edge meets B (exact): the fold.
bool neighboursFold(const detail::CrossingSurface& s) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    auto p = [&](std::uint32_t v) {
        return K::Point_3(s.points[v].x(), s.points[v].y(), s.points[v].z());
    };
    return CGAL::do_intersect(K::Triangle_3(p(0), p(1), p(2)), K::Segment_3(p(3), p(4))) ||
           CGAL::do_intersect(K::Triangle_3(p(0), p(3), p(4)), K::Segment_3(p(1), p(2)));
}

// Neighbours that fold through each other by a few float steps count as a crossing pair and
// are parted by a few float steps (since session 36; before, the repair passed over every pair
// that shares a position and left such folds to a new union).
TEST(CrossingRepair, NeighboursFoldedByFloatStepsAreParted) {
    for (const float depth : {1.0f, 3.0f, 8.0f}) {
        SCOPED_TRACE(depth);
        const detail::CrossingSurface start = neighboursFoldedBy(depth);
        ASSERT_TRUE(neighboursFold(start));
        detail::CrossingSurface s = start;
        const std::vector<detail::TrianglePair> pairs = {{0, 1}};
        const detail::CrossingRepair repair = detail::separateCrossings(s, pairs, kMaxMove);
        EXPECT_EQ(repair.pairsLeft, 0u);
        EXPECT_GE(repair.movedVertices, 1u);
        EXPECT_FALSE(neighboursFold(s));
        EXPECT_LE(largestMove(start, s), 64.0 * (std::nextafter(1.0f, 2.0f) - 1.0f));
    }
}

// The unit cube of cubeAndTetrahedron (and its far tetrahedron) and a second unit cube
// [1, 2] x [1, 2] x [0, 1] with its own corners, from index `base` on: the cubes share an edge
// exactly, a pinched edge as rounding leaves where two sheets touch. Corners base + 0 (1, 1, 0)
// and base + 4 (1, 1, 1) of the second cube are at corners 3 and 7 of the first.
detail::CrossingSurface cubesPinchedAlongAnEdge(std::uint32_t* base) {
    detail::CrossingSurface s = cubeAndTetrahedron(3.0f);  // the tetrahedron far away
    *base = static_cast<std::uint32_t>(s.points.size());
    for (int i = 0; i < 8; ++i) {
        s.points.emplace_back(static_cast<float>(1 + (i & 1)),
                              static_cast<float>(1 + ((i >> 1) & 1)),
                              static_cast<float>((i >> 2) & 1));
    }
    for (std::size_t t = 0; t < 12; ++t) {
        const auto& c = s.triangles[t];
        s.triangles.push_back({*base + c[0], *base + c[1], *base + c[2]});
    }
    return s;
}

// After unpinchVertices on cubesPinchedAlongAnEdge: the `moved` corners went a few float steps
// into their own cube (towards `inside`, per axis +1 or −1), every other vertex stayed, and
// nothing crosses.
void expectPartedInto(const detail::CrossingSurface& start, const detail::CrossingSurface& s,
                      const std::vector<std::uint32_t>& moved, const Vec3f& inside) {
    const float ulp = std::nextafter(1.0f, 2.0f) - 1.0f;
    for (std::uint32_t v = 0; v < s.points.size(); ++v) {
        SCOPED_TRACE(v);
        if (std::find(moved.begin(), moved.end(), v) == moved.end()) {
            EXPECT_EQ(s.points[v], start.points[v]);
            continue;
        }
        EXPECT_NE(s.points[v], start.points[v]);
        EXPECT_LE((s.points[v] - start.points[v]).cast<double>().norm(), 8.0 * ulp);
        EXPECT_GT((s.points[v].x() - start.points[v].x()) * inside.x(), 0.0f);
        EXPECT_GT((s.points[v].y() - start.points[v].y()) * inside.y(), 0.0f);
    }
    EXPECT_EQ(test::countSelfIntersections(meshOf(s), 100), 0u);
    EXPECT_TRUE(test::analyzeTopology(meshOf(s)).closedOriented);
}

// The second cube's two corners on the shared edge move a few float steps into their own cube,
// so the cubes no longer share a position; nothing crosses.
TEST(CrossingRepair, PinchedCornersMoveIntoTheirOwnSolid) {
    std::uint32_t base = 0;
    const detail::CrossingSurface start = cubesPinchedAlongAnEdge(&base);
    const std::vector<std::uint32_t> pinched = {base + 0, base + 4};
    ASSERT_EQ(start.points[base + 0], start.points[3]);
    detail::CrossingSurface s = start;
    const detail::CrossingRepair repair = detail::unpinchVertices(s, pinched, kMaxMove);
    EXPECT_EQ(repair.movedVertices, 2u);
    expectPartedInto(start, s, pinched, Vec3f(1, 1, 0));
}

// With both sheets' corners listed, the first listed that can move do, and their partners, no
// longer sharing a position, stay: the second cube's corners where they may move, the first
// cube's where the second's are fixed (session 28: a pinched edge of ABOP 1.24b whose preferred
// corner was shared with a third surface vertex).
TEST(CrossingRepair, PinchedEdgesPartByTheOtherSheetWhereTheFirstCannotMove) {
    std::uint32_t base = 0;
    const detail::CrossingSurface start = cubesPinchedAlongAnEdge(&base);
    const std::vector<std::uint32_t> both = {base + 0, base + 4, 3, 7};
    {
        detail::CrossingSurface s = start;
        EXPECT_EQ(detail::unpinchVertices(s, both, kMaxMove).movedVertices, 2u);
        expectPartedInto(start, s, {base + 0, base + 4}, Vec3f(1, 1, 0));
    }
    detail::CrossingSurface s = start;
    s.fixed.assign(s.points.size(), 0);
    s.fixed[base + 0] = s.fixed[base + 4] = 1;
    EXPECT_EQ(detail::unpinchVertices(s, both, kMaxMove).movedVertices, 2u);
    s.fixed.clear();
    expectPartedInto(start, s, {3, 7}, Vec3f(-1, -1, 0));
}

// `planks` thin planks (2 × 0.2 × 0.02, 12 triangles each) turned about z by 180° / planks
// from one another, all through the origin: every plank crosses every other, and a corner near
// the middle has most of the surface within reach. The crossings are real, so no move separates
// them and the repair would try every move of every corner of every pair.
detail::CrossingSurface starOfPlanks(int planks) {
    Mesh mesh;
    for (int p = 0; p < planks; ++p) {
        const auto first = mesh.positions.size();
        const double lift = 0.001 * p;
        test::appendBox(mesh, Vec3(-1.0, -0.1, lift - 0.01), Vec3(1.0, 0.1, lift + 0.01));
        const double angle = 3.14159265358979 * p / planks;
        const double c = std::cos(angle), sn = std::sin(angle);
        for (std::size_t v = first; v < mesh.positions.size(); ++v) {
            const Vec3 q = mesh.positions[v].cast<double>();
            mesh.positions[v] =
                Vec3(c * q.x() - sn * q.y(), sn * q.x() + c * q.y(), q.z()).cast<float>();
        }
    }
    detail::CrossingSurface s;
    s.points = mesh.positions;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        s.triangles.push_back(
            {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
    }
    return s;
}

// Every pair of triangles of different planks (the repair works on the ones that cross).
std::vector<detail::TrianglePair> pairsOfPlanks(const detail::CrossingSurface& s) {
    std::vector<detail::TrianglePair> pairs;
    const auto triangles = static_cast<std::uint32_t>(s.triangles.size());
    for (std::uint32_t f = 0; f < triangles; ++f) {
        for (std::uint32_t g = f - f % 12 + 12; g < triangles; ++g) pairs.emplace_back(f, g);
    }
    return pairs;
}

// The repair counts the pairs of a moving corner's triangle and a triangle near it that it
// looks at, and stops moving corners past its work limit (session 45: session 43's pinched
// junctions had run for minutes); it then leaves the pairs it has not separated and has moved
// nothing farther than allowed. The same inputs stop at the same point. Below the limit, as on
// every shipped example, nothing changes.
TEST(CrossingRepair, StopsMovingCornersPastItsWorkLimit) {
    EXPECT_EQ(detail::crossingRepairWorkLimit(1000),
              detail::kCrossingRepairWorkFloor +
                  1000 * std::uint64_t{detail::kCrossingRepairWorkPerTriangle});
    const detail::CrossingSurface start = starOfPlanks(24);
    ASSERT_GT(test::countSelfIntersections(meshOf(start), 100000), 1000u);
    const std::vector<detail::TrianglePair> pairs = pairsOfPlanks(start);
    const std::uint64_t limit = 2'000'000;
    detail::CrossingSurface s = start;
    const detail::CrossingRepair repair = detail::separateCrossings(s, pairs, kMaxMove, limit);
    EXPECT_TRUE(repair.overWorkLimit);
    EXPECT_GT(repair.work, limit);
    EXPECT_LT(repair.work, 2 * limit);  // it stops within one corner's moves past the limit
    EXPECT_GT(repair.pairsLeft, 1000u);
    EXPECT_LE(largestMove(start, s), kMaxMove);
    detail::CrossingSurface again = start;
    const detail::CrossingRepair repeated =
        detail::separateCrossings(again, pairs, kMaxMove, limit);
    EXPECT_EQ(repeated.work, repair.work);
    EXPECT_EQ(repeated.movedVertices, repair.movedVertices);
    EXPECT_EQ(again.points, s.points);

    // A grazing crossing is repaired far below any limit.
    const float ulp = std::nextafter(1.0f, 2.0f) - 1.0f;
    detail::CrossingSurface graze = cubeAndTetrahedron(1.0f - 3.0f * ulp);
    const detail::CrossingRepair small =
        detail::separateCrossings(graze, cubeTetrahedronPairs(), kMaxMove);
    EXPECT_FALSE(small.overWorkLimit);
    EXPECT_EQ(small.pairsLeft, 0u);
    EXPECT_GT(small.work, 0u);
    EXPECT_LT(small.work, 10'000u);
}

}  // namespace
}  // namespace ramus
