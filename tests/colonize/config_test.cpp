// Colonization configs (docs/colonize.md): values, defaults, and one test per error case.
#include <gtest/gtest.h>

#include <filesystem>

#include "ramus/colonize.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"

namespace ramus {
namespace {

std::string errorOf(const std::string& json) {
    try {
        parseColonizeConfig(json, "tree.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(ColonizeConfig, ReadsEveryKey) {
    const ColonizeConfig c = parseColonizeConfig(R"({
        "description": "test", "seed": 42,
        "influence_radius": 50, "kill_radius": 10, "step": 5, "tropism": [0, -0.5, 0.25],
        "max_iterations": 300, "max_degree": 3, "max_branch_depth": 6, "max_no_growth": 4,
        "weighted_growth": true, "angle_reduction": true, "curve_reduction": 0.98,
        "roots": [[0, 0, 0], [100, 0, 0]], "points_file": "scan.xyz",
        "envelopes": [
            {"shape": "sphere", "center": [0, 200, 0], "radius": 80, "points": 500, "seed": 3},
            {"shape": "cylinder", "offset": [1, 2, 3], "radius": 10, "height": 90, "points": 20},
            {"shape": "disc", "center": [0, 0, 0], "radius": 9, "inner_radius": 4, "points": 7}
        ],
        "obstacles": [{"shape": "box", "center": [0, 100, 0], "size": [10, 20, 30]}],
        "mesh": {"leaf_radius": 0.5, "radius_exponent": 2.5, "trunk_multiplier": 1.5,
                 "min_segments": 5, "max_segments": 12, "cap_tips": false}
    })",
                                                 "t.json");
    EXPECT_EQ(c.seed, 42u);
    EXPECT_EQ(c.params.influenceRadius, 50);
    EXPECT_EQ(c.params.killRadius, 10);
    EXPECT_EQ(c.params.step, 5);
    EXPECT_EQ(c.params.tropism, Vec3(0, -0.5, 0.25));
    EXPECT_EQ(c.params.maxIterations, 300);
    EXPECT_EQ(c.params.maxDegree, 3);
    EXPECT_EQ(c.params.maxBranchDepth, 6);
    EXPECT_EQ(c.params.maxNoGrowth, 4);
    EXPECT_TRUE(c.params.weightedGrowth);
    EXPECT_TRUE(c.reduceBranchAngles);
    EXPECT_EQ(c.curveReduction, 0.98);
    ASSERT_EQ(c.params.roots.size(), 2u);
    EXPECT_EQ(c.params.roots[1], Vec3(100, 0, 0));
    EXPECT_EQ(c.pointsFile, "scan.xyz");
    ASSERT_EQ(c.envelopes.size(), 3u);
    EXPECT_EQ(c.envelopes[0].shape.kind, ShapeKind::Sphere);
    EXPECT_EQ(c.envelopes[0].shape.offset, Vec3(0, 200, 0));
    EXPECT_EQ(c.envelopes[0].shape.radius, 80);
    EXPECT_EQ(c.envelopes[0].pointCount, 500u);
    EXPECT_EQ(c.envelopes[0].seed, 3u);
    EXPECT_EQ(c.envelopes[1].shape.offset, Vec3(1, 2, 3));
    EXPECT_EQ(c.envelopes[1].shape.height, 90);
    EXPECT_EQ(c.envelopes[1].seed, 1u);  // default: its index
    EXPECT_EQ(c.envelopes[2].shape.innerRadius, 4);
    ASSERT_EQ(c.obstacles.size(), 1u);
    EXPECT_EQ(c.obstacles[0].size, Vec3(10, 20, 30));
    EXPECT_TRUE(c.mesh.hasLeafRadius);
    EXPECT_EQ(c.mesh.leafRadius, 0.5);
    EXPECT_EQ(c.mesh.radiusExponent, 2.5);
    EXPECT_EQ(c.mesh.trunkMultiplier, 1.5);
    EXPECT_EQ(c.mesh.minSegments, 5);
    EXPECT_EQ(c.mesh.maxSegments, 12);
    EXPECT_FALSE(c.mesh.capTips);
}

TEST(ColonizeConfig, AnEmptyObjectGivesTheDefaults) {
    const ColonizeConfig c = parseColonizeConfig("{}", "t.json");
    const ColonizeParams defaults;
    EXPECT_EQ(c.params.influenceRadius, defaults.influenceRadius);
    EXPECT_EQ(c.params.killRadius, defaults.killRadius);
    EXPECT_EQ(c.params.step, defaults.step);
    ASSERT_EQ(c.params.roots.size(), 1u);
    EXPECT_EQ(c.params.roots[0], Vec3::Zero());
    EXPECT_TRUE(c.envelopes.empty());
    EXPECT_FALSE(c.mesh.hasLeafRadius);
    EXPECT_FALSE(c.reduceBranchAngles);
}

TEST(ColonizeConfig, InvalidJsonNamesTheFile) {
    EXPECT_EQ(errorOf("{\"step\": }").rfind("tree.json:1:10: invalid JSON: ", 0), 0u);
}

TEST(ColonizeConfig, TopLevelMustBeAnObject) {
    EXPECT_EQ(errorOf("[1, 2]"), "tree.json: expected a JSON object at the top level");
}

TEST(ColonizeConfig, UnknownKeysAreErrors) {
    EXPECT_EQ(errorOf(R"({"stepp": 3})").rfind("tree.json: stepp: unknown key; expected one of", 0),
              0u);
}

TEST(ColonizeConfig, ANegativeRadiusNamesKeyRangeAndUnits) {
    EXPECT_EQ(errorOf(R"({"influence_radius": -4})"),
              "tree.json: influence_radius: out of range; expected > 0 (model units, d_i), got -4");
}

TEST(ColonizeConfig, AStringWhereANumberBelongsIsAnError) {
    EXPECT_EQ(errorOf(R"({"step": "15"})"),
              "tree.json: step: expected a number (model units, D), got \"15\"");
}

TEST(ColonizeConfig, KillRadiusMustBeBelowInfluenceRadius) {
    EXPECT_EQ(errorOf(R"({"influence_radius": 10, "kill_radius": 10})"),
              "tree.json: kill_radius: must be below influence_radius 10.0 (model units), got "
              "10.0");
}

TEST(ColonizeConfig, IterationsMustBeAnInteger) {
    EXPECT_EQ(errorOf(R"({"max_iterations": 2.5})"),
              "tree.json: max_iterations: expected an integer (iterations), got 2.5");
}

TEST(ColonizeConfig, NegativeMaxDegreeIsOutOfRange) {
    EXPECT_EQ(errorOf(R"({"max_degree": -1})"),
              "tree.json: max_degree: out of range; expected an integer in [0, 1000000] "
              "(children per node; 0 = unlimited), got -1");
}

TEST(ColonizeConfig, WeightedGrowthNeedsAMaxBranchDepth) {
    EXPECT_EQ(errorOf(R"({"weighted_growth": true})"),
              "tree.json: weighted_growth: needs max_branch_depth >= 1 (the depth where the step "
              "falls to D), got max_branch_depth 0");
}

TEST(ColonizeConfig, CurveReductionMustBeBelowOne) {
    EXPECT_EQ(errorOf(R"({"curve_reduction": 1.5})")
                  .rfind("tree.json: curve_reduction: out of range; expected [0, 0.999999]", 0),
              0u);
}

TEST(ColonizeConfig, TropismNeedsThreeNumbers) {
    EXPECT_EQ(errorOf(R"({"tropism": [0, 1]})"),
              "tree.json: tropism: expected an array of 3 numbers [x, y, z] (unitless vector T "
              "added to the direction sum), got [0,1]");
}

TEST(ColonizeConfig, RootAndRootsTogetherAreAnError) {
    EXPECT_EQ(errorOf(R"({"root": [0, 0, 0], "roots": [[1, 0, 0]]})"),
              "tree.json: roots: give either root or roots");
}

TEST(ColonizeConfig, EmptyRootsAreAnError) {
    EXPECT_EQ(errorOf(R"({"roots": []})"),
              "tree.json: roots: expected a non-empty array of [x, y, z] positions, got []");
}

TEST(ColonizeConfig, ABadEnvelopeValueNamesItsPath) {
    EXPECT_EQ(errorOf(R"({"envelopes": [
        {"shape": "sphere", "radius": 1, "points": 1},
        {"shape": "sphere", "radius": 1, "points": 1},
        {"shape": "sphere", "radius": 0, "points": 1}]})"),
              "tree.json: envelopes[2].radius: out of range; expected > 0 (model units), got 0");
}

