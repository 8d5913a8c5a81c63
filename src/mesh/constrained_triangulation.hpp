// A constrained Delaunay triangulation of the points of one triangle (its three corners, the
// others inside it or on its edges) with segments between them as constraints: the
// refinement's triangulation of each cut triangle (triangle_refinement.cpp). Points are numbers;
// the caller's predicates decide on them (exactly), so the triangulation constructs nothing.
//
// Points are inserted one by one (a walk to the face that holds the point, a split into three
// faces or, on an edge, into four, then Lawson's flips while a neighbour's corner lies inside a
// new face's circumcircle); then each constraint removes the faces it crosses and the two
// pseudo-polygons on either side are triangulated again, each face the Delaunay one of its
// polygon's base (Anglada, "An improved incremental algorithm for constructing restricted
// Delaunay triangulations", 1997), which keeps the triangulation constrained Delaunay. A
// constraint through a point is split there.
//
// Until session 39 the refinement ran CGAL's Constrained_Delaunay_triangulation_2 over the same
// predicates: on 38 k cut triangles of 5–300 points its generic structures (a compact container
// per triangulation, a deque per constraint) had taken about half of the triangulation's time.
// Internal to src/mesh.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace ramus::detail {

/// Thrown where the points or constraints are not what the triangulation takes: two points at
/// one place, a point outside the triangle, constraints that cross away from a point.
struct TriangulationFailure {
    const char* why;
};

class ConstrainedTriangulation {
public:
    static constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();

    /// A counterclockwise face; edge i runs from v[i + 1] to v[i + 2] (mod 3), opposite v[i],
    /// with the face across it (kNoFace: on the triangle's sides) and whether it lies on a
    /// constraint.
    struct Face {
        std::array<std::uint32_t, 3> v;
        std::array<std::uint32_t, 3> neighbor;
        std::array<bool, 3> constrained;
    };

    /// Triangulates points 0 … count − 1, of which 0, 1, 2 are the triangle's corners (in either
    /// turn), with the segments `constraints` (pairs of points) as edges. `predicates` has
    ///   int orientation(a, b, c): > 0 where a, b, c turn counterclockwise, 0 on one line;
    ///   int inCircle(a, b, c, d): > 0 where d lies inside the circle through the
    ///     counterclockwise a, b, c, 0 on it.
    template <class Predicates>
    void triangulate(const Predicates& predicates, std::uint32_t count,
                     std::span<const std::pair<std::uint32_t, std::uint32_t>> constraints);

    const std::vector<Face>& faces() const { return faces_; }

private:
    static std::uint32_t next(std::uint32_t i) { return i == 2 ? 0 : i + 1; }
    static std::uint32_t prev(std::uint32_t i) { return i == 0 ? 2 : i - 1; }

    // The index of face f's edge from a to b (3: none).
    std::uint32_t edgeIndex(std::uint32_t f, std::uint32_t a, std::uint32_t b) const {
        const Face& face = faces_[f];
        for (std::uint32_t i = 0; i < 3; ++i) {
            if (face.v[next(i)] == a && face.v[prev(i)] == b) return i;
        }
        return 3;
    }
    // Points the face across face f's edge i (from a to b) back at f.
    void pointBack(std::uint32_t f, std::uint32_t i) {
        const Face& face = faces_[f];
        const std::uint32_t g = face.neighbor[i];
        if (g == kNoFace) return;
        const std::uint32_t j = edgeIndex(g, face.v[prev(i)], face.v[next(i)]);
        if (j == 3) throw TriangulationFailure{"faces that do not match across an edge"};
        faces_[g].neighbor[j] = f;
    }
    void setConstrained(std::uint32_t f, std::uint32_t i) {
        Face& face = faces_[f];
        face.constrained[i] = true;
        const std::uint32_t g = face.neighbor[i];
        if (g == kNoFace) return;
        const std::uint32_t j = edgeIndex(g, face.v[prev(i)], face.v[next(i)]);
        if (j == 3) throw TriangulationFailure{"faces that do not match across an edge"};
        faces_[g].constrained[j] = true;
    }

    // Calls visit(g, k) for the faces g around point a (a = faces_[g].v[k]), turning both ways
    // from faceAt_[a], until it returns true; returns whether it did.
    template <class Visit>
    bool aroundPoint(std::uint32_t a, Visit visit) const;

    template <class Predicates>
    void insertPoint(const Predicates& predicates, std::uint32_t p);
    template <class Predicates>
    void legalize(const Predicates& predicates);
    template <class Predicates>
    void insertConstraint(const Predicates& predicates, std::uint32_t a, std::uint32_t b);
    template <class Predicates>
    void triangulatePseudoPolygon(const Predicates& predicates, std::uint32_t a, std::uint32_t b,
                                  std::span<const std::uint32_t> chain);
    void glueCavity(std::uint32_t a, std::uint32_t b);

