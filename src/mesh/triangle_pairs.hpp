// Exact tests of pairs of triangles of closed surfaces, shared by the solid union
// (src/mesh/solid_union.cpp: what to cut, what its result still has crossing) and its crossing
// repair (src/mesh/crossing_repair.cpp: which moves mend that), so that both count the same
// pairs. Internal to src/mesh; needs CGAL.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace ramus::detail {

using PairKernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// The plane through three points p, q, r, for CGAL::orientation(p, q, r, x) of many points x
/// (strictlyOnOneSide): the cross product of q − p and r − p is computed once, and each x takes
/// a dot product whose error is bounded per term. Where the bound leaves the sign open (x within
/// rounding of the plane, corners on a line, tiny or huge coordinates) CGAL's exact predicate
/// decides, so the answer is always CGAL's. CGAL's own filter recomputes the differences of
/// p, q, r for every x; the searches of the solid union test most pairs of neighbouring
/// triangles this way (tree_3d: 1.46 M of 1.76 M pairs share a corner), where that had been a
/// fifth of their time.
class PlaneSide {
public:
    using Point = PairKernel::Point_3;

    PlaneSide(const Point& p, const Point& q, const Point& r) : p_(p), q_(q), r_(r) {
        const double ax = q.x() - p.x(), ay = q.y() - p.y(), az = q.z() - p.z();
        const double bx = r.x() - p.x(), by = r.y() - p.y(), bz = r.z() - p.z();
        normal_ = {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
        size_ = {std::abs(ay * bz) + std::abs(az * by), std::abs(az * bx) + std::abs(ax * bz),
                 std::abs(ax * by) + std::abs(ay * bx)};
    }

    /// CGAL::orientation(p, q, r, x).
    CGAL::Orientation orientation(const Point& x) const {
        const double dx = x.x() - p_.x(), dy = x.y() - p_.y(), dz = x.z() - p_.z();
        const double det = normal_[0] * dx + normal_[1] * dy + normal_[2] * dz;
        // |computed − exact| ≤ 8 u Σ size_i |d_i| to first order (u = 2^-53: each difference
        // and product rounds once, each normal component carries 4 u of its size, the sum 2 u);
        // kBound is 45 times that u and leaves room for the higher orders and the rounding of
        // the bound itself.
        const double bound =
            kBound * (size_[0] * std::abs(dx) + size_[1] * std::abs(dy) + size_[2] * std::abs(dz));
        if (bound > kSmallest && bound < kLargest) {
            if (det > bound) return CGAL::POSITIVE;
            if (det < -bound) return CGAL::NEGATIVE;
        }
        return CGAL::orientation(p_, q_, r_, x);
    }

private:
    static constexpr double kBound = 5e-15;
    // Outside these the products may have lost precision to underflow or overflowed.
    static constexpr double kSmallest = 1e-250;
    static constexpr double kLargest = 1e250;

    const Point& p_;
    const Point& q_;
    const Point& r_;
    std::array<double, 3> normal_{};
    std::array<double, 3> size_{};
};

/// Whether the points `others` all lie strictly on one side of the plane through p, q, r
/// (exact; never where those are on a line).
inline bool strictlyOnOneSide(const PairKernel::Point_3& p, const PairKernel::Point_3& q,
                              const PairKernel::Point_3& r,
                              std::initializer_list<const PairKernel::Point_3*> others) {
    const PlaneSide plane(p, q, r);
    CGAL::Orientation first = CGAL::COPLANAR;
    for (const PairKernel::Point_3* x : others) {
        const CGAL::Orientation o = plane.orientation(*x);
        if (o == CGAL::COPLANAR || (first != CGAL::COPLANAR && o != first)) return false;
        first = o;
    }
    return true;
}

/// Whether the triangles with corners `a` and `b` (vertex ids; pointOf(id) gives a corner's
/// Point_3) intersect other than in the corners or the edge they share (the same ids): as CGAL's
/// self-intersection test (do_faces_intersect in Polygon_mesh_processing/self_intersections.h),
/// triangles that share an edge intersect where they fold onto each other (coplanar, on one
/// side of it), triangles that share one corner where the edge opposite it in one meets the
/// other. With `skipDegenerate`, a pair with a degenerate triangle (corners on a line) does not
/// intersect: that is tested only where the pair could (CGAL's collinearity test has no static
/// filter and cost more than the rest where most pairs are apart), and before CGAL's
/// intersection tests, which do not take degenerate triangles.
template <class PointOf>
bool trianglesIntersect(const PointOf& pointOf, const std::uint32_t* a, const std::uint32_t* b,
                        bool skipDegenerate = false) {
    using Point = PairKernel::Point_3;
    using Triangle = PairKernel::Triangle_3;
    int shared = 0, sharedInA = 0, sharedInB = 0;
    std::array<bool, 3> aShares{}, bShares{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (a[i] != b[j]) continue;
            ++shared;
            aShares[static_cast<std::size_t>(i)] = bShares[static_cast<std::size_t>(j)] = true;
            sharedInA = i;
            sharedInB = j;
        }
    }
    const std::array<Point, 3> pa{pointOf(a[0]), pointOf(a[1]), pointOf(a[2])};
    const std::array<Point, 3> pb{pointOf(b[0]), pointOf(b[1]), pointOf(b[2])};
    auto degenerate = [&] {
        return skipDegenerate &&
               (CGAL::collinear(pa[0], pa[1], pa[2]) || CGAL::collinear(pb[0], pb[1], pb[2]));
    };
    if (shared == 3) return !degenerate();  // two triangles on the same corners lie on each other
    auto at = [](const std::array<Point, 3>& t, int k) -> const Point& {
        return t[static_cast<std::size_t>(k % 3)];
    };
    if (shared == 2) {
        auto unshared = [](const std::array<bool, 3>& shares) {
            return static_cast<int>(std::find(shares.begin(), shares.end(), false) -
                                    shares.begin());
        };
        const int ra = unshared(aShares), rb = unshared(bShares);
        const Point& p = at(pa, ra + 1);
        const Point& q = at(pa, ra + 2);
        // (degenerate() before coplanar_orientation, whose precondition is that p, q and a's
        // third corner make a triangle: CGAL's assertion aborted there, fuzz_union, session 44.)
        return PlaneSide(p, q, at(pa, ra)).orientation(at(pb, rb)) == CGAL::COPLANAR &&
               !degenerate() &&
               CGAL::coplanar_orientation(p, q, at(pa, ra), at(pb, rb)) == CGAL::POSITIVE;
    }
    // Where the corners of one triangle that it does not share lie strictly on one side of the
    // other's plane, the two do not meet beyond what they share: most neighbouring pairs are
    // told apart so before CGAL's tests build their objects (tree_3d: 1.46 M of the 1.76 M
    // pairs of overlapping boxes share a corner or an edge).
    auto oneSide = [](const std::array<Point, 3>& t, std::initializer_list<const Point*> others) {
        return strictlyOnOneSide(t[0], t[1], t[2], others);
    };
    if (shared == 1) {  // apart where either's far edge misses the other's plane
        const Point &b1 = at(pb, sharedInB + 1), &b2 = at(pb, sharedInB + 2);
        const Point &a1 = at(pa, sharedInA + 1), &a2 = at(pa, sharedInA + 2);
        if (oneSide(pa, {&b1, &b2}) || oneSide(pb, {&a1, &a2}) || degenerate()) return false;
        const Triangle ta(pa[0], pa[1], pa[2]);
        const Triangle tb(pb[0], pb[1], pb[2]);
        return CGAL::do_intersect(ta, PairKernel::Segment_3(b1, b2)) ||
               CGAL::do_intersect(tb, PairKernel::Segment_3(a1, a2));
    }
    if (oneSide(pa, {&pb[0], &pb[1], &pb[2]}) || oneSide(pb, {&pa[0], &pa[1], &pa[2]}) ||
        degenerate()) {
        return false;
    }
    return CGAL::do_intersect(Triangle(pa[0], pa[1], pa[2]), Triangle(pb[0], pb[1], pb[2]));
}

/// Whether two triangles of the union's result cross, as the union counts its defects
/// (SolidUnionReport::remainingIntersections): corners `a` and `b` are surface vertices
/// (pointOf(id): the corner's Point_3), samePosition(i, j) whether corner i of a lies where
/// corner j of b does. Triangles that share no position cross where they intersect; neighbours
/// on one sheet (every position they share is a surface vertex of both) where they fold
/// through each other beside what they share (trianglesIntersect: rounding the cut leaves a
/// few); triangles that share a position through different surface vertices (touching points,
/// pinched edges, counted apart) do not. Degenerate triangles (corners on a line) are not
/// tested, as in CGAL's self-intersection test, which reports them alone.
template <class PointOf, class SamePosition>
bool trianglesCross(const PointOf& pointOf, const std::uint32_t* a, const std::uint32_t* b,
                    const SamePosition& samePosition) {
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (samePosition(i, j) && a[i] != b[j]) return false;  // another sheet's vertex there
        }
    }
    // Triangles that share no position share no surface vertex: trianglesIntersect tests them
    // whole.
    return trianglesIntersect(pointOf, a, b, true);
}

}  // namespace ramus::detail