TEST(ColonizeConfig, AMissingShapeIsAnError) {
    EXPECT_EQ(errorOf(R"({"envelopes": [{"radius": 1, "points": 1}]})"),
              "tree.json: envelopes[0]: missing key \"shape\"");
}

TEST(ColonizeConfig, AnUnknownShapeListsTheKnownOnes) {
    EXPECT_EQ(errorOf(R"({"envelopes": [{"shape": "torus", "points": 1}]})"),
              "tree.json: envelopes[0].shape: unknown shape \"torus\"; expected sphere, "
              "ellipsoid, box, cylinder, cone, hemisphere, disc or mesh");
}

TEST(ColonizeConfig, AKeyAShapeDoesNotTakeIsAnError) {
    EXPECT_EQ(
        errorOf(R"({"envelopes": [{"shape": "sphere", "radius": 1, "height": 2, "points": 1}]})"),
        "tree.json: envelopes[0].height: unknown key for a sphere; expected one of center, "
        "description, offset, points, radius, seed, shape");
}

TEST(ColonizeConfig, AMissingSizeKeyIsNamed) {
    EXPECT_EQ(errorOf(R"({"envelopes": [{"shape": "cone", "radius": 1, "points": 1}]})"),
              "tree.json: envelopes[0]: missing key \"height\" for a cone");
}

