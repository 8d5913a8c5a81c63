// Cutting intersecting triangles along their intersections (triangle_refinement.hpp).
//
// 1. Per intersecting pair: the segment where the two triangles meet, its ends named by how they
//    arise (an edge of one through the inside of the other, or the corner both share), from
//    exact orientation predicates on the input corners.
// 2. Per cut triangle: the segments in it; where two of them cross, the point common to three
//    triangles; then a constrained Delaunay triangulation (ConstrainedTriangulation) of the
//    triangle's corners and all these points, projected on the axis plane where the triangle is
//    largest, with every segment as a constraint. Its predicates decide on interval bounds of
//    the points (interval arithmetic on the input), else on their exact coordinates (CGAL's
//    Epeck, built where first needed), and know which points lie on one line (PlaneTable).
//    Points on the triangle's edges are exactly on them, so the triangulation covers the
//    triangle exactly.
// 3. Vertices: one per named point and sheet (the inside of a triangle, or an edge of its
//    surface), numbered in the order of the cut triangles; coordinates are the exact points
//    rounded to doubles, computed once per vertex from the input alone (deterministic).
#include "triangle_refinement.hpp"

#if RAMUS_WITH_CGAL

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <compare>
#include <exception>
#include <limits>
#include <numeric>
#include <optional>
#include <span>

#include "constrained_triangulation.hpp"
#include "fixed_hash.hpp"
#include "index_hash_table.hpp"
#include "on_cores.hpp"

namespace ramus::detail {
namespace {

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = Exact::Point_3;

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A point where the refinement may need a vertex, named by how it arises, so that every
// triangle that meets it names it alike (no comparison of coordinates).
struct PointId {
    enum Kind : std::uint32_t {
        corner,         // of = {vertex, -, -}
        edgeThrough,    // of = {u, w, triangle}: the edge u–w (u < w) through the triangle
        threeTriangles  // of = three triangles, ascending, whose planes meet there
    };
    Kind kind = corner;
    std::array<std::uint32_t, 3> of{kNone, kNone, kNone};
    auto operator<=>(const PointId&) const = default;
};

// The intersection of a pair of triangles.
struct Segment {
    PointId from, to;
};

// Thrown where the input is not in general position; caught per pair and per triangle.
struct Degenerate {
    const char* why;
};

enum class Passage { none, through, degenerate };

// Whether the segment pq passes through the inside of triangle abc (exact).
Passage passage(const RefinementPoint& p, const RefinementPoint& q, const RefinementPoint& a,
                const RefinementPoint& b, const RefinementPoint& c) {
    const CGAL::Orientation sp = CGAL::orientation(a, b, c, p);
    const CGAL::Orientation sq = CGAL::orientation(a, b, c, q);
    if (sp == CGAL::COPLANAR || sq == CGAL::COPLANAR) return Passage::degenerate;
    if (sp == sq) return Passage::none;
    // The line pq meets the plane inside the triangle iff it turns alike about all three edges.
    const std::array<CGAL::Orientation, 3> turns{CGAL::orientation(p, q, a, b),
                                                 CGAL::orientation(p, q, b, c),
                                                 CGAL::orientation(p, q, c, a)};
    const bool positive = std::find(turns.begin(), turns.end(), CGAL::POSITIVE) != turns.end();
    const bool negative = std::find(turns.begin(), turns.end(), CGAL::NEGATIVE) != turns.end();
    if (positive && negative) return Passage::none;
    if (std::find(turns.begin(), turns.end(), CGAL::COPLANAR) != turns.end()) {
        return Passage::degenerate;  // through an edge or a corner
    }
    return Passage::through;
}

// Rounding upward for the interval arithmetic of one predicate, unless the caller set it for a
// whole triangulation (cutTriangle): switching the FPU's mode twice a predicate (stmxcsr,
// ldmxcsr) had taken most of the orientation test's time.
class UpwardRounding {
public:
    explicit UpwardRounding(bool already) {
        if (!already) protect_.emplace();
    }

private:
    std::optional<CGAL::Protect_FPU_rounding<true>> protect_;
};

class Refiner {
    using Interval = CGAL::Interval_nt<false>;

public:
    Refiner(const std::vector<RefinementPoint>& points, const std::vector<std::uint32_t>& fan)
        : points_(points), fan_(fan) {}

