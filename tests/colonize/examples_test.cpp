// Every example in examples/colonize grows, stops well before its iteration limit, reaches
// (nearly) all of its points, meshes, and gives byte-identical GLBs for the same seed.
#include <gtest/gtest.h>

#include <filesystem>

#include "colonize_test_util.hpp"
#include "ramus/colonize.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/scene.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus::testing {
namespace {

std::vector<std::string> exampleFiles() {
    std::vector<std::string> files;
    for (const auto& entry :
         std::filesystem::directory_iterator(RAMUS_SOURCE_DIR "/examples/colonize")) {
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TubeMeshParams meshParams(const ColonizeConfig& c) {
    TubeMeshParams p;
    applyMeshOverrides(c, p);
    return p;
}

std::string growGlb(const ColonizeConfig& config) {
    const ColonizeResult r = growFromConfig(config, configAttractionPoints(config));
    Mesh mesh;
    for (const BranchTree& t : r.trees) appendMesh(mesh, buildTubeMesh(t, meshParams(config)));
    return encodeGlb(makeSingleMeshScene(mesh, "tree"));
}

TEST(ColonizeExamples, ThereAreNine) { EXPECT_EQ(exampleFiles().size(), 9u); }

TEST(ColonizeExamples, EveryExampleGrowsAndStopsOnItsOwn) {
    for (const std::string& file : exampleFiles()) {
        SCOPED_TRACE(file);
        const ColonizeConfig config = loadColonizeConfig(file);
        const std::vector<Vec3> points = configAttractionPoints(config);
        const ColonizeResult r = growFromConfig(config, points);
        EXPECT_LT(r.iterations, config.params.maxIterations);  // stopped on its own
        EXPECT_LT(r.attractorsLeft, r.attractors / 100 + 1);   // reached almost every point
        EXPECT_EQ(r.trees.size(), config.params.roots.size());
        for (const BranchTree& tree : r.trees) {
            EXPECT_GT(tree.size(), 200u);
            for (const BranchNode& n : tree.nodes()) ASSERT_TRUE(n.position.allFinite());
        }
    }
}

TEST(ColonizeExamples, SameConfigAndSeedGiveByteIdenticalGlbs) {
    const std::string out = testOutputDirectory();
    for (const std::string& file : exampleFiles()) {
        SCOPED_TRACE(file);
        const ColonizeConfig config = loadColonizeConfig(file);
        const std::string first = growGlb(config);
        EXPECT_EQ(first, growGlb(config));
        ColonizeConfig reseeded = config;
        reseeded.seed += 1;
        EXPECT_NE(first, growGlb(reseeded));
        if (!out.empty()) {
            const std::string name = std::filesystem::path(file).stem().string();
            writeFileAtomic(out + "/colonize_example_" + name + ".glb", first);
        }
    }
}

TEST(ColonizeExamples, TheSeedsRingStaysInItsPlane) {
    const ColonizeConfig config =
        loadColonizeConfig(RAMUS_SOURCE_DIR "/examples/colonize/fig3_2_ring.json");
    // Seed 002 fig 3.2: N = 2000, r = 500, d_i = 100, d_k = 20, D = 15, T = 0, angle reduction.
    ASSERT_EQ(config.envelopes.size(), 1u);
    EXPECT_EQ(config.envelopes[0].pointCount, 2000u);
    EXPECT_EQ(config.envelopes[0].shape.radius, 500);
    EXPECT_EQ(config.params.influenceRadius, 100);
    EXPECT_EQ(config.params.killRadius, 20);
    EXPECT_EQ(config.params.step, 15);
    EXPECT_EQ(config.params.tropism, Vec3::Zero());
    EXPECT_TRUE(config.reduceBranchAngles);
    EXPECT_EQ(config.mesh.leafRadius, 1);
    EXPECT_EQ(config.mesh.radiusExponent, 2);
    const ColonizeResult r = growFromConfig(config, configAttractionPoints(config));
    for (const BranchNode& n : r.trees[0].nodes()) ASSERT_EQ(n.position.z(), 0.0);
}

TEST(ColonizeExamples, TheObstacleExampleNeverGrowsIntoItsObstacle) {
    const ColonizeConfig config =
        loadColonizeConfig(RAMUS_SOURCE_DIR "/examples/colonize/obstacle.json");
    ASSERT_EQ(config.obstacles.size(), 1u);
    ColonizeConfig raw = config;  // before post-processing moves nodes
    raw.reduceBranchAngles = false;
    raw.curveReduction = 0.0;
    const ColonizeResult r = growFromConfig(raw, configAttractionPoints(raw));
    const BranchTree& tree = r.trees[0];
    for (const BranchNode& n : tree.nodes()) {
        if (n.parent == kNoNode) continue;
        ASSERT_FALSE(
            segmentHitsShape(config.obstacles[0], tree.node(n.parent).position, n.position));
    }
}

// Several trunks of one asset: each root grows its own stem up into the shared crown and takes
// a fair share of it (competition splits the points instead of one stem taking all).
TEST(ColonizeExamples, EveryTrunkOfTheMultiTrunkExampleReachesTheSharedCrown) {
    const ColonizeConfig config =
        loadColonizeConfig(RAMUS_SOURCE_DIR "/examples/colonize/multi_trunk.json");
    ASSERT_EQ(config.params.roots.size(), 3u);
    const ColonizeResult r = growFromConfig(config, configAttractionPoints(config));
    ASSERT_EQ(r.trees.size(), 3u);
    std::size_t total = 0;
    for (const BranchTree& tree : r.trees) total += tree.size();
    for (std::size_t t = 0; t < r.trees.size(); ++t) {
        SCOPED_TRACE(t);
        const BranchTree& tree = r.trees[t];
        EXPECT_EQ(tree.node(0).position, config.params.roots[t]);
        EXPECT_GT(tree.bounds().max.y(), 420.0 - 260.0);  // into the crown's lower half at least
        EXPECT_GT(tree.size(), total / 10);               // a fair share, not a stub
    }
}

}  // namespace
}  // namespace ramus::testing
