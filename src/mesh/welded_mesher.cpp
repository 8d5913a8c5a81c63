// Based on: Bærentzen, Misztal, Wełnicka 2012, "Converting skeletal structures to quad
// dominant meshes" (tubes between branch nodes, the nodes themselves meshed from the convex
// hull of the meeting tubes' rings, as Blender's skin modifier does); tube rings, frames, radii,
// segment rule and UVs as buildTubeMesh (seed 002 §4.4, src/mesh/tube_mesher.cpp).
//
// Pipeline: buildWeldSkeleton groups drawn edges into limbs (unbranched stretches between the
// root, tips and branch nodes); solveWeldJunctions places each limb's rings at its branch
// nodes; this file meshes every limb as a tube from ring to ring (flat fans at tips and the
// base), and welded_junction_mesh.cpp closes every branch node with the convex hull of its
// rings minus the rings' discs.
//
// Rules this file settles:
// - Limb rings: one at each end (at the node for tips and the base, at the solver's offset at
//   branch nodes) and one at every inner node farther than 5 % of its radius from those (curve
//   reduction as buildTubeMesh). A ring between nodes faces its edge, a ring at a node the
//   bisector of its two edges, as in buildTubeMesh.
// - v runs on through branch nodes: every limb starts with the v its branch node has on the
//   limb that ends there, so the texture continues along the main axis and starts in step on
//   side branches.
// - Rings of limbs taken into a junction are emitted only as hull points; vertices that end
//   up inside the hull are dropped at the end.
// - Wind data (params.tube.windAttributes; src/mesh/tree_wind.cpp): a tube ring names the tree
//   edge it lies on and how far along it (RingPlace::edgeNode, edgeFraction), and its vertices
//   get TreeWind::at of that point — exactly what buildTubeMesh gives its rings there, so a
//   ring on both meshes carries the same level, phase, distance and pivot (a junction's arm
//   rings sit a little way out along their own limb: the side branch's ring has its level
//   and a distance just above 0). Caps copy their ring's values, as in buildTubeMesh.
//   Junction triangles add no vertices; only the rings of limbs absorbed into a junction need
//   a choice: they take the values of the branch they grow out of at the limb's start node
//   (TreeWind::at(startKey)), so the whole junction moves with its parent branch. Their own
//   values would make a stub shorter than the junction's ring offset sway as a full side
//   branch (relative distance up to 1) and pull the hull surface out of the parent's
//   surface. No vertex shares its position with a vertex of another value (seam and cap
//   copies belong to one ring), so any animation driven by these attributes keeps the
//   surface closed.
#include "ramus/welded_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <utility>

#include "ramus/error.hpp"
#include "welded_builder.hpp"

