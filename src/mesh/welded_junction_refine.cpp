// Shrinking junction hulls onto the branches they join (docs/welded.md, "Shrunk junctions").
//
// A junction's convex hull spans everything between its rings: where several thin branches
// leave a thick trunk at small angles (colonization hedges: 9 arms from 6 merged branch nodes,
// rings up to 19 radii out), it is one faceted blob over the whole crotch, far outside the tubes.
// The hull faces that lie far from the branches (webs) are subdivided (edges on an arm's ring
// stay whole: the tube's sides share them), and every new vertex moves from the hull towards
// a centre point inside the hull until it reaches the branches' surface — the union of their
// tapered capsules with a small fillet (a smooth minimum), as a sculpted crotch has.
//
// Why that keeps the surface clean: the hull is convex and holds the centre strictly inside,
// so it is star-shaped from there, and a vertex moving along its ray towards the centre stays
// inside the hull, behind every arm's ring plane, where no tube runs. A closed mesh whose
// triangles all face away from the centre projects one to one onto the sphere around it, so
// it cannot intersect itself. Each moved triangle is checked for that, and for keeping the
// branches' axes inside; where one fails its corners' moves are shortened until it passes, and
// after a few rounds they go back onto the hull (a flat subdivided hull face always passes).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "on_cores.hpp"
#include "ramus/rng.hpp"
#include "welded_builder.hpp"

namespace ramus::detail {

JunctionShape::Capsule::Point JunctionShape::Capsule::nearest(const Vec3& p) const {
    const double t = std::clamp((p - a).dot(ab) * inverse2, 0.0, 1.0);
    return {p - a - t * ab, ra + t * (rb - ra)};
}

namespace {

// A hull face is a web, and refined, when its centre or an edge's midpoint lies farther than
// this (in radii of the nearest branch) outside the branches: at 0.5 a quarter of the faces
// of a hand-made crotch of twigs that lay farther than a quarter radius out were left
// (WeldedMesh.JunctionHullOverACrotchIsShrunkOntoTheBranches).
constexpr double kRefineExcess = 0.5;
// At most this many pieces per hull edge (a face becomes up to kMaxSplit² triangles).
constexpr int kMaxSplit = 8;
// Target length of the new edges, in radii of the junction's thinnest arm.
constexpr double kSplitLength = 2.0;
// Fillet of the crotches (the smooth minimum's blend width) and how far outside the capsules'
// surface the vertices stop (flat triangles between points on a curved surface cut in by their
// sag, and the tube polygons they meet lie inside their capsules), in radii of the thinnest arm.
constexpr double kFillet = 0.5;
constexpr double kSurfaceOffset = 0.05;
// A centre moved onto a branch axis lies at least this far inside the hull (radii of the
// thinnest arm), so the faces around it clearly face away from it.
constexpr double kCentreDepth = 0.5;
// Junctions with more branch segments than this within reach of their hull keep it: in a
// tangle of branches (a dense synthetic binary tree: thousands per junction) shrinking would
// cost time growing with the density, and the hull hides little there. The shipped examples
// have at most 66 (one junction of ABOP 1.27; hedge 36, the median junction 3–4). Session 19
// measured this cap at 256 more than halving the welding speed of the synthetic trees
// (monopodial 1M edges 1.28 → 0.59 M triangles/s) and kept 64; since session 20 a ray's
// distance evaluations fold only the capsules near it, nearest first (orderFor), and the cap
// of 256 costs monopodial about 15 % (docs/BENCHMARKS.md).
constexpr std::size_t kMaxCapsules = 256;
// And junctions whose reach meets the boxes of more than this many segments (candidates, of
// which those in reach are a part) keep it too, without counting those in reach: in a tangle
// that count stopped only at the cap, after about 6 500 candidates per junction (synthetic
// binary tree, 262k edges: 8 499 of its 8 534 junctions with webs were over the cap, and
// counting took a fifth of its welding time; session 22). The shipped examples visit at most
// 202 candidates per junction, monopodial 262k 1 528 for a junction under the cap.
constexpr std::size_t kMaxCandidates = 8 * kMaxCapsules;
// Centres tried for a junction not star-shaped from its first (docs/welded.md, "Shrunk
// junctions", step 4), in all, where at most kMaxCentreCapsules branch segments are in reach
// (beyond, see kMaxExcessCentreCapsules). Measured in session 20 (silhouettes, largest view, and
// monopodial 262k edges, paired runs): up to 3 centres give ABOP 1.27 11.5 → 5.4 radii and
// hedge_1 2.3 → 0.66, as 5 or 8 do; at 64 segments monopodial loses 6 % of its speed (1.34–1.38
// → 1.26–1.29 M triangles/s), at 128 24 % for 1.31a's worst junction (84 segments: 6.2 → 3.4
// radii).
constexpr std::size_t kMaxCentres = 3;
constexpr std::size_t kMaxCentreCapsules = 64;
// The third centre only where at most kMaxThirdCentreCapsules segments are in reach: there the
// tries are cheap and gain most (conifer: at 6–8 segments the best centre leaves 5–14 % of the
// first one's excess), while the junctions with more (ABOP 1.24a: 17–34, each try a few hundred
// rays) rarely gain (in 1.24a the third centre was the best in 7 of 60, by 1–10 % of the
// excess, and no silhouette changed). Measured in session 34 (every shipped example's
// silhouette, paired benchmarks): welding ABOP 1.24a 191 → 128 ms, 1.27 34.5 → 27.6 ms;
// silhouettes the same but hedge_4 (largest view 0.44 → 0.61 radii, within the tolerance of
// 1), hedge_2 (one view 0.25 → 0.35, its largest 0.54 as before) and 1.27 (area 3.99 → 3.97 %).
constexpr std::size_t kMaxThirdCentreCapsules = 16;
// Junctions with more segments in reach, up to kMaxExcessCentreCapsules, try more centres too
// where the faces around their halved moves leave much outside the branches: an excess
// (excess(true)) of at least kLargeExcess thinnest radii cubed. Measured in session 21: ABOP
// 1.31a's worst junction (84 segments) leaves 7.3·10⁴, and more centres take its silhouette
// from 2.6 % / 6.2 radii to 2.0 % / 3.4. In the synthetic monopodial trees few junctions reach
// it (262k edges: 4 of the 222 with 65–256 segments whose moves are halved; 16k: 2 of 96
// shrunk, with 115 and 210 segments), but each try runs over all their segments: up to 256,
// monopodial 16k lost 27 % of its speed (1.97 → 1.45 M triangles/s, paired), up to 128 6–8 %,
// up to 96 nothing measurable. The excess of all their faces instead of those around halved
// moves as the gate cost monopodial 262k about 10 %.
constexpr std::size_t kMaxExcessCentreCapsules = 128;
constexpr double kLargeExcess = 1e4;
// Over-relaxation of the sphere tracing along the rays (JunctionRefiner::restingPoint).
constexpr double kRelaxation = 1.6;
// How far a moved triangle must face away from the centre (JunctionRefiner::facesAway).
constexpr double kEdgeOn = 1e-5;
// Rounds of shortening the moves of triangles that turn edge-on to the rays or leave a point of
// a branch axis outside. Each shortens a failing triangle's moves by the largest factor (to
// 1/64) with which it passes; until session 22 they were halved, which left more of the webs
// (ABOP 1.31a 1.40 → 0.55 radii off the tubes, 1.41 → 1.22 % of the area; 1.27 4.5 → 4.0 %).
constexpr int kShorteningRounds = 6;
// With the solid union, a shrunk junction whose faces still lie more than this many local radii
// outside the branches (a face's centre or an edge's midpoint: webs the shrinking could not
// pull in, over clusters of tips not star-shaped from any centre tried) is meshed as capped
// tubes instead, as a fallback junction, and the union joins them: 1 radius is the tolerance
// of the silhouette gained against the tube mesh (tests/mesh/welded_silhouette_test.cpp).
// Where the convex hulls are united instead (WeldReport::convexForUnion), hulls with such
// faces are tubes too (hullWebbed). Measured in session 24 (every shipped example united):
// 0–79 junctions per example (ABOP 1.27 12, 1.31a 5, hedges 2–3), and every example within
// the silhouette tolerances united (1.27 4.0 % of the area and 5.35 radii gained → 0, 1.31a
// 1.2 % → 0, hedges 0.47–0.82 % → 0.22–0.33 %; docs/welded.md, Shrunk junctions, step 7).
constexpr double kUnionWebLimit = 1.0;

// A hash of the bits of a float position: vertices at one position (texture seam copies)
// hash alike.
std::uint64_t positionHash(const Vec3f& p) {
    return hashCombine(
        hashCombine(std::bit_cast<std::uint32_t>(p.x()), std::bit_cast<std::uint32_t>(p.y())),
        std::bit_cast<std::uint32_t>(p.z()));
}

// The signed distance to tapered capsules folded in one at a time, smoothed by the fillet.
struct SmoothUnion {
    double fillet;
    double d = std::numeric_limits<double>::infinity();
    double plain = std::numeric_limits<double>::infinity();  // the nearest surface's distance

