// The welded mesher's view of a BranchTree: coincident nodes merged (zero-length edges, edges
// drawn twice from one node), drawn edges grouped into limbs (unbranched stretches between key
// nodes), and the junction solver that places each limb's end rings. Internal to src/mesh
// (welded_*.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus::detail {

/// An unbranched stretch of drawn edges from key node `startKey` (towards the root) to key
/// node `endKey`. Key nodes: part roots (the root, nodes after a hidden edge), tips and branch
/// nodes (≥ 3 drawn edges).
struct WeldLimb {
    NodeId startKey = kNoNode;
    NodeId endKey = kNoNode;
    std::uint32_t first = 0;  ///< first point in WeldSkeleton's point arrays
    std::uint32_t count = 0;  ///< points (≥ 2): startKey, inner nodes, endKey
    int segments = 3;         ///< ring vertices of this limb
};

struct WeldSkeleton {
    std::vector<NodeId> rep;              ///< per node: the node it was merged into (or itself)
    std::vector<std::uint32_t> degree;    ///< per node: drawn edges at it (merged nodes: 0)
    std::vector<std::uint8_t> key;        ///< per node: 1 = key node
    std::vector<std::int32_t> inLimb;     ///< per key node: the limb ending there, or -1
    std::vector<std::int32_t> firstOut;   ///< per key node: first limb starting there, or -1
    std::vector<std::uint32_t> outCount;  ///< per key node: limbs starting there (consecutive)
    std::vector<WeldLimb> limbs;          ///< ordered so a limb's start key ends an earlier limb
    std::vector<Vec3> pointPosition;      ///< per limb point
    std::vector<double> pointArc;         ///< arc length from the limb's start
    std::vector<double> pointRadius;      ///< tube radius there (as buildTubeMesh's rings)
    std::vector<NodeId> pointNode;        ///< the tree node of each limb point
    /// Per limb point: pointDirection's unit direction of its limb there, computed once (the
    /// junction solver reads it for every ring it moves, in every step: ABOP 1.24c's serial ring
    /// placement had spent a sixth of its time normalizing the same edges again).
    std::vector<Vec3> pointDirections;
    double maxRadius = 0.0;
    double mergeDistance = 0.0;

    double limbLength(const WeldLimb& limb) const { return pointArc[limb.first + limb.count - 1]; }
};

/// Groups the drawn edges of `tree` into limbs with the radii and segment counts of
/// buildTubeMesh for `params`.
WeldSkeleton buildWeldSkeleton(const BranchTree& tree, const TubeMeshParams& params);

/// A ring on a limb, `t` arc length from one of its ends; `normal` points away from that end.
struct RingPlace {
    Vec3 center = Vec3::Zero();
    Vec3 normal = Vec3::Zero();
    double radius = 0.0;
    double arc = 0.0;  ///< arc length from the limb's start
    /// The tree edge the ring lies on, as the tube mesher's rings name it for their wind data
    /// (TreeWind::at): the node the edge ends at, and the fraction along it from its parent.
    NodeId edgeNode = kNoNode;
    double edgeFraction = 1.0;
};
RingPlace ringOnLimb(const WeldSkeleton& skeleton, const WeldLimb& limb, bool fromEnd, double t);

/// Unit direction of the limb at point k (k inside: bisector of its two edges).
inline const Vec3& pointDirection(const WeldSkeleton& skeleton, const WeldLimb& limb,
                                  std::uint32_t k) {
    return skeleton.pointDirections[limb.first + k];
}

/// The ring at limb point k (its node), facing pointDirection. Its edge is the one into the
/// point's node (k = 0: the start of the limb's first edge), as buildTubeMesh's ring there.
RingPlace ringAtPoint(const WeldSkeleton& skeleton, const WeldLimb& limb, std::uint32_t k);

/// The height of `point` over the plane of `ring` (along its normal).
inline double heightOver(const RingPlace& ring, const Vec3& point) {
    return (point - ring.center).dot(ring.normal);
}

/// How far a ring (unit normal, radius; its centre `height` over the plane of `ring`) reaches in
/// front of that plane: the height plus radius · sin of the angle between the two normals. In
/// floating point too it is at most height + radius (the sine is at most 1, and rounding is
/// monotone), which the junction solver uses to pass over rings far behind.
inline double reachInFront(const RingPlace& ring, double height, const Vec3& normal,
                           double radius) {
    const double cosine = ring.normal.dot(normal);
    return height + radius * std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
}
inline double reachInFront(const RingPlace& ring, const Vec3& center, const Vec3& normal,
                           double radius) {
    return reachInFront(ring, heightOver(ring, center), normal, radius);
}