namespace ramus::detail {
namespace {

// Whether ring b lies wholly ahead of ring a's plane and a wholly behind b's (normals along
// the limb): a ring of radius r tilted by θ against a plane reaches r·sin θ off it.
bool ringsApart(const RingPlace& a, const RingPlace& b) {
    const Vec3 step = b.center - a.center;
    const double cosine = std::clamp(a.normal.dot(b.normal), -1.0, 1.0);
    const double sine = std::sqrt(1.0 - cosine * cosine);
    return step.dot(a.normal) > b.radius * sine && step.dot(b.normal) > a.radius * sine;
}

}  // namespace

WeldBuilder::WeldBuilder(const BranchTree& tree, const WeldedMeshParams& params, std::size_t cores)
    : WeldEmitter(params, treeWind_), cores_(cores), team_(cores) {
    margin_ =
        std::isfinite(params.junctionMargin) ? std::clamp(params.junctionMargin, 0.01, 1.0) : 0.05;
    const double aspect = params.tube.uvAspect > 0.0 && std::isfinite(params.tube.uvAspect)
                              ? params.tube.uvAspect
                              : 1.0;
    vScale_ = 1.0 / (aspect * kPi);
    skeleton_ = buildWeldSkeleton(tree, params.tube);
    junctions_ = solveWeldJunctions(skeleton_, margin_);
    if (params.tube.windAttributes) treeWind_ = TreeWind(tree, params.tube.windSeed);
    continuesChain_.assign(skeleton_.limbs.size(), 0);
    for (std::size_t l = 0; l < skeleton_.limbs.size(); ++l) {
        const BranchNode& child = tree.node(skeleton_.pointNode[skeleton_.limbs[l].first + 1]);
        continuesChain_[l] = child.parent != kNoNode && !child.hidden &&
                             child.branchDepth == tree.node(child.parent).branchDepth;
    }
}

WindSample WeldEmitter::windAt(const RingPlace& place) const {
    if (!params_.tube.windAttributes) return {};
    return wind_.at(place.edgeNode, place.edgeFraction);
}

const AngleTable& WeldEmitter::table(int n) {
    const auto index = static_cast<std::size_t>(n);
    if (tables_.size() <= index) tables_.resize(index + 1);
    AngleTable& entry = tables_[index];
    if (entry.cosines.empty()) {
        entry = makeAngleTable(n, degToRad(params_.tube.startRotationDegrees));
    }
    return entry;
}

// The rings of limb `l` from its start to its end, with texture v (see the file comment).
void WeldBuilder::gatherLimbRings(std::int32_t l) {
    const WeldSkeleton& s = skeleton_;
    const WeldLimb& limb = s.limbs[static_cast<std::size_t>(l)];
    const auto li = static_cast<std::size_t>(l);
    const bool startJunction = junctions_.cluster[static_cast<std::size_t>(limb.startKey)] >= 0;
    const bool endJunction = junctions_.cluster[static_cast<std::size_t>(limb.endKey)] >= 0;
    const double length = s.limbLength(limb);
    const double s0 = startJunction ? junctions_.startOffset[li] : 0.0;
    const double s1 = length - (endJunction ? junctions_.endOffset[li] : 0.0);
    const std::uint32_t last = limb.count - 1;
    auto atPoint = [&](std::uint32_t k) { return ringAtPoint(s, limb, k); };
    rings_.clear();
    rings_.push_back({startJunction ? ringOnLimb(s, limb, false, s0) : atPoint(0), 0.0});
    RingPlace end =
        endJunction ? ringOnLimb(s, limb, true, junctions_.endOffset[li]) : atPoint(last);
    if (endJunction) end.normal = -end.normal;  // rings face along the limb
    const double maxK = params_.tube.curveReduction;
    for (std::uint32_t k = 1; k < last; ++k) {
        const std::uint32_t p = limb.first + k;
        const double spacing = 0.05 * s.pointRadius[p];
        if (s.pointArc[p] <= s0 + spacing || s.pointArc[p] >= s1 - spacing) continue;
        if (maxK > 0.0) {
            const Vec3 in = (s.pointPosition[p] - rings_.back().place.center).normalized();
            const Vec3 out = (s.pointPosition[p + 1] - s.pointPosition[p]).normalized();
            if (in.dot(out) > maxK) continue;
        }
        const RingPlace inner = atPoint(k);
        // A ring at an inner node faces the bisector of its bend, a junction's ring faces the
        // limb: close to each other they cross, and the tube between them folds into the hull.
        if (startJunction && rings_.size() == 1 && !ringsApart(rings_[0].place, inner)) continue;
        rings_.push_back({inner, 0.0});
    }
    // The same at the end, from the end ring back to the first ring clear of it: a ring
    // farther back need not be (on a limb that turns by more than a right angle, distant
    // rings face away from the end ring), the tube runs through the ones between.
    while (endJunction && rings_.size() > 1 && !ringsApart(rings_.back().place, end)) {
        rings_.pop_back();
    }
    rings_.push_back({end, 0.0});

    double v = keyV_[static_cast<std::size_t>(limb.startKey)];
    double arc = 0.0;
    double radius = s.pointRadius[limb.first];
    for (LimbRing& ring : rings_) {
        v -= (ring.place.arc - arc) * vScale_ / (radius + ring.place.radius);
        ring.v = v;
        arc = ring.place.arc;
        radius = ring.place.radius;
    }
    keyV_[static_cast<std::size_t>(limb.endKey)] =
        v - (length - arc) * vScale_ / (radius + s.pointRadius[limb.first + last]);
}

// A crossing limb whose junctions share one ring (WeldJunctions::sharedNormal): that ring,
// where the limb crosses the plane parting the two junctions, and no tube; each junction takes
// it as its arm's ring, facing away from it across the plane. A straight limb (two points).
void WeldBuilder::meshSharedRing(std::int32_t l) {
    const WeldSkeleton& s = skeleton_;
    const auto li = static_cast<std::size_t>(l);
    const WeldLimb& limb = s.limbs[li];
    const Vec3& plane = junctions_.sharedNormal[li];
    const Vec3& from = s.pointPosition[limb.first];
    const double length = s.limbLength(limb);
    const double heightFrom = junctions_.sharedOffset[li] - from.dot(plane);
    const double rise = (s.pointPosition[limb.first + 1] - from).dot(plane);
    const double arc = std::clamp(heightFrom / rise, 0.0, 1.0) * length;
    const RingPlace place = ringOnLimb(s, limb, false, arc);
    // Texture v as along the tube from the start node, and on from the ring to the end node.
    const double startRadius = s.pointRadius[limb.first];
    const double endRadius = s.pointRadius[limb.first + 1];
    const double v = keyV_[static_cast<std::size_t>(limb.startKey)] -
                     arc * vScale_ / (startRadius + place.radius);
    keyV_[static_cast<std::size_t>(limb.endKey)] =
        v - (length - arc) * vScale_ / (place.radius + endRadius);
    RingRecord ring = emitRing(place, initialReference(place.normal), static_cast<float>(v),
                               limb.segments, windAt(place), &plane);
    startRing_[li] = ring;
    ring.outward = -plane;
    endRing_[li] = ring;
}

void WeldBuilder::meshLimb(std::int32_t l) {
    const WeldLimb& limb = skeleton_.limbs[static_cast<std::size_t>(l)];
    if (junctions_.sharedNormal[static_cast<std::size_t>(l)] != Vec3::Zero()) {
        meshSharedRing(l);
        emitPointsBeforeRings(l);  // none (a straight limb), but its rings' range is set
        return;
    }
    gatherLimbRings(l);
    const int n = limb.segments;
    Vec3 normal = rings_[0].place.normal;
    Vec3 e1 = initialReference(normal);
    RingRecord previous =
        emitRing(rings_[0].place, e1, static_cast<float>(rings_[0].v), n, windAt(rings_[0].place));
    if (junctions_.cluster[static_cast<std::size_t>(limb.startKey)] >= 0) {
        startRing_[static_cast<std::size_t>(l)] = previous;
    } else {
        emitCap(previous, -normal, false, previous.center);  // the base of a tree part
    }
    for (std::size_t k = 1; k < rings_.size(); ++k) {
        const RingPlace& place = rings_[k].place;
        const Vec3 step = place.center - rings_[k - 1].place.center;
        const double length = step.norm();
        const Vec3 direction = length > 0.0 ? Vec3(step / length) : place.normal;
        e1 = transportReference(e1, normal, direction, place.normal);
        normal = place.normal;
        const RingRecord current =
            emitRing(place, e1, static_cast<float>(rings_[k].v), n, windAt(place));
        emitSides(previous.base, current.base, n);
        previous = current;
    }
    if (junctions_.cluster[static_cast<std::size_t>(limb.endKey)] >= 0) {
        previous.outward = -normal;
        endRing_[static_cast<std::size_t>(l)] = previous;
    } else {
        emitCap(previous, normal, true, previous.center);
    }
    emitPointsBeforeRings(l);
}

// Rings at the inner points of limb `l` between a junction's node and the limb's ring there
// (forEachPointBeforeRing), as hull points of that junction: without them a limb that bends
// there is cut off by the hull's chord. Texture v runs from the node as along the tube.
void WeldBuilder::emitPointsBeforeRings(std::int32_t l) {
    const WeldSkeleton& s = skeleton_;
    const auto li = static_cast<std::size_t>(l);
    const WeldLimb& limb = s.limbs[li];
    for (const bool atEnd : {false, true}) {
        const NodeId node = atEnd ? limb.endKey : limb.startKey;
        if (junctions_.cluster[static_cast<std::size_t>(node)] >= 0) {
            const double t = atEnd ? junctions_.endOffset[li] : junctions_.startOffset[li];
            const RingPlace ring = ringOnLimb(s, limb, atEnd, t);
            const double v = keyV_[static_cast<std::size_t>(node)];
            forEachPointBeforeRing(
                s, limb, atEnd, t, ring, kBeforeClearance * margin_,
                [&](std::uint32_t k, const Vec3&) {
                    const RingPlace place = ringAtPoint(s, limb, k);
                    const auto vk = static_cast<float>(vFromNode(limb, atEnd, k, v));
                    before_.push_back(emitRing(place, initialReference(place.normal), vk,
                                               limb.segments, windAt(place)));
                });
        }
        beforeFirst_[2 * li + (atEnd ? 1 : 0) + 1] = static_cast<std::uint32_t>(before_.size());
    }
}

// Texture v at point k of `limb`, from v at its start node (or its end node, `fromEnd`):
// the steps of vAfterStep between them (v falls along the limb).
double WeldBuilder::vFromNode(const WeldLimb& limb, bool fromEnd, std::uint32_t k, double v) const {
    if (!fromEnd) {
        for (std::uint32_t i = 1; i <= k; ++i) {
            v = vAfterStep(skeleton_, vScale_, limb.first + i, v);
        }
        return v;
    }
    for (std::uint32_t i = limb.count - 1; i > k; --i) {
        // Towards the start v rises by the same steps.
        v += v - vAfterStep(skeleton_, vScale_, limb.first + i, v);
    }
    return v;
}

// A limb inside a junction: one ring per point, as hull points only.
void WeldBuilder::meshAbsorbedLimb(std::int32_t l) {
    const WeldSkeleton& s = skeleton_;
    const WeldLimb& limb = s.limbs[static_cast<std::size_t>(l)];
    double v = keyV_[static_cast<std::size_t>(limb.startKey)];
    // The start node's ring is already there when the limb ending at it is absorbed too (on a
    // straight chain it would repeat it bit for bit and pinch the hull), or an earlier limb
    // from the same node: rings of equal centre and radius share points wherever their planes
    // cross (in a flat plant, ±r off the plane), and the hull would join the two copies of a
    // point in a degenerate face.
    const auto key = static_cast<std::size_t>(limb.startKey);
    const std::int32_t in = s.inLimb[key];
    bool startShown = in >= 0 && junctions_.absorbed[static_cast<std::size_t>(in)];
    for (std::int32_t earlier = s.firstOut[key]; earlier < l && !startShown; ++earlier) {
        startShown = junctions_.absorbed[static_cast<std::size_t>(earlier)] != 0;
    }
    // The parent branch's values at the limb's start (see the file comment).
    const WindSample wind = params_.tube.windAttributes ? wind_.at(limb.startKey) : WindSample{};
    for (std::uint32_t k = 0; k < limb.count; ++k) {
        if (k > 0) {
            v = vAfterStep(s, vScale_, limb.first + k, v);
        } else if (startShown) {
            continue;
        }
        const RingPlace place = ringAtPoint(s, limb, k);
        discs_.push_back(emitRing(place, initialReference(place.normal), static_cast<float>(v),
                                  limb.segments, wind));
    }
    keyV_[static_cast<std::size_t>(limb.endKey)] = v;
}

// Texture v at limb point `point` from v at the point before it (see the file comment).
double vAfterStep(const WeldSkeleton& s, double vScale, std::uint32_t point, double v) {
    return v - (s.pointArc[point] - s.pointArc[point - 1]) * vScale /
                   (s.pointRadius[point - 1] + s.pointRadius[point]);
}

// The ring at `place` that follows ring `previous` of the same tube, its frame carried along
// the step between them as the tube mesher's (rotation-minimizing).
RingRecord WeldEmitter::ringAfter(const RingRecord& previous, const RingPlace& place, float v) {
    const Vec3 step = place.center - previous.center;
    const double length = step.norm();
    const Vec3 e1 =
        transportReference(previous.e1, previous.e1.cross(previous.e2),
                           length > 0.0 ? Vec3(step / length) : place.normal, place.normal);
    return emitRing(place, e1, v, previous.n, windAt(place));
}

// With `plane` (a unit normal not square to place.normal) the ring is the tube's section by
// the plane through place.center with that normal, not the circle square to the tube: every
// vertex slid along the tube onto the plane (a ring two junctions share,
// WeldBuilder::meshSharedRing). The record's frame then spans that ellipse (vertex i at
// center + radius (cos_i e1 + sin_i e2), e1 and e2 neither unit nor square) and it faces along
// the plane's normal; the vertices keep the tube's normals.
RingRecord WeldEmitter::emitRing(const RingPlace& place, const Vec3& e1, float v, int n,
                                 const WindSample& wind, const Vec3* plane) {
    const AngleTable& angles = table(n);
    RingRecord ring;
    ring.wind = wind;
    ring.base = static_cast<std::uint32_t>(mesh_.positions.size());
    ring.n = n;
    ring.center = place.center;
    ring.e1 = e1;
    ring.e2 = place.normal.cross(e1);
    ring.outward = place.normal;
    ring.radius = place.radius;
    const Vec3f c = place.center.cast<float>();
    const Vec3f a = e1.cast<float>();
    const Vec3f b = ring.e2.cast<float>();
    const auto r = static_cast<float>(place.radius);
    if (plane != nullptr) {
        const double along = place.normal.dot(*plane);
        ring.e1 -= (ring.e1.dot(*plane) / along) * place.normal;
        ring.e2 -= (ring.e2.dot(*plane) / along) * place.normal;
        ring.outward = *plane;
    }
    for (std::size_t i = 0; i < angles.cosines.size(); ++i) {
        const float cs = angles.cosines[i];
        const float sn = angles.sines[i];
        const Vec3f radial = cs * a + sn * b;
        const Vec3f tangent = cs * b - sn * a;  // direction of increasing u
        if (plane != nullptr) {
            mesh_.positions.push_back(
                (place.center + place.radius * (cs * ring.e1 + sn * ring.e2)).cast<float>());
        } else {
            mesh_.positions.push_back(c + r * radial);
        }
        mesh_.normals.push_back(radial);
        mesh_.tangents.emplace_back(tangent.x(), tangent.y(), tangent.z(), 1.0f);
        mesh_.uvs.emplace_back(angles.us[i], v);
    }
    if (params_.tube.windAttributes) windOut_.append(angles.cosines.size(), wind);
    return ring;
}

// Quads between ring `a` (behind) and ring `b` (ahead), counter-clockwise seen from outside.
void WeldEmitter::emitSides(std::uint32_t a, std::uint32_t b, int n) {
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
        mesh_.indices.insert(mesh_.indices.end(),
                             {a + i, a + i + 1, b + i + 1, a + i, b + i + 1, b + i});
    }
}

