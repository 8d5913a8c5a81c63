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
#include <sstream>

#include "growth_rules.hpp"
#include "ramus/error.hpp"
#include "spatial_grid.hpp"

namespace ramus {

using namespace colonize_detail;

namespace {

constexpr std::int32_t kUnassigned = -1;  // point alive, no node within d_i
constexpr std::int32_t kDead = -2;        // point removed (a node came within d_k)
constexpr std::int32_t kNone = -1;
constexpr int kGridSubdivision = 2;  // cells of d_i / 2

class Colonizer {
public:
    Colonizer(const ColonizeParams& params, std::span<const Vec3f> points,
              std::span<const Shape> obstacles);
    int run();
    std::size_t aliveCount() const { return alive_; }
    std::vector<BranchTree> buildTrees() const;

private:
    // Nodes and points.
    NodeId addNode(NodeId parent, const Vec3& position, std::uint32_t tree, int iteration);
    void attach(std::uint32_t point, NodeId node);
    void detach(std::uint32_t point);
    void markDirty(NodeId node);
    void killAround(NodeId node);
    void assignAround(NodeId node);
    // Iteration parts.
    void deactivateDue(int iteration);
    NodeId nearestActiveNode(std::uint32_t point) const;
    void updateTrunkPhases();
    bool anyTrunkCanGrow() const;
    bool hasPointWithin(const Vec3& center, double radius) const;
    std::int64_t nearestAlivePoint(const Vec3& center) const;
    Vec3 attractionSum(NodeId node);
    bool tryGrow(NodeId node, int iteration);
    bool isDuplicate(const Vec3& position) const;
    int nextEventIteration();