TEST(ColonizeConfig, EnvelopesNeedAPointCount) {
    EXPECT_EQ(errorOf(R"({"envelopes": [{"shape": "sphere", "radius": 1}]})"),
              "tree.json: envelopes[0]: missing key \"points\" (point count N)");
}

TEST(ColonizeConfig, CenterAndOffsetTogetherAreAnError) {
    EXPECT_EQ(errorOf(R"({"envelopes": [{"shape": "sphere", "radius": 1, "points": 1,
                                         "center": [0, 0, 0], "offset": [0, 0, 0]}]})"),
              "tree.json: envelopes[0].offset: give either center or offset, not both");
}

TEST(ColonizeConfig, InnerRadiusMustBeBelowTheRadius) {
    EXPECT_EQ(errorOf(R"({"envelopes": [{"shape": "disc", "radius": 2, "inner_radius": 3,
                                         "points": 1}]})"),
              "tree.json: envelopes[0].inner_radius: must be below radius 2.0 (model units), got "
              "3.0");
}

TEST(ColonizeConfig, ObstaclesTakeNoPointCount) {
    EXPECT_EQ(errorOf(R"({"obstacles": [{"shape": "sphere", "radius": 1, "points": 5}]})"),
              "tree.json: obstacles[0].points: unknown key for a sphere; expected one of center, "
              "description, offset, radius, shape");
}

TEST(ColonizeConfig, ObstacleDiscsCannotHaveAHole) {
    EXPECT_EQ(errorOf(R"({"obstacles": [{"shape": "disc", "radius": 2, "inner_radius": 1}]})"),
              "tree.json: obstacles[0].inner_radius: obstacle discs cannot have a hole");
}

TEST(ColonizeConfig, NegativeSeedIsAnError) {
    EXPECT_EQ(errorOf(R"({"seed": -1})"),
              "tree.json: seed: expected a non-negative integer seed, got -1");
}

TEST(ColonizeConfig, MeshSegmentsMustBeOrdered) {
    EXPECT_EQ(errorOf(R"({"mesh": {"min_segments": 8, "max_segments": 6}})"),
              "tree.json: mesh.max_segments: must be >= mesh.min_segments 8, got 6");
}

TEST(ColonizeConfig, MeshSegmentsHaveARange) {
    EXPECT_EQ(errorOf(R"({"mesh": {"min_segments": 2}})"),
              "tree.json: mesh.min_segments: out of range; expected an integer in [3, 256] (ring "
              "vertices), got 2");
}

TEST(ColonizeConfig, UnknownMeshKeysAreErrors) {
    EXPECT_EQ(errorOf(R"({"mesh": {"leaf": 1}})").rfind("tree.json: mesh.leaf: unknown key", 0),
              0u);
}

TEST(ColonizeConfig, PointsFileIsResolvedNextToTheConfig) {
    const auto dir = std::filesystem::temp_directory_path() / "ramus_colonize_config_test";
    std::filesystem::create_directories(dir);
    writeFileAtomic((dir / "cloud.xyz").string(), "0 10 0\n0 20 0\n");
    writeFileAtomic((dir / "c.json").string(),
                    R"({"points_file": "cloud.xyz", "influence_radius": 30, "kill_radius": 5,
                        "step": 3})");
    const ColonizeConfig config = loadColonizeConfig((dir / "c.json").string());
    EXPECT_EQ(config.pointsFile, (dir / "cloud.xyz").string());
    const std::vector<Vec3> points = configAttractionPoints(config);
    ASSERT_EQ(points.size(), 2u);
    const ColonizeResult r = growFromConfig(config, points);
    EXPECT_EQ(r.attractorsLeft, 0u);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

TEST(ColonizeConfigNonFinite, ANumberBeyondDoubleRangeIsLocatedAtTheNumber) {
    const std::string message = errorOf("{\n  \"step\": 1e999\n}");
    EXPECT_NE(message.find("tree.json:2:"), std::string::npos) << message;
    EXPECT_NE(message.find("number '1e999' is out of range"), std::string::npos) << message;
}

TEST(ColonizeConfigNonFinite, NanAndInfinityAreNotJson) {
    for (const char* value : {"NaN", "Infinity", "-Infinity"}) {
        const std::string message = errorOf(std::string("{\"step\":\n ") + value + "}");
        EXPECT_NE(message.find("tree.json:2:"), std::string::npos) << message;
    }
}

TEST(ColonizeConfigLimits, AMeshShapeFileLargerThanTheLimitIsReportedUnderItsKey) {
    const auto dir = std::filesystem::temp_directory_path() / "ramus_config_mesh_limit";
    std::filesystem::create_directories(dir);
    writeFileAtomic((dir / "m.obj").string(), "v 0 0 0\nv 1 0 0\n");  // 16 bytes
    const std::string config =
        R"({"envelopes": [{"shape": "mesh", "file": "m.obj", "points": 10}]})";
    try {
        parseColonizeConfig(config, (dir / "tree.json").string(), 15);
        FAIL() << "expected the size limit";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("envelopes[0].file"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("the file is larger than the input limit of 15 bytes"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace ramus
