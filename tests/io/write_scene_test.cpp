#include <gtest/gtest.h>

#include "io/io_fixtures.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {
namespace {

TEST(WriteScene, UnknownExtensionIsAnErrorNamingItAndTheSupportedOnes) {
    const std::filesystem::path dir = testing::scratchDir("write_scene_unknown");
    const std::string path = (dir / "tree.stl").string();
    try {
        writeScene(makeSingleMeshScene(testing::makeCube()), path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": unsupported output format '.stl'; expected .glb or .obj");
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(WriteScene, MissingExtensionIsAnError) {
    EXPECT_THROW(writeScene(Scene{}, "/tmp/ramus_io_no_extension"), Error);
}

TEST(WriteScene, ExtensionIsCaseInsensitive) {
    const std::filesystem::path dir = testing::scratchDir("write_scene_case");
    const Scene scene = makeSingleMeshScene(testing::makeCube());
    writeScene(scene, (dir / "a.GLB").string());
    writeScene(scene, (dir / "b.Obj").string());
    EXPECT_EQ(readFile((dir / "a.GLB").string()), encodeGlb(scene));
    testing::exportForValidator(scene, "write_scene_upper_case");
    EXPECT_TRUE(std::filesystem::exists(dir / "b.Obj"));
    EXPECT_TRUE(std::filesystem::exists(dir / "b.mtl"));
}

}  // namespace
}  // namespace ramus