    // Folds in a capsule whose surface lies `di` away; returns the weight of its direction in
    // the gradient (1 − h/2 where it is the nearer, h/2 where it is the farther).
    double fold(double di) {
        // Polynomial smooth minimum (Quilez): min(d, di) − fillet h²/4 with h = (fillet −
        // |d − di|) / fillet, which is min(d, di) once they differ by `fillet`. Its slope in d
        // is 1 − h/2 where d is the smaller, h/2 where it is the larger.
        const double h = std::max(fillet - std::abs(d - di), 0.0) / fillet;
        const double toNew = di < d ? 1.0 - 0.5 * h : 0.5 * h;
        d = std::min(d, di) - 0.25 * h * h * fillet;
        plain = std::min(plain, di);
        return toNew;
    }
};

// SmoothUnion at a point, with the gradient's direction.
struct SmoothUnionAt {
    const Vec3& p;
    bool withGradient;
    SmoothUnion sum;
    Vec3 g = Vec3::Zero();

    void add(const JunctionShape::Capsule& c) {
        const JunctionShape::Capsule::Point q = c.nearest(p);
        const double length = q.offset.norm();
        const double toNew = sum.fold(length - q.radius);
        if (withGradient && length > 0.0) g = (1.0 - toNew) * g + toNew * (q.offset / length);
    }
    double result(Vec3* gradient) const {
        if (gradient != nullptr) *gradient = g;
        return sum.d;
    }
};

}  // namespace

// Subdivides the hull faces of one junction (the last triangles of the mesh, from
// `firstIndex`) and moves the new vertices onto the branches.
class JunctionRefiner {
public:
    JunctionRefiner(Mesh& mesh, WindAttributes* wind, const JunctionShape& shape,
                    std::size_t firstIndex, CoreTeam& team)
        : mesh_(mesh), wind_(wind), shape_(shape), first_(firstIndex), team_(team) {}

    // Marks the edges to split: those of faces far outside the branches (webs), but not the
    // arms' ring edges (`whole(a, b)`), which the tubes share. Returns false if there is none.
    template <class WholeEdge>
    bool markWebs(WholeEdge whole) {
        double longest = 0.0;
        for (std::size_t f = first_; f < mesh_.indices.size(); f += 3) {
            if (!faceFarOutside(f, kRefineExcess)) continue;
            const std::array<std::uint32_t, 3> v = face(f);
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t p = v[static_cast<std::size_t>(e)];
                const std::uint32_t q = v[static_cast<std::size_t>((e + 1) % 3)];
                if (whole(p, q)) continue;
                split_.insert(edgeKey(canonical(p), canonical(q)));
                longest = std::max(longest, (position(q) - position(p)).norm());
            }
        }
        if (split_.empty()) return false;
        m_ = std::clamp(static_cast<int>(std::ceil(longest / (kSplitLength * shape_.thinnest))), 2,
                        kMaxSplit);
        return true;
    }

    // Replaces the junction's faces: a face with all three edges split by a grid of m² triangles,
    // with two by a ladder from their common corner, with one by a fan from the opposite corner.
    void subdivide() {
        const std::vector<std::uint32_t> faces(
            mesh_.indices.begin() + static_cast<std::ptrdiff_t>(first_), mesh_.indices.end());
        mesh_.indices.resize(first_);
        firstNew_ = static_cast<std::uint32_t>(mesh_.positions.size());
        hullFaces_.clear();
        for (std::size_t f = 0; f < faces.size(); f += 3) {
            std::array<std::uint32_t, 3> v = {faces[f], faces[f + 1], faces[f + 2]};
            hullFaces_.push_back({v, mesh_.indices.size(), 0});
            std::array<bool, 3> cut{};
            int cuts = 0;
            for (int e = 0; e < 3; ++e) {
                cut[static_cast<std::size_t>(e)] =
                    split_.count(edgeKey(canonical(v[static_cast<std::size_t>(e)]),
                                         canonical(v[static_cast<std::size_t>((e + 1) % 3)]))) > 0;
                cuts += cut[static_cast<std::size_t>(e)] ? 1 : 0;
            }
            if (cuts == 0) {
                mesh_.indices.insert(mesh_.indices.end(), v.begin(), v.end());
            } else if (cuts == 1) {  // rotate the split edge to v0 → v1
                const auto e =
                    static_cast<int>(std::find(cut.begin(), cut.end(), true) - cut.begin());
                std::rotate(v.begin(), v.begin() + e, v.end());
                fan(v);
            } else if (cuts == 2) {  // rotate the whole edge to v1 → v2
                const auto e =
                    static_cast<int>(std::find(cut.begin(), cut.end(), false) - cut.begin());
                std::rotate(v.begin(), v.begin() + (e + 2) % 3, v.end());
                ladder(v);
            } else {
                grid(v);
            }
            hullFaces_.back().end = mesh_.indices.size();
        }
        // What every shrink, whatever its centre, reads: the capsules' bounding spheres and the
        // new vertices' seam copies.
        spheres_.clear();
        for (const JunctionShape::Capsule& c : shape_.capsules) {
            const Vec3 middle = 0.5 * (c.a + c.b);
            spheres_.emplace_back(middle.x(), middle.y(), middle.z(),
                                  0.5 * std::sqrt(c.length2) + std::max(c.ra, c.rb));
        }
        findSeamCopies();
    }

