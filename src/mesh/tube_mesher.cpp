// Based on: seed 002 §4.4.4 (rings of eq 4.2 joined into cylinder segments, 3 rings for 2
// cylinders along chains of equal branch depth, new chain for a child of other depth), §4.4.3
// (start radius = predecessor's end radius, root: trunk multiplier; start normal =
// predecessor's end normal), §3.5 eq 3.8 (curve reduction with max_K); Wang, Jüttler, Zheng,
// Liu 2008, "Computation of rotation minimizing frames" (double reflection); SPEC §D.
//
// Rules this file settles where the seed is silent or scale dependent:
// - Ring normal: eq 4.1 adds the unnormalised edge vector to the previous normal, so the result
//   depends on model units and lags one edge behind on curves. We use the symmetric form of the
//   same smoothing: an inner chain ring faces the bisector of its two unit edge directions (the
//   miter plane of a bent pipe); a chain's first ring faces its first edge (the seed's rule for
//   the root), its last ring faces its last edge. Within a chain the shared ring is both the
//   predecessor's end and the successor's start, so "start normal = predecessor's end normal"
//   holds by construction.
// - New chains (children with another branch depth, children of hidden nodes) start with a ring
//   at the parent node's position, facing the child's edge, with the child's own radius: under
//   Murray's rule r_child <= r_parent, so the ring lies inside the parent tube and the joint is
//   closed. Only the root chain starts with trunkMultiplier × (root radius).
// - Segment count per chain (all rings of a chain share vertices, so they share n):
//   n = minSegments + round((maxSegments - minSegments) × r_first / r_max), r_first the chain's
//   first ring radius, r_max the largest ring radius of the tree.
// - UVs: u = i/n around the ring (the seam vertex is duplicated with u = 1); v starts at 0 at a
//   chain's first ring and decreases by |Δc| / (uvAspect × π (r_a + r_b)) per tube piece (its
//   length over its mean circumference), so texels stay square and the texture runs on along
//   the chain. glTF puts the UV origin at the image's top-left and normal maps use +Y = image
//   up, so the bitangent cross(n, t) · w must point to decreasing v: with v decreasing along the
//   growth direction the bark image stands upright and w = +1.
// - Caps (capTips): a flat fan around a centre vertex closes every open tube end: branch tips,
//   and chain starts with no tube passing through their start node (the root, hidden nodes,
//   nodes whose own chain ends there).
// - Nodes closer than 1e-6 × (largest absolute coordinate) to the previous ring are merged
//   into it, so zero-length edges give no degenerate triangles.
#include "ramus/tube_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ramus/error.hpp"
#include "ramus/tree_wind.hpp"
#include "ring_frames.hpp"

namespace ramus {
namespace {

constexpr int kMaxSegments = 4096;

using detail::AngleTable;
using detail::initialReference;
using detail::makeAngleTable;
using detail::transportReference;

class TubeBuilder {
public:
    TubeBuilder(const BranchTree& tree, const TubeMeshParams& params);
    Mesh build();
    std::size_t countTriangles();

private:
    struct Ring {
        Vec3 center;
        double radius;
        Vec3 direction;  // unit, from the previous ring (unused for the first)
        double length;   // distance from the previous ring
        NodeId node;     // the node at the ring (the chain's first node for its first ring)
        double t;        // where along the edge into `node` (0: its parent, 1: the node)
    };

    void linkChains();
    bool drawn(std::size_t node) const { return !tree_.nodes()[node].hidden; }
    void setWind(std::uint32_t first, std::size_t count, const Ring& ring);
    bool startsChain(NodeId first) const;
    double startRadius(NodeId first) const;
    bool needsBaseCap(NodeId first) const;
    int segmentsFor(double radius) const;
    const AngleTable& table(int n);
    void reserve();
    void gatherRings(NodeId first);
    void meshChain(NodeId first);
    std::uint32_t emitRing(const Ring& ring, const Vec3& e1, const Vec3& e2, float v,
                           const AngleTable& table);
    void emitSides(std::uint32_t a, std::uint32_t b, int n);
    void emitCap(std::uint32_t ringBase, const Ring& ring, const Vec3& normal, const Vec3& e1,
                 const AngleTable& table, bool tip);

