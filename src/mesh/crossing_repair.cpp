// Greedy separation of crossing triangle pairs by float-step moves (crossing_repair.hpp).
#include "crossing_repair.hpp"

#if RAMUS_WITH_CGAL

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>

#include "box_tree.hpp"
#include "position_bits.hpp"
#include "ramus/error.hpp"
#include "triangle_pairs.hpp"

namespace ramus::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;

Point pointOf(const Vec3f& p) { return {p.x(), p.y(), p.z()}; }

// The spacing of floats at p: the largest of its coordinates' units in the last place.
double ulpAt(const Vec3f& p) {
    float largest = 0.0f;
    for (int axis = 0; axis < 3; ++axis) largest = std::max(largest, std::abs(p[axis]));
    return static_cast<double>(std::nextafter(largest, std::numeric_limits<float>::infinity()) -
                               largest);
}

// Every vertex stays within maxMove of where it was, so a triangle meeting one of v's triangles
// now was, as stored, within maxMove of its box: kReach of maxMove around that box.
constexpr double kReach = 1.01;

class Separator {
public:
    Separator(CrossingSurface& surface, double maxMove, std::uint64_t workLimit);
    CrossingRepair run(std::span<const TrianglePair> crossing);
    CrossingRepair unpinchAll(std::span<const std::uint32_t> vertices);

private:
    Triangle triangle(std::uint32_t t) const;
    Vec3 normal(std::uint32_t t) const;  // not normalized
    bool degenerate(std::uint32_t t) const;
    bool cross(std::uint32_t f, std::uint32_t g) const;
    std::size_t crossingsAround(std::uint32_t v, std::vector<TrianglePair>* pairs = nullptr);
    Box3 reachOf(std::uint32_t f, double grow) const;
    Box3 boxNow(std::uint32_t t) const;
    void collectNear(std::uint32_t v);
    std::size_t crossingsNear(std::uint32_t v, std::vector<TrianglePair>* pairs = nullptr) const;
    bool atMostCrossingsNear(std::uint32_t v, std::size_t most);
    bool turnsNoTriangle(std::uint32_t v, const std::vector<Vec3>& before) const;
    bool separate(std::uint32_t v, std::uint32_t partner);
    bool unpinch(std::uint32_t v);
    bool movable(std::uint32_t v) const { return s_.fixed.empty() || !s_.fixed[v]; }
    bool tryMoves(std::uint32_t v, std::size_t most);
    Vec3 vertexNormal(std::uint32_t v);
    void addDirection(const Vec3& d);
    void addTowardsMiddle(std::uint32_t v);
    Vec3f originalOf(std::uint32_t v) const;
    Box3 originalBox(std::uint32_t t) const;
    template <class Vertices>
    void cover(const Vertices& vertices);
    // v's triangles: around_[star(v).first], … up to star(v).second (ascending; v covered).
    std::pair<std::uint32_t, std::uint32_t> star(std::uint32_t v) const;