    // Moves every new vertex to where its ray towards the centre enters the branches' surface,
    // then shortens the moves around triangles that turn edge-on to the rays or leave a
    // `sample` (a point of a branch's axis) outside, until none does; after kShorteningRounds such
    // vertices go back onto the hull. Copies of a vertex on a texture seam share one move.
    void shrink(const Vec3& centre, const std::vector<Vec3>& samples) {
        centre_ = centre;
        centreDistance_ = shape_.plainDistance(centre);
        const std::size_t added = onHull_.size();
        // From the flat subdivision (a shrink towards another centre may have moved them).
        for (std::size_t i = 0; i < added; ++i) {
            mesh_.positions[firstNew_ + i] = onHull_[i].cast<float>();
        }
        target_.resize(added);
        targetNormal_.resize(added);
        // The rays are independent: on the machine's cores, each with scratch space of its own.
        rays_.resize(team_.workersFor(added));
        team_.forEach(added, [&](std::size_t i, std::size_t worker) {
            if (owner_[i] == i) {
                target_[i] = restingPoint(onHull_[i], targetNormal_[i], rays_[worker]);
            }
        });
        for (std::size_t i = 0; i < added; ++i) {
            if (owner_[i] != i) {  // a seam copy, at the same point as its owner
                target_[i] = target_[owner_[i]];
                targetNormal_[i] = targetNormal_[owner_[i]];
            }
        }
        share_.assign(added, 1.0);
        // The vertices move along rays from the centre, so the triangle whose cone holds a
        // sample stays the same.
        std::vector<std::pair<std::size_t, Vec3>> held;
        for (const Vec3& q : samples) {
            const std::size_t f = faceAbove(q);
            if (f != kNone) held.emplace_back(f, q);
        }
        for (int round = 0;; ++round) {
            for (std::size_t i = 0; i < added; ++i) {
                mesh_.positions[firstNew_ + i] =
                    (onHull_[i] + share_[owner_[i]] * (target_[i] - onHull_[i])).cast<float>();
            }
            bool halved = false;
            for (std::size_t f = first_; f < mesh_.indices.size(); f += 3) {
                if (!facesAway(f)) {
                    halved =
                        shortenMoves(f, round,
                                     [&](const std::array<Vec3, 3>& p) { return facesAway(p); }) ||
                        halved;
                }
            }
            for (const auto& [f, q] : held) {
                if (!below(f, q)) {
                    // q by value: clang before 16 cannot capture a structured binding.
                    halved = shortenMoves(f, round,
                                          [sample = q](const std::array<Vec3, 3>& p) {
                                              return below(p, sample);
                                          }) ||
                             halved;
                }
            }
            if (!halved) break;
        }
    }

    // What a shrink leaves (the moves towards one centre), to go back to the best of several.
    struct Shrunk {
        Vec3 centre;
        double centreDistance;
        std::vector<Vec3> target, targetNormal;
        std::vector<double> share;
    };
    Shrunk shrunk() const { return {centre_, centreDistance_, target_, targetNormal_, share_}; }
    // The state of the shrink that left `s`, as a shrink towards its centre would leave it
    // again (the moves do not depend on what was shrunk before).
    void restore(Shrunk s) {
        centre_ = s.centre;
        centreDistance_ = s.centreDistance;
        target_ = std::move(s.target);
        targetNormal_ = std::move(s.targetNormal);
        share_ = std::move(s.share);
        for (std::size_t i = 0; i < onHull_.size(); ++i) {
            mesh_.positions[firstNew_ + i] =
                (onHull_[i] + share_[owner_[i]] * (target_[i] - onHull_[i])).cast<float>();
        }
    }

    // Normals of the new vertices where the last shrink left them: the surface's gradient
    // (the same at seam copies). A vertex that made its whole move has the one found there.
    void setNormals() {
        for (std::size_t i = 0; i < onHull_.size(); ++i) {
            Vec3 gradient = targetNormal_[owner_[i]];
            if (share_[owner_[i]] != 1.0 || gradient == Vec3::Zero()) {
                const Vec3 p = position(firstNew_ + static_cast<std::uint32_t>(i));
                orderFor(p, p, rays_[0]);
                shape_.distance(p, rays_[0].order, &gradient);
                if (!(gradient.norm() > 1e-6)) gradient = p - centre_;
            }
            mesh_.normals[firstNew_ + i] = gradient.normalized().cast<float>();
        }
    }

    // Whether a face of the junction still lies more than `limit` local radii outside the
    // branches (its centre or an edge's midpoint).
    bool websLeft(double limit) const {
        for (std::size_t f = first_; f < mesh_.indices.size(); f += 3) {
            if (faceFarOutside(f, limit)) return true;
        }
        return false;
    }

