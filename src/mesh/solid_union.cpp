// Solid union of overlapping closed surfaces (include/ramus/solid_union.hpp).
//
// Based on: Zhou, Grinspun, Zorin, Jacobson 2016, "Mesh arrangements for solid geometry"
// (resolve all intersections, then keep the patches whose winding number is 0 on one side and
// positive on the other); the resolution is our own refinement (triangle_refinement.hpp: exact
// predicates, intersection curves inserted as constrained edges), which replaced CGAL's
// autorefinement in session 31.
//
// Steps:
// 1. Weld the input by position (edges shared by several surfaces paired per surface) and move
//    each surface vertex by at most 1e-5 of the extent (fixed hash; larger on retries): exact
//    coincidences — faces of a flat plant lying in one plane, a ring drawn twice, three sheets
//    through one intersection edge — are cases the refinement rejects ("triple
//    intersection"); after the move they are in general position, and the moved positions are
//    floats, so untouched triangles keep exactly representable corners.
// 2. Cut the triangles that intersect others along the intersections (the exact test of CGAL's
//    self-intersection test on the pairs of overlapping boxes, box_overlaps.hpp, finds the
//    pairs; on a tree a few percent of the mesh), the rest staying as they are; each piece
//    keeps the index of the input triangle it came from (triangle_refinement.hpp).
// 3. Patches: connected regions between intersection edges. The winding number of the whole
//    input is constant on each side of a patch, and the patch bounds the union iff it is 0
//    outside it. Across an intersection edge it changes by one along the sheet (the refinement
//    tells which side of the cutting triangle each piece is on), so it is carried from patch to
//    patch; one ray per connected part of the input, from the centre of a patch's largest
//    triangle roughly along its normal, counts signed crossings with the input triangles (+1
//    leaving a surface). A ray through an edge or corner (counted twice or not at all) is found
//    by exact predicates and another ray is cast. Until session 32 every patch had its ray.
// 4. Kept pieces become output triangles; corners interpolate the attributes of the input
//    triangle the piece came from (corners that are input corners copy them exactly).
// 5. Check: every edge welded by position is used as often in one direction as in the other
//    (once each way, or k times where rounding pinched k sheets together along it: counted).
//    Pockets (closed components of negative volume) are filled, with any piece inside one.
// 6. Rounding to float can make grazing surfaces cross (CGAL's exact self-intersection test on
//    the floats, near the triangles that were cut or moved: the others were tested in step 2)
//    or pinch two sheets together along an edge, and the union keeps points where surfaces
//    touch (pieces of one input triangle on both sides of a cut meeting at a corner): the
//    corners of each crossing pair are moved a few float steps apart, where that lowers the
//    crossings and turns no triangle over, and then the corners of one sheet at a pinched edge
//    or a touching point into its own solid, where that adds no crossing
//    (crossing_repair.hpp); up to three rounds, each allowed larger moves.
// 7. Rounding can also break the check: up to seven moves are tried (kUnionMoves), and the
//    first result without crossings, pinched edges or touching points, else the one with the
//    fewest, replaces the mesh.
// 8. After each attempt that leaves some, the result itself is united again (up to
//    kSolidUnionReunions times) with only the corners of its defects moved: its other triangles
//    cross nothing, so a few dozen are cut instead of tens of thousands (session 29: ABOP 1.24c was
//    clean at its fourth attempt after 64 s, now after its first and one re-union in 19 s).
#include "ramus/solid_union.hpp"

#include "ramus/error.hpp"

#if RAMUS_WITH_CGAL

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "box_overlaps.hpp"
#include "box_tree.hpp"
#include "crossing_repair.hpp"
#include "fixed_hash.hpp"
#include "index_hash_table.hpp"
#include "on_cores.hpp"
#include "position_bits.hpp"
#include "triangle_pairs.hpp"
#include "triangle_refinement.hpp"

namespace ramus {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using FaceIndex = SurfaceMesh::Face_index;
using VertexIndex = SurfaceMesh::Vertex_index;
namespace PMP = CGAL::Polygon_mesh_processing;

constexpr std::uint32_t kUnknown = std::numeric_limits<std::uint32_t>::max();

// The corner after corner c in its triangle.
std::uint32_t nextCorner(std::uint32_t c) { return c - c % 3 + (c % 3 + 1) % 3; }

using detail::bitsOf;
using detail::PositionBits;

// Per vertex: the index of its position among the distinct positions (bit-exact), numbered
// in order of first appearance (a hash table: sorting the positions had taken a third of the
// union's own bookkeeping on tree_3d, session 32).
std::vector<std::uint32_t> weldByPosition(const std::vector<Vec3f>& positions,
                                          std::uint32_t* distinct) {
    std::vector<PositionBits> bits(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) bits[i] = bitsOf(positions[i]);
    detail::IndexHashTable table(positions.size());
    std::vector<std::uint32_t> id(positions.size());
    std::uint32_t next = 0;
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
        const PositionBits& b = bits[i];
        const std::uint32_t first =
            table.findOrAdd(detail::PositionBitsHash{}(b), i, [&](std::uint32_t j) {
                return bits[j][0] == b[0] && bits[j][1] == b[1] && bits[j][2] == b[2];
            });
        id[i] = first == i ? next++ : id[first];
    }
    *distinct = next;
    return id;
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

// Per triangle: its component (welded by position), numbered from 0; `count` receives how many.
std::vector<std::uint32_t> triangleComponents(const std::vector<std::uint32_t>& weld,
                                              std::uint32_t distinct,
                                              const std::vector<std::uint32_t>& indices,
                                              std::uint32_t* count) {
    std::vector<std::uint32_t> parent(distinct);
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = findRoot(parent, weld[indices[t]]);
        for (int k = 1; k < 3; ++k) parent[findRoot(parent, weld[indices[t + k]])] = a;
    }
    std::vector<std::uint32_t> number(distinct, kUnknown);
    std::vector<std::uint32_t> component(indices.size() / 3);
    *count = 0;
    for (std::size_t t = 0; t < component.size(); ++t) {
        std::uint32_t& n = number[findRoot(parent, weld[indices[3 * t]])];
        if (n == kUnknown) n = (*count)++;
        component[t] = n;
    }
    return component;
}

// Connected components of the triangles over welded vertex ids.
std::size_t countComponents(const std::vector<std::uint32_t>& weld, std::uint32_t distinct,
                            const std::vector<std::uint32_t>& indices) {
    std::uint32_t count = 0;
    triangleComponents(weld, distinct, indices, &count);
    return count;
}

// Keeps the triangles with keep[t] (primitive ranges shrink with them, empty ones go) and
// then only the vertices they use.
void keepTriangles(Mesh& mesh, const std::vector<char>& keep) {
    std::size_t kept = 0;
    std::size_t primitive = 0;
    std::uint32_t primitiveEnd = mesh.primitives.empty() ? 0 : mesh.primitives[0].indexCount;
    std::vector<std::uint32_t> keptPerPrimitive(mesh.primitives.size(), 0);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        while (primitive + 1 < mesh.primitives.size() && 3 * t >= primitiveEnd) {
            primitiveEnd += mesh.primitives[++primitive].indexCount;
        }
        if (!keep[t]) continue;
        std::copy_n(mesh.indices.begin() + static_cast<std::ptrdiff_t>(3 * t), 3,
                    mesh.indices.begin() + static_cast<std::ptrdiff_t>(kept));
        kept += 3;
        if (!mesh.primitives.empty()) keptPerPrimitive[primitive] += 3;
    }
    mesh.indices.resize(kept);
    std::uint32_t first = 0;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        mesh.primitives[p].firstIndex = first;
        mesh.primitives[p].indexCount = keptPerPrimitive[p];
        first += keptPerPrimitive[p];
    }
    std::erase_if(mesh.primitives, [](const MeshPrimitive& p) { return p.indexCount == 0; });

    removeUnusedVertices(mesh);
}

// Keeps the flags of the triangles with keep[t], as keepTriangles keeps the triangles.
void keepFlags(std::vector<char>& flags, const std::vector<char>& keep) {
    std::size_t kept = 0;
    for (std::size_t t = 0; t < flags.size(); ++t) {
        if (keep[t]) flags[kept++] = flags[t];
    }
    flags.resize(kept);
}

// Per triangle: whether it is kept when pieces so thin that rounding the new positions to
// float joined two of their corners are removed (an edge collapse, which leaves the rest of
// the surface closed).
std::vector<char> uncollapsedTriangles(const std::vector<std::uint32_t>& weld,
                                       const std::vector<std::uint32_t>& indices) {
    std::vector<char> keep(indices.size() / 3);
    for (std::size_t t = 0; t < keep.size(); ++t) {
        const std::uint32_t a = weld[indices[3 * t]], b = weld[indices[3 * t + 1]],
                            c = weld[indices[3 * t + 2]];
        keep[t] = a != b && b != c && c != a;
    }
    return keep;
}

using Triangle = Kernel::Triangle_3;

// `boxes` gets the box of each triangle t < triangles, whose corners are point(t, 0..2); empty
// where not include(t). Filling the same vector again reuses its memory (first touches of fresh
// pages are dear: tree_3d's 230 k boxes, 11 MB, 1.8 ms in reused memory, 6.5 in fresh).
template <class PointOf, class Include>
void fillTriangleBoxes(std::vector<detail::Box3>& boxes, std::size_t triangles, PointOf point,
                       Include include) {
    boxes.assign(triangles, detail::Box3{});
    for (std::uint32_t t = 0; t < triangles; ++t) {
        if (!include(t)) continue;
        for (std::size_t k = 0; k < 3; ++k) {
            const Point& p = point(t, k);
            boxes[t].add({p.x(), p.y(), p.z()});
        }
    }
}

// The boxes of fillTriangleBoxes, in a vector of their own.
template <class PointOf, class Include>
std::vector<detail::Box3> triangleBoxes(std::size_t triangles, PointOf point, Include include) {
    std::vector<detail::Box3> boxes;
    fillTriangleBoxes(boxes, triangles, point, include);
    return boxes;
}

