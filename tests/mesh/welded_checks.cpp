#include "welded_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "ramus/colonize.hpp"
#include "ramus/export.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/scene.hpp"
#include "ramus/turtle.hpp"

namespace ramus::test {
namespace {

std::uint64_t positionKey(const Vec3f& p) {
    std::uint32_t bits[3];
    std::memcpy(bits, p.data(), sizeof bits);
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
    return h;
}

// Canonical id per vertex: the first vertex with a bit-identical position.
std::vector<std::uint32_t> weldIds(const Mesh& mesh) {
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> buckets;
    std::vector<std::uint32_t> id(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
        auto& bucket = buckets[positionKey(mesh.positions[i])];
        id[i] = i;
        for (std::uint32_t j : bucket) {
            if (mesh.positions[j] == mesh.positions[i]) id[i] = j;
        }
        if (id[i] == i) bucket.push_back(i);
    }
    return id;
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

Vec3 corner(const Mesh& mesh, std::size_t t, int k) {
    return mesh.positions[mesh.indices[3 * t + static_cast<std::size_t>(k)]].cast<double>();
}

std::array<Vec3, 3> corners(const Mesh& mesh, std::size_t t) {
    return {corner(mesh, t, 0), corner(mesh, t, 1), corner(mesh, t, 2)};
}

// Where segment p→q crosses the interior of triangle (a, b, c), as a fraction of the way from
// p (Möller–Trumbore, strict); negative if it does not.
double segmentHitOnTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                            const Vec3& c) {
    const Vec3 d = q - p;
    const Vec3 e1 = b - a;
    const Vec3 e2 = c - a;
    const Vec3 h = d.cross(e2);
    const double det = e1.dot(h);
    const double scale = e1.norm() * e2.norm() * d.norm();
    if (std::abs(det) <= 1e-12 * scale) return -1.0;  // parallel: not counted
    const double inv = 1.0 / det;
    const Vec3 s = p - a;
    const double u = s.dot(h) * inv;
    const Vec3 qv = s.cross(e1);
    const double v = d.dot(qv) * inv;
    const double t = e2.dot(qv) * inv;
    constexpr double kEps = 1e-7;
    const bool hit = u > kEps && v > kEps && u + v < 1.0 - kEps && t > kEps && t < 1.0 - kEps;
    return hit ? t : -1.0;
}

// Calls visit(point) where an edge of triangle `a` crosses the interior of triangle `b`.
template <typename Visit>
void forEachEdgeThrough(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b, Visit visit) {
    for (int e = 0; e < 3; ++e) {
        const Vec3& p = a[e];
        const Vec3& q = a[(e + 1) % 3];
        const double t = segmentHitOnTriangle(p, q, b[0], b[1], b[2]);
        if (t >= 0.0) visit(Vec3(p + t * (q - p)));
    }
}

bool trianglesIntersect(const Mesh& mesh, std::size_t s, std::size_t t) {
    const std::array<Vec3, 3> a = corners(mesh, s);
    const std::array<Vec3, 3> b = corners(mesh, t);
    bool hit = false;
    auto found = [&](const Vec3&) { hit = true; };
    forEachEdgeThrough(a, b, found);
    forEachEdgeThrough(b, a, found);
    return hit;
}

}  // namespace

Topology analyzeTopology(const Mesh& mesh) {
    const std::vector<std::uint32_t> id = weldIds(mesh);
    Topology top;
    top.faces = mesh.triangleCount();
    std::unordered_map<std::uint64_t, int> directed;
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<std::uint8_t> used(mesh.positions.size(), 0);
    std::vector<std::uint8_t> bad(mesh.positions.size(), 0);  // on an edge that fails
    for (std::size_t t = 0; t < top.faces; ++t) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = id[mesh.indices[3 * t + e]];
            const std::uint32_t b = id[mesh.indices[3 * t + (e + 1) % 3]];
            if (a == b) bad[a] = 1;
            used[a] = 1;
            if (++directed[(std::uint64_t{a} << 32) | b] > 1) bad[a] = 1;
            parent[findRoot(parent, a)] = findRoot(parent, b);
        }
    }
    for (const auto& [edge, count] : directed) {
        const std::uint64_t reverse = (edge << 32) | (edge >> 32);
        if (directed.find(reverse) == directed.end()) bad[edge >> 32] = 1;
    }
    top.edges = (directed.size() + 1) / 2;
    std::vector<std::uint8_t> open(mesh.positions.size(), 0);  // per component root
    for (std::uint32_t v = 0; v < used.size(); ++v) {
        if (!used[v]) continue;
        ++top.vertices;
        const std::uint32_t root = findRoot(parent, v);
        if (root == v) ++top.components;
        if (bad[v] && !open[root]) open[root] = 1, ++top.openComponents;
    }
    top.closedOriented = top.openComponents == 0;
    if (!top.closedOriented) return top;
    // Fans: the corners at a position joined across each edge from it with the twin's corner
    // there; a position with more than one fan is where surfaces touch.
    std::unordered_map<std::uint64_t, std::uint32_t> cornerOfEdge;  // a→b → the corner at a
    auto next = [](std::uint32_t c) { return c - c % 3 + (c % 3 + 1) % 3; };
    for (std::uint32_t c = 0; c < mesh.indices.size(); ++c) {
        cornerOfEdge[std::uint64_t{id[mesh.indices[c]]} << 32 | id[mesh.indices[next(c)]]] = c;
    }
    std::vector<std::uint32_t> fan(mesh.indices.size());
    std::iota(fan.begin(), fan.end(), 0u);
    for (std::uint32_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t a = id[mesh.indices[c]], b = id[mesh.indices[next(c)]];
        const std::uint32_t twin = cornerOfEdge.at(std::uint64_t{b} << 32 | a);  // at b
        fan[findRoot(fan, c)] = findRoot(fan, next(twin));
    }
    std::vector<std::uint32_t> firstFan(mesh.positions.size(),
                                        std::numeric_limits<std::uint32_t>::max());
    std::vector<std::uint8_t> counted(mesh.positions.size(), 0);
    for (std::uint32_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t a = id[mesh.indices[c]];
        const std::uint32_t root = findRoot(fan, c);
        if (firstFan[a] == std::numeric_limits<std::uint32_t>::max()) firstFan[a] = root;
        if (firstFan[a] != root && !counted[a]) counted[a] = 1, ++top.nonManifoldVertices;
    }
    return top;
}

double signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        volume += corner(mesh, t, 0).dot(corner(mesh, t, 1).cross(corner(mesh, t, 2))) / 6.0;
    }
    return volume;
}

double smallestTriangleShape(const Mesh& mesh) {
    double worst = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
        const double longest =
            std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
        const double shape = longest > 0.0 ? (b - a).cross(c - a).norm() / longest : 0.0;
        worst = std::min(worst, shape);
    }
    return worst;
}

double worstNormalLength(const Mesh& mesh) {
    double worst = 0.0;
    for (const Vec3f& n : mesh.normals) {
        if (!n.allFinite()) return std::numeric_limits<double>::infinity();
        worst = std::max(worst, std::abs(static_cast<double>(n.norm()) - 1.0));
    }
    return worst;
}

std::size_t countSelfIntersections(const Mesh& mesh, std::size_t limit,
                                   std::vector<std::pair<std::uint32_t, std::uint32_t>>* pairs) {
    const std::size_t count = mesh.triangleCount();
    if (count == 0) return 0;
    const std::vector<std::uint32_t> id = weldIds(mesh);
    // Cell size: the mean triangle extent, so a triangle covers a few cells.
    std::vector<Aabb> boxes(count);
    double mean = 0.0;
    Aabb all;
    for (std::size_t t = 0; t < count; ++t) {
        for (int k = 0; k < 3; ++k) boxes[t].add(corner(mesh, t, k));
        mean += boxes[t].extent().maxCoeff();
        all.add(boxes[t].min);
        all.add(boxes[t].max);
    }
    const double cell = std::max(mean / static_cast<double>(count), 1e-12);
    auto cellOf = [&](const Vec3& p) {
        return ((p - all.min) / cell).array().floor().cast<long long>().eval();
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    auto cellKey = [](long long x, long long y, long long z) {
        return (static_cast<std::uint64_t>(x) * 73856093ull) ^
               (static_cast<std::uint64_t>(y) * 19349663ull) ^
               (static_cast<std::uint64_t>(z) * 83492791ull);
    };
    for (std::size_t t = 0; t < count; ++t) {
        const auto lo = cellOf(boxes[t].min), hi = cellOf(boxes[t].max);
        for (long long x = lo[0]; x <= hi[0]; ++x)
            for (long long y = lo[1]; y <= hi[1]; ++y)
                for (long long z = lo[2]; z <= hi[2]; ++z)
                    grid[cellKey(x, y, z)].push_back(static_cast<std::uint32_t>(t));
    }
    std::size_t found = 0;
    for (const auto& [key, list] : grid) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            for (std::size_t j = i + 1; j < list.size(); ++j) {
                const std::uint32_t s = list[i], t = list[j];
                // Test each pair once: in the cell of the lower corner of the boxes' overlap.
                const Vec3 lo = boxes[s].min.cwiseMax(boxes[t].min);
                const Vec3 hi = boxes[s].max.cwiseMin(boxes[t].max);
                if ((lo.array() > hi.array()).any()) continue;
                const auto c = cellOf(lo);
                if (cellKey(c[0], c[1], c[2]) != key) continue;
                bool shared = false;
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        shared =
                            shared || id[mesh.indices[3 * s + a]] == id[mesh.indices[3 * t + b]];
                if (shared || !trianglesIntersect(mesh, s, t)) continue;
                if (pairs != nullptr) pairs->emplace_back(s, t);
                if (++found >= limit) return found;
            }
        }
    }
    return found;
}

