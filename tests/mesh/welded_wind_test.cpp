// Wind data on welded meshes: every vertex carries `_WIND`, `_WIND_PIVOT`, `_WIND_LEAF` within
// their documented ranges (docs/export.md "Wind data"); ring vertices get the branch and the
// distance along it that buildTubeMesh gives a ring there; rings absorbed into a junction move
// with the parent branch; vertices at one position never disagree (the surface cannot tear
// when an engine animates by these values); LODs keep the attributes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "ramus/colonize.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/tree_asset.hpp"
#include "ramus/tree_wind.hpp"
#include "ramus/turtle.hpp"
#include "ramus/welded_mesher.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

constexpr std::uint64_t kSeed = 11;

WeldedMeshParams windParams(int segments) {
    WeldedMeshParams params;
    params.tube.minSegments = params.tube.maxSegments = segments;
    params.tube.windAttributes = true;
    params.tube.windSeed = kSeed;
    return params;
}

struct WindView {
    const VertexAttribute* wind = nullptr;
    const VertexAttribute* pivot = nullptr;
    const VertexAttribute* leaf = nullptr;
    const float* at(std::size_t v) const { return &wind->values[4 * v]; }
    Vec3f pivotAt(std::size_t v) const {
        return Vec3f(pivot->values[3 * v], pivot->values[3 * v + 1], pivot->values[3 * v + 2]);
    }
};

// All three attributes, one value per vertex, finite and in their documented ranges (bark:
// leaf pair (0, 0)); vertices at bit-identical positions (seam and cap copies) carry identical
// values, so any displacement computed from position and attributes keeps the surface closed.
WindView expectWindAttributes(const Mesh& mesh) {
    WindView view;
    view.wind = findAttribute(mesh, kWindAttribute);
    view.pivot = findAttribute(mesh, kWindPivotAttribute);
    view.leaf = findAttribute(mesh, kWindLeafAttribute);
    EXPECT_NE(view.wind, nullptr);
    EXPECT_NE(view.pivot, nullptr);
    EXPECT_NE(view.leaf, nullptr);
    if (view.wind == nullptr || view.pivot == nullptr || view.leaf == nullptr) return {};
    EXPECT_EQ(view.wind->components, 4);
    EXPECT_EQ(view.pivot->components, 3);
    EXPECT_EQ(view.leaf->components, 2);
    const std::size_t n = mesh.vertexCount();
    EXPECT_EQ(view.wind->values.size(), 4 * n);
    EXPECT_EQ(view.pivot->values.size(), 3 * n);
    EXPECT_EQ(view.leaf->values.size(), 2 * n);
    if (view.wind->values.size() != 4 * n || view.pivot->values.size() != 3 * n) return {};
    using Key = std::tuple<float, float, float>;
    std::map<Key, std::size_t> first;  // position → first vertex there
    std::size_t tears = 0;
    for (std::size_t v = 0; v < n; ++v) {
        const float* w = view.at(v);
        const float* pivot = &view.pivot->values[3 * v];
        const bool finite = std::all_of(w, w + 4, [](float x) { return std::isfinite(x); }) &&
                            std::all_of(pivot, pivot + 3, [](float x) { return std::isfinite(x); });
        EXPECT_TRUE(finite) << "vertex " << v;
        EXPECT_GE(w[0], 0.0f);
        EXPECT_EQ(w[0], std::floor(w[0]));
        EXPECT_GE(w[1], 0.0f);
        EXPECT_LT(w[1], 1.0f);
        EXPECT_GE(w[2], 0.0f);
        EXPECT_LE(w[2], 1.0f);
        EXPECT_GE(w[3], 0.0f);
        EXPECT_EQ(view.leaf->values[2 * v], 0.0f);
        EXPECT_EQ(view.leaf->values[2 * v + 1], 0.0f);
        const Vec3f& p = mesh.positions[v];
        const auto [it, fresh] = first.try_emplace(Key{p.x(), p.y(), p.z()}, v);
        if (fresh) continue;
        const float* o = view.at(it->second);
        const bool same = std::equal(w, w + 4, o) && view.pivotAt(v) == view.pivotAt(it->second);
        tears += same ? 0 : 1;
    }
    EXPECT_EQ(tears, 0u) << "vertices at one position with different wind data";
    return view;
}

// A trunk of four unit edges up +Y with a side branch of two unit edges along +X from its
// middle node (0, 2, 0).
BranchTree trunkWithBranch() {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    const NodeId a = tree.addChild(root, Vec3(0, 1, 0));
    const NodeId b = tree.addChild(a, Vec3(0, 2, 0));
    const NodeId c = tree.addChild(b, Vec3(0, 3, 0));  // trunk continues (first child)
    tree.addChild(c, Vec3(0, 4, 0));
    const NodeId s = tree.addChild(b, Vec3(1, 2, 0));  // side branch
    tree.addChild(s, Vec3(2, 2, 0));
    return tree;
}

