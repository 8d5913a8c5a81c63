// The constrained Delaunay triangulation of a triangle's points (src/mesh/
// constrained_triangulation.hpp), on integer points with exact predicates: the faces must tile
// the triangle, meet edge to edge, carry every constraint as a chain of constrained edges through
// the points on it, and be locally Delaunay across every edge that is not constrained (which
// makes the triangulation constrained Delaunay).
#include "mesh/constrained_triangulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus {
namespace {

using detail::ConstrainedTriangulation;
using detail::TriangulationFailure;
using Constraint = std::pair<std::uint32_t, std::uint32_t>;

struct IntegerPoint {
    std::int64_t x, y;
};

int signOf(__int128 v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

// Exact predicates on small integer coordinates.
struct IntegerPredicates {
    std::vector<IntegerPoint> points;

    int orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
        const IntegerPoint &p = points[a], &q = points[b], &r = points[c];
        return signOf(__int128{q.x - p.x} * (r.y - p.y) - __int128{q.y - p.y} * (r.x - p.x));
    }
    int inCircle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
        const IntegerPoint& s = points[d];
        auto row = [&](std::uint32_t i) {
            const __int128 x = points[i].x - s.x, y = points[i].y - s.y;
            return std::array<__int128, 3>{x, y, x * x + y * y};
        };
        const auto p = row(a), q = row(b), r = row(c);
        return signOf(p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                      p[2] * (q[0] * r[1] - q[1] * r[0]));
    }
    // Whether m lies on the segment a–b, strictly between its ends.
    bool between(std::uint32_t a, std::uint32_t b, std::uint32_t m) const {
        if (orientation(a, b, m) != 0 || m == a || m == b) return false;
        const IntegerPoint &p = points[a], &q = points[b], &r = points[m];
        const std::int64_t along = (r.x - p.x) * (q.x - p.x) + (r.y - p.y) * (q.y - p.y);
        const std::int64_t length = (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
        return along > 0 && along < length;
    }
    std::int64_t twiceArea(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
        const IntegerPoint &p = points[a], &q = points[b], &r = points[c];
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    }
};

void expectConstrainedDelaunay(const IntegerPredicates& predicates,
                               const std::vector<Constraint>& constraints,
                               const ConstrainedTriangulation& triangulation) {
    const auto& faces = triangulation.faces();
    const auto count = static_cast<std::uint32_t>(predicates.points.size());
    constexpr auto kNoFace = ConstrainedTriangulation::kNoFace;
    std::int64_t area = 0;
    std::set<std::uint32_t> used;
    std::set<Constraint> constrainedEdges;
    std::uint32_t onSides = 0;  // points on the triangle's sides, corners included
    for (std::uint32_t p = 0; p < count; ++p) {
        onSides += p < 3 || predicates.orientation(0, 1, p) == 0 ||
                   predicates.orientation(1, 2, p) == 0 || predicates.orientation(2, 0, p) == 0;
    }
    for (std::uint32_t f = 0; f < faces.size(); ++f) {
        const auto& face = faces[f];
        ASSERT_GT(predicates.orientation(face.v[0], face.v[1], face.v[2]), 0) << "face " << f;
        area += predicates.twiceArea(face.v[0], face.v[1], face.v[2]);
        for (std::uint32_t i = 0; i < 3; ++i) {
            used.insert(face.v[i]);
            const std::uint32_t a = face.v[(i + 1) % 3], b = face.v[(i + 2) % 3];
            if (face.constrained[i]) constrainedEdges.insert(std::minmax(a, b));
            const std::uint32_t g = face.neighbor[i];
            if (g == kNoFace) {
                // On a side of the triangle.
                EXPECT_TRUE(
                    predicates.orientation(0, 1, a) == 0 && predicates.orientation(0, 1, b) == 0 ||
                    predicates.orientation(1, 2, a) == 0 && predicates.orientation(1, 2, b) == 0 ||
                    predicates.orientation(2, 0, a) == 0 && predicates.orientation(2, 0, b) == 0)
                    << "edge " << a << "–" << b << " without a face across";
                continue;
            }
            ASSERT_LT(g, faces.size());
            const auto& across = faces[g];
            std::uint32_t j = 0;
            while (j < 3 && !(across.v[(j + 1) % 3] == b && across.v[(j + 2) % 3] == a)) ++j;
            ASSERT_LT(j, 3u) << "face " << g << " does not have edge " << b << "–" << a;
            EXPECT_EQ(across.neighbor[j], f);
            EXPECT_EQ(across.constrained[j], face.constrained[i]);
            if (!face.constrained[i]) {
                EXPECT_LE(predicates.inCircle(face.v[0], face.v[1], face.v[2], across.v[j]), 0)
                    << "edge " << a << "–" << b << " is not locally Delaunay";
            }
        }
    }
    EXPECT_EQ(area, std::abs(predicates.twiceArea(0, 1, 2)));
    EXPECT_EQ(used.size(), count);
    EXPECT_EQ(faces.size(), 2 * count - onSides - 2);  // Euler, with onSides points on the hull
    // Each constraint: the chain of edges through the points on it, all constrained; and no other
    // edge constrained.
    std::set<Constraint> expected;
    for (const auto& [a, b] : constraints) {
        std::vector<std::uint32_t> chain{a, b};
        for (std::uint32_t m = 0; m < count; ++m) {
            if (predicates.between(a, b, m)) chain.push_back(m);
        }
        const IntegerPoint from = predicates.points[a];
        std::sort(chain.begin(), chain.end(), [&](std::uint32_t p, std::uint32_t q) {
            auto distance = [&](std::uint32_t i) {
                const IntegerPoint& r = predicates.points[i];
                return (r.x - from.x) * (r.x - from.x) + (r.y - from.y) * (r.y - from.y);
            };
            return distance(p) < distance(q);
        });
        for (std::size_t k = 0; k + 1 < chain.size(); ++k)
            expected.insert(std::minmax(chain[k], chain[k + 1]));
    }
    EXPECT_EQ(constrainedEdges, expected);
}

// The triangle (0, 0), (1024, 0), (0, 1024) (turned clockwise where `clockwise`), whose sides
// have many integer points.
IntegerPredicates cornerTriangle(bool clockwise = false) {
    IntegerPredicates p;
    p.points = {{0, 0}, {1024, 0}, {0, 1024}};
    if (clockwise) std::swap(p.points[1], p.points[2]);
    return p;
}

ConstrainedTriangulation triangulated(const IntegerPredicates& p,
                                      const std::vector<Constraint>& constraints) {
    ConstrainedTriangulation t;
    t.triangulate(p, static_cast<std::uint32_t>(p.points.size()), constraints);
    return t;
}

TEST(ConstrainedTriangulation, TheTriangleAloneIsOneFace) {
    for (const bool clockwise : {false, true}) {
        const IntegerPredicates p = cornerTriangle(clockwise);
        const ConstrainedTriangulation t = triangulated(p, {});
        ASSERT_EQ(t.faces().size(), 1u);
        expectConstrainedDelaunay(p, {}, t);
    }
}

TEST(ConstrainedTriangulation, PointsInsideAndOnTheSides) {
    IntegerPredicates p = cornerTriangle();
    // Inside, on each side, and on an inner edge made by earlier points (300, 300)–(0, 0).
    p.points.insert(
        p.points.end(),
        {{300, 300}, {512, 0}, {0, 200}, {512, 512}, {100, 100}, {200, 200}, {700, 100}});
    const ConstrainedTriangulation t = triangulated(p, {});
    expectConstrainedDelaunay(p, {}, t);
    EXPECT_EQ(t.faces().size(), 2 * 10 - 6 - 2u);  // 6 points on the sides
}

TEST(ConstrainedTriangulation, AConstraintThatNeedsNewFacesIsAnEdge) {
    IntegerPredicates p = cornerTriangle();
    // A long thin constraint from near the right-angle corner to the hypotenuse, across a fan of
    // points that the Delaunay faces join across it.
    p.points.insert(p.points.end(), {{10, 20},
                                     {900, 124},
                                     {300, 40},
                                     {320, 120},
                                     {500, 80},
                                     {520, 140},
                                     {700, 100},
                                     {720, 170}});
    const std::vector<Constraint> constraints{{3, 4}};
    const ConstrainedTriangulation unconstrained = triangulated(p, {});
    bool present = false;
    for (const auto& f : unconstrained.faces()) {
        for (int i = 0; i < 3; ++i) {
            present = present || std::minmax(f.v[(i + 1) % 3], f.v[(i + 2) % 3]) ==
                                     std::minmax(std::uint32_t{3}, std::uint32_t{4});
        }
    }
    ASSERT_FALSE(present) << "the test needs a constraint the Delaunay triangulation lacks";
    expectConstrainedDelaunay(p, constraints, triangulated(p, constraints));
}

TEST(ConstrainedTriangulation, AConstraintThroughPointsIsSplitThere) {
    IntegerPredicates p = cornerTriangle();
    // (100, 100), (200, 200), (300, 300) on the constraint (50, 50)–(400, 400); others around.
    p.points.insert(p.points.end(), {{50, 50},
                                     {400, 400},
                                     {200, 200},
                                     {100, 100},
                                     {300, 300},
                                     {250, 100},
                                     {100, 260},
                                     {380, 150}});
    const std::vector<Constraint> constraints{{3, 4}, {8, 10}, {10, 7}};
    expectConstrainedDelaunay(p, constraints, triangulated(p, constraints));
}

TEST(ConstrainedTriangulation, ConstraintsThatShareEnds) {
    IntegerPredicates p = cornerTriangle(true);
    p.points.insert(p.points.end(), {{400, 300}, {100, 50}, {50, 700}, {700, 300}, {200, 200}});
    const std::vector<Constraint> constraints{{3, 4}, {3, 5}, {3, 6}, {3, 1}, {4, 5}, {6, 2}};
    expectConstrainedDelaunay(p, constraints, triangulated(p, constraints));
}

TEST(ConstrainedTriangulation, BadInputIsRefused) {
    IntegerPredicates crossing = cornerTriangle();
    crossing.points.insert(crossing.points.end(), {{100, 100}, {400, 400}, {100, 400}, {400, 100}});
    EXPECT_THROW(triangulated(crossing, {{3, 4}, {5, 6}}), TriangulationFailure);
    IntegerPredicates twice = cornerTriangle();
    twice.points.insert(twice.points.end(), {{100, 100}, {200, 50}, {100, 100}});
    EXPECT_THROW(triangulated(twice, {}), TriangulationFailure);
    IntegerPredicates outside = cornerTriangle();
    outside.points.insert(outside.points.end(), {{100, 100}, {800, 800}});
    EXPECT_THROW(triangulated(outside, {}), TriangulationFailure);
    IntegerPredicates flat;
    flat.points = {{0, 0}, {10, 10}, {20, 20}};
    EXPECT_THROW(triangulated(flat, {}), TriangulationFailure);
}

// Random points (a third on the triangle's sides, on a coarse grid so that many lie on one line
// or one circle) and random constraints that do not cross.
TEST(ConstrainedTriangulation, RandomPointsAndConstraints) {
    Rng rng(39);
    auto pick = [&](std::int64_t lo, std::int64_t hi) {  // in [lo, hi]
        return lo +
               static_cast<std::int64_t>(rng.uniformInt(static_cast<std::uint32_t>(hi - lo + 1)));
    };
    for (int round = 0; round < 300; ++round) {
        IntegerPredicates p = cornerTriangle(round % 2 == 1);
        const int count = static_cast<int>(pick(3, 63));
        std::set<std::pair<std::int64_t, std::int64_t>> taken{{0, 0}, {1024, 0}, {0, 1024}};
        while (static_cast<int>(p.points.size()) < count) {
            const std::int64_t grid = round % 3 == 0 ? 64 : 1;
            std::int64_t x = grid * pick(0, 1024 / grid);
            std::int64_t y = grid * pick(0, 1024 / grid);
            const auto side = pick(0, 5);
            if (side == 0) y = 0;
            if (side == 1) x = 0;
            if (side == 2) y = 1024 - x;
            if (x + y > 1024 || !taken.insert({x, y}).second) continue;
            p.points.push_back({x, y});
        }
        std::vector<Constraint> constraints;
        const auto n = static_cast<std::int64_t>(p.points.size());
        for (int tries = 0; tries < 20 && n > 3; ++tries) {
            const auto a = static_cast<std::uint32_t>(pick(0, n - 1));
            const auto b = static_cast<std::uint32_t>(pick(0, n - 1));
            if (a == b) continue;
            const bool crosses =
                std::any_of(constraints.begin(), constraints.end(), [&](const Constraint& c) {
                    return p.orientation(a, b, c.first) * p.orientation(a, b, c.second) < 0 &&
                           p.orientation(c.first, c.second, a) *
                                   p.orientation(c.first, c.second, b) <
                               0;
                });
            if (!crosses) constraints.emplace_back(a, b);
        }
        SCOPED_TRACE("round " + std::to_string(round));
        expectConstrainedDelaunay(p, constraints, triangulated(p, constraints));
        if (HasFatalFailure()) return;
    }
}

}  // namespace
}  // namespace ramus
