// Tree assets: one bark and one leaves primitive, wind on both, square bark texels with the
// default texture's aspect, and LODs that hit their triangle targets with nested leaves.
#include "ramus/tree_asset.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/rng.hpp"
#include "ramus/scene.hpp"
#include "ramus/tree_textures.hpp"
#include "ramus/tree_wind.hpp"
#include "same_mesh.hpp"

namespace ramus {
namespace {

// A random binary-ish tree: every node of the frontier grows one or two children upwards.
BranchTree bushyTree(int levels, std::uint64_t seed) {
    BranchTree tree;
    Rng rng(seed);
    std::vector<NodeId> frontier{tree.addRoot(Vec3::Zero())};
    tree.addChild(0, Vec3(0, 2, 0));
    frontier = {1};
    for (int l = 0; l < levels; ++l) {
        std::vector<NodeId> next;
        for (NodeId n : frontier) {
            const int children = rng.uniform01() < 0.7 ? 2 : 1;
            for (int c = 0; c < children; ++c) {
                const Vec3 step(rng.uniform(-0.6, 0.6), 1.0, rng.uniform(-0.6, 0.6));
                next.push_back(tree.addChild(n, tree.node(n).position + 0.8 * step));
            }
        }
        frontier = next;
    }
    return tree;
}

TreeMeshParams leafyParams() {
    TreeMeshParams p;
    p.leaves = true;
    p.leaf.size = 0.4;
    p.leaf.perLength = 2.0;
    p.tube.windAttributes = true;
    return p;
}

TEST(TreeAsset, ForestOfTwoTreesHasOneBarkAndOneLeavesPrimitiveWithWind) {
    const BranchTree a = bushyTree(5, 1), b = bushyTree(5, 2);
    const TreeMeshInput inputs[] = {{&a, {}, {}, {}}, {&b, {}, {}, {}}};
    const Mesh mesh = buildTreeMesh(inputs, leafyParams());
    ASSERT_EQ(mesh.primitives.size(), 2u);
    EXPECT_EQ(mesh.primitives[0].name, "bark");
    EXPECT_EQ(mesh.primitives[1].name, "leaves");
    EXPECT_EQ(mesh.triangleCount(),
              primitiveTriangles(mesh, "bark") + primitiveTriangles(mesh, "leaves"));
    const VertexAttribute* wind = findAttribute(mesh, kWindAttribute);
    ASSERT_NE(wind, nullptr);
    EXPECT_EQ(wind->values.size(), 4 * mesh.vertexCount());
    EXPECT_NE(findAttribute(mesh, kWindLeafAttribute), nullptr);
    if (const char* dir = std::getenv("RAMUS_TEST_OUTPUT"); dir != nullptr && *dir != '\0') {
        TreeMeshParams textured = leafyParams();
        const TreeTextures t = makeTreeTextures();
        textured.tube.material.baseColorTexture = t.barkColor;
        textured.tube.material.normalTexture = t.barkNormal;
        textured.leaf.material.baseColorTexture = t.leafColor;
        textured.leaf.material.alphaMask = true;
        writeGlb(makeSingleMeshScene(buildTreeMesh(inputs, textured), "tree"),
                 std::string(dir) + "/tree_asset_forest_textured.glb");
    }
}

// The trees of a forest are welded and united on threads of their own: the forest is still
// each tree's mesh in the trees' order, and its report the sum of theirs.
TEST(TreeAsset, ForestIsItsTreesInOrderWhenMeshedOnThreads) {
    const BranchTree a = bushyTree(4, 3), b = bushyTree(3, 4), c = bushyTree(4, 5);
    const TreeMeshInput inputs[] = {{&a, {}, {}, {}}, {&b, {}, {}, {}}, {&c, {}, {}, {}}};
    TreeMeshParams params;
    params.tube.leafRadius = 0.12;  // thick enough for neighbouring branches to overlap
    params.weldJunctions = true;
    params.solidUnion = true;
    TreeMeshReport forestReport;
    const Mesh forest = buildTreeMesh(inputs, params, &forestReport);
    Mesh alone;
    alone.name = "tree";
    TreeMeshReport sum;
    for (const TreeMeshInput& input : inputs) {
        TreeMeshReport report;
        appendMesh(alone, buildTreeMesh(std::span(&input, 1), params, &report));
        sum.weldedMeshes += report.weldedMeshes;
        sum.unionsApplied += report.unionsApplied;
        sum.unionAttempts += report.unionAttempts;
        sum.crossingMoves += report.crossingMoves;
        sum.shrunkJunctions += report.shrunkJunctions;
    }
    mergePrimitivesByMaterial(alone);
    test::expectSameMesh(forest, alone, "forest against its trees alone");
    TreeMeshParams oneThread = params;  // as `ramus batch` meshes each item
    oneThread.threads = 1;
    test::expectSameMesh(buildTreeMesh(inputs, oneThread), forest, "forest on one thread");
    EXPECT_EQ(forestReport.weldedMeshes, 3u);
    EXPECT_EQ(forestReport.unionsApplied, 3u);
    EXPECT_EQ(forestReport.weldedMeshes, sum.weldedMeshes);
    EXPECT_EQ(forestReport.unionsApplied, sum.unionsApplied);
    EXPECT_EQ(forestReport.unionAttempts, sum.unionAttempts);
    EXPECT_EQ(forestReport.crossingMoves, sum.crossingMoves);
    EXPECT_EQ(forestReport.shrunkJunctions, sum.shrunkJunctions);
    EXPECT_EQ(forestReport.unionsFailed, 0u);
}

// uvAspect = texture height / width keeps texels square on the bark: along a straight tube of
// radius r and length L, u covers the circumference once (W texels) and v covers
// L / (2πr · aspect), i.e. L / (2πr · aspect) · H texels.
TEST(TreeAsset, DefaultBarkTextureAspectGivesSquareTexels) {
    BranchTree tree;
    tree.addChild(tree.addRoot(Vec3::Zero()), Vec3(0, 10, 0));
    const TreeTextures t = makeTreeTextures();
    TubeMeshParams p;
    p.leafRadius = 0.5;
    p.capTips = false;
    p.uvAspect = t.barkAspect;
    const Mesh mesh = buildTubeMesh(tree, p);
    float vMin = 0.0f;
    for (const Vec2f& uv : mesh.uvs) vMin = std::min(vMin, uv.y());
    const double texelsAround = t.barkColor->width;
    const double texelsAlong = -vMin * t.barkColor->height;
    const double around = 2.0 * kPi * 0.5, along = 10.0;
    EXPECT_NEAR((around / texelsAround) / (along / texelsAlong), 1.0, 1e-5);
}

TEST(TreeAsset, LodsLandWithinTenPercentOfTheirTargets) {
    const BranchTree tree = bushyTree(9, 3);
    const TreeMeshInput input{&tree, {}, {}, {}};
    const double ratios[] = {1.0, 0.6, 0.4, 0.15, 0.05};
    const std::vector<TreeLod> lods = buildTreeLods({&input, 1}, leafyParams(), ratios);
    ASSERT_EQ(lods.size(), 5u);
    const double full = static_cast<double>(lods[0].mesh.triangleCount());
    EXPECT_EQ(lods[0].mesh.triangleCount(),
              buildTreeMesh({&input, 1}, leafyParams()).triangleCount());
    for (const TreeLod& lod : lods) {
        SCOPED_TRACE(lod.mesh.name);
        EXPECT_NEAR(static_cast<double>(lod.mesh.triangleCount()), lod.ratio * full,
                    0.10 * lod.ratio * full);
        EXPECT_EQ(lod.targetTriangles, static_cast<std::size_t>(std::round(lod.ratio * full)));
        EXPECT_NE(findAttribute(lod.mesh, kWindAttribute), nullptr);
        for (const MeshPrimitive& p : lod.mesh.primitives) EXPECT_GT(p.indexCount, 0u);
    }
    EXPECT_EQ(lods[1].mesh.name, "tree_LOD1");
    // Lower levels thin (or card) the leaves and reduce the bark.
    EXPECT_LT(primitiveTriangles(lods[3].mesh, "bark"), primitiveTriangles(lods[0].mesh, "bark"));
    EXPECT_LT(primitiveTriangles(lods[3].mesh, "leaves"),
              primitiveTriangles(lods[0].mesh, "leaves"));
}

// The levels are planned and meshed on threads of their own: each is the level built alone, and
// the report adds theirs up in order.
// (Welded, not united: the same threads; SolidUnion.UnitedLods… unites levels.)
TEST(TreeAsset, LodLevelsMeshedOnThreadsAreEachLevelAlone) {
    const BranchTree a = bushyTree(6, 7), b = bushyTree(5, 8);
    const TreeMeshInput inputs[] = {{&a, {}, {}, {}}, {&b, {}, {}, {}}};
    TreeMeshParams params;
    params.tube.leafRadius = 0.12;
    params.weldJunctions = true;
    const double ratios[] = {1.0, 0.4, 0.15};
    TreeMeshReport report;
    const std::vector<TreeLod> lods = buildTreeLods(inputs, params, ratios, &report);
    ASSERT_EQ(lods.size(), 3u);
    TreeMeshReport sum;
    for (std::size_t i = 0; i < lods.size(); ++i) {
        TreeMeshReport alone;
        std::vector<TreeLod> level = buildTreeLods(inputs, params, {&ratios[i], 1}, &alone);
        level[0].mesh.name = lods[i].mesh.name;
        test::expectSameMesh(lods[i].mesh, level[0].mesh, "level " + std::to_string(i));
        EXPECT_EQ(lods[i].prunedNodes, level[0].prunedNodes);
        sum.weldedMeshes += alone.weldedMeshes;
        sum.shrunkJunctions += alone.shrunkJunctions;
    }
    TreeMeshParams oneThread = params;
    oneThread.threads = 1;
    const std::vector<TreeLod> sequential = buildTreeLods(inputs, oneThread, ratios);
    ASSERT_EQ(sequential.size(), lods.size());
    for (std::size_t i = 0; i < lods.size(); ++i) {
        test::expectSameMesh(sequential[i].mesh, lods[i].mesh, "level on one thread");
    }
    EXPECT_EQ(report.weldedMeshes, 6u);  // two trees, three levels
    EXPECT_EQ(report.weldedMeshes, sum.weldedMeshes);
    EXPECT_GT(report.shrunkJunctions, 0u);
    EXPECT_EQ(report.shrunkJunctions, sum.shrunkJunctions);
    EXPECT_GT(lods[0].mesh.triangleCount(), lods[2].mesh.triangleCount());
}

TEST(TreeAsset, LodRatiosOutsideTheUnitIntervalAreErrors) {
    const BranchTree tree = bushyTree(3, 1);
    const TreeMeshInput input{&tree, {}, {}, {}};
    const double bad[] = {1.0, 0.0};
    EXPECT_THROW(buildTreeLods({&input, 1}, {}, bad), Error);
    const double over[] = {1.5};
    EXPECT_THROW(buildTreeLods({&input, 1}, {}, over), Error);
    EXPECT_THROW(buildTreeLods({&input, 1}, {}, {}), Error);
}

}  // namespace
}  // namespace ramus