    CrossingSurface& s_;
    double maxMove_;
    // Where the vertices that moved were (moves stay within maxMove); the others are there still.
    std::vector<std::uint8_t> moved_;  // per vertex
    std::unordered_map<std::uint32_t, Vec3f> original_;
    // The searches look only at the triangles near the vertices that may move (session 40: a tree
    // over all of the surface's boxes, of tens of megabytes for the 230 k triangles of tree_3d,
    // had cost more than the repair of its 3 crossing pairs). A vertex is covered once its
    // triangles are in local_ and so is every triangle whose box, as it was, comes within reach
    // of theirs wherever they move (region_); the searches are only made for covered vertices,
    // so they find what a tree over every triangle would (in another order, which no decision
    // depends on).
    std::vector<std::uint8_t> covered_;  // per vertex
    std::vector<Box3> region_;           // boxes around the covered vertices' triangles
    std::vector<std::uint32_t> local_;   // the triangles meeting region_, ascending
    std::optional<BoxTree> tree_;        // over their boxes as they were (local_ order)
    std::vector<std::uint32_t> first_;   // per vertex + 1: its triangles of local_ in around_
    std::vector<std::uint32_t> around_;
    // Scratch of tryMoves: per triangle k of the vertex it moves (its k-th in around_), the
    // triangles near[nearFirst[k]], … that come within reach wherever the vertex goes.
    std::vector<std::uint32_t> nearFirst_, near_;
    // The pair that ended atMostCrossingsNear's last count: (k, index into near_); kNoPair: none.
    static constexpr std::uint32_t kNoPair = std::numeric_limits<std::uint32_t>::max();
    std::pair<std::uint32_t, std::uint32_t> lastCrossing_{kNoPair, kNoPair};
#if defined(RAMUS_ENABLE_ASSERTS)
    std::size_t nearChecks_ = 0;  // collectNear's searches, of which every 16th is checked
#endif
    std::vector<Vec3> normals_;     // scratch: normals of a vertex's triangles before a move
    std::vector<Vec3> directions_;  // scratch: the directions of a vertex's moves
    // Pairs of a vertex's triangle and a triangle near it looked at so far (kept apart by their
    // boxes or tested), and how many the repair may look at before it stops moving vertices.
    mutable std::uint64_t work_ = 0;
    std::uint64_t workLimit_;
    bool pastWorkLimit() const { return work_ > workLimit_; }
    // What the repair reports of its work, once it is done.
    void reportWork(CrossingRepair& repair) const {
        repair.work = work_;
        repair.overWorkLimit = pastWorkLimit();
    }
};

Separator::Separator(CrossingSurface& surface, double maxMove, std::uint64_t workLimit)
    : s_(surface),
      maxMove_(maxMove),
      moved_(surface.points.size(), 0),
      covered_(surface.points.size(), 0),
      workLimit_(workLimit) {}

Vec3f Separator::originalOf(std::uint32_t v) const {
    return moved_[v] ? original_.at(v) : s_.points[v];
}

Box3 Separator::originalBox(std::uint32_t t) const {
    Box3 box;
    for (const std::uint32_t v : s_.triangles[t]) {
        const Vec3f p = originalOf(v);
        box.add({p.x(), p.y(), p.z()});
    }
    return box;
}

// `box` grown by `grow` on every side.
Box3 grown(Box3 box, double grow) {
    for (int d = 0; d < 3; ++d) {
        box.lo[d] -= grow;
        box.hi[d] += grow;
    }
    return box;
}

std::pair<std::uint32_t, std::uint32_t> Separator::star(std::uint32_t v) const {
    RAMUS_ASSERT(covered_[v]);
    return {first_[v], first_[v + 1]};
}

// The cells of a uniform grid over some boxes (a region) that those boxes meet, as bits: to tell
// which of many other boxes meet the region, without a tree over either. At most kRegionCells
// cells on an axis, each at least as wide as the largest side of the region's boxes. A box that
// could meet the region counts as meeting it (a superset: one that meets more than 64 cells); a
// box of the region itself meets at most 2 cells an axis, all of them marked.
class RegionCells {
public:
    static constexpr std::int64_t kRegionCells = 128;

    explicit RegionCells(const std::vector<Box3>& boxes) {
        double largest = 0.0;
        for (const Box3& b : boxes) {
            for (int d = 0; d < 3; ++d) {
                bounds_.lo[d] = std::min(bounds_.lo[d], b.lo[d]);
                bounds_.hi[d] = std::max(bounds_.hi[d], b.hi[d]);
                largest = std::max(largest, b.hi[d] - b.lo[d]);
            }
        }
        for (int d = 0; d < 3; ++d) {
            side_ = std::max(side_, (bounds_.hi[d] - bounds_.lo[d]) / kRegionCells);
        }
        side_ = std::max(side_, largest);
        if (!(side_ > 0.0)) side_ = 1.0;
        bits_.assign((kRegionCells * kRegionCells * kRegionCells + 63) / 64, 0);
        for (const Box3& b : boxes) {
            forCells(
                b, [&](std::int64_t cell) { bits_[cell / 64] |= std::uint64_t{1} << (cell % 64); });
        }
    }