// Fan around a centre vertex at `centre` (the ring's centre: a flat cap as buildTubeMesh's;
// elsewhere a cone), shaded as facing `normal`: own vertices (positions copied bit-exactly
// from the ring), disc UVs, tangent e1. `tip`: the ring faces the same way as the cap (else
// the cap closes the ring's back).
void WeldEmitter::emitCap(const RingRecord& ring, const Vec3& normal, bool tip,
                          const Vec3& centre) {
    const AngleTable& angles = table(ring.n);
    const auto n = static_cast<std::uint32_t>(ring.n);
    const auto hub = static_cast<std::uint32_t>(mesh_.positions.size());
    const Vec3f nf = normal.cast<float>();
    const Vec4f tangent(static_cast<float>(ring.e1.x()), static_cast<float>(ring.e1.y()),
                        static_cast<float>(ring.e1.z()), 1.0f);
    const float vSign = tip ? -0.5f : 0.5f;  // keeps cross(n, e1) pointing to decreasing v
    mesh_.positions.push_back(centre.cast<float>());
    mesh_.uvs.emplace_back(0.5f, 0.5f);
    for (std::uint32_t i = 0; i < n; ++i) {
        mesh_.positions.push_back(mesh_.positions[ring.base + i]);
        mesh_.uvs.emplace_back(0.5f + 0.5f * angles.cosines[i], 0.5f + vSign * angles.sines[i]);
    }
    mesh_.normals.insert(mesh_.normals.end(), n + 1, nf);
    mesh_.tangents.insert(mesh_.tangents.end(), n + 1, tangent);
    if (params_.tube.windAttributes) windOut_.append(n + 1, ring.wind);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t a = hub + 1 + i;
        const std::uint32_t b = hub + 1 + (i + 1 == n ? 0 : i + 1);
        mesh_.indices.insert(mesh_.indices.end(), {hub, tip ? a : b, tip ? b : a});
    }
}