double intersectionLength(const Mesh& mesh,
                          const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
    double length = 0.0;
    std::vector<Vec3> points;  // where an edge of either triangle passes through the other
    auto add = [&](const Vec3& p) { points.push_back(p); };
    for (const auto& [s, t] : pairs) {
        const std::array<Vec3, 3> a = corners(mesh, s);
        const std::array<Vec3, 3> b = corners(mesh, t);
        points.clear();
        forEachEdgeThrough(a, b, add);
        forEachEdgeThrough(b, a, add);
        double longest = 0.0;
        for (const Vec3& p : points) {
            for (const Vec3& q : points) longest = std::max(longest, (p - q).norm());
        }
        length += longest;
    }
    return length;
}

namespace {
std::uint64_t planeCellKey(long y, long z) {
    return static_cast<std::uint64_t>(y) << 32 ^ static_cast<std::uint32_t>(z);
}
}  // namespace

RayWinding::RayWinding(const Mesh& mesh)
    : turn_(Eigen::AngleAxisd(0.7, Vec3(0.3, 0.5, 0.81).normalized()).toRotationMatrix()) {
    points_.reserve(mesh.positions.size());
    for (const Vec3f& p : mesh.positions) points_.push_back(turn_ * p.cast<double>());
    indices_ = mesh.indices;
    Aabb box;
    for (const Vec3& p : points_) box.add(p);
    lo_ = box.min;
    cell_ = std::max(box.extent().maxCoeff() / 256.0, 1e-9);
    for (std::size_t t = 0; t < indices_.size() / 3; ++t) {
        Aabb tri;
        for (int k = 0; k < 3; ++k) tri.add(corner(t, k));
        const auto [y0, z0] = cellOf(tri.min);
        const auto [y1, z1] = cellOf(tri.max);
        for (long y = y0; y <= y1; ++y)
            for (long z = z0; z <= z1; ++z) cells_[planeCellKey(y, z)].push_back(t);
    }
}

int RayWinding::at(const Vec3& point, int sign) const {
    const Vec3 p = turn_ * point;
    const auto [y, z] = cellOf(p);
    const auto found = cells_.find(planeCellKey(y, z));
    if (found == cells_.end()) return 0;
    int winding = 0;
    for (std::size_t t : found->second) {
        const Vec3 a = corner(t, 0) - p, b = corner(t, 1) - p, c = corner(t, 2) - p;
        // Where the ray's line meets the plane of (a, b, c) inside the triangle, by the
        // signs of the (y, z) edge functions; the crossing's x decides the ray's side.
        const double ea = b.y() * c.z() - b.z() * c.y();
        const double eb = c.y() * a.z() - c.z() * a.y();
        const double ec = a.y() * b.z() - a.z() * b.y();
        if (!((ea > 0 && eb > 0 && ec > 0) || (ea < 0 && eb < 0 && ec < 0))) continue;
        const double x = (ea * a.x() + eb * b.x() + ec * c.x()) / (ea + eb + ec);
        if (x * sign <= 0) continue;
        const double normalX = (b - a).cross(c - a).x();
        winding += (normalX * sign > 0) ? 1 : -1;
    }
    return winding;
}

std::pair<long, long> RayWinding::cellOf(const Vec3& p) const {
    return {static_cast<long>(std::floor((p.y() - lo_.y()) / cell_)),
            static_cast<long>(std::floor((p.z() - lo_.z()) / cell_))};
}

std::vector<Capsule> branchCapsules(const BranchTree& tree, const std::vector<double>& radii,
                                    double rootRadius) {
    std::vector<Capsule> capsules;
    for (std::size_t i = 1; i < tree.size(); ++i) {
        const BranchNode& node = tree.nodes()[i];
        if (node.hidden) continue;
        const auto parent = static_cast<std::size_t>(node.parent);
        // A chain's edge tapers from its parent's radius; the root edge from the trunk radius.
        const bool continues = tree.nodes()[parent].firstChild == static_cast<NodeId>(i) &&
                               !tree.nodes()[parent].hidden;
        capsules.push_back({tree.nodes()[parent].position, node.position,
                            continues ? (parent == 0 ? rootRadius : radii[parent]) : radii[i],
                            radii[i]});
    }
    return capsules;
}