    // Whether every new vertex made its whole move.
    bool allMoved() const {
        return std::all_of(share_.begin(), share_.end(), [](double s) { return s == 1.0; });
    }
    // How far the junction's faces with a moved corner stay outside the branches' surface:
    // the distance of each face's centre beyond it times the face's area, summed (the other
    // faces are the same whatever the centre); `halvedOnly`: over the faces with a corner whose
    // move was halved alone.
    double excess(bool halvedOnly = false) {
        const double iso = kSurfaceOffset * shape_.thinnest;
        const std::size_t faces = (mesh_.indices.size() - first_) / 3;
        excess_.resize(faces);
        team_.forEach(faces, [&](std::size_t k, std::size_t) {
            excess_[k] = 0.0;
            const std::array<std::uint32_t, 3> v = face(first_ + 3 * k);
            if (std::none_of(v.begin(), v.end(), [&](std::uint32_t u) {
                    return u >= firstNew_ && (!halvedOnly || share_[owner_[u - firstNew_]] < 1.0);
                })) {
                return;
            }
            const Vec3 a = position(v[0]), b = position(v[1]), c = position(v[2]);
            const double out = distanceAt((a + b + c) / 3.0) - iso;
            if (out > 0.0) excess_[k] = out * 0.5 * (b - a).cross(c - a).norm();
        });
        double sum = 0.0;  // in face order, whatever the threads
        for (const double e : excess_) sum += e;
        return sum;
    }

private:
    // shape_.distance(p) with the capsule whose bounding sphere's middle lies nearest folded in
    // first: each capsule after it whose sphere lies a fillet beyond the nearest surface so far
    // leaves the distance as it is, and is passed over (most of them: a face's centre lies near
    // one or two branches of the dozens in reach), without a square root.
    double distanceAt(const Vec3& p) const {
        std::array<double, kMaxCapsules> apart2;  // from p to each sphere's middle, squared
        if (spheres_.empty() || spheres_.size() > apart2.size()) return shape_.distance(p);
        std::size_t nearest = 0;
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            apart2[i] = (spheres_[i].head<3>() - p).squaredNorm();
            if (apart2[i] < apart2[nearest]) nearest = i;
        }
        SmoothUnionAt sum{p, false, {shape_.fillet}};
        sum.add(shape_.capsules[nearest]);
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            const double beyond = sum.sum.plain + shape_.fillet + spheres_[i].w();
            if (i == nearest || (apart2[i] >= beyond * beyond && beyond > 0.0)) continue;
            sum.add(shape_.capsules[i]);
        }
        return sum.result(nullptr);
    }

    // Scratch space of one ray (one per thread).
    struct Ray {
        std::vector<JunctionShape::Bound> order;  // the capsules by distance from the ray
        struct Along {
            double q0, q1, q2;         // |x − a|² = q0 + s (q1 + s q2)
            double e0, e1;             // (x − a)·(b − a) = e0 + e1 s
            double length2, inverse2;  // |b − a|² and its inverse (0 for a ball)
            double ra, dr;             // the radius at a and its change to b
            double bound;              // order's bound of the surface's distance from the ray
        };
        std::vector<Along> along;  // order along the ray of restingPoint
    };
    static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

    static std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
        return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    }
    Vec3 position(std::uint32_t v) const { return mesh_.positions[v].cast<double>(); }
    // The first corner vertex seen at v's position: one id for a ring vertex and its seam
    // copy, so a split edge is split in both faces on it whichever copy they use.
    std::uint32_t canonical(std::uint32_t v) {
        const Vec3f& p = mesh_.positions[v];
        const auto it = corners_.emplace(positionHash(p), v).first;
        return mesh_.positions[it->second] == p ? it->second : v;  // else a 64-bit collision
    }
    std::array<std::uint32_t, 3> face(std::size_t f) const {
        return {mesh_.indices[f], mesh_.indices[f + 1], mesh_.indices[f + 2]};
    }
    // Whether face f's centre or an edge's midpoint lies more than `limit` local radii outside
    // the branches (JunctionShape::farOutside).
    bool faceFarOutside(std::size_t f, double limit) const {
        const std::array<std::uint32_t, 3> v = face(f);
        const Vec3 a = position(v[0]), b = position(v[1]), c = position(v[2]);
        for (const Vec3& probe : {Vec3((a + b + c) / 3.0), Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)),
                                  Vec3(0.5 * (c + a))}) {
            if (shape_.farOutside(probe, limit)) return true;
        }
        return false;
    }

    // A new vertex on the hull at `p`: texture and tangent blended from `corners` by `weights`,
    // the wind values of the nearest corner (the level must stay a whole number, and one
    // branch's phase is not to be mixed with another's).
    std::uint32_t addVertex(const Vec3& p, const std::array<std::uint32_t, 3>& corners,
                            const Vec3& weights) {
        const auto id = static_cast<std::uint32_t>(mesh_.positions.size());
        Vec2f uv = Vec2f::Zero();
        Vec3f tangent = Vec3f::Zero();
        int nearest = 0;
        for (int i = 0; i < 3; ++i) {
            const auto w = static_cast<float>(weights[i]);
            uv += w * mesh_.uvs[corners[static_cast<std::size_t>(i)]];
            tangent += w * mesh_.tangents[corners[static_cast<std::size_t>(i)]].head<3>();
            if (weights[i] > weights[nearest]) nearest = i;
        }
        tangent = tangent.norm() > 0.0f ? Vec3f(tangent.normalized()) : Vec3f::UnitX();
        onHull_.push_back(p);
        mesh_.positions.push_back(p.cast<float>());
        mesh_.normals.push_back(Vec3f::UnitY());  // set once the vertex has moved
        mesh_.tangents.emplace_back(tangent.x(), tangent.y(), tangent.z(), 1.0f);
        mesh_.uvs.push_back(uv);
        if (wind_ != nullptr) {
            const std::size_t from = corners[static_cast<std::size_t>(nearest)];
            wind_->resize(mesh_.positions.size());
            auto copy = [&](std::vector<float>& values, std::size_t width) {
                std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(from * width), width,
                            values.begin() + static_cast<std::ptrdiff_t>(id * width));
            };
            copy(wind_->wind, 4);
            copy(wind_->pivot, 3);
            copy(wind_->leaf, 2);
        }
        return id;
    }

    // Vertex k (0 … m) along edge a → b. A split edge's m − 1 vertices are shared by the faces
    // on it and placed from its lexicographically smaller end, so seam copies of the edge
    // (other vertex ids, the same positions) get bit-identical positions.
    std::uint32_t edgeVertex(std::uint32_t a, std::uint32_t b, int k) {
        if (k == 0) return a;
        if (k == m_) return b;
        auto it = edges_.find(edgeKey(a, b));
        if (it == edges_.end()) {
            const Vec3f& pa = mesh_.positions[a];
            const Vec3f& pb = mesh_.positions[b];
            const bool forward =
                !std::lexicographical_compare(pb.data(), pb.data() + 3, pa.data(), pa.data() + 3);
            const std::uint32_t from = forward ? a : b, to = forward ? b : a;
            const Vec3 p = position(from), q = position(to);
            const auto firstId = static_cast<std::uint32_t>(mesh_.positions.size());
            for (int i = 1; i < m_; ++i) {
                const double t = static_cast<double>(i) / m_;
                addVertex(p + t * (q - p), {from, to, to}, Vec3(1.0 - t, t, 0.0));
            }
            it = edges_.emplace(edgeKey(a, b), SplitEdge{firstId, from}).first;
        }
        const int i = it->second.from == a ? k : m_ - k;
        return it->second.first + static_cast<std::uint32_t>(i - 1);
    }

    void emit(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
    }
    // Edge v0 → v1 split, fan from v2.
    void fan(const std::array<std::uint32_t, 3>& v) {
        for (int i = 0; i < m_; ++i)
            emit(edgeVertex(v[0], v[1], i), edgeVertex(v[0], v[1], i + 1), v[2]);
    }
    // Edges v0 → v1 and v0 → v2 split: rows between them from v0.
    void ladder(const std::array<std::uint32_t, 3>& v) {
        emit(v[0], edgeVertex(v[0], v[1], 1), edgeVertex(v[0], v[2], 1));
        for (int l = 1; l < m_; ++l) {
            const std::uint32_t b0 = edgeVertex(v[0], v[1], l), b1 = edgeVertex(v[0], v[1], l + 1);
            const std::uint32_t c0 = edgeVertex(v[0], v[2], l), c1 = edgeVertex(v[0], v[2], l + 1);
            emit(b0, b1, c1);
            emit(b0, c1, c0);
        }
    }
    // All edges split: vertex (i, j) at v0 + i/m (v1 − v0) + j/m (v2 − v0).
    void grid(const std::array<std::uint32_t, 3>& v) {
        const auto side = static_cast<std::size_t>(m_ + 1);
        grid_.assign(side * side, 0);
        auto at = [&](int i, int j) -> std::uint32_t& {
            return grid_[static_cast<std::size_t>(i) * side + static_cast<std::size_t>(j)];
        };
        const Vec3 p0 = position(v[0]), p1 = position(v[1]), p2 = position(v[2]);
        for (int i = 0; i <= m_; ++i) {
            for (int j = 0; i + j <= m_; ++j) {
                if (j == 0) {
                    at(i, j) = edgeVertex(v[0], v[1], i);
                } else if (i == 0) {
                    at(i, j) = edgeVertex(v[0], v[2], j);
                } else if (i + j == m_) {
                    at(i, j) = edgeVertex(v[1], v[2], j);
                } else {
                    const Vec3 w(static_cast<double>(m_ - i - j) / m_, static_cast<double>(i) / m_,
                                 static_cast<double>(j) / m_);
                    at(i, j) = addVertex(w[0] * p0 + w[1] * p1 + w[2] * p2, v, w);
                }
            }
        }
        for (int i = 0; i < m_; ++i) {
            for (int j = 0; i + j < m_; ++j) {
                emit(at(i, j), at(i + 1, j), at(i, j + 1));
                if (i + j + 1 < m_) emit(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            }
        }
    }

    // Along the ray from hull point p to the centre, the first point inside the branches'
    // surface (sphere tracing, then regula falsi), and the surface's gradient there; p itself
    // and a zero gradient if the ray meets none before the centre.
    Vec3 restingPoint(const Vec3& p, Vec3& normal, Ray& ray) const {
        const double iso = kSurfaceOffset * shape_.thinnest;
        const Vec3 toCentre = centre_ - p;
        const double length = toCentre.norm();
        normal = Vec3::Zero();
        if (!(length > 0.0)) return p;
        const Vec3 direction = toCentre / length;
        orderFor(p, centre_, ray);
        const double safe = alongRay(p, direction, ray);
        double outside = 0.0, dOut = distanceAlong(0.0, ray) - iso;
        if (dOut <= 0.0) return p;
        // Sphere tracing: no branch lies within d / L of a point d outside them (L bounds the
        // distance's slope: safe = 1 / L), so the first crossing is not stepped over.
        // Over-relaxed (Keinert et al. 2014, "Enhanced sphere tracing"): steps of kRelaxation
        // times that, kept while the safe balls around the two ends cover the step (a ray at a
        // slant to the branches); where they do not, the step is taken again plainly and so are
        // the rest. 15 % fewer distance evaluations than plain steps on the synthetic monopodial
        // tree.
        const double least = 0.05 * shape_.thinnest;
        double relaxation = kRelaxation;
        while (outside < length) {
            const double step = std::max(relaxation * safe * dOut, least);
            const double s = std::min(length, outside + step);
            const double d = distanceAlong(s, ray) - iso;
            if (relaxation > 1.0 && safe * (dOut + std::abs(d)) < s - outside &&
                step > std::max(safe * dOut, least)) {
                relaxation = 1.0;
                continue;
            }
            if (d <= 0.0) {
                // The ray's capsules hold every one that matters at any point of it.
                const Vec3 x = p + crossing(outside, dOut, s, d, ray) * direction;
                shape_.distance(x, ray.order, &normal);
                if (!(normal.norm() > 1e-6)) normal = Vec3::Zero();
                return x;
            }
            dOut = d;
            outside = s;
        }
        return p;
    }

    // Where the surface (offset by the iso value) crosses the ray of alongRay between
    // `outside` (value dOut > 0) and `inside` (dIn ≤ 0): regula falsi, Illinois variant.
    double crossing(double outside, double dOut, double inside, double dIn, const Ray& ray) const {
        const double iso = kSurfaceOffset * shape_.thinnest;
        const double tolerance = 1e-3 * shape_.thinnest;
        int side = 0;
        for (int k = 0; k < 32 && inside - outside > tolerance; ++k) {
            const double s = outside + (inside - outside) * dOut / (dOut - dIn);
            const double d = distanceAlong(s, ray) - iso;
            if (std::abs(d) < 1e-2 * tolerance) return s;
            if (d > 0.0) {
                outside = s;
                dOut = d;
                if (side == 1) dIn *= 0.5;
                side = 1;
            } else {
                inside = s;
                dIn = d;
                if (side == -1) dOut *= 0.5;
                side = -1;
            }
        }
        return inside;
    }

    // ray.along: the capsules of ray.order seen from the ray p + s·u, each as a few coefficients
    // in s, for the dozens of distance evaluations along one ray (distanceAlong). Returns the
    // inverse of the distance's steepest slope along the ray: a capsule's distance |x − axis point|
    // − r(t) grows by √(1 + (Δr / |b − a|)²) per unit at most (its gradient is the unit offset plus
    // the taper along the axis; balls and the smooth minimum, a blend of its terms' gradients, add
    // no more). The dense ABOP plants have tapers of up to 1.6 near their bases (a factor 0.52),
    // most branches below 0.05 (0.999).
    double alongRay(const Vec3& p, const Vec3& u, Ray& ray) const {
        ray.along.clear();
        const double u2 = u.squaredNorm();
        double steepest = 0.0;
        for (const JunctionShape::Bound& bound : ray.order) {
            const JunctionShape::Capsule& c = shape_.capsules[bound.capsule];
            const Vec3 w = p - c.a;
            const Vec3& ab = c.ab;
            const double length2 = c.length2;
            const Ray::Along& along = ray.along.emplace_back(
                Ray::Along{w.squaredNorm(), 2.0 * w.dot(u), u2, w.dot(ab), u.dot(ab), length2,
                           c.inverse2, c.ra, c.rb - c.ra, bound.distance});
            steepest = std::max(steepest, along.dr * along.dr * along.inverse2);
        }
        return 1.0 / std::sqrt(1.0 + steepest);
    }
    // shape_.distance(p + s·u, ray.order) for the ray of alongRay, up to rounding: the offset from
    // the nearest axis point squared is |x − a|² − 2t (x − a)·(b − a) + t² |b − a|².
    double distanceAlong(double s, const Ray& ray) const {
        SmoothUnion sum{shape_.fillet};
        for (const Ray::Along& c : ray.along) {
            if (c.bound >= sum.plain + sum.fillet) break;
            const double e = c.e0 + c.e1 * s;
            const double t = std::clamp(e * c.inverse2, 0.0, 1.0);
            const double offset2 = c.q0 + s * (c.q1 + s * c.q2) - t * (2.0 * e - t * c.length2);
            sum.fold(std::sqrt(std::max(offset2, 0.0)) - (c.ra + t * c.dr));
        }
        return sum.d;
    }

    // owner_[i]: the first new vertex at new vertex i's hull position (seam copies).
    void findSeamCopies() {
        owner_.resize(onHull_.size());
        std::unordered_map<std::uint64_t, std::uint32_t> first;
        for (std::size_t i = 0; i < onHull_.size(); ++i) {
            const Vec3f p = onHull_[i].cast<float>();
            const auto [it, fresh] = first.emplace(positionHash(p), static_cast<std::uint32_t>(i));
            const bool same = !fresh && onHull_[it->second].cast<float>() == p;
            owner_[i] = same ? it->second : static_cast<std::uint32_t>(i);
        }
    }

    // Triangle f faces away from the centre, by more than rounding. Moves along the rays keep
    // the sign of (b − a) × (c − a) · (a − centre) (the triple product of the corners' rays
    // times their positive lengths), so a triangle fails only by turning nearly edge-on to
    // them: a steep wall of a surface pulled deep into a crotch. The margin (the sine of the
    // angle between the triangle and the ray to its corner) was 1e-3 until session 22, which
    // halved such walls' moves (fig3_2_ring: 1.33 radii off the tubes, 0.48 at 1e-5; ABOP 1.31a
    // 3.4 → 1.4); computed in double from the float corners the mesh keeps, it is exact to
    // about 1e-15, and below 1e-5 1.24a's silhouette got a little worse (0.51 → 0.70 radii).
    bool facesAway(std::size_t f) const {
        const std::array<std::uint32_t, 3> v = face(f);
        return facesAway({position(v[0]), position(v[1]), position(v[2])});
    }
    bool facesAway(const std::array<Vec3, 3>& p) const {
        const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
        return normal.dot(p[0] - centre_) > kEdgeOn * normal.norm() * (p[0] - centre_).norm();
    }
    // The triangle whose cone from the centre holds q, or kNone.
    // The faces of one hull face's subdivision cover it, so their cones from the centre
    // divide its cone: only those of the hull face whose cone holds q are searched.
    std::size_t faceAbove(const Vec3& q) const {
        for (const HullFace& hull : hullFaces_) {
            if (!inCone(hull.corners, q)) continue;
            for (std::size_t f = hull.begin; f < hull.end; f += 3) {
                if (inCone(face(f), q)) return f;
            }
        }
        return kNone;
    }
    // q lies in the cone from the centre through the triangle with corners v.
    bool inCone(const std::array<std::uint32_t, 3>& v, const Vec3& q) const {
        const Vec3 d = q - centre_;
        const Vec3 a = position(v[0]) - centre_, b = position(v[1]) - centre_,
                   c = position(v[2]) - centre_;
        return d.dot(a.cross(b)) >= 0.0 && d.dot(b.cross(c)) >= 0.0 && d.dot(c.cross(a)) >= 0.0;
    }
    // q lies on the centre's side of triangle f's plane.
    bool below(std::size_t f, const Vec3& q) const {
        const std::array<std::uint32_t, 3> v = face(f);
        return below({position(v[0]), position(v[1]), position(v[2])}, q);
    }
    static bool below(const std::array<Vec3, 3>& p, const Vec3& q) {
        return (p[1] - p[0]).cross(p[2] - p[0]).dot(q - p[0]) < 0.0;
    }
    // Shortens the moves of triangle f's new vertices by the one factor (a bisection to 1/64)
    // that lets `passes` hold of its corners as floats, the moves as they stand this round
    // (zeroes them after kShorteningRounds); returns whether any was still moved.
    template <class Passes>
    bool shortenMoves(std::size_t f, int round, Passes passes) {
        const std::array<std::uint32_t, 3> v = face(f);
        auto corners = [&](double t) {
            std::array<Vec3, 3> p;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t u = v[static_cast<std::size_t>(k)];
                if (u < firstNew_) {
                    p[static_cast<std::size_t>(k)] = position(u);
                    continue;
                }
                const std::size_t i = u - firstNew_;
                const double share = t * share_[owner_[i]];
                p[static_cast<std::size_t>(k)] =
                    (onHull_[i] + share * (target_[i] - onHull_[i])).cast<float>().cast<double>();
            }
            return p;
        };
        double keep = 0.0;
        if (round < kShorteningRounds) {
            if (passes(corners(1.0))) return false;  // shortened enough by another triangle
            double lo = 0.0, hi = 1.0;
            for (int k = 0; k < 6; ++k) {
                const double mid = 0.5 * (lo + hi);
                (passes(corners(mid)) ? lo : hi) = mid;
            }
            keep = lo;
        }
        bool any = false;
        for (const std::uint32_t u : v) {
            if (u < firstNew_) continue;
            double& share = share_[owner_[u - firstNew_]];
            if (share == 0.0) continue;
            share *= keep;
            any = true;
        }
        return any;
    }
    // ray.order: the capsules that can matter to the distance at points of the segment [a, b],
    // each with a bound (the distance from the segment to its bounding sphere, below the
    // distance to its surface from any point of the segment), nearest first. From any point x
    // of the segment the capsule surface nearest the centre lies at most centreDistance_ +
    // |x − centre| away, and capsules bound a fillet beyond that change nothing.
    void orderFor(const Vec3& a, const Vec3& b, Ray& ray) const {
        const double farthest = std::max((a - centre_).norm(), (b - centre_).norm());
        const double beyond = centreDistance_ + farthest + shape_.fillet;
        const Vec3 ab = b - a;
        const double length2 = ab.squaredNorm();
        const double inverse2 = length2 > 0.0 ? 1.0 / length2 : 0.0;
        std::vector<JunctionShape::Bound>& order = ray.order;
        order.clear();
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            const Vec3 middle = spheres_[i].head<3>();
            const double reach = beyond + spheres_[i].w();
            const double t = std::clamp((middle - a).dot(ab) * inverse2, 0.0, 1.0);
            const double apart2 = (middle - a - t * ab).squaredNorm();
            if (reach <= 0.0 || apart2 >= reach * reach) continue;
            order.push_back({std::sqrt(apart2) - spheres_[i].w(), static_cast<std::uint32_t>(i)});
        }
        std::sort(order.begin(), order.end());
    }

    struct HullFace {
        std::array<std::uint32_t, 3> corners;
        std::size_t begin, end;  // its faces in the index buffer once subdivided
    };
    struct SplitEdge {
        std::uint32_t first;  // of its m − 1 vertices, counted from `from`
        std::uint32_t from;
    };
    Mesh& mesh_;
    WindAttributes* wind_;
    const JunctionShape& shape_;
    Vec3 centre_;
    double centreDistance_ = 0.0;  // from the centre to the nearest capsule's surface
    std::size_t first_;
    int m_ = 2;
    std::uint32_t firstNew_ = 0;
    std::unordered_set<std::uint64_t> split_;  // edges to split, by canonical corner ids
    std::unordered_map<std::uint64_t, std::uint32_t> corners_;  // position hash → corner
    std::unordered_map<std::uint64_t, SplitEdge> edges_;
    std::vector<Vec3> onHull_;        // per new vertex: its position on the hull
    std::vector<Vec3> target_;        // per new vertex: where it rests on the branches
    std::vector<Vec3> targetNormal_;  // per new vertex: the surface's gradient there, or zero
    std::vector<std::uint32_t> owner_;
    std::vector<double> share_;  // per owner: the fraction of its move made
    std::vector<std::uint32_t> grid_;
    CoreTeam& team_;
    std::vector<double> excess_;                   // per face, for excess()
    std::vector<Ray> rays_ = std::vector<Ray>(1);  // per worker thread
    std::vector<HullFace> hullFaces_;
    std::vector<Vec4> spheres_;  // per capsule: around its axis' midpoint, holding it
};

