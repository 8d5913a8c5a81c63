// The welded mesher meshes junctions on several threads (WeldBuilder::meshJunctions): the mesh
// must not depend on how many, nor on which thread took which junction.
#include <gtest/gtest.h>

#include <string>

#include "mesh/welded_builder.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

void expectSameMesh(const Mesh& a, const Mesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.tangents, b.tangents);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.attributes.size(), b.attributes.size());
    for (std::size_t i = 0; i < a.attributes.size(); ++i) {
        EXPECT_EQ(a.attributes[i].name, b.attributes[i].name);
        EXPECT_EQ(a.attributes[i].values, b.attributes[i].values);
    }
}

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
        expectSameMesh(alone, shared);
    }
}

}  // namespace
}  // namespace ramus
