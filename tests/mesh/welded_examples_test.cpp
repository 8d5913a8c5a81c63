// The welded mesher on every shipped example (examples/lsystems/*.lsys,
// examples/colonize/*.json): one closed genus-0 surface per tree part, positive volume, no
// fallback junctions; on small versions also no self-intersections and a silhouette close to
// the branch capsules. GLBs go to $RAMUS_TEST_OUTPUT for the glTF validator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
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

// Closed, consistently wound, genus 0 per closed part, positive volume. Returns the report
// (and the mesh through `meshOut`).
WeldReport expectClosedSurfaces(const BranchTree& tree, const WeldedMeshParams& params,
                                const std::string& name, Mesh* meshOut = nullptr) {
    SCOPED_TRACE(name);
    WeldReport report;
    Mesh local;
    Mesh& mesh = meshOut ? *meshOut : local;
    mesh = buildWeldedTreeMesh(tree, params, &report);
    test::writeWeldedGlb(mesh, name);
    if (mesh.triangleCount() == 0) return report;
    const test::Topology top = test::analyzeTopology(mesh);
    EXPECT_TRUE(top.closedOriented);
    EXPECT_EQ(top.euler(), 2 * static_cast<long long>(top.components));
    if (report.fallbacks == 0) EXPECT_EQ(top.components, report.components);
    EXPECT_GT(test::signedVolume(mesh), 0.0);
    EXPECT_GT(test::smallestTriangleShape(mesh), 1e-5);
    EXPECT_LT(test::worstNormalLength(mesh), 1e-5);
    std::printf("%s: %zu junctions, %zu merges, %zu absorbed, %zu crossings, %zu fallbacks\n",
                name.c_str(), report.junctions, report.merges, report.absorbedLimbs,
                report.crossings, report.fallbacks);
    return report;
}

// Examples whose branches are thin against their internodes weld without any compromise;
// the ABOP 1.24–1.31 plants, 2.6d and 2.8a–c have radii (Murray's rule with many tips, or
// wide `!`) far above their internode lengths near the base: there some junctions overlap
// or fall back to capped tubes, but every part stays closed.
bool weldsCleanly(const std::string& name) {
    for (const char* dense : {"abop_1_", "abop_2_6d", "abop_2_8a", "abop_2_8b", "abop_2_8c"}) {
        if (name.rfind(dense, 0) == 0) return false;
    }
    return true;
}

TEST(WeldedExamples, LSystemExamplesWithThinBranchesAreOneClosedGenusZeroSurface) {
    for (const std::string& file : exampleFiles("/examples/lsystems", ".lsys")) {
        if (!weldsCleanly(stem(file))) continue;
        const WeldReport report =
            expectClosedSurfaces(growLSystem(file), {}, "lsystem_" + stem(file));
        SCOPED_TRACE(file);
        EXPECT_EQ(report.fallbacks, 0u);
        EXPECT_EQ(report.crossings, 0u);
        EXPECT_EQ(report.components, 1u);
    }
}

// Dense examples whose welded mesh has pieces that share edges (docs/welded.md, "Quality and
// limits"): in 1.31a two tips end at one point from different directions, and their flat caps
// share the spokes along the line where the caps' planes cross (each piece is closed on its
// own; the solid union accepts and separates them). Edges drawn again from other nodes, which
// gave 3 open pieces there, are merged since session 12.
std::size_t sharedEdgePieces(const std::string& name) { return name == "abop_1_31a" ? 2 : 0; }

// Known limit (docs/welded.md): where junctions overlap or fall back, the surface may intersect
// itself and a fallback leaves the limbs as separately capped tubes, so it is not one surface.
// What must hold: meshing ends, the output is well formed and encloses positive volume, every
// piece (apart from the examples above) is a closed, consistently wound genus-0 surface, and
// the report says what was given up.
TEST(WeldedExamples, DenseLSystemExamplesStillMeshAndReportTheirCompromises) {
    for (const std::string& file : exampleFiles("/examples/lsystems", ".lsys")) {
        if (weldsCleanly(stem(file))) continue;
        SCOPED_TRACE(file);
        WeldReport report;
        const Mesh mesh = buildWeldedTreeMesh(growLSystem(file), {}, &report);
        test::writeWeldedGlb(mesh, "lsystem_" + stem(file));
        ASSERT_GT(mesh.triangleCount(), 0u);
        for (std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertexCount());
        for (const Vec3f& p : mesh.positions) ASSERT_TRUE(p.allFinite());
        EXPECT_LT(test::worstNormalLength(mesh), 1e-5);
        EXPECT_GT(test::signedVolume(mesh), 0.0);
        EXPECT_GT(report.crossings + report.fallbacks, 0u);
        const test::Topology top = test::analyzeTopology(mesh);
        EXPECT_EQ(top.openComponents, sharedEdgePieces(stem(file)));
        if (sharedEdgePieces(stem(file)) == 0) {
            // Every edge on exactly two triangles, wound oppositely; and since a closed piece
            // has χ ≤ 2, χ = 2 per piece in total means every piece is a sphere.
            EXPECT_EQ(top.euler(), 2 * static_cast<long long>(top.components));
        }
        std::printf(
            "%s: %zu pieces, %zu open, euler %lld, %zu junctions, %zu crossings, "
            "%zu fallbacks\n",
            stem(file).c_str(), top.components, top.openComponents, top.euler(), report.junctions,
            report.crossings, report.fallbacks);
    }
}

