// Junctions of the welded mesher: the convex hull of the rings meeting at a branch node, with
// each arm's disc removed, joins the arms' tubes into one surface.
//
// Based on: Bærentzen, Misztal, Wełnicka 2012, "Converting skeletal structures to quad
// dominant meshes" §4 (branch node polyhedra from convex hulls), as in Blender's skin
// modifier. welded_junctions.cpp has placed the rings so that every arm's ring plane has all
// other rings behind it; then the hull has each ring as a face, and removing those faces
// leaves a sphere with one hole per arm whose rim is exactly that arm's ring.
//
// Making the ring faces identifiable and the hull robust:
// - A ring's vertices are coplanar, so each arm gets an apex just in front of its ring's
//   centre (2e-4 × margin × radius out): the ring face becomes a cone of n triangles around
//   the apex, every ring vertex is a strict hull vertex, and the hull faces touching an apex
//   are exactly the faces to remove. The apex stays behind the neighbouring faces, which tilt
//   by at least the clearance margin over the junction's extent.
// - Points are perturbed by 1e-9 of the junction's extent (a fixed hash of the point index),
//   so no four are exactly coplanar (parallel equal rings would otherwise be); the output keeps
//   the exact positions. The hull works on the rings' double-precision positions.
// - Every hole is checked: its apex must carry n faces, each on one ring edge, all wound the way
//   the tube expects. A junction failing any check (crowded junctions of dense plants) is
//   closed conservatively instead: each arm's tube follows its limb to a ring past the node
//   and a cone, and each absorbed limb becomes a capped tube of its own.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "fixed_hash.hpp"
#include "ramus/error.hpp"
#include "welded_builder.hpp"

