// The welded mesher's output stage, shared by welded_mesher.cpp (tubes along limbs, caps) and
// welded_junction_mesh.cpp (convex-hull junctions). Internal to src/mesh.
#pragma once

#include <array>
#include <cstdint>
#include <mutex>
#include <optional>
#include <span>
#include <utility>
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

/// A SegmentGrid of the skeleton built by the first junction shrunk (on any mesher's thread):
/// trees whose junctions need no shrinking never build it.
class SharedSegmentGrid {
public:
    explicit SharedSegmentGrid(const WeldSkeleton& skeleton) : skeleton_(skeleton) {}
    const SegmentGrid& get() {
        std::call_once(built_, [&] { grid_.emplace(skeleton_); });
        return *grid_;
    }

private:
    const WeldSkeleton& skeleton_;
    std::once_flag built_;
    std::optional<SegmentGrid> grid_;
};

/// Where the welded mesher's stages write: a mesh with its wind values, and the rings, sides
/// and caps both stages emit (welded_mesher.cpp).
class WeldEmitter {
protected:
    WeldEmitter(const WeldedMeshParams& params, const TreeWind& wind)
        : params_(params), wind_(wind) {}

    const AngleTable& table(int n);  // built on first use
    WindSample windAt(const RingPlace& place) const;
    RingRecord emitRing(const RingPlace& place, const Vec3& e1, float v, int n,
                        const WindSample& wind, const Vec3* plane = nullptr);
    RingRecord ringAfter(const RingRecord& previous, const RingPlace& place, float v);
    void emitSides(std::uint32_t a, std::uint32_t b, int n);
    void emitCap(const RingRecord& ring, const Vec3& normal, bool tip, const Vec3& centre);

    const WeldedMeshParams& params_;
    const TreeWind& wind_;            // read when params.tube.windAttributes
    std::vector<AngleTable> tables_;  // by n, built on first use
    Mesh mesh_;
    WindAttributes windOut_;  // when params.tube.windAttributes
};

/// Appends a copy of vertices [first, first + count) of `from` (positions, normals, tangents,
/// texture coordinates: the welded mesher's) to `to` (welded_junction_mesh.cpp).
void appendVertices(Mesh& to, const Mesh& from, std::size_t first, std::size_t count);

/// Texture v at limb point `point` of `s` from v at the point before it (welded_mesher.cpp).
double vAfterStep(const WeldSkeleton& s, double vScale, std::uint32_t point, double v);

class WeldBuilder : WeldEmitter {
public:
    /// Meshes junctions on up to `cores` threads (the same mesh whatever their number).
    WeldBuilder(const BranchTree& tree, const WeldedMeshParams& params,
                std::size_t cores = machineCores());
    Mesh build(WeldReport* report);

private:
    friend class JunctionMesher;  // reads the tubes' rings and what placed them
    struct LimbRing {
        RingPlace place;
        double v;
    };

    // welded_mesher.cpp
    void gatherLimbRings(std::int32_t limb);
    void meshLimb(std::int32_t limb);
    void meshSharedRing(std::int32_t limb);
    void meshAbsorbedLimb(std::int32_t limb);
    void emitPointsBeforeRings(std::int32_t limb);
    double vFromNode(const WeldLimb& limb, bool fromEnd, std::uint32_t k, double v) const;
    void meshJunctions();

    WeldSkeleton skeleton_;
    WeldJunctions junctions_;
    TreeWind treeWind_;  // when params.tube.windAttributes (wind_ refers to it)
    double margin_ = 0.05;
    double vScale_ = 1.0;
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
    WeldReport report_;
    SharedSegmentGrid segments_{skeleton_};
    std::size_t cores_;
    CoreTeam team_;  // shares a shrunk junction's rays (junctions meshed on one thread)
};

/// Meshes junctions one at a time, each into a piece of its own mesh_ after the pieces of the
/// junctions before. While a junction is meshed, the vertices of the tube rings it joins are
/// copied into mesh_ first (in the order of their vertex numbers in the tubes' mesh), then come
/// those it adds and its triangles; when it is done, the copies are dropped and its triangles
/// name tube vertices by their numbers in the tubes' mesh and its own with kOwnVertex set.
/// Reads the builder's tubes and rings only, so several meshers run junctions on several
/// threads; the builder appends the pieces in junction order (WeldBuilder::meshJunctions).
class JunctionMesher : WeldEmitter {
public:
    /// In a piece's indices: the vertex is the piece's own (its number from the piece's first).
    /// Tube vertex numbers stay below it: 2³¹ vertices of 48 bytes would be 100 GiB, far
    /// beyond the node limits (docs/cli.md, "Limits").
    static constexpr std::uint32_t kOwnVertex = 0x80000000u;

