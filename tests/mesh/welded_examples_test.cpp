// The welded mesher on every shipped example (examples/lsystems/*.lsys,
// examples/colonize/*.json): one closed genus-0 surface per tree part, positive volume, no
// fallback junctions; on small versions also no self-intersections and a silhouette close to
// the branch capsules. GLBs go to $RAMUS_TEST_OUTPUT for the glTF validator.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "ramus/colonize.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/turtle.hpp"
#include "ramus/welded_mesher.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

std::vector<std::string> exampleFiles(const std::string& dir, const std::string& extension) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(RAMUS_SOURCE_DIR + dir)) {
        if (entry.path().extension() == extension) files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

BranchTree growLSystem(const std::string& file, int derivations = -1) {
    const LSystem system = loadLSystem(file);
    DeriveOptions options;
    options.derivations = derivations;
    const ModuleString word = deriveLSystem(system, options);
    return interpretTurtle(word, system.symbols, turtleParamsFrom(system.settings)).tree;
}

// Closed, consistently wound, genus 0 per part, positive volume, no fallbacks.
void expectClosedSurfaces(const BranchTree& tree, const WeldedMeshParams& params,
                          const std::string& name) {
    SCOPED_TRACE(name);
    WeldReport report;
    const Mesh mesh = buildWeldedTreeMesh(tree, params, &report);
    test::writeWeldedGlb(mesh, name);
    EXPECT_EQ(report.fallbacks, 0u);
    if (mesh.triangleCount() == 0) return;
    const test::Topology top = test::analyzeTopology(mesh);
    EXPECT_TRUE(top.closedOriented);
    EXPECT_EQ(top.components, report.components);
    EXPECT_EQ(top.euler(), 2 * static_cast<long long>(top.components));
    EXPECT_GT(test::signedVolume(mesh), 0.0);
    EXPECT_GT(test::smallestTriangleShape(mesh), 1e-5);
    EXPECT_LT(test::worstNormalLength(mesh), 1e-5);
}

TEST(WeldedExamples, EveryLSystemExampleIsClosedGenusZeroSurfaces) {
    for (const std::string& file : exampleFiles("/examples/lsystems", ".lsys")) {
        expectClosedSurfaces(growLSystem(file), {}, "lsystem_" + stem(file));
    }
}

TEST(WeldedExamples, EveryColonizationExampleIsClosedGenusZeroSurfaces) {
    for (const std::string& file : exampleFiles("/examples/colonize", ".json")) {
        const ColonizeConfig config = loadColonizeConfig(file);
        const ColonizeResult result = growFromConfig(config, configAttractionPoints(config));
        WeldedMeshParams params;
        applyMeshOverrides(config, params.tube);
        for (std::size_t t = 0; t < result.trees.size(); ++t) {
            expectClosedSurfaces(result.trees[t], params,
                                 "colonize_" + stem(file) + "_" + std::to_string(t));
        }
    }
}

TEST(WeldedExamples, SmallExamplesHaveNoSelfIntersections) {
    const std::vector<std::pair<std::string, int>> cases = {
        {"tree_3d.lsys", 4}, {"tree_3d_tropism.lsys", 4}, {"monopodial.lsys", 6},
        {"sympodial.lsys", 6}, {"abop_2_6a.lsys", 6},     {"abop_1_24a.lsys", 3}};
    for (const auto& [file, derivations] : cases) {
        SCOPED_TRACE(file);
        const BranchTree tree = growLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/" + file,
                                            derivations);
        const Mesh mesh = buildWeldedTreeMesh(tree);
        ASSERT_GT(mesh.triangleCount(), 0u);
        EXPECT_EQ(test::countSelfIntersections(mesh), 0u);
    }
}

}  // namespace
}  // namespace ramus