namespace ramus::detail {

JunctionMesher::JunctionMesher(WeldBuilder& builder, const Mesh& tubes,
                               const WindAttributes& tubeWind, CoreTeam& team)
    : WeldEmitter(builder.params_, builder.wind_),
      skeleton_(builder.skeleton_),
      junctions_(builder.junctions_),
      margin_(builder.margin_),
      vScale_(builder.vScale_),
      keyV_(builder.keyV_),
      startRing_(builder.startRing_),
      endRing_(builder.endRing_),
      discFirst_(builder.discFirst_),
      continuesChain_(builder.continuesChain_),
      discs_(builder.discs_),
      beforeFirst_(builder.beforeFirst_),
      before_(builder.before_),
      segments_(builder.segments_),
      tubes_(tubes),
      tubeWind_(tubeWind),
      team_(team) {}

void JunctionMesher::reserve(std::size_t vertices, std::size_t indices) {
    mesh_.positions.reserve(vertices);
    mesh_.normals.reserve(vertices);
    mesh_.tangents.reserve(vertices);
    mesh_.uvs.reserve(vertices);
    mesh_.indices.reserve(indices);
    if (params_.tube.windAttributes) windOut_.reserve(vertices);
}

void appendVertices(Mesh& to, const Mesh& from, std::size_t first, std::size_t count) {
    auto copy = [&](auto& into, const auto& values) {
        const auto begin = values.begin() + static_cast<std::ptrdiff_t>(first);
        into.insert(into.end(), begin, begin + static_cast<std::ptrdiff_t>(count));
    };
    copy(to.positions, from.positions);
    copy(to.normals, from.normals);
    copy(to.tangents, from.tangents);
    copy(to.uvs, from.uvs);
}

// Rings of the junction's arms (holes), with the rings of their limbs' points before them,
// and of the limbs inside it (plain points).
void JunctionMesher::gatherJunction(NodeId cluster) {
    hullRings_.clear();
    pointsKept_.clear();
    const WeldSkeleton& s = skeleton_;
    for (NodeId m = cluster; m != kNoNode; m = junctions_.nextMember[static_cast<std::size_t>(m)]) {
        const auto i = static_cast<std::size_t>(m);
        auto visit = [&](std::int32_t l) {
            const auto li = static_cast<std::size_t>(l);
            const WeldLimb& limb = s.limbs[li];
            const bool start = limb.startKey == m;
            const Vec3& node = s.pointPosition[start ? limb.first : limb.first + limb.count - 1];
            if (!junctions_.absorbed[li]) {
                hullRings_.push_back(
                    {start ? startRing_[li] : endRing_[li], HullRingKind::Arm, start, node, l});
                const std::size_t side = 2 * li + (start ? 0 : 1);
                for (std::uint32_t b = beforeFirst_[side]; b < beforeFirst_[side + 1]; ++b) {
                    hullRings_.push_back({before_[b], HullRingKind::Before, start, node, l});
                }
            } else if (start) {  // inside: listed once, from its start
                for (std::uint32_t d = discFirst_[li]; d < discFirst_[li + 1]; ++d) {
                    hullRings_.push_back({discs_[d], HullRingKind::Absorbed, true, node, l});
                }
            }
        };
        if (s.inLimb[i] >= 0) visit(s.inLimb[i]);
        for (std::uint32_t k = 0; k < s.outCount[i]; ++k) visit(s.firstOut[i] + k);
    }
}

// Copies the vertices of the gathered rings (all the tubes') into mesh_ and renumbers the
// rings to the copies. In the order of their numbers in the tubes' mesh, and the junction's
// own vertices after them: the junction sees its vertices in the order one mesh for the whole
// tree would have them, so its result does not depend on which mesher ran it.
void JunctionMesher::copyTubeRings() {
    tubeRings_.clear();
    for (const HullRing& h : hullRings_) {
        tubeRings_.push_back({h.ring.base, static_cast<std::uint32_t>(h.ring.n + 1), 0});
    }
    std::sort(tubeRings_.begin(), tubeRings_.end());
    tubeRings_.erase(std::unique(tubeRings_.begin(), tubeRings_.end()), tubeRings_.end());
    for (TubeRing& ring : tubeRings_) {
        ring.copy = static_cast<std::uint32_t>(mesh_.positions.size());
        appendVertices(mesh_, tubes_, ring.base, ring.count);
        if (params_.tube.windAttributes) windOut_.appendFrom(tubeWind_, ring.base, ring.count);
        for (std::uint32_t k = 0; k < ring.count; ++k) tubeVertices_.push_back(ring.base + k);
    }
    for (HullRing& h : hullRings_) {
        h.ring.base =
            std::lower_bound(tubeRings_.begin(), tubeRings_.end(), TubeRing{h.ring.base, 0, 0})
                ->copy;
    }
}

// Hull of the gathered rings (and the planes of its faces); false where it fails.
// `firstRing` > 0: the rings from there on are added to the hull last built of those before.
bool JunctionMesher::buildHull(std::size_t firstRing) {
    if (firstRing == 0) {
        points_.clear();
        pointRing_.clear();
        pointIndex_.clear();
    }
    const std::size_t firstPoint = points_.size();
    const Vec3 origin = hullRings_.front().ring.center;
    for (std::size_t r = firstRing; r < hullRings_.size(); ++r) {
        const HullRing& h = hullRings_[r];
        const AngleTable& angles = table(h.ring.n);
        for (int k = 0; k < h.ring.n; ++k) {
            const auto i = static_cast<std::size_t>(k);
            if (h.kept >= 0 && pointsKept_[static_cast<std::size_t>(h.kept) + i] == 0) continue;
            const double cs = angles.cosines[i];
            const double sn = angles.sines[i];
            points_.push_back(h.ring.center - origin +
                              h.ring.radius * (cs * h.ring.e1 + sn * h.ring.e2));
            pointRing_.push_back(static_cast<std::int32_t>(r));
            pointIndex_.push_back(k);
        }
        if (h.hole()) {
            const double lift = 2e-4 * margin_ * h.ring.radius;
            points_.push_back(h.ring.center - origin + lift * h.ring.outward);
            pointRing_.push_back(static_cast<std::int32_t>(r));
            pointIndex_.push_back(-1);
        }
    }
    if (points_.size() < 4) return false;
    if (firstRing == 0) {
        hullExtent_ = 0.0;
        for (const Vec3& p : points_) hullExtent_ = std::max(hullExtent_, p.cwiseAbs().maxCoeff());
    }
    for (std::size_t p = firstPoint; p < points_.size(); ++p) {
        const std::uint64_t seed = 3 * static_cast<std::uint64_t>(p);
        points_[p] +=
            1e-9 * hullExtent_ * Vec3(hashUnit(seed), hashUnit(seed + 1), hashUnit(seed + 2));
    }
    const double epsilon = 1e-11 * hullExtent_;
    if (firstRing == 0 ? !hull_.build(points_, epsilon)
                       : !hull_.extend(points_, static_cast<std::uint32_t>(firstPoint), epsilon)) {
        return false;
    }
    hullPlanes_.clear();
    for (const auto& face : hull_.faces()) {
        const Vec3& a = points_[face[0]];
        const Vec3 normal = (points_[face[1]] - a).cross(points_[face[2]] - a);
        const double length = normal.norm();
        if (length > 0.0) hullPlanes_.push_back({normal / length, a.dot(normal) / length});
    }
    return true;
}

// Whether each arm's disc is a hole of the hull: n faces at its apex, each on one ring edge,
// wound as the tube expects (a ring that starts its limb is seen from behind by the hull, one
// that ends it from the front).
bool JunctionMesher::holesAreRings() {
    std::vector<int>& coneFaces = coneFaces_;
    coneFaces.assign(hullRings_.size(), 0);
    for (const auto& face : hull_.faces()) {
        for (int e = 0; e < 3; ++e) {
            if (pointIndex_[face[e]] >= 0) continue;
            const std::int32_t r = pointRing_[face[e]];
            const std::uint32_t a = face[(e + 1) % 3];
            const std::uint32_t b = face[(e + 2) % 3];
            if (pointRing_[a] != r || pointRing_[b] != r) return false;
            const int n = hullRings_[static_cast<std::size_t>(r)].ring.n;
            const int ahead = hullRings_[static_cast<std::size_t>(r)].start ? 1 : n - 1;
            if ((pointIndex_[a] + ahead) % n != pointIndex_[b]) return false;
            ++coneFaces[static_cast<std::size_t>(r)];
        }
    }
    for (std::size_t r = 0; r < hullRings_.size(); ++r) {
        if (hullRings_[r].hole() && coneFaces[r] != hullRings_[r].ring.n) return false;
    }
    return true;
}

// Appends the hull's faces that are not ring discs.
void JunctionMesher::emitHull() {
    for (const auto& face : hull_.faces()) {
        if (pointIndex_[face[0]] < 0 || pointIndex_[face[1]] < 0 || pointIndex_[face[2]] < 0) {
            continue;
        }
        for (int e = 0; e < 3; ++e) mesh_.indices.push_back(seamVertex(face[e], face));
    }
}

// How far `point` lies inside the last hull built; negative outside (then not how far: the
// callers only ask whether it is at least some depth).
double JunctionMesher::depthInHull(const Vec3& point) const {
    const Vec3 p = point - hullRings_.front().ring.center;  // hull points are relative to it
    double depth = std::numeric_limits<double>::infinity();
    for (const Plane& plane : hullPlanes_) {
        depth = std::min(depth, plane.offset - plane.normal.dot(p));
        if (depth < 0.0) break;
    }
    return depth;
}

// A branch node the hull leaves (nearly) bare: where branches fold back along their parent,
// as colonization's do at times, all rings lie on one side of the node and their hull spans
// past it, so the branches' own thickness at the node has no surface. Such nodes get a ball
// of their thickest branch's radius as hull points (latitude rings), shrunk so it stays
// behind every arm's ring plane by the clearance. Returns whether any ball was added (the
// hull must be built again). At an ordinary fork the node lies 0.2–1 of its radius inside the
// hull (measured in session 15 on the first tree of 8 colonization examples: the faceted rings
// and the taper bring the faces that close); less than kBareDepth of it is taken as bare (48
// of 3 000 junctions there, 26 of them with the node outside the hull).
constexpr double kBareDepth = 0.1;

bool JunctionMesher::addNodeBalls() {
    const std::size_t arms = hullRings_.size();
    bool added = false;
    for (std::size_t i = 0; i < arms; ++i) {
        const HullRing h = hullRings_[i];  // a copy: balls are appended to hullRings_
        if (!h.hole() ||
            std::any_of(hullRings_.begin(), hullRings_.begin() + i,
                        [&](const HullRing& e) { return e.hole() && e.node == h.node; })) {
            continue;  // one ball per node
        }
        double radius = 0.0;
        const double room = ballRoom(h.node, arms, radius);
        if (depthInHull(h.node) >= kBareDepth * radius) continue;
        const double ball = std::min(radius, room);
        if (!(ball > 0.05 * radius)) continue;
        emitBall(h, ball);
        added = true;
    }
    return added;
}

// Where a branch bends at a branch node, the tube mesher's chain runs on through the node with
// a ring there facing the bend's bisector (tube_mesher.cpp), and that ring's outer side lies
// beyond the chord the hull spans from the ring before the node to the ring after it: the hull
// cut the outer corner off (the hedges lost 0.11–0.18 % of their tube silhouette, within 0.24
// radii, nearly all of it at such bends; session 24). Where the chain turns by more than 10°
// there, the tube mesher's ring at the node is added as hull points (those clearly outside the
// hull), shrunk about its centre to stay behind every arm's ring plane by the clearance, as the
// balls. Returns whether any was added (its points are then added to the hull: buildHull).
constexpr double kBendTurnCosine = 0.9848077530122080;  // cos 10°
// Points of such a ring within this fraction of its radius outside the hull are left out. At
// 0.05 the solid union of ABOP 1.24c kept a crossing pair whatever its moves (session 24).
constexpr double kBendOutside = 0.1;

bool JunctionMesher::addBendRings() {
    const WeldSkeleton& s = skeleton_;
    const std::size_t arms = hullRings_.size();
    bool added = false;
    for (std::size_t i = 0; i < arms; ++i) {
        const HullRing in = hullRings_[i];     // a copy: rings are appended to hullRings_
        if (!in.hole() || in.start) continue;  // the limb ending at the node
        const auto li = static_cast<std::size_t>(in.limb);
        const WeldLimb& inLimb = s.limbs[li];
        const auto out =
            std::find_if(hullRings_.begin(), hullRings_.begin() + arms, [&](const HullRing& h) {
                return h.hole() && h.start && h.node == in.node &&
                       continuesChain_[static_cast<std::size_t>(h.limb)] != 0;
            });
        if (out == hullRings_.begin() + arms) continue;
        // Not where a ring of a limb inside the junction is centred on the node already: two
        // rings about one centre share the points where their planes cross (see
        // meshAbsorbedLimb), and the solid union kept a crossing there (ABOP 1.24c).
        const RingPlace atNode = ringAtPoint(s, inLimb, inLimb.count - 1);
        if (std::any_of(hullRings_.begin(), hullRings_.begin() + arms, [&](const HullRing& h) {
                return !h.hole() && (h.ring.center - atNode.center).norm() < 1e-6 * atNode.radius;
            })) {
            continue;
        }
        const WeldLimb& outLimb = s.limbs[static_cast<std::size_t>(out->limb)];
        const std::uint32_t last = inLimb.first + inLimb.count - 1;
        const Vec3 into = (s.pointPosition[last] - s.pointPosition[last - 1]).normalized();
        const Vec3 onward =
            (s.pointPosition[outLimb.first + 1] - s.pointPosition[outLimb.first]).normalized();
        if (!(into.dot(onward) < kBendTurnCosine)) continue;
        RingPlace place = atNode;
        place.normal = (into + onward).normalized();
        double radius = place.radius;
        for (std::size_t j = 0; j < arms; ++j) {
            const HullRing& arm = hullRings_[j];
            if (!arm.hole()) continue;
            const double cosine = arm.ring.outward.dot(place.normal);
            const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
            const double room =
                (arm.ring.center - place.center).dot(arm.ring.outward) - margin_ * arm.ring.radius;
            if (room <= 0.0) {
                radius = 0.0;
                break;
            }
            if (room < radius * sine) radius = room / sine;
        }
        if (!(radius > 0.5 * place.radius)) continue;
        place.radius = radius;
        // Only its points clearly outside the hull: in a flat plant the points off the plant's
        // plane lie in the planes of the other rings' points, on lines through theirs (ABOP
        // 1.24f: triangles 1e-7 of their length high).
        const Vec3 e1 = initialReference(place.normal);
        const Vec3 e2 = place.normal.cross(e1);
        const AngleTable& angles = table(inLimb.segments);
        const auto kept = static_cast<std::int32_t>(pointsKept_.size());
        bool any = false;
        for (std::size_t k = 0; k < static_cast<std::size_t>(inLimb.segments); ++k) {
            const Vec3 p =
                place.center + place.radius * (angles.cosines[k] * e1 + angles.sines[k] * e2);
            const bool outside = depthInHull(p) < -kBendOutside * place.radius;
            pointsKept_.push_back(outside ? 1 : 0);
            any = any || outside;
        }
        if (!any) {
            pointsKept_.resize(static_cast<std::size_t>(kept));
            continue;
        }
        const auto v = static_cast<float>(keyV_[static_cast<std::size_t>(inLimb.endKey)]);
        const RingRecord ring = emitRing(place, e1, v, inLimb.segments, windAt(place));
        hullRings_.push_back({ring, HullRingKind::Before, false, in.node, in.limb, kept});
        ++report_.bendRings;
        added = true;
    }
    return added;
}

// How large a ball at `node` may be: the least distance from it to an arm's ring plane, less
// the clearance; `radius` receives the thickest radius of the arms at `node` (of the first
// `arms` hull rings, which are the junction's own).
double JunctionMesher::ballRoom(const Vec3& node, std::size_t arms, double& radius) const {
    double room = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < arms; ++j) {
        const HullRing& arm = hullRings_[j];
        if (!arm.hole()) continue;
        const WeldLimb& l = skeleton_.limbs[static_cast<std::size_t>(arm.limb)];
        if (arm.node == node) {
            radius = std::max(radius,
                              skeleton_.pointRadius[arm.start ? l.first : l.first + l.count - 1]);
        }
        room = std::min(room,
                        (arm.ring.center - node).dot(arm.ring.outward) - margin_ * arm.ring.radius);
    }
    return room;
}