    bool mayMeet(const Box3& b) const {
        if (!b.overlaps(bounds_)) return false;
        bool meets = false;
        const bool few = forCells(b, [&](std::int64_t cell) {
            meets = meets || (bits_[cell / 64] >> (cell % 64) & 1) != 0;
        });
        return meets || !few;
    }

private:
    // Calls visit(cell) for the cells b meets (b overlapping the region's bounds); false (and no
    // calls) where those are more than 64.
    template <class Visit>
    bool forCells(const Box3& b, Visit visit) const {
        std::array<std::int64_t, 3> lo, hi;
        std::int64_t cells = 1;
        for (int d = 0; d < 3; ++d) {
            auto cellOf = [&](double x) {
                return std::clamp(
                    static_cast<std::int64_t>(std::floor((x - bounds_.lo[d]) / side_)),
                    std::int64_t{0}, kRegionCells - 1);
            };
            lo[d] = cellOf(b.lo[d]);
            hi[d] = cellOf(b.hi[d]);
            cells *= hi[d] - lo[d] + 1;
            if (cells > 64) return false;
        }
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
                for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
                    visit((x * kRegionCells + y) * kRegionCells + z);
                }
            }
        }
        return true;
    }

    Box3 bounds_;
    double side_ = 0.0;
    std::vector<std::uint64_t> bits_;  // per cell, x major
};

// Where the region around the covered vertices has more than one box in this many triangles of
// the surface, cover takes every triangle instead of telling them apart.
constexpr std::size_t kWholeSurface = 8;

// The triangles of the vertices `vertices` that are not covered yet, and those whose boxes, as
// they were, come within reach of theirs, go into the searches (local_, tree_, the stars).
// Every vertex stays within maxMove of where it was, and tryMoves moves a vertex at most 2
// maxMove from where it is: collectNear's reach of a covered vertex's triangle lies within its
// box as it was grown by (kReach + 3.01) maxMove.
template <class Vertices>
void Separator::cover(const Vertices& vertices) {
    bool adding = false;
    for (const std::uint32_t v : vertices) {
        if (covered_[v] == 0) covered_[v] = 2;  // being added
        adding = adding || covered_[v] == 2;
    }
    if (!adding) return;
    const double margin = (kReach + 3.5) * maxMove_;
    for (std::uint32_t t = 0; t < s_.triangles.size(); ++t) {
        const auto& c = s_.triangles[t];
        if (covered_[c[0]] == 2 || covered_[c[1]] == 2 || covered_[c[2]] == 2) {
            region_.push_back(grown(originalBox(t), margin));
        }
    }
    for (std::uint8_t& flag : covered_) flag = flag != 0 ? 1 : 0;
    const bool everything = kWholeSurface * region_.size() > s_.triangles.size();
    const std::optional<RegionCells> cells =
        everything ? std::nullopt : std::optional<RegionCells>(region_);
    local_.clear();
    std::vector<Box3> boxes;
    for (std::uint32_t t = 0; t < s_.triangles.size(); ++t) {
        const Box3 box = originalBox(t);
        if (cells && !cells->mayMeet(box)) continue;
        local_.push_back(t);
        boxes.push_back(box);
    }
    tree_.emplace(boxes);
    // The stars: local_'s triangles by vertex, ascending (a counting sort).
    first_.assign(s_.points.size() + 1, 0);
    for (const std::uint32_t t : local_) {
        for (const std::uint32_t v : s_.triangles[t]) ++first_[v + 1];
    }
    for (std::size_t v = 0; v + 1 < first_.size(); ++v) first_[v + 1] += first_[v];
    around_.resize(first_.back());
    std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
    for (const std::uint32_t t : local_) {
        for (const std::uint32_t v : s_.triangles[t]) around_[fill[v]++] = t;
    }
}

