// The exact triangle tests shared by the solid union and its crossing repair
// (src/mesh/triangle_pairs.hpp): the filtered plane side agrees with CGAL's exact orientation,
// above all where points lie on or within rounding of the plane, which is where a filter errs.
#include "mesh/triangle_pairs.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus {
namespace {

using Point = detail::PairKernel::Point_3;

// A float coordinate of magnitude up to `scale` (the union's points are floats held as doubles).
double floatCoordinate(Rng& rng, double scale) {
    return static_cast<double>(static_cast<float>(rng.uniform(-scale, scale)));
}

Point floatPoint(Rng& rng, double scale) {
    return {floatCoordinate(rng, scale), floatCoordinate(rng, scale), floatCoordinate(rng, scale)};
}

// p + a (q − p) + b (r − p) rounded to floats, moved by `offset` float steps along each axis:
// on the plane up to rounding (offset 0), or just off it.
Point nearPlane(const Point& p, const Point& q, const Point& r, double a, double b, int offset) {
    std::array<double, 3> c{};
    for (int d = 0; d < 3; ++d) {
        const double x = p[d] + a * (q[d] - p[d]) + b * (r[d] - p[d]);
        float f = static_cast<float>(x);
        for (int k = 0; k < std::abs(offset); ++k) {
            f = std::nextafter(f, offset > 0 ? HUGE_VALF : -HUGE_VALF);
        }
        c[static_cast<std::size_t>(d)] = f;
    }
    return {c[0], c[1], c[2]};
}

TEST(PlaneSide, AgreesWithCgalsExactOrientationOnAndNearThePlane) {
    Rng rng(20261207);
    std::size_t coplanar = 0, decided = 0;  // points tested, exactly on their plane
    for (int trial = 0; trial < 20000; ++trial) {
        // Scales from a twig's millimetres to a large scene, some triangles slivers.
        const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
        const Point p = floatPoint(rng, scale);
        Point q = floatPoint(rng, scale);
        const Point r = trial % 5 == 0 ? nearPlane(p, q, q, rng.uniform(0.0, 2.0), 0.0, 0)
                                       : floatPoint(rng, scale);
        if (trial % 7 == 0) q = nearPlane(p, r, r, rng.uniform(-1.0, 1.0), 0.0, 1);
        const detail::PlaneSide plane(p, q, r);
        for (int k = 0; k < 8; ++k) {
            const Point x = k == 0
                                ? floatPoint(rng, scale)
                                : nearPlane(p, q, r, rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0),
                                            static_cast<int>(rng.uniformInt(5)) - 2);
            const CGAL::Orientation exact = CGAL::orientation(p, q, r, x);
            ASSERT_EQ(plane.orientation(x), exact)
                << "trial " << trial << " point " << k << " scale " << scale;
            coplanar += exact == CGAL::COPLANAR;
            decided += 1;
        }
    }
    EXPECT_EQ(decided, 160000u);
    // On a grid, a plane's points are exactly on it or a float step away.
    for (int trial = 0; trial < 20000; ++trial) {
        const double unit = std::ldexp(1.0, static_cast<int>(rng.uniformInt(40)) - 20);
        auto gridPoint = [&] {
            auto c = [&] { return unit * (static_cast<double>(rng.uniformInt(2001)) - 1000.0); };
            return Point(c(), c(), c());
        };
        const Point p = gridPoint(), q = gridPoint(), r = gridPoint();
        const detail::PlaneSide plane(p, q, r);
        for (int k = 0; k < 8; ++k) {
            const double i = static_cast<double>(rng.uniformInt(7)) - 3.0;
            const double j = static_cast<double>(rng.uniformInt(7)) - 3.0;
            std::array<double, 3> c{};
            for (int d = 0; d < 3; ++d)
                c[static_cast<std::size_t>(d)] = p[d] + i * (q[d] - p[d]) + j * (r[d] - p[d]);
            if (k % 2 == 1) {  // a float step off, along one axis
                double& x = c[rng.uniformInt(3)];
                x = std::nextafter(static_cast<float>(x), k % 4 == 1 ? HUGE_VALF : -HUGE_VALF);
            }
            const Point x(c[0], c[1], c[2]);
            const CGAL::Orientation exact = CGAL::orientation(p, q, r, x);
            ASSERT_EQ(plane.orientation(x), exact) << "grid trial " << trial << " point " << k;
            coplanar += exact == CGAL::COPLANAR;
        }
    }
    // The cases exercise the exact fallback: many points lie exactly on their plane.
    EXPECT_GT(coplanar, 40000u);
}

