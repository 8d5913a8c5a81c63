// Ring placement at the junctions of the welded mesher.
//
// Based on: Bærentzen, Misztal, Wełnicka 2012, "Converting skeletal structures to quad
// dominant meshes" (branch nodes joined through the convex hull of their arms); the placement
// rule below is ours.
//
// The convex hull of the rings meeting at a junction has every ring as a face exactly when
// each ring's plane has all other rings strictly behind it. For ring i (centre c_i, outward
// unit normal n_i) and a ring j (c_j, n_j, radius r_j) the farthest point of j in front of
// plane i is (c_j − c_i)·n_i + r_j·√(1 − (n_i·n_j)²). Each ring moves out along its limb until
// that is below −margin·min(r_i, r_j) for every other ring. Two straight arms at angle θ settle at
// t(1 − cos θ) ≈ r sin θ, so the step divides the violation by (1 − cos θ) of the worst
// partner: one step solves a symmetric pair. When a limb is too short for the rings of both
// its ends, its two junctions become one (its rings join the hull as plain points); an end
// limb too short for its junction's ring is taken into the junction whole.
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "ramus/math.hpp"
#include "welded_skeleton.hpp"

namespace ramus::detail {
namespace {

constexpr int kMaxIterations = 240;
// Junction size limits: dense thick branching (radii far above the internode length) would
// otherwise merge whole trees into one hull, in quadratic time. At 8 / 96 the conifer
// example's base junction filled up with rings that did not fit (its hull check failed);
// 16 / 256 settles it and costs the synthetic binary tree about a quarter of its speed
// (bench/welded_bench.cpp).
constexpr std::uint32_t kMaxMembers = 16;
constexpr std::uint32_t kMaxDiscs = 256;
// Directions tried for the plane of a ring shared by two junctions (shareCrossingRings): tilted
// from the limb by kSharedTiltStep degrees at a time up to kMaxSharedTilt, kSharedTurns around.
// Measured on conifer's crossing: parted at 10° by 0.185 of the limb's radius.
constexpr double kSharedTiltStep = 5.0;
constexpr double kMaxSharedTilt = 60.0;
constexpr int kSharedTurns = 36;

struct Arm {
    std::int32_t limb;
    bool atEnd;  // the junction is the limb's end key
    double t;
    double radius;  // at the junction end of the limb
    RingPlace place;
};

struct Disc {
    Vec3 center;
    Vec3 normal;
    double radius;
};

class JunctionSolver {
public:
    JunctionSolver(const WeldSkeleton& skeleton, double margin);
    WeldJunctions solve();

private:
    NodeId find(NodeId node);
    NodeId unite(NodeId a, NodeId b);
    void gather(NodeId cluster);
    std::int32_t placeRings(bool clamp);  // returns the arm that does not fit, or -1
    bool canJoin(NodeId cluster, NodeId other, std::int32_t limb) const;
    void settle(NodeId cluster);
    double gap(std::int32_t limb) const;
    bool fitsBothEnds(std::int32_t limb) const;

