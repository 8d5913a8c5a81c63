// Which of many axis-aligned boxes overlap: the broad phase of the solid union's
// self-intersection and crossing tests (src/mesh/solid_union.cpp). Internal to src/mesh.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace ramus::detail {

/// A closed axis-aligned box; one with lo > hi on some axis is empty and overlaps nothing.
struct Box3 {
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    std::array<double, 3> hi{-std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};

    void add(const std::array<double, 3>& p) {
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
        }
    }
    bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
    bool overlaps(const Box3& b) const {
        return lo[0] <= b.hi[0] && b.lo[0] <= hi[0] && lo[1] <= b.hi[1] && b.lo[1] <= hi[1] &&
               lo[2] <= b.hi[2] && b.lo[2] <= hi[2];
    }
};

using BoxPair = std::pair<std::uint32_t, std::uint32_t>;

/// Whether a pair (i, j), i < j, of overlapping boxes is wanted; called from several threads.
using PairFilter = std::function<bool(std::uint32_t, std::uint32_t)>;

/// Every pair (i, j), i < j, of `boxes` that overlap (touching counts), where boxes[i] or
/// boxes[j] is `suspect` (every pair where `suspect` is empty), once each, in an order that
/// depends on the boxes alone (not sorted). A box with a coordinate that is not finite is left
/// out.
///
/// A few levels of uniform grids: level 0's cells twice as wide as the median box's largest
/// side, holding the boxes up to two of its cells wide; the next level the same over the boxes
/// left, and so on. Every box is entered in the cells of its level that it meets, is paired
/// with the boxes of those cells and looks up the cells it meets on the levels above (at most 8
/// on each); of the cells of a level that both boxes of a pair meet, the one holding the lowest
/// corner of their intersection reports it. With suspects only the suspects are entered: every
/// box looks them up on its level and above, and every suspect looks up the other boxes (in a
/// table of their own) above its level; where at most one box in 32 is a suspect, the suspects
/// go into a box tree (box_tree.hpp) that every box looks up instead, and where more than half
/// are, all pairs are found and those without a suspect dropped. For the boxes of a mesh's
/// triangles the work grows with the boxes and the pairs, whatever the mix of sizes (a tree's trunk
/// beside its twigs, a flat plant's large leaves). Replaced CGAL's box intersection (a segment tree
/// that sorts the boxes on every level) in session 30: the union's box searches had taken 0.5 s of
/// tree_3d's 1.5 s (8 derivations, 230 k triangles). Only pairs where keep(i, j) holds are returned
/// (every pair where `keep` is empty): the test runs as the pairs are found, on the search's
/// threads, so that the many pairs a test rejects (for a mesh's triangles: neighbours sharing a
/// corner) are never stored (tree_3d: 1.76 M overlapping pairs, 14 MB). Once `stop` (if given)
/// is set — by `keep`, say — the threads look at no more boxes and the pairs found so far are
/// returned, incomplete (the solid union's work limit: seed 332 of scripts/random-unions.py
/// enumerated its boxes' pairs for 1.1 s after the limit was passed).
std::vector<BoxPair> overlappingBoxes(const std::vector<Box3>& boxes,
                                      const std::vector<char>& suspect, const PairFilter& keep = {},
                                      const std::atomic<bool>* stop = nullptr);

}  // namespace ramus::detail