Triangle Separator::triangle(std::uint32_t t) const {
    const auto& v = s_.triangles[t];
    return {pointOf(s_.points[v[0]]), pointOf(s_.points[v[1]]), pointOf(s_.points[v[2]])};
}

Vec3 Separator::normal(std::uint32_t t) const {
    const auto& v = s_.triangles[t];
    const Vec3 a = s_.points[v[0]].cast<double>();
    return (s_.points[v[1]].cast<double>() - a).cross(s_.points[v[2]].cast<double>() - a);
}

bool Separator::degenerate(std::uint32_t t) const {
    const auto& v = s_.triangles[t];
    return CGAL::collinear(pointOf(s_.points[v[0]]), pointOf(s_.points[v[1]]),
                           pointOf(s_.points[v[2]]));
}

// As the solid union counts crossings (detail::trianglesCross): triangles that share no
// position and intersect, and neighbours on one sheet that fold through each other beside what
// they share (since session 36: before, the repair passed over such folds, which only a new
// union could mend, while the union counted them since session 35).
bool Separator::cross(std::uint32_t f, std::uint32_t g) const {
    const auto& a = s_.triangles[f];
    const auto& b = s_.triangles[g];
    return trianglesCross([&](std::uint32_t v) { return pointOf(s_.points[v]); }, a.data(),
                          b.data(),
                          [&](int i, int j) {
                              return s_.points[a[static_cast<std::size_t>(i)]] ==
                                     s_.points[b[static_cast<std::size_t>(j)]];
                          });
}

// Triangle f's box where it is now, grown by `grow` on every side.
Box3 Separator::reachOf(std::uint32_t f, double grow) const {
    const CGAL::Bbox_3 bbox = triangle(f).bbox();
    Box3 box;
    box.add({bbox.xmin() - grow, bbox.ymin() - grow, bbox.zmin() - grow});
    box.add({bbox.xmax() + grow, bbox.ymax() + grow, bbox.zmax() + grow});
    return box;
}

// Triangle t's box where it is now.
Box3 Separator::boxNow(std::uint32_t t) const {
    Box3 box;
    for (const std::uint32_t v : s_.triangles[t]) {
        const Vec3f& p = s_.points[v];
        box.add({p.x(), p.y(), p.z()});
    }
    return box;
}

// Crossing pairs with one of v's triangles where it is now (appended to `pairs` when given).
std::size_t Separator::crossingsAround(std::uint32_t v, std::vector<TrianglePair>* pairs) {
    collectNear(v);
    return crossingsNear(v, pairs);
}

// Fills near_ for the moves tryMoves tries: v goes at most 2 maxMove from where it is (maxMove
// from where it was, which it may already be maxMove from), so the boxes of its triangles grow
// by at most that, and crossingsNear need not search the tree for every move (the searches had
// been 40 % of the repair's time: ABOP 1.24a tries 22 moves per vertex, 1.24c 77).
void Separator::collectNear(std::uint32_t v) {
    nearFirst_.clear();
    near_.clear();
    const auto [first, end] = star(v);
    for (std::uint32_t i = first; i < end; ++i) {
        const std::uint32_t f = around_[i];
        nearFirst_.push_back(static_cast<std::uint32_t>(near_.size()));
        const Box3 reach = reachOf(f, (kReach + 2.01) * maxMove_);
        tree_->forEachOverlapping(reach, [&](std::uint32_t k) {
            if (local_[k] != f) near_.push_back(local_[k]);
        });
#if defined(RAMUS_ENABLE_ASSERTS)
        // What a search of every triangle would find: each whose box, as it was, meets the reach
        // (on one search in 16: a pass over the surface each time doubled the unions' tests).
        if (nearChecks_++ % 16 != 0) continue;
        std::vector<std::uint32_t> found(near_.begin() + nearFirst_.back(), near_.end());
        std::sort(found.begin(), found.end());
        for (std::uint32_t g = 0; g < s_.triangles.size(); ++g) {
            RAMUS_ASSERT(g == f || !originalBox(g).overlaps(reach) ||
                         std::binary_search(found.begin(), found.end(), g));
        }
#endif
    }
    nearFirst_.push_back(static_cast<std::uint32_t>(near_.size()));
    work_ += near_.size();
    lastCrossing_ = {kNoPair, kNoPair};
}