// Signed distance of `p` to the junction's branches (tapered capsules), smoothed by the
// fillet: negative inside.
double JunctionShape::distance(const Vec3& p, Vec3* gradient) const {
    SmoothUnionAt sum{p, gradient != nullptr, {fillet}};
    for (const Capsule& c : capsules) sum.add(c);
    return sum.result(gradient);
}

double JunctionShape::plainDistance(const Vec3& p) const {
    SmoothUnionAt sum{p, false, {fillet}};
    for (const Capsule& c : capsules) sum.add(c);
    return sum.sum.plain;
}

// A capsule whose surface lies at least a fillet beyond the nearest one's so far (d is at most
// that) has h = 0: d and the gradient stay; so has every capsule after it in the order.
double JunctionShape::distance(const Vec3& p, std::span<const Bound> order, Vec3* gradient) const {
    SmoothUnionAt sum{p, gradient != nullptr, {fillet}};
    for (const Bound& bound : order) {
        if (bound.distance >= sum.sum.plain + fillet) break;
        sum.add(capsules[bound.capsule]);
    }
    return sum.result(gradient);
}

// The junction's own branches (its arms' and absorbed limbs' segments within reach of its hull,
// the faces from `firstIndex`) as capsules, and its thinnest arm: `centre` receives the mean of
// the faces' corners (strictly inside a convex hull), `reach` the largest distance of a corner
// from it. False where there is nothing to judge by.
bool JunctionMesher::gatherOwnShape(std::size_t firstIndex, Vec3& centre, double& reach) {
    if (mesh_.indices.size() == firstIndex) return false;
    centre = Vec3::Zero();
    for (std::size_t i = firstIndex; i < mesh_.indices.size(); ++i) {
        centre += mesh_.positions[mesh_.indices[i]].cast<double>();
    }
    centre /= static_cast<double>(mesh_.indices.size() - firstIndex);
    reach = 0.0;
    for (std::size_t i = firstIndex; i < mesh_.indices.size(); ++i) {
        reach = std::max(reach, (mesh_.positions[mesh_.indices[i]].cast<double>() - centre).norm());
    }
    const WeldSkeleton& s = skeleton_;
    shape_.capsules.clear();
    shape_.thinnest = std::numeric_limits<double>::infinity();
    std::int32_t last = -1;
    for (const HullRing& h : hullRings_) {
        if (h.hole()) shape_.thinnest = std::min(shape_.thinnest, h.ring.radius);
        if (h.limb == last) continue;  // a limb's rings are listed together
        last = h.limb;
        const WeldLimb& limb = s.limbs[static_cast<std::size_t>(h.limb)];
        for (std::uint32_t p = limb.first; p + 1 < limb.first + limb.count; ++p) {
            addSegmentInReach(p, centre, reach);
        }
    }
    shape_.fillet = kFillet * shape_.thinnest;
    return !shape_.capsules.empty() && shape_.thinnest > 0.0;
}