    const std::uint32_t* corners(std::uint32_t t) const { return &fan_[3 * std::size_t{t}]; }
    const RefinementPoint& point(std::uint32_t v) const { return points_[v]; }

    // The segment where triangles s and t meet (they intersect other than in what they share).
    Segment segment(std::uint32_t s, std::uint32_t t) const {
        const std::uint32_t* a = corners(s);
        const std::uint32_t* b = corners(t);
        int shared = 0;
        std::uint32_t common = kNone;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                if (a[i] == b[j]) {
                    ++shared;
                    common = a[i];
                }
            }
        }
        if (shared >= 2) throw Degenerate{"triangles that share an edge overlap"};
        std::array<PointId, 3> ends;
        int found = 0;
        if (shared == 1)
            ends[static_cast<std::size_t>(found++)] =
                PointId{PointId::corner, {common, kNone, kNone}};
        // The edges of one triangle through the other (with a shared corner, only the edge
        // opposite it can pass through: the others meet the other plane at the shared corner).
        auto edgesThrough = [&](const std::uint32_t* edges, const std::uint32_t* triangle,
                                std::uint32_t triangleIndex) {
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t u = edges[i], w = edges[(i + 1) % 3];
                if (u == common || w == common) continue;
                const Passage p = passage(points_[u], points_[w], points_[triangle[0]],
                                          points_[triangle[1]], points_[triangle[2]]);
                if (p == Passage::degenerate)
                    throw Degenerate{"an edge meets a triangle's edge or plane"};
                if (p == Passage::none) continue;
                if (found == 3) throw Degenerate{"more than two ends of an intersection"};
                ends[static_cast<std::size_t>(found++)] =
                    PointId{PointId::edgeThrough, {std::min(u, w), std::max(u, w), triangleIndex}};
            }
        };
        edgesThrough(a, b, t);
        edgesThrough(b, a, s);
        if (found != 2) throw Degenerate{"triangles that touch without crossing"};
        return Segment{ends[0], ends[1]};
    }

    ExactPoint exactCorner(std::uint32_t v) const {
        const RefinementPoint& p = points_[v];
        return ExactPoint(p.x(), p.y(), p.z());
    }

    Exact::Plane_3 exactPlane(std::uint32_t t) const {
        const std::uint32_t* c = corners(t);
        return Exact::Plane_3(exactCorner(c[0]), exactCorner(c[1]), exactCorner(c[2]));
    }

    // The point's exact coordinates (lazily evaluated), built from the input alone.
    ExactPoint exactPoint(const PointId& id) const {
        if (id.kind == PointId::corner) return exactCorner(id.of[0]);
        auto pointOf = [](const auto& intersection) {
            const ExactPoint* p = intersection ? boost::get<ExactPoint>(&*intersection) : nullptr;
            if (p == nullptr) throw Degenerate{"an intersection that is not a point"};
            return *p;
        };
        if (id.kind == PointId::edgeThrough) {
            return pointOf(CGAL::intersection(
                Exact::Line_3(exactCorner(id.of[0]), exactCorner(id.of[1])), exactPlane(id.of[2])));
        }
        return pointOf(
            CGAL::intersection(exactPlane(id.of[0]), exactPlane(id.of[1]), exactPlane(id.of[2])));
    }

    // Bounds of the point's coordinates, in interval arithmetic on the input (no exact
    // numbers are built; where a bound would not be finite, the lazy exact point's), rounding
    // upward (`roundingUp`: the caller has set that already, UpwardRounding).
    std::array<Interval, 3> bounds(const PointId& id, bool roundingUp = false) const {
        const UpwardRounding protect(roundingUp);
        std::array<Interval, 3> out;
        if (id.kind == PointId::corner) {
            out = corner(id.of[0]);
        } else if (id.kind == PointId::edgeThrough) {
            const auto [normal, offset] = plane(id.of[2]);
            const auto u = corner(id.of[0]), w = corner(id.of[1]);
            const Interval at = (offset - dot(normal, u)) / dot(normal, minus(w, u));
            for (int d = 0; d < 3; ++d) out[d] = u[d] + at * (w[d] - u[d]);
        } else {
            const auto [n1, d1] = plane(id.of[0]);
            const auto [n2, d2] = plane(id.of[1]);
            const auto [n3, d3] = plane(id.of[2]);
            const auto c23 = cross(n2, n3), c31 = cross(n3, n1), c12 = cross(n1, n2);
            const Interval det = dot(n1, c23);
            for (int d = 0; d < 3; ++d) out[d] = (d1 * c23[d] + d2 * c31[d] + d3 * c12[d]) / det;
        }
        for (const Interval& x : out) {
            if (!std::isfinite(x.inf()) || !std::isfinite(x.sup())) {
                const auto& a = CGAL::approx(exactPoint(id));
                return {a.x(), a.y(), a.z()};
            }
        }
        return out;
    }