// The crossing pairs with one of v's triangles (appended to `pairs` when given), for v where
// collectNear(v) allowed for: of the triangles collected, those whose boxes where they are now
// meet the box of one of v's triangles are tested (since session 38; before, those whose stored
// boxes came within kReach maxMove of it: ABOP 1.24a's first repair took 88 ms instead of 67,
// 1.6 M pairs tested for 8 k moves tried, the same moves).
std::size_t Separator::crossingsNear(std::uint32_t v, std::vector<TrianglePair>* pairs) const {
    std::size_t count = 0;
    const auto [first, end] = star(v);
    work_ += near_.size();
    for (std::uint32_t i = first; i < end; ++i) {
        const std::uint32_t f = around_[i];
        const Box3 box = boxNow(f);
        const std::uint32_t k = i - first;
        for (std::uint32_t n = nearFirst_[k]; n < nearFirst_[k + 1]; ++n) {
            const std::uint32_t g = near_[n];
            if (!boxNow(g).overlaps(box) || !cross(f, g)) continue;
            ++count;
            if (pairs != nullptr) pairs->emplace_back(std::min(f, g), std::max(f, g));
        }
    }
    return count;
}

// Whether at most `most` of the pairs crossingsNear(v) counts cross, stopping at the first
// most + 1. The pair that ended the previous count is tested first: the moves tryMoves tries one
// after another mostly fail on the same pair (ABOP 1.24a's first repair: 8 k moves tried, which
// had tested 1.6 M pairs in all, most of them apart).
bool Separator::atMostCrossingsNear(std::uint32_t v, std::size_t most) {
    std::size_t count = 0;
    const auto [first, end] = star(v);
    // (A copy: clang 14, the fuzz build's, does not let lambdas capture structured bindings.)
    auto crosses = [&, first = first](std::uint32_t k, std::uint32_t n, const Box3& box) {
        const std::uint32_t g = near_[n];
        return boxNow(g).overlaps(box) && cross(around_[first + k], g);
    };
    const auto [lastK, lastN] = lastCrossing_;
    if (lastK != kNoPair && crosses(lastK, lastN, boxNow(around_[first + lastK])) &&
        ++count > most) {
        return false;
    }
    for (std::uint32_t k = 0; k + first < end; ++k) {
        const Box3 box = boxNow(around_[first + k]);
        for (std::uint32_t n = nearFirst_[k]; n < nearFirst_[k + 1]; ++n) {
            ++work_;
            if ((k == lastK && n == lastN) || !crosses(k, n, box)) continue;
            lastCrossing_ = {k, n};
            if (++count > most) return false;
        }
    }
    return true;
}

// Every triangle of v keeps its orientation and some area (normals before the move given).
bool Separator::turnsNoTriangle(std::uint32_t v, const std::vector<Vec3>& before) const {
    const auto [first, end] = star(v);
    for (std::uint32_t i = first; i < end; ++i) {
        const std::uint32_t t = around_[i];
        if (!(normal(t).dot(before[i - first]) > 0.0) || degenerate(t)) return false;
    }
    return true;
}

