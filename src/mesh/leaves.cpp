// Leaves near branch tips (issue 9). Placement follows the usual tree-modelling rules: leaves
// at the tips and, near them, at regular intervals along each branch, turning by a constant
// divergence angle (phyllotaxis; the golden angle 137.5°, Prusinkiewicz & Lindenmayer, ABOP
// §4.1) and tilted away from the branch. Every leaf has a stable key (its branch and slot, or
// its tip and index) that seeds its own random stream (DESIGN.md: per-entity streams) and
// ranks it for LOD thinning.
#include "ramus/leaves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ramus/error.hpp"
#include "ramus/rng.hpp"
#include "ramus/tree_wind.hpp"

namespace ramus {

namespace {

constexpr std::uint64_t kSlotSalt = 0x6c6561662d736c74ULL;  // "leaf-slt"
constexpr std::uint64_t kTipSalt = 0x6c6561662d746970ULL;   // "leaf-tip"
constexpr std::uint64_t kPolygonSalt = 0x6c6561662d706f6cULL;
constexpr double kMaxLeaves = 20e6;  // a runaway density fails clearly instead of eating memory

double unitFromHash(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

std::uint64_t leafKey(std::uint64_t seed, std::uint64_t salt, std::uint64_t a, std::uint64_t b) {
    return hashCombine(hashCombine(hashCombine(seed, salt), a), b);
}

double meanDrawnEdge(const BranchTree& tree) {
    double total = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 1; i < tree.size(); ++i) {
        const BranchNode& n = tree.nodes()[i];
        if (n.hidden) continue;
        total += (n.position - tree.node(n.parent).position).norm();
        ++count;
    }
    return count > 0 ? total / static_cast<double>(count) : 0.0;
}

// Distance from every node to the nearest tip below it along the branches (∞ without one).
std::vector<double> distanceToTips(const BranchTree& tree) {
    std::vector<double> d(tree.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i = tree.size(); i-- > 1;) {  // children come after their parents
        const BranchNode& n = tree.nodes()[i];
        if (n.childCount == 0 && !n.hidden) d[i] = 0.0;
        const auto p = static_cast<std::size_t>(n.parent);
        d[p] = std::min(d[p], d[i] + (n.position - tree.nodes()[p].position).norm());
    }
    return d;
}

// Everything one leaf needs from its branch.
struct LeafSite {
    NodeId node;
    double t;        // along the edge into `node`
    double azimuth;  // radians, before jitter
    double tilt;     // radians, before jitter
    std::uint64_t key;
};

class LeafPlacer {
public:
    LeafPlacer(const BranchTree& tree, std::span<const double> radii, const LeafParams& params)
        : tree_(tree), radii_(radii), params_(params), wind_(tree, params.seed) {
        length_ = params.size > 0.0 ? params.size : meanDrawnEdge(tree);
        zone_ = params.zone > 0.0 ? params.zone : 4.0 * length_;
        step_ = degToRad(params.phyllotaxisDegrees);
        tilt_ = degToRad(params.tiltDegrees);
    }

    std::vector<LeafPlacement> place() {
        const std::vector<double> toTip = distanceToTips(tree_);
        checkCount(toTip);
        for (std::size_t i = 1; i < tree_.size(); ++i) {
            const BranchNode& n = tree_.nodes()[i];
            if (n.hidden) continue;
            const auto node = static_cast<NodeId>(i);
            if (params_.perLength > 0.0) placeAlongEdge(node, toTip[i]);
            if (n.childCount == 0) placeAtTip(node);
        }
        return std::move(out_);
    }

private:
    void checkCount(const std::vector<double>& toTip) const {
        double estimate = 0.0;
        for (std::size_t i = 1; i < tree_.size(); ++i) {
            const BranchNode& n = tree_.nodes()[i];
            if (n.hidden || !(toTip[i] <= zone_)) continue;
            if (n.childCount == 0) estimate += params_.perTip;
            estimate += params_.perLength * (n.position - tree_.node(n.parent).position).norm();
        }
        if (estimate > kMaxLeaves) {
            throw Error("leaves: about " + std::to_string(static_cast<long long>(estimate)) +
                        " leaves; expected at most 20000000 (lower leaves per tip or per length)");
        }
    }

