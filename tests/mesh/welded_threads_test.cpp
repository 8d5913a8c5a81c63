// The welded mesher meshes junctions on several threads (WeldBuilder::meshJunctions): the mesh
// must not depend on how many, nor on which thread took which junction.
#include <gtest/gtest.h>

#include <string>

#include "mesh/welded_builder.hpp"
#include "same_mesh.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

// ABOP 1.27 has fallback junctions (their tubes), shrunk ones (new vertices) and crossings;
// 2.8a many shrunk junctions and limbs absorbed into them. Both have enough junctions for
// three threads (workersFor), and wind values (copied with the tube rings).
TEST(WeldedThreads, JunctionsOnOneOrSeveralThreadsGiveTheSameMesh) {
    for (const std::string name : {"abop_1_27", "abop_2_8a"}) {
        SCOPED_TRACE(name);
        const BranchTree tree =
            test::growLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/" + name + ".lsys");
        WeldedMeshParams params;
        params.tube.windAttributes = true;
        WeldReport one, three;
        const Mesh alone = detail::WeldBuilder(tree, params, 1).build(&one);
        const Mesh shared = detail::WeldBuilder(tree, params, 3).build(&three);
        ASSERT_EQ(detail::workersFor(one.junctions, 3), 3u);
        EXPECT_GT(one.refinedJunctions, 0u);
        EXPECT_EQ(one.refinedJunctions, three.refinedJunctions);
        EXPECT_EQ(one.fallbacks, three.fallbacks);
        EXPECT_EQ(one.absorbedTubes, three.absorbedTubes);
        EXPECT_EQ(one.nodeBalls, three.nodeBalls);
        EXPECT_EQ(one.bendRings, three.bendRings);
        EXPECT_EQ(one.junctionTriangles, three.junctionTriangles);
        test::expectSameMesh(alone, shared, name);
    }
}

}  // namespace
}  // namespace ramus
