// The asset keys of configs: root systems below the ground, leaves, LODs of every example.
#include <gtest/gtest.h>

#include <filesystem>

#include "colonize_test_util.hpp"
#include "ramus/colonize.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/tree_asset.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus::testing {
namespace {

const std::string kRoots = RAMUS_SOURCE_DIR "/examples/colonize/roots.json";

TEST(RootSystem, PointsBelowTheGroundGrowRootsDownFromTheRootNode) {
    const ColonizeConfig config = loadColonizeConfig(kRoots);
    ASSERT_TRUE(config.hasGround);
    const ColonizeResult r = growFromConfig(config, configAttractionPoints(config));
    ASSERT_EQ(r.trees.size(), 1u);
    const BranchTree& tree = r.trees[0];
    // Every node below the ground descends from a child of the root that is itself below it,
    // and no crown node is.
    std::size_t below = 0;
    for (std::size_t i = 1; i < tree.size(); ++i) {
        NodeId top = static_cast<NodeId>(i);
        while (tree.node(top).parent != 0) top = tree.node(top).parent;
        const bool rootSide = tree.node(top).position.y() < 0.0;
        if (tree.nodes()[i].position.y() < -1e-9) {
            ++below;
            EXPECT_TRUE(rootSide) << "node " << i;
        }
    }
    EXPECT_GT(below, 500u);
    EXPECT_GE(tree.node(0).childCount, 2u);  // the trunk and at least one root
    EXPECT_LT(r.attractorsLeft, r.attractors / 50);
}

TEST(RootSystem, LeavesStayAboveTheGround) {
    const ColonizeConfig config = loadColonizeConfig(kRoots);
    ASSERT_TRUE(config.hasLeaves);
    const ColonizeResult r = growFromConfig(config, configAttractionPoints(config));
    LeafParams leaf = config.leaves;
    leaf.minHeight = config.ground;
    const Mesh leaves = buildLeafMesh(r.trees[0], leaf);
    ASSERT_GT(leaves.vertexCount(), 1000u);
    // Blades start at their base on the bark above y = 0; their tips may tilt a little.
    for (const Vec3f& p : leaves.positions) EXPECT_GT(p.y(), -30.0f);
    std::size_t low = 0;
    for (const Vec3f& p : leaves.positions) low += p.y() < 0.0f;
    EXPECT_EQ(low, 0u);
}

TEST(RootSystem, ConfigErrorsNameTheKey) {
    auto error = [](const std::string& text) {
        try {
            parseColonizeConfig(text, "t.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error(R"({"root_growth": {"step": 2}})").find("root_growth: needs \"ground\""),
              std::string::npos);
    EXPECT_NE(error(R"({"ground": 0, "root_growth": {"stpe": 2}})").find("root_growth.stpe"),
              std::string::npos);
    EXPECT_NE(error(R"({"ground": 0, "root_growth": {"step": -2}})").find("root_growth.step"),
              std::string::npos);
    EXPECT_NE(error(R"({"ground": "low"})").find("ground"), std::string::npos);
    EXPECT_NE(error(R"({"leaves": {"per_tip": -1}})").find("leaves.per_tip"), std::string::npos);
    EXPECT_NE(error(R"({"leaves": {"shape": "round"}})").find("leaves.shape"), std::string::npos);
    EXPECT_NE(error(R"({"leaves": {"atlas": [0.5, 0, 0.2, 1]}})").find("leaves.atlas"),
              std::string::npos);
    EXPECT_NE(error(R"({"mesh": {"lods": [1, 0]}})").find("mesh.lods[1]"), std::string::npos);
    EXPECT_NE(error(R"({"mesh": {"wind": 1}})").find("mesh.wind"), std::string::npos);
}

TEST(RootSystem, WithoutGroundEveryPointFeedsTheCrownAsBefore) {
    ColonizeConfig config = loadColonizeConfig(kRoots);
    config.hasGround = false;
    const ColonizeResult r = growFromConfig(config, configAttractionPoints(config));
    const ColonizeResult plain = colonize(config.params, configAttractionPoints(config));
    EXPECT_EQ(r.attractors, plain.attractors);
}

// Issue 9: LOD triangle counts within 10 % of their targets on the examples, with leaves.
TEST(ColonizeExamplesAssets, LodsOfEveryExampleAreWithinTenPercentOfTheirTargets) {
    for (const auto& entry :
         std::filesystem::directory_iterator(RAMUS_SOURCE_DIR "/examples/colonize")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const ColonizeConfig config = loadColonizeConfig(entry.path().string());
        const ColonizeResult r = growFromConfig(config, configAttractionPoints(config));
        TreeMeshParams params;
        applyMeshOverrides(config, params.tube);
        params.tube.windAttributes = true;
        params.leaves = true;
        if (config.hasLeaves) params.leaf = config.leaves;
        std::vector<TreeMeshInput> inputs;
        for (const BranchTree& t : r.trees) inputs.push_back({&t, {}, {}, {}});
        const double ratios[] = {1.0, 0.4, 0.15};
        const std::vector<TreeLod> lods = buildTreeLods(inputs, params, ratios);
        const double full = static_cast<double>(lods[0].mesh.triangleCount());
        for (const TreeLod& lod : lods) {
            EXPECT_NEAR(static_cast<double>(lod.mesh.triangleCount()), lod.ratio * full,
                        0.10 * lod.ratio * full)
                << lod.mesh.name;
        }
        const std::string out = testOutputDirectory();
        if (!out.empty() && entry.path().stem() == "roots") {
            Scene scene;
            scene.nodes.push_back(SceneNode{"tree"});
            for (std::size_t i = 0; i < lods.size(); ++i) {
                scene.meshes.push_back(lods[i].mesh);
                SceneNode node{lods[i].mesh.name};
                node.parent = 0;
                node.mesh = static_cast<int>(i);
                scene.nodes.push_back(node);
            }
            writeGlb(scene, out + "/colonize_roots_lods.glb");
        }
    }
}

}  // namespace
}  // namespace ramus::testing
