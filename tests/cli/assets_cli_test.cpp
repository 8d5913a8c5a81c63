// `ramus lsystem` / `ramus colonize` asset flags end to end: leaves, wind, textures, LODs in the
// GLB; the OBJ's texture files; the preview shows leaves; bad flags are errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.hpp"
#include "ramus/render.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

namespace ramus::testing {
namespace {

namespace fs = std::filesystem;

const std::string kExample = RAMUS_SOURCE_DIR "/examples/lsystems/tree_3d.lsys";

TEST(AssetsCli, LeavesWindTexturesAndLodsEndUpInTheGlb) {
    const fs::path dir = scratchDirectory("assets_glb");
    const CommandResult r = runRamus("lsystem '" + kExample + "' -n 4 --leaves --wind --lods " +
                                         "1,0.4,0.15 -o " + (dir / "t.glb").string() + " --stats",
                                     dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto stats = nlohmann::json::parse(r.out);
    ASSERT_EQ(stats["lod_triangles"].size(), 3u);
    const double full = stats["lod_triangles"][0].get<double>();
    EXPECT_NEAR(stats["lod_triangles"][1].get<double>(), 0.4 * full, 0.04 * full);
    EXPECT_NEAR(stats["lod_triangles"][2].get<double>(), 0.15 * full, 0.015 * full);
    EXPECT_GT(stats["leaf_triangles"].get<int>(), 0);
    const auto doc = glbJson(readFile((dir / "t.glb").string()));
    ASSERT_EQ(doc["nodes"].size(), 4u);
    EXPECT_EQ(doc["nodes"][0]["name"], "tree");
    EXPECT_EQ(doc["nodes"][1]["name"], "tree_LOD0");
    EXPECT_EQ(doc["nodes"][3]["name"], "tree_LOD2");
    EXPECT_EQ(doc["nodes"][2]["extras"]["lod"], 1);
    ASSERT_EQ(doc["meshes"].size(), 3u);
    const auto& prims = doc["meshes"][0]["primitives"];
    ASSERT_EQ(prims.size(), 2u);
    for (const auto& p : prims) {
        EXPECT_TRUE(p["attributes"].contains("_WIND"));
        EXPECT_TRUE(p["attributes"].contains("_WIND_PIVOT"));
        EXPECT_TRUE(p["attributes"].contains("_WIND_LEAF"));
    }
    EXPECT_EQ(doc["images"].size(), 3u);  // bark colour, bark normal map, leaf
    bool masked = false;
    for (const auto& m : doc["materials"]) masked = masked || m.value("alphaMode", "") == "MASK";
    EXPECT_TRUE(masked);
    keepForValidation(dir / "t.glb", "cli_assets_lods.glb");
}

TEST(AssetsCli, WindWithoutLeavesEndsUpInTheGlb) {
    const fs::path dir = scratchDirectory("assets_wind_bark");
    const CommandResult r =
        runRamus("lsystem '" + kExample + "' -n 3 --wind -o " + (dir / "t.glb").string(), dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto doc = glbJson(readFile((dir / "t.glb").string()));
    EXPECT_TRUE(doc["meshes"][0]["primitives"][0]["attributes"].contains("_WIND"));
}

TEST(AssetsCli, PreviewShowsGreenLeaves) {
    const fs::path dir = scratchDirectory("assets_png");
    auto greenShare = [&](const std::string& flags) {
        const fs::path png = dir / "t.png";
        const CommandResult r = runRamus("lsystem '" + kExample + "' -n 4 " + flags + " --png " +
                                             png.string() + " --size 200x200",
                                         dir);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        int w = 0, h = 0, n = 0;
        const std::string bytes = readFile(png.string());
        unsigned char* pixels =
            stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                  static_cast<int>(bytes.size()), &w, &h, &n, 4);
        EXPECT_NE(pixels, nullptr);
        int green = 0;
        for (int i = 0; i < w * h; ++i) {
            const unsigned char* p = pixels + 4 * i;
            green += p[1] > p[0] + 20 && p[1] > p[2] + 20;
        }
        stbi_image_free(pixels);
        return static_cast<double>(green) / (w * h);
    };
    EXPECT_LT(greenShare(""), 0.001);
    EXPECT_GT(greenShare("--leaves"), 0.05);
}

TEST(AssetsCli, ObjGetsTheTexturesNextToIt) {
    const fs::path dir = scratchDirectory("assets_obj");
    const CommandResult r =
        runRamus("lsystem '" + kExample + "' -n 3 --leaves -o " + (dir / "t.obj").string(), dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string mtl = readFile((dir / "t.mtl").string());
    EXPECT_NE(mtl.find("map_Kd t_bark.png"), std::string::npos);
    EXPECT_NE(mtl.find("norm t_bark_normal.png"), std::string::npos);
    EXPECT_NE(mtl.find("map_d t_leaves.png"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "t_bark.png"));
    EXPECT_TRUE(fs::exists(dir / "t_leaves.png"));
}

TEST(AssetsCli, NoTexturesLeavesPlainMaterials) {
    const fs::path dir = scratchDirectory("assets_plain");
    const CommandResult r = runRamus(
        "lsystem '" + kExample + "' -n 3 --no-textures -o " + (dir / "t.glb").string(), dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FALSE(glbJson(readFile((dir / "t.glb").string())).contains("images"));
}

TEST(AssetsCli, ColonizeConfigLeavesAndRootsWork) {
    const fs::path dir = scratchDirectory("assets_colonize");
    const CommandResult r =
        runRamus("colonize '" RAMUS_SOURCE_DIR "/examples/colonize/roots.json' --stats -o " +
                     (dir / "r.glb").string(),
                 dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto stats = nlohmann::json::parse(r.out);
    EXPECT_GT(stats["leaf_triangles"].get<int>(), 1000);
    const auto doc = glbJson(readFile((dir / "r.glb").string()));
    EXPECT_TRUE(doc["meshes"][0]["primitives"][0]["attributes"].contains("_WIND"));
    keepForValidation(dir / "r.glb", "cli_colonize_roots.glb");
}

TEST(AssetsCli, BadAssetFlagsAreUsageErrors) {
    const fs::path dir = scratchDirectory("assets_errors");
    EXPECT_NE(runRamus("lsystem '" + kExample + "' --lods 1,0", dir).exitCode, 0);
    EXPECT_NE(runRamus("lsystem '" + kExample + "' --lods 1,x", dir).exitCode, 0);
    EXPECT_NE(runRamus("lsystem '" + kExample + "' --leaf-atlas 0,0,1", dir).exitCode, 0);
    EXPECT_NE(runRamus("lsystem '" + kExample + "' --leaf-shape round", dir).exitCode, 0);
    const CommandResult r = runRamus("lsystem '" + kExample + "' --leaf-width 0", dir);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("leaf-width"), std::string::npos);
}

}  // namespace
}  // namespace ramus::testing