// Signed crossings of rays with a fixed set of triangles: the winding number of the surfaces
// they make at a ray's start (all wound outward), with chosen triangles left out. Where many
// rays are cast, over a tree of the triangles' boxes (detail::BoxTree; CGAL's AABB tree until
// session 31), built at once so that threads can cast rays together; for a few, every
// triangle's box is tested instead (a tree over 230 k boxes took 0.03 s to build, 0.09 s in
// fresh memory, session 32; tree_3d casts one ray).
class RayCrossings {
public:
    // The triangles `faces`, corners into `points` (which must outlive this).
    RayCrossings(std::span<const Point> points, std::vector<std::array<std::uint32_t, 3>> faces,
                 bool manyRays)
        : points_(points), faces_(std::move(faces)) {
        if (manyRays) {
            tree_.emplace(triangleBoxes(
                faces_.size(),
                [&](std::size_t t, std::size_t k) -> const Point& { return points_[faces_[t][k]]; },
                [](std::size_t) { return true; }));
            return;
        }
        double magnitude = 0.0;
        for (const Point& p : points_) {
            magnitude = std::max({magnitude, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
        }
        widen_ = detail::BoxTree::widening(2.0 * magnitude);
    }
    RayCrossings(const RayCrossings&) = delete;
    RayCrossings& operator=(const RayCrossings&) = delete;

    struct Count {
        int winding = 0;
        bool degenerate = false;
    };

    // +1 for every triangle the ray from `origin` along `d` leaves (`origin` on its inner side),
    // -1 for every one it enters; triangle i left out where skip(i). Degenerate where the ray
    // meets a triangle through an edge or a corner (counted by both sides or by neither) or
    // starts in its plane (exact predicates): then the crossings need not be the winding number.
    template <class Skip>
    Count count(const Point& origin, const Vector& d, Skip skip) const {
        const Kernel::Ray_3 ray(origin, d);
        const Point& o = ray.source();
        const Point q = ray.second_point();
        Count result;
        auto cross = [&](std::uint32_t i) {
            if (skip(std::size_t{i})) return;
            const Point& a = points_[faces_[i][0]];
            const Point& b = points_[faces_[i][1]];
            const Point& c = points_[faces_[i][2]];
            if (!CGAL::do_intersect(ray, Triangle(a, b, c))) return;
            const CGAL::Orientation side = CGAL::orientation(a, b, c, o);
            if (side == CGAL::COPLANAR || CGAL::orientation(o, q, a, b) == CGAL::COPLANAR ||
                CGAL::orientation(o, q, b, c) == CGAL::COPLANAR ||
                CGAL::orientation(o, q, c, a) == CGAL::COPLANAR) {
                result.degenerate = true;
            }
            result.winding += side == CGAL::NEGATIVE ? 1 : -1;
        };
        const std::array<double, 3> from{o.x(), o.y(), o.z()}, along{d.x(), d.y(), d.z()};
        if (tree_) {
            tree_->forEachAlongRay(from, along, cross);
            return result;
        }
        std::array<double, 3> inverse;
        for (int k = 0; k < 3; ++k) inverse[k] = along[k] == 0.0 ? 0.0 : 1.0 / along[k];
        for (std::uint32_t i = 0; i < faces_.size(); ++i) {
            detail::Box3 box;
            for (const std::uint32_t v : faces_[i])
                box.add({points_[v].x(), points_[v].y(), points_[v].z()});
            for (int k = 0; k < 3; ++k) {
                box.lo[k] -= widen_;
                box.hi[k] += widen_;
            }
            if (detail::BoxTree::meets(box, from, along, inverse)) cross(i);
        }
        return result;
    }

private:
    std::span<const Point> points_;
    std::vector<std::array<std::uint32_t, 3>> faces_;
    std::optional<detail::BoxTree> tree_;
    double widen_ = 0.0;  // of the boxes, without a tree: as the tree's
};

// Where fewer rays than this are cast, RayCrossings tests every triangle's box instead of
// building a tree.
constexpr std::size_t kRaysWithoutTree = 16;

using detail::forEachOnCores;

// The winding number that the rays ray(0), ray(1), … count (RayCrossings::count): the first of
// them that meets no triangle degenerately decides (it counts the winding number exactly);
// where the first kRayTries all do (not met on the examples), the middle of the first three
// counts. Until session 30 every decision took two rays, and a third where they disagreed.
constexpr std::uint64_t kRayTries = 8;
template <class Ray>
int windingByRays(Ray ray) {
    std::array<int, 3> counts{};
    for (std::uint64_t k = 0; k < kRayTries; ++k) {
        const RayCrossings::Count count = ray(k);
        if (!count.degenerate) return count.winding;
        if (k < counts.size()) counts[k] = count.winding;
    }
    std::sort(counts.begin(), counts.end());
    return counts[1];
}

// The pairs (s, t), s < t, of triangles whose `boxes` overlap (detail::overlappingBoxes), at
// least one of them `suspect` (every pair where that is empty), for which test(s, t) holds,
// tested on the search's threads as they are found, until `stop` is set (then incomplete);
// sorted.
template <class Test>
std::vector<detail::TrianglePair> overlappingPairsWhere(const std::vector<detail::Box3>& boxes,
                                                        const std::vector<char>& suspect, Test test,
                                                        const std::atomic<bool>* stop = nullptr) {
    std::vector<detail::TrianglePair> pairs = detail::overlappingBoxes(boxes, suspect, test, stop);
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// The most pairs of intersection segments within one cut triangle, summed over the cut
// triangles, that the union of a mesh of `triangles` triangles cuts (kSolidUnionSegmentPairsFloor,
// kSolidUnionSegmentPairsPerTriangle): they bound the refinement's crossing tests and its
// crossings.
std::uint64_t segmentPairLimit(std::size_t triangles) {
    return kSolidUnionSegmentPairsFloor +
           std::uint64_t{kSolidUnionSegmentPairsPerTriangle} * triangles;
}

// The triangles of closed surfaces (corners: the surface vertices `fan`, at `points`) that the
// refinement has to cut: per triangle whether it is degenerate (corners on a line) or
// intersects another triangle other than in the corners or edge they share
// (trianglesIntersect), and the intersecting pairs. What CGAL's self-intersection test finds,
// on two cores (on one it was a quarter of tree_3d's union, 0.36 s of 1.4 s, session 30). Only
// pairs with a triangle that `mayCross` (per triangle; empty: every pair) are searched: a
// re-union knows which (step 8).
//
// The pairs of segments within each cut triangle (one segment per pair found with it) are
// counted as the pairs are found: a triangle's k-th pair adds k − 1. Once the sum is over
// segmentPairLimit the search tests no more pairs and `overLimit` is set (`cut` and `pairs` are
// then incomplete): as the sum only grows, that happens exactly when the whole search would
// end over the limit, whatever the threads' order, and seed 332 of scripts/random-unions.py
// (1.5 G pairs against a limit of 34 M) is refused after 0.15–0.35 s of search instead of 1.9 s
// (session 45).
struct Intersections {
    std::vector<char> cut;
    std::vector<detail::TrianglePair> pairs;
    bool overLimit = false;
};

Intersections intersectingTriangles(const std::vector<Point>& points,
                                    const std::vector<std::uint32_t>& fan,
                                    const std::vector<char>& mayCross) {
    const std::size_t triangles = fan.size() / 3;
    auto point = [&](std::uint32_t t, std::size_t k) -> const Point& {
        return points[fan[3 * std::size_t{t} + k]];
    };
    Intersections found;
    found.cut.resize(triangles);
    for (std::uint32_t t = 0; t < triangles; ++t) {
        found.cut[t] = CGAL::collinear(point(t, 0), point(t, 1), point(t, 2));
    }
    const std::uint64_t limit = segmentPairLimit(triangles);
    std::vector<std::atomic<std::uint32_t>> segments(triangles);  // pairs found per triangle
    std::atomic<std::uint64_t> segmentPairs{0};
    std::atomic<bool> overLimit{false};
    found.pairs = overlappingPairsWhere(
        triangleBoxes(triangles, point, [&](std::uint32_t t) { return !found.cut[t]; }), mayCross,
        [&](std::uint32_t s, std::uint32_t t) {
            if (overLimit.load(std::memory_order_relaxed)) return false;
            if (!detail::trianglesIntersect(
                    [&](std::uint32_t v) -> const Point& { return points[v]; },
                    &fan[3 * std::size_t{s}], &fan[3 * std::size_t{t}])) {
                return false;
            }
            const std::uint64_t added =
                std::uint64_t{segments[s].fetch_add(1, std::memory_order_relaxed)} +
                segments[t].fetch_add(1, std::memory_order_relaxed);
            if (segmentPairs.fetch_add(added, std::memory_order_relaxed) + added > limit) {
                overLimit.store(true, std::memory_order_relaxed);
            }
            return true;
        },
        &overLimit);
    found.overLimit = overLimit.load();
    for (const auto& [s, t] : found.pairs) found.cut[s] = found.cut[t] = 1;
    return found;
}

// Whether the intersections `found` of a mesh of `triangles` triangles are more than the union
// cuts; if so, report.failure says so.
bool overWorkLimit(std::size_t triangles, const Intersections& found, SolidUnionReport& report) {
    if (!found.overLimit) return false;
    report.failure = "the surfaces overlap too densely to cut (more than " +
                     std::to_string(segmentPairLimit(triangles)) +
                     " pairs of intersections within triangles, the most the union takes for " +
                     std::to_string(triangles) +
                     " triangles): branches run inside one another along their length";
    return true;
}

// A separate closed piece of the result with less than this fraction of the largest piece's
// volume is a sliver: where surfaces graze, the cut leaves wedges of 4–8 triangles a few
// thousandths of a unit thick beside the main surface (ABOP 1.24a, 1.25, 2.8a: 1e-13–1.6e-10
// of the largest piece's volume; 1.31a: 1.1e-7, 8 triangles, once its fallback junctions mesh
// their inner limbs as tubes), while the smallest real separate piece measured, a branch
// cluster of 1.25, had 2e-4 of it.
constexpr double kSliverVolume = 1e-6;

// Per triangle: whether it lies on the outer surface of the solid. The union's boundary is the
// outer surface of each solid piece, plus the inward-facing surface of every pocket that the
// overlapping tubes enclose without covering it, plus any piece inside such a pocket. A pocket's
// surface has negative volume (summed about its own first corner, so that tiny pockets far from
// the origin keep their sign); a piece inside one has winding number ≥ 1 with respect to the
// rest once the pockets are gone (rays, as for the patches: windingByRays). Both are removed: the
// pockets are filled, as hidden inner geometry is nothing an engine or a printer wants.
// Slivers (kSliverVolume) are removed too.
std::vector<char> outerSurfaces(const Mesh& mesh, const std::vector<std::uint32_t>& weld,
                                std::uint32_t distinct, SolidUnionReport& report) {
    const std::vector<std::uint32_t>& indices = mesh.indices;
    std::uint32_t count = 0;
    const std::vector<std::uint32_t> component =
        triangleComponents(weld, distinct, indices, &count);
    const std::size_t triangles = component.size();
    auto corner = [&](std::size_t t, int k) {
        return mesh.positions[indices[3 * t + k]].cast<double>();
    };
    std::vector<double> volume(count, 0.0);
    std::vector<std::size_t> firstTriangle(count, triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t c = component[t];
        if (firstTriangle[c] == triangles) firstTriangle[c] = t;
        const Vec3 o = corner(firstTriangle[c], 0);
        volume[c] += (corner(t, 0) - o).dot((corner(t, 1) - o).cross(corner(t, 2) - o)) / 6.0;
    }
    std::vector<char> keepComponent(count);
    for (std::uint32_t c = 0; c < count; ++c) keepComponent[c] = volume[c] >= 0.0;
    report.cavitiesFilled =
        static_cast<std::size_t>(std::count(keepComponent.begin(), keepComponent.end(), 0));
    const double largest = *std::max_element(volume.begin(), volume.end());
    for (std::uint32_t c = 0; c < count; ++c) {
        if (keepComponent[c] && volume[c] < kSliverVolume * largest) {
            keepComponent[c] = 0;
            ++report.sliversRemoved;
        }
    }

    if (std::count(keepComponent.begin(), keepComponent.end(), 1) > 1) {
        std::vector<Point> points;
        points.reserve(mesh.positions.size());
        for (const Vec3f& p : mesh.positions) points.emplace_back(p.x(), p.y(), p.z());
        std::vector<std::array<std::uint32_t, 3>> solid;
        std::vector<std::uint32_t> solidComponent;
        for (std::size_t t = 0; t < triangles; ++t) {
            if (!keepComponent[component[t]]) continue;
            solid.push_back({indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]});
            solidComponent.push_back(component[t]);
        }
        const RayCrossings rays(points, std::move(solid), count > kRaysWithoutTree);
        std::vector<char> enclosed(count, 0);
        forEachOnCores(count, [&](std::size_t c) {
            if (!keepComponent[c]) return;
            const std::size_t t = firstTriangle[c];
            const Vec3 centre = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
            auto ray = [&](std::uint64_t k) {
                const std::uint64_t seed = 0xC0FFEE + 3 * (3 * std::uint64_t{c} + k);
                const Vector d(detail::hashUnit(seed), detail::hashUnit(seed + 1),
                               detail::hashUnit(seed + 2));
                return rays.count(Point(centre.x(), centre.y(), centre.z()), d,
                                  [&](std::size_t hit) { return solidComponent[hit] == c; });
            };
            enclosed[c] = windingByRays(ray) >= 1;
        });
        for (std::uint32_t c = 0; c < count; ++c) {
            if (enclosed[c]) {
                keepComponent[c] = 0;
                ++report.enclosedPieces;
            }
        }
    }
    std::vector<char> keep(triangles);
    for (std::size_t t = 0; t < triangles; ++t) keep[t] = keepComponent[component[t]];
    return keep;
}

// The kept faces of the union: the refined vertices (the input's surface vertices first, by
// index, then the ones the cuts made), the uncut input triangles and the pieces of cut ones on
// the union's boundary, each with the input triangle it is a piece of.
struct RefinedSoup {
    using Face = detail::RefinedTriangles::Piece;  // the input triangle, the corners
    std::vector<Point> points;
    std::vector<Face> faces;
};

// The soup renumbered in an order of its own: the vertices its faces use by position (ties:
// their refined index, which for the input's vertices is their input index; the others go),
// faces by their input triangle and then their corners, each face starting at its lowest corner.
// Until session 31 CGAL's autorefinement numbered the refined mesh by where the heap put its
// arrays (it broke ties between boxes by their addresses), and this order made the union
// deterministic (tree_3d_tropism at 4 derivations: 3 of 20 rounds of
// SolidUnion.TheSameInputGivesTheSame… had differed). Our refinement numbers alike every time, but
// the order of the faces is the order in which the crossing repair (step 6) tries its moves, which
// are greedy: in the refinement's own order (pieces after the uncut triangles) ABOP 2.8c kept a
// defect after its first attempt and needed two (1 postponed move) instead of one.
void canonicalOrder(RefinedSoup& soup) {
    struct Keyed {
        double x, y, z;
        std::uint32_t vertex;
    };
    std::vector<char> used(soup.points.size(), 0);
    for (const RefinedSoup::Face& face : soup.faces) {
        for (const std::uint32_t c : face.corners) used[c] = 1;
    }
    std::vector<Keyed> byPosition;
    byPosition.reserve(soup.points.size());
    for (std::uint32_t v = 0; v < soup.points.size(); ++v) {
        const Point& p = soup.points[v];
        if (used[v]) byPosition.push_back({p.x(), p.y(), p.z(), v});
    }
    std::sort(byPosition.begin(), byPosition.end(), [](const Keyed& a, const Keyed& b) {
        return std::tie(a.x, a.y, a.z, a.vertex) < std::tie(b.x, b.y, b.z, b.vertex);
    });
    std::vector<std::uint32_t> rank(soup.points.size(), kUnknown);
    for (std::uint32_t i = 0; i < byPosition.size(); ++i) rank[byPosition[i].vertex] = i;
    for (RefinedSoup::Face& face : soup.faces) {
        for (std::uint32_t& c : face.corners) c = rank[c];
        std::rotate(face.corners.begin(),
                    std::min_element(face.corners.begin(), face.corners.end()), face.corners.end());
    }
    // The uncut faces and the pieces each come by input triangle (refineIntersections): merged,
    // then each cut triangle's pieces sorted.
    auto byOrigin = [](const RefinedSoup::Face& f, const RefinedSoup::Face& g) {
        return f.origin < g.origin;
    };
    std::inplace_merge(soup.faces.begin(),
                       std::is_sorted_until(soup.faces.begin(), soup.faces.end(), byOrigin),
                       soup.faces.end(), byOrigin);
    for (auto f = soup.faces.begin(); f != soup.faces.end();) {
        const auto end = std::find_if(
            f, soup.faces.end(), [&](const RefinedSoup::Face& g) { return g.origin != f->origin; });
        std::sort(f, end, [](const RefinedSoup::Face& a, const RefinedSoup::Face& b) {
            return a.corners < b.corners;
        });
        f = end;
    }
    std::vector<Point> points(byPosition.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) points[i] = soup.points[byPosition[i].vertex];
    soup.points = std::move(points);
}

// Whether no two triangles (corners: the surface vertices `fan`, below `vertices`) use an edge
// in the same direction: with closed surfaces (fanVertices pairs every edge with its twin and
// gives every fan around a position its vertex) each surface is then a 2-manifold over its
// vertices, as the refinement and the patches need. Until session 32 a CGAL surface mesh
// checked this as it took the faces (0.06 s of tree_3d's union).
bool eachEdgeOnce(const std::vector<std::uint32_t>& fan, std::uint32_t vertices) {
    std::vector<std::uint32_t> first(std::size_t{vertices} + 1, 0);
    for (const std::uint32_t v : fan) ++first[v + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<std::uint32_t> ends(fan.size());  // per vertex a: the ends b of its edges a → b
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::uint32_t c = 0; c < fan.size(); ++c) ends[next[fan[c]]++] = fan[nextCorner(c)];
    for (std::uint32_t a = 0; a < vertices; ++a) {
        const auto from = ends.begin() + first[a], to = ends.begin() + first[a + 1];
        std::sort(from, to);
        if (std::adjacent_find(from, to) != to) return false;
    }
    return true;
}

#if defined(RAMUS_ENABLE_ASSERTS)
// Per triangle (corners: the surface vertices `fan`, at `points`): whether it intersects
// another triangle other than in the corners or edge they share (CGAL's self-intersection test,
// exact predicates): the triangles the refinement cuts. The reference for
// intersectingTriangles.
std::vector<char> intersectingFaces(const std::vector<Point>& points,
                                    const std::vector<std::uint32_t>& fan) {
    SurfaceMesh m;
    for (const Point& p : points) m.add_vertex(p);
    for (std::size_t t = 0; 3 * t < fan.size(); ++t) {
        const FaceIndex f = m.add_face(VertexIndex(fan[3 * t]), VertexIndex(fan[3 * t + 1]),
                                       VertexIndex(fan[3 * t + 2]));
        RAMUS_ASSERT(f != SurfaceMesh::null_face());  // eachEdgeOnce held
    }
    std::vector<std::pair<FaceIndex, FaceIndex>> pairs;
    PMP::self_intersections(m, std::back_inserter(pairs));
    std::vector<char> intersecting(m.number_of_faces(), 0);
    for (const auto& [f, g] : pairs) intersecting[f.idx()] = intersecting[g.idx()] = 1;
    return intersecting;
}
#endif

// The triangles that intersect others cut along the intersections (detail::refineTriangles).
// Returns why the refinement failed, or nullptr.
const char* refineIntersections(const std::vector<Point>& points,
                                const std::vector<std::uint32_t>& fan,
                                const Intersections& intersections,
                                detail::RefinedTriangles& refined) {
    std::vector<char> inPair(intersections.cut.size(), 0);
    for (const auto& [s, t] : intersections.pairs) inPair[s] = inPair[t] = 1;
    if (inPair != intersections.cut) return "a degenerate triangle (corners on a line)";
    return detail::refineTriangles(points, fan, intersections.pairs, refined);
}

// Sets of nodes with winding numbers relative to their set's root (a union-find with offsets):
// winding(x) = winding(root) + offset(x).
class RelativeWindings {
public:
    explicit RelativeWindings(std::size_t nodes) : parent_(nodes), offset_(nodes, 0) {
        std::iota(parent_.begin(), parent_.end(), 0u);
    }

    // x's root, and x's winding number relative to it.
    std::pair<std::uint32_t, int> find(std::uint32_t x) {
        int sum = 0;
        std::uint32_t root = x;
        while (parent_[root] != root) {
            sum += offset_[root];
            root = parent_[root];
        }
        // Path compression: every node on the way points at the root.
        int left = sum;
        while (parent_[x] != root && x != root) {
            const std::uint32_t next = parent_[x];
            const int step = offset_[x];
            parent_[x] = root;
            offset_[x] = left;
            left -= step;
            x = next;
        }
        return {root, sum};
    }

    // Records winding(y) = winding(x) + change; false where that contradicts what is known.
    // `joined` counts the sets joined.
    bool link(std::uint32_t x, std::uint32_t y, int change) {
        const auto [rx, ox] = find(x);
        const auto [ry, oy] = find(y);
        if (rx == ry) return oy == ox + change;
        parent_[ry] = rx;
        offset_[ry] = ox + change - oy;
        ++joined;
        return true;
    }

    std::size_t joined = 0;

private:
    std::vector<std::uint32_t> parent_;
    std::vector<int> offset_;
};

// Which faces bound the union: per uncut input triangle (`keepTriangle`) and per region of a cut
// one (`keepRegion`, detail::RefinedTriangles::regions), whether the winding number just outside
// it (on the side its normals point to) is 0 (Zhou et al. 2016). Nodes: the uncut triangles and
// the regions. A node has the winding number of the node across each of its edges on the
// triangle's sides (the same sheet, no cut between), and the regions of one triangle differ by
// what the refinement found along its cuts (the inner side of a cut one more than the outer):
// the nodes so fall into sets with winding numbers relative to one another, as many as the
// input has connected surfaces, and one ray per set counts its first node's (windingByRays),
// from the centre of the node's triangle or largest piece, roughly along its normal, through the
// input triangles (corners `fan` at `points`). Until session 38 the refined pieces themselves
// were joined into patches across the edges that are not cut, and the winding numbers carried
// from patch to patch across the cuts: ABOP 1.24a's 576 k pieces (80 % of them dropped) were
// sorted, paired and joined where its 188 k regions (and 36 k uncut triangles) now are. Until
// session 32 every patch had its ray through the refined mesh (1.24a: 34 k rays, 0.35 s). `report`
// gets the patches (nodes joined across their sides) and those kept. Returns why the winding
// numbers disagree (a cut whose sides were told wrong; not met), or nullptr.
const char* classifyRegions(const std::vector<Point>& points, const std::vector<std::uint32_t>& fan,
                            const std::vector<char>& cut, const detail::RefinedTriangles& refined,
                            SolidUnionReport& report, std::vector<char>& keepTriangle,
                            std::vector<char>& keepRegion) {
    const auto triangles = static_cast<std::uint32_t>(cut.size());
    const std::size_t nodes = triangles + refined.regions.size();  // region r: triangles + r
    // The directed edges on the nodes' sides, bucketed by their start (a counting sort; a
    // bucket holds a vertex's few edges, each sheet's at most once each way).
    const std::size_t vertexCount = points.size() + refined.newPoints.size();
    struct Edge {
        std::uint32_t end, node;
    };
    std::vector<std::uint32_t> first(vertexCount + 1, 0);
    auto forEachSide = [&](auto visit) {
        for (std::uint32_t t = 0; t < triangles; ++t) {
            if (cut[t]) continue;
            const std::uint32_t* c = &fan[3 * std::size_t{t}];
            for (int k = 0; k < 3; ++k) visit(c[k], c[(k + 1) % 3], t);
        }
        for (const auto& [from, to, region] : refined.sides) visit(from, to, triangles + region);
    };
    forEachSide([&](std::uint32_t a, std::uint32_t, std::uint32_t) { ++first[a + 1]; });
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<Edge> edges(first.back());
    {
        std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
        forEachSide([&](std::uint32_t a, std::uint32_t b, std::uint32_t node) {
            edges[next[a]++] = {b, node};
        });
    }
    RelativeWindings windings(nodes);
    for (std::uint32_t a = 0; a < vertexCount; ++a) {
        for (std::uint32_t i = first[a]; i < first[a + 1]; ++i) {
            const std::uint32_t b = edges[i].end;
            if (b < a) continue;  // each edge once, from its lower end
            const auto last = edges.begin() + first[b + 1];
            const auto twin = std::find_if(edges.begin() + first[b], last,
                                           [&](const Edge& e) { return e.end == a; });
            if (twin == last) return "an edge of the refined surfaces alone";
            if (!windings.link(edges[i].node, twin->node, 0)) {
                return "the winding numbers across the sides disagree";
            }
        }
    }
    const std::size_t cutCount = static_cast<std::size_t>(std::count(cut.begin(), cut.end(), 1));
    report.patches = triangles - cutCount + refined.regions.size() - windings.joined;
    std::vector<std::uint32_t> patchOf(nodes);  // its root after the sides alone
    for (std::uint32_t x = 0; x < nodes; ++x) patchOf[x] = windings.find(x).first;
    for (std::uint32_t r = 1, firstOfTriangle = 0; r < refined.regions.size(); ++r) {
        if (refined.regions[r].origin != refined.regions[r - 1].origin) {
            firstOfTriangle = r;
            continue;
        }
        if (!windings.link(triangles + firstOfTriangle, triangles + r,
                           refined.regions[r].winding - refined.regions[firstOfTriangle].winding)) {
            return "the winding numbers along the cuts disagree";
        }
    }
    // The rays: one per set, from its first node (in builds with assertions also from every
    // region and every 16th uncut triangle, to check the sets against the rays).
    auto inUse = [&](std::uint32_t x) { return x >= triangles || !cut[x]; };
    std::vector<char> cast(nodes, 0);
    {
        std::vector<char> seen(nodes, 0);  // per root
        for (std::uint32_t x = 0; x < nodes; ++x) {
            if (!inUse(x)) continue;
            const std::uint32_t root = windings.find(x).first;
            cast[x] = !seen[root];
            seen[root] = 1;
#if defined(RAMUS_ENABLE_ASSERTS)
            cast[x] = cast[x] || x >= triangles || x % 16 == 0;
#endif
        }
    }
    auto at = [&](std::uint32_t v) -> const Point& {  // a refined vertex's point
        return v < points.size() ? points[v] : refined.newPoints[v - points.size()];
    };
    // A cast region's largest piece.
    std::vector<std::uint32_t> largest(refined.regions.size(), kUnknown);
    {
        std::vector<double> area(refined.regions.size(), -1.0);
        for (std::uint32_t f = 0; f < refined.pieces.size(); ++f) {
            const std::uint32_t r = refined.pieceRegion[f];
            if (!cast[triangles + r]) continue;
            const auto& c = refined.pieces[f].corners;
            const double a =
                CGAL::cross_product(at(c[1]) - at(c[0]), at(c[2]) - at(c[0])).squared_length();
            if (a > area[r]) {
                area[r] = a;
                largest[r] = f;
            }
        }
    }
    std::vector<std::uint32_t> rays;
    for (std::uint32_t x = 0; x < nodes; ++x) {
        if (cast[x]) rays.push_back(x);
    }
    std::vector<std::array<std::uint32_t, 3>> faces(triangles);
    for (std::size_t t = 0; t < triangles; ++t)
        faces[t] = {fan[3 * t], fan[3 * t + 1], fan[3 * t + 2]};
    const RayCrossings crossings(points, std::move(faces), rays.size() > kRaysWithoutTree);
    std::vector<int> counted(nodes, 0);  // where cast
    forEachOnCores(rays.size(), [&](std::size_t i) {
        const std::uint32_t x = rays[i];
        std::array<Point, 3> corners;
        std::uint32_t origin = x;
        if (x < triangles) {
            for (std::size_t k = 0; k < 3; ++k) corners[k] = points[fan[3 * std::size_t{x} + k]];
        } else {
            const RefinedSoup::Face& piece = refined.pieces[largest[x - triangles]];
            origin = piece.origin;
            for (std::size_t k = 0; k < 3; ++k) corners[k] = at(piece.corners[k]);
        }
        const Point centre = CGAL::centroid(corners[0], corners[1], corners[2]);
        Vector normal = CGAL::cross_product(corners[1] - corners[0], corners[2] - corners[0]);
        normal = normal / std::sqrt(normal.squared_length());
        // The winding number just outside the face, its input triangle left out.
        auto ray = [&](std::uint64_t k) {
            const std::uint64_t hash = 3 * (3 * std::uint64_t{x} + k);
            const Vector direction =
                normal + 0.1 * Vector(detail::hashUnit(hash), detail::hashUnit(hash + 1),
                                      detail::hashUnit(hash + 2));
            return crossings.count(centre, direction,
                                   [&](std::size_t hit) { return hit == origin; });
        };
        counted[x] = windingByRays(ray);
    });
    std::vector<int> rootWinding(nodes, 0);
    std::vector<char> rootKnown(nodes, 0);
    for (const std::uint32_t x : rays) {
        const auto [root, offset] = windings.find(x);
        if (!rootKnown[root]) rootWinding[root] = counted[x] - offset;
        rootKnown[root] = 1;
        RAMUS_ASSERT(counted[x] == rootWinding[root] + offset);
    }
    keepTriangle.assign(triangles, 0);
    keepRegion.assign(refined.regions.size(), 0);
    report.keptPatches = 0;
    for (std::uint32_t x = 0; x < nodes; ++x) {
        if (!inUse(x)) continue;
        const auto [root, offset] = windings.find(x);
        const char keep = rootWinding[root] + offset == 0;
        (x < triangles ? keepTriangle[x] : keepRegion[x - triangles]) = keep;
        report.keptPatches += keep && patchOf[x] == x;
    }
    return nullptr;
}

// The soup of the faces that bound the union: the uncut input triangles (corners `fan`, at
// `points`) with keepTriangle, then the pieces of the regions with keepRegion (classifyRegions).
RefinedSoup keptFaces(const std::vector<Point>& points, const std::vector<std::uint32_t>& fan,
                      const std::vector<char>& cut, const detail::RefinedTriangles& refined,
                      const std::vector<char>& keepTriangle, const std::vector<char>& keepRegion) {
    RefinedSoup soup;
    soup.points.reserve(points.size() + refined.newPoints.size());
    soup.points.insert(soup.points.end(), points.begin(), points.end());
    soup.points.insert(soup.points.end(), refined.newPoints.begin(), refined.newPoints.end());
    for (std::uint32_t t = 0; t < cut.size(); ++t) {
        if (cut[t] || !keepTriangle[t]) continue;
        const std::uint32_t* c = &fan[3 * std::size_t{t}];
        soup.faces.push_back(RefinedSoup::Face{t, {c[0], c[1], c[2]}});
    }
    for (std::size_t f = 0; f < refined.pieces.size(); ++f) {
        if (keepRegion[refined.pieceRegion[f]]) soup.faces.push_back(refined.pieces[f]);
    }
    return soup;
}

// Output vertices by a 64-bit key, each made once.
class VerticesByKey {
public:
    // The vertex made for `key`, made by make() where there is none yet.
    template <class Make>
    std::uint32_t get(std::uint64_t key, Make make) {
        const auto next = static_cast<std::uint32_t>(keys_.size());
        if (next == table_.capacity()) {
            table_.grow(2 * next, [&](std::uint32_t j) { return detail::splitMixFinal(keys_[j]); });
        }
        const std::uint32_t found = table_.findOrAdd(
            detail::splitMixFinal(key), next, [&](std::uint32_t j) { return keys_[j] == key; });
        if (found != next) return vertices_[found];
        keys_.push_back(key);
        vertices_.push_back(make());
        return vertices_.back();
    }
    std::size_t size() const { return keys_.size(); }

private:
    detail::IndexHashTable table_{1024};
    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> vertices_;
};

// Interpolates the input's vertex attributes at points of its triangles into a new mesh.
class CornerWriter {
public:
    // `moved`: per surface vertex its moved position; `fan`: per input corner its surface vertex;
    // `corners`: how many corners will be written (room for as many vertices is reserved: that
    // touches no memory, where growing the arrays would copy them).
    CornerWriter(const Mesh& input, const std::vector<Point>& moved,
                 const std::vector<std::uint32_t>& fan, Mesh& output, std::size_t corners)
        : in_(input), moved_(moved), fan_(fan), out_(output), firstCopy_(input.positions.size()) {
        out_.positions.reserve(corners);
        if (!in_.normals.empty()) out_.normals.reserve(corners);
        if (!in_.tangents.empty()) out_.tangents.reserve(corners);
        if (!in_.uvs.empty()) out_.uvs.reserve(corners);
        for (const VertexAttribute& a : input.attributes) {
            out_.attributes.push_back({a.name, a.components, {}});
            out_.attributes.back().values.reserve(corners * static_cast<std::size_t>(a.components));
        }
    }

    // The output vertex for point `p` (index `vertex` in the refined mesh) of a piece of input
    // triangle `t`.
    std::uint32_t corner(std::uint32_t t, std::uint32_t vertex, const Point& p) {
        const std::uint32_t* tri = &in_.indices[3 * std::size_t{t}];
        for (int k = 0; k < 3; ++k) {
            const Vec3 c = movedCorner(3 * std::size_t{t} + k);
            if (c.x() == p.x() && c.y() == p.y() && c.z() == p.z()) return copy(tri[k], vertex, c);
        }
        return interpolated_.get(std::uint64_t{vertex} << 32 | t,
                                 [&] { return interpolate(t, Vec3(p.x(), p.y(), p.z())); });
    }

    std::size_t interpolatedCount() const { return interpolated_.size(); }

private:
    // Input vertex `v` at refined vertex `vertex` (moved to `p`). Nearly every input vertex is
    // copied for one refined vertex only: that copy is found by v in an array (`firstCopy_`),
    // the others by both in a hash table (690 k lookups on tree_3d, 230 k triangles).
    std::uint32_t copy(std::uint32_t v, std::uint32_t vertex, const Vec3& p) {
        auto make = [&] {
            const std::uint32_t made = appendVertexCopy(out_, in_, v);
            out_.positions[made] = p.cast<float>();
            return made;
        };
        FirstCopy& first = firstCopy_[v];
        if (first.vertex == vertex) return first.made;
        if (first.vertex == kUnknown) {
            first = {vertex, make()};
            return first.made;
        }
        return copied_.get(std::uint64_t{v} << 32 | vertex, make);
    }

    std::uint32_t interpolate(std::uint32_t t, const Vec3& p) {
        const std::uint32_t* tri = &in_.indices[3 * std::size_t{t}];
        const Vec3 a = movedCorner(3 * std::size_t{t});
        const Vec3 b = movedCorner(3 * std::size_t{t} + 1);
        const Vec3 c = movedCorner(3 * std::size_t{t} + 2);
        const Vec3 normal = (b - a).cross(c - a);
        std::array<double, 3> w = {(b - p).cross(c - p).dot(normal),
                                   (c - p).cross(a - p).dot(normal),
                                   (a - p).cross(b - p).dot(normal)};
        double sum = 0.0;
        for (double& x : w) sum += (x = std::max(x, 0.0));
        if (!(sum > 0.0))
            w = {1.0, 0.0, 0.0};
        else
            for (double& x : w) x /= sum;
        const std::uint32_t made = append(p.cast<float>());
        if (!in_.normals.empty()) {
            Vec3f n = Vec3f::Zero();
            for (int k = 0; k < 3; ++k) n += static_cast<float>(w[k]) * in_.normals[tri[k]];
            const Vec3f face = normal.cast<float>();
            out_.normals.push_back(n.norm() > 1e-6f ? n.normalized() : face.normalized());
        }
        if (!in_.tangents.empty()) {
            Vec3f tangent = Vec3f::Zero();
            for (int k = 0; k < 3; ++k) {
                tangent += static_cast<float>(w[k]) * in_.tangents[tri[k]].head<3>();
            }
            if (!out_.normals.empty()) {
                const Vec3f& n = out_.normals.back();
                tangent -= n.dot(tangent) * n;
                if (tangent.norm() < 1e-6f) tangent = n.unitOrthogonal();
            }
            tangent.normalize();
            out_.tangents.emplace_back(tangent.x(), tangent.y(), tangent.z(),
                                       in_.tangents[tri[0]].w());
        }
        if (!in_.uvs.empty()) {
            Vec2f uv = Vec2f::Zero();
            for (int k = 0; k < 3; ++k) uv += static_cast<float>(w[k]) * in_.uvs[tri[k]];
            out_.uvs.push_back(uv);
        }
        for (std::size_t at = 0; at < in_.attributes.size(); ++at) {
            const auto width = static_cast<std::size_t>(in_.attributes[at].components);
            for (std::size_t i = 0; i < width; ++i) {
                double value = 0.0;
                for (int k = 0; k < 3; ++k) {
                    value += w[k] * in_.attributes[at].values[width * tri[k] + i];
                }
                out_.attributes[at].values.push_back(static_cast<float>(value));
            }
        }
        return made;
    }

    std::uint32_t append(const Vec3f& position) {
        out_.positions.push_back(position);
        return static_cast<std::uint32_t>(out_.positions.size() - 1);
    }

    const Mesh& in_;
    // Input corner c's moved position (floats).
    Vec3 movedCorner(std::size_t c) const {
        const Point& p = moved_[fan_[c]];
        return {p.x(), p.y(), p.z()};
    }

    const std::vector<Point>& moved_;        // per surface vertex
    const std::vector<std::uint32_t>& fan_;  // per input corner: its surface vertex
    Mesh& out_;
    struct FirstCopy {
        std::uint32_t vertex = kUnknown;  // refined
        std::uint32_t made = kUnknown;    // output
    };
    std::vector<FirstCopy> firstCopy_;  // per input vertex: its first copy
    VerticesByKey copied_;              // the others, by (input vertex, refined vertex)
    VerticesByKey interpolated_;        // by (refined vertex, input triangle)
};

// Directed edges a→b of the triangles over welded vertex ids, sorted: (a, b) and, to tell apart
// copies of one edge, the input vertex indices of its corners; `corner` is the corner at a.
struct DirectedEdge {
    std::uint64_t welded;
    std::uint64_t input;
    std::uint32_t corner;
    auto operator<=>(const DirectedEdge&) const = default;
};

// The directed edges of a mesh in that order, bucketed by their start a: a counting sort by a,
// then each bucket (a vertex's few edges) sorted, and the uses of an edge found in its start's
// bucket. Linear in the corners; a sort of all edges and binary searches over them took a
// quarter of the union's own bookkeeping on tree_3d (230 k triangles).
class DirectedEdges {
public:
    // `weld`: per mesh vertex its position's id, below `positions`.
    DirectedEdges(const std::vector<std::uint32_t>& weld, std::uint32_t positions,
                  const std::vector<std::uint32_t>& indices)
        : edges_(indices.size()), start_(std::size_t{positions} + 1, 0) {
        for (std::uint32_t c = 0; c < indices.size(); ++c) ++start_[weld[indices[c]] + 1];
        std::partial_sum(start_.begin(), start_.end(), start_.begin());
        std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
        for (std::uint32_t c = 0; c < indices.size(); ++c) {
            const std::uint32_t next = nextCorner(c);
            const std::uint32_t a = weld[indices[c]];
            edges_[fill[a]++] = {std::uint64_t{a} << 32 | weld[indices[next]],
                                 std::uint64_t{indices[c]} << 32 | indices[next], c};
        }
        for (std::uint32_t a = 0; a < positions; ++a) {
            std::sort(edges_.begin() + start_[a], edges_.begin() + start_[a + 1]);
        }
    }

    const std::vector<DirectedEdge>& all() const { return edges_; }

    // The uses of the welded edge `key` (a << 32 | b), as a range of all().
    std::pair<const DirectedEdge*, const DirectedEdge*> uses(std::uint64_t key) const {
        const std::size_t a = key >> 32;
        const DirectedEdge* first = edges_.data() + start_[a];
        const DirectedEdge* last = edges_.data() + start_[a + 1];
        first = std::lower_bound(first, last, DirectedEdge{key, 0, 0});
        const DirectedEdge* end = first;
        while (end != last && end->welded == key) ++end;
        return {first, end};
    }

private:
    std::vector<DirectedEdge> edges_;
    std::vector<std::uint32_t> start_;  // per position a: its first edge; then the end
};

std::uint64_t reversed(std::uint64_t edge) { return edge << 32 | edge >> 32; }

// Whether no triangle has two corners at one position (a first condition of closed surfaces).
bool noCollapsedTriangles(const std::vector<std::uint32_t>& weld,
                          const std::vector<std::uint32_t>& indices) {
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = weld[indices[t]], b = weld[indices[t + 1]],
                            c = weld[indices[t + 2]];
        if (a == b || b == c || c == a) return false;
    }
    return true;
}

// Edges of closed surfaces (fanVertices found them closed) used more than once in each direction:
// where k > 1 sheets meet along one edge.
std::size_t pinchedEdges(const std::vector<DirectedEdge>& edges) {
    std::size_t pinched = 0;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].welded == edges[i].welded) ++j;
        if (j - i > 1 && edges[i].welded < reversed(edges[i].welded)) ++pinched;
        i = j;
    }
    return pinched;
}