// Tries moves of v in directions_, smallest first (1, 2, 4, … float steps, each direction in
// turn), and keeps the first that turns no triangle of v over and leaves at most `most`
// crossings around v. normals_ holds the normals of v's triangles before the move.
bool Separator::tryMoves(std::uint32_t v, std::size_t most) {
    const Vec3f start = s_.points[v];
    const Vec3f origin = originalOf(v);
    const Vec3 p = start.cast<double>();
    collectNear(v);
    for (double step = ulpAt(start); step <= maxMove_; step *= 2.0) {
        for (const Vec3& d : directions_) {
            const Vec3f q = (p + step * d).cast<float>();
            if (q == start || (q - origin).cast<double>().norm() > maxMove_) continue;
            s_.points[v] = q;
            if (turnsNoTriangle(v, normals_) && atMostCrossingsNear(v, most)) {
                if (!moved_[v]) original_.emplace(v, origin);
                moved_[v] = 1;
                return true;
            }
            s_.points[v] = start;
        }
    }
    return false;
}

// Fills normals_ with the normals of v's triangles and returns their sum (v's normal).
Vec3 Separator::vertexNormal(std::uint32_t v) {
    normals_.clear();
    Vec3 sum = Vec3::Zero();
    const auto [first, end] = star(v);
    for (std::uint32_t i = first; i < end; ++i) {
        normals_.push_back(normal(around_[i]));
        sum += normals_.back();
    }
    return sum;
}

// Adds d and −d to directions_ (a zero d adds nothing).
void Separator::addDirection(const Vec3& d) {
    if (!(d.norm() > 0.0)) return;
    directions_.push_back(d.normalized());
    directions_.push_back(-d.normalized());
}

// A move of v that lowers the crossings around it: off the sheets first (v's normal, the
// partner triangle's), then towards the middle of v's neighbours (which widens a sliver), away
// from the partner's corners (a corner of another sheet a rounding error away), along the axes.
bool Separator::separate(std::uint32_t v, std::uint32_t partner) {
    const std::size_t before = crossingsAround(v);
    if (before == 0) return false;
    directions_.clear();
    addDirection(vertexNormal(v));
    addDirection(normal(partner));
    addTowardsMiddle(v);
    const Vec3 p = s_.points[v].cast<double>();
    for (std::uint32_t w : s_.triangles[partner]) addDirection(p - s_.points[w].cast<double>());
    for (int axis = 0; axis < 3; ++axis) addDirection(Vec3::Unit(axis));
    return tryMoves(v, before - 1);
}

// Adds the direction from v towards the middle of its triangles' corners (which widens a
// sliver), and its opposite.
void Separator::addTowardsMiddle(std::uint32_t v) {
    Vec3 middle = Vec3::Zero();
    const auto [first, end] = star(v);
    for (std::uint32_t i = first; i < end; ++i) {
        for (std::uint32_t w : s_.triangles[around_[i]]) middle += s_.points[w].cast<double>();
    }
    addDirection(middle / (3.0 * (end - first)) - s_.points[v].cast<double>());
}

// A move of v, a corner of a sheet that rounding pinched to another along an edge, off that
// position: into its own solid first (−normal), which opens a gap to the other sheet, then out,
// then towards the middle of its neighbours and along the axes (where a sliver beside v turns
// over along the normal); no more crossings around v than before.
bool Separator::unpinch(std::uint32_t v) {
    const std::size_t before = crossingsAround(v);
    directions_.clear();
    addDirection(-vertexNormal(v));
    addTowardsMiddle(v);
    for (int axis = 0; axis < 3; ++axis) addDirection(Vec3::Unit(axis));
    return tryMoves(v, before);
}

