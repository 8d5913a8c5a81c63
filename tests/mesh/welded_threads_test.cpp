// The welded mesher meshes junctions on several threads (WeldBuilder::meshJunctions): the mesh
// must not depend on how many, nor on which thread took which junction.
#include <gtest/gtest.h>

#include <string>

#include "mesh/welded_builder.hpp"
#include "same_mesh.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

// The junction counters and the mesh of one thread and of three.
void expectSameOnThreeThreads(const BranchTree& tree, const WeldedMeshParams& params,
                              const std::string& label, WeldReport& report) {
    SCOPED_TRACE(label);
    WeldReport three;
    const Mesh alone = detail::WeldBuilder(tree, params, 1).build(&report);
    const Mesh shared = detail::WeldBuilder(tree, params, 3).build(&three);
    ASSERT_EQ(detail::workersFor(report.junctions, 3), 3u);
    EXPECT_EQ(report.refinedJunctions, three.refinedJunctions);
    EXPECT_EQ(report.tubedForUnion, three.tubedForUnion);
    EXPECT_EQ(report.fallbacks, three.fallbacks);
    EXPECT_EQ(report.absorbedTubes, three.absorbedTubes);
    EXPECT_EQ(report.nodeBalls, three.nodeBalls);
    EXPECT_EQ(report.bendRings, three.bendRings);
    EXPECT_EQ(report.junctionTriangles, three.junctionTriangles);
    test::expectSameMesh(alone, shared, label);
}

// ABOP 1.27 has fallback junctions (their tubes), shrunk ones (new vertices) and crossings;
// 2.8a many shrunk junctions and limbs absorbed into them. Both have enough junctions for
// three threads (workersFor), and wind values (copied with the tube rings). Welded for the
// solid union, junctions whose shrunk faces stay outside the branches become tubes after
// their hull was meshed (the piece is cut back first); with convex junctions, hulls far
// outside the branches do.
TEST(WeldedThreads, JunctionsOnOneOrSeveralThreadsGiveTheSameMesh) {
    std::size_t shrunk = 0, tubed = 0, tubedHulls = 0;
    for (const std::string name : {"abop_1_27", "abop_2_8a"}) {
        const BranchTree tree =
            test::growLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/" + name + ".lsys");
        WeldedMeshParams params;
        params.tube.windAttributes = true;
        WeldReport report;
        expectSameOnThreeThreads(tree, params, name, report);
        shrunk += report.refinedJunctions;
        params.solidUnion = true;  // WeldBuilder welds for the union, without uniting
        expectSameOnThreeThreads(tree, params, name + " for the union", report);
        tubed += report.tubedForUnion;
        params.shrinkJunctions = false;
        expectSameOnThreeThreads(tree, params, name + " convex, for the union", report);
        tubedHulls += report.tubedForUnion;
    }
    EXPECT_GT(shrunk, 0u);
    EXPECT_GT(tubed, 0u);
    EXPECT_GT(tubedHulls, 0u);
}

}  // namespace
}  // namespace ramus