private:
    using Triple = std::array<Interval, 3>;

    Triple corner(std::uint32_t v) const {
        const RefinementPoint& p = points_[v];
        return {Interval(p.x()), Interval(p.y()), Interval(p.z())};
    }
    static Triple minus(const Triple& a, const Triple& b) {
        return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }
    static Triple cross(const Triple& a, const Triple& b) {
        return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    static Interval dot(const Triple& a, const Triple& b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
    // Triangle t's plane: normal · x = offset.
    std::pair<Triple, Interval> plane(std::uint32_t t) const {
        const std::uint32_t* c = corners(t);
        const Triple a = corner(c[0]);
        const Triple normal = cross(minus(corner(c[1]), a), minus(corner(c[2]), a));
        return {normal, dot(normal, a)};
    }

    const std::vector<RefinementPoint>& points_;
    const std::vector<std::uint32_t>& fan_;
};

// One cut triangle's pieces, over local vertices, and its regions (cutTriangle).
struct TriangleCut {
    std::vector<PointId> points;
    std::vector<std::array<std::uint32_t, 3>> pieces;
    std::vector<std::uint32_t> region;          // per piece: its region, numbered from 0
    std::vector<int> winding;                   // per region: relative to region 0's
    std::vector<RefinedTriangles::Side> sides;  // region: local
    const char* failure = nullptr;
};

// The points of one cut triangle, projected on an axis plane: bounds of their coordinates there
// (interval arithmetic on the input), exact coordinates (lazily evaluated) and the lines each is
// known to lie on (the triangle's edges, and the intersections with other triangles), so that
// collinear points are found without exact arithmetic. Answers the predicates of the
// triangulation (ConstrainedTriangulation) on them, by index.
struct PlaneTable {
    using Interval = CGAL::Interval_nt<false>;
    const Refiner* refiner = nullptr;
    int dropped = 2;                                       // the axis projected away
    std::vector<PointId> ids;                              // per point
    std::vector<std::array<Interval, 2>> at;               // per point: bounds in the plane
    std::vector<std::vector<std::uint32_t>> lines;         // per point, ascending
    mutable std::vector<std::optional<ExactPoint>> exact;  // built where first needed
    bool roundingUp = false;  // whether the FPU rounds upward already (UpwardRounding)

    void add(const PointId& id) {
        const auto bounds = refiner->bounds(id, roundingUp);
        ids.push_back(id);
        const int u = dropped == 0 ? 1 : 0, v = dropped == 2 ? 1 : 2;
        at.push_back({bounds[static_cast<std::size_t>(u)], bounds[static_cast<std::size_t>(v)]});
        lines.emplace_back();
        exact.emplace_back();
    }
    // The exact projected coordinates, as references into `exact` (no copies of the rationals).
    struct Exact2 {
        const Exact::FT::ET& u;
        const Exact::FT::ET& v;
        const Exact::FT::ET& operator[](int axis) const { return axis == 0 ? u : v; }
    };
    Exact2 exact2(std::uint32_t i) const {
        if (!exact[i]) exact[i] = refiner->exactPoint(ids[i]);
        const auto& e = CGAL::exact(*exact[i]);
        static_assert(std::is_same_v<decltype(e[0]), const Exact::FT::ET&>);  // no temporary
        const int u = dropped == 0 ? 1 : 0, v = dropped == 2 ? 1 : 2;
        return {e[u], e[v]};
    }
    // The one line that points a and b both lie on other than the triangle's edges (the
    // intersection with another triangle: its index); kNone where there is none or more.
    std::uint32_t intersectionThrough(std::uint32_t a, std::uint32_t b) const;
    bool onOneLine(std::initializer_list<std::uint32_t> points) const {
        const std::vector<std::uint32_t>& first = lines[*points.begin()];
        return std::any_of(first.begin(), first.end(), [&](std::uint32_t line) {
            return std::all_of(points.begin() + 1, points.end(), [&](std::uint32_t p) {
                return std::binary_search(lines[p].begin(), lines[p].end(), line);
            });
        });
    }

    // Predicates: interval arithmetic first, exact arithmetic where that cannot decide, and
    // points on one known line collinear at once (a cut triangle's edge points, and the points
    // along an intersection, are exactly collinear, which no filter can show: on tree_3d the
    // exact evaluations had made the refinement 4× slower).
    CGAL::Orientation orientation(std::uint32_t p, std::uint32_t q, std::uint32_t r) const {
        {
            // Points on one line have bounds that cannot tell their orientation (or tell
            // COLLINEAR): the lines are looked up only where the bounds leave it open.
            const UpwardRounding protect(roundingUp);
            const auto sign =
                CGAL::orientationC2(at[p][0], at[p][1], at[q][0], at[q][1], at[r][0], at[r][1]);
            if (CGAL::is_certain(sign)) return CGAL::get_certain(sign);
        }
        if (onOneLine({p, q, r})) return CGAL::COLLINEAR;
        const auto a = exact2(p), b = exact2(q), c = exact2(r);
        return CGAL::orientationC2(a[0], a[1], b[0], b[1], c[0], c[1]);
    }
    // Where s lies to the circle through p, q, r (counterclockwise): ON_POSITIVE_SIDE inside.
    CGAL::Oriented_side inCircle(std::uint32_t p, std::uint32_t q, std::uint32_t r,
                                 std::uint32_t s) const {
        {
            const UpwardRounding protect(roundingUp);
            const auto side = CGAL::side_of_oriented_circleC2(
                at[p][0], at[p][1], at[q][0], at[q][1], at[r][0], at[r][1], at[s][0], at[s][1]);
            if (CGAL::is_certain(side)) return CGAL::get_certain(side);
        }
        const auto a = exact2(p), b = exact2(q), c = exact2(r), d = exact2(s);
        return CGAL::side_of_oriented_circleC2(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]);
    }
};

