// A bounding volume hierarchy over boxes, for casting rays and finding the boxes near one: the
// broad phase of the solid union's winding numbers (src/mesh/solid_union.cpp) and of the
// crossing repair's searches (crossing_repair.cpp). Internal to src/mesh.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "box_overlaps.hpp"

namespace ramus::detail {

/// The boxes in a binary tree, built once and then only read (threads may search together): sorted
/// along a Morton curve of their centres, split in halves down to leaves of at most kLeafSize
/// boxes, each node holding the box around its boxes, widened by a relative 1e-9 of the scene so
/// that the slab test in floating point never misses a box that a ray touches. Building is a sort
/// and a linear pass (CGAL's AABB tree, which it replaced for the union's rays in session 31,
/// splits at the median on every level: 0.09 s for tree_3d's 257 k triangles, most of the patch
/// classification's time).
class BoxTree {
public:
    static constexpr std::uint32_t kLeafSize = 4;

    explicit BoxTree(const std::vector<Box3>& boxes);

    /// Calls visit(i) for every box i that the ray from `origin` along `direction` meets (and
    /// any it passes within the widening of), each once, in no particular order. Empty boxes
    /// are never visited.
    template <class Visit>
    void forEachAlongRay(const std::array<double, 3>& origin,
                         const std::array<double, 3>& direction, Visit visit) const {
        if (nodes_.empty()) return;
        std::array<double, 3> inverse;
        for (int d = 0; d < 3; ++d) inverse[d] = direction[d] == 0.0 ? 0.0 : 1.0 / direction[d];
        std::uint32_t stack[64];  // depth ≤ log2(boxes / kLeafSize) + 1
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const std::uint32_t n = stack[--top];
            const Node& node = nodes_[n];
            if (!meets(node.box, origin, direction, inverse)) continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    if (meets(boxes_[i], origin, direction, inverse)) visit(order_[i]);
                }
                continue;
            }
            stack[top++] = node.first;  // the right child
            stack[top++] = n + 1;       // the left child, first
        }
    }

    /// Calls visit(i) for every box i that overlaps `query` (touching counts; and any within
    /// the widening of it), each once, in no particular order.
    template <class Visit>
    void forEachOverlapping(const Box3& query, Visit visit) const {
        if (nodes_.empty() || query.empty()) return;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const std::uint32_t n = stack[--top];
            const Node& node = nodes_[n];
            if (!node.box.overlaps(query)) continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    if (boxes_[i].overlaps(query)) visit(order_[i]);
                }
                continue;
            }
            stack[top++] = node.first;
            stack[top++] = n + 1;
        }
    }

    /// Whether the ray from `origin` along `direction` (`inverse`: 1 / each component, 0 where
    /// that is 0) meets the box (slab test; boxes are to be widened as the tree's are).
    static bool meets(const Box3& box, const std::array<double, 3>& origin,
                      const std::array<double, 3>& direction,
                      const std::array<double, 3>& inverse) {
        double near = 0.0, far = std::numeric_limits<double>::infinity();
        for (int d = 0; d < 3; ++d) {
            if (direction[d] == 0.0) {
                if (origin[d] < box.lo[d] || origin[d] > box.hi[d]) return false;
                continue;
            }
            double t0 = (box.lo[d] - origin[d]) * inverse[d];
            double t1 = (box.hi[d] - origin[d]) * inverse[d];
            if (t0 > t1) std::swap(t0, t1);
            near = std::max(near, t0);
            far = std::min(far, t1);
        }
        return near <= far;
    }

    /// How much the boxes are widened, for a scene whose coordinates reach `magnitude` in
    /// absolute value (and whose extent is at most that).
    static double widening(double magnitude) { return 1e-9 * magnitude; }

private:
    struct Node {
        Box3 box;
        std::uint32_t first = 0;  // a leaf's first index into order_, else the right child
        std::uint32_t count = 0;  // boxes in a leaf; 0 for an inner node (left child next)
    };

    std::uint32_t build(std::uint32_t first, std::uint32_t count);

    std::vector<std::uint32_t> order_;  // box indices along the curve (non-empty boxes only)
    std::vector<Box3> boxes_;           // their boxes, widened, in that order
    std::vector<Node> nodes_;           // depth first: a node's left child follows it
    double widen_ = 0.0;
};

}  // namespace ramus::detail