// A ball of `radius` at arm h's branch node, as four latitude rings about the arm's axis
// (hull points, shaded as the ball), with the wind values of the node (as absorbed limbs).
void JunctionMesher::emitBall(const HullRing& h, double radius) {
    const WeldLimb& limb = skeleton_.limbs[static_cast<std::size_t>(h.limb)];
    const NodeId node = h.start ? limb.startKey : limb.endKey;
    const Vec3 axis = h.ring.outward;
    const Vec3 e1 = initialReference(axis);
    const WindSample wind = params_.tube.windAttributes ? wind_.at(node) : WindSample{};
    const auto v = static_cast<float>(keyV_[static_cast<std::size_t>(node)]);
    constexpr int kLatitudes = 4;
    for (int j = 1; j <= kLatitudes; ++j) {
        const double polar = kPi * j / (kLatitudes + 1);
        RingPlace place;
        place.center = h.node + radius * std::cos(polar) * axis;
        place.normal = axis;
        place.radius = radius * std::sin(polar);
        const RingRecord ring = emitRing(place, e1, v, h.ring.n, wind);
        for (std::uint32_t k = 0; k <= static_cast<std::uint32_t>(ring.n); ++k) {
            mesh_.normals[ring.base + k] =
                (mesh_.positions[ring.base + k] - h.node.cast<float>()).normalized();
        }
        hullRings_.push_back({ring, HullRingKind::Ball, h.start, h.node, h.limb});
    }
    ++report_.nodeBalls;
}