// With the solid union and convex junctions (the retry where the shrunk ones do not unite
// cleanly): whether the hull's faces from `firstIndex` lie more than kUnionWebLimit local radii
// outside the junction's own branches; such junctions are tubes there too.
bool JunctionMesher::hullWebbed(std::size_t firstIndex) {
    Vec3 centre;
    double reach = 0.0;
    if (!gatherOwnShape(firstIndex, centre, reach)) return false;
    return JunctionRefiner(mesh_, nullptr, shape_, firstIndex, team_).websLeft(kUnionWebLimit);
}

// The branches within reach of the junction's hull (centre `centre`, radius `reach`): its arms
// and absorbed limbs, and any other branch that passes through it (a crossing in the
// skeleton; the shrunk surface must keep it inside, as the hull did), as tapered capsules.
bool JunctionMesher::gatherJunctionShape(const Vec3& centre, double reach) {
    shape_.capsules.clear();
    std::size_t candidates = 0;
    return segments_.get().near(centre, reach, segmentMarks_, [&](std::uint32_t p) {
        addSegmentInReach(p, centre, reach);
        return shape_.capsules.size() <= kMaxCapsules && ++candidates <= kMaxCandidates;
    });
}

// Adds the segment from limb point p to p + 1 to the shape if its capsule comes within
// `reach` of `centre`.
void JunctionMesher::addSegmentInReach(std::uint32_t p, const Vec3& centre, double reach) {
    const WeldSkeleton& s = skeleton_;
    const JunctionShape::Capsule capsule{s.pointPosition[p], s.pointPosition[p + 1],
                                         s.pointRadius[p], s.pointRadius[p + 1]};
    const JunctionShape::Capsule::Point q = capsule.nearest(centre);
    if (q.offset.norm() - q.radius <= reach) shape_.capsules.push_back(capsule);
}

