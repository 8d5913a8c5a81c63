// End-to-end checks of `ramus colonize` (runs the real binary, see tests/cli/cli_test_util.hpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.hpp"

namespace ramus::testing {
namespace {

const std::string kRing = "'" RAMUS_SOURCE_DIR "/examples/colonize/fig3_2_ring.json'";
const std::string kHedge = "'" RAMUS_SOURCE_DIR "/examples/colonize/hedge.json'";

TEST(ColonizeCli, WritesEveryRequestedOutputAndPrintsStats) {
    const auto dir = scratchDirectory("colonize_outputs");
    const CommandResult r =
        runRamus("colonize " + kRing + " -o '" + (dir / "t.glb").string() + "' --tree-json '" +
                     (dir / "t.json").string() + "' --png '" + (dir / "t.png").string() +
                     "' --size 64x64 --stats",
                 dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto stats = nlohmann::json::parse(r.out);
    for (const char* key : {"attractors", "attractors_left", "iterations", "nodes", "triangles",
                            "grow_seconds", "mesh_seconds"}) {
        EXPECT_TRUE(stats.contains(key)) << key;
    }
    EXPECT_EQ(stats["attractors"], 2000);
    EXPECT_GT(stats["nodes"].get<int>(), 500);
    EXPECT_GT(stats["triangles"].get<int>(), 1000);
    EXPECT_TRUE(std::filesystem::file_size(dir / "t.glb") > 1000);
    EXPECT_TRUE(std::filesystem::file_size(dir / "t.png") > 100);
    const auto tree = nlohmann::json::parse(readFile((dir / "t.json").string()));
    EXPECT_EQ(tree["nodes"].size(), stats["nodes"].get<std::size_t>());
    // The seed's parameters put the kill radius below 2 x step: the user is told.
    EXPECT_NE(r.err.find("warning: kill radius 20 is below 2 x step"), std::string::npos);
    keepForValidation(dir / "t.glb", "colonize_cli_ring.glb");
}

TEST(ColonizeCli, SeveralTreesGoIntoOneModelAndATreesArray) {
    const auto dir = scratchDirectory("colonize_forest");
    const CommandResult r = runRamus("colonize " + kHedge + " -o '" + (dir / "h.obj").string() +
                                         "' --tree-json '" + (dir / "h.json").string() + "'",
                                     dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "h.mtl"));
    const auto trees = nlohmann::json::parse(readFile((dir / "h.json").string()));
    ASSERT_TRUE(trees.contains("trees"));
    EXPECT_EQ(trees["trees"].size(), 5u);
}

TEST(ColonizeCli, SameSeedGivesByteIdenticalFilesOtherSeedsDiffer) {
    const auto dir = scratchDirectory("colonize_seed");
    for (const char* name : {"a", "b", "c"}) {
        const std::string seed = std::string(name) == "c" ? "8" : "7";
        const CommandResult r = runRamus("colonize " + kRing + " --seed " + seed + " -o '" +
                                             (dir / (std::string(name) + ".glb")).string() + "'",
                                         dir);
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    EXPECT_EQ(readFile((dir / "a.glb").string()), readFile((dir / "b.glb").string()));
    EXPECT_NE(readFile((dir / "a.glb").string()), readFile((dir / "c.glb").string()));
}

TEST(ColonizeCli, PointsFromAFileAreAdded) {
    const auto dir = scratchDirectory("colonize_points");
    writeFileAtomic((dir / "extra.csv").string(), "x,y,z\n0,1200,0\n0,1230,0\n");
    const CommandResult r = runRamus(
        "colonize " + kRing + " --points '" + (dir / "extra.csv").string() + "' --stats", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["attractors"], 2002);
}

TEST(ColonizeCli, ABadConfigValueExitsWithOneAndNamesTheKey) {
    const auto dir = scratchDirectory("colonize_bad");
    writeFileAtomic((dir / "bad.json").string(), R"({"step": -1})");
    const CommandResult r = runRamus("colonize '" + (dir / "bad.json").string() + "'", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("bad.json: step: out of range; expected > 0 (model units, D), got -1"),
              std::string::npos)
        << r.err;
}

TEST(ColonizeCli, AnInvalidSeedExitsWithOne) {
    const auto dir = scratchDirectory("colonize_badseed");
    const CommandResult r = runRamus("colonize " + kRing + " --seed x1", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("--seed: invalid seed 'x1'"), std::string::npos);
}

TEST(ColonizeCli, AMissingConfigIsAUsageError) {
    const auto dir = scratchDirectory("colonize_usage");
    EXPECT_EQ(runRamus("colonize", dir).exitCode, 2);
}

}  // namespace
}  // namespace ramus::testing

namespace ramus::testing {
namespace {

TEST(ColonizeCli, TooManyPointsStopBeforeSampling) {
    const auto dir = scratchDirectory("colonize_max_points");
    const CommandResult r = runRamus(
        "colonize " + kRing + " --max-points 1999 -o '" + (dir / "t.glb").string() + "'", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("2000 attraction points, above the limit of 1999"), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "t.glb"));
}

TEST(ColonizeCli, TooManyNodesStopGrowthWithAClearError) {
    const auto dir = scratchDirectory("colonize_max_nodes");
    const CommandResult r = runRamus(
        "colonize " + kRing + " --max-nodes 50 -o '" + (dir / "t.glb").string() + "'", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("node limit of 50 nodes"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "t.glb"));
}

}  // namespace
}  // namespace ramus::testing
