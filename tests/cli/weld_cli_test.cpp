// `--weld` on `ramus lsystem` and `ramus colonize`: the welded mesh replaces the tubes (fewer
// overlapping tube starts, a different triangle count), and the default stays the tubes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.hpp"

namespace ramus::testing {
namespace {

namespace fs = std::filesystem;

std::size_t triangles(const std::string& args, const fs::path& dir) {
    const CommandResult r = runRamus(args + " --stats", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out)["triangles"].get<std::size_t>();
}

TEST(WeldCli, LsystemWeldWritesAWeldedModel) {
    const fs::path dir = scratchDirectory("weld_lsystem");
    const std::string file = RAMUS_SOURCE_DIR "/examples/lsystems/tree_3d.lsys";
    const std::string glb = (dir / "welded.glb").string();
    const std::size_t tubes = triangles("lsystem " + file + " -n 4", dir);
    const std::size_t welded = triangles("lsystem " + file + " -n 4 --weld -o " + glb, dir);
    EXPECT_NE(welded, tubes);
    EXPECT_GT(welded, 0u);
    ASSERT_TRUE(fs::exists(glb));
    keepForValidation(glb, "weld_cli_tree_3d.glb");
}

TEST(WeldCli, ColonizeWeldWritesAWeldedModel) {
    const fs::path dir = scratchDirectory("weld_colonize");
    const std::string file = RAMUS_SOURCE_DIR "/examples/colonize/fig3_2_ring.json";
    const std::string glb = (dir / "welded.glb").string();
    const std::size_t tubes = triangles("colonize " + file, dir);
    const std::size_t welded = triangles("colonize " + file + " --weld -o " + glb, dir);
    EXPECT_NE(welded, tubes);
    ASSERT_TRUE(fs::exists(glb));
    keepForValidation(glb, "weld_cli_fig3_2_ring.glb");
}

}  // namespace
}  // namespace ramus::testing