    std::vector<Face> faces_;
    std::uint32_t last_ = 0;  // the face last made: where the next point's walk starts
    // Per point, once the points are in: a face at it (kept as constraints remake faces), where
    // insertConstraint starts its turn around the point.
    std::vector<std::uint32_t> faceAt_;
    // Edges to check for Lawson's flips: (face, edge index).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> toCheck_;
    // Scratch of a constraint's cavity: the faces it crossed, their corners on the left and on the
    // right of the constraint, the faces made again, and the cavity's border (edge → face across).
    std::vector<std::uint32_t> crossed_, left_, right_, made_;
    struct BorderEdge {
        std::uint32_t from, to, across;
        bool constrained;
    };
    std::vector<BorderEdge> border_;
};

template <class Predicates>
void ConstrainedTriangulation::triangulate(
    const Predicates& predicates, std::uint32_t count,
    std::span<const std::pair<std::uint32_t, std::uint32_t>> constraints) {
    faces_.clear();
    const int turn = predicates.orientation(0, 1, 2);
    if (turn == 0) throw TriangulationFailure{"a triangle with its corners on one line"};
    faces_.push_back(Face{
        turn > 0 ? std::array<std::uint32_t, 3>{0, 1, 2} : std::array<std::uint32_t, 3>{0, 2, 1},
        {kNoFace, kNoFace, kNoFace},
        {false, false, false}});
    last_ = 0;
    for (std::uint32_t p = 3; p < count; ++p) insertPoint(predicates, p);
    faceAt_.assign(count, kNoFace);
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
        for (const std::uint32_t v : faces_[f].v) faceAt_[v] = f;
    }
    for (const auto& [a, b] : constraints) insertConstraint(predicates, a, b);
}

template <class Visit>
bool ConstrainedTriangulation::aroundPoint(std::uint32_t a, Visit visit) const {
    const std::uint32_t start = faceAt_[a];
    if (start == kNoFace) return false;
    for (int way = 0; way < 2; ++way) {
        std::uint32_t g = start;
        do {
            const Face& face = faces_[g];
            std::uint32_t k = 0;
            while (k < 3 && face.v[k] != a) ++k;
            if (k == 3) return false;
            if ((way == 0 || g != start) && visit(g, k)) return true;
            g = face.neighbor[way == 0 ? prev(k) : next(k)];
        } while (g != kNoFace && g != start);
        if (g == start) break;  // all the way round: no need to turn back
    }
    return false;
}