// Per corner (3 t + k): the vertex of the closed surfaces it belongs to. Corners are joined
// across each edge with the twin corner of the neighbouring triangle, so where surfaces only
// touch at a point (a non-manifold vertex: two fans of triangles around one position) each fan
// gets its own vertex. Where k surfaces share an edge, its uses a→b are paired with the uses
// b→a of the same input vertices first (the triangles of one fan or cap share their vertices),
// the rest in order, so the surfaces keep their own vertices there and the move pulls them
// apart. Numbered in order of first appearance; `count` receives how many.
//
// Nothing where the triangles (without collapsed ones: noCollapsedTriangles) do not bound closed
// oriented surfaces, where a welded edge is not used as often in one direction as in the other
// (once each way where the surfaces are 2-manifold; k times each way where k surfaces share the
// edge, as two tips ending at one point from different directions share their caps' spokes).
// Each edge a → b with a < b is matched with its uses b → a here, where they are paired (a
// lookup in b's bucket, mostly a cache miss: once per edge), and the edges b → a without a
// partner are the uses left over.
std::optional<std::vector<std::uint32_t>> fanVertices(const std::vector<std::uint32_t>& indices,
                                                      const DirectedEdges& table,
                                                      std::uint32_t* count, bool* turned) {
    const std::vector<DirectedEdge>& edges = table.all();
    const std::size_t corners = indices.size();
    // Per corner whose edge is a→b: the corner of the use b→a it is paired with; edges shared
    // by several sheets listed in `shared` (their uses a→b in all()).
    std::vector<std::uint32_t> twinOf(corners, kUnknown);
    std::vector<std::pair<std::size_t, std::size_t>> shared;
    std::vector<char> paired(corners, 0);
    auto pair = [&](std::uint32_t c, std::uint32_t twin) {
        paired[c] = paired[twin] = 1;
        twinOf[c] = twin;
    };
    std::size_t matched = 0;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].welded == edges[i].welded) ++j;
        const std::uint64_t reverse = reversed(edges[i].welded);
        if (edges[i].welded < reverse) {  // each undirected edge once
            const auto [first, last] = table.uses(reverse);
            if (last - first != static_cast<std::ptrdiff_t>(j - i)) return std::nullopt;
            matched += 2 * (j - i);
            if (j - i > 1) shared.emplace_back(i, j);
            for (int pass = 0; pass < 2; ++pass) {  // same input vertices first, then any
                for (std::size_t k = i; k < j; ++k) {
                    if (paired[edges[k].corner]) continue;
                    for (auto twin = first; twin != last; ++twin) {
                        if (paired[twin->corner]) continue;
                        if (pass == 0 && twin->input != reversed(edges[k].input)) continue;
                        pair(edges[k].corner, twin->corner);
                        break;
                    }
                }
            }
        }
        i = j;
    }
    if (matched != edges.size()) return std::nullopt;
    std::vector<std::uint32_t> vertex(corners);
    std::vector<std::uint32_t> parent(corners);
    auto number = [&] {
        std::iota(parent.begin(), parent.end(), 0u);
        // The twin b→a of corner c's edge a→b starts at b: its corner is a's neighbour in the
        // same fan as c's next.
        for (std::uint32_t c = 0; c < corners; ++c) {
            const std::uint32_t twin = twinOf[c];
            if (twin == kUnknown) continue;
            parent[findRoot(parent, nextCorner(twin))] = findRoot(parent, c);
            parent[findRoot(parent, twin)] = findRoot(parent, nextCorner(c));
        }
        std::vector<std::uint32_t> numbered(corners, kUnknown);
        std::uint32_t next = 0;
        for (std::size_t c = 0; c < corners; ++c) {
            std::uint32_t& n = numbered[findRoot(parent, static_cast<std::uint32_t>(c))];
            if (n == kUnknown) n = next++;
            vertex[c] = n;
        }
        *count = next;
    };
    number();
    // Where a shared edge's uses a→b start and end at the same two vertices, the edge is used
    // twice between them, which no move of a vertex parts (a surface mesh does not even take
    // it): the pairing there is turned by one (each use a→b takes the next one's twin), which
    // splits each end into a vertex per sheet (session 29: ABOP 1.24c, where the fan around
    // one end had passed through the edge twice).
    *turned = false;
    for (const auto& [i, j] : shared) {
        bool twice = false;
        for (std::size_t k = i; k < j && !twice; ++k) {
            for (std::size_t l = k + 1; l < j && !twice; ++l) {
                const std::uint32_t c = edges[k].corner, d = edges[l].corner;
                twice = vertex[c] == vertex[d] && vertex[nextCorner(c)] == vertex[nextCorner(d)];
            }
        }
        if (!twice) continue;
        const std::uint32_t firstTwin = twinOf[edges[i].corner];
        for (std::size_t k = i; k + 1 < j; ++k)
            twinOf[edges[k].corner] = twinOf[edges[k + 1].corner];
        twinOf[edges[j - 1].corner] = firstTwin;
        *turned = true;
    }
    if (*turned) number();
    return vertex;
}