/// Points within this fraction of their radius of the chord are left out by
/// forEachPointBeforeRing.
constexpr double kBeforeOffChord = 0.1;
/// The `clearance` of forEachPointBeforeRing, as a fraction of the junction margin: far above
/// the hull's apex lift (2e-4 of the margin), so the ring stays a face of the hull.
constexpr double kBeforeClearance = 0.25;

/// Calls visit(k) for the inner points k of `limb` that lie between its start node (or its end
/// node, `fromEnd`) and the junction ring `ring` (ringOnLimb at arc length `t` from that node,
/// normal away from the node), from the node outwards: a junction's hull spans these points
/// instead of a tube, and where the limb bends there their rings must be hull points, or the
/// hull cuts the bend off along the chord from the node to the ring. Points within 5 % of
/// their radius of the ring are left out (the ring covers them), and so are points whose ring
/// reaches to within `clearance` × the smaller radius of the ring's plane (a bend sharper than
/// the tube's radius folds the tube there anyway, and such a point would keep the ring from
/// being a face of the hull), and points on the chord (kBeforeOffChord).
template <class Visit>
void forEachPointBeforeRing(const WeldSkeleton& s, const WeldLimb& limb, bool fromEnd, double t,
                            const RingPlace& ring, double clearance, Visit visit) {
    const double length = s.limbLength(limb);
    for (std::uint32_t i = 1; i + 1 < limb.count; ++i) {
        const std::uint32_t k = fromEnd ? limb.count - 1 - i : i;
        const std::uint32_t p = limb.first + k;
        const double fromNode = fromEnd ? length - s.pointArc[p] : s.pointArc[p];
        if (fromNode >= t - 0.05 * s.pointRadius[p]) return;
        // On the chord from the node to the ring (a straight limb) the hull spans the tube
        // anyway, and the point's ring would only add slivers along it.
        const Vec3& node = s.pointPosition[fromEnd ? limb.first + limb.count - 1 : limb.first];
        const Vec3 chord = ring.center - node;
        const Vec3 off = s.pointPosition[p] - node;
        const double chord2 = chord.squaredNorm();
        const double along = chord2 > 0.0 ? std::clamp(off.dot(chord) / chord2, 0.0, 1.0) : 0.0;
        if ((off - along * chord).norm() <= kBeforeOffChord * s.pointRadius[p]) continue;
        const Vec3 normal = pointDirection(s, limb, k);
        const double front = reachInFront(ring, s.pointPosition[p], normal, s.pointRadius[p]) +
                             clearance * std::min(s.pointRadius[p], ring.radius);
        if (front < 0.0) visit(k, normal);
    }
}

/// Where the junction solver put things.
struct WeldJunctions {
    std::vector<std::int32_t> cluster;     ///< per node: its junction (a member node id) or -1
    std::vector<std::int32_t> nextMember;  ///< per node: next node of the same junction, or -1
    std::vector<NodeId> junctions;         ///< one member (the smallest id) per junction
    std::vector<double> startOffset;       ///< per limb: ring distance from its start key
    std::vector<double> endOffset;         ///< per limb: ring distance from its end key
    std::vector<std::uint8_t> absorbed;    ///< per limb: 1 = lies inside a junction's hull
    std::size_t merges = 0;
    std::size_t absorbedLimbs = 0;
    std::size_t crowded = 0;  ///< junctions at their size limit with rings that do not fit
    /// Limbs between two junctions too short for both end rings (the rings pass each other),
    /// counted once the junctions are placed; `crossing` flags them per limb (1).
    std::size_t crossings = 0;
    std::vector<std::uint8_t> crossing;
    /// Per limb: the plane of one ring that both junctions at its ends share instead of a ring
    /// each (shareCrossingRing), as a unit normal pointing from the start key's junction to the
    /// end key's and the offset of its points x (sharedNormal · x = sharedOffset); a zero normal
    /// for every other limb.
    std::vector<Vec3> sharedNormal;
    std::vector<double> sharedOffset;
    std::size_t sharedRings = 0;  ///< crossing limbs given a shared ring (not in `crossings`)
};

/// Places every limb's end rings so that at each junction no ring's plane cuts another
/// branch's ring (`margin` × radius of clearance), merging junctions and absorbing end limbs
/// where the limbs are too short for that.
WeldJunctions solveWeldJunctions(const WeldSkeleton& skeleton, double margin);

}  // namespace ramus::detail
