// The limb graph of the welded mesher (see welded_skeleton.hpp): one pass merges coincident
// nodes (zero-length edges, edges drawn twice), a second groups drawn edges into limbs between
// key nodes. Radii, the trunk multiplier and the segment rule are those of buildTubeMesh
// (src/mesh/tube_mesher.cpp), so a welded branch's rings lie on the same tube.
#include "welded_skeleton.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace ramus::detail {
namespace {

constexpr int kMaxSegments = 4096;

// The tube mesher's segment rule: min + round((max - min) · r / r_max).
int segmentsFor(const TubeMeshParams& params, double radius, double maxRadius) {
    const int lo = std::clamp(params.minSegments, 3, kMaxSegments);
    const int hi = std::clamp(params.maxSegments, lo, kMaxSegments);
    if (!(maxRadius > 0.0)) return lo;
    const double t = std::clamp(radius / maxRadius, 0.0, 1.0);
    return lo + static_cast<int>((hi - lo) * t + 0.5);
}

// Distance within which a node coincides with an earlier-drawn sibling: a thousandth of the
// smaller of the two edges' radii and lengths (at least the merge distance). The turtle draws
// ABOP 1.24b's `[F]` and the `F` of the following branch from the same state, and 1.24f's
// `+X` and `+F` along the same line; the copies agree to rounding, far below this.
constexpr double kSiblingTolerance = 1e-3;
// Chains turning by more than about 93° at a node (cosine of the turn below this) get a
// junction. Until session 17 this was 120°: colonization tips that turned by 96–108° just
// past a branch node ran their tube through that node's hull (the junction triangle
// intersections of broadleaf 12, hedge_4 4, roots 7, all gone at this bound; docs/welded.md).
// Not 90° itself: the turtle's right angles (koch_island) come out a rounding error either side.
constexpr double kFoldCosine = -0.05;

// Drawn edges by the grid cell of their end node, to find an edge drawn again from another
// node: ABOP 1.31a's lattice of unit steps at multiples of 22.5° sends later branches along
// edges already drawn. Their tubes would coincide vertex for vertex with the first ones and
// share edges with them (no longer 2-manifold), and they add nothing to the surface.
class DrawnEdges {
public:
    DrawnEdges(const BranchTree& tree, const std::vector<NodeId>& rep, double tolerance)
        : tree_(tree), rep_(rep), tolerance_(tolerance), cell_(2.0 * tolerance) {
        // One bit per cell hash, 4–8 per node: most queried cells are empty, and the bit
        // says so without probing the hash table (a cache miss each on large trees).
        std::size_t bits = 64;
        while (bits < 4 * tree.size()) bits *= 2;
        occupied_.assign(bits / 64, 0);
        mask_ = bits - 1;
        // Open addressing with linear probing, at most half full (every node is added at most
        // once): a node-based hash map cost a cache miss per insertion and another per node
        // freed: a seventh of the welding time of the synthetic monopodial tree at 1M edges.
        std::size_t slots = 16;
        while (slots < 2 * tree.size()) slots *= 2;
        slots_.assign(slots, Slot{0, kNoNode});
        slotMask_ = slots - 1;
    }

    void add(NodeId node) {
        const Cell c = cellOf(tree_.node(node).position);
        const std::size_t hash = CellHash{}(c);
        const std::size_t h = hash & mask_;
        occupied_[h / 64] |= std::uint64_t{1} << (h % 64);
        std::size_t i = hash & slotMask_;
        while (slots_[i].node != kNoNode) i = (i + 1) & slotMask_;
        slots_[i] = {tagOf(hash), node};
    }