// Why an attempt failed: for the input (no use trying again) or in the geometry.
// The closed surfaces of a mesh: vertices welded by position, and per corner the vertex of
// its surface (fanVertices).
struct Surfaces {
    std::vector<std::uint32_t> weld;  ///< per mesh vertex: its position's id
    std::uint32_t positions = 0;      ///< distinct positions
    bool closed = false;              ///< closed oriented surfaces (fanVertices); fan only then
    std::vector<std::uint32_t> fan;   ///< per corner: its surface vertex
    std::uint32_t vertices = 0;       ///< surface vertices
    std::size_t pinchedEdges = 0;     ///< edges where several sheets meet (when closed)
    /// Whether parting positions needs surfacesOf again (partSurfaces): fanVertices turned the
    /// pairing at an edge used twice, or the mesh's vertices were split since where sheets are
    /// pinched (splitSharedMeshVertices: the pairing of a pinched edge's uses follows the vertex
    /// ids).
    bool recomputeOnPart = false;
};

// From the mesh's triangles and `weld`, its vertices' position ids (weldByPosition, `positions`
// of them): everything in Surfaces follows from these two.
Surfaces surfacesOf(std::vector<std::uint32_t> weld, std::uint32_t positions,
                    const std::vector<std::uint32_t>& indices) {
    Surfaces s;
    s.weld = std::move(weld);
    s.positions = positions;
    if (!noCollapsedTriangles(s.weld, indices)) return s;
    const DirectedEdges edges(s.weld, s.positions, indices);
    std::optional<std::vector<std::uint32_t>> fan =
        fanVertices(indices, edges, &s.vertices, &s.recomputeOnPart);
    s.closed = fan.has_value();
    if (s.closed) {
        s.fan = std::move(*fan);
        s.pinchedEdges = pinchedEdges(edges.all());
    }
    return s;
}