// Meshes every junction (JunctionMesher) and appends the pieces in junction order: a piece's
// copies of tube vertices become those vertices again, its own vertices follow the mesh's. A
// junction reads only the tubes and writes only its piece, so with many junctions meshers on
// several threads take one junction at a time (a shrunk one takes far longer than a plain
// hull), each running its rays on its own thread; with few, one mesher shares every shrunk
// junction's rays among the cores. The mesh is the same either way.
void WeldBuilder::meshJunctions() {
    const std::vector<NodeId>& clusters = junctions_.junctions;
    if (clusters.empty()) return;
    RAMUS_ASSERT(mesh_.positions.size() < JunctionMesher::kOwnVertex);
    const std::size_t threads = workersFor(clusters.size(), cores_);
    std::deque<CoreTeam> teams;  // one thread each
    // Room in each mesher for a share of the tube rings the junctions join: the copies go
    // when a junction is done, but what the junctions add fits in their place (measured: less
    // is slower on tree_3d and 1.24a); the hulls have about two triangles a ring vertex.
    std::size_t ringVertices = 0;
    for (const std::vector<RingRecord>* rings : {&startRing_, &endRing_, &discs_, &before_}) {
        for (const RingRecord& ring : *rings) {
            if (ring.n > 0) ringVertices += static_cast<std::size_t>(ring.n) + 1;
        }
    }
    std::deque<JunctionMesher> meshers;
    for (std::size_t w = 0; w < threads; ++w) {
        CoreTeam& team = threads == 1 ? team_ : teams.emplace_back(1);
        meshers.emplace_back(*this, mesh_, windOut_, team)
            .reserve(ringVertices / threads, 6 * ringVertices / threads);
    }
    std::vector<JunctionMesher::Piece> pieces(clusters.size());
    std::vector<std::uint32_t> pieceMesher(clusters.size(), 0);
    // The largest junctions first (by the limbs meeting at their branch nodes), so that a slow
    // one taken last does not leave the other threads idle; the pieces keep junction order.
    std::vector<std::uint32_t> order(clusters.size());
    std::iota(order.begin(), order.end(), 0u);
    if (threads > 1) {
        std::vector<std::uint32_t> limbsAt(clusters.size(), 0);
        for (std::size_t j = 0; j < clusters.size(); ++j) {
            for (NodeId m = clusters[j]; m != kNoNode;
                 m = junctions_.nextMember[static_cast<std::size_t>(m)]) {
                limbsAt[j] += skeleton_.degree[static_cast<std::size_t>(m)];
            }
        }
        std::stable_sort(order.begin(), order.end(),
                         [&](std::uint32_t a, std::uint32_t b) { return limbsAt[a] > limbsAt[b]; });
    }
    forEachOnThreads(
        clusters.size(), threads,
        [&](std::size_t k, std::size_t w) {
            const std::uint32_t j = order[k];
            pieces[j] = meshers[w].meshJunction(clusters[j]);
            pieceMesher[j] = static_cast<std::uint32_t>(w);
        },
        1);

    std::size_t vertices = mesh_.positions.size();
    std::size_t indices = mesh_.indices.size();
    for (const JunctionMesher::Piece& piece : pieces) {
        vertices += piece.endVertex - piece.firstVertex;
        indices += piece.endIndex - piece.firstIndex;
    }
    mesh_.positions.reserve(vertices);
    mesh_.normals.reserve(vertices);
    mesh_.tangents.reserve(vertices);
    mesh_.uvs.reserve(vertices);
    mesh_.indices.reserve(indices);
    constexpr std::uint32_t kOwn = JunctionMesher::kOwnVertex;
    for (std::size_t j = 0; j < clusters.size(); ++j) {
        const JunctionMesher& mesher = meshers[pieceMesher[j]];
        const JunctionMesher::Piece& piece = pieces[j];
        const Mesh& from = mesher.mesh();
        const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
        const std::uint32_t count = piece.endVertex - piece.firstVertex;
        appendVertices(mesh_, from, piece.firstVertex, count);
        if (params_.tube.windAttributes) {
            windOut_.appendFrom(mesher.windOut(), piece.firstVertex, count);
        }
        for (std::size_t i = piece.firstIndex; i < piece.endIndex; ++i) {
            const std::uint32_t v = from.indices[i];
            mesh_.indices.push_back((v & kOwn) != 0 ? base + (v & ~kOwn) : v);
        }
    }
    for (const JunctionMesher& mesher : meshers) {
        const WeldReport& r = mesher.report();
        report_.fallbacks += r.fallbacks;
        report_.crossingTubes += r.crossingTubes;
        report_.absorbedTubes += r.absorbedTubes;
        report_.nodeBalls += r.nodeBalls;
        report_.bendRings += r.bendRings;
        report_.refinedJunctions += r.refinedJunctions;
        report_.tubedForUnion += r.tubedForUnion;
    }
}

