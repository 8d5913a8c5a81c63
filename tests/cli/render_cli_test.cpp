// `ramus render` end to end: one preview, and contact sheets of several files (issue 8).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_test_util.hpp"
#include "ramus/file_util.hpp"

namespace ramus::testing {
namespace {

namespace fs = std::filesystem;

/// Width and height from a PNG's IHDR chunk (big-endian at bytes 16 and 20).
std::pair<int, int> pngSize(const std::string& bytes) {
    auto be32 = [&](std::size_t at) {
        int v = 0;
        for (std::size_t i = 0; i < 4; ++i)
            v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
        return v;
    };
    return {be32(16), be32(20)};
}

TEST(RenderCli, TilesSeveralFilesIntoALabelledContactSheet) {
    const fs::path dir = scratchDirectory("render_sheet");
    ASSERT_EQ(runRamus("skeleton --count 3 --seed 2 -o '" + dir.string() + "'", dir).exitCode, 0);
    const std::string inputs = "'" + (dir / "skeleton0.glb").string() + "' '" +
                               (dir / "skeleton1.glb").string() + "' '" +
                               (dir / "skeleton2.glb").string() + "'";
    const CommandResult r = runRamus("render " + inputs + " --sheet --columns 2 --size 64x48 -o '" +
                                         (dir / "sheet.png").string() + "'",
                                     dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto [w, h] = pngSize(readFile((dir / "sheet.png").string()));
    EXPECT_EQ(w, 2 * (64 + 8) + 8);       // two columns, 8 px gaps
    EXPECT_EQ(h, 2 * (48 + 24 + 8) + 8);  // two rows, each with a 24 px label band
}

TEST(RenderCli, SeveralInputsWithoutSheetAreAnError) {
    const fs::path dir = scratchDirectory("render_two");
    ASSERT_EQ(runRamus("skeleton --count 2 -o '" + dir.string() + "'", dir).exitCode, 0);
    const CommandResult r =
        runRamus("render '" + (dir / "skeleton0.glb").string() + "' '" +
                     (dir / "skeleton1.glb").string() + "' -o '" + (dir / "x.png").string() + "'",
                 dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("--sheet"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace ramus::testing