// Lines a point of a cut triangle can lie on: the triangle's edges, and its intersection with
// another triangle (that triangle's index).
constexpr std::uint32_t kEdgeLine = kNone - 3;  // + the edge's first corner, 0–2

std::uint32_t PlaneTable::intersectionThrough(std::uint32_t a, std::uint32_t b) const {
    std::uint32_t found = kNone;
    for (const std::uint32_t line : lines[a]) {
        if (line >= kEdgeLine || !std::binary_search(lines[b].begin(), lines[b].end(), line)) {
            continue;
        }
        if (found != kNone) return kNone;
        found = line;
    }
    return found;
}

// A step from region `from` of a cut triangle across a cut into region `to`, where the winding
// number changes by `change`.
struct RegionStep {
    std::uint32_t from, to;
    int change;
};

constexpr int kUnsetWinding = std::numeric_limits<int>::min();

// Fills `winding` (per region, kUnsetWinding) with the winding numbers relative to region 0's,
// breadth first along `steps` (reordered).
void windingsAcross(std::vector<RegionStep>& steps, std::vector<int>& winding) {
    std::sort(steps.begin(), steps.end(),
              [](const RegionStep& a, const RegionStep& b) { return a.from < b.from; });
    winding[0] = 0;
    std::vector<std::uint32_t> queue{0};
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::uint32_t r = queue[q];
        auto step =
            std::lower_bound(steps.begin(), steps.end(), r,
                             [](const RegionStep& s, std::uint32_t v) { return s.from < v; });
        for (; step != steps.end() && step->from == r; ++step) {
            const int w = winding[r] + step->change;
            if (winding[step->to] == kUnsetWinding) {
                winding[step->to] = w;
                queue.push_back(step->to);
            } else if (winding[step->to] != w) {
                throw Degenerate{"the cuts of a triangle disagree"};
            }
        }
    }
    if (queue.size() != winding.size())
        throw Degenerate{"a region of a cut triangle no cut reaches"};
}