Surfaces surfacesOf(const Mesh& mesh) {
    std::uint32_t positions = 0;
    std::vector<std::uint32_t> weld = weldByPosition(mesh.positions, &positions);
    return surfacesOf(std::move(weld), positions, mesh.indices);
}

// Keeps the triangles of `mesh` with keep[t] (keepTriangles) and replaces its closed `surfaces`
// by those of the result. Where the triangles dropped share no position with those kept (whole
// surfaces apart from the rest: pockets, parted pieces) and no sheets are pinched together,
// every edge of the kept triangles pairs as before, so the surfaces kept are the old ones
// numbered again in order of first appearance, as surfacesOf numbers them, without welding and
// pairing the mesh again (on ABOP 1.24a each call had taken 35–45 ms); else surfacesOf.
void keepTrianglesAndSurfaces(Mesh& mesh, Surfaces& surfaces, const std::vector<char>& keep) {
    bool apart = surfaces.closed && surfaces.pinchedEdges == 0;
    std::vector<char> droppedAt(apart ? surfaces.positions : 0, 0);  // per position
    for (std::size_t c = 0; apart && c < mesh.indices.size(); ++c) {
        if (!keep[c / 3]) droppedAt[surfaces.weld[mesh.indices[c]]] = 1;
    }
    for (std::size_t c = 0; apart && c < mesh.indices.size(); ++c) {
        apart = !keep[c / 3] || !droppedAt[surfaces.weld[mesh.indices[c]]];
    }
    if (!apart) {
        keepTriangles(mesh, keep);
        surfaces = surfacesOf(mesh);
        return;
    }
    std::vector<char> usedBefore(mesh.positions.size(), 0);  // per vertex: by a kept triangle
    std::vector<std::uint32_t> fan;
    fan.reserve(mesh.indices.size());
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        if (!keep[c / 3]) continue;
        usedBefore[mesh.indices[c]] = 1;
        fan.push_back(surfaces.fan[c]);
    }
    // Renumbers old ids in order of first appearance in `ids` (in place); returns how many.
    auto renumber = [](std::vector<std::uint32_t>& ids, std::size_t before) {
        std::vector<std::uint32_t> number(before, kUnknown);
        std::uint32_t next = 0;
        for (std::uint32_t& id : ids) {
            std::uint32_t& n = number[id];
            if (n == kUnknown) n = next++;
            id = n;
        }
        return next;
    };
    std::vector<std::uint32_t> weld;  // per vertex kept (removeUnusedVertices keeps their order)
    weld.reserve(mesh.positions.size());
    for (std::size_t v = 0; v < usedBefore.size(); ++v) {
        if (usedBefore[v]) weld.push_back(surfaces.weld[v]);
    }
    Surfaces kept;
    kept.positions = renumber(weld, surfaces.positions);
    kept.weld = std::move(weld);
    kept.vertices = renumber(fan, surfaces.vertices);
    kept.fan = std::move(fan);
    kept.closed = true;
    keepTriangles(mesh, keep);
    surfaces = std::move(kept);
    RAMUS_ASSERT([&] {
        const Surfaces again = surfacesOf(mesh);
        return again.closed && again.weld == surfaces.weld &&
               again.positions == surfaces.positions && again.fan == surfaces.fan &&
               again.vertices == surfaces.vertices && again.pinchedEdges == 0;
    }());
}

// `p`, the position of surface vertex `v`, moved by up to `step` along each axis (a fixed hash
// of `salt` and `v`), as floats.
Vec3f hashMoved(Vec3f p, std::uint32_t v, double step, std::uint64_t salt) {
    for (unsigned axis = 0; axis < 3; ++axis) {
        const double h = detail::hashUnit(salt + 3 * std::uint64_t{v} + axis);
        p[axis] = static_cast<float>(p[axis] + h * step);
    }
    return p;
}

// postponed: the move made more triangles intersect than allowed (unionAttempt's cutLimit);
// overLimit: the cut would be more work than the union takes on (overWorkLimit).
enum class Outcome { done, badInput, retry, postponed, overLimit };

Outcome failWith(SolidUnionReport& report, const char* why, Outcome outcome) {
    report.failure = why;
    return outcome;
}

// One attempt on the closed surfaces `input` of `mesh` with the positions moved by up to
// `jitter` (fraction of the mesh's extent) with hash salt `salt`; only triangles that `mayCross`
// (per triangle of `mesh`; empty: all) are looked at for intersections. `suspect` gets, where the
// union cut anything, per triangle of the result whether it is a piece of a cut one (the others are
// input triangles that intersected nothing, where they were). `cut` gets the number
// of input triangles that intersect others after the move; where that is more than `cutLimit`,
// nothing more is done (Outcome::postponed). When done, `united` gets the new mesh (the input
// where nothing was cut) and `unitedSurfaces` its closed surfaces.
Outcome unionAttempt(const Mesh& mesh, const Surfaces& input, SolidUnionReport& report,
                     double jitter, std::uint64_t salt, const std::vector<char>& mayCross,
                     std::size_t cutLimit, std::size_t& cut, Mesh& united,
                     std::vector<char>& suspect, Surfaces& unitedSurfaces) {
    const std::vector<std::uint32_t>& fan = input.fan;
    const std::uint32_t vertices = input.vertices;

    // 1. Surface vertices, moved off exact coincidences (to floats: see the file comment).
    const Aabb box = mesh.bounds();
    const double step = jitter * box.extent().maxCoeff();
    // The floats are stored before they are read back as doubles: GCC 12's SLP vectorizer at
    // -O3 dropped the rounding when the double was taken from the float just computed
    // (CMakeLists.txt also turns that vectorizer off for this file).
    std::vector<Vec3f> movedFloat(vertices);
    std::vector<char> made(vertices, 0);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t v = fan[c];
        if (made[v]) continue;
        movedFloat[v] = hashMoved(mesh.positions[mesh.indices[c]], v, step, salt);
        made[v] = 1;
    }
    if (!eachEdgeOnce(fan, vertices)) {
        return failWith(report, "the input is not 2-manifold", Outcome::badInput);
    }

    // 2. Cut the triangles along their intersections.
    std::vector<Point> points;  // per surface vertex: its moved position
    points.reserve(vertices);
    for (const Vec3f& p : movedFloat) points.emplace_back(p.x(), p.y(), p.z());
    const Intersections intersections = intersectingTriangles(points, fan, mayCross);
    if (overWorkLimit(mesh.triangleCount(), intersections, report)) return Outcome::overLimit;
    const std::vector<char>& intersecting = intersections.cut;
    RAMUS_ASSERT(intersecting == intersectingFaces(points, fan));
    cut = static_cast<std::size_t>(std::count(intersecting.begin(), intersecting.end(), 1));
    if (cut > cutLimit) return Outcome::postponed;
    if (cut == 0) {
        report.outputComponents = report.inputComponents;  // nothing intersects: keep the input
        report.patches = report.keptPatches = report.outputComponents;
        united = mesh;
        unitedSurfaces = input;
        return Outcome::done;
    }
    detail::RefinedTriangles refined;
    if (const char* failure = refineIntersections(points, fan, intersections, refined)) {
        return failWith(report, failure, Outcome::retry);
    }

    // 3. Faces on the union's boundary.
    std::vector<char> keepTriangle, keepRegion;
    if (const char* failure =
            classifyRegions(points, fan, intersecting, refined, report, keepTriangle, keepRegion)) {
        return failWith(report, failure, Outcome::retry);
    }
    RefinedSoup soup = keptFaces(points, fan, intersecting, refined, keepTriangle, keepRegion);
    refined = {};
    canonicalOrder(soup);

    // 4. The kept pieces, by primitive.
    std::vector<std::uint32_t> primitiveOf(mesh.triangleCount(), 0);
    for (std::uint32_t p = 0; p < mesh.primitives.size(); ++p) {
        const MeshPrimitive& prim = mesh.primitives[p];
        for (std::uint32_t t = prim.firstIndex / 3; t < (prim.firstIndex + prim.indexCount) / 3;
             ++t) {
            primitiveOf[t] = p;
        }
    }
    Mesh out;
    out.name = mesh.name;
    out.materials = mesh.materials;
    CornerWriter writer(mesh, points, fan, out, 3 * soup.faces.size());
    const std::size_t primitiveCount = std::max<std::size_t>(mesh.primitives.size(), 1);
    std::vector<std::vector<std::uint32_t>> byPrimitive(primitiveCount);
    std::vector<std::vector<char>> piecesByPrimitive(primitiveCount);
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        const std::uint32_t t = soup.faces[f].origin;
        std::vector<std::uint32_t>& indices = byPrimitive[primitiveOf[t]];
        for (const std::uint32_t v : soup.faces[f].corners) {
            indices.push_back(writer.corner(t, v, soup.points[v]));
        }
        piecesByPrimitive[primitiveOf[t]].push_back(intersecting[t]);
    }
    suspect.clear();
    for (std::size_t p = 0; p < primitiveCount; ++p) {
        const auto first = static_cast<std::uint32_t>(out.indices.size());
        out.indices.insert(out.indices.end(), byPrimitive[p].begin(), byPrimitive[p].end());
        suspect.insert(suspect.end(), piecesByPrimitive[p].begin(), piecesByPrimitive[p].end());
        if (mesh.primitives.empty() || byPrimitive[p].empty()) continue;
        MeshPrimitive prim = mesh.primitives[p];
        prim.firstIndex = first;
        prim.indexCount = static_cast<std::uint32_t>(byPrimitive[p].size());
        out.primitives.push_back(std::move(prim));
    }
    report.newVertices = writer.interpolatedCount();

    // 5. Check, then replace.
    std::uint32_t outDistinct = 0;
    std::vector<std::uint32_t> outWeld = weldByPosition(out.positions, &outDistinct);
    const std::vector<char> uncollapsed = uncollapsedTriangles(outWeld, out.indices);
    if (std::find(uncollapsed.begin(), uncollapsed.end(), 0) != uncollapsed.end()) {
        keepTriangles(out, uncollapsed);
        keepFlags(suspect, uncollapsed);
        if (out.indices.empty()) return failWith(report, "no surface was left", Outcome::retry);
        outWeld = weldByPosition(out.positions, &outDistinct);
    }
    Surfaces surfaces = surfacesOf(std::move(outWeld), outDistinct, out.indices);
    if (!surfaces.closed) {
        return failWith(report, "the union's surface is not closed after rounding", Outcome::retry);
    }
    const std::vector<char> outer = outerSurfaces(out, surfaces.weld, surfaces.positions, report);
    if (std::find(outer.begin(), outer.end(), 0) != outer.end()) {
        keepFlags(suspect, outer);
        keepTrianglesAndSurfaces(out, surfaces, outer);
        if (out.indices.empty()) return failWith(report, "no surface was left", Outcome::retry);
    }
    report.outputComponents = countComponents(surfaces.weld, surfaces.positions, out.indices);
    united = std::move(out);
    unitedSurfaces = std::move(surfaces);
    return Outcome::done;
}