// Whether `p` lies more than `limit` local radii outside the plain union of the capsules: of the
// thickest capsule whose surface is within the nearest one's radius of the nearest distance (so a
// face bridging a thin branch's ring to its thick parent's, an ordinary crotch, is judged by the
// parent's radius; a web between twigs far from any thick branch by the twigs').
bool JunctionShape::farOutside(const Vec3& p, double limit) const {
    double best = std::numeric_limits<double>::infinity();
    double nearest = thinnest;
    auto surface = [&](const Capsule& c, double& radius) {
        const Capsule::Point q = c.nearest(p);
        radius = q.radius;
        return q.offset.norm() - q.radius;
    };
    for (const Capsule& c : capsules) {
        double r = 0.0;
        const double d = surface(c, r);
        if (d < best) {
            best = d;
            nearest = r;
        }
    }
    if (best <= limit * nearest) return false;  // the local radius is at least the nearest's
    double scale = nearest;
    for (const Capsule& c : capsules) {
        double r = 0.0;
        if (surface(c, r) <= best + nearest) scale = std::max(scale, r);
    }
    return best > limit * scale;
}

// Whether mesh vertices a and b are neighbours on one arm's ring (an edge the arm's tube
// shares: it must stay whole).
bool JunctionMesher::onArmRingEdge(std::uint32_t a, std::uint32_t b) const {
    for (const HullRing& h : hullRings_) {
        if (!h.hole()) continue;
        const std::uint32_t base = h.ring.base;
        const auto n = static_cast<std::uint32_t>(h.ring.n);
        if (a < base || a > base + n || b < base || b > base + n) continue;
        const std::uint32_t i = (a - base) % n, j = (b - base) % n;
        return (i + 1) % n == j || (j + 1) % n == i;
    }
    return false;
}