    const WeldSkeleton& s_;
    double margin_;
    WeldJunctions out_;
    std::vector<NodeId> parent_;              // union-find over nodes of junctions
    std::vector<NodeId> tail_;                // per cluster root: last member
    std::vector<std::uint32_t> members_;      // per cluster root: member nodes
    std::vector<std::uint32_t> discs_count_;  // per cluster root: points of absorbed limbs
    std::vector<std::uint8_t> solved_;
    std::vector<Arm> arms_;
    std::vector<Disc> discs_;
    std::vector<Disc> bends_;               // inner points of the arms' limbs before their rings
    std::vector<std::uint32_t> bendOwner_;  // per bend: its arm
    struct Front {
        double front;
        double cosine;
        std::int32_t partner;  // the arm whose ring it is, or -1
    };
    Front worstFront(std::size_t arm) const;
    double pairStep(std::size_t arm) const;
    double straightAhead(const Arm& arm) const;
    std::vector<Front> fronts_;
    std::vector<double> step_;
    // Limbs found too short for both rings, once for every time they were (the candidates of
    // shareCrossingRings; the crossings are counted once every junction is placed).
    std::vector<std::int32_t> crossingLimbs_;
    void markCrossings();
    void shareCrossingRings();
    std::vector<Disc> junctionDiscs(NodeId cluster, std::int32_t without);
    bool separatingPlane(const std::vector<Disc>& from, const std::vector<Disc>& to,
                         const Vec3& axis, double clearance, Vec3& normal, double& offset) const;
};

JunctionSolver::JunctionSolver(const WeldSkeleton& skeleton, double margin)
    : s_(skeleton), margin_(margin) {
    const std::size_t n = skeleton.rep.size();
    out_.cluster.assign(n, -1);
    out_.nextMember.assign(n, -1);
    out_.startOffset.assign(skeleton.limbs.size(), 0.0);
    out_.endOffset.assign(skeleton.limbs.size(), 0.0);
    out_.absorbed.assign(skeleton.limbs.size(), 0);
    out_.sharedNormal.assign(skeleton.limbs.size(), Vec3::Zero());
    out_.sharedOffset.assign(skeleton.limbs.size(), 0.0);
    parent_.assign(n, kNoNode);
    tail_.assign(n, kNoNode);
    solved_.assign(n, 0);
    members_.assign(n, 1);
    discs_count_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (skeleton.key[i] && skeleton.degree[i] >= 2) {
            parent_[i] = static_cast<NodeId>(i);
            tail_[i] = static_cast<NodeId>(i);
        }
    }
}

NodeId JunctionSolver::find(NodeId node) {
    NodeId root = node;
    while (parent_[static_cast<std::size_t>(root)] != root) root = parent_[root];
    while (parent_[static_cast<std::size_t>(node)] != root) {
        const NodeId next = parent_[static_cast<std::size_t>(node)];
        parent_[static_cast<std::size_t>(node)] = root;
        node = next;
    }
    return root;
}

// Joins two clusters (or a cluster and a lone tip node); the smaller id stays the root, so the
// result does not depend on the order of the merges. Member lists are concatenated.
NodeId JunctionSolver::unite(NodeId a, NodeId b) {
    if (parent_[static_cast<std::size_t>(b)] == kNoNode) {  // a lone key node joins
        parent_[static_cast<std::size_t>(b)] = b;
        tail_[static_cast<std::size_t>(b)] = b;
    }
    a = find(a);
    b = find(b);
    if (b < a) std::swap(a, b);
    parent_[static_cast<std::size_t>(b)] = a;
    out_.nextMember[static_cast<std::size_t>(tail_[a])] = b;
    members_[static_cast<std::size_t>(a)] += members_[static_cast<std::size_t>(b)];
    discs_count_[static_cast<std::size_t>(a)] += discs_count_[static_cast<std::size_t>(b)];
    tail_[static_cast<std::size_t>(a)] = tail_[static_cast<std::size_t>(b)];
    solved_[static_cast<std::size_t>(a)] = 0;
    return a;
}

// Arms (limbs leaving the cluster) with their current offsets, and discs of absorbed limbs.
void JunctionSolver::gather(NodeId cluster) {
    arms_.clear();
    discs_.clear();
    auto visit = [&](std::int32_t limb, NodeId member) {
        const WeldLimb& l = s_.limbs[static_cast<std::size_t>(limb)];
        const bool atEnd = l.endKey == member;
        if (out_.absorbed[static_cast<std::size_t>(limb)]) {
            if (atEnd && parent_[static_cast<std::size_t>(l.startKey)] != kNoNode) return;
            for (std::uint32_t k = 0; k < l.count; ++k) {
                discs_.push_back({s_.pointPosition[l.first + k], pointDirection(s_, l, k),
                                  s_.pointRadius[l.first + k]});
            }
            return;
        }
        const double start = s_.pointRadius[atEnd ? l.first + l.count - 1 : l.first];
        // Every solve starts from the same base offset, so the result does not depend on
        // the order in which junctions were merged.
        arms_.push_back({limb, atEnd, margin_ * start, start, {}});
    };
    for (NodeId m = cluster; m != kNoNode; m = out_.nextMember[static_cast<std::size_t>(m)]) {
        const auto i = static_cast<std::size_t>(m);
        if (s_.inLimb[i] >= 0) visit(s_.inLimb[i], m);
        for (std::uint32_t k = 0; k < s_.outCount[i]; ++k) visit(s_.firstOut[i] + k, m);
    }
}

// How far the farthest point of another ring (arms, discs of absorbed limbs, points before
// the other arms' rings) reaches in front of arm i's ring plane, clearance included; with the
// arm it belongs to and the cosine between the two rings' normals when it is an arm's ring.
JunctionSolver::Front JunctionSolver::worstFront(std::size_t i) const {
    const RingPlace& p = arms_[i].place;
    Front worst{-1e300, 0.0, -1};
    // Clearance margin × the smaller radius: a thin twig's ring may come as close to a thick
    // limb's ring as its own size allows, which keeps the joint tight.
    // A ring that could not reach past the worst so far even facing the plane edge-on (height
    // + radius bounds reachInFront from above, rounding included) is passed over before the
    // sine: the same worst front, and most rings and discs of a crowded cluster lie far behind
    // (session 45: with the limb directions computed once, WeldSkeleton::pointDirections, ABOP
    // 1.24c's ring placement, which runs on one core, 29.5 → 15 ms and 1.31a's 14.5 → 8.4 ms;
    // the same rings).
    auto consider = [&](const Disc& d, double clearance, std::int32_t arm) {
        const double room = clearance * std::min(d.radius, arms_[i].radius);
        const double height = heightOver(p, d.center);
        if (height + d.radius + room <= worst.front) return;
        const double front = reachInFront(p, height, d.normal, d.radius) + room;
        if (front > worst.front) worst = {front, arm >= 0 ? p.normal.dot(d.normal) : 0.0, arm};
    };
    for (std::size_t j = 0; j < arms_.size(); ++j) {
        const RingPlace& q = arms_[j].place;
        if (j != i) consider({q.center, q.normal, q.radius}, margin_, static_cast<std::int32_t>(j));
    }
    for (const Disc& d : discs_) consider(d, margin_, -1);
    // An arm's own points before its ring are behind it by construction
    // (forEachPointBeforeRing).
    for (std::size_t b = 0; b < bends_.size(); ++b) {
        if (bendOwner_[b] != i) consider(bends_[b], margin_, -1);
    }
    // But its ring at the branch node must be behind it too: a limb that runs back along its
    // parent and turns can put its ring's plane through the node, and the hull (even a ball
    // there, WeldBuilder::addNodeBalls) could not cover the node. On a straight limb this
    // holds from the start.
    const WeldLimb& l = s_.limbs[static_cast<std::size_t>(arms_[i].limb)];
    const std::uint32_t k = arms_[i].atEnd ? l.count - 1 : 0;
    consider({s_.pointPosition[l.first + k], pointDirection(s_, l, k), arms_[i].radius},
             kBeforeClearance * margin_, -1);
    return worst;
}

// The step of arm i: plain, its worst front (the ring moves just clear of the others as they
// stand, so the offsets grow towards the smallest solution from below and never pass it).
// Plain steps settle two rings at a small angle θ slowly, though: each step only swaps the
// pair's fronts, gaining front·(1 − cos θ). So two arm rings that are each other's worst
// partner step together by the exact solution of their two constraints on straight limbs,
// δ_i − c·δ_j = f_i and δ_j − c·δ_i = f_j (c = cos θ), unless that would move one of them
// back; both steps are scaled down alike so that neither ring passes the next point of its
// limb, where a bend would break that linear model (the plain step where that leaves less).
// (Accelerating each ring on its own, as this did before, made the two leapfrog each other ever
// farther out along their limbs: limbs absorbed and junctions merged that had room, in dense plants
// hundreds of them.)
double JunctionSolver::pairStep(std::size_t i) const {
    const Front& f = fronts_[i];
    const double tolerance = 1e-9 * arms_[i].radius;
    const double plain = f.front > tolerance ? f.front : 0.0;
    if (f.partner < 0) return plain;
    const auto j = static_cast<std::size_t>(f.partner);
    const Front& g = fronts_[j];
    if (g.partner != static_cast<std::int32_t>(i) || !(f.cosine > 0.0 && f.cosine < 1.0)) {
        return plain;
    }
    const double c = f.cosine;
    const double mine = (f.front + c * g.front) / (1.0 - c * c);
    const double theirs = (g.front + c * f.front) / (1.0 - c * c);
    if (!(mine > tolerance && theirs >= 0.0)) return plain;
    const double scale = std::min({1.0, straightAhead(arms_[i]) / mine,
                                   theirs > 0.0 ? straightAhead(arms_[j]) / theirs : 1.0});
    return std::max(plain, scale * mine);
}

// Arc length from the arm's ring to the end of the limb's edge it lies on, away from the
// junction (0 at a point of the limb: its normal is the edge's before the point, a step would
// take it onto the next edge).
double JunctionSolver::straightAhead(const Arm& arm) const {
    const WeldLimb& l = s_.limbs[static_cast<std::size_t>(arm.limb)];
    const double length = s_.limbLength(l);
    const double ringArc = arm.atEnd ? length - arm.t : arm.t;
    for (std::uint32_t i = 1; i < l.count; ++i) {
        const std::uint32_t k = arm.atEnd ? l.count - 1 - i : i;
        const double ahead =
            arm.atEnd ? ringArc - s_.pointArc[l.first + k] : s_.pointArc[l.first + k] - ringArc;
        if (ahead >= 0.0) return ahead;
    }
    return 0.0;
}

double JunctionSolver::gap(std::int32_t limb) const {
    const WeldLimb& l = s_.limbs[static_cast<std::size_t>(limb)];
    return 0.02 * (s_.pointRadius[l.first] + s_.pointRadius[l.first + l.count - 1]);
}

// Moves the rings out until every ring plane has all other rings behind it (see the file
// comment). Returns the arm whose limb is too short for its ring, or -1 when all fit.
std::int32_t JunctionSolver::placeRings(bool clamp) {
    std::vector<double>& step = step_;
    step.assign(arms_.size(), 0.0);
    fronts_.resize(arms_.size());
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        bends_.clear();
        bendOwner_.clear();
        for (std::size_t i = 0; i < arms_.size(); ++i) {
            Arm& arm = arms_[i];
            const WeldLimb& l = s_.limbs[static_cast<std::size_t>(arm.limb)];
            arm.place = ringOnLimb(s_, l, arm.atEnd, arm.t);
            forEachPointBeforeRing(s_, l, arm.atEnd, arm.t, arm.place, kBeforeClearance * margin_,
                                   [&](std::uint32_t k, const Vec3& normal) {
                                       bends_.push_back({s_.pointPosition[l.first + k], normal,
                                                         s_.pointRadius[l.first + k]});
                                       bendOwner_.push_back(static_cast<std::uint32_t>(i));
                                   });
        }
        bool moved = false;
        for (std::size_t i = 0; i < arms_.size(); ++i) {
            fronts_[i] = worstFront(i);
            moved = moved || fronts_[i].front > 1e-9 * arms_[i].radius;
        }
        for (std::size_t i = 0; i < arms_.size(); ++i) step[i] = pairStep(i);
        if (!moved) break;
        moved = false;  // now: did any ring actually move (rings at their limb's end stay)
        for (std::size_t i = 0; i < arms_.size(); ++i) {
            Arm& arm = arms_[i];
            const WeldLimb& l = s_.limbs[static_cast<std::size_t>(arm.limb)];
            const double room = s_.limbLength(l) - gap(arm.limb);
            if (arm.t + step[i] > room && !clamp) return static_cast<std::int32_t>(i);
            const double t = std::min(arm.t + step[i], room);
            moved = moved || t > arm.t;
            arm.t = t;
        }
        if (!moved) break;
        if (iteration + 1 == kMaxIterations && !clamp) {
            return static_cast<std::int32_t>(std::max_element(step.begin(), step.end()) -
                                             step.begin());
        }
    }
    return -1;
}