// Every point comes before the constraints (triangulate): no edge is constrained yet.
template <class Predicates>
void ConstrainedTriangulation::insertPoint(const Predicates& predicates, std::uint32_t p) {
    // A visibility walk, which ends in a Delaunay triangulation (no constraints yet); bounded all
    // the same, then every face is tried.
    std::uint32_t f = last_;
    std::array<int, 3> side{};
    const std::size_t maxSteps = 4 * faces_.size() + 8;
    for (std::size_t step = 0;; ++step) {
        if (step == maxSteps) {
            for (f = 0; f < faces_.size(); ++f) {
                const Face& face = faces_[f];
                bool inside = true;
                for (std::uint32_t i = 0; i < 3 && inside; ++i) {
                    side[i] = predicates.orientation(face.v[next(i)], face.v[prev(i)], p);
                    inside = side[i] >= 0;
                }
                if (inside) break;
            }
            if (f == faces_.size()) throw TriangulationFailure{"a point outside the triangle"};
            break;
        }
        const Face& face = faces_[f];
        std::uint32_t across = 3;
        for (std::uint32_t i = 0; i < 3; ++i) {
            side[i] = predicates.orientation(face.v[next(i)], face.v[prev(i)], p);
            if (side[i] < 0) {
                across = i;
                break;
            }
        }
        if (across == 3) break;
        f = faces_[f].neighbor[across];
        if (f == kNoFace) throw TriangulationFailure{"a point outside the triangle"};
    }
    const int onEdges = (side[0] == 0) + (side[1] == 0) + (side[2] == 0);
    if (onEdges >= 2) throw TriangulationFailure{"two points at one place"};
    toCheck_.clear();
    if (onEdges == 0) {
        // Split face f = (a, b, c) into (b, c, p), (c, a, p), (a, b, p): p last in each.
        const Face old = faces_[f];
        const auto first = static_cast<std::uint32_t>(faces_.size());
        const std::array<std::uint32_t, 3> made{f, first, first + 1};
        faces_.resize(faces_.size() + 2);
        for (std::uint32_t i = 0; i < 3; ++i) {
            // Face made[i] keeps the old edge i, from v[i + 1] to v[i + 2].
            faces_[made[i]] = Face{{old.v[next(i)], old.v[prev(i)], p},
                                   {made[next(i)], made[prev(i)], old.neighbor[i]},
                                   {}};
        }
        for (std::uint32_t i = 0; i < 3; ++i) {
            pointBack(made[i], 2);
            toCheck_.emplace_back(made[i], 2);
        }
    } else {
        // p on edge i of f (from u to w, opposite x); g across, opposite y: each split in two.
        const std::uint32_t i = side[0] == 0 ? 0 : side[1] == 0 ? 1 : 2;
        const Face old = faces_[f];
        const std::uint32_t x = old.v[i], u = old.v[next(i)], w = old.v[prev(i)];
        const std::uint32_t g = old.neighbor[i];
        const auto first = static_cast<std::uint32_t>(faces_.size());
        if (g == kNoFace) {
            // (x, u, p) and (w, x, p).
            faces_.resize(faces_.size() + 1);
            faces_[f] = Face{{x, u, p}, {kNoFace, first, old.neighbor[prev(i)]}, {}};
            faces_[first] = Face{{w, x, p}, {f, kNoFace, old.neighbor[next(i)]}, {}};
            for (const std::uint32_t m : {f, first}) {
                pointBack(m, 2);
                toCheck_.emplace_back(m, 2);
            }
        } else {
            const Face oldG = faces_[g];
            const std::uint32_t j = edgeIndex(g, w, u);
            const std::uint32_t y = oldG.v[j];
            // (x, u, p), (w, x, p), (y, w, p), (u, y, p).
            faces_.resize(faces_.size() + 2);
            const std::uint32_t xu = f, wx = first, yw = g, uy = first + 1;
            faces_[xu] = Face{{x, u, p}, {uy, wx, old.neighbor[prev(i)]}, {}};
            faces_[wx] = Face{{w, x, p}, {xu, yw, old.neighbor[next(i)]}, {}};
            faces_[yw] = Face{{y, w, p}, {wx, uy, oldG.neighbor[prev(j)]}, {}};
            faces_[uy] = Face{{u, y, p}, {yw, xu, oldG.neighbor[next(j)]}, {}};
            for (const std::uint32_t m : {xu, wx, yw, uy}) {
                pointBack(m, 2);
                toCheck_.emplace_back(m, 2);
            }
        }
    }
    last_ = f;
    legalize(predicates);
}

template <class Predicates>
void ConstrainedTriangulation::legalize(const Predicates& predicates) {
    while (!toCheck_.empty()) {
        const auto [f, i] = toCheck_.back();
        toCheck_.pop_back();
        const Face face = faces_[f];
        const std::uint32_t g = face.neighbor[i];
        if (g == kNoFace) continue;
        const std::uint32_t p = face.v[i], u = face.v[next(i)], w = face.v[prev(i)];
        const std::uint32_t j = edgeIndex(g, w, u);
        const Face across = faces_[g];
        const std::uint32_t y = across.v[j];
        if (predicates.inCircle(p, u, w, y) <= 0) continue;
        // Flip u–w to p–y: (p, u, y) and (p, y, w).
        faces_[f] = Face{{p, u, y}, {across.neighbor[next(j)], g, face.neighbor[prev(i)]}, {}};
        faces_[g] = Face{{p, y, w}, {across.neighbor[prev(j)], face.neighbor[next(i)], f}, {}};
        pointBack(f, 0);
        pointBack(g, 1);
        toCheck_.emplace_back(f, 0);
        toCheck_.emplace_back(g, 0);
    }
}