TEST(WeldedWind, TrunkVerticesHaveLevelZeroAndTheBranchLevelOneWithDistancesAlongThem) {
    const BranchTree tree = trunkWithBranch();
    const WeldedMeshParams params = windParams(8);
    WeldReport report;
    const Mesh mesh = buildWeldedTreeMesh(tree, params, &report);
    ASSERT_EQ(report.junctions, 1u);
    ASSERT_EQ(report.absorbedLimbs, 0u);
    const WindView view = expectWindAttributes(mesh);
    ASSERT_NE(view.wind, nullptr);
    const TreeWind wind(tree, kSeed);
    const float trunkPhase = wind.at(4).phase, branchPhase = wind.at(6).phase;
    ASSERT_NE(trunkPhase, branchPhase);
    std::size_t trunk = 0, branch = 0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const float* w = view.at(v);
        const Vec3f& p = mesh.positions[v];
        SCOPED_TRACE("vertex " + std::to_string(v));
        if (w[0] == 0.0f) {
            // On the trunk: rings are horizontal, so the distance from the base is the height.
            ++trunk;
            EXPECT_LT(std::hypot(p.x(), p.z()), 0.1f);
            EXPECT_EQ(w[1], trunkPhase);
            EXPECT_NEAR(w[3], p.y(), 1e-5f);
            EXPECT_NEAR(w[2], p.y() / 4.0f, 1e-5f);
            EXPECT_EQ(view.pivotAt(v), Vec3f(0, 0, 0));
        } else {
            // On the side branch: rings face +X, the distance is x, from 0 at the trunk axis.
            ASSERT_EQ(w[0], 1.0f);
            ++branch;
            EXPECT_GT(p.x(), 0.0f);
            EXPECT_LT(std::hypot(p.y() - 2.0f, p.z()), 0.1f);
            EXPECT_EQ(w[1], branchPhase);
            EXPECT_NEAR(w[3], p.x(), 1e-5f);
            EXPECT_NEAR(w[2], p.x() / 2.0f, 1e-5f);
            EXPECT_EQ(view.pivotAt(v), Vec3f(0, 2, 0));
        }
    }
    EXPECT_GT(trunk, 0u);
    EXPECT_GT(branch, 0u);
}

TEST(WeldedWind, RingVerticesAgreeWithTheTubeMesherAtTheSameSpot) {
    const BranchTree tree = trunkWithBranch();
    const WeldedMeshParams params = windParams(8);
    const Mesh welded = buildWeldedTreeMesh(tree, params);
    const Mesh tubes = buildTubeMesh(tree, params.tube);
    const WindView w = expectWindAttributes(welded);
    const WindView t = expectWindAttributes(tubes);
    ASSERT_NE(w.wind, nullptr);
    ASSERT_NE(t.wind, nullptr);
    // Rings at the nodes away from the junction (base, y = 1, 3, 4; x = 1, 2) lie where the
    // tube mesher's do: every welded vertex there must carry the tube vertex's values.
    std::size_t matched = 0;
    for (std::size_t v = 0; v < welded.vertexCount(); ++v) {
        for (std::size_t u = 0; u < tubes.vertexCount(); ++u) {
            if ((welded.positions[v] - tubes.positions[u]).norm() > 1e-5f) continue;
            SCOPED_TRACE("welded vertex " + std::to_string(v));
            for (int k = 0; k < 4; ++k) EXPECT_NEAR(w.at(v)[k], t.at(u)[k], 1e-5f);
            EXPECT_LT((w.pivotAt(v) - t.pivotAt(u)).norm(), 1e-6f);
            ++matched;
            break;
        }
    }
    // 8 ring vertices (+ seam copy) at each of those 6 nodes, plus the 3 caps' rims.
    EXPECT_GE(matched, 6u * 8u);
}

