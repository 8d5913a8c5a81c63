// Cutting intersecting triangles along their intersections (src/mesh/triangle_refinement.hpp):
// boxes turned into general position and pushed through each other; the pieces must tile their
// triangles, keep every surface closed, and carry each intersection on both surfaces.
#include "mesh/triangle_refinement.hpp"

#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus {
namespace {

using detail::RefinedTriangles;
using detail::RefinementPoint;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vector = Kernel::Vector_3;

struct Surfaces {
    std::vector<RefinementPoint> points;
    std::vector<std::uint32_t> fan;
    std::vector<std::uint32_t> surfaceOf;  // per triangle
};

// A box with half-sides `half`, turned by the angles `turn` (radians, about x, then y, then z)
// and centred at `centre`, as 12 outward triangles.
void addBox(Surfaces& s, std::array<double, 3> half, std::array<double, 3> turn,
            std::array<double, 3> centre) {
    const auto base = static_cast<std::uint32_t>(s.points.size());
    const auto surface = s.surfaceOf.empty() ? 0u : s.surfaceOf.back() + 1;
    for (int i = 0; i < 8; ++i) {
        double p[3] = {i & 1 ? half[0] : -half[0], i & 2 ? half[1] : -half[1],
                       i & 4 ? half[2] : -half[2]};
        for (int axis = 0; axis < 3; ++axis) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const double c = std::cos(turn[axis]), sn = std::sin(turn[axis]);
            const double pu = c * p[u] - sn * p[v], pv = sn * p[u] + c * p[v];
            p[u] = pu;
            p[v] = pv;
        }
        s.points.emplace_back(p[0] + centre[0], p[1] + centre[1], p[2] + centre[2]);
    }
    // Corners by bits (x = 1, y = 2, z = 4); each face wound outward.
    constexpr std::uint32_t kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                            {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : kFaces) {
        for (const std::uint32_t k : {q[0], q[1], q[2], q[0], q[2], q[3]})
            s.fan.push_back(base + k);
        s.surfaceOf.push_back(surface);
        s.surfaceOf.push_back(surface);
    }
}

Kernel::Triangle_3 triangle(const Surfaces& s, std::uint32_t t) {
    return {s.points[s.fan[3 * t]], s.points[s.fan[3 * t + 1]], s.points[s.fan[3 * t + 2]]};
}

// Every pair of triangles of different surfaces that intersect (boxes are convex: a surface
// does not intersect itself), by testing all pairs.
std::vector<std::pair<std::uint32_t, std::uint32_t>> intersectingPairs(const Surfaces& s) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::uint32_t a = 0; a < s.surfaceOf.size(); ++a) {
        for (std::uint32_t b = a + 1; b < s.surfaceOf.size(); ++b) {
            if (s.surfaceOf[a] != s.surfaceOf[b] &&
                CGAL::do_intersect(triangle(s, a), triangle(s, b))) {
                pairs.emplace_back(a, b);
            }
        }
    }
    return pairs;
}

struct Refined {
    const char* failure = nullptr;
    RefinedTriangles result;
    std::vector<RefinementPoint> points;              // input's, then the new ones
    std::vector<std::array<std::uint32_t, 3>> faces;  // uncut triangles and pieces
    std::vector<std::uint32_t> faceSurface;
};

Refined refine(const Surfaces& s) {
    Refined r;
    const auto pairs = intersectingPairs(s);
    r.failure = detail::refineTriangles(s.points, s.fan, pairs, r.result);
    if (r.failure) return r;
    r.points = s.points;
    r.points.insert(r.points.end(), r.result.newPoints.begin(), r.result.newPoints.end());
    std::vector<char> cut(s.surfaceOf.size(), 0);
    for (const auto& [a, b] : pairs) cut[a] = cut[b] = 1;
    for (std::uint32_t t = 0; t < s.surfaceOf.size(); ++t) {
        if (cut[t]) continue;
        r.faces.push_back({s.fan[3 * t], s.fan[3 * t + 1], s.fan[3 * t + 2]});
        r.faceSurface.push_back(s.surfaceOf[t]);
    }
    for (const RefinedTriangles::Piece& piece : r.result.pieces) {
        r.faces.push_back(piece.corners);
        r.faceSurface.push_back(s.surfaceOf[piece.origin]);
    }
    return r;
}