Mesh WeldBuilder::build(WeldReport* report) {
    mesh_.name = "tree";
    const WeldSkeleton& s = skeleton_;
    const std::size_t limbs = s.limbs.size();
    keyV_.assign(s.rep.size(), 0.0);
    startRing_.assign(limbs, {});
    endRing_.assign(limbs, {});
    discFirst_.assign(limbs + 1, 0);
    beforeFirst_.assign(2 * limbs + 1, 0);
    // Upper bounds without junctions: a ring per point plus caps; junctions add about as
    // many triangles as their rings have vertices.
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    for (const WeldLimb& limb : s.limbs) {
        const auto n = static_cast<std::size_t>(limb.segments);
        vertices += (limb.count + 2) * (n + 1);
        triangles += 2 * n * (limb.count + 1);
    }
    mesh_.positions.reserve(vertices);
    mesh_.normals.reserve(vertices);
    mesh_.tangents.reserve(vertices);
    mesh_.uvs.reserve(vertices);
    mesh_.indices.reserve(3 * triangles);
    for (std::size_t l = 0; l < limbs; ++l) {
        const auto id = static_cast<std::int32_t>(l);
        if (junctions_.absorbed[l]) {
            meshAbsorbedLimb(id);
            beforeFirst_[2 * l + 1] = beforeFirst_[2 * l + 2] =
                static_cast<std::uint32_t>(before_.size());
        } else {
            meshLimb(id);
        }
        discFirst_[l + 1] = static_cast<std::uint32_t>(discs_.size());
    }
    const std::size_t tubeIndices = mesh_.indices.size();
    meshJunctions();
    report_.junctionTriangles = (mesh_.indices.size() - tubeIndices) / 3;
    if (params_.tube.windAttributes) {
        RAMUS_ASSERT(windOut_.vertexCount() == mesh_.positions.size());
        windOut_.moveInto(mesh_);
    }
    // Rings of absorbed limbs, of points before arm rings, of balls and bends inside a hull are
    // used by no triangle (nor by any where their junction fell back).
    if (junctions_.absorbedLimbs + junctions_.merges + report_.nodeBalls + report_.bendRings > 0 ||
        !before_.empty()) {
        removeUnusedVertices(mesh_);
    }
    if (!mesh_.indices.empty()) {
        mesh_.materials.push_back(params_.tube.material);
        mesh_.primitives.push_back(
            MeshPrimitive{0, static_cast<std::uint32_t>(mesh_.indices.size()), 0, "bark"});
    }
    if (report != nullptr) {
        report_.junctions = junctions_.junctions.size();
        report_.merges = junctions_.merges;
        report_.absorbedLimbs = junctions_.absorbedLimbs;
        report_.crowded = junctions_.crowded;
        report_.crossings = junctions_.crossings;
        report_.sharedRings = junctions_.sharedRings;
        for (std::size_t i = 0; i < s.rep.size(); ++i) {
            if (s.key[i] && s.inLimb[i] < 0) ++report_.components;
        }
        *report = report_;
    }
    return std::move(mesh_);
}

}  // namespace ramus::detail

