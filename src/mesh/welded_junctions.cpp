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
    std::vector<double> step_;
};

JunctionSolver::JunctionSolver(const WeldSkeleton& skeleton, double margin)
    : s_(skeleton), margin_(margin) {
    const std::size_t n = skeleton.rep.size();
    out_.cluster.assign(n, -1);
    out_.nextMember.assign(n, -1);
    out_.startOffset.assign(skeleton.limbs.size(), 0.0);
    out_.endOffset.assign(skeleton.limbs.size(), 0.0);
    out_.absorbed.assign(skeleton.limbs.size(), 0);
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

double JunctionSolver::gap(std::int32_t limb) const {
    const WeldLimb& l = s_.limbs[static_cast<std::size_t>(limb)];
    return 0.02 * (s_.pointRadius[l.first] + s_.pointRadius[l.first + l.count - 1]);
}

// Moves the rings out until every ring plane has all other rings behind it (see the file
// comment). Returns the arm whose limb is too short for its ring, or -1 when all fit.
std::int32_t JunctionSolver::placeRings(bool clamp) {
    std::vector<double>& step = step_;
    step.assign(arms_.size(), 0.0);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        for (Arm& arm : arms_) {
            const WeldLimb& l = s_.limbs[static_cast<std::size_t>(arm.limb)];
            arm.place = ringOnLimb(s_, l, arm.atEnd, arm.t);
        }
        bool moved = false;
        for (std::size_t i = 0; i < arms_.size(); ++i) {
            const RingPlace& p = arms_[i].place;
            double worst = -1e300;
            double worstCos = 0.0;
            // Clearance margin × the smaller radius: a thin twig's ring may come as close to
            // a thick limb's ring as its own size allows, which keeps the joint tight.
            auto consider = [&](const Vec3& c, const Vec3& n, double r, bool isArm) {
                const double cosine = p.normal.dot(n);
                const double front = (c - p.center).dot(p.normal) +
                                     r * std::sqrt(std::max(0.0, 1.0 - cosine * cosine)) +
                                     margin_ * std::min(r, arms_[i].radius);
                if (front > worst) worst = front, worstCos = isArm ? cosine : 0.0;
            };
            for (std::size_t j = 0; j < arms_.size(); ++j) {
                if (j != i)
                    consider(arms_[j].place.center, arms_[j].place.normal, arms_[j].place.radius,
                             true);
            }
            for (const Disc& d : discs_) consider(d.center, d.normal, d.radius, false);
            const double tolerance = 1e-9 * arms_[i].radius;
            // Plain steps first (no overshoot); the accelerated step only for slow pairs.
            const double divisor = iteration < 24 ? 1.0 : std::max(1.0 - worstCos, 0.25);
            step[i] = worst > tolerance ? worst / divisor : 0.0;
            moved = moved || step[i] > 0.0;
        }
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
                ++out_.crossings;  // the limb's two rings pass each other: a local overlap
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
    // Final clusters: roots in id order; every member points at its root.
    for (std::size_t i = 0; i < parent_.size(); ++i) {
        if (parent_[i] == kNoNode) continue;
        const NodeId root = find(static_cast<NodeId>(i));
        out_.cluster[i] = root;
        if (root == static_cast<NodeId>(i)) out_.junctions.push_back(root);
    }
    return std::move(out_);
}

}  // namespace

WeldJunctions solveWeldJunctions(const WeldSkeleton& skeleton, double margin) {
    return JunctionSolver(skeleton, margin).solve();
}

}  // namespace ramus::detail