// Cuts triangle t along the segments through it (`through`: each with the other triangle of
// its pair), triangulated in the axis plane where t is largest.
void cutTriangle(const Refiner& refiner, std::uint32_t t,
                 std::span<const std::pair<Segment, std::uint32_t>> through, TriangleCut& cut) {
    const std::uint32_t* c = refiner.corners(t);
    PlaneTable table;
    table.refiner = &refiner;
    {
        const RefinementPoint& p0 = refiner.point(c[0]);
        const auto normal = CGAL::cross_product(refiner.point(c[1]) - p0, refiner.point(c[2]) - p0);
        const double n[3] = {std::abs(normal.x()), std::abs(normal.y()), std::abs(normal.z())};
        table.dropped = n[2] >= n[0] && n[2] >= n[1] ? 2 : n[1] >= n[0] ? 1 : 0;
    }

    // The points: t's corners, then the ends of the segments, then where segments cross.
    std::vector<PointId>& ids = cut.points;
    for (int k = 0; k < 3; ++k) ids.push_back(PointId{PointId::corner, {c[k], kNone, kNone}});
    for (const auto& [segment, other] : through) {
        // The only corners that end segments in t are its own (shared with the other triangle).
        for (const PointId& end : {segment.from, segment.to}) {
            if (end.kind != PointId::corner) ids.push_back(end);
        }
    }
    std::sort(ids.begin() + 3, ids.end());
    ids.erase(std::unique(ids.begin() + 3, ids.end()), ids.end());
    auto local = [&](const PointId& id) {
        const auto found = id.kind == PointId::corner
                               ? std::find(ids.begin(), ids.begin() + 3, id)
                               : std::lower_bound(ids.begin() + 3, ids.end(), id);
        return static_cast<std::uint32_t>(found - ids.begin());
    };
    {
        // One switch to rounding upward for the bounds of all of them (Refiner::bounds).
        const CGAL::Protect_FPU_rounding<true> upward;
        table.roundingUp = true;
        for (const PointId& id : ids) table.add(id);
        table.roundingUp = false;
    }
    for (std::uint32_t k = 0; k < 3; ++k) {
        table.lines[k] = {kEdgeLine + k, kEdgeLine + (k + 2) % 3};
    }
    for (std::uint32_t i = 3; i < ids.size(); ++i) {
        const PointId& id = ids[i];
        if (id.kind != PointId::edgeThrough || id.of[2] == t) continue;
        for (std::uint32_t k = 0; k < 3; ++k) {  // on t's edge from corner k
            if (std::minmax(c[k], c[(k + 1) % 3]) == std::minmax(id.of[0], id.of[1])) {
                table.lines[i].push_back(kEdgeLine + k);
            }
        }
    }
    struct Local {
        std::uint32_t from, to, other;
    };
    std::vector<Local> segments;
    for (const auto& [segment, other] : through) {
        segments.push_back({local(segment.from), local(segment.to), other});
        table.lines[segments.back().from].push_back(other);
        table.lines[segments.back().to].push_back(other);
    }
    // Our predicates, and the exact points they may build (rationals, bounds from MPFR), do not
    // depend on the rounding mode: one switch to rounding upward for all of the crossings and the
    // triangulation (not for the filtered predicates of CGAL's kernels below, whose static
    // filters assume rounding to nearest).
    ConstrainedTriangulation cdt;
    bool flip = false;
    {
        const CGAL::Protect_FPU_rounding<true> upward;
        table.roundingUp = true;
        // Where two segments cross, the planes of three triangles meet: a vertex of all three.
        for (std::size_t i = 0; i < segments.size(); ++i) {
            const Local& a = segments[i];
            for (std::size_t j = i + 1; j < segments.size(); ++j) {
                const Local& b = segments[j];
                if (a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to) continue;
                const auto s1 = table.orientation(a.from, a.to, b.from);
                const auto s2 = table.orientation(a.from, a.to, b.to);
                if (s1 == s2) continue;
                const auto s3 = table.orientation(b.from, b.to, a.from);
                const auto s4 = table.orientation(b.from, b.to, a.to);
                if (s3 == s4) continue;
                if (s1 == CGAL::COLLINEAR || s2 == CGAL::COLLINEAR || s3 == CGAL::COLLINEAR ||
                    s4 == CGAL::COLLINEAR) {
                    throw Degenerate{"intersections that meet at an end"};
                }
                std::array<std::uint32_t, 3> three{t, a.other, b.other};
                std::sort(three.begin(), three.end());
                ids.push_back(PointId{PointId::threeTriangles, three});
                table.add(ids.back());
                table.lines.back() = {a.other, b.other};
            }
        }
        for (auto& lines : table.lines) std::sort(lines.begin(), lines.end());
        std::vector<std::pair<std::uint32_t, std::uint32_t>> constraints;
        constraints.reserve(segments.size());
        for (const Local& s : segments) constraints.emplace_back(s.from, s.to);
        cdt.triangulate(table, static_cast<std::uint32_t>(ids.size()), constraints);
        // Faces are counterclockwise in the plane: pieces turn as t does.
        flip = table.orientation(0, 1, 2) == CGAL::CLOCKWISE;
        table.roundingUp = false;
    }
    const auto& faces = cdt.faces();
    for (const auto& f : faces) {
        cut.pieces.push_back(flip ? std::array{f.v[0], f.v[2], f.v[1]} : f.v);
    }
    // The regions: pieces joined across the edges that are not cut, numbered in the order of their
    // first pieces; the edges on t's sides as their pieces use them.
    std::vector<std::uint32_t> parent(cut.pieces.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    constexpr auto kNoFace = ConstrainedTriangulation::kNoFace;
    for (std::uint32_t f = 0; f < faces.size(); ++f) {
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t g = faces[f].neighbor[i];
            if (g == kNoFace) {
                const std::uint32_t a = faces[f].v[(i + 1) % 3], b = faces[f].v[(i + 2) % 3];
                cut.sides.push_back({flip ? b : a, flip ? a : b, f});  // its piece for now
            } else if (!faces[f].constrained[i] && f < g) {
                parent[root(g)] = root(f);
            }
        }
    }
    {
        std::vector<std::uint32_t> number(cut.pieces.size(), kNone);  // per root
        cut.region.resize(cut.pieces.size());
        std::uint32_t regions = 0;
        for (std::uint32_t f = 0; f < cut.pieces.size(); ++f) {
            std::uint32_t& n = number[root(f)];
            if (n == kNone) n = regions++;
            cut.region[f] = n;
        }
        cut.winding.assign(regions, kUnsetWinding);
    }
    for (RefinedTriangles::Side& side : cut.sides) side.region = cut.region[side.region];
    std::vector<RegionStep> steps;  // across the cuts, both ways
    // Across each cut edge, the piece on the inner side of the other triangle has one more
    // (RefinedTriangles::Region). Face f lies left of its edge a → b opposite vertex i (faces are
    // counterclockwise in the plane); a corner of t off the edge's line is on f's side or not
    // (in the plane), and on the inner or the outer side of the other triangle (exact, on the
    // input corners), which tells f's side without the cut points' coordinates.
    for (std::uint32_t f = 0; f < faces.size(); ++f) {
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t g = faces[f].neighbor[i];
            if (!faces[f].constrained[i] || (g != kNoFace && g < f)) continue;
            if (g == kNoFace) throw Degenerate{"a cut along a side of the triangle"};
            const std::uint32_t a = faces[f].v[(i + 1) % 3], b = faces[f].v[(i + 2) % 3];
            const std::uint32_t other = table.intersectionThrough(a, b);
            if (other == kNone) throw Degenerate{"a cut edge on no single intersection"};
            std::size_t k = 0;
            CGAL::Orientation turn = CGAL::COLLINEAR;
            while (k < 3 && (turn = table.orientation(a, b, static_cast<std::uint32_t>(k))) ==
                                CGAL::COLLINEAR)
                ++k;
            if (k == 3) throw Degenerate{"a cut edge along every corner"};
            const std::uint32_t* o = refiner.corners(other);
            const CGAL::Orientation side = CGAL::orientation(
                refiner.point(o[0]), refiner.point(o[1]), refiner.point(o[2]), refiner.point(c[k]));
            if (side == CGAL::COPLANAR) throw Degenerate{"a corner on an intersection"};
            const bool inner = (side == CGAL::NEGATIVE) == (turn == CGAL::LEFT_TURN);
            const std::uint32_t mine = cut.region[f];
            const std::uint32_t across = cut.region[g];
            steps.push_back({across, mine, inner ? 1 : -1});
            steps.push_back({mine, across, inner ? -1 : 1});
        }
    }
    windingsAcross(steps, cut.winding);
}

