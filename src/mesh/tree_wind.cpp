// Wind data per branch (issue 9). Branches are the tube mesher's chains (seed 002 §4.4.4:
// edges of equal branch depth Z, eq 3.7, share a tube): a node continues its parent's branch
// when it is the parent's first child of equal Z. Engines bend a vertex by its branch's level
// and phase, weighted by how far along the branch it sits (e.g. Sousa, "Vegetation Procedural
// Animation and Shading in Crysis", GPU Gems 3 ch. 16: per-branch phase and bending weights).
#include "ramus/tree_wind.hpp"

#include <algorithm>

#include "ramus/rng.hpp"

namespace ramus {

namespace {

constexpr std::uint64_t kPhaseSalt = 0x77696e6470686173ULL;  // "windphas"

float phaseOf(std::uint64_t seed, NodeId branch) {
    const std::uint64_t h =
        hashCombine(hashCombine(seed, kPhaseSalt), static_cast<std::uint64_t>(branch));
    return static_cast<float>(static_cast<double>(h >> 11) * 0x1.0p-53);
}

}  // namespace

TreeWind::TreeWind(const BranchTree& tree, std::uint64_t seed) {
    const std::size_t n = tree.size();
    branch_.assign(n, 0);
    parent_.assign(n, kNoNode);
    distance_.assign(n, 0.0f);
    level_.assign(n, 0.0f);
    position_.resize(n);
    branchLength_.assign(n, 0.0f);
    branchPhase_.assign(n, 0.0f);
    std::vector<std::uint8_t> continued(n, 0);  // the node's chain already has its continuation
    // Children come after their parents, so one forward pass links every branch.
    for (std::size_t i = 0; i < n; ++i) {
        const BranchNode& node = tree.nodes()[i];
        position_[i] = node.position.cast<float>();
        level_[i] = static_cast<float>(node.branchDepth);
        if (node.parent == kNoNode) {
            branchPhase_[i] = phaseOf(seed, static_cast<NodeId>(i));
            continue;
        }
        const auto p = static_cast<std::size_t>(node.parent);
        parent_[i] = node.parent;
        const float edge = static_cast<float>((node.position - tree.nodes()[p].position).norm());
        if (!continued[p] && node.branchDepth == tree.nodes()[p].branchDepth) {
            continued[p] = 1;
            branch_[i] = branch_[p];
            distance_[i] = distance_[p] + edge;
        } else {
            branch_[i] = static_cast<NodeId>(i);
            distance_[i] = edge;
            branchPhase_[i] = phaseOf(seed, static_cast<NodeId>(i));
        }
        float& length = branchLength_[static_cast<std::size_t>(branch_[i])];
        length = std::max(length, distance_[i]);
    }
}

WindSample TreeWind::at(NodeId node, double t) const {
    const auto i = static_cast<std::size_t>(node);
    const auto b = static_cast<std::size_t>(branch_[i]);
    WindSample s;
    s.level = level_[i];
    s.phase = branchPhase_[b];
    const NodeId parent = parent_[i];
    // A branch's base: its first node's parent (the root for the trunk).
    const NodeId baseNode = b == 0 ? 0 : parent_[b];
    s.pivot = position_[static_cast<std::size_t>(baseNode)];
    if (parent == kNoNode) return s;
    const auto p = static_cast<std::size_t>(parent);
    const float start = branch_[p] == branch_[i] ? distance_[p] : 0.0f;
    const auto tf = static_cast<float>(std::clamp(t, 0.0, 1.0));
    s.distance = start + tf * (distance_[i] - start);
    const float length = branchLength_[b];
    s.relative = length > 0.0f ? std::min(1.0f, s.distance / length) : 0.0f;
    return s;
}

void WindAttributes::resize(std::size_t vertexCount) {
    wind.resize(4 * vertexCount);
    pivot.resize(3 * vertexCount);
    leaf.resize(2 * vertexCount);
}

void WindAttributes::set(std::size_t first, std::size_t count, const WindSample& s, float leafPhase,
                         float flutter) {
    float* w = wind.data() + 4 * first;
    float* p = pivot.data() + 3 * first;
    float* l = leaf.data() + 2 * first;
    for (std::size_t k = 0; k < count; ++k, w += 4, p += 3, l += 2) {
        w[0] = s.level;
        w[1] = s.phase;
        w[2] = s.relative;
        w[3] = s.distance;
        p[0] = s.pivot.x();
        p[1] = s.pivot.y();
        p[2] = s.pivot.z();
        l[0] = leafPhase;
        l[1] = flutter;
    }
}

void WindAttributes::reserve(std::size_t vertexCount) {
    wind.reserve(4 * vertexCount);
    pivot.reserve(3 * vertexCount);
    leaf.reserve(2 * vertexCount);
}

void WindAttributes::append(std::size_t count, const WindSample& s) {
    const std::size_t first = vertexCount();
    resize(first + count);
    set(first, count, s);
}

void WindAttributes::appendFrom(const WindAttributes& other, std::size_t first, std::size_t count) {
    auto copy = [&](std::vector<float>& to, const std::vector<float>& from, std::size_t width) {
        const auto begin = from.begin() + static_cast<std::ptrdiff_t>(first * width);
        to.insert(to.end(), begin, begin + static_cast<std::ptrdiff_t>(count * width));
    };
    copy(wind, other.wind, 4);
    copy(pivot, other.pivot, 3);
    copy(leaf, other.leaf, 2);
}

void WindAttributes::moveInto(Mesh& mesh) {
    mesh.attributes.push_back(VertexAttribute{kWindAttribute, 4, std::move(wind)});
    mesh.attributes.push_back(VertexAttribute{kWindPivotAttribute, 3, std::move(pivot)});
    mesh.attributes.push_back(VertexAttribute{kWindLeafAttribute, 2, std::move(leaf)});
    wind.clear();
    pivot.clear();
    leaf.clear();
}

}  // namespace ramus