TEST(PlaneSide, CornersOnALineLeaveEveryPointCoplanar) {
    const Point p(0, 0, 0), q(1, 1, 1), r(2, 2, 2);
    const detail::PlaneSide plane(p, q, r);
    EXPECT_EQ(plane.orientation(Point(5, -3, 0.25)), CGAL::COPLANAR);
    EXPECT_EQ(plane.orientation(Point(1e-30, 0, 0)), CGAL::COPLANAR);
}

TEST(PlaneSide, TinyAndHugeCoordinatesFallBackToTheExactTest) {
    for (const double scale : {1e-200, 1e-120, 1e120, 1e200}) {
        const Point p(0, 0, 0), q(scale, 0, 0), r(0, scale, 0);
        const detail::PlaneSide plane(p, q, r);
        EXPECT_EQ(plane.orientation(Point(0.3 * scale, 0.2 * scale, scale)), CGAL::POSITIVE);
        EXPECT_EQ(plane.orientation(Point(0.3 * scale, 0.2 * scale, -scale)), CGAL::NEGATIVE);
        EXPECT_EQ(plane.orientation(Point(0.3 * scale, 0.2 * scale, 0)), CGAL::COPLANAR);
    }
}

TEST(StrictlyOnOneSide, NeedsEveryPointOffThePlaneOnTheSameSide) {
    const Point p(0, 0, 0), q(1, 0, 0), r(0, 1, 0);
    const Point above(0.2, 0.2, 1), above2(5, -3, 1e-7), on(0.5, 0.5, 0), below(0, 0, -1);
    EXPECT_TRUE(detail::strictlyOnOneSide(p, q, r, {&above, &above2}));
    EXPECT_TRUE(detail::strictlyOnOneSide(p, q, r, {&below}));
    EXPECT_FALSE(detail::strictlyOnOneSide(p, q, r, {&above, &on}));
    EXPECT_FALSE(detail::strictlyOnOneSide(p, q, r, {&above, &below}));
}

// Two triangles on one edge, one of them degenerate (its third corner on the edge's line): the
// union's check on its result (trianglesCross, which skips degenerate triangles) must not ask
// CGAL for the side of the other across the edge, whose precondition is a triangle (builds
// with CGAL's assertions aborted there: found by fuzz_union, session 44).
TEST(TrianglesIntersect, ADegenerateTriangleOnASharedEdgeIsSkippedBeforeCgalsCoplanarTest) {
    const std::vector<Point> points{{0, 0, 0}, {1, 0, 0},   {2, 0, 0},
                                    {1, 1, 0}, {1, 0.5, 0}, {1, -1, 0}};
    auto pointOf = [&](std::uint32_t v) -> const Point& { return points[v]; };
    const std::uint32_t degenerate[3] = {0, 1, 2};  // on the x axis
    const std::uint32_t beside[3] = {2, 0, 3};      // on its edge 0–2, in the same plane
    EXPECT_FALSE(detail::trianglesIntersect(pointOf, degenerate, beside, true));
    EXPECT_FALSE(detail::trianglesIntersect(pointOf, beside, degenerate, true));
    // Proper triangles on the edge 0–2 in one plane: folded onto each other where both lie on
    // one side of it, apart where on either side.
    const std::uint32_t upper[3] = {0, 2, 3}, folded[3] = {2, 0, 4}, lower[3] = {2, 0, 5};
    EXPECT_TRUE(detail::trianglesIntersect(pointOf, upper, folded, true));
    EXPECT_FALSE(detail::trianglesIntersect(pointOf, upper, lower, true));
}

}  // namespace
}  // namespace ramus