// A vertex of the refined triangles: a named point on one sheet. A point where an edge passes
// through a triangle is on two sheets (the triangle's, and the one of the two triangles that
// share the edge); a point where three planes meet is on three.
struct VertexKey {
    PointId point;
    std::uint32_t sheet;  // the triangle whose inside holds it, or kNone: on an edge
    bool operator==(const VertexKey&) const = default;
};

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        std::uint64_t h = splitMixFinal(k.point.kind + 0x9E3779B97F4A7C15ull * k.sheet);
        for (std::uint32_t v : k.point.of) h = splitMixFinal(h ^ v);
        return static_cast<std::size_t>(h);
    }
};

std::uint32_t sheetOf(const PointId& id, std::uint32_t t) {
    if (id.kind == PointId::edgeThrough && id.of[2] != t) return kNone;
    return t;
}

// A new point rounded to doubles, per coordinate: the middle of its interval bounds
// (Refiner::bounds, interval arithmetic on the input) where they are closer than kRoundingWidth
// times the input's largest coordinate `scale` (far below a float's precision, which the union's
// output has), else the exact value rounded (ABOP 1.24a: 66 k of 806 k coordinates with bounds
// wider than 1e-12 of their value had taken 1.6 s). Either depends on the input alone. Until
// session 32 the bounds were those of the lazy exact point, which was built for every point
// (0.12 s of 1.24a's refinement).
constexpr double kRoundingWidth = 1e-10;

