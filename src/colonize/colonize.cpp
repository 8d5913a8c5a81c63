// Based on: Runions, Lane, Prusinkiewicz, "Modeling Trees with a Space Colonization Algorithm"
// (2007) §2; seed 002 §3.3 (iteration), §3.5 (Z, max_grad, max_Z, max_NG, weighted growth),
// §5.2.3 (oscillation); SPEC §C.
//
// Speed: instead of searching every node for every point in every iteration, each point keeps
// its nearest node (time coherence). Only points near a new node can change it, and only nodes
// whose set of attracting points S(v) changed ("dirty") can grow differently from last time: a
// node with an unchanged S(v) would propose exactly the same child again, which then exists
// (or was refused for a reason that still holds). Points live in a static uniform grid sorted
// by cell; nodes in per-cell lists of the same grid. Each node keeps a linked list of its
// attracting points. The result is identical to the brute-force definition in colonize.hpp
// (tests/colonize/brute_force_colonize.cpp checks that node by node).
#include "ramus/colonize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "attractor_store.hpp"
#include "growth_rules.hpp"
#include "ramus/error.hpp"

namespace ramus {

using namespace colonize_detail;

namespace {

constexpr NodeId kNone = -1;
constexpr int kGridSubdivision = 2;  // cells of d_i / 2

class Colonizer {
public:
    /// Takes the coordinates of the points (rounded to float) in point index order.
    Colonizer(const ColonizeParams& params, std::vector<float> xs, std::vector<float> ys,
              std::vector<float> zs, std::span<const Shape> obstacles);
    int run();
    std::size_t aliveCount() const { return store_.aliveCount(); }
    /// Builds the trees; frees the points first (call once, after run()).
    std::vector<BranchTree> buildTrees();

private:
    NodeId addNode(NodeId parent, const Vec3& position, std::uint32_t tree, int iteration);
    void markChanged();
    void deactivateDue(int iteration);
    NodeId nearestActiveNode(std::uint32_t point, double& bestSquaredDistance) const;
    void updateTrunkPhases();
    bool anyTrunkCanGrow() const;
    Vec3 attractionSum(NodeId node);
    bool tryGrow(NodeId node, int iteration);
    bool isDuplicate(const Vec3& position) const;
    int nextEventIteration();