bool JunctionSolver::fitsBothEnds(std::int32_t limb) const {
    const auto i = static_cast<std::size_t>(limb);
    return out_.startOffset[i] + out_.endOffset[i] + gap(limb) <= s_.limbLength(s_.limbs[i]);
}

bool JunctionSolver::canJoin(NodeId cluster, NodeId other, std::int32_t limb) const {
    const auto c = static_cast<std::size_t>(cluster);
    const bool tip = parent_[static_cast<std::size_t>(other)] == kNoNode;
    const std::size_t o = tip ? 0 : static_cast<std::size_t>(other);
    const std::uint32_t members = members_[c] + (tip ? 1 : members_[o]);
    const std::uint32_t discs = discs_count_[c] + (tip ? 0 : discs_count_[o]) +
                                s_.limbs[static_cast<std::size_t>(limb)].count;
    return members <= kMaxMembers && discs <= kMaxDiscs;
}

void JunctionSolver::settle(NodeId cluster) {
    for (const Arm& arm : arms_) {
        const auto i = static_cast<std::size_t>(arm.limb);
        (arm.atEnd ? out_.endOffset[i] : out_.startOffset[i]) = arm.t;
    }
    solved_[static_cast<std::size_t>(cluster)] = 1;
}

// The rings, discs and branch nodes of junction `cluster` as the mesher's hull takes them, its
// arm rings where the solve left them, but for limb `without`'s: discs, the nodes as discs of
// radius 0 (so that a plane between two junctions' discs crosses the limb between them).
std::vector<Disc> JunctionSolver::junctionDiscs(NodeId cluster, std::int32_t without) {
    gather(cluster);
    std::vector<Disc> discs = discs_;
    for (const Arm& arm : arms_) {
        if (arm.limb == without) continue;
        const auto li = static_cast<std::size_t>(arm.limb);
        const WeldLimb& l = s_.limbs[li];
        const double t = arm.atEnd ? out_.endOffset[li] : out_.startOffset[li];
        const RingPlace ring = ringOnLimb(s_, l, arm.atEnd, t);
        discs.push_back({ring.center, ring.normal, ring.radius});
        forEachPointBeforeRing(s_, l, arm.atEnd, t, ring, kBeforeClearance * margin_,
                               [&](std::uint32_t k, const Vec3& normal) {
                                   discs.push_back({s_.pointPosition[l.first + k], normal,
                                                    s_.pointRadius[l.first + k]});
                               });
        discs.push_back(
            {s_.pointPosition[arm.atEnd ? l.first + l.count - 1 : l.first], ring.normal, 0.0});
    }
    return discs;
}