#if defined(RAMUS_ENABLE_ASSERTS)
// Pairs of the triangles `triangles` of the closed surfaces `surfaces` of `mesh` that intersect
// other than in corners or edges they share (exact predicates on the float positions), as
// triangle indices; false if some of them did not go into the surface mesh (left out).
bool intersectingPairs(const Mesh& mesh, const Surfaces& surfaces,
                       const std::vector<std::uint32_t>& triangles,
                       std::vector<detail::TrianglePair>& pairs) {
    SurfaceMesh m;
    std::vector<std::uint32_t> local(surfaces.vertices, kUnknown);
    std::vector<std::uint32_t> triangleOf;  // per face
    triangleOf.reserve(triangles.size());
    for (std::uint32_t t : triangles) {
        std::array<VertexIndex, 3> corners;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t c = 3 * std::size_t{t} + k;
            std::uint32_t& v = local[surfaces.fan[c]];
            if (v == kUnknown) {
                const Vec3f& p = mesh.positions[mesh.indices[c]];
                v = static_cast<std::uint32_t>(m.add_vertex(Point(p.x(), p.y(), p.z())).idx());
            }
            corners[k] = VertexIndex(v);
        }
        if (m.add_face(corners[0], corners[1], corners[2]) != SurfaceMesh::null_face()) {
            triangleOf.push_back(t);
        }
    }
    std::vector<std::pair<FaceIndex, FaceIndex>> faces;
    PMP::self_intersections(m, std::back_inserter(faces));
    pairs.clear();
    for (const auto& [f, g] : faces) pairs.emplace_back(triangleOf[f.idx()], triangleOf[g.idx()]);
    return triangleOf.size() == triangles.size();
}
#endif

// Pairs of triangles of the closed surfaces `mesh` that intersect and share no position, or
// are neighbours on one sheet that fold through each other beside what they share (since
// session 35; detail::trianglesCross, exact predicates on the float positions, welded by
// position, also what the crossing repair counts since session 36): what rounding the
// cut positions to float left where surfaces only graze each other. In order. `surfaces`:
// surfacesOf(mesh), closed (Surfaces::closed). Triangles that are not `suspect`
// (input triangles that crossed nothing, where they still are; after moves, those that neither
// moved nor crossed) do not cross each other, so only pairs with a suspect are tested: the boxes of
// the suspects against all boxes (detail::overlappingBoxes), then the exact triangle test, on two
// cores. An empty `suspect` tests the whole mesh. Until session 29 the triangles near the suspects
// went through CGAL's self-intersection test on a surface mesh of them (the same pairs on tree_3d,
// ABOP 1.24a and 2.8c), which builds that mesh and tests every pair of boxes, most of them
// neighbours that share a corner; about 5–10 % of tree_3d's union in paired runs. `boxes`:
// scratch for the triangles' boxes, kept by the caller between counts (fillTriangleBoxes).
std::vector<detail::TrianglePair> crossingPairs(const Mesh& mesh, const Surfaces& surfaces,
                                                const std::vector<char>& suspect,
                                                std::vector<detail::Box3>& boxes) {
    const std::vector<std::uint32_t>& weld = surfaces.weld;
    auto positionOf = [&](std::uint32_t t, int k) {
        return weld[mesh.indices[3 * std::size_t{t} + static_cast<std::size_t>(k)]];
    };
    auto point = [&](std::uint32_t t, std::size_t k) {
        const Vec3f& p = mesh.positions[mesh.indices[3 * std::size_t{t} + k]];
        return Point(p.x(), p.y(), p.z());
    };
    std::vector<Point> sheetPoints(surfaces.vertices, Point(0, 0, 0));  // per surface vertex
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const Vec3f& p = mesh.positions[mesh.indices[c]];
        sheetPoints[surfaces.fan[c]] = Point(p.x(), p.y(), p.z());
    }
    fillTriangleBoxes(boxes, mesh.triangleCount(), point, [](std::uint32_t) { return true; });
    const std::vector<detail::TrianglePair> crossing =
        overlappingPairsWhere(boxes, suspect, [&](std::uint32_t s, std::uint32_t t) {
            return detail::trianglesCross(
                [&](std::uint32_t v) -> const Point& { return sheetPoints[v]; },
                &surfaces.fan[3 * std::size_t{s}], &surfaces.fan[3 * std::size_t{t}],
                [&](int i, int j) { return positionOf(s, i) == positionOf(t, j); });
        });
#if defined(RAMUS_ENABLE_ASSERTS)
    // The premise of the local search and the test itself, checked in the tests against CGAL's
    // self-intersection test over the whole mesh (where every triangle went into its surface
    // mesh): no other pair (the premise failed in Release when GCC left the moved positions
    // unrounded, CMakeLists.txt).
    std::vector<std::uint32_t> every(mesh.triangleCount());
    std::iota(every.begin(), every.end(), 0u);
    std::vector<detail::TrianglePair> everyPair;
    auto sheetVertexOf = [&](std::uint32_t t, int k) {  // its surface vertex
        return surfaces.fan[3 * std::size_t{t} + static_cast<std::size_t>(k)];
    };
    if (intersectingPairs(mesh, surfaces, every, everyPair)) {
        std::vector<detail::TrianglePair> reference;
        for (const auto& [s, t] : everyPair) {
            // (f, f): CGAL's report of a degenerate triangle, which is not tested here; pairs
            // that share a position through different surface vertices are counted apart.
            bool touching = false;
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) {
                    touching = touching || (positionOf(s, i) == positionOf(t, j) &&
                                            sheetVertexOf(s, i) != sheetVertexOf(t, j));
                }
            }
            if (s != t && !touching) {
                reference.emplace_back(std::min(s, t), std::max(s, t));
            }
        }
        std::sort(reference.begin(), reference.end());
        RAMUS_ASSERT(reference == crossing);
    }
#endif
    return crossing;
}

// Per triangle of `mesh`: whether it is in one of the pairs `crossing` (all its crossing pairs)
// or has a corner that `surface` (crossingSurfaceOf(mesh, surfaces), moved) moves: the others
// crossed nothing and will not while they stay.
std::vector<char> trianglesMovedOrCrossing(const Mesh& mesh, const Surfaces& surfaces,
                                           const detail::CrossingSurface& surface,
                                           const std::vector<detail::TrianglePair>& crossing) {
    std::vector<char> suspect(mesh.triangleCount(), 0);
    for (const auto& [s, t] : crossing) suspect[s] = suspect[t] = 1;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        if (surface.points[surfaces.fan[c]] != mesh.positions[mesh.indices[c]]) {
            suspect[c / 3] = 1;
        }
    }
    return suspect;
}

// Largest moves of a corner that separates a crossing pair or parts pinched sheets, as fractions
// of the mesh's extent, one round of repairs each while defects are left: first the first
// attempt's own move (grazes measured reached at most 5.7e-6 of it across the other triangle,
// docs/welded.md), then the next attempts' (a new attempt moves every vertex that far). Before
// session 26 there was one round: the few pairs or pinched edges it left cost a whole new attempt
// (ABOP 1.24a, 1.24b, 1.31a: 1 or 2 defects after the first).
constexpr double kSeparationMoves[] = {1e-5, 3e-5, 1e-4};

// The closed surfaces `surfaces` of `mesh` as surface vertices and triangles for
// crossing_repair.hpp: all copies of a surface vertex move together, and a mesh vertex that
// belongs to several surface vertices stays.
detail::CrossingSurface crossingSurfaceOf(const Mesh& mesh, const Surfaces& surfaces) {
    const std::vector<std::uint32_t>& fan = surfaces.fan;
    detail::CrossingSurface surface;
    surface.points.resize(surfaces.vertices);
    surface.fixed.assign(surfaces.vertices, 0);
    std::vector<std::uint32_t> owner(mesh.positions.size(), kUnknown);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t vertex = mesh.indices[c];
        surface.points[fan[c]] = mesh.positions[vertex];
        if (owner[vertex] == kUnknown) owner[vertex] = fan[c];
        if (owner[vertex] != fan[c]) surface.fixed[fan[c]] = surface.fixed[owner[vertex]] = 1;
    }
    surface.triangles.resize(mesh.triangleCount());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        surface.triangles[t] = {fan[3 * t], fan[3 * t + 1], fan[3 * t + 2]};
    }
    return surface;
}

// Replaces the closed `surfaces` of a mesh (corners `indices`) by those after moves that gave its
// vertices the position ids `weld` (weldByPosition, `positions` of them), where the moves only
// parted positions (no two joined) and surfaces.recomputeOnPart is not set; else false, nothing
// changed. As every copy of a surface vertex moves with it (crossingSurfaceOf), the two uses of
// an edge that fanVertices paired still start and end at the same positions, and it pairs them
// again (the uses of an edge are a part of the uses before, in the same order), so the fans and
// their vertices stay; only edges at parted positions can stop being pinched. surfacesOf had
// taken 17 ms of each of ABOP 1.24a's 23 ms takeMoves (its moves part touching sheets).
bool partSurfaces(Surfaces& surfaces, std::vector<std::uint32_t>& weld, std::uint32_t positions,
                  const std::vector<std::uint32_t>& indices) {
    if (!surfaces.closed || surfaces.recomputeOnPart) return false;
    std::vector<std::uint32_t> before(positions, kUnknown);   // per position: its id before
    std::vector<std::uint32_t> parts(surfaces.positions, 0);  // per id before: positions now
    for (std::size_t v = 0; v < weld.size(); ++v) {
        std::uint32_t& id = before[weld[v]];
        if (id == kUnknown) ++parts[id = surfaces.weld[v]];
        if (id != surfaces.weld[v]) return false;  // two positions joined
    }
    std::size_t pinched = surfaces.pinchedEdges;
    if (pinched > 0) {
        // Edges a → b (a < b before) at a parted position: pinched before and now.
        std::vector<std::uint64_t> was, is;
        for (std::uint32_t c = 0; c < indices.size(); ++c) {
            const std::uint32_t u = indices[c], w = indices[nextCorner(c)];
            const std::uint32_t a = surfaces.weld[u], b = surfaces.weld[w];
            if (a > b || (parts[a] < 2 && parts[b] < 2)) continue;
            was.push_back(std::uint64_t{a} << 32 | b);
            is.push_back(std::uint64_t{weld[u]} << 32 | weld[w]);
        }
        auto usedMoreThanOnce = [](std::vector<std::uint64_t>& keys) {
            std::sort(keys.begin(), keys.end());
            std::size_t count = 0;
            for (std::size_t i = 0; i < keys.size();) {
                std::size_t j = i;
                while (j < keys.size() && keys[j] == keys[i]) ++j;
                count += j - i > 1;
                i = j;
            }
            return count;
        };
        pinched = pinched - usedMoreThanOnce(was) + usedMoreThanOnce(is);
    }
    surfaces.weld = std::move(weld);
    surfaces.positions = positions;
    surfaces.pinchedEdges = pinched;
    RAMUS_ASSERT([&] {
        const Surfaces again = surfacesOf(surfaces.weld, positions, indices);
        return again.closed && again.fan == surfaces.fan && again.vertices == surfaces.vertices &&
               again.pinchedEdges == surfaces.pinchedEdges && !again.recomputeOnPart;
    }());
    return true;
}

// Writes the moved points of `surface` (crossingSurfaceOf(mesh, surfaces)) into `mesh` and
// replaces `surfaces` by the new ones; a result that is no longer closed (a move joined two
// positions) is not taken: false, both unchanged.
bool takeMoves(Mesh& mesh, Surfaces& surfaces, const detail::CrossingSurface& surface) {
    std::vector<Vec3f> before = mesh.positions;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        mesh.positions[mesh.indices[c]] = surface.points[surfaces.fan[c]];
    }
    std::uint32_t positions = 0;
    std::vector<std::uint32_t> weld = weldByPosition(mesh.positions, &positions);
    // Ids are numbered in order of first appearance: the same ids, the same positions coincide
    // as before, and so the same surfaces (most moves part nothing and join nothing).
    if (weld == surfaces.weld || partSurfaces(surfaces, weld, positions, mesh.indices)) return true;
    Surfaces moved = surfacesOf(std::move(weld), positions, mesh.indices);
    if (!moved.closed) {
        mesh.positions = std::move(before);
        return false;
    }
    surfaces = std::move(moved);
    return true;
}

// Surface vertices at pinched edges (closed `surfaces`), in the order unpinchVertices tries
// them: at each edge where k > 1 sheets meet, the two corners of every sheet but the first, then
// the first sheet's (which move where a corner of the others cannot: session 28, ABOP 1.24b's
// only pinched edge had a corner shared with a third surface vertex, which stays, and the other
// turned a sliver over).
std::vector<std::uint32_t> pinchedSheetCorners(const Mesh& mesh, const Surfaces& surfaces) {
    const DirectedEdges table(surfaces.weld, surfaces.positions, mesh.indices);
    const std::vector<DirectedEdge>& edges = table.all();
    std::vector<std::uint32_t> vertices;
    std::vector<char> listed(surfaces.vertices, 0);
    auto list = [&](std::uint32_t corner) {
        for (const std::uint32_t c : {corner, nextCorner(corner)}) {
            const std::uint32_t v = surfaces.fan[c];
            if (!listed[v]) vertices.push_back(v);
            listed[v] = 1;
        }
    };
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].welded == edges[i].welded) ++j;
        if (j - i > 1 && edges[i].welded < reversed(edges[i].welded)) {
            for (std::size_t k = i + 1; k < j; ++k) list(edges[k].corner);
            list(edges[i].corner);
        }
        i = j;
    }
    return vertices;
}

