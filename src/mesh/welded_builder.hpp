// The welded mesher's output stage, shared by welded_mesher.cpp (tubes along limbs, caps) and
// welded_junction_mesh.cpp (convex-hull junctions). Internal to src/mesh.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "on_cores.hpp"
#include "ramus/mesh.hpp"
#include "ramus/tree_wind.hpp"
#include "ramus/welded_mesher.hpp"
#include "ring_frames.hpp"
#include "segment_grid.hpp"
#include "welded_hull.hpp"
#include "welded_skeleton.hpp"

namespace ramus::detail {

/// One emitted ring: n + 1 vertices from `base` (the last repeats the first with u = 1).
struct RingRecord {
    std::uint32_t base = 0;
    int n = 0;
    Vec3 center = Vec3::Zero();
    Vec3 e1 = Vec3::Zero();  ///< frame: vertex i at center + radius (cos_i e1 + sin_i e2)
    Vec3 e2 = Vec3::Zero();
    Vec3 outward = Vec3::Zero();  ///< unit, away from the junction (or the limb's direction)
    double radius = 0.0;
    WindSample wind;  ///< of every vertex of the ring (and of caps made from it)
};

/// The branches around a junction as tapered capsules, for shrinking its hull onto them
/// (welded_junction_refine.cpp).
struct JunctionShape {
    struct Capsule {
        Capsule(const Vec3& from, const Vec3& to, double radiusFrom, double radiusTo)
            : a(from),
              b(to),
              ra(radiusFrom),
              rb(radiusTo),
              ab(to - from),
              length2(ab.squaredNorm()),
              inverse2(length2 > 0.0 ? 1.0 / length2 : 0.0) {}
        Vec3 a, b;
        double ra, rb;
        Vec3 ab;          ///< b − a
        double length2;   ///< |b − a|²
        double inverse2;  ///< 1 / |b − a|² (0 for a ball)
        struct Point {
            Vec3 offset;    ///< from the nearest axis point to the query point
            double radius;  ///< the capsule's radius there
        };
        /// The axis point nearest to `p` (tapered radius linear along the axis).
        Point nearest(const Vec3& p) const;
    };
    /// A capsule and a lower bound of its surface's distance from every point of a segment.
    struct Bound {
        double distance;
        std::uint32_t capsule;
        bool operator<(const Bound& o) const {
            return distance < o.distance || (distance == o.distance && capsule < o.capsule);
        }
    };
    std::vector<Capsule> capsules;
    double thinnest = 0.0;  ///< radius of the junction's thinnest arm
    double fillet = 0.0;    ///< blend width of the smooth minimum
    /// Signed distance to the union of the capsules, smoothed by the fillet (< 0 inside);
    /// `gradient` (optional) receives its direction of steepest ascent (about unit length).
    double distance(const Vec3& p, Vec3* gradient = nullptr) const;
    /// The distance to the nearest capsule's surface, without the fillet.
    double plainDistance(const Vec3& p) const;
    /// distance(p, gradient) folding the capsules in `order` (bounds for a segment holding p,
    /// nearest first; those that cannot change the distance may be left out) up
    /// to the first whose bound shows that it and all after it leave the result as it is: the
    /// value of folding them all in that order, for a fraction of the work where hundreds of
    /// branch segments are in reach and a few are near.
    double distance(const Vec3& p, std::span<const Bound> order, Vec3* gradient = nullptr) const;
    /// Whether `p` lies more than `limit` local radii outside the capsules (without the
    /// fillet; welded_junction_refine.cpp says which radius).
    bool farOutside(const Vec3& p, double limit) const;
};

class JunctionRefiner;  // welded_junction_refine.cpp

class WeldBuilder {
public:
    WeldBuilder(const BranchTree& tree, const WeldedMeshParams& params);
    Mesh build(WeldReport* report);

private:
    struct LimbRing {
        RingPlace place;
        double v;
    };

    // welded_mesher.cpp
    const AngleTable& table(int n);
    void gatherLimbRings(std::int32_t limb);
    void meshLimb(std::int32_t limb);
    void meshAbsorbedLimb(std::int32_t limb);
    void tubeAbsorbedLimb(std::int32_t limb);
    void emitPointsBeforeRings(std::int32_t limb);
    double vFromNode(const WeldLimb& limb, bool fromEnd, std::uint32_t k, double v) const;
    double vAfterStep(std::uint32_t point, double v) const;
    WindSample windAt(const RingPlace& place) const;
    RingRecord emitRing(const RingPlace& place, const Vec3& e1, float v, int n,
                        const WindSample& wind);
    RingRecord ringAfter(const RingRecord& previous, const RingPlace& place, float v);
    void emitSides(std::uint32_t a, std::uint32_t b, int n);
    void emitCap(const RingRecord& ring, const Vec3& normal, bool tip, const Vec3& centre);