// A plane with every disc of `from` behind it and every disc of `to` in front, by `clearance`
// each: of the directions tilted from `axis` by 0°, 5°, … up to kMaxSharedTilt (36 around each),
// the least tilted that parts them so, and of those the one with the widest gap; the plane
// halfway across the gap. False if none does.
bool JunctionSolver::separatingPlane(const std::vector<Disc>& from, const std::vector<Disc>& to,
                                     const Vec3& axis, double clearance, Vec3& normal,
                                     double& offset) const {
    // The farthest a disc reaches along unit direction d: its centre's height plus its radius
    // times the sine between d and its normal.
    auto reach = [](const Disc& disc, const Vec3& d) {
        const double cosine = disc.normal.dot(d);
        return disc.radius * std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
    };
    const Vec3 e1 = axis.unitOrthogonal();
    const Vec3 e2 = axis.cross(e1);
    for (int tilt = 0; tilt * kSharedTiltStep <= kMaxSharedTilt; ++tilt) {
        const double theta = degToRad(tilt * kSharedTiltStep);
        double widest = 2.0 * clearance;
        const int turns = tilt == 0 ? 1 : kSharedTurns;
        for (int turn = 0; turn < turns; ++turn) {
            const double phi = 2.0 * kPi * turn / kSharedTurns;
            const Vec3 d = std::cos(theta) * axis +
                           std::sin(theta) * (std::cos(phi) * e1 + std::sin(phi) * e2);
            double back = -std::numeric_limits<double>::infinity();
            double front = std::numeric_limits<double>::infinity();
            for (const Disc& disc : from)
                back = std::max(back, disc.center.dot(d) + reach(disc, d));
            for (const Disc& disc : to)
                front = std::min(front, disc.center.dot(d) - reach(disc, d));
            if (front - back > widest) {
                widest = front - back;
                normal = d;
                offset = 0.5 * (back + front);
            }
        }
        if (widest > 2.0 * clearance) return true;
    }
    return false;
}