// Gives every surface vertex of `surfaces` (closed, of `mesh`) mesh vertices of its own: where
// one mesh vertex serves several (surfaces touching at a point: the union keeps such points
// where pieces of one input triangle on both sides of a cut meet, about 400–600 on ABOP 1.24a
// and 1.24c), the corners of all but the first get a copy of it. Positions, surface vertices
// and fans stay as they are.
void splitSharedMeshVertices(Mesh& mesh, Surfaces& surfaces) {
    std::vector<std::uint32_t> owner(mesh.positions.size(), kUnknown);
    std::unordered_map<std::uint64_t, std::uint32_t> copies;  // (mesh, surface vertex) → copy
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t vertex = mesh.indices[c];
        const std::uint32_t surfaceVertex = surfaces.fan[c];
        if (owner[vertex] == kUnknown) owner[vertex] = surfaceVertex;
        if (owner[vertex] == surfaceVertex) continue;
        const auto [at, added] =
            copies.try_emplace(std::uint64_t{vertex} << 32 | surfaceVertex, kUnknown);
        if (added) {
            at->second = appendVertexCopy(mesh, mesh, vertex);
            surfaces.weld.push_back(surfaces.weld[vertex]);
            surfaces.recomputeOnPart = surfaces.recomputeOnPart || surfaces.pinchedEdges > 0;
        }
        mesh.indices[c] = at->second;
    }
}

// Surface vertices of the closed `surfaces` of `mesh` at positions that other surface vertices
// share, in the order unpinchVertices tries them: the corners of pinched edges
// (pinchedSheetCorners), then at each other such position every surface vertex but the first,
// then the first ones. Where surfaces touch at a point (the union keeps such points where pieces
// of one input triangle on both sides of a cut meet: 400–600 on ABOP 1.24a and 1.24c, session
// 29) the surface is not a 2-manifold at that vertex, and a later union would meet the point as
// a triple intersection.
std::vector<std::uint32_t> sheetCornersToPart(const Mesh& mesh, const Surfaces& surfaces) {
    std::vector<std::uint32_t> vertices = pinchedSheetCorners(mesh, surfaces);
    std::vector<char> listed(surfaces.vertices, 0);
    for (const std::uint32_t v : vertices) listed[v] = 1;
    std::vector<std::uint32_t> first(surfaces.positions, kUnknown);  // per position
    std::vector<std::uint32_t> firstOnes;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t v = surfaces.fan[c];
        std::uint32_t& owner = first[surfaces.weld[mesh.indices[c]]];
        if (owner == kUnknown) owner = v;
        if (owner == v || listed[v]) continue;
        vertices.push_back(v);
        listed[v] = 1;
        if (!listed[owner]) firstOnes.push_back(owner);
        listed[owner] = 1;
    }
    vertices.insert(vertices.end(), firstOnes.begin(), firstOnes.end());
    return vertices;
}

// Positions of `mesh` shared by several surface vertices of the closed `surfaces`: points where
// surfaces touch, and the ends of pinched edges.
std::size_t touchingPoints(const Mesh& mesh, const Surfaces& surfaces) {
    std::vector<std::uint32_t> first(surfaces.positions, kUnknown);
    std::vector<char> counted(surfaces.positions, 0);
    std::size_t points = 0;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t position = surfaces.weld[mesh.indices[c]];
        if (first[position] == kUnknown) first[position] = surfaces.fan[c];
        if (first[position] == surfaces.fan[c] || counted[position]) continue;
        counted[position] = 1;
        ++points;
    }
    return points;
}

// Pieces that hung on the rest of the closed `surfaces` of `mesh` only at points where surfaces
// touched are separate once those are parted: pockets and slivers of 2–4 triangles that the cut
// left (volume 0 or -2e-8 on ABOP 1.24b and 1.27, session 29). They go as in step 5
// (outerSurfaces), `surfaces` and the pairs `crossing` follow.
void dropPartedPieces(Mesh& mesh, Surfaces& surfaces, std::vector<detail::TrianglePair>& crossing,
                      SolidUnionReport& report) {
    const std::size_t cavities = report.cavitiesFilled;
    const std::vector<char> keep = outerSurfaces(mesh, surfaces.weld, surfaces.positions, report);
    report.cavitiesFilled += cavities;
    if (std::find(keep.begin(), keep.end(), 0) == keep.end()) return;
    std::vector<std::uint32_t> kept(keep.size(), kUnknown);  // per triangle: its new index
    std::uint32_t next = 0;
    for (std::size_t t = 0; t < keep.size(); ++t) {
        if (keep[t]) kept[t] = next++;
    }
    std::erase_if(crossing,
                  [&](const detail::TrianglePair& p) { return !keep[p.first] || !keep[p.second]; });
    for (detail::TrianglePair& p : crossing) p = {kept[p.first], kept[p.second]};
    keepTrianglesAndSurfaces(mesh, surfaces, keep);
    report.outputComponents = countComponents(surfaces.weld, surfaces.positions, mesh.indices);
}

// Edges of crossing triangles shorter than this fraction of the mesh's extent are collapsed
// where the float moves leave crossings (session 36). Where several intersection curves meet
// within a float step or two, the cut leaves clusters of triangles with edges of 1e-8–6e-6
// units (ABOP 1.24c, 243 units wide, at coordinates up to 45, where a float step is 4e-6),
// neighbours folded flat onto each other that no move of one corner parts; the shortest
// real feature of a plant is a twig's ring, thousands of times longer.
constexpr double kMicroEdge = 1e-7;

// Collapses edges shorter than kMicroEdge of the extent of the triangles in the crossing pairs
// `crossing` of the closed `surfaces` of `mesh`: the edge's first surface vertex moves onto the
// second (its mesh vertices keep their attributes) and the two triangles on the edge go. Only
// where the surface stays a 2-manifold (the two vertices have no common neighbour but the
// triangles' third corners), no triangle turns over or goes flat, neither vertex shares its
// position with another surface vertex, and no collapse beside it was made in this pass.
// `changed` gets, per triangle of the result, whether it moved or was in a crossing pair (the
// others cross nothing, as before). Returns how many edges were collapsed; none: all unchanged.
std::size_t collapseMicroEdges(Mesh& mesh, Surfaces& surfaces,
                               const std::vector<detail::TrianglePair>& crossing,
                               std::vector<char>& changed) {
    const double shortest = kMicroEdge * mesh.bounds().extent().maxCoeff();
    const std::vector<std::uint32_t>& fan = surfaces.fan;
    const std::size_t triangles = mesh.triangleCount();
    std::vector<Vec3f> at(surfaces.vertices);                        // per surface vertex
    std::vector<std::uint32_t> owner(surfaces.positions, kUnknown);  // per position
    std::vector<char> blocked(surfaces.vertices, 0);  // shares its position, or near a collapse
    std::vector<std::uint32_t> first(std::size_t{surfaces.vertices} + 1, 0);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t v = fan[c];
        at[v] = mesh.positions[mesh.indices[c]];
        std::uint32_t& o = owner[surfaces.weld[mesh.indices[c]]];
        if (o == kUnknown) o = v;
        if (o != v) blocked[v] = blocked[o] = 1;
        ++first[v + 1];
    }
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<std::uint32_t> around(first.back());  // per surface vertex: its corners
    {
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::uint32_t c = 0; c < mesh.indices.size(); ++c) around[fill[fan[c]]++] = c;
    }
    auto cornersOf = [&](std::uint32_t v) {
        return std::span(around.data() + first[v], around.data() + first[v + 1]);
    };
    auto corner = [&](std::uint32_t t, std::uint32_t k) { return fan[3 * std::size_t{t} + k]; };
    auto normal = [&](std::uint32_t t, std::uint32_t moved, const Vec3f& to) {
        std::array<Vec3, 3> p;
        for (std::uint32_t k = 0; k < 3; ++k) {
            p[k] = (corner(t, k) == moved ? to : at[corner(t, k)]).cast<double>();
        }
        return Vec3((p[1] - p[0]).cross(p[2] - p[0]));
    };
    // The surface vertices of v's triangles (v among them), sorted.
    auto linkOf = [&](std::uint32_t v, std::vector<std::uint32_t>& link) {
        link.clear();
        for (const std::uint32_t c : cornersOf(v)) {
            for (std::uint32_t j = 0; j < 3; ++j) link.push_back(corner(c / 3, j));
        }
        std::sort(link.begin(), link.end());
        link.erase(std::unique(link.begin(), link.end()), link.end());
    };
    std::vector<char> gone(triangles, 0);
    std::vector<std::uint32_t> linkV, linkW, onEdge;
    changed.assign(triangles, 0);
    for (const auto& [s, t] : crossing) changed[s] = changed[t] = 1;
    std::size_t collapsed = 0;
    for (const auto& pair : crossing) {
        for (const std::uint32_t t : {pair.first, pair.second}) {
            for (std::uint32_t k = 0; k < 3 && !gone[t]; ++k) {
                const std::uint32_t v = corner(t, k), w = corner(t, (k + 1) % 3);
                if (blocked[v] || blocked[w] ||
                    !((at[v] - at[w]).cast<double>().norm() < shortest)) {
                    continue;
                }
                // A 2-manifold after the collapse: two triangles on the edge, and no neighbour
                // of both but their third corners.
                onEdge.clear();
                for (const std::uint32_t c : cornersOf(v)) {
                    const std::uint32_t f = c / 3;
                    if (corner(f, 0) == w || corner(f, 1) == w || corner(f, 2) == w) {
                        onEdge.push_back(f);
                    }
                }
                linkOf(v, linkV);
                linkOf(w, linkW);
                const auto common = std::count_if(linkW.begin(), linkW.end(), [&](std::uint32_t x) {
                    return x != v && x != w && std::binary_search(linkV.begin(), linkV.end(), x);
                });
                if (onEdge.size() != 2 || common != 2) continue;
                // No other triangle of v turns over or goes flat when v moves onto w.
                bool turns = false;
                for (const std::uint32_t c : cornersOf(v)) {
                    const std::uint32_t f = c / 3;
                    if (f == onEdge[0] || f == onEdge[1]) continue;
                    const Vec3 after = normal(f, v, at[w]);
                    turns = turns || !(after.dot(normal(f, v, at[v])) > 0.0) ||
                            !(after.squaredNorm() > 0.0);
                }
                if (turns) continue;
                for (const std::uint32_t c : cornersOf(v)) {
                    mesh.positions[mesh.indices[c]] = at[w];
                    changed[c / 3] = 1;
                }
                gone[onEdge[0]] = gone[onEdge[1]] = 1;
                for (const std::uint32_t x : linkV) blocked[x] = 1;
                for (const std::uint32_t x : linkW) blocked[x] = 1;
                ++collapsed;
            }
        }
    }
    if (collapsed == 0) return 0;
    std::vector<char> keep(triangles);
    for (std::size_t f = 0; f < triangles; ++f) keep[f] = !gone[f];
    keepFlags(changed, keep);
    keepTriangles(mesh, keep);
    surfaces = surfacesOf(mesh);
    return collapsed;
}

// 6. Moves corners a few float steps (crossing_repair.hpp) to separate the crossing pairs of the
// closed surfaces `surfaces` of `mesh`, then to part sheets pinched together along an edge;
// `report` gets the moves and what is left: crossings (counted again over the whole mesh) and
// pinched edges; `left` the crossing pairs left. `pieces`: per triangle whether it is a piece of
// a cut one (unionAttempt's `suspect`; the others crossed nothing, so the first search looks
// only at pairs with a piece), empty to search the whole mesh.
void separateRoundingDefects(Mesh& mesh, Surfaces surfaces, const std::vector<char>& pieces,
                             std::size_t collapsePasses, SolidUnionReport& report,
                             std::vector<detail::TrianglePair>& left) {
    const double extent = mesh.bounds().extent().maxCoeff();
    splitSharedMeshVertices(mesh, surfaces);
    std::vector<detail::Box3> boxes;  // crossingPairs' scratch
    std::vector<detail::TrianglePair> crossing = crossingPairs(mesh, surfaces, pieces, boxes);
    std::size_t touching = touchingPoints(mesh, surfaces);
    const bool touched = touching > 0;
    // Moves `surface` (crossingSurfaceOf(mesh, surfaces), moved by `repair`) into the mesh and
    // counts the crossings again, where they can have changed: at the triangles that moved or
    // crossed before.
    auto take = [&](const detail::CrossingSurface& surface, const detail::CrossingRepair& repair) {
        if (repair.movedVertices == 0) return;
        const std::vector<char> suspect =
            trianglesMovedOrCrossing(mesh, surfaces, surface, crossing);
        if (!takeMoves(mesh, surfaces, surface)) return;
        report.crossingMoves += repair.movedVertices;
        crossing = crossingPairs(mesh, surfaces, suspect, boxes);
        touching = touchingPoints(mesh, surfaces);
    };
    auto moveApart = [&] {
        for (const double move : kSeparationMoves) {
            if (crossing.empty() && touching == 0) break;
            const double maxMove = move * extent;
            if (!crossing.empty()) {
                detail::CrossingSurface surface = crossingSurfaceOf(mesh, surfaces);
                take(surface, detail::separateCrossings(surface, crossing, maxMove));
            }
            if (touching > 0) {
                detail::CrossingSurface surface = crossingSurfaceOf(mesh, surfaces);
                const std::vector<std::uint32_t> corners = sheetCornersToPart(mesh, surfaces);
                take(surface, detail::unpinchVertices(surface, corners, maxMove));
            }
        }
    };
    moveApart();
    // Clusters of tiny triangles that the moves could not part: their shortest edges collapsed,
    // then the moves again, kept where that leaves fewer defects.
    for (std::size_t pass = 0; pass < collapsePasses && !crossing.empty(); ++pass) {
        const Mesh meshBefore = mesh;
        const Surfaces surfacesBefore = surfaces;
        const std::vector<detail::TrianglePair> crossingBefore = crossing;
        const std::size_t touchingBefore = touching;
        const std::size_t movesBefore = report.crossingMoves;
        std::vector<char> changed;
        const std::size_t collapsed = collapseMicroEdges(mesh, surfaces, crossing, changed);
        if (collapsed > 0 && surfaces.closed) {
            crossing = crossingPairs(mesh, surfaces, changed, boxes);
            touching = touchingPoints(mesh, surfaces);
            moveApart();
            if (crossing.size() + touching < crossingBefore.size() + touchingBefore) {
                report.collapsedEdges += collapsed;
                continue;
            }
        }
        mesh = meshBefore;
        surfaces = surfacesBefore;
        crossing = crossingBefore;
        touching = touchingBefore;
        report.crossingMoves = movesBefore;
        break;
    }
    if (touched) dropPartedPieces(mesh, surfaces, crossing, report);
    report.remainingIntersections = crossing.size();
    report.pinchedEdges = surfaces.pinchedEdges;
    report.touchingPoints = touchingPoints(mesh, surfaces);
    left = std::move(crossing);
}