    const ColonizeParams& params_;
    std::span<const Shape> obstacles_;
    double influence2_, spacing2_;
    AttractorStore store_;
    // Nodes; nodes inside the grid are also in per-cell lists (cellHead_, cellNext_).
    std::vector<Vec3> nodePos_;
    std::vector<NodeId> parent_, cellNext_;
    std::vector<std::uint32_t> tree_, branchDepth_, childCount_;
    std::vector<int> lastGrowth_;
    std::vector<std::uint8_t> active_, dirty_;
    std::vector<std::int32_t> cellHead_;
    std::vector<NodeId> outside_;  // nodes outside the grid (too far from every point)
    // Nodes whose S(v) changed since their last growth attempt.
    std::vector<NodeId> changed_, dirtyList_, newNodes_;
    std::vector<std::pair<int, NodeId>> events_;  // (iteration, node): max_NG retirement
    std::size_t eventCursor_ = 0;
    // Trees: the trunk phase lasts until a point is within d_i of the trunk's tip.
    std::vector<NodeId> trunkTip_;
    std::vector<std::uint8_t> inTrunk_;
    std::vector<std::int64_t> trunkTarget_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> gather_;
};

Colonizer::Colonizer(const ColonizeParams& params, std::vector<float> xs, std::vector<float> ys,
                     std::vector<float> zs, std::span<const Shape> obstacles)
    : params_(params),
      obstacles_(obstacles),
      influence2_(params.influenceRadius * params.influenceRadius),
      spacing2_(minNodeSpacingSquared(params)),
      store_(std::move(xs), std::move(ys), std::move(zs), params.influenceRadius, params.killRadius,
             kGridSubdivision) {
    cellHead_.assign(store_.grid().cellCount(), kNone);
    const std::size_t roots = params.roots.size();
    for (std::size_t t = 0; t < roots; ++t) {
        addNode(kNone, params.roots[t], static_cast<std::uint32_t>(t), 0);
        trunkTip_.push_back(static_cast<NodeId>(t));
    }
    inTrunk_.assign(roots, 1);
    trunkTarget_.assign(roots, -1);
    // The roots remove the points they already reach, and attract the others.
    for (NodeId r = 0; r < static_cast<NodeId>(roots); ++r) {
        store_.removeAndClaimNear(r, nodePos_[static_cast<std::size_t>(r)], nodePos_, changed_);
    }
    markChanged();
}

NodeId Colonizer::addNode(NodeId parent, const Vec3& position, std::uint32_t tree, int iteration) {
    const auto id = static_cast<NodeId>(nodePos_.size());
    nodePos_.push_back(position);
    parent_.push_back(parent);
    store_.addNode();
    tree_.push_back(tree);
    childCount_.push_back(0);
    lastGrowth_.push_back(iteration);
    active_.push_back(1);
    dirty_.push_back(0);
    const int retire = iteration + params_.maxNoGrowth + 1;
    if (parent == kNone) {
        branchDepth_.push_back(0);
    } else {
        const auto p = static_cast<std::size_t>(parent);
        branchDepth_.push_back(childBranchDepth(branchDepth_[p], childCount_[p]));
        ++childCount_[p];
        lastGrowth_[p] = iteration;
        if (params_.maxNoGrowth > 0) events_.emplace_back(retire, parent);
    }
    if (params_.maxNoGrowth > 0) events_.emplace_back(retire, id);
    const std::int64_t cell = store_.grid().cellOf(position);
    if (cell >= 0) {
        cellNext_.push_back(cellHead_[static_cast<std::size_t>(cell)]);
        cellHead_[static_cast<std::size_t>(cell)] = id;
    } else {
        cellNext_.push_back(kNone);
        outside_.push_back(id);
    }
    return id;
}

// Moves the nodes reported by the store into the dirty list (once each).
void Colonizer::markChanged() {
    for (NodeId node : changed_) {
        if (!dirty_[static_cast<std::size_t>(node)]) {
            dirty_[static_cast<std::size_t>(node)] = 1;
            dirtyList_.push_back(node);
        }
    }
    changed_.clear();
}

// max_NG: nodes without a child for max_NG iterations drop out of step 1 for good; their
// points go to the nearest node still considered.
void Colonizer::deactivateDue(int iteration) {
    std::vector<NodeId> due;
    while (eventCursor_ < events_.size() && events_[eventCursor_].first <= iteration) {
        const auto [when, node] = events_[eventCursor_++];
        const auto n = static_cast<std::size_t>(node);
        if (active_[n] && lastGrowth_[n] + params_.maxNoGrowth + 1 == when) {
            active_[n] = 0;
            due.push_back(node);
        }
    }
    for (NodeId node : due) {
        for (std::int32_t i = store_.firstOf(node); i != -1; i = store_.firstOf(node)) {
            const auto point = static_cast<std::uint32_t>(i);
            double d2 = 0.0;
            const NodeId nearest = nearestActiveNode(point, d2);
            store_.moveTo(point, nearest, d2);
            if (nearest != kNone) changed_.push_back(nearest);
        }
    }
    markChanged();
}

NodeId Colonizer::nearestActiveNode(std::uint32_t i, double& bestD2) const {
    NodeId best = kNone;
    bestD2 = influence2_;
    const Vec3f p = store_.position(i);
    store_.grid().forEachCell(p.cast<double>(), params_.influenceRadius, [&](std::size_t cell) {
        for (NodeId n = cellHead_[cell]; n != kNone; n = cellNext_[static_cast<std::size_t>(n)]) {
            if (!active_[static_cast<std::size_t>(n)]) continue;
            const double d2 = squaredDistance(p, nodePos_[static_cast<std::size_t>(n)]);
            if (d2 < bestD2 || (d2 == bestD2 && best != kNone && n < best)) {
                bestD2 = d2;
                best = n;
            }
        }
    });
    return best;
}

void Colonizer::updateTrunkPhases() {
    for (std::size_t t = 0; t < trunkTip_.size(); ++t) {
        const Vec3& tip = nodePos_[static_cast<std::size_t>(trunkTip_[t])];
        if (inTrunk_[t] && store_.hasPointWithin(tip, params_.influenceRadius)) inTrunk_[t] = 0;
    }
}

bool Colonizer::anyTrunkCanGrow() const {
    for (std::size_t t = 0; t < trunkTip_.size(); ++t) {
        if (inTrunk_[t] && active_[static_cast<std::size_t>(trunkTip_[t])]) return true;
    }
    return false;
}

// Σ normalize(s − v) over S(v) in increasing original point index (eq 3.3).
Vec3 Colonizer::attractionSum(NodeId node) {
    gather_.clear();
    for (std::int32_t i = store_.firstOf(node); i != -1;
         i = store_.nextInList(static_cast<std::uint32_t>(i))) {
        const auto point = static_cast<std::uint32_t>(i);
        gather_.emplace_back(store_.originalIndex(point), point);
    }
    std::sort(gather_.begin(), gather_.end());
    Vec3 sum = Vec3::Zero();
    const Vec3& v = nodePos_[static_cast<std::size_t>(node)];
    for (const auto& entry : gather_) addUnitDirection(sum, store_.position(entry.second), v);
    return sum;
}

bool Colonizer::isDuplicate(const Vec3& p) const {
    const double radius = std::sqrt(spacing2_);
    bool found = false;
    store_.grid().forEachCell(p, radius, [&](std::size_t cell) {
        for (NodeId n = cellHead_[cell]; n != kNone && !found;
             n = cellNext_[static_cast<std::size_t>(n)]) {
            found = squaredDistance(nodePos_[static_cast<std::size_t>(n)], p) < spacing2_;
        }
    });
    if (found || store_.grid().containsBall(p, radius)) return found;
    for (NodeId n : outside_) {
        if (squaredDistance(nodePos_[static_cast<std::size_t>(n)], p) < spacing2_) return true;
    }
    return false;
}

// Step 2 for one node: attraction growth, or a trunk step towards the nearest point.
bool Colonizer::tryGrow(NodeId node, int iteration) {
    const auto n = static_cast<std::size_t>(node);
    const std::uint32_t t = tree_[n];
    const bool trunk = inTrunk_[t] && trunkTip_[t] == node;
    Vec3 direction;
    if (trunk) {
        std::int64_t& target = trunkTarget_[t];
        if (target < 0 ||
            store_.owner(static_cast<std::uint32_t>(target)) == AttractorStore::kDead) {
            target = store_.nearestAlive(nodePos_[n]);
        }
        if (target < 0) return false;
        direction =
            store_.position(static_cast<std::uint32_t>(target)).cast<double>() - nodePos_[n];
    } else {
        direction = attractionSum(node) + params_.tropism;
    }
    Vec3 child;
    if (!proposeChild(params_, obstacles_, nodePos_[n], branchDepth_[n], childCount_[n], direction,
                      child) ||
        isDuplicate(child)) {
        return false;
    }
    if (nodePos_.size() >= params_.maxNodes) {
        throw Error("colonization would exceed the node limit of " +
                    std::to_string(params_.maxNodes) + " nodes at iteration " +
                    std::to_string(iteration) +
                    "; expected fewer points or iterations, a larger step, or a larger "
                    "--max-nodes (ColonizeParams::maxNodes)");
    }
    const NodeId id = addNode(node, child, t, iteration);
    if (trunk) trunkTip_[t] = id;
    newNodes_.push_back(id);
    return true;
}

int Colonizer::nextEventIteration() {
    while (eventCursor_ < events_.size()) {
        const auto [when, node] = events_[eventCursor_];
        const auto n = static_cast<std::size_t>(node);
        if (active_[n] && lastGrowth_[n] + params_.maxNoGrowth + 1 == when) return when;
        ++eventCursor_;  // stale: the node grew since, or is already inactive
    }
    return -1;
}

int Colonizer::run() {
    int k = 0;
    std::vector<NodeId> candidates;
    while (store_.aliveCount() > 0 && k < params_.maxIterations) {
        const int iteration = k + 1;
        deactivateDue(iteration);
        updateTrunkPhases();
        // No node within d_i of any point, and no trunk to grow: done.
        if (store_.assignedCount() == 0 && !anyTrunkCanGrow()) break;
        k = iteration;

        // Step 2 for the nodes whose S(v) changed, and trunk tips, in increasing id order.
        candidates.clear();
        for (NodeId node : dirtyList_) {
            const auto n = static_cast<std::size_t>(node);
            dirty_[n] = 0;
            if (active_[n] && store_.firstOf(node) != -1) candidates.push_back(node);
        }
        dirtyList_.clear();
        for (std::size_t t = 0; t < trunkTip_.size(); ++t) {
            if (inTrunk_[t] && active_[static_cast<std::size_t>(trunkTip_[t])]) {
                candidates.push_back(trunkTip_[t]);
            }
        }
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        newNodes_.clear();
        for (NodeId node : candidates) tryGrow(node, iteration);

        // Step 3, and step 1 of the next iteration, for the new nodes.
        for (NodeId node : newNodes_) {
            store_.removeAndClaimNear(node, nodePos_[static_cast<std::size_t>(node)], nodePos_,
                                      changed_);
        }
        markChanged();
        if (!newNodes_.empty()) continue;

        // Nothing grew: only max_NG retirements can still change anything. Skip the idle
        // iterations up to the next one (each would repeat the same refused proposals).
        if (params_.maxNoGrowth <= 0 || (store_.assignedCount() == 0 && !anyTrunkCanGrow())) {
            break;
        }
        const int next = nextEventIteration();
        if (next < 0) break;
        k = std::max(k, std::min(next - 1, params_.maxIterations));
    }
    return k;
}

std::vector<BranchTree> Colonizer::buildTrees() {
    store_.release();
    std::vector<BranchTree> trees(trunkTip_.size());
    std::vector<std::size_t> sizes(trees.size(), 0);
    for (std::uint32_t t : tree_) ++sizes[t];
    for (std::size_t t = 0; t < trees.size(); ++t) trees[t].reserve(sizes[t]);
    std::vector<NodeId> local(nodePos_.size(), kNone);
    for (std::size_t n = 0; n < nodePos_.size(); ++n) {
        BranchTree& tree = trees[tree_[n]];
        if (parent_[n] == kNone) {
            local[n] = tree.addRoot(nodePos_[n]);
        } else {
            local[n] = tree.addChild(local[static_cast<std::size_t>(parent_[n])], nodePos_[n]);
        }
        RAMUS_ASSERT(tree.node(local[n]).branchDepth == branchDepth_[n]);
    }
    return trees;
}

}  // namespace

std::size_t ColonizeResult::nodeCount() const {
    std::size_t count = 0;
    for (const BranchTree& tree : trees) count += tree.size();
    return count;
}

ColonizeResult colonize(const ColonizeParams& params, std::span<const Vec3> points,
                        std::span<const Shape> obstacles) {
    validateColonizeParams(params);
    ColonizeResult result;
    // The points used, rounded to float, as three coordinate arrays (12 bytes per point; the
    // colonizer rearranges them in place).
    std::vector<float> xs, ys, zs;
    xs.reserve(points.size()), ys.reserve(points.size()), zs.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].allFinite()) {
            throw Error("attraction point " + std::to_string(i) + " is not finite");
        }
        const bool inside = std::any_of(obstacles.begin(), obstacles.end(), [&](const Shape& o) {
            return shapeContains(o, points[i]);
        });
        if (inside) continue;
        const Vec3f p = points[i].cast<float>();
        if (!p.allFinite()) {  // a finite double beyond float's range (fuzzed configs hung)
            std::ostringstream what;
            what << "attraction point " << i << " (" << points[i].x() << ", " << points[i].y()
                 << ", " << points[i].z()
                 << ") is beyond the float range the points are kept in (magnitudes up to "
                 << std::numeric_limits<float>::max() << "); make the envelopes smaller";
            throw Error(what.str());
        }
        xs.push_back(p.x()), ys.push_back(p.y()), zs.push_back(p.z());
    }
    result.warnings = colonizeWarnings(params, xs.size(), obstacles);
    result.attractors = xs.size();
    Colonizer colonizer(params, std::move(xs), std::move(ys), std::move(zs), obstacles);
    result.iterations = colonizer.run();
    result.attractorsLeft = colonizer.aliveCount();
    result.trees = colonizer.buildTrees();
    return result;
}

}  // namespace ramus