// A crossing limb (too short for a ring at each end, between two junctions too full to merge)
// whose junctions' rings a plane parts gets one ring in that plane, the section of its tube
// there, which both junctions take as their arm's ring: each hull then lies on its own side of
// the plane (a hull's face's plane has the whole hull behind it), so the two meet in that ring
// and nowhere else, where their rings passing each other had made them overlap. Only a straight
// limb (no inner points, whose rings would be hull points on either side) between junctions
// with no other crossing (another shared ring would be one of their rings too, which this
// plane has not parted). Run once every junction is placed.
void JunctionSolver::shareCrossingRings() {
    std::vector<std::uint32_t> crossingsAt(parent_.size(), 0);  // per cluster root: limbs
    std::vector<std::int32_t> limbs = crossingLimbs_;
    std::sort(limbs.begin(), limbs.end());
    limbs.erase(std::unique(limbs.begin(), limbs.end()), limbs.end());
    auto ends = [&](std::int32_t limb) {
        const WeldLimb& l = s_.limbs[static_cast<std::size_t>(limb)];
        return std::pair{find(l.startKey), find(l.endKey)};
    };
    for (const std::int32_t limb : limbs) {
        const auto [a, b] = ends(limb);
        ++crossingsAt[static_cast<std::size_t>(a)];
        if (b != a) ++crossingsAt[static_cast<std::size_t>(b)];
    }
    for (const std::int32_t limb : limbs) {
        const auto li = static_cast<std::size_t>(limb);
        const WeldLimb& l = s_.limbs[li];
        const auto [a, b] = ends(limb);
        if (a == b || l.count != 2 || crossingsAt[static_cast<std::size_t>(a)] != 1 ||
            crossingsAt[static_cast<std::size_t>(b)] != 1) {
            continue;
        }
        const Vec3& axis = pointDirection(s_, l, 0);  // the straight limb's direction
        const double clearance =
            margin_ * std::min(s_.pointRadius[l.first], s_.pointRadius[l.first + 1]);
        const std::vector<Disc> from = junctionDiscs(a, limb);
        const std::vector<Disc> to = junctionDiscs(b, limb);
        if (!separatingPlane(from, to, axis, clearance, out_.sharedNormal[li],
                             out_.sharedOffset[li])) {
            continue;
        }
        ++out_.sharedRings;
    }
}