// Surface vertices of the closed `surfaces` of `mesh` where a result has defects: the corners
// of the crossing pairs `crossing`, and every surface vertex whose position another one shares
// (sheets pinched together along an edge, surfaces touching at a point), which a refinement
// would meet as exact coincidences.
std::vector<char> defectVertices(const Mesh& mesh, const Surfaces& surfaces,
                                 const std::vector<detail::TrianglePair>& crossing) {
    std::vector<char> defect(surfaces.vertices, 0);
    for (const auto& [s, t] : crossing) {
        for (const std::uint32_t triangle : {s, t}) {
            for (std::size_t k = 0; k < 3; ++k)
                defect[surfaces.fan[3 * std::size_t{triangle} + k]] = 1;
        }
    }
    for (const std::uint32_t v : sheetCornersToPart(mesh, surfaces)) defect[v] = 1;
    return defect;
}

// Re-union, step 8: moves the defect vertices (defectVertices) of the closed `surfaces` of
// `mesh` by up to `jitter` of the extent (hash salt `salt`), where they may move
// (crossingSurfaceOf), into `mesh` and `surfaces`; false, both unchanged, where that leaves them
// not closed. `mayCross` gets per triangle whether it has a defect vertex: the others crossed
// nothing (`crossing` being all the pairs that cross, as crossingPairs counts them, which is
// how the refinement tests them where no position is shared by several surface vertices) and
// stay where they are, so the re-union looks for intersections only at those (session 36; the
// box search over all triangles had been a third of a re-union's time on ABOP 1.24c).
bool moveDefectVertices(Mesh& mesh, Surfaces& surfaces,
                        const std::vector<detail::TrianglePair>& crossing, double jitter,
                        std::uint64_t salt, std::vector<char>& mayCross) {
    const std::vector<char> defect = defectVertices(mesh, surfaces, crossing);
    mayCross.assign(mesh.triangleCount(), 0);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        if (defect[surfaces.fan[c]]) mayCross[c / 3] = 1;
    }
    const double step = jitter * mesh.bounds().extent().maxCoeff();
    detail::CrossingSurface surface = crossingSurfaceOf(mesh, surfaces);
    for (std::uint32_t v = 0; v < surfaces.vertices; ++v) {
        if (defect[v] && !surface.fixed[v]) {
            surface.points[v] = hashMoved(surface.points[v], v, step, salt);
        }
    }
    return takeMoves(mesh, surfaces, surface);
}

// The moves of the attempts (step 7), in order: the largest move of a surface vertex as a
// fraction of the mesh's extent, and the salt of its hash. Every entry keeps its own salt, so
// an entry moves the same vertices the same way wherever it stands in the list. Measured in
// session 28 (make union-check, Release; docs/welded.md, Solid union, step 7): a larger move
// separates grazing surfaces of dense plants better (ABOP 1.24a: 1e-5 left a crossing pair,
// 3e-5 nothing), but on a flat plant it tilts its coplanar faces through more of each other:
// on ABOP 2.8c 1e-5, 3e-5, 1e-4 cut the surface into 240 k, 365 k and 1.03 M triangles in 4 s,
// 60 s and minutes, leaving 3, 46 and 194 defects, while 5e-6 left none for 4 of 8 salts. With
// the order of sessions 25–27 (1e-5, 3e-5, 1e-4, 2e-5, 6e-5, salts 0x51ED·attempt) every
// attempt of 2.8c kept defects and its hulls were united after 5 min 23 s. So larger and
// smaller moves take turns, and how many triangles a move makes intersect tells the two kinds
// of plant apart before the cut (postponedAbove): on 1.24a and 1.24c 1e-5, 5e-6 and 3e-5 made
// 38.5 k, 38.5 k, 38.7 k of 74.6 k and 37.8 k, 37.8 k, 38.2 k of 63.1 k triangles intersect, on
// 2.8c 1e-5 and 5e-6 4 726 and 992 of 234 k. With this order and larger cuts put off, 2.8c is
// clean at its second attempt (5.8 s in all), 1.24a at its second, 1.24c its fourth, the other
// 39 examples at their first (1.24b since the first sheet's corners of a pinched edge may move
// too, pinchedSheetCorners).
struct UnionMove {
    double jitter;
    std::uint64_t salt;
};
constexpr UnionMove kUnionMoves[] = {{1e-5, 0x51ED},     {3e-5, 2 * 0x51ED}, {5e-6, 3 * 0x51ED},
                                     {1e-5, 4 * 0x51ED}, {5e-6, 5 * 0x51ED}, {2e-5, 6 * 0x51ED},
                                     {1e-4, 7 * 0x51ED}};
static_assert(std::size(kUnionMoves) == kSolidUnionAttempts);

// A move that makes more triangles intersect than this, for `firstCut` after the first
// attempt's move (1.5 times), is tried only after the others (SolidUnionReport::postponedMoves):
// on a flat plant the cut grows with the move (kUnionMoves), and with it the time, while on
// dense plants the moves differ by under 1 %. Finding the intersecting triangles costs a tenth
// to a hundredth of the cut.
std::size_t postponedAbove(std::size_t firstCut) { return firstCut + firstCut / 2; }

// The hash salt of the re-unions' moves (step 8), added per round to the attempt's salt.
constexpr std::uint64_t kReunionSalt = 0x2E0;

// `report`, of a result, after a re-union of it that `reunion` reports: what is left is the
// re-union's, what was done adds up (its patches and cuts are not the attempt's).
void addReunion(SolidUnionReport& report, const SolidUnionReport& reunion) {
    report.outputComponents = reunion.outputComponents;
    report.newVertices += reunion.newVertices;
    report.cavitiesFilled += reunion.cavitiesFilled;
    report.enclosedPieces += reunion.enclosedPieces;
    report.sliversRemoved += reunion.sliversRemoved;
    report.crossingMoves += reunion.crossingMoves;
    report.collapsedEdges += reunion.collapsedEdges;
    report.remainingIntersections = reunion.remainingIntersections;
    report.pinchedEdges = reunion.pinchedEdges;
    report.touchingPoints = reunion.touchingPoints;
}

}  // namespace

bool unionClosedSurfaces(Mesh& mesh, SolidUnionReport* report, std::size_t maxAttempts,
                         std::size_t maxReunions, std::size_t maxCollapsePasses) {
    SolidUnionReport local;
    SolidUnionReport& r = report != nullptr ? *report : local;
    r = SolidUnionReport{};
    if (mesh.indices.empty()) return false;
    if (!mesh.joints.empty()) {
        r.failure = "skinned meshes are not supported";
        return false;
    }
    // Rounding the cut positions to float can join a piece's corners with a neighbour's, or
    // make surfaces that graze each other cross, differently for every move: the moves of
    // kUnionMoves are tried in turn, and the first clean result or else the one with the fewest
    // crossings is kept.
    const Surfaces input = surfacesOf(mesh);
    r.inputComponents = countComponents(input.weld, input.positions, mesh.indices);
    if (!input.closed) {
        r.failure = "the input is not closed oriented surfaces (welded by position)";
        return false;
    }
    std::optional<Mesh> best;
    SolidUnionReport bestReport;
    std::vector<detail::TrianglePair> bestCrossing;  // the crossing pairs best has left
    std::size_t firstCut = 0;  // input triangles that intersect after the first attempt's move
    std::vector<UnionMove> postponed;
    auto clean = [&] { return best && bestReport.defects() == 0; };
    // One attempt with `move`, unless it makes more than `cutLimit` triangles intersect
    // (postponed); keeps the result if it is the best so far.
    auto attempt = [&](const UnionMove& move, std::size_t cutLimit) {
        SolidUnionReport tried;  // each attempt counts its own patches, pockets and slivers
        tried.inputComponents = r.inputComponents;
        Mesh trial;
        std::vector<char> suspect;
        std::size_t cut = 0;
        Surfaces surfaces;
        const Outcome outcome = unionAttempt(mesh, input, tried, move.jitter, move.salt, {},
                                             cutLimit, cut, trial, suspect, surfaces);
        if (outcome == Outcome::postponed) {
            postponed.push_back(move);
            return outcome;
        }
        if (++r.attempts == 1) firstCut = cut;
        r.failure = tried.failure;
        if (outcome != Outcome::done) return outcome;
        std::vector<detail::TrianglePair> left;
        separateRoundingDefects(trial, std::move(surfaces), suspect, maxCollapsePasses, tried,
                                left);
        if (!best || tried.defects() < bestReport.defects()) {
            best = std::move(trial);
            bestReport = tried;
            bestCrossing = std::move(left);
        }
        return outcome;
    };
    // Step 8: unites the best result again after moving its defect vertices (moveDefectVertices)
    // by `move`, up to maxReunions times while it has defects; a result with fewer replaces it.
    auto reunite = [&](const UnionMove& move) {
        for (std::size_t round = 0; round < maxReunions && !clean(); ++round) {
            Mesh moved = *best;
            Surfaces surfaces = surfacesOf(moved);
            std::vector<char> mayCross;
            if (!surfaces.closed ||
                !moveDefectVertices(moved, surfaces, bestCrossing, move.jitter,
                                    move.salt + kReunionSalt * (round + 1), mayCross)) {
                return;
            }
            SolidUnionReport tried;
            tried.inputComponents = bestReport.outputComponents;
            std::vector<char> suspect;
            std::size_t cut = 0;
            ++r.reunions;
            Mesh trial;
            Surfaces united;
            if (unionAttempt(moved, surfaces, tried, 0.0, 0, mayCross,
                             std::numeric_limits<std::size_t>::max(), cut, trial, suspect,
                             united) != Outcome::done) {
                return;
            }
            std::vector<detail::TrianglePair> left;
            separateRoundingDefects(trial, std::move(united), suspect, maxCollapsePasses, tried,
                                    left);
            if (tried.defects() >= bestReport.defects()) continue;
            best = std::move(trial);
            bestCrossing = std::move(left);
            addReunion(bestReport, tried);
        }
    };
    const std::size_t moves = std::clamp<std::size_t>(maxAttempts, 1, std::size(kUnionMoves));
    // A move whose cut would be over the work limit ends the attempts (the best so far stays).
    bool overLimit = false;
    for (const UnionMove& move : std::span(kUnionMoves, moves)) {
        const std::size_t cutLimit =
            r.attempts == 0 ? std::numeric_limits<std::size_t>::max() : postponedAbove(firstCut);
        const Outcome outcome = attempt(move, cutLimit);
        if (outcome == Outcome::badInput) return false;
        overLimit = outcome == Outcome::overLimit;
        if (outcome == Outcome::done) reunite(move);
        if (clean() || overLimit) break;
    }
    const std::size_t postponedMoves = postponed.size();
    for (const UnionMove& move : std::vector<UnionMove>(std::move(postponed))) {
        if (clean() || overLimit) break;
        const Outcome outcome = attempt(move, std::numeric_limits<std::size_t>::max());
        if (outcome == Outcome::badInput) return false;
        overLimit = outcome == Outcome::overLimit;
        if (outcome == Outcome::done) reunite(move);
    }
    if (!best) return false;
    const std::size_t made = r.attempts, reunions = r.reunions;
    r = bestReport;
    r.attempts = made;
    r.reunions = reunions;
    r.postponedMoves = postponedMoves;
    r.applied = true;
    r.failure.clear();
    mesh = std::move(*best);
    return true;
}

}  // namespace ramus

#else  // built with -DRAMUS_WITH_CGAL=OFF: no GPL code in the binaries, and no solid union

namespace ramus {

bool unionClosedSurfaces(Mesh& /*mesh*/, SolidUnionReport* /*report*/, std::size_t /*maxAttempts*/,
                         std::size_t /*maxReunions*/, std::size_t /*maxCollapsePasses*/) {
    throw Error(std::string(kSolidUnionMissing));
}

}  // namespace ramus

#endif

namespace ramus {

bool solidUnionAvailable() {
#if RAMUS_WITH_CGAL
    return true;
#else
    return false;
#endif
}

}  // namespace ramus