    const ColonizeParams& params_;
    std::span<const Shape> obstacles_;
    double influence2_, kill2_, spacing2_;
    SpatialGrid grid_;
    // Points in grid cell order: position, original index, owner node (or kUnassigned/kDead)
    // and the links of the owner's list of attracting points.
    std::vector<Vec3f> pos_;
    std::vector<std::uint32_t> original_;
    std::vector<std::int32_t> owner_, next_, prev_;
    std::size_t alive_ = 0, assigned_ = 0;
    // Nodes.
    std::vector<Vec3> nodePos_;
    std::vector<NodeId> parent_, head_, cellNext_;
    std::vector<std::uint32_t> tree_, branchDepth_, childCount_;
    std::vector<int> lastGrowth_;
    std::vector<std::uint8_t> active_, dirty_;
    std::vector<std::int32_t> cellHead_;
    std::vector<NodeId> outside_;  // nodes outside the grid (too far from every point)
    std::vector<NodeId> dirtyList_, newNodes_;
    std::vector<std::pair<int, NodeId>> events_;  // (iteration, node): max_NG deactivation
    std::size_t eventCursor_ = 0;
    // Trees: the trunk phase lasts until a point is within d_i of the trunk's tip.
    std::vector<NodeId> trunkTip_;
    std::vector<std::uint8_t> inTrunk_;
    std::vector<std::int64_t> trunkTarget_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> gather_;
};

Colonizer::Colonizer(const ColonizeParams& params, std::span<const Vec3f> points,
                     std::span<const Shape> obstacles)
    : params_(params),
      obstacles_(obstacles),
      influence2_(params.influenceRadius * params.influenceRadius),
      kill2_(params.killRadius * params.killRadius),
      spacing2_(minNodeSpacingSquared(params)) {
    grid_ = SpatialGrid(points, params.influenceRadius, kGridSubdivision,
                        std::max<std::size_t>(points.size() / 4, 4096), original_);
    pos_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) pos_[i] = points[original_[i]];
    owner_.assign(points.size(), kUnassigned);
    next_.assign(points.size(), kNone);
    prev_.assign(points.size(), kNone);
    alive_ = points.size();
    cellHead_.assign(grid_.cellCount(), kNone);
    const std::size_t roots = params.roots.size();
    for (std::size_t t = 0; t < roots; ++t) {
        addNode(kNone, params.roots[t], static_cast<std::uint32_t>(t), 0);
        trunkTip_.push_back(static_cast<NodeId>(t));
    }
    inTrunk_.assign(roots, 1);
    trunkTarget_.assign(roots, -1);
    // The roots remove the points they already reach, then attract.
    for (NodeId r = 0; r < static_cast<NodeId>(roots); ++r) killAround(r);
    for (NodeId r = 0; r < static_cast<NodeId>(roots); ++r) assignAround(r);
}

NodeId Colonizer::addNode(NodeId parent, const Vec3& position, std::uint32_t tree, int iteration) {
    const auto id = static_cast<NodeId>(nodePos_.size());
    nodePos_.push_back(position);
    parent_.push_back(parent);
    head_.push_back(kNone);
    tree_.push_back(tree);
    childCount_.push_back(0);
    lastGrowth_.push_back(iteration);
    active_.push_back(1);
    dirty_.push_back(0);
    if (parent == kNone) {
        branchDepth_.push_back(0);
    } else {
        const auto p = static_cast<std::size_t>(parent);
        branchDepth_.push_back(childBranchDepth(branchDepth_[p], childCount_[p]));
        ++childCount_[p];
        lastGrowth_[p] = iteration;
        if (params_.maxNoGrowth > 0)
            events_.emplace_back(iteration + params_.maxNoGrowth + 1, parent);
    }
    if (params_.maxNoGrowth > 0) events_.emplace_back(iteration + params_.maxNoGrowth + 1, id);
    const std::int64_t cell = grid_.cellOf(position);
    if (cell >= 0) {
        cellNext_.push_back(cellHead_[static_cast<std::size_t>(cell)]);
        cellHead_[static_cast<std::size_t>(cell)] = id;
    } else {
        cellNext_.push_back(kNone);
        outside_.push_back(id);
    }
    return id;
}

void Colonizer::attach(std::uint32_t i, NodeId node) {
    owner_[i] = node;
    prev_[i] = kNone;
    next_[i] = head_[static_cast<std::size_t>(node)];
    if (next_[i] != kNone) prev_[static_cast<std::size_t>(next_[i])] = static_cast<std::int32_t>(i);
    head_[static_cast<std::size_t>(node)] = static_cast<std::int32_t>(i);
    ++assigned_;
}

void Colonizer::detach(std::uint32_t i) {
    const NodeId node = owner_[i];
    if (prev_[i] != kNone) {
        next_[static_cast<std::size_t>(prev_[i])] = next_[i];
    } else {
        head_[static_cast<std::size_t>(node)] = next_[i];
    }
    if (next_[i] != kNone) prev_[static_cast<std::size_t>(next_[i])] = prev_[i];
    owner_[i] = kUnassigned;
    --assigned_;
}

void Colonizer::markDirty(NodeId node) {
    if (!dirty_[static_cast<std::size_t>(node)]) {
        dirty_[static_cast<std::size_t>(node)] = 1;
        dirtyList_.push_back(node);
    }
}

// Step 3 for one new node: remove the points closer than d_k.
void Colonizer::killAround(NodeId node) {
    const Vec3& c = nodePos_[static_cast<std::size_t>(node)];
    grid_.forEachPointRange(c, params_.killRadius, [&](std::uint32_t first, std::uint32_t last) {
        for (std::uint32_t i = first; i < last; ++i) {
            if (owner_[i] == kDead || squaredDistance(pos_[i], c) >= kill2_) continue;
            if (owner_[i] >= 0) {
                markDirty(owner_[i]);
                detach(i);
            }
            owner_[i] = kDead;
            --alive_;
        }
    });
}

// Step 1, incrementally: points within d_i of a new node switch to it when it is strictly
// nearer than their node (a tie keeps the older node, which has the lower id).
void Colonizer::assignAround(NodeId node) {
    const Vec3& c = nodePos_[static_cast<std::size_t>(node)];
    grid_.forEachPointRange(
        c, params_.influenceRadius, [&](std::uint32_t first, std::uint32_t last) {
            for (std::uint32_t i = first; i < last; ++i) {
                const NodeId current = owner_[i];
                if (current == kDead) continue;
                const double d2 = squaredDistance(pos_[i], c);
                if (d2 >= influence2_) continue;
                if (current >= 0) {
                    if (d2 >=
                        squaredDistance(pos_[i], nodePos_[static_cast<std::size_t>(current)])) {
                        continue;
                    }
                    markDirty(current);
                    detach(i);
                }
                attach(i, node);
                markDirty(node);
            }
        });
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
        while (head_[static_cast<std::size_t>(node)] != kNone) {
            const auto i = static_cast<std::uint32_t>(head_[static_cast<std::size_t>(node)]);
            detach(i);
            const NodeId nearest = nearestActiveNode(i);
            if (nearest != kNone) {
                attach(i, nearest);
                markDirty(nearest);
            }
        }
    }
}