// A junction over several branch nodes (a crotch of merged nodes, a cluster of tips) need
// not be star-shaped from its first centre; where moves had to be halved, the branch nodes of
// its arms that lie well inside the hull are tried as centres too (at most kMaxCentres in all,
// two where more than kMaxThirdCentreCapsules segments are in reach), and the one that leaves
// the least of the surface outside the branches is kept.
// With many segments in reach (each try runs over all of them) only where the faces around the
// halved moves leave much outside.
void JunctionMesher::tryMoreCentres(JunctionRefiner& refiner, const Vec3& first,
                                    const std::vector<Vec3>& samples) {
    const std::size_t segments = shape_.capsules.size();
    if (segments > kMaxExcessCentreCapsules) return;
    const double thinnest = shape_.thinnest;
    if (segments > kMaxCentreCapsules &&
        refiner.excess(true) < kLargeExcess * thinnest * thinnest * thinnest) {
        return;
    }
    double least = refiner.excess();
    std::vector<Vec3> tried{first};
    JunctionRefiner::Shrunk best = refiner.shrunk();
    bool lastIsBest = true;
    const std::size_t centres = segments <= kMaxThirdCentreCapsules ? kMaxCentres : 2;
    for (const HullRing& h : hullRings_) {
        if (tried.size() == centres) break;
        if (!h.hole() ||
            std::any_of(tried.begin(), tried.end(),
                        [&](const Vec3& t) { return (t - h.node).norm() < thinnest; }) ||
            depthInHull(h.node) < kCentreDepth * thinnest) {
            continue;
        }
        tried.push_back(h.node);
        refiner.shrink(h.node, samples);
        const double excess = refiner.excess();
        lastIsBest = excess < least;
        if (lastIsBest) {
            least = excess;
            best = refiner.shrunk();
        }
    }
    if (!lastIsBest) refiner.restore(std::move(best));
}

// Returns whether, with `judgeWebs`, faces of the shrunk junction still lie more than
// kUnionWebLimit local radii outside the branches. Junctions at a crossing (a limb between two
// of them too short for both rings, which pass each other) are shrunk too: their hulls overlap and
// cut through each other whether shrunk or not, along curves of about the same length
// (conifer: 58.3 units as hulls, 59.2 shrunk), and as hulls they bulge far out (conifer: a bump
// of 11.8 twig radii beside the trunk, 0.26 shrunk).
bool JunctionMesher::refineJunction(std::size_t firstIndex, bool judgeWebs) {
    Vec3 centre;
    double reach = 0.0;
    // Webs are judged against the junction's own branches alone (few capsules: most junctions
    // have none, and this is all they cost); the shrinking then takes every branch in reach.
    if (!gatherOwnShape(firstIndex, centre, reach)) return false;
    JunctionRefiner refiner(mesh_, params_.tube.windAttributes ? &windOut_ : nullptr, shape_,
                            firstIndex, team_);
    if (!refiner.markWebs([&](std::uint32_t a, std::uint32_t b) { return onArmRingEdge(a, b); }) ||
        !gatherJunctionShape(centre, reach)) {
        return false;
    }
    // Points along the branches' axes inside the hull: they must stay inside.
    std::vector<Vec3> samples;
    // The rays run to a centre inside the branches. Where the corners' mean lies in the air
    // between them (a crotch of several merged branch nodes), the rays from the webs over it
    // met no branch before it and their vertices stayed on the hull (hedge_1: 429 of 833 new
    // vertices, the junction 4.3 twig radii beside the tubes in the silhouette); there the
    // axis point nearest the mean that lies well inside the hull is the centre. Inside the
    // branches themselves, not only inside the surface the vertices move to (5 % of the thinnest
    // radius beyond them, kSurfaceOffset), as until session 43: from a mean in that thin shell
    // the rays towards the near side met the surface at once, and their vertices crowded into a
    // pinch (a random plant: 198 positions within 0.002 of one point, 5 % of a twig's radius,
    // whose union cut them into 90 k pieces meeting there and ran for minutes; five junctions of
    // the shipped examples took their centres there too).
    const bool centreInside = shape_.distance(centre) <= 0.0;
    Vec3 rayCentre = centre;
    double nearest = std::numeric_limits<double>::infinity();
    for (const JunctionShape::Capsule& capsule : shape_.capsules) {
        const double length = std::sqrt(capsule.length2);
        const double spacing = 0.5 * std::min(capsule.ra, capsule.rb);
        const int pieces = std::clamp(static_cast<int>(std::ceil(length / spacing)), 1, 16);
        for (int k = 0; k <= pieces; ++k) {
            const Vec3 q = capsule.a + (static_cast<double>(k) / pieces) * capsule.ab;
            const double depth = depthInHull(q);
            if (depth > 0.0) samples.push_back(q);
            if (!centreInside && depth >= kCentreDepth * shape_.thinnest &&
                (q - centre).norm() < nearest) {
                nearest = (q - centre).norm();
                rayCentre = q;
            }
        }
    }
    refiner.subdivide();
    refiner.shrink(rayCentre, samples);
    ++report_.refinedJunctions;
    if (!refiner.allMoved()) tryMoreCentres(refiner, rayCentre, samples);
    refiner.setNormals();
    return judgeWebs && refiner.websLeft(kUnionWebLimit);
}

}  // namespace ramus::detail