RefinementPoint roundedPoint(const Refiner& refiner, const PointId& id, double scale) {
    const auto bounds = refiner.bounds(id);
    std::array<double, 3> at;
    std::optional<ExactPoint> exact;
    for (int d = 0; d < 3; ++d) {
        const auto& i = bounds[static_cast<std::size_t>(d)];
        if (i.sup() - i.inf() <= kRoundingWidth * scale) {
            at[static_cast<std::size_t>(d)] = 0.5 * (i.inf() + i.sup());
            continue;
        }
        if (!exact) exact = refiner.exactPoint(id);
        at[static_cast<std::size_t>(d)] = CGAL::to_double(CGAL::exact((*exact)[d]));
    }
    return RefinementPoint(at[0], at[1], at[2]);
}

}  // namespace

const char* refineTriangles(const std::vector<RefinementPoint>& points,
                            const std::vector<std::uint32_t>& fan,
                            const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                            RefinedTriangles& out) {
    out = RefinedTriangles{};
    const Refiner refiner(points, fan);
    std::vector<Segment> segments(pairs.size());
    std::vector<const char*> pairFailures(pairs.size(), nullptr);
    forEachOnCores(pairs.size(), [&](std::size_t i) {
        try {
            segments[i] = refiner.segment(pairs[i].first, pairs[i].second);
        } catch (const Degenerate& d) {
            pairFailures[i] = d.why;
        }
    });
    for (const char* failure : pairFailures) {
        if (failure) return failure;
    }

    // The cut triangles, ascending, each with the segments through it (in the order of the
    // pairs): a counting sort of the pairs by triangle.
    const std::size_t triangles = fan.size() / 3;
    std::vector<std::uint32_t> slot(triangles + 1, 0);  // per triangle + 1: its segments
    for (const auto& [s, t] : pairs) {
        ++slot[s + 1];
        ++slot[t + 1];
    }
    std::vector<std::uint32_t> cutTriangles;
    for (std::uint32_t t = 0; t < triangles; ++t) {
        if (slot[t + 1] > 0) cutTriangles.push_back(t);
    }
    std::partial_sum(slot.begin(), slot.end(), slot.begin());
    std::vector<std::pair<Segment, std::uint32_t>> through(slot.back());
    {
        std::vector<std::uint32_t> next(slot.begin(), slot.end() - 1);
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            const auto [s, t] = pairs[i];
            through[next[s]++] = {segments[i], t};
            through[next[t]++] = {segments[i], s};
        }
    }
    auto throughTriangle = [&](std::uint32_t t) {
        return std::span(through).subspan(slot[t], slot[t + 1] - slot[t]);
    };
    std::vector<TriangleCut> cuts(cutTriangles.size());
    forEachOnCores(cutTriangles.size(), [&](std::size_t i) {
        try {
            cutTriangle(refiner, cutTriangles[i], throughTriangle(cutTriangles[i]), cuts[i]);
        } catch (const Degenerate& d) {
            cuts[i].failure = d.why;
        } catch (const TriangulationFailure& f) {
            cuts[i].failure = f.why;
        } catch (const std::exception&) {
            // CGAL's checks (builds with assertions) on a configuration we did not foresee:
            // as for a degenerate one, the union moves the corners and tries again.
            cuts[i].failure = "the triangulation of a cut triangle failed";
        }
    });

    // Where each cut triangle's points, pieces, regions and sides go in the output.
    struct Offsets {
        std::size_t points = 0, pieces = 0, regions = 0, sides = 0;
    };
    std::vector<Offsets> offsets(cuts.size() + 1);
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        const TriangleCut& cut = cuts[i];
        if (cut.failure) return cut.failure;
        const Offsets& o = offsets[i];
        offsets[i + 1] = {o.points + cut.points.size(), o.pieces + cut.pieces.size(),
                          o.regions + cut.winding.size(), o.sides + cut.sides.size()};
    }
    // Vertices: the input's corners keep their index; the others are numbered as they come (one
    // thread: the order of the cut triangles), the rest is written on all cores.
    const auto inputPoints = static_cast<std::uint32_t>(points.size());
    const std::size_t cutPoints = offsets.back().points;  // with repeats and corners
    IndexHashTable vertexOf(cutPoints);                   // indices into newVertices
    std::vector<VertexKey> newVertices;
    newVertices.reserve(cutPoints);
    std::vector<std::uint32_t> global(cutPoints);  // per point of each cut triangle in turn
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        std::uint32_t* vertex = &global[offsets[i].points];
        for (const PointId& id : cuts[i].points) {
            if (id.kind == PointId::corner) {
                *vertex++ = id.of[0];
                continue;
            }
            const VertexKey key{id, sheetOf(id, cutTriangles[i])};
            const auto next = static_cast<std::uint32_t>(newVertices.size());
            const std::uint32_t found = vertexOf.findOrAdd(
                VertexKeyHash{}(key), next, [&](std::uint32_t j) { return newVertices[j] == key; });
            if (found == next) newVertices.push_back(key);
            *vertex++ = inputPoints + found;
        }
    }
    const Offsets& total = offsets.back();
    out.pieces.resize(total.pieces);
    out.pieceRegion.resize(total.pieces);
    out.regions.resize(total.regions);
    out.sides.resize(total.sides);
    forEachOnCores(cuts.size(), [&](std::size_t i) {
        const TriangleCut& cut = cuts[i];
        const Offsets& o = offsets[i];
        const std::uint32_t* at = &global[o.points];
        const auto firstRegion = static_cast<std::uint32_t>(o.regions);
        for (std::size_t f = 0; f < cut.pieces.size(); ++f) {
            const auto& piece = cut.pieces[f];
            out.pieces[o.pieces + f] = {cutTriangles[i],
                                        {at[piece[0]], at[piece[1]], at[piece[2]]}};
            out.pieceRegion[o.pieces + f] = firstRegion + cut.region[f];
        }
        for (std::size_t r = 0; r < cut.winding.size(); ++r) {
            out.regions[o.regions + r] = {cutTriangles[i], cut.winding[r]};
        }
        for (std::size_t k = 0; k < cut.sides.size(); ++k) {
            const RefinedTriangles::Side& side = cut.sides[k];
            out.sides[o.sides + k] = {at[side.from], at[side.to], firstRegion + side.region};
        }
    });
    double scale = 0;
    for (const RefinementPoint& p : points) {
        scale = std::max({scale, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
    }
    out.newPoints.resize(newVertices.size());
    std::vector<const char*> pointFailures(newVertices.size(), nullptr);
    forEachOnCores(newVertices.size(), [&](std::size_t i) {
        try {
            out.newPoints[i] = roundedPoint(refiner, newVertices[i].point, scale);
        } catch (const Degenerate& d) {
            pointFailures[i] = d.why;
        }
    });
    for (const char* failure : pointFailures) {
        if (failure) return failure;
    }
    return nullptr;
}

}  // namespace ramus::detail

#endif  // RAMUS_WITH_CGAL