NodeId Colonizer::nearestActiveNode(std::uint32_t i) const {
    NodeId best = kNone;
    double bestD2 = influence2_;
    grid_.forEachCell(pos_[i].cast<double>(), params_.influenceRadius, [&](std::size_t cell) {
        for (NodeId n = cellHead_[cell]; n != kNone; n = cellNext_[static_cast<std::size_t>(n)]) {
            if (!active_[static_cast<std::size_t>(n)]) continue;
            const double d2 = squaredDistance(pos_[i], nodePos_[static_cast<std::size_t>(n)]);
            if (d2 < bestD2 || (d2 == bestD2 && best != kNone && n < best)) {
                bestD2 = d2;
                best = n;
            }
        }
    });
    return best;
}

bool Colonizer::hasPointWithin(const Vec3& center, double radius) const {
    bool found = false;
    const double r2 = radius * radius;
    grid_.forEachPointRange(center, radius, [&](std::uint32_t first, std::uint32_t last) {
        for (std::uint32_t i = first; i < last && !found; ++i) {
            found = owner_[i] != kDead && squaredDistance(pos_[i], center) < r2;
        }
    });
    return found;
}

// Linear scan; only trunks use it, once per target.
std::int64_t Colonizer::nearestAlivePoint(const Vec3& center) const {
    std::int64_t best = -1;
    double bestD2 = 0.0;
    for (std::size_t i = 0; i < pos_.size(); ++i) {
        if (owner_[i] == kDead) continue;
        const double d2 = squaredDistance(pos_[i], center);
        if (best < 0 || d2 < bestD2 ||
            (d2 == bestD2 && original_[i] < original_[static_cast<std::size_t>(best)])) {
            best = static_cast<std::int64_t>(i);
            bestD2 = d2;
        }
    }
    return best;
}