    // Slots k at branch distances (k + ½)/perLength inside this edge and within zone of a tip.
    void placeAlongEdge(NodeId node, double toTip) {
        const double s0 = wind_.at(node, 0.0).distance, s1 = wind_.at(node, 1.0).distance;
        if (!(s1 > s0) || toTip - zone_ > s1 - s0) return;
        const double density = params_.perLength;
        const auto branch = static_cast<std::uint64_t>(wind_.branchOf(node));
        const double first = std::ceil(s0 * density - 0.5);
        for (double k = first; (k + 0.5) / density < s1; k += 1.0) {
            const double s = (k + 0.5) / density;
            if (toTip + (s1 - s) > zone_) continue;
            const auto slot = static_cast<std::uint64_t>(k);
            emit({node, (s - s0) / (s1 - s0), k * step_, tilt_,
                  leafKey(params_.seed, kSlotSalt, branch, slot)});
        }
    }

    // A small rosette at the tip: the first leaf points on along the branch, the others fan
    // out a little behind it.
    void placeAtTip(NodeId node) {
        const double edge =
            (tree_.node(node).position - tree_.node(tree_.node(node).parent).position).norm();
        for (int j = 0; j < params_.perTip; ++j) {
            const double back = edge > 0.0 ? 0.15 * length_ * j / edge : 0.0;
            emit({node, std::max(0.0, 1.0 - back), j * step_, j == 0 ? 0.3 * tilt_ : tilt_,
                  leafKey(params_.seed, kTipSalt, static_cast<std::uint64_t>(node),
                          static_cast<std::uint64_t>(j))});
        }
    }

    void emit(const LeafSite& site) {
        const BranchNode& n = tree_.node(site.node);
        const Vec3& from = tree_.node(n.parent).position;
        const Vec3 edge = n.position - from;
        const double len = edge.norm();
        if (!(len > 0.0)) return;
        const Vec3 dir = edge / len;
        // Azimuth 0 faces the sky (or +X on a vertical branch); each branch is turned by its
        // hashed phase so neighbouring branches do not line their leaves up.
        Vec3 e1 = Vec3::UnitY() - dir.y() * dir;
        if (e1.squaredNorm() < 1e-12) e1 = Vec3::UnitX() - dir.x() * dir;
        e1.normalize();
        const Vec3 e2 = dir.cross(e1);
        Rng rng = Rng::forStream(params_.seed, site.key);
        const double jitter = degToRad(params_.jitterDegrees);
        const double branchTurn = 2.0 * kPi * wind_.at(site.node).phase;
        const double az = site.azimuth + branchTurn + jitter * rng.uniform(-1.0, 1.0);
        const double tilt = site.tilt + jitter * rng.uniform(-1.0, 1.0);
        const double scale = 1.0 + params_.sizeVariation * rng.uniform(-1.0, 1.0);
        const Vec3 out = std::cos(az) * e1 + std::sin(az) * e2;
        LeafPlacement leaf;
        leaf.axis = (std::cos(tilt) * dir + std::sin(tilt) * out).normalized();
        Vec3 side = dir.cross(out);  // tangent to the bark, ⊥ the axis
        leaf.normal = leaf.axis.cross(side).normalized();
        if (leaf.normal.y() < 0.0) leaf.normal = -leaf.normal;
        const double radius = radii_.empty() ? 0.0 : radii_[static_cast<std::size_t>(site.node)];
        leaf.base = from + site.t * edge + radius * out;
        if (leaf.base.y() < params_.minHeight) return;
        leaf.length = length_ * scale;
        leaf.width = leaf.length * params_.widthRatio;
        leaf.node = site.node;
        leaf.t = site.t;
        leaf.key = site.key;
        out_.push_back(leaf);
    }