    // An edge drawn so far between (near) `from` and (near) `to`, either way round: its node
    // at `to` and the node that holds its radius (the edge's end); kNoNode when there is none.
    struct Copy {
        NodeId atTo = kNoNode;
        NodeId edge = kNoNode;
    };
    Copy between(const Vec3& from, const Vec3& to) const {
        const NodeId forward = endingAt(to, from);
        if (forward != kNoNode) return {forward, forward};
        const NodeId backward = endingAt(from, to);
        if (backward != kNoNode) return {rep_[tree_.node(backward).parent], backward};
        return {};
    }

private:
    using Cell = std::array<std::int64_t, 3>;

    // Cells twice the tolerance wide, so the tolerance around a point meets at most two per
    // axis: its own and the neighbour on the nearer side (`side`: −1 or +1). Eight lookups per
    // query instead of 27 with cells one tolerance wide, which took a quarter of the welding
    // time of the synthetic monopodial tree (1M edges: two queries per edge, each a chain of
    // cache misses). Clamped so that no position (nor a non-finite one) overflows the cast.
    Cell cellOf(const Vec3& p, Cell* side = nullptr) const {
        Cell c;
        for (int axis = 0; axis < 3; ++axis) {
            const double scaled = p[axis] / cell_;
            const double x = std::floor(scaled);
            const bool finite = x >= -1e15 && x <= 1e15;
            c[static_cast<std::size_t>(axis)] = finite ? static_cast<std::int64_t>(x) : 0;
            if (side) (*side)[static_cast<std::size_t>(axis)] = scaled - x < 0.5 ? -1 : 1;
        }
        return c;
    }

    // A drawn edge ending within the tolerance of `end` whose start is within it of `start`.
    NodeId endingAt(const Vec3& end, const Vec3& start) const {
        Cell side;
        const Cell c = cellOf(end, &side);
        const double tolerance2 = tolerance_ * tolerance_;
        for (int dx = 0; dx <= 1; ++dx) {
            for (int dy = 0; dy <= 1; ++dy) {
                for (int dz = 0; dz <= 1; ++dz) {
                    const Cell cell{c[0] + dx * side[0], c[1] + dy * side[1], c[2] + dz * side[2]};
                    const std::size_t hash = CellHash{}(cell);
                    const std::size_t h = hash & mask_;
                    if (!(occupied_[h / 64] >> (h % 64) & 1)) continue;
                    // Slots of other cells with the same tag only add candidates, which the
                    // distance test drops.
                    for (std::size_t i = hash & slotMask_; slots_[i].node != kNoNode;
                         i = (i + 1) & slotMask_) {
                        if (slots_[i].tag != tagOf(hash)) continue;
                        const BranchNode& node = tree_.node(slots_[i].node);
                        const Vec3& parent = tree_.node(rep_[node.parent]).position;
                        if ((node.position - end).squaredNorm() <= tolerance2 &&
                            (parent - start).squaredNorm() <= tolerance2) {
                            return slots_[i].node;
                        }
                    }
                }
            }
        }
        return kNoNode;
    }

    struct CellHash {
        std::size_t operator()(const Cell& c) const {
            std::uint64_t h = 0x9E3779B97F4A7C15ull;
            for (std::int64_t v : c)
                h = (h ^ static_cast<std::uint64_t>(v)) * 0xBF58476D1CE4E5B9ull;
            return static_cast<std::size_t>(h ^ (h >> 31));
        }
    };