// The mesh vertex of hull point `point` in `face`: a ring's vertex 0 is taken as its seam copy
// (u = 1) when the face's other corners on that ring lie past the ring's middle.
std::uint32_t JunctionMesher::seamVertex(std::uint32_t point,
                                         const std::array<std::uint32_t, 3>& face) const {
    const std::int32_t r = pointRing_[point];
    const RingRecord& ring = hullRings_[static_cast<std::size_t>(r)].ring;
    const int k = pointIndex_[point];
    if (k == 0) {
        for (std::uint32_t other : face) {
            if (other != point && pointRing_[other] == r && 2 * pointIndex_[other] > ring.n) {
                return ring.base + static_cast<std::uint32_t>(ring.n);
            }
        }
    }
    return ring.base + static_cast<std::uint32_t>(k);
}

// Conservative close: each arm's tube runs on at its ring's radius a quarter of the radius past
// the branch node and is closed there by a cone half the radius long, so the arms overlap
// around the node as plain tubes do, by a margin far above the solid union's moves (with a
// cone alone the arms met only in a needle around the node, and the union's moves pulled them
// apart). Past the node rather than at it: rings of equal radius centred on one node share
// the points where their planes cross, which would join the arms' surfaces there. A flat cap
// where the node is not in front of the ring. Each absorbed limb as a tube of its own.
// A fallback arm's tube from its ring back along its limb: a ring at every limb point between
// the arm's ring and the node (a crowded junction pushes rings far along their limbs, up to
// their far ends, and a straight tube from there would leave a bent limb). Returns the ring
// nearest the node (the arm's own when no point lies between), facing away from the node.
RingRecord JunctionMesher::armBackToNode(const HullRing& h) {
    const WeldSkeleton& s = skeleton_;
    const auto li = static_cast<std::size_t>(h.limb);
    const WeldLimb& limb = s.limbs[li];
    const double length = s.limbLength(limb);
    const double ringArc = h.start ? junctions_.startOffset[li] : length - junctions_.endOffset[li];
    RingRecord arm = h.ring;
    double arc = ringArc;
    double v = mesh_.uvs[arm.base].y();
    const std::uint32_t inner = limb.count - 2;  // points 1 … count − 2 lie between the nodes
    for (std::uint32_t i = 0; i < inner; ++i) {
        const std::uint32_t k = h.start ? inner - i : 1 + i;  // from the ring towards the node
        const std::uint32_t p = limb.first + k;
        const double spacing = 0.05 * s.pointRadius[p];
        if (h.start ? s.pointArc[p] >= ringArc - spacing : s.pointArc[p] <= ringArc + spacing) {
            continue;
        }
        const RingPlace place = ringAtPoint(s, limb, k);
        const double dv = std::abs(s.pointArc[p] - arc) * vScale_ / (arm.radius + place.radius);
        v += h.start ? dv : -dv;
        arc = s.pointArc[p];
        RingRecord ring = ringAfter(arm, place, static_cast<float>(v));
        if (h.start) {
            emitSides(ring.base, arm.base, arm.n);
        } else {
            emitSides(arm.base, ring.base, arm.n);
            ring.outward = -place.normal;  // away from the end node
        }
        arm = ring;
    }
    return arm;
}