    const BranchTree& tree_;
    std::span<const double> radii_;
    const LeafParams& params_;
    TreeWind wind_;
    double length_ = 0.0, zone_ = 0.0, step_ = 0.0, tilt_ = 0.0;
    std::vector<LeafPlacement> out_;
};

// Keeps the `keep` fraction of leaves with the smallest keys (nested across fractions),
// scaled by 1/√keep; order unchanged.
void thinLeaves(std::vector<LeafPlacement>& leaves, double keep) {
    if (!(keep < 1.0) || leaves.empty()) return;
    const auto count = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::llround(keep * static_cast<double>(leaves.size()))));
    if (count >= leaves.size()) return;
    std::vector<std::uint64_t> keys(leaves.size());
    for (std::size_t i = 0; i < leaves.size(); ++i) keys[i] = leaves[i].key;
    std::nth_element(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(count - 1),
                     keys.end());
    const std::uint64_t limit = keys[count - 1];
    const double grow = 1.0 / std::sqrt(keep);
    std::size_t kept = 0;
    for (const LeafPlacement& leaf : leaves) {
        if (leaf.key > limit || kept == count) continue;
        LeafPlacement& k = leaves[kept++];
        k = leaf;
        k.length *= grow;
        k.width *= grow;
    }
    leaves.resize(kept);
}

// Blade outline: midrib points at y = 0, ¼, ½, ¾, 1, edge points at ¼, ½, ¾ on both sides;
// 12 triangles counter-clockwise around the normal (x = side, y = axis).
struct LeafTemplate {
    std::vector<Vec2> points;  // x in [-½, ½] of the width, y in [0, 1] of the length
    std::vector<float> lift;   // along the normal, fraction of the width (the midrib fold)
    std::vector<std::uint32_t> triangles;
};

LeafTemplate leafTemplate(LeafShape shape) {
    LeafTemplate t;
    if (shape == LeafShape::Card) {
        t.points = {{-0.5, 0.0}, {0.5, 0.0}, {0.5, 1.0}, {-0.5, 1.0}};
        t.lift.assign(4, 0.0f);
        t.triangles = {0, 1, 2, 0, 2, 3};
        return t;
    }
    for (int i = 0; i <= 4; ++i) t.points.emplace_back(0.0, i / 4.0);  // 0..4
    for (int j = 1; j <= 3; ++j)
        t.points.emplace_back(-leafOutlineHalfWidth(j / 4.0), j / 4.0);  // 5..7
    for (int j = 1; j <= 3; ++j)
        t.points.emplace_back(leafOutlineHalfWidth(j / 4.0), j / 4.0);  // 8..10
    t.lift.assign(11, 0.0f);
    for (int k = 5; k < 11; ++k) t.lift[static_cast<std::size_t>(k)] = 0.12f;
    t.triangles = {0, 8, 1, 1, 8, 9, 1, 9, 2, 2, 9, 10, 2, 10, 3, 3, 10, 4,   // right
                   0, 1, 5, 1, 6, 5, 1, 2, 6, 2, 7, 6,  2, 3,  7, 3, 4,  7};  // left
    return t;
}

}  // namespace

LeafShape parseLeafShape(const std::string& name) {
    if (name == "card") return LeafShape::Card;
    if (name == "blade") return LeafShape::Blade;
    throw Error("unknown leaf shape '" + name + "'; expected card or blade");
}

void validateLeafParams(const LeafParams& p) {
    auto check = [](bool ok, const std::string& what) {
        if (!ok) throw Error("leaves: " + what);
    };
    check(p.perTip >= 0 && p.perTip <= 1000,
          "per_tip is " + std::to_string(p.perTip) + "; expected 0 to 1000 leaves per tip");
    check(std::isfinite(p.perLength) && p.perLength >= 0.0,
          "per_length must be a finite number >= 0 (leaves per model unit)");
    check(std::isfinite(p.zone) && p.zone >= 0.0,
          "zone must be a finite number >= 0 (model units)");
    check(std::isfinite(p.size) && p.size >= 0.0,
          "size must be a finite number >= 0 (model units)");
    check(std::isfinite(p.widthRatio) && p.widthRatio > 0.0 && p.widthRatio <= 4.0,
          "width_ratio must be in (0, 4]");
    check(std::isfinite(p.sizeVariation) && p.sizeVariation >= 0.0 && p.sizeVariation < 1.0,
          "size_variation must be in [0, 1)");
    check(std::isfinite(p.phyllotaxisDegrees), "phyllotaxis must be a finite angle (degrees)");
    check(std::isfinite(p.tiltDegrees), "tilt must be a finite angle (degrees)");
    check(std::isfinite(p.jitterDegrees) && p.jitterDegrees >= 0.0,
          "jitter must be a finite angle >= 0 (degrees)");
    check(std::isfinite(p.keep) && p.keep > 0.0 && p.keep <= 1.0, "keep must be in (0, 1]");
    check(!std::isnan(p.minHeight), "min_height must be a number (model units)");
    for (float a : p.atlas)
        check(std::isfinite(a) && a >= 0.0f && a <= 1.0f,
              "atlas values must be in [0, 1] (u0, v0, u1, v1)");
    check(p.atlas[2] > p.atlas[0] && p.atlas[3] > p.atlas[1],
          "atlas must have u1 > u0 and v1 > v0");
}