// Moves the listed vertices in order, each only while another surface vertex still shares its
// position: once one corner of a pinched pair has moved, its partner stays (a caller may list
// both sheets' corners, the preferred sheet first, so that the other moves where a corner of the
// first cannot).
CrossingRepair Separator::unpinchAll(std::span<const std::uint32_t> vertices) {
    std::unordered_map<PositionBits, std::uint32_t, PositionBitsHash> sharing;
    for (std::uint32_t v : vertices) sharing.emplace(bitsOf(s_.points[v]), 0);
    for (const Vec3f& p : s_.points) {
        if (auto it = sharing.find(bitsOf(p)); it != sharing.end()) ++it->second;
    }
    cover(vertices);
    CrossingRepair repair;
    for (std::uint32_t v : vertices) {
        if (pastWorkLimit()) break;
        std::uint32_t& shared = sharing.at(bitsOf(originalOf(v)));
        if (shared < 2 || s_.points[v] != originalOf(v) || !movable(v) || !unpinch(v)) continue;
        --shared;
        ++repair.movedVertices;
    }
    reportWork(repair);
    return repair;
}

// Rounds over the pairs still to separate. A move is kept when it lowers the crossings around
// its vertex in all, so it may have made new pairs there (a corner that parts from a position
// it shared with another sheet): those join the list for the next round.
CrossingRepair Separator::run(std::span<const TrianglePair> crossing) {
    CrossingRepair repair;
    std::vector<TrianglePair> pending(crossing.begin(), crossing.end());
    std::vector<TrianglePair> made;
    std::vector<std::uint32_t> corners;  // of the pending pairs: the vertices that may move
    for (int round = 0; round < 8; ++round) {
        made.clear();
        corners.clear();
        for (const auto& [f, g] : pending) {
            for (const std::uint32_t t : {f, g}) {
                corners.insert(corners.end(), s_.triangles[t].begin(), s_.triangles[t].end());
            }
        }
        cover(corners);
        for (const auto& [f, g] : pending) {
            for (int side = 0; side < 2 && cross(f, g); ++side) {
                const std::uint32_t mine = side == 0 ? f : g;
                const std::uint32_t partner = side == 0 ? g : f;
                for (std::uint32_t v : s_.triangles[mine]) {
                    if (pastWorkLimit()) break;
                    if (!movable(v) || !separate(v, partner)) continue;
                    ++repair.movedVertices;
                    crossingsAround(v, &made);
                    if (!cross(f, g)) break;
                }
            }
        }
        if (made.empty() || pastWorkLimit()) break;
        pending.insert(pending.end(), made.begin(), made.end());
        std::sort(pending.begin(), pending.end());
        pending.erase(std::unique(pending.begin(), pending.end()), pending.end());
        std::erase_if(pending, [&](const TrianglePair& p) { return !cross(p.first, p.second); });
    }
    reportWork(repair);
    repair.pairsLeft = static_cast<std::size_t>(
        std::count_if(pending.begin(), pending.end(),
                      [&](const TrianglePair& p) { return cross(p.first, p.second); }));
    return repair;
}

}  // namespace

std::uint64_t crossingRepairWorkLimit(std::size_t triangles) {
    return kCrossingRepairWorkFloor + std::uint64_t{kCrossingRepairWorkPerTriangle} * triangles;
}

CrossingRepair separateCrossings(CrossingSurface& surface, std::span<const TrianglePair> crossing,
                                 double maxMove, std::optional<std::uint64_t> workLimit) {
    if (crossing.empty()) return {};
    return Separator(surface, maxMove,
                     workLimit.value_or(crossingRepairWorkLimit(surface.triangles.size())))
        .run(crossing);
}

CrossingRepair unpinchVertices(CrossingSurface& surface, std::span<const std::uint32_t> vertices,
                               double maxMove, std::optional<std::uint64_t> workLimit) {
    if (vertices.empty()) return {};
    return Separator(surface, maxMove,
                     workLimit.value_or(crossingRepairWorkLimit(surface.triangles.size())))
        .unpinchAll(vertices);
}

}  // namespace ramus::detail

#endif  // RAMUS_WITH_CGAL