template <class Predicates>
void ConstrainedTriangulation::insertConstraint(const Predicates& predicates, std::uint32_t a,
                                                std::uint32_t b) {
    while (a != b) {
        // The face at a whose angle holds the direction to b: found by turning around a (that
        // face is the only one, so any search finds the same; until session 43 every face was
        // scanned for each, quadratic in a triangle's pieces: a random plant's union ran for
        // minutes in here), or by a scan should the turn miss it.
        std::uint32_t f = kNoFace, k = 0;
        bool through = false;  // the segment passes through a point on the way to b: a moved on
        bool ends = false;     // an edge of the face is a–b
        auto holds = [&](std::uint32_t g, std::uint32_t at) {
            const Face& face = faces_[g];
            const std::uint32_t u = face.v[next(at)], w = face.v[prev(at)];
            if (u == b || w == b) {
                setConstrained(g, u == b ? prev(at) : next(at));
                ends = true;
                return true;
            }
            const int su = predicates.orientation(a, u, b);
            const int sw = predicates.orientation(a, w, b);
            if (su < 0 || sw > 0) return false;
            if (su == 0 || sw == 0) {  // through u or w on the way to b
                setConstrained(g, su == 0 ? prev(at) : next(at));
                a = su == 0 ? u : w;
                through = true;
                return true;
            }
            f = g;
            k = at;
            return true;
        };
        if (!aroundPoint(a, holds)) {
            bool found = false;
            for (std::uint32_t g = 0; g < faces_.size() && !found; ++g) {
                std::uint32_t at = 0;
                while (at < 3 && faces_[g].v[at] != a) ++at;
                found = at < 3 && holds(g, at);
            }
            if (!found) throw TriangulationFailure{"a constraint that leaves the triangle"};
        }
        if (ends) return;
        if (through) continue;
        // Walk across the faces the segment a–b crosses, up to b or a point on it.
        crossed_.assign(1, f);
        left_.clear();
        right_.clear();
        std::uint32_t u = faces_[f].v[next(k)], w = faces_[f].v[prev(k)];  // u right, w left
        right_.push_back(u);
        left_.push_back(w);
        std::uint32_t end = b;
        for (;;) {
            const Face& face = faces_[f];
            if (face.constrained[k]) {
                throw TriangulationFailure{"constraints that cross away from a point"};
            }
            const std::uint32_t g = face.neighbor[k];
            if (g == kNoFace) throw TriangulationFailure{"a constraint that leaves the triangle"};
            const std::uint32_t j = edgeIndex(g, w, u);
            const std::uint32_t y = faces_[g].v[j];
            crossed_.push_back(g);
            if (y == b) break;
            const int s = predicates.orientation(a, b, y);
            if (s == 0) {
                end = y;
                break;
            }
            f = g;
            if (s > 0) {  // y on the left: the segment leaves g between u and y
                left_.push_back(y);
                w = y;
                k = edgeIndex(g, u, y);
            } else {
                right_.push_back(y);
                u = y;
                k = edgeIndex(g, y, w);
            }
        }
        // The cavity's border, then the two pseudo-polygons triangulated again into the crossed
        // faces' places.
        border_.clear();
        for (const std::uint32_t c : crossed_) {
            const Face& face = faces_[c];
            for (std::uint32_t i = 0; i < 3; ++i) {
                const std::uint32_t g = face.neighbor[i];
                bool inside = false;
                for (const std::uint32_t d : crossed_) inside = inside || d == g;
                if (!inside) {
                    border_.push_back({face.v[next(i)], face.v[prev(i)], g, face.constrained[i]});
                }
            }
        }
        made_.clear();
        triangulatePseudoPolygon(predicates, a, end, left_);
        std::reverse(right_.begin(), right_.end());
        triangulatePseudoPolygon(predicates, end, a, right_);
        if (made_.size() != crossed_.size())
            throw TriangulationFailure{"a cavity that does not close"};
        glueCavity(a, end);
        a = end;
    }
}

template <class Predicates>
void ConstrainedTriangulation::triangulatePseudoPolygon(const Predicates& predicates,
                                                        std::uint32_t a, std::uint32_t b,
                                                        std::span<const std::uint32_t> chain) {
    // chain: the polygon's points from a to b, all left of a → b.
    if (chain.empty()) return;
    std::size_t c = 0;
    for (std::size_t i = 1; i < chain.size(); ++i) {
        if (predicates.inCircle(a, b, chain[c], chain[i]) > 0) c = i;
    }
    if (made_.size() == crossed_.size()) throw TriangulationFailure{"a cavity that does not close"};
    made_.push_back(crossed_[made_.size()]);
    faces_[made_.back()].v = {a, b, chain[c]};
    faceAt_[a] = faceAt_[b] = faceAt_[chain[c]] = made_.back();
    triangulatePseudoPolygon(predicates, a, chain[c], chain.first(c));
    triangulatePseudoPolygon(predicates, chain[c], b, chain.subspan(c + 1));
}

inline void ConstrainedTriangulation::glueCavity(std::uint32_t a, std::uint32_t b) {
    // Each made face's edges: the constraint a–b, another made face's edge, or the border's.
    for (const std::uint32_t f : made_) {
        Face& face = faces_[f];
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t from = face.v[next(i)], to = face.v[prev(i)];
            face.constrained[i] = (from == a && to == b) || (from == b && to == a);
            face.neighbor[i] = kNoFace;
            bool found = false;
            for (const std::uint32_t g : made_) {
                if (g != f && edgeIndex(g, to, from) != 3) {
                    face.neighbor[i] = g;
                    found = true;
                    break;
                }
            }
            if (found) continue;
            for (const BorderEdge& e : border_) {
                if (e.from == from && e.to == to) {
                    face.neighbor[i] = e.across;
                    face.constrained[i] = e.constrained;
                    found = true;
                    break;
                }
            }
            if (!found) throw TriangulationFailure{"a cavity that does not close"};
            pointBack(f, i);
        }
    }
}

}  // namespace ramus::detail