void Colonizer::updateTrunkPhases() {
    for (std::size_t t = 0; t < trunkTip_.size(); ++t) {
        if (inTrunk_[t] && hasPointWithin(nodePos_[static_cast<std::size_t>(trunkTip_[t])],
                                          params_.influenceRadius)) {
            inTrunk_[t] = 0;
        }
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
    for (std::int32_t i = head_[static_cast<std::size_t>(node)]; i != kNone;
         i = next_[static_cast<std::size_t>(i)]) {
        gather_.emplace_back(original_[static_cast<std::size_t>(i)], static_cast<std::uint32_t>(i));
    }
    std::sort(gather_.begin(), gather_.end());
    Vec3 sum = Vec3::Zero();
    const Vec3& v = nodePos_[static_cast<std::size_t>(node)];
    for (const auto& entry : gather_) addUnitDirection(sum, pos_[entry.second], v);
    return sum;
}

bool Colonizer::isDuplicate(const Vec3& p) const {
    const double radius = std::sqrt(spacing2_);
    bool found = false;
    grid_.forEachCell(p, radius, [&](std::size_t cell) {
        for (NodeId n = cellHead_[cell]; n != kNone && !found;
             n = cellNext_[static_cast<std::size_t>(n)]) {
            found = squaredDistance(nodePos_[static_cast<std::size_t>(n)], p) < spacing2_;
        }
    });
    if (found || grid_.containsBall(p, radius)) return found;
    for (NodeId n : outside_) {
        if (squaredDistance(nodePos_[static_cast<std::size_t>(n)], p) < spacing2_) return true;
    }
    return false;
}

// Step 2 for one node: attraction growth, or a trunk step towards the nearest point.
bool Colonizer::tryGrow(NodeId node, int iteration) {
    const auto n = static_cast<std::size_t>(node);
    const std::uint32_t t = tree_[n];
    Vec3 direction;
    if (inTrunk_[t] && trunkTip_[t] == node) {
        std::int64_t& target = trunkTarget_[t];
        if (target < 0 || owner_[static_cast<std::size_t>(target)] == kDead) {
            target = nearestAlivePoint(nodePos_[n]);
        }
        if (target < 0) return false;
        direction = pos_[static_cast<std::size_t>(target)].cast<double>() - nodePos_[n];
    } else {
        direction = attractionSum(node) + params_.tropism;
    }
    Vec3 child;
    if (!proposeChild(params_, obstacles_, nodePos_[n], branchDepth_[n], childCount_[n], direction,
                      child) ||
        isDuplicate(child)) {
        return false;
    }
    const NodeId id = addNode(node, child, t, iteration);
    if (inTrunk_[t] && trunkTip_[t] == node) trunkTip_[t] = id;
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
    while (alive_ > 0 && k < params_.maxIterations) {
        const int iteration = k + 1;
        deactivateDue(iteration);
        updateTrunkPhases();
        if (assigned_ == 0 && !anyTrunkCanGrow()) break;  // no node within d_i of any point
        k = iteration;

        // Step 2 for the nodes whose S(v) changed, and trunk tips, in increasing id order.
        candidates.clear();
        for (NodeId node : dirtyList_) {
            dirty_[static_cast<std::size_t>(node)] = 0;
            const auto n = static_cast<std::size_t>(node);
            if (active_[n] && head_[n] != kNone) candidates.push_back(node);
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

        // Step 3, then step 1 of the next iteration for the new nodes.
        for (NodeId node : newNodes_) killAround(node);
        for (NodeId node : newNodes_) assignAround(node);
        if (!newNodes_.empty()) continue;

        // Nothing grew: only max_NG deactivations can still change anything. Skip the idle
        // iterations up to the next one (each would repeat the same refused proposals).
        if (params_.maxNoGrowth <= 0 || (assigned_ == 0 && !anyTrunkCanGrow())) break;
        const int next = nextEventIteration();
        if (next < 0) break;
        k = std::max(k, std::min(next - 1, params_.maxIterations));
    }
    return k;
}

std::vector<BranchTree> Colonizer::buildTrees() const {
    std::vector<BranchTree> trees(trunkTip_.size());
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
    std::vector<Vec3f> kept;
    kept.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].allFinite()) {
            throw Error("attraction point " + std::to_string(i) + " is not finite");
        }
        const bool inside = std::any_of(obstacles.begin(), obstacles.end(), [&](const Shape& o) {
            return shapeContains(o, points[i]);
        });
        if (!inside) kept.push_back(points[i].cast<float>());
    }
    result.warnings = colonizeWarnings(params, kept.size(), obstacles);
    result.attractors = kept.size();
    Colonizer colonizer(params, kept, obstacles);
    std::vector<Vec3f>().swap(kept);  // the colonizer holds its own copy in grid order
    result.iterations = colonizer.run();
    result.attractorsLeft = colonizer.aliveCount();
    result.trees = colonizer.buildTrees();
    return result;
}

}  // namespace ramus