void JunctionMesher::fallbackJunction() {
    for (const HullRing& h : hullRings_) {
        if (!h.hole()) continue;
        const RingRecord arm = armBackToNode(h);
        // Towards the node along the tube, and the tube's frame there (the arm ring's own: its
        // plane is square to the tube).
        Vec3 towardNode = -arm.outward;
        Vec3 frameNormal = arm.e1.cross(arm.e2);
        Vec3 e1 = arm.e1;
        const auto li = static_cast<std::size_t>(h.limb);
        if (junctions_.sharedNormal[li] != Vec3::Zero()) {
            // A ring shared with the junction across its plane (a straight limb) is slanted to
            // the tube and faces across the plane: the tube runs back square to the limb, on
            // this side of the plane, and its frame is the ring's unslanted.
            const Vec3& along = pointDirection(skeleton_, skeleton_.limbs[li], 0);
            towardNode = h.start ? Vec3(-along) : along;
            frameNormal = along;
            e1 = (arm.e1 - arm.e1.dot(along) * along).normalized();
        }
        const double ahead = (h.node - arm.center).dot(towardNode);
        if (!(ahead > 0.05 * arm.radius)) {
            emitCap(arm, -arm.outward, !h.start, arm.center);
            continue;
        }
        // The ring past the node keeps the arm ring's frame; texture v runs on along the arm.
        RingPlace place;
        place.center = h.node + 0.25 * arm.radius * towardNode;
        place.normal = frameNormal;
        place.radius = arm.radius;
        const float ringV = mesh_.uvs[arm.base].y();
        const double dv = (ahead + 0.25 * arm.radius) * vScale_ / (2.0 * arm.radius);
        const auto v = static_cast<float>(ringV + (h.start ? dv : -dv));
        const RingRecord pastNode = emitRing(place, e1, v, arm.n, arm.wind);
        if (h.start) {
            emitSides(pastNode.base, arm.base, arm.n);
        } else {
            emitSides(arm.base, pastNode.base, arm.n);
        }
        emitCap(pastNode, towardNode, !h.start, place.center + 0.5 * arm.radius * towardNode);
    }
    // The limbs inside the junction (between its merged branch nodes) become tubes of their
    // own. The convex hull of their rings, which this used before, spans the whole crowded
    // cluster (up to 16 branch nodes): large faceted blobs where a fine crown should be (ABOP
    // 2.8a), and where it failed (1.25: 103 rings whose incremental hull met a horizon that
    // was not a simple cycle) the limbs had no surface and the tree split. An absorbed limb's
    // rings are listed together.
    std::int32_t last = -1;
    for (const HullRing& h : hullRings_) {
        if (h.kind != HullRingKind::Absorbed || h.limb == last) continue;
        tubeAbsorbedLimb(h.limb);
        last = h.limb;
        ++report_.absorbedTubes;
    }
}