double leafOutlineHalfWidth(double y) {
    if (!(y > 0.0 && y < 1.0)) return 0.0;
    return 0.5 * std::pow(std::sin(kPi * std::pow(y, 0.8)), 0.9);
}

std::vector<LeafPlacement> placeLeaves(const BranchTree& tree, std::span<const double> radii,
                                       const LeafParams& params) {
    if (tree.size() < 2) return {};
    std::vector<LeafPlacement> leaves = LeafPlacer(tree, radii, params).place();
    thinLeaves(leaves, params.keep);
    return leaves;
}

Mesh buildLeafMesh(const BranchTree& tree, const LeafParams& params, const TubeMeshParams& tube) {
    validateLeafParams(params);
    const std::vector<double> radii = computeEdgeRadii(tree, tube);
    const std::vector<LeafPlacement> leaves = placeLeaves(tree, radii, params);
    Mesh mesh;
    mesh.name = "leaves";
    if (leaves.empty()) return mesh;
    const LeafTemplate shape = leafTemplate(params.shape);
    const std::size_t per = shape.points.size();
    const std::size_t vertices = per * leaves.size();
    mesh.positions.resize(vertices);
    mesh.normals.resize(vertices);
    mesh.tangents.resize(vertices);
    mesh.uvs.resize(vertices);
    mesh.indices.resize(shape.triangles.size() * leaves.size());
    WindAttributes wind;
    TreeWind treeWind;
    if (tube.windAttributes) {
        wind.resize(vertices);
        treeWind = TreeWind(tree, tube.windSeed);
    }
    const auto& [u0, v0, u1, v1] = params.atlas;
    for (std::size_t l = 0; l < leaves.size(); ++l) {
        const LeafPlacement& leaf = leaves[l];
        const Vec3 side = leaf.axis.cross(leaf.normal);  // (side, axis, normal) right-handed
        const Vec3f n = leaf.normal.cast<float>();
        const Vec4f tangent(static_cast<float>(side.x()), static_cast<float>(side.y()),
                            static_cast<float>(side.z()), 1.0f);
        const std::size_t base = l * per;
        for (std::size_t k = 0; k < per; ++k) {
            const Vec2& q = shape.points[k];
            const Vec3 p = leaf.base + (q.x() * leaf.width) * side +
                           (q.y() * leaf.length) * leaf.axis +
                           (shape.lift[k] * leaf.width) * leaf.normal;
            mesh.positions[base + k] = p.cast<float>();
            mesh.normals[base + k] = n;
            mesh.tangents[base + k] = tangent;
            mesh.uvs[base + k] = Vec2f(u0 + static_cast<float>(q.x() + 0.5) * (u1 - u0),
                                       v1 - static_cast<float>(q.y()) * (v1 - v0));
        }
        if (tube.windAttributes) {
            const WindSample sample = treeWind.at(leaf.node, leaf.t);
            const auto phase = static_cast<float>(unitFromHash(hashCombine(leaf.key, 1)));
            for (std::size_t k = 0; k < per; ++k) {
                wind.set(base + k, 1, sample, phase, static_cast<float>(shape.points[k].y()));
            }
        }
        const std::size_t firstIndex = l * shape.triangles.size();
        for (std::size_t k = 0; k < shape.triangles.size(); ++k) {
            mesh.indices[firstIndex + k] = static_cast<std::uint32_t>(base + shape.triangles[k]);
        }
    }
    if (tube.windAttributes) wind.moveInto(mesh);
    Material material = params.material;
    material.doubleSided = true;
    mesh.materials.push_back(material);
    mesh.primitives.push_back(
        MeshPrimitive{0, static_cast<std::uint32_t>(mesh.indices.size()), 0, "leaves"});
    return mesh;
}