    const BranchTree& tree_;
    const std::vector<NodeId>& rep_;
    double tolerance_;
    double cell_;
    static std::uint32_t tagOf(std::size_t hash) { return static_cast<std::uint32_t>(hash >> 32); }
    struct Slot {
        std::uint32_t tag;  // the high bits of the cell's hash
        NodeId node;        // the drawn edge's end node; kNoNode: empty
    };
    std::vector<Slot> slots_;  // drawn edges by the cell of their end node
    std::size_t slotMask_ = 0;
    std::vector<std::uint64_t> occupied_;  // bit (hash & mask_): some drawn edge ends in a cell
    std::size_t mask_ = 0;
};

// Whether the chain through `node` (one drawn edge in, one to `child` out) turns by more than
// kFoldCosine allows. A tube ring there would face the bisector of a bend that sends the tube
// back along itself (colonization's tips at times grow back to their parent's node after the
// branch-angle reduction: turns of 165–179°), so its tube folds flat; as a key node it gets a
// junction instead, whose hull closes over the bend as at a fork.
bool foldsBack(const BranchTree& tree, const WeldSkeleton& s, NodeId node, NodeId child) {
    const Vec3& at = tree.node(node).position;
    const Vec3 in =
        at - tree.node(s.rep[static_cast<std::size_t>(tree.node(node).parent)]).position;
    const Vec3 out = tree.node(child).position - at;
    return in.dot(out) < kFoldCosine * in.norm() * out.norm();
}
// Merges every node closer than the merge distance to its (merged) parent into it, and every
// node that coincides with an earlier sibling (an edge drawn twice) into that sibling, which
// keeps the thicker radius; the merged node's children then hang from its representative, so
// an edge chain drawn twice merges node by node. An edge that repeats one drawn earlier from
// other nodes, either way round (DrawnEdges), is merged the same way: its end node into the
// earlier edge's node there, and the earlier edge keeps the thicker radius. Counts the drawn edges
// at every remaining node and marks the key nodes. Siblings are compared pairwise: quadratic only
// in a node's degree, as the ring placement at its junction is.
void mergeNodes(const BranchTree& tree, WeldSkeleton& s, std::vector<double>& radii,
                std::vector<std::uint8_t>& incoming) {
    const std::size_t n = tree.size();
    const double merge2 = s.mergeDistance * s.mergeDistance;
    s.rep.resize(n);
    s.degree.assign(n, 0);
    incoming.assign(n, 0);
    // Per node: its children so far after merging, as a list through nextChild.
    std::vector<NodeId> firstChild(n, kNoNode);
    std::vector<NodeId> nextChild(n, kNoNode);
    DrawnEdges drawn(tree, s.rep, 4.0 * s.mergeDistance);
    s.rep[0] = 0;
    for (std::size_t i = 1; i < n; ++i) {
        const BranchNode& node = tree.nodes()[i];
        s.rep[i] = static_cast<NodeId>(i);
        if (node.hidden) continue;
        const NodeId p = s.rep[static_cast<std::size_t>(node.parent)];
        const Vec3& origin = tree.node(p).position;
        const double length2 = (node.position - origin).squaredNorm();
        if (length2 <= merge2) {
            s.rep[i] = p;
            continue;
        }
        NodeId twin = firstChild[static_cast<std::size_t>(p)];
        for (; twin != kNoNode; twin = nextChild[static_cast<std::size_t>(twin)]) {
            const auto t = static_cast<std::size_t>(twin);
            const double scale = std::min({radii[i], radii[t], std::sqrt(length2),
                                           (tree.node(twin).position - origin).norm()});
            const double tolerance = std::max(s.mergeDistance, kSiblingTolerance * scale);
            if ((node.position - tree.node(twin).position).squaredNorm() <= tolerance * tolerance) {
                break;
            }
        }
        if (twin != kNoNode) {
            s.rep[i] = twin;
            double& kept = radii[static_cast<std::size_t>(twin)];
            kept = std::max(kept, radii[i]);
            continue;
        }
        const DrawnEdges::Copy copy = drawn.between(origin, node.position);
        if (copy.atTo != kNoNode) {
            s.rep[i] = copy.atTo;
            double& kept = radii[static_cast<std::size_t>(copy.edge)];
            kept = std::max(kept, radii[i]);
            continue;
        }
        drawn.add(static_cast<NodeId>(i));
        nextChild[i] = firstChild[static_cast<std::size_t>(p)];
        firstChild[static_cast<std::size_t>(p)] = static_cast<NodeId>(i);
        incoming[i] = 1;
        ++s.degree[i];
        ++s.degree[static_cast<std::size_t>(p)];
    }
    s.key.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const bool chainInterior = s.degree[i] == 2 && incoming[i] != 0 &&
                                   !foldsBack(tree, s, static_cast<NodeId>(i), firstChild[i]);
        s.key[i] = s.rep[i] == static_cast<NodeId>(i) && s.degree[i] > 0 && !chainInterior;
    }
}