TEST(WeldedWind, AbsorbedTipMovesWithItsParentBranch) {
    // As WeldedMesh.ShortTipNextToAJunctionIsAbsorbed, the twig a little longer: it is still
    // taken into the junction but pokes out of the trunk (radius 0.3), so some of its hull
    // points stay vertices.
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero(), 0.3);
    const NodeId a = tree.addChild(root, Vec3(0, 2, 0), 0.3);
    tree.addChild(a, Vec3(0, 4, 0), 0.3);
    const NodeId twig = tree.addChild(a, Vec3(0.32, 2.1, 0), 0.1);
    WeldReport report;
    const Mesh mesh = buildWeldedTreeMesh(tree, windParams(8), &report);
    ASSERT_EQ(report.absorbedLimbs, 1u);
    EXPECT_EQ(report.fallbacks, 0u);
    EXPECT_TRUE(test::analyzeTopology(mesh).closedOriented);
    const WindView view = expectWindAttributes(mesh);
    ASSERT_NE(view.wind, nullptr);
    const TreeWind wind(tree, kSeed);
    ASSERT_NE(wind.at(twig).phase, wind.at(a).phase);
    // Every vertex is the trunk's; the twig's (outside the trunk's radius) take the trunk's
    // values at node a, where the twig leaves it, not their own.
    std::size_t twigVertices = 0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const float* w = view.at(v);
        EXPECT_EQ(w[0], 0.0f);
        EXPECT_EQ(w[1], wind.at(a).phase);
        const Vec3f& p = mesh.positions[v];
        if (std::hypot(p.x(), p.z()) < 0.301f) continue;
        ++twigVertices;
        EXPECT_EQ(w[3], wind.at(a).distance);
        EXPECT_EQ(w[2], wind.at(a).relative);
        EXPECT_EQ(view.pivotAt(v), Vec3f(0, 0, 0));
    }
    EXPECT_GT(twigVertices, 0u);
}

TEST(WeldedWind, MergedJunctionsAndHiddenEdgesKeepTheDataInRange) {
    // As WeldedMesh.BranchNodesCloserThanTheirRingsMergeIntoOneJunction, with a hidden edge
    // and a part above it.
    BranchTree tree;
    const NodeId top = test::addDenseBranching(tree);
    const NodeId gap = tree.addChild(top, Vec3(0, 3.0, 0), 0.3);
    tree.node(gap).hidden = true;
    tree.addChild(tree.addChild(gap, Vec3(0, 4.0, 0), 0.2), Vec3(0.5, 4.5, 0), 0.1);  // trunk
    WeldReport report;
    const Mesh mesh = buildWeldedTreeMesh(tree, windParams(10), &report);
    EXPECT_GT(report.merges, 0u);
    const WindView view = expectWindAttributes(mesh);
    ASSERT_NE(view.wind, nullptr);
    // Distances continue across the hidden edge (TreeWind counts it): the part above starts
    // at 3 (its base ring and cap at node `gap`) and the trunk ends at 4 + √0.5.
    float highest = 0.0f, lowestAbove = 1e9f;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        highest = std::max(highest, view.at(v)[3]);
        if (mesh.positions[v].y() > 2.9f) lowestAbove = std::min(lowestAbove, view.at(v)[3]);
    }
    EXPECT_NEAR(highest, 4.0f + std::sqrt(0.5f), 1e-4f);
    EXPECT_NEAR(lowestAbove, 3.0f, 1e-4f);
}

TEST(WeldedWind, ExamplesCarryWindDataOnEveryVertex) {
    const LSystem system = loadLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/tree_3d.lsys");
    DeriveOptions options;
    options.derivations = 4;
    const BranchTree lsystemTree = interpretTurtle(deriveLSystem(system, options), system.symbols,
                                                   turtleParamsFrom(system.settings))
                                       .tree;
    WeldedMeshParams params;
    params.tube.windAttributes = true;
    const Mesh mesh = buildWeldedTreeMesh(lsystemTree, params);
    ASSERT_GT(mesh.vertexCount(), 0u);
    expectWindAttributes(mesh);
    test::writeWeldedGlb(mesh, "wind_tree_3d");

    const ColonizeConfig config =
        loadColonizeConfig(RAMUS_SOURCE_DIR "/examples/colonize/fig3_2_ring.json");
    const ColonizeResult grown = growFromConfig(config, configAttractionPoints(config));
    ASSERT_FALSE(grown.trees.empty());
    WeldedMeshParams colonizeParams;
    applyMeshOverrides(config, colonizeParams.tube);
    colonizeParams.tube.windAttributes = true;
    expectWindAttributes(buildWeldedTreeMesh(grown.trees.front(), colonizeParams));
}

TEST(WeldedWind, EveryLodOfAWeldedTreeKeepsTheWindData) {
    const BranchTree tree = trunkWithBranch();
    TreeMeshParams params;
    params.weldJunctions = true;
    params.tube.windAttributes = true;
    params.tube.leafRadius = 0.05;
    const TreeMeshInput inputs[] = {{&tree, {}, {}, {}}};
    const double ratios[] = {1.0, 0.5};
    for (const TreeLod& lod : buildTreeLods(inputs, params, ratios)) {
        SCOPED_TRACE(lod.mesh.name);
        expectWindAttributes(lod.mesh);
    }
}

TEST(WeldedWind, WithoutTheFlagTheMeshHasNoCustomAttributes) {
    WeldedMeshParams params = windParams(8);
    params.tube.windAttributes = false;
    EXPECT_TRUE(buildWeldedTreeMesh(trunkWithBranch(), params).attributes.empty());
}

}  // namespace
}  // namespace ramus