namespace ramus {

namespace {

// The defects a union left; a union that failed counts as worst.
std::size_t unionDefects(const SolidUnionReport& united) {
    return united.applied ? united.defects() : std::numeric_limits<std::size_t>::max();
}

}  // namespace

Mesh buildWeldedTreeMesh(const BranchTree& tree, const WeldedMeshParams& params,
                         WeldReport* report) {
    if (report != nullptr) *report = WeldReport{};
    if (tree.size() < 2) {
        Mesh empty;
        empty.name = "tree";
        return empty;
    }
    WeldReport weld;
    Mesh mesh = detail::WeldBuilder(tree, params).build(&weld);
    if (params.solidUnion) {
        unionClosedSurfaces(mesh, &weld.solidUnion, params.unionAttempts, params.unionReunions,
                            params.unionCollapsePasses);
        // Shrunk junctions hug neighbouring branches within hundredths of a radius; where the
        // union's cut, rounded to float, leaves such grazes crossing or pinched after every
        // attempt (make union-check, sessions 24–27: ABOP 1.24a and 2.8c; none since session
        // 28's order of moves), the convex hulls, which keep their distance, may unite cleanly. The
        // better union is kept, the shrunk one on a tie.
        if (params.shrinkJunctions && unionDefects(weld.solidUnion) > 0) {
            WeldedMeshParams hulls = params;
            hulls.shrinkJunctions = false;
            WeldReport convexWeld;
            Mesh convex = detail::WeldBuilder(tree, hulls).build(&convexWeld);
            unionClosedSurfaces(convex, &convexWeld.solidUnion, params.unionAttempts,
                                params.unionReunions, params.unionCollapsePasses);
            if (unionDefects(convexWeld.solidUnion) < unionDefects(weld.solidUnion)) {
                mesh = std::move(convex);
                weld = std::move(convexWeld);
                weld.convexForUnion = true;
            }
        }
    }
    if (report != nullptr) *report = std::move(weld);
    return mesh;
}

}  // namespace ramus