// Radius at the start of the limb from key `k` to child `c`, as buildTubeMesh's rings: the
// root's chain starts with trunk × root radius; a chain running on through a branch node (the
// first child, same branch depth) keeps the node's radius; other children start with their own.
double startRadius(const BranchTree& tree, const std::vector<double>& radii, double trunk, NodeId k,
                   NodeId c) {
    const BranchNode& key = tree.node(k);
    const BranchNode& child = tree.node(c);
    const bool continues = child.parent == k && key.firstChild == c &&
                           child.branchDepth == key.branchDepth && !key.hidden;
    if (continues) return k == 0 ? trunk * radii[0] : radii[static_cast<std::size_t>(k)];
    return radii[static_cast<std::size_t>(c)];
}

// pointDirection, computed.
Vec3 directionAt(const WeldSkeleton& s, const WeldLimb& limb, std::uint32_t k) {
    const std::uint32_t p = limb.first + k;
    const Vec3 in =
        k > 0 ? Vec3((s.pointPosition[p] - s.pointPosition[p - 1]).normalized()) : Vec3::Zero();
    const Vec3 out = k + 1 < limb.count
                         ? Vec3((s.pointPosition[p + 1] - s.pointPosition[p]).normalized())
                         : Vec3::Zero();
    const Vec3 sum = in + out;
    const double length2 = sum.squaredNorm();
    if (length2 > 1e-12) return sum / std::sqrt(length2);
    return k > 0 ? in : out;
}

}  // namespace

