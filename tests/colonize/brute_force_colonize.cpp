// Based on: seed 002 §3.3 and §3.5, Runions et al. 2007 §2 — each step recomputed from scratch.
#include "brute_force_colonize.hpp"

#include <algorithm>
#include <vector>

#include "../../src/colonize/growth_rules.hpp"

namespace ramus::testing {

using namespace colonize_detail;

namespace {

struct Node {
    Vec3 position;
    int parent = -1;
    std::uint32_t tree = 0, branchDepth = 0, childCount = 0;
    int lastGrowth = 0;
};

struct State {
    const ColonizeParams& params;
    std::span<const Shape> obstacles;
    std::vector<Vec3f> points;
    std::vector<bool> alive;
    std::vector<Node> nodes;
    std::vector<int> owner;
    std::vector<int> trunkTip;
    std::vector<bool> inTrunk;
    std::vector<long> trunkTarget;

    bool considered(int v, int iteration) const {
        return params.maxNoGrowth <= 0 ||
               iteration <= nodes[static_cast<std::size_t>(v)].lastGrowth + params.maxNoGrowth;
    }

    void addNode(int parent, const Vec3& position, std::uint32_t tree, int iteration) {
        Node n;
        n.position = position;
        n.parent = parent;
        n.tree = tree;
        n.lastGrowth = iteration;
        if (parent >= 0) {
            Node& p = nodes[static_cast<std::size_t>(parent)];
            n.branchDepth = childBranchDepth(p.branchDepth, p.childCount);
            ++p.childCount;
            p.lastGrowth = iteration;
        }
        nodes.push_back(n);
    }

    void killAround(const Vec3& c) {
        const double k2 = params.killRadius * params.killRadius;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (alive[i] && squaredDistance(points[i], c) < k2) alive[i] = false;
        }
    }

    // Step 1: nearest considered node within d_i (ties: lowest id); returns the count.
    std::size_t assign(int iteration) {
        const double i2 = params.influenceRadius * params.influenceRadius;
        std::size_t assigned = 0;
        owner.assign(points.size(), -1);
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!alive[i]) continue;
            double best = i2;
            for (std::size_t v = 0; v < nodes.size(); ++v) {
                if (!considered(static_cast<int>(v), iteration)) continue;
                const double d2 = squaredDistance(points[i], nodes[v].position);
                if (d2 < best) {
                    best = d2;
                    owner[i] = static_cast<int>(v);
                }
            }
            if (owner[i] >= 0) ++assigned;
        }
        return assigned;
    }

    long nearestAlive(const Vec3& c) const {
        long best = -1;
        double bestD2 = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double d2 = squaredDistance(points[i], c);
            if (alive[i] && (best < 0 || d2 < bestD2)) {
                best = static_cast<long>(i);
                bestD2 = d2;
            }
        }
        return best;
    }

    bool duplicate(const Vec3& p) const {
        const double s2 = minNodeSpacingSquared(params);
        return std::any_of(nodes.begin(), nodes.end(),
                           [&](const Node& n) { return squaredDistance(n.position, p) < s2; });
    }

    // Step 2 for node v; returns true when a child was added.
    bool grow(int v, int iteration) {
        const Node node = nodes[static_cast<std::size_t>(v)];
        const std::uint32_t t = node.tree;
        Vec3 direction = Vec3::Zero();
        bool attracted = false;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (owner[i] == v) {
                addUnitDirection(direction, points[i], node.position);
                attracted = true;
            }
        }
        if (attracted) {
            direction += params.tropism;
        } else if (inTrunk[t] && trunkTip[t] == v) {
            long& target = trunkTarget[t];
            if (target < 0 || !alive[static_cast<std::size_t>(target)]) {
                target = nearestAlive(node.position);
            }
            direction = points[static_cast<std::size_t>(target)].cast<double>() - node.position;
        } else {
            return false;
        }
        Vec3 child;
        if (!proposeChild(params, obstacles, node.position, node.branchDepth, node.childCount,
                          direction, child) ||
            duplicate(child)) {
            return false;
        }
        addNode(v, child, t, iteration);
        if (!attracted) trunkTip[t] = static_cast<int>(nodes.size()) - 1;
        return true;
    }
};

}  // namespace

ColonizeResult bruteForceColonize(const ColonizeParams& params, std::span<const Vec3> input,
                                  std::span<const Shape> obstacles) {
    validateColonizeParams(params);
    State s{params, obstacles, {}, {}, {}, {}, {}, {}, {}};
    for (const Vec3& p : input) {
        if (std::none_of(obstacles.begin(), obstacles.end(),
                         [&](const Shape& o) { return shapeContains(o, p); })) {
            s.points.push_back(p.cast<float>());
        }
    }
    s.alive.assign(s.points.size(), true);
    for (std::size_t t = 0; t < params.roots.size(); ++t) {
        s.addNode(-1, params.roots[t], static_cast<std::uint32_t>(t), 0);
        s.trunkTip.push_back(static_cast<int>(t));
    }
    s.inTrunk.assign(params.roots.size(), true);
    s.trunkTarget.assign(params.roots.size(), -1);
    for (const Node& root : std::vector<Node>(s.nodes)) s.killAround(root.position);

    const double i2 = params.influenceRadius * params.influenceRadius;
    int k = 0;
    for (;;) {
        const std::size_t aliveCount =
            static_cast<std::size_t>(std::count(s.alive.begin(), s.alive.end(), true));
        if (aliveCount == 0 || k >= params.maxIterations) break;
        const int iteration = k + 1;
        const std::size_t assigned = s.assign(iteration);
        bool trunkCanGrow = false;
        for (std::size_t t = 0; t < s.trunkTip.size(); ++t) {
            if (!s.inTrunk[t]) continue;
            const Vec3 tip = s.nodes[static_cast<std::size_t>(s.trunkTip[t])].position;
            for (std::size_t i = 0; i < s.points.size(); ++i) {
                if (s.alive[i] && squaredDistance(s.points[i], tip) < i2) s.inTrunk[t] = false;
            }
            if (s.inTrunk[t] && s.considered(s.trunkTip[t], iteration)) trunkCanGrow = true;
        }
        if (assigned == 0 && !trunkCanGrow) break;
        k = iteration;
        const std::size_t before = s.nodes.size();
        for (std::size_t v = 0; v < before; ++v) {
            if (s.considered(static_cast<int>(v), iteration))
                s.grow(static_cast<int>(v), iteration);
        }
        for (std::size_t n = before; n < s.nodes.size(); ++n) s.killAround(s.nodes[n].position);
        if (s.nodes.size() == before && params.maxNoGrowth <= 0) break;
    }

    ColonizeResult result;
    result.iterations = k;
    result.attractors = s.points.size();
    result.attractorsLeft =
        static_cast<std::size_t>(std::count(s.alive.begin(), s.alive.end(), true));
    result.trees.resize(params.roots.size());
    std::vector<NodeId> local(s.nodes.size());
    for (std::size_t n = 0; n < s.nodes.size(); ++n) {
        BranchTree& tree = result.trees[s.nodes[n].tree];
        local[n] = s.nodes[n].parent < 0
                       ? tree.addRoot(s.nodes[n].position)
                       : tree.addChild(local[static_cast<std::size_t>(s.nodes[n].parent)],
                                       s.nodes[n].position);
    }
    return result;
}

}  // namespace ramus::testing
