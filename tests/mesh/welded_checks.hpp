// Checks of the welded tree meshes: topology after welding by position (closed, oriented
// 2-manifold, Euler characteristic, components), volume, degenerate triangles, unit normals,
// triangle–triangle self-intersections over a grid, and distance to the branch capsules; and
// the shipped examples' files and trees they are run on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/mesh.hpp"
#include "ramus/welded_mesher.hpp"

namespace ramus::test {

/// Topology of `mesh` with vertices of bit-identical positions taken as one (seam and cap
/// copies repeat ring positions exactly).
struct Topology {
    std::size_t vertices = 0;  ///< distinct positions used by triangles
    std::size_t edges = 0;     ///< undirected
    std::size_t faces = 0;
    std::size_t components = 0;
    /// Every directed edge once and its reverse once: each edge has exactly two faces, and
    /// they are wound consistently.
    bool closedOriented = false;
    /// Components with an edge that breaks that (closedOriented: none); the others are each
    /// closed and consistently wound.
    std::size_t openComponents = 0;
    /// Where closedOriented: positions whose triangles form more than one fan (surfaces that
    /// touch at a point there, or along an edge: not a 2-manifold).
    std::size_t nonManifoldVertices = 0;
    long long euler() const {
        return static_cast<long long>(vertices) - static_cast<long long>(edges) +
               static_cast<long long>(faces);
    }
};
Topology analyzeTopology(const Mesh& mesh);

/// Σ over triangles of a·(b×c)/6: the enclosed volume of a closed outward mesh.
double signedVolume(const Mesh& mesh);

/// Smallest 2·area / (longest edge)² over all triangles (0 for a degenerate one; an
/// equilateral triangle has √3/2).
double smallestTriangleShape(const Mesh& mesh);

/// Largest | |normal| − 1 | (infinite if any normal is not finite).
double worstNormalLength(const Mesh& mesh);

/// Pairs of triangles that share no vertex position and intersect (edge of one through the
/// other's interior), found over a uniform grid. Returns the count, up to `limit`.
std::size_t countSelfIntersections(
    const Mesh& mesh, std::size_t limit = 10,
    std::vector<std::pair<std::uint32_t, std::uint32_t>>* pairs = nullptr);

/// Total length of the segments along which the given pairs of triangles meet: the length of
/// the intersection curves, which, unlike the number of pairs, does not grow when the surface
/// is subdivided.
double intersectionLength(const Mesh& mesh,
                          const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs);

/// Signed crossings of rays along ±d from a point with the triangles (+1 where the ray leaves a
/// surface): the winding number of closed outward surfaces there, overlapping ones summed. d is
/// an oblique direction (no plane of a flat plant holds it, so rays do not run along ring
/// edges); in a frame whose x is d the triangles are binned by their (y, z) bounds, so a ray
/// meets only those of its cell.
class RayWinding {
public:
    explicit RayWinding(const Mesh& mesh);
    /// Crossings of the ray from `point` along +d (`sign` = 1) or −d (−1).
    int at(const Vec3& point, int sign) const;

private:
    const Vec3& corner(std::size_t t, int k) const { return points_[indices_[3 * t + k]]; }
    std::pair<long, long> cellOf(const Vec3& p) const;
    Mat3 turn_;
    std::vector<Vec3> points_;
    std::vector<std::uint32_t> indices_;
    Vec3 lo_;
    double cell_ = 1.0;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

/// The tapered capsule of a drawn edge: the round cone (convex hull of two spheres) from the
/// parent's position `a` (radius `ra`) to the node's `b` (radius `rb`).
struct Capsule {
    Vec3 a, b;
    double ra = 0.0, rb = 0.0;
};

/// One capsule per drawn edge of `tree`, radii from `radii` (computeEdgeRadii) as
/// buildTubeMesh uses them: a chain's edge tapers from its parent's radius, the root edge from
/// `rootRadius` (trunkMultiplier × radii[0]).
std::vector<Capsule> branchCapsules(const BranchTree& tree, const std::vector<double>& radii,
                                    double rootRadius);

/// Signed distance to the union of the tree's tapered capsules (branchCapsules); `radius`: of the
/// nearest capsule at the nearest point of its axis; `scale`: the largest such radius among the
/// capsules whose surface is within their own radius of the point (the local branch size: at
/// a junction, the thickest branch meeting there).
struct CapsuleDistance {
    double distance = 0.0;
    double radius = 0.0;
    double scale = 0.0;
};
class CapsuleUnion {
public:
    CapsuleUnion(const BranchTree& tree, const std::vector<double>& radii, double rootRadius)
        : capsules_(branchCapsules(tree, radii, rootRadius)) {}
    CapsuleDistance at(const Vec3& p) const;
    std::size_t size() const { return capsules_.size(); }

private:
    std::vector<Capsule> capsules_;
};

/// Generalized winding number of `mesh` at `p` (≈ 1 inside a closed outward mesh, 0 outside).
double windingNumber(const Mesh& mesh, const Vec3& p);

/// A thick trunk (radius 0.4) with four side branches every 0.1 of height — far closer than the
/// trunk's radius, so their junctions merge — ending in a top at (0, 2.5, 0); returns the top.
NodeId addDenseBranching(BranchTree& tree);

/// Paths of the files in RAMUS_SOURCE_DIR + `dir` (e.g. "/examples/lsystems") whose extension
/// is `extension` (e.g. ".lsys"), sorted.
std::vector<std::string> exampleFiles(const std::string& dir, const std::string& extension);

/// The file name of `path` without folder and extension.
std::string stem(const std::string& path);

/// The tree the L-system file `file` grows at `derivations` (-1: the file's default).
BranchTree growLSystem(const std::string& file, int derivations = -1);

/// The visitor of colonization trees: (name, tree, the welded meshing parameters its config's
/// `mesh` object sets).
using ColonizationTreeVisitor =
    std::function<void(const std::string&, const BranchTree&, const WeldedMeshParams&)>;

/// Calls visit for every tree the colonization config `file` grows (name "<file stem>_<tree
/// index>").
void forEachTreeOf(const std::string& file, const ColonizationTreeVisitor& visit);

/// forEachTreeOf every colonization example (examples/colonize/*.json, sorted).
void forEachColonizationTree(const ColonizationTreeVisitor& visit);

/// Writes `mesh` as <$RAMUS_TEST_OUTPUT>/welded_<name>.glb when the variable is set.
void writeWeldedGlb(const Mesh& mesh, const std::string& name);

}  // namespace ramus::test