// Round cone (Quilez): exact distance to the convex hull of two spheres.
CapsuleDistance CapsuleUnion::at(const Vec3& p) const {
    CapsuleDistance best{std::numeric_limits<double>::infinity(), 0.0, 0.0};
    for (const Capsule& capsule : capsules_) {
        const Vec3 ba = capsule.b - capsule.a;
        const double l2 = ba.squaredNorm();
        const double r1 = capsule.ra, r2 = capsule.rb;
        double d = 0.0;
        double s = 0.0;
        const Vec3 pa = p - capsule.a;
        if (l2 <= (r1 - r2) * (r1 - r2)) {
            d = r1 >= r2 ? pa.norm() - r1 : (p - capsule.b).norm() - r2;
            s = r1 >= r2 ? 0.0 : 1.0;
        } else {
            const double rr = r1 - r2;
            const double a2 = l2 - rr * rr;
            const double y = pa.dot(ba);
            const double z = y - l2;
            const double x2 = (pa * l2 - ba * y).squaredNorm();
            const double y2 = y * y * l2;
            const double z2 = z * z * l2;
            const double k = (rr > 0 ? 1.0 : rr < 0 ? -1.0 : 0.0) * rr * rr * x2;
            const double sz = z > 0 ? 1.0 : z < 0 ? -1.0 : 0.0;
            const double sy = y > 0 ? 1.0 : y < 0 ? -1.0 : 0.0;
            if (sz * a2 * z2 > k) {
                d = std::sqrt(x2 + z2) / l2 - r2;
            } else if (sy * a2 * y2 < k) {
                d = std::sqrt(x2 + y2) / l2 - r1;
            } else {
                d = (std::sqrt(x2 * a2 / l2) + y * rr) / l2 - r1;
            }
            s = std::clamp(y / l2, 0.0, 1.0);
        }
        const double r = r1 + s * (r2 - r1);
        if (d < best.distance) best.distance = d, best.radius = r;
        if (d <= r) best.scale = std::max(best.scale, r);
    }
    best.scale = std::max(best.scale, best.radius);
    return best;
}

// Van Oosterom–Strackee solid angles, summed over triangles, over 4π.
double windingNumber(const Mesh& mesh, const Vec3& p) {
    double total = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 a = corner(mesh, t, 0) - p, b = corner(mesh, t, 1) - p,
                   c = corner(mesh, t, 2) - p;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        const double numerator = a.dot(b.cross(c));
        const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        total += 2.0 * std::atan2(numerator, denominator);
    }
    return total / (4.0 * kPi);
}

NodeId addDenseBranching(BranchTree& tree) {
    NodeId node = tree.addRoot(Vec3::Zero(), 0.4);
    node = tree.addChild(node, Vec3(0, 1, 0), 0.4);
    for (int i = 0; i < 4; ++i) {
        const double a = degToRad(137.5 * i);
        const NodeId next = tree.addChild(node, Vec3(0, 1.1 + 0.1 * i, 0), 0.38);
        tree.addChild(node, Vec3(1.2 * std::cos(a), 1.5 + 0.1 * i, 1.2 * std::sin(a)), 0.08);
        node = next;
    }
    return tree.addChild(node, Vec3(0, 2.5, 0), 0.3);
}

std::vector<std::string> exampleFiles(const std::string& dir, const std::string& extension) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(RAMUS_SOURCE_DIR + dir)) {
        if (entry.path().extension() == extension) files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

BranchTree growLSystem(const std::string& file, int derivations) {
    const LSystem system = loadLSystem(file);
    DeriveOptions options;
    options.derivations = derivations;
    const ModuleString word = deriveLSystem(system, options);
    return interpretTurtle(word, system.symbols, turtleParamsFrom(system.settings)).tree;
}

void forEachTreeOf(const std::string& file, const ColonizationTreeVisitor& visit) {
    const ColonizeConfig config = loadColonizeConfig(file);
    const ColonizeResult result = growFromConfig(config, configAttractionPoints(config));
    WeldedMeshParams params;
    applyMeshOverrides(config, params.tube);
    for (std::size_t t = 0; t < result.trees.size(); ++t) {
        visit(stem(file) + "_" + std::to_string(t), result.trees[t], params);
    }
}

void forEachColonizationTree(const ColonizationTreeVisitor& visit) {
    for (const std::string& file : exampleFiles("/examples/colonize", ".json")) {
        forEachTreeOf(file, visit);
    }
}

void writeWeldedGlb(const Mesh& mesh, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir == nullptr || *dir == '\0' || mesh.positions.empty()) return;
    writeGlb(makeSingleMeshScene(mesh, "tree"), std::string(dir) + "/welded_" + name + ".glb");
}

}  // namespace ramus::test