namespace {

// The polygons LOD thinning keeps (all with keep = 1): ranked by their hashed keys like
// generated leaves, each scaled by 1/√keep about its first vertex (its base).
struct KeptPolygons {
    std::vector<Vec3> vertices;
    std::vector<std::uint32_t> offsets{0};
    std::vector<std::uint32_t> source;  // original polygon index
};

KeptPolygons keepPolygons(std::span<const Vec3> vertices, std::span<const std::uint32_t> offsets,
                          const LeafParams& params) {
    KeptPolygons kept;
    const std::size_t count = offsets.empty() ? 0 : offsets.size() - 1;
    std::vector<std::uint64_t> keys(count);
    for (std::size_t p = 0; p < count; ++p) keys[p] = leafKey(params.seed, kPolygonSalt, p, 0);
    std::uint64_t limit = std::numeric_limits<std::uint64_t>::max();
    double grow = 1.0;
    if (params.keep < 1.0 && count > 0) {
        const auto want = std::max<std::size_t>(
            1, static_cast<std::size_t>(std::llround(params.keep * static_cast<double>(count))));
        std::vector<std::uint64_t> sorted = keys;
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(want - 1),
                         sorted.end());
        limit = sorted[want - 1];
        grow = 1.0 / std::sqrt(params.keep);
    }
    for (std::size_t p = 0; p < count; ++p) {
        const std::size_t begin = offsets[p],
                          end = std::min<std::size_t>(offsets[p + 1], vertices.size());
        if (keys[p] > limit || end <= begin) continue;
        for (std::size_t v = begin; v < end; ++v) {
            kept.vertices.push_back(vertices[begin] + grow * (vertices[v] - vertices[begin]));
        }
        kept.offsets.push_back(static_cast<std::uint32_t>(kept.vertices.size()));
        kept.source.push_back(static_cast<std::uint32_t>(p));
    }
    return kept;
}

}  // namespace

Mesh buildLeafPolygons(const BranchTree& tree, std::span<const Vec3> vertices,
                       std::span<const std::uint32_t> offsets, std::span<const NodeId> polygonNodes,
                       const LeafParams& params, const TubeMeshParams& tube) {
    const KeptPolygons kept = keepPolygons(vertices, offsets, params);
    std::vector<std::uint32_t> polygonOf;
    Mesh mesh = buildPolygonMesh(kept.vertices, kept.offsets, params.material, &polygonOf);
    for (MeshPrimitive& p : mesh.primitives) p.name = params.material.name;
    const auto& [u0, v0, u1, v1] = params.atlas;
    for (Vec2f& uv : mesh.uvs) uv = Vec2f(u0 + uv.x() * (u1 - u0), v0 + uv.y() * (v1 - v0));
    if (!tube.windAttributes || mesh.positions.empty() || tree.empty()) return mesh;
    const TreeWind treeWind(tree, tube.windSeed);
    WindAttributes wind;
    wind.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const std::uint32_t p = kept.source[polygonOf[v]];
        const NodeId node = p < polygonNodes.size() && polygonNodes[p] >= 0 &&
                                    static_cast<std::size_t>(polygonNodes[p]) < tree.size()
                                ? polygonNodes[p]
                                : 0;
        const auto phase = static_cast<float>(
            unitFromHash(hashCombine(leafKey(params.seed, kPolygonSalt, p, 0), 1)));
        // buildPolygonMesh's v runs from 1 (the first vertex, the base) to 0 (the farthest).
        const float flutter = 1.0f - (mesh.uvs[v].y() - v0) / (v1 - v0);
        wind.set(v, 1, treeWind.at(node), phase, std::clamp(flutter, 0.0f, 1.0f));
    }
    wind.moveInto(mesh);
    return mesh;
}

}  // namespace ramus