// An absorbed limb of a fallback junction: a tube through its points, run a
// quarter of the radius past both end nodes and closed there by cones half the radius long,
// as the fallback's arms are, so that it overlaps them (the solid union joins them).
void JunctionMesher::tubeAbsorbedLimb(std::int32_t l) {
    const WeldSkeleton& s = skeleton_;
    const WeldLimb& limb = s.limbs[static_cast<std::size_t>(l)];
    double v = keyV_[static_cast<std::size_t>(limb.startKey)];
    RingRecord previous{};
    for (std::uint32_t k = 0; k < limb.count; ++k) {
        RingPlace place = ringAtPoint(s, limb, k);
        const double past = 0.25 * place.radius;
        if (k == 0) place.center -= past * place.normal;
        if (k + 1 == limb.count) place.center += past * place.normal;
        if (k == 0) {
            previous = emitRing(place, initialReference(place.normal), static_cast<float>(v),
                                limb.segments, windAt(place));
            emitCap(previous, -place.normal, false, place.center - 2.0 * past * place.normal);
            continue;
        }
        v = vAfterStep(s, vScale_, limb.first + k, v);
        const RingRecord ring = ringAfter(previous, place, static_cast<float>(v));
        emitSides(previous.base, ring.base, limb.segments);
        previous = ring;
    }
    const Vec3 normal = previous.e1.cross(previous.e2);
    emitCap(previous, normal, true, previous.center + 0.5 * previous.radius * normal);
}