    /// A junction's piece of mesh_: its own vertices and its triangles.
    struct Piece {
        std::uint32_t firstVertex = 0, endVertex = 0;
        std::size_t firstIndex = 0, endIndex = 0;
    };

    /// `team` shares the rays of a shrunk junction.
    JunctionMesher(WeldBuilder& builder, const Mesh& tubes, const WindAttributes& tubeWind,
                   CoreTeam& team);
    Piece meshJunction(NodeId cluster);
    /// Room in mesh_ for this many vertices and indices.
    void reserve(std::size_t vertices, std::size_t indices);
    const Mesh& mesh() const { return mesh_; }
    const WindAttributes& windOut() const { return windOut_; }
    /// The junction counters of every junction meshed (fallbacks, balls, bends, shrunk, tubed).
    const WeldReport& report() const { return report_; }

private:
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

    // welded_junction_mesh.cpp
    void gatherJunction(NodeId cluster);
    void copyTubeRings();
    void closeJunction();
    bool atCrossing() const;
    void eraseVertices(std::uint32_t first, std::uint32_t count);
    bool buildHull(std::size_t firstRing = 0);
    bool holesAreRings();
    void emitHull();
    double depthInHull(const Vec3& point) const;
    bool addNodeBalls();
    bool addBendRings();
    void fallbackJunction();
    void tubeAbsorbedLimb(std::int32_t limb);
    std::uint32_t seamVertex(std::uint32_t point, const std::array<std::uint32_t, 3>& face) const;
    RingRecord armBackToNode(const HullRing& h);
    double ballRoom(const Vec3& node, std::size_t arms, double& radius) const;
    void emitBall(const HullRing& h, double radius);

    // welded_junction_refine.cpp
    bool refineJunction(std::size_t firstIndex, bool judgeWebs);
    void tryMoreCentres(JunctionRefiner& refiner, const Vec3& first,
                        const std::vector<Vec3>& samples);
    bool gatherOwnShape(std::size_t firstIndex, Vec3& centre, double& reach);
    bool hullWebbed(std::size_t firstIndex);
    bool gatherJunctionShape(const Vec3& centre, double reach);
    void addSegmentInReach(std::uint32_t p, const Vec3& centre, double reach);
    bool onArmRingEdge(std::uint32_t a, std::uint32_t b) const;

    // The builder's, read only.
    const WeldSkeleton& skeleton_;
    const WeldJunctions& junctions_;
    const double margin_, vScale_;
    const std::vector<double>& keyV_;
    const std::vector<RingRecord>& startRing_;
    const std::vector<RingRecord>& endRing_;
    const std::vector<std::uint32_t>& discFirst_;
    const std::vector<std::uint8_t>& continuesChain_;
    const std::vector<RingRecord>& discs_;
    const std::vector<std::uint32_t>& beforeFirst_;
    const std::vector<RingRecord>& before_;
    SharedSegmentGrid& segments_;
    const Mesh& tubes_;  // the builder's mesh of the tubes, and their wind values
    const WindAttributes& tubeWind_;
    CoreTeam& team_;

    WeldReport report_;
    std::vector<std::uint32_t> tubeVertices_;  // per vertex copied: its number in the tubes'

    // Junction scratch, reused.
    std::vector<HullRing> hullRings_;
    std::vector<std::uint8_t> pointsKept_;  // see HullRing::kept
    std::vector<Vec3> points_;
    std::vector<std::int32_t> pointRing_;   // per hull point: index into hullRings_
    std::vector<std::int32_t> pointIndex_;  // per hull point: vertex in its ring, -1 = apex
    std::vector<int> coneFaces_;
    struct TubeRing {  // a ring of the tubes' mesh copied into mesh_ (copyTubeRings)
        std::uint32_t base, count, copy;
        bool operator<(const TubeRing& o) const { return base < o.base; }
        bool operator==(const TubeRing& o) const { return base == o.base; }
    };
    std::vector<TubeRing> tubeRings_;
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
    SegmentGrid::Marks segmentMarks_;
};

}  // namespace ramus::detail