    // welded_junction_mesh.cpp
    void meshJunction(NodeId cluster);
    void gatherJunction(NodeId cluster);
    bool buildHull(std::size_t firstRing = 0);
    bool holesAreRings();
    void emitHull();
    double depthInHull(const Vec3& point) const;
    bool addNodeBalls();
    bool addBendRings();
    void fallbackJunction();
    std::uint32_t seamVertex(std::uint32_t point, const std::array<std::uint32_t, 3>& face) const;

    // welded_junction_refine.cpp
    bool refineJunction(std::size_t firstIndex, bool judgeWebs);
    void tryMoreCentres(JunctionRefiner& refiner, const Vec3& first,
                        const std::vector<Vec3>& samples);
    bool gatherOwnShape(std::size_t firstIndex, Vec3& centre, double& reach);
    bool hullWebbed(std::size_t firstIndex);
    bool gatherJunctionShape(const Vec3& centre, double reach);
    void addSegmentInReach(std::uint32_t p, const Vec3& centre, double reach);
    bool onArmRingEdge(std::uint32_t a, std::uint32_t b) const;

    const WeldedMeshParams& params_;
    WeldSkeleton skeleton_;
    WeldJunctions junctions_;
    double margin_ = 0.05;
    double vScale_ = 1.0;
    std::vector<AngleTable> tables_;               // by n - 3, built on first use
    std::vector<double> keyV_;                     // per node: texture v at key nodes
    std::vector<RingRecord> startRing_, endRing_;  // per limb: its rings at junctions
    std::vector<std::uint32_t> discFirst_;         // per limb + 1: absorbed rings in discs_
    // Per limb: 1 = the tube mesher's chain runs on into it from the limb ending at its start
    // (its first edge's child keeps its parent's branch depth: tube_mesher.cpp, linkChains).
    std::vector<std::uint8_t> continuesChain_;
    std::vector<RingRecord> discs_;
    // Per limb side (2 l: at its start, 2 l + 1: at its end) + 1: rings of its inner points
    // between the junction's node and the limb's ring there (hull points) in before_.
    std::vector<std::uint32_t> beforeFirst_;
    std::vector<RingRecord> before_;
    std::vector<LimbRing> rings_;  // rings of the limb being meshed, reused
    Mesh mesh_;
    TreeWind wind_;  // when params.tube.windAttributes
    WindAttributes windOut_;
    WeldReport report_;

    // Junction scratch, reused.
    enum class HullRingKind : std::uint8_t {
        Arm,       // an arm's ring: its disc is cut out (a hole)
        Absorbed,  // a ring of a limb inside the junction: plain points
        Before,    // a ring of an arm's limb between the node and the arm's ring: plain points
        Ball,      // a latitude ring of a ball around an exposed branch node: plain points
    };
    struct HullRing {
        RingRecord ring;
        HullRingKind kind;
        bool hole() const { return kind == HullRingKind::Arm; }
        bool start;  // the ring starts its limb (else it ends it)
        Vec3 node;   // the branch node where the ring's limb meets the junction
        std::int32_t limb;
        // Into pointsKept_ (ring.n flags: which of its points are hull points), or -1: all.
        std::int32_t kept = -1;
    };
    RingRecord armBackToNode(const HullRing& h);  // welded_junction_mesh.cpp
    double ballRoom(const Vec3& node, std::size_t arms, double& radius) const;
    void emitBall(const HullRing& h, double radius);
    std::vector<HullRing> hullRings_;
    std::vector<std::uint8_t> pointsKept_;  // see HullRing::kept
    std::vector<Vec3> points_;
    std::vector<std::int32_t> pointRing_;   // per hull point: index into hullRings_
    std::vector<std::int32_t> pointIndex_;  // per hull point: vertex in its ring, -1 = apex
    std::vector<int> coneFaces_;
    ConvexHull hull_;
    double hullExtent_ = 0.0;  // of the points of the last hull built (for its perturbation)
    // Per face of hull_, for depthInHull: its outward unit normal and the normal's dot with
    // its points (relative to hullRings_.front()'s centre, as points_).
    struct Plane {
        Vec3 normal;
        double offset;
    };
    std::vector<Plane> hullPlanes_;

    JunctionShape shape_;
    std::unique_ptr<SegmentGrid> segments_;  // built on the first junction shrunk
    CoreTeam team_;                          // shares a shrunk junction's rays
};

}  // namespace ramus::detail