JunctionMesher::Piece JunctionMesher::meshJunction(NodeId cluster) {
    Piece piece;
    piece.firstVertex = static_cast<std::uint32_t>(mesh_.positions.size());
    piece.firstIndex = mesh_.indices.size();
    tubeVertices_.clear();
    gatherJunction(cluster);
    if (!hullRings_.empty()) {
        copyTubeRings();
        closeJunction();
    }
    // The copies go (only the tubes' own vertices are kept), so a mesher holds no more than
    // the junctions' own vertices: on the synthetic trees nearly every tube vertex is on a
    // junction's ring.
    const auto copied = static_cast<std::uint32_t>(tubeVertices_.size());
    const std::uint32_t own = piece.firstVertex + copied;
    for (std::size_t i = piece.firstIndex; i < mesh_.indices.size(); ++i) {
        std::uint32_t& v = mesh_.indices[i];
        RAMUS_ASSERT(v >= piece.firstVertex && v < mesh_.positions.size());
        v = v < own ? tubeVertices_[v - piece.firstVertex] : kOwnVertex | (v - own);
    }
    eraseVertices(piece.firstVertex, copied);
    piece.endVertex = static_cast<std::uint32_t>(mesh_.positions.size());
    piece.endIndex = mesh_.indices.size();
    return piece;
}