// Triangle pairs that intersect with at least one junction triangle in them (the junctions
// are the last triangles of the mesh).
std::size_t junctionIntersections(const Mesh& mesh, const WeldReport& report) {
    const std::size_t firstJunction = mesh.triangleCount() - report.junctionTriangles;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    test::countSelfIntersections(mesh, 1u << 22, &pairs);
    return static_cast<std::size_t>(std::count_if(pairs.begin(), pairs.end(), [&](auto pair) {
        return std::max(pair.first, pair.second) >= firstJunction;
    }));
}

// Junction–triangle intersections per colonization tree as measured (session 10) once rings at
// inner nodes that cross a junction's ring are left out (docs/welded.md, "Quality and
// limits"); before that they were 5–184 per tree. They must not grow. conifer's are all
// between the two full junctions around its one crossing limb.
std::size_t junctionIntersectionBound(const std::string& tree) {
    static const std::vector<std::pair<std::string, std::size_t>> bounds = {
        {"broadleaf_0", 10}, {"conifer_0", 49},   {"multi_trunk_0", 20}, {"obstacle_0", 5},
        {"roots_0", 12},     {"two_trees_0", 11}, {"two_trees_1", 11}};
    for (const auto& [name, bound] : bounds) {
        if (name == tree) return bound;
    }
    return 0;
}

TEST(WeldedExamples, EveryColonizationExampleIsClosedGenusZeroSurfaces) {
    for (const std::string& file : exampleFiles("/examples/colonize", ".json")) {
        const ColonizeConfig config = loadColonizeConfig(file);
        const ColonizeResult result = growFromConfig(config, configAttractionPoints(config));
        WeldedMeshParams params;
        applyMeshOverrides(config, params.tube);
        for (std::size_t t = 0; t < result.trees.size(); ++t) {
            const std::string tree = stem(file) + "_" + std::to_string(t);
            Mesh mesh;
            const WeldReport report =
                expectClosedSurfaces(result.trees[t], params, "colonize_" + tree, &mesh);
            SCOPED_TRACE(file);
            EXPECT_LE(junctionIntersections(mesh, report), junctionIntersectionBound(tree)) << tree;
            EXPECT_EQ(report.fallbacks, 0u);
            EXPECT_EQ(report.crowded, 0u);
            EXPECT_EQ(report.components, 1u);
            // conifer: one limb near the base between two full junctions (16 branch nodes).
            EXPECT_LE(report.crossings, 1u);
        }
    }
}

TEST(WeldedExamples, SmallExamplesHaveNoSelfIntersections) {
    const std::vector<std::pair<std::string, int>> cases = {{"monopodial.lsys", 6},
                                                            {"sympodial.lsys", 6},
                                                            {"abop_2_6a.lsys", 6},
                                                            {"abop_2_7a.lsys", 6}};
    for (const auto& [file, derivations] : cases) {
        SCOPED_TRACE(file);
        const BranchTree tree =
            growLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/" + file, derivations);
        const Mesh mesh = buildWeldedTreeMesh(tree);
        ASSERT_GT(mesh.triangleCount(), 0u);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
        EXPECT_EQ(test::countSelfIntersections(mesh, 10, &pairs), 0u);
        for (const auto& [s, t] : pairs) {
            std::printf("  triangles %u %u (indices %u..): ", s, t, mesh.indices[3 * s]);
            for (std::uint32_t tri : {s, t}) {
                for (int k = 0; k < 3; ++k) {
                    const Vec3f p = mesh.positions[mesh.indices[3 * tri + k]];
                    std::printf("(%.2f %.2f %.2f) ", p.x(), p.y(), p.z());
                }
                std::printf("| ");
            }
            std::printf("\n");
        }
    }
}

// tree_3d's branches cross each other in the skeleton at 4 derivations, so its tubes do
// intersect; the junctions (the last triangles of the mesh) must not take part in any of it.
// tree_3d_tropism's bent limbs still give 15 junction–tube intersections there, an open defect
// listed in docs/welded.md: that count must not grow.
TEST(WeldedExamples, Tree3dJunctionsIntersectNothingTropismNoMoreThanMeasured) {
    for (const auto& [file, bound] :
         {std::pair{"tree_3d.lsys", 0u}, {"tree_3d_tropism.lsys", 15u}}) {
        SCOPED_TRACE(file);
        const BranchTree tree =
            growLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/" + std::string(file), 4);
        WeldReport report;
        const Mesh mesh = buildWeldedTreeMesh(tree, {}, &report);
        ASSERT_GT(report.junctionTriangles, 100u);
        EXPECT_LE(junctionIntersections(mesh, report), std::size_t{bound});
    }
}

}  // namespace
}  // namespace ramus