// The crossings as the junctions end up: limbs between two junctions whose rings pass each
// other, without a shared ring. (Counted where found, a limb whose junction was placed again
// after a merge counted each time: ABOP 1.24b 112 for 105 limbs, 1.31a 63 for 58.)
void JunctionSolver::markCrossings() {
    out_.crossing.assign(s_.limbs.size(), 0);
    for (std::size_t l = 0; l < s_.limbs.size(); ++l) {
        const WeldLimb& limb = s_.limbs[l];
        const NodeId a = out_.cluster[static_cast<std::size_t>(limb.startKey)];
        const NodeId b = out_.cluster[static_cast<std::size_t>(limb.endKey)];
        if (out_.absorbed[l] != 0 || out_.sharedNormal[l] != Vec3::Zero() || a == kNoNode ||
            b == kNoNode || a == b || fitsBothEnds(static_cast<std::int32_t>(l))) {
            continue;
        }
        out_.crossing[l] = 1;
        ++out_.crossings;
    }
}

WeldJunctions JunctionSolver::solve() {
    std::deque<NodeId> queue;
    for (std::size_t i = 0; i < parent_.size(); ++i) {
        if (parent_[i] == static_cast<NodeId>(i)) queue.push_back(static_cast<NodeId>(i));
    }
    while (!queue.empty()) {
        const NodeId cluster = queue.front();
        queue.pop_front();
        if (find(cluster) != cluster || solved_[static_cast<std::size_t>(cluster)]) continue;
        gather(cluster);
        const std::int32_t failed = placeRings(false);
        if (failed >= 0) {
            // Too short: take the limb in, with the junction or tip at its other end.
            const Arm& arm = arms_[static_cast<std::size_t>(failed)];
            const WeldLimb& l = s_.limbs[static_cast<std::size_t>(arm.limb)];
            NodeId other = arm.atEnd ? l.startKey : l.endKey;
            if (parent_[static_cast<std::size_t>(other)] != kNoNode) other = find(other);
            if (canJoin(cluster, other, arm.limb)) {
                const bool tip = parent_[static_cast<std::size_t>(other)] == kNoNode;
                ++(tip ? out_.absorbedLimbs : out_.merges);
                out_.absorbed[static_cast<std::size_t>(arm.limb)] = 1;
                const NodeId joined = unite(cluster, other);
                discs_count_[static_cast<std::size_t>(joined)] += l.count;
                queue.push_back(joined);
                continue;
            }
            // Full: keep the rings within their limbs; the hull check decides (fallback).
            ++out_.crowded;
            gather(cluster);
            placeRings(true);
        }
        settle(cluster);
        // A neighbour already placed may leave too little of a shared limb: merge with it.
        for (const Arm& arm : arms_) {
            const WeldLimb& l = s_.limbs[static_cast<std::size_t>(arm.limb)];
            const NodeId other = arm.atEnd ? l.startKey : l.endKey;
            if (parent_[static_cast<std::size_t>(other)] == kNoNode) continue;
            const NodeId neighbour = find(other);
            if (!solved_[static_cast<std::size_t>(neighbour)] || fitsBothEnds(arm.limb)) continue;
            if (!canJoin(cluster, neighbour, arm.limb)) {
                crossingLimbs_.push_back(arm.limb);  // its two rings pass each other
                continue;
            }
            out_.absorbed[static_cast<std::size_t>(arm.limb)] = 1;
            ++out_.merges;
            const NodeId joined = unite(cluster, neighbour);
            discs_count_[static_cast<std::size_t>(joined)] += l.count;
            queue.push_back(joined);
            break;
        }
    }
    shareCrossingRings();
    // Final clusters: roots in id order; every member points at its root.
    for (std::size_t i = 0; i < parent_.size(); ++i) {
        if (parent_[i] == kNoNode) continue;
        const NodeId root = find(static_cast<NodeId>(i));
        out_.cluster[i] = root;
        if (root == static_cast<NodeId>(i)) out_.junctions.push_back(root);
    }
    markCrossings();
    return std::move(out_);
}

}  // namespace

WeldJunctions solveWeldJunctions(const WeldSkeleton& skeleton, double margin) {
    return JunctionSolver(skeleton, margin).solve();
}

}  // namespace ramus::detail