// Removes vertices [first, first + count) of mesh_ (and their wind values).
void JunctionMesher::eraseVertices(std::uint32_t first, std::uint32_t count) {
    auto erase = [&](auto& values, std::size_t width) {
        const auto begin = values.begin() + static_cast<std::ptrdiff_t>(first * width);
        values.erase(begin, begin + static_cast<std::ptrdiff_t>(count * width));
    };
    erase(mesh_.positions, 1);
    erase(mesh_.normals, 1);
    erase(mesh_.tangents, 1);
    erase(mesh_.uvs, 1);
    if (params_.tube.windAttributes) {
        erase(windOut_.wind, 4);
        erase(windOut_.pivot, 3);
        erase(windOut_.leaf, 2);
    }
}

// Whether an arm of the junction gathered is a crossing limb (WeldJunctions::crossing).
bool JunctionMesher::atCrossing() const {
    return std::any_of(hullRings_.begin(), hullRings_.end(), [&](const HullRing& h) {
        return h.hole() && junctions_.crossing[static_cast<std::size_t>(h.limb)] != 0;
    });
}

// The junction gathered: its hull with the arms' discs cut out (shrunk onto the branches with
// shrinkJunctions), or, where that fails, the fallback's tubes. Without the solid union, a
// junction at a crossing is tubes from the start (WeldReport::crossingTubes): its hull would
// overlap the neighbour's across the crossing anyway, and shrunk over the crowded clusters
// where crossings happen it left webs far outside the branches (ABOP 1.27: fins up to 5.4
// radii beside the trunk, 11 of its 12 webbed junctions at a crossing); that shrinking was
// most of the dense plants' welding time (1.27 0.030 → 0.009 s, 1.24a 0.12 → 0.026 s). With
// the union the hulls are kept: it joins them to their neighbours and tubes only those left
// webbed (tubing every one at a crossing made ABOP 1.24a's union 0.96 → 1.45 s, 167 k → 208 k
// triangles).
void JunctionMesher::closeJunction() {
    if (params_.tubesAtCrossings && !params_.solidUnion && atCrossing()) {
        ++report_.crossingTubes;
        fallbackJunction();
        return;
    }
    const std::size_t before = mesh_.indices.size();
    bool closed = buildHull() && holesAreRings();
    if (closed && addNodeBalls()) closed = buildHull() && holesAreRings();
    const std::size_t rings = hullRings_.size();
    if (closed && addBendRings() && !(buildHull(rings) && holesAreRings())) {
        report_.bendRings -= hullRings_.size() - rings;  // without them, as before
        hullRings_.resize(rings);
        closed = buildHull() && holesAreRings();
    }
    if (!closed) {
        ++report_.fallbacks;
        fallbackJunction();
        return;
    }
    emitHull();
    // Webs the shrinking left (or a convex hull has) are meshed as tubes where the union will
    // join them (kUnionWebLimit, welded_junction_refine.cpp); shrunk vertices go again.
    const std::size_t vertices = mesh_.positions.size();
    const bool webbed = params_.shrinkJunctions ? refineJunction(before, params_.solidUnion)
                                                : params_.solidUnion && hullWebbed(before);
    if (!webbed) return;
    ++report_.tubedForUnion;
    mesh_.positions.resize(vertices);
    mesh_.normals.resize(vertices);
    mesh_.tangents.resize(vertices);
    mesh_.uvs.resize(vertices);
    if (params_.tube.windAttributes) windOut_.resize(vertices);
    mesh_.indices.resize(before);
    fallbackJunction();
}

}  // namespace ramus::detail