Vector normal(const std::vector<RefinementPoint>& points, const std::array<std::uint32_t, 3>& f) {
    return CGAL::cross_product(points[f[1]] - points[f[0]], points[f[2]] - points[f[0]]);
}

// The cut edges, read off the regions: the edges between pieces of one triangle in different
// regions, each once, directed as the piece of the region with the higher winding number (the
// inner side of the other triangle) uses it.
std::vector<std::pair<std::uint32_t, std::uint32_t>> cutEdges(const Refined& r) {
    const RefinedTriangles& out = r.result;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> pieceUsing;
    for (std::size_t i = 0; i < out.pieces.size(); ++i) {
        const auto& c = out.pieces[i].corners;
        for (std::size_t k = 0; k < 3; ++k) pieceUsing[{c[k], c[(k + 1) % 3]}] = i;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> cuts;
    for (const auto& [edge, i] : pieceUsing) {
        const auto twin = pieceUsing.find({edge.second, edge.first});
        if (twin == pieceUsing.end()) continue;
        const std::size_t j = twin->second;
        const std::uint32_t ri = out.pieceRegion[i], rj = out.pieceRegion[j];
        if (out.pieces[i].origin != out.pieces[j].origin || ri == rj) continue;
        if (out.regions[ri].winding > out.regions[rj].winding) cuts.push_back(edge);
    }
    return cuts;
}

// The checks every refinement must pass: the pieces of each cut triangle cover it (their
// areas add up to its area) and face its way; every surface stays closed over its own vertices
// (each edge once in each direction); every cut edge is an edge of pieces, and each
// intersection segment, by position, is cut on exactly two surfaces.
void expectValidRefinement(const Surfaces& s, const Refined& r) {
    ASSERT_EQ(r.failure, nullptr) << r.failure;
    std::vector<double> pieceArea(s.surfaceOf.size(), 0.0);
    for (const RefinedTriangles::Piece& piece : r.result.pieces) {
        const Vector n = normal(r.points, piece.corners);
        const Vector whole = normal(s.points, {s.fan[3 * piece.origin], s.fan[3 * piece.origin + 1],
                                               s.fan[3 * piece.origin + 2]});
        EXPECT_GE(n * whole, 0.0) << "a piece of triangle " << piece.origin << " turned over";
        pieceArea[piece.origin] += std::sqrt(n.squared_length()) / 2;
    }
    std::vector<char> cut(s.surfaceOf.size(), 0);
    for (const RefinedTriangles::Piece& piece : r.result.pieces) cut[piece.origin] = 1;
    for (std::uint32_t t = 0; t < s.surfaceOf.size(); ++t) {
        if (!cut[t]) continue;
        const double area = std::sqrt(triangle(s, t).squared_area());
        EXPECT_NEAR(pieceArea[t], area, 1e-9 * area) << "triangle " << t;
    }

    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& f : r.faces) {
        for (int k = 0; k < 3; ++k) ++directed[{f[k], f[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
        const auto reverse = directed.find({edge.second, edge.first});
        EXPECT_TRUE(reverse != directed.end() && reverse->second == 1)
            << "edge " << edge.first << "-" << edge.second << " has no twin";
    }

    const auto cuts = cutEdges(r);
    EXPECT_FALSE(cuts.empty());
    std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> cutsByPosition;
    for (const auto& [a, b] : cuts) {
        EXPECT_TRUE(directed.count({a, b}) + directed.count({b, a}) > 0) << "a cut edge not used";
        const RefinementPoint& p = r.points[a];
        const RefinementPoint& q = r.points[b];
        const std::array<double, 3> pa{p.x(), p.y(), p.z()}, qa{q.x(), q.y(), q.z()};
        ++cutsByPosition[std::minmax(pa, qa)];
    }
    for (const auto& [segment, count] : cutsByPosition) EXPECT_EQ(count, 2);

    // Each cut runs as the piece on the inner side of the surface that cuts it uses it: across
    // the cut, the number of other boxes holding a piece's centre goes up by one from the piece
    // using it the other way (what the union's winding numbers follow, solid_union.cpp).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> faceUsing;
    for (std::size_t f = 0; f < r.faces.size(); ++f) {
        for (int k = 0; k < 3; ++k) faceUsing[{r.faces[f][k], r.faces[f][(k + 1) % 3]}] = f;
    }
    auto boxesHolding = [&](std::size_t face) {
        const auto& f = r.faces[face];
        const RefinementPoint centre =
            CGAL::centroid(r.points[f[0]], r.points[f[1]], r.points[f[2]]);
        std::map<std::uint32_t, bool> holds;  // per other surface: the centre behind every face
        for (std::uint32_t t = 0; t < s.surfaceOf.size(); ++t) {
            if (s.surfaceOf[t] == r.faceSurface[face]) continue;
            const auto tri = triangle(s, t);
            const bool behind = CGAL::orientation(tri[0], tri[1], tri[2], centre) == CGAL::NEGATIVE;
            holds.try_emplace(s.surfaceOf[t], true).first->second &= behind;
        }
        return std::count_if(holds.begin(), holds.end(), [](const auto& h) { return h.second; });
    };
    for (const auto& [a, b] : cuts) {
        ASSERT_TRUE(faceUsing.count({a, b}) && faceUsing.count({b, a}));
        EXPECT_EQ(boxesHolding(faceUsing.at({a, b})), boxesHolding(faceUsing.at({b, a})) + 1)
            << "cut " << a << " → " << b;
    }

    // Regions: the boxes around each piece's centre differ from those around a piece of its
    // triangle's first region by the region's winding number relative to that one; each side
    // edge is a piece's of its region, with the face across (another triangle's, on the same
    // surface) as deep in the other boxes.
    const std::vector<RefinedTriangles::Region>& regions = r.result.regions;
    ASSERT_EQ(r.result.pieceRegion.size(), r.result.pieces.size());
    const std::size_t uncut = r.faces.size() - r.result.pieces.size();
    std::map<std::uint32_t, std::pair<std::uint32_t, long>> firstRegion;  // per triangle
    for (std::size_t i = 0; i < r.result.pieces.size(); ++i) {
        const std::uint32_t region = r.result.pieceRegion[i];
        ASSERT_LT(region, regions.size());
        EXPECT_EQ(regions[region].origin, r.result.pieces[i].origin);
        const long holding = boxesHolding(uncut + i);
        const auto [first, added] = firstRegion.try_emplace(r.result.pieces[i].origin, region,
                                                            holding - regions[region].winding);
        if (!added) {
            EXPECT_EQ(holding - regions[region].winding, first->second.second)
                << "piece " << i << " of triangle " << r.result.pieces[i].origin;
        }
    }
    EXPECT_FALSE(r.result.sides.empty());
    for (const auto& [a, b, region] : r.result.sides) {
        ASSERT_TRUE(faceUsing.count({a, b}) && faceUsing.count({b, a}));
        const std::size_t piece = faceUsing.at({a, b});
        ASSERT_GE(piece, uncut);
        EXPECT_EQ(r.result.pieceRegion[piece - uncut], region);
        const std::size_t across = faceUsing.at({b, a});
        EXPECT_NE(r.faces[across], r.faces[piece]);
        EXPECT_EQ(boxesHolding(across), boxesHolding(piece)) << "side " << a << " → " << b;
    }
}

TEST(TriangleRefinement, TwoTurnedBoxesThroughEachOther) {
    Surfaces s;
    addBox(s, {1.0, 0.7, 0.5}, {0.1, 0.2, 0.3}, {0.0, 0.0, 0.0});
    addBox(s, {0.6, 1.1, 0.4}, {0.5, -0.3, 0.7}, {0.9, 0.3, 0.1});
    const Refined r = refine(s);
    expectValidRefinement(s, r);
    // Two convex boxes meet along closed polylines, as many corners as edges, each corner an
    // edge of one box through a face of the other: a new vertex on each of the two surfaces,
    // and each edge cut on both.
    EXPECT_EQ(cutEdges(r).size(), r.result.newPoints.size());
}

// Three long boxes through one another, like the axes of a frame: the intersection curves of
// two pairs cross on faces of the third, where the planes of three triangles meet.
TEST(TriangleRefinement, ThreeBoxesWhoseIntersectionsCross) {
    Surfaces s;
    addBox(s, {2.0, 0.5, 0.45}, {0.03, 0.05, 0.02}, {0.01, 0.02, 0.0});
    addBox(s, {0.48, 2.1, 0.52}, {-0.04, 0.02, 0.06}, {0.0, -0.03, 0.02});
    addBox(s, {0.51, 0.47, 1.9}, {0.05, -0.06, 0.03}, {-0.02, 0.01, 0.03});
    const Refined r = refine(s);
    expectValidRefinement(s, r);
    // A point where three surfaces meet is a vertex of pieces of all three.
    std::map<std::array<double, 3>, std::vector<std::uint32_t>> surfacesAt;
    for (std::size_t f = 0; f < r.faces.size(); ++f) {
        for (const std::uint32_t v : r.faces[f]) {
            if (v < s.points.size()) continue;
            const RefinementPoint& p = r.points[v];
            surfacesAt[{p.x(), p.y(), p.z()}].push_back(r.faceSurface[f]);
        }
    }
    std::size_t threeFold = 0;
    for (auto& [at, surfaces] : surfacesAt) {
        std::sort(surfaces.begin(), surfaces.end());
        surfaces.erase(std::unique(surfaces.begin(), surfaces.end()), surfaces.end());
        threeFold += surfaces.size() == 3;
    }
    EXPECT_GT(threeFold, 0u);
}

TEST(TriangleRefinement, RandomBoxesInGeneralPosition) {
    Rng rng(0x7E1A);
    for (int round = 0; round < 40; ++round) {
        SCOPED_TRACE(round);
        Surfaces s;
        const int boxes = 2 + static_cast<int>(rng.uniformInt(4));
        for (int b = 0; b < boxes; ++b) {
            addBox(s, {rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0)},
                   {rng.uniform(0, 3.1), rng.uniform(0, 3.1), rng.uniform(0, 3.1)},
                   {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)});
        }
        expectValidRefinement(s, refine(s));
    }
}

TEST(TriangleRefinement, TheSameInputGivesTheSamePieces) {
    Surfaces s;
    Rng rng(0x5A3E);
    for (int b = 0; b < 6; ++b) {
        addBox(s, {rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0)},
               {rng.uniform(0, 3.1), rng.uniform(0, 3.1), rng.uniform(0, 3.1)},
               {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)});
    }
    const Refined a = refine(s), b = refine(s);
    ASSERT_EQ(a.failure, nullptr);
    ASSERT_EQ(b.failure, nullptr);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.faces, b.faces);
    EXPECT_EQ(a.result.pieceRegion, b.result.pieceRegion);
    EXPECT_EQ(cutEdges(a), cutEdges(b));
}

// Boxes with faces in one plane are not in general position: the refinement says so (the
// union then moves the corners and tries again) instead of cutting wrongly or crashing.
TEST(TriangleRefinement, CoplanarFacesAreRefused) {
    Surfaces s;
    addBox(s, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0});
    addBox(s, {0.5, 0.7, 1.0}, {0.0, 0.0, 0.0}, {0.8, 0.3, 0.0});  // top and bottom shared planes
    const Refined r = refine(s);
    ASSERT_NE(r.failure, nullptr);
    EXPECT_GT(std::string(r.failure).size(), 10u);
}

}  // namespace
}  // namespace ramus