WeldSkeleton buildWeldSkeleton(const BranchTree& tree, const TubeMeshParams& params) {
    WeldSkeleton s;
    const std::size_t n = tree.size();
    if (n < 2) return s;
    const Aabb box = tree.bounds();
    s.mergeDistance = 1e-6 * std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
    // Radii first: a node merged into an earlier sibling passes on its radius if thicker.
    std::vector<double> radii = computeEdgeRadii(tree, params);
    std::vector<std::uint8_t> incoming;
    mergeNodes(tree, s, radii, incoming);

    // Children of every remaining node (CSR, by child id).
    std::vector<std::uint32_t> childFirst(n + 1, 0);
    for (std::size_t i = 1; i < n; ++i) {
        if (incoming[i]) ++childFirst[static_cast<std::size_t>(s.rep[tree.nodes()[i].parent]) + 1];
    }
    for (std::size_t i = 0; i < n; ++i) childFirst[i + 1] += childFirst[i];
    std::vector<NodeId> children(childFirst[n]);
    std::vector<std::uint32_t> fill(childFirst.begin(), childFirst.end() - 1);
    for (std::size_t i = 1; i < n; ++i) {
        if (incoming[i]) {
            children[fill[static_cast<std::size_t>(s.rep[tree.nodes()[i].parent])]++] =
                static_cast<NodeId>(i);
        }
    }

    const double trunk = params.trunkMultiplier > 0.0 && std::isfinite(params.trunkMultiplier)
                             ? params.trunkMultiplier
                             : 1.0;
    s.inLimb.assign(n, -1);
    s.firstOut.assign(n, -1);
    s.outCount.assign(n, 0);
    s.limbs.reserve(childFirst[n] / 2 + 1);
    s.pointPosition.reserve(childFirst[n] + childFirst[n] / 2 + 2);
    // Limbs from every key node along each child until the next key node. Keys are visited in
    // id order, so a limb's start key always ends an earlier limb (parents precede children).
    for (std::size_t k = 0; k < n; ++k) {
        if (!s.key[k]) continue;
        s.outCount[k] = childFirst[k + 1] - childFirst[k];
        if (s.outCount[k] > 0) s.firstOut[k] = static_cast<std::int32_t>(s.limbs.size());
        for (std::uint32_t c = childFirst[k]; c < childFirst[k + 1]; ++c) {
            WeldLimb limb;
            limb.startKey = static_cast<NodeId>(k);
            limb.first = static_cast<std::uint32_t>(s.pointPosition.size());
            NodeId x = children[c];
            s.pointPosition.push_back(tree.node(limb.startKey).position);
            s.pointRadius.push_back(startRadius(tree, radii, trunk, limb.startKey, x));
            s.pointNode.push_back(limb.startKey);
            s.pointArc.push_back(0.0);
            for (;;) {
                const Vec3& p = tree.node(x).position;
                s.pointArc.push_back(s.pointArc.back() + (p - s.pointPosition.back()).norm());
                s.pointPosition.push_back(p);
                s.pointRadius.push_back(radii[static_cast<std::size_t>(x)]);
                s.pointNode.push_back(x);
                if (s.key[static_cast<std::size_t>(x)]) break;
                x = children[childFirst[static_cast<std::size_t>(x)]];
            }
            limb.endKey = x;
            limb.count = static_cast<std::uint32_t>(s.pointPosition.size()) - limb.first;
            s.inLimb[static_cast<std::size_t>(x)] = static_cast<std::int32_t>(s.limbs.size());
            s.limbs.push_back(limb);
        }
    }
    for (double r : s.pointRadius) s.maxRadius = std::max(s.maxRadius, r);
    s.pointDirections.resize(s.pointPosition.size());
    for (WeldLimb& limb : s.limbs) {
        limb.segments = segmentsFor(params, s.pointRadius[limb.first], s.maxRadius);
        for (std::uint32_t k = 0; k < limb.count; ++k) {
            s.pointDirections[limb.first + k] = directionAt(s, limb, k);
        }
    }
    return s;
}

RingPlace ringOnLimb(const WeldSkeleton& s, const WeldLimb& limb, bool fromEnd, double t) {
    const double length = s.limbLength(limb);
    const double arc = std::clamp(fromEnd ? length - t : t, 0.0, length);
    std::uint32_t k = 0;
    if (fromEnd) {
        k = limb.count - 2;
        while (k > 0 && s.pointArc[limb.first + k] > arc) --k;
    } else {
        while (k + 2 < limb.count && s.pointArc[limb.first + k + 1] < arc) ++k;
    }
    const std::uint32_t a = limb.first + k;
    const double span = s.pointArc[a + 1] - s.pointArc[a];
    const double u = std::clamp((arc - s.pointArc[a]) / span, 0.0, 1.0);
    const Vec3 direction = (s.pointPosition[a + 1] - s.pointPosition[a]) / span;
    RingPlace place;
    place.center = s.pointPosition[a] + u * (s.pointPosition[a + 1] - s.pointPosition[a]);
    place.radius = s.pointRadius[a] + u * (s.pointRadius[a + 1] - s.pointRadius[a]);
    place.normal = fromEnd ? Vec3(-direction) : direction;
    place.arc = arc;
    place.edgeNode = s.pointNode[a + 1];
    place.edgeFraction = u;
    return place;
}

RingPlace ringAtPoint(const WeldSkeleton& s, const WeldLimb& limb, std::uint32_t k) {
    const std::uint32_t p = limb.first + k;
    RingPlace place{s.pointPosition[p], pointDirection(s, limb, k), s.pointRadius[p],
                    s.pointArc[p]};
    place.edgeNode = s.pointNode[k > 0 ? p : p + 1];
    place.edgeFraction = k > 0 ? 1.0 : 0.0;
    return place;
}

}  // namespace ramus::detail