    const BranchTree& tree_;
    const TubeMeshParams& params_;
    std::vector<double> radii_;
    std::vector<NodeId> next_;  // chain continuation per node (linkChains)
    TreeWind wind_;             // when params.windAttributes
    WindAttributes windOut_;
    int minSegments_ = 3;
    int maxSegments_ = 3;
    double trunkMultiplier_ = 1.0;
    double uvAspect_ = 1.0;
    double mergeDistance_ = 0.0;
    double maxRadius_ = 0.0;
    std::vector<AngleTable> tables_;  // index n - minSegments_, built on first use
    std::vector<Ring> rings_;         // rings of the chain being meshed, reused
    Mesh mesh_;
    std::uint32_t vertexCount_ = 0;  // vertices written so far
    std::size_t indexCount_ = 0;     // indices written so far
};

TubeBuilder::TubeBuilder(const BranchTree& tree, const TubeMeshParams& params)
    : tree_(tree), params_(params) {
    minSegments_ = std::clamp(params.minSegments, 3, kMaxSegments);
    maxSegments_ = std::clamp(params.maxSegments, minSegments_, kMaxSegments);
    trunkMultiplier_ = params.trunkMultiplier > 0.0 && std::isfinite(params.trunkMultiplier)
                           ? params.trunkMultiplier
                           : 1.0;
    uvAspect_ = params.uvAspect > 0.0 && std::isfinite(params.uvAspect) ? params.uvAspect : 1.0;
    tables_.resize(static_cast<std::size_t>(maxSegments_ - minSegments_ + 1));
    radii_ = computeEdgeRadii(tree, params);
    linkChains();
    if (params.windAttributes) wind_ = TreeWind(tree, params.windSeed);
    const Aabb box = tree.bounds();
    mergeDistance_ = 1e-6 * std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
    maxRadius_ = trunkMultiplier_ * radii_[0];
    for (std::size_t i = 1; i < tree.size(); ++i) {
        if (!tree.nodes()[i].hidden) maxRadius_ = std::max(maxRadius_, radii_[i]);
    }
}

// next_[id]: the child continuing `id`'s chain. Eq 3.7 gives the parent's branch depth to
// exactly one child (the first created, so the smallest id); a hidden child, or a hidden `id`
// (its edge is not drawn), ends the chain. One forward pass: children follow their parents.
void TubeBuilder::linkChains() {
    constexpr NodeId kUnset = -2;
    next_.assign(tree_.size(), kUnset);
    for (std::size_t i = 1; i < tree_.size(); ++i) {
        const BranchNode& child = tree_.nodes()[i];
        const auto parent = static_cast<std::size_t>(child.parent);
        const BranchNode& p = tree_.nodes()[parent];
        if (next_[parent] == kUnset && child.branchDepth == p.branchDepth) {
            next_[parent] = drawn(i) && drawn(parent) ? static_cast<NodeId>(i) : kNoNode;
        }
    }
    for (NodeId& next : next_) {
        if (next == kUnset) next = kNoNode;
    }
}

// Whether the visible edge ending at `first` begins a chain: its parent is the root, hidden,
// or continues with another child.
bool TubeBuilder::startsChain(NodeId first) const {
    const NodeId parent = tree_.node(first).parent;
    return parent == 0 || next_[static_cast<std::size_t>(parent)] != first;
}

double TubeBuilder::startRadius(NodeId first) const {
    const bool rootChain = tree_.node(first).parent == 0 && next_[0] == first;
    return rootChain ? trunkMultiplier_ * radii_[0] : radii_[static_cast<std::size_t>(first)];
}

// A chain start needs a base cap when no drawn tube passes through its start node.
bool TubeBuilder::needsBaseCap(NodeId first) const {
    const NodeId parent = tree_.node(first).parent;
    return params_.capTips && (parent == 0 || next_[static_cast<std::size_t>(parent)] == kNoNode);
}

int TubeBuilder::segmentsFor(double radius) const {
    if (!(maxRadius_ > 0.0)) return minSegments_;
    const double t = std::clamp(radius / maxRadius_, 0.0, 1.0);
    return minSegments_ + static_cast<int>((maxSegments_ - minSegments_) * t + 0.5);
}

const AngleTable& TubeBuilder::table(int n) {
    AngleTable& entry = tables_[static_cast<std::size_t>(n - minSegments_)];
    if (entry.cosines.empty()) entry = makeAngleTable(n, degToRad(params_.startRotationDegrees));
    return entry;
}

// Sizes the arrays for the mesh without merged or reduced rings (an exact upper bound), so the
// meshing pass writes through raw pointers and never reallocates; build() trims the rest.
void TubeBuilder::reserve() {
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::vector<std::uint16_t> segments(tree_.size(), 0);  // per node, its chain's n
    for (std::size_t i = 1; i < tree_.size(); ++i) {
        const BranchNode& node = tree_.nodes()[i];
        const auto id = static_cast<NodeId>(i);
        if (!drawn(i)) continue;
        std::size_t n = 0;
        if (startsChain(id)) {
            n = static_cast<std::size_t>(segmentsFor(startRadius(id)));
            vertices += n + 1;  // the chain's first ring
            if (needsBaseCap(id)) {
                vertices += n + 1;
                triangles += n;
            }
        } else {
            n = segments[static_cast<std::size_t>(node.parent)];
        }
        segments[i] = static_cast<std::uint16_t>(n);
        vertices += n + 1;
        triangles += 2 * n;
        if (params_.capTips && next_[i] == kNoNode) {
            vertices += n + 1;
            triangles += n;
        }
    }
    mesh_.positions.resize(vertices);
    mesh_.normals.resize(vertices);
    mesh_.tangents.resize(vertices);
    mesh_.uvs.resize(vertices);
    mesh_.indices.resize(triangles * 3);
    if (params_.windAttributes) windOut_.resize(vertices);
}

// Collects the rings of the chain whose first edge ends at `first`: merges nodes that coincide
// with the previous ring and, with curve reduction, skips nodes of one child where the chain
// runs straight on (eq 3.8, measured from the last kept ring so slow bends are kept).
void TubeBuilder::gatherRings(NodeId first) {
    rings_.clear();
    const Vec3& start = tree_.node(tree_.node(first).parent).position;
    rings_.push_back({start, startRadius(first), Vec3::Zero(), 0.0, first, 0.0});
    const double maxK = params_.curveReduction;
    const double merge2 = mergeDistance_ * mergeDistance_;
    for (NodeId x = first; x != kNoNode;) {
        const BranchNode& node = tree_.node(x);
        const NodeId next = next_[static_cast<std::size_t>(x)];
        const Vec3 in = node.position - rings_.back().center;
        const double length2 = in.squaredNorm();
        if (length2 > merge2) {
            const double length = std::sqrt(length2);
            const Vec3 direction = in * (1.0 / length);  // one division, not three
            bool keep = true;
            if (maxK > 0.0 && node.childCount == 1 && next != kNoNode) {
                const Vec3 out = tree_.node(next).position - node.position;
                const double out2 = out.squaredNorm();
                keep = out2 <= merge2 || direction.dot(out) <= maxK * std::sqrt(out2);
            }
            if (keep) {
                rings_.push_back({node.position, radii_[static_cast<std::size_t>(x)], direction,
                                  length, x, 1.0});
            }
        }
        x = next;
    }
}

// Wind data of a ring's (or its cap's) vertices.
void TubeBuilder::setWind(std::uint32_t first, std::size_t count, const Ring& ring) {
    if (params_.windAttributes) windOut_.set(first, count, wind_.at(ring.node, ring.t));
}

// Appends one ring (n + 1 vertices, the last repeating the first with u = 1).
std::uint32_t TubeBuilder::emitRing(const Ring& ring, const Vec3& e1, const Vec3& e2, float v,
                                    const AngleTable& table) {
    const std::uint32_t base = vertexCount_;
    const std::size_t count = table.cosines.size();
    RAMUS_ASSERT(base + count <= mesh_.positions.size());
    const Vec3f c = ring.center.cast<float>();
    const Vec3f a = e1.cast<float>();
    const Vec3f b = e2.cast<float>();
    const auto r = static_cast<float>(ring.radius);
    Vec3f* positions = mesh_.positions.data() + base;
    Vec3f* normals = mesh_.normals.data() + base;
    Vec4f* tangents = mesh_.tangents.data() + base;
    Vec2f* uvs = mesh_.uvs.data() + base;
    for (std::size_t i = 0; i < count; ++i) {
        const float cs = table.cosines[i];
        const float sn = table.sines[i];
        const Vec3f radial = cs * a + sn * b;
        positions[i] = c + r * radial;
        normals[i] = radial;
        // d(radial)/d(angle): direction of increasing u; cross(radial, it) = +t.
        const Vec3f tangent = cs * b - sn * a;
        tangents[i] = Vec4f(tangent.x(), tangent.y(), tangent.z(), 1.0f);
        uvs[i] = Vec2f(table.us[i], v);
    }
    setWind(base, count, ring);
    vertexCount_ += static_cast<std::uint32_t>(count);
    return base;
}

// Quads between ring `a` (behind) and ring `b` (ahead), counter-clockwise seen from outside.
void TubeBuilder::emitSides(std::uint32_t a, std::uint32_t b, int n) {
    RAMUS_ASSERT(indexCount_ + 6 * static_cast<std::size_t>(n) <= mesh_.indices.size());
    std::uint32_t* out = mesh_.indices.data() + indexCount_;
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i, out += 6) {
        out[0] = a + i;
        out[1] = a + i + 1;
        out[2] = b + i + 1;
        out[3] = a + i;
        out[4] = b + i + 1;
        out[5] = b + i;
    }
    indexCount_ += 6 * static_cast<std::size_t>(n);
}

// Flat fan around a centre vertex. Own vertices (positions copied bit-exactly from the ring)
// carry the cap's normal; UVs map the disc onto the unit square, tangent e1 (w = +1).
void TubeBuilder::emitCap(std::uint32_t ringBase, const Ring& ring, const Vec3& normal,
                          const Vec3& e1, const AngleTable& table, bool tip) {
    const auto n = static_cast<std::uint32_t>(table.cosines.size() - 1);
    const std::uint32_t centre = vertexCount_;
    RAMUS_ASSERT(centre + n + 1 <= mesh_.positions.size() &&
                 indexCount_ + 3 * static_cast<std::size_t>(n) <= mesh_.indices.size());
    const Vec3f nf = normal.cast<float>();
    const Vec4f tangent(static_cast<float>(e1.x()), static_cast<float>(e1.y()),
                        static_cast<float>(e1.z()), 1.0f);
    const float vSign = tip ? -0.5f : 0.5f;  // keeps cross(n, e1) pointing to decreasing v
    Vec3f* positions = mesh_.positions.data();
    Vec2f* uvs = mesh_.uvs.data();
    positions[centre] = ring.center.cast<float>();
    uvs[centre] = Vec2f(0.5f, 0.5f);
    for (std::uint32_t i = 0; i < n; ++i) {
        positions[centre + 1 + i] = positions[ringBase + i];
        uvs[centre + 1 + i] = Vec2f(0.5f + 0.5f * table.cosines[i], 0.5f + vSign * table.sines[i]);
    }
    std::fill_n(mesh_.normals.data() + centre, n + 1, nf);
    setWind(centre, n + 1, ring);
    std::fill_n(mesh_.tangents.data() + centre, n + 1, tangent);
    std::uint32_t* out = mesh_.indices.data() + indexCount_;
    for (std::uint32_t i = 0; i < n; ++i, out += 3) {
        const std::uint32_t a = centre + 1 + i;
        const std::uint32_t b = centre + 1 + (i + 1 == n ? 0 : i + 1);
        out[0] = centre;
        out[1] = tip ? a : b;
        out[2] = tip ? b : a;
    }
    vertexCount_ += n + 1;
    indexCount_ += 3 * static_cast<std::size_t>(n);
}

void TubeBuilder::meshChain(NodeId first) {
    gatherRings(first);
    const std::size_t count = rings_.size();
    if (count < 2) return;  // the whole chain has zero length
    const int n = segmentsFor(rings_[0].radius);
    const AngleTable& angles = table(n);

    // First ring: faces the first edge; frame from the fixed reference rule.
    Vec3 normal = rings_[1].direction;
    Vec3 e1 = initialReference(normal);
    double v = 0.0;
    std::uint32_t previous = emitRing(rings_[0], e1, normal.cross(e1), 0.0f, angles);
    if (needsBaseCap(first)) emitCap(previous, rings_[0], -normal, e1, angles, false);

    const double vScale = 1.0 / (uvAspect_ * kPi);
    for (std::size_t k = 1; k < count; ++k) {
        const Ring& ring = rings_[k];
        // Inner rings face the bisector of their two edges, the last one its edge.
        Vec3 nextNormal = ring.direction;
        if (k + 1 < count) {
            const Vec3 bisector = ring.direction + rings_[k + 1].direction;
            const double length2 = bisector.squaredNorm();
            if (length2 > 1e-12) nextNormal = bisector * (1.0 / std::sqrt(length2));
        }
        e1 = transportReference(e1, normal, ring.direction, nextNormal);
        normal = nextNormal;
        v -= ring.length * vScale / (rings_[k - 1].radius + ring.radius);
        const Vec3 e2 = normal.cross(e1);
        const std::uint32_t current = emitRing(ring, e1, e2, static_cast<float>(v), angles);
        emitSides(previous, current, n);
        if (k + 1 == count && params_.capTips) emitCap(current, ring, normal, e1, angles, true);
        previous = current;
    }
}

// What meshChain and emitSides/emitCap write, per chain: 2n triangles per tube piece, n per
// cap.
std::size_t TubeBuilder::countTriangles() {
    std::size_t triangles = 0;
    for (std::size_t i = 1; i < tree_.size(); ++i) {
        const auto first = static_cast<NodeId>(i);
        if (!drawn(i) || !startsChain(first)) continue;
        gatherRings(first);
        if (rings_.size() < 2) continue;
        const auto n = static_cast<std::size_t>(segmentsFor(rings_[0].radius));
        triangles += 2 * n * (rings_.size() - 1);
        if (needsBaseCap(first)) triangles += n;
        if (params_.capTips) triangles += n;
    }
    return triangles;
}

Mesh TubeBuilder::build() {
    mesh_.name = "tree";
    if (tree_.size() < 2) return std::move(mesh_);
    reserve();
    for (std::size_t i = 1; i < tree_.size(); ++i) {
        const auto first = static_cast<NodeId>(i);
        if (drawn(i) && startsChain(first)) meshChain(first);
    }
    mesh_.positions.resize(vertexCount_);
    mesh_.normals.resize(vertexCount_);
    mesh_.tangents.resize(vertexCount_);
    mesh_.uvs.resize(vertexCount_);
    mesh_.indices.resize(indexCount_);
    if (params_.windAttributes) {
        windOut_.resize(vertexCount_);
        windOut_.moveInto(mesh_);
    }
    if (!mesh_.indices.empty()) {
        mesh_.materials.push_back(params_.material);
        mesh_.primitives.push_back(
            MeshPrimitive{0, static_cast<std::uint32_t>(mesh_.indices.size()), 0, "bark"});
    }
    return std::move(mesh_);
}

}  // namespace

Mesh buildTubeMesh(const BranchTree& tree, const TubeMeshParams& params) {
    if (tree.size() < 2) {
        Mesh empty;
        empty.name = "tree";
        return empty;
    }
    return TubeBuilder(tree, params).build();
}

std::size_t countTubeTriangles(const BranchTree& tree, const TubeMeshParams& params) {
    if (tree.size() < 2) return 0;
    TubeMeshParams counting = params;
    counting.windAttributes = false;  // no vertices: no wind data to prepare
    return TubeBuilder(tree, counting).countTriangles();
}

}  // namespace ramus
