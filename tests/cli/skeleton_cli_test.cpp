// `ramus skeleton` end to end (issue 5 item 9): every input reaches the generator, files per
// skeleton, save → load regenerates identical bytes, clear errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_test_util.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton_io.hpp"

namespace ramus::testing {
namespace {

namespace fs = std::filesystem;

int countKind(const LoadedSkeleton& loaded, LimbKind kind) {
    int n = 0;
    for (LimbKind k : loaded.design.limbs) n += k == kind ? 2 : 0;
    return n;
}

TEST(SkeletonCli, WritesGlbObjJsonAndPngPerSkeleton) {
    const fs::path dir = scratchDirectory("skeleton_files");
    const CommandResult r =
        runRamus("skeleton --count 2 --seed 4 --png --size 64x64 --name beast -o '" +
                     (dir / "out").string() + "'",
                 dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* stem : {"beast0", "beast1"}) {
        for (const char* ext : {".glb", ".obj", ".mtl", ".json", ".png"}) {
            EXPECT_TRUE(fs::exists(dir / "out" / (std::string(stem) + ext))) << stem << ext;
        }
    }
    keepForValidation(dir / "out" / "beast0.glb", "cli_skeleton_beast0.glb");
}

TEST(SkeletonCli, LoadRegeneratesIdenticalFiles) {
    const fs::path dir = scratchDirectory("skeleton_load");
    const std::string first = (dir / "first").string(), second = (dir / "second").string();
    ASSERT_EQ(
        runRamus("skeleton --legs 4 --wings 2 --two-per-girdle --seed 9 -o '" + first + "'", dir)
            .exitCode,
        0);
    const CommandResult r =
        runRamus("skeleton --load '" + first + "/skeleton0.json' -o '" + second + "'", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* file : {"skeleton0.glb", "skeleton0.obj", "skeleton0.json"}) {
        EXPECT_EQ(readFile(first + "/" + file), readFile(second + "/" + file)) << file;
    }
}

TEST(SkeletonCli, InputsReachTheDesign) {
    const fs::path dir = scratchDirectory("skeleton_inputs");
    const std::string out = (dir / "out").string();
    const CommandResult r =
        runRamus("skeleton --legs 4 --arms 2 --neck-shoulder forced --name centaur --seed 2 -o '" +
                     out + "'",
                 dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const LoadedSkeleton loaded = readSkeletonMetadata(out + "/centaur0.json");
    EXPECT_EQ(countKind(loaded, LimbKind::Leg), 4);
    EXPECT_EQ(countKind(loaded, LimbKind::Arm), 2);
    EXPECT_EQ(loaded.design.limb(Attachment::Neck), LimbKind::Arm);
}

TEST(SkeletonCli, VariationsOfAnExampleDiffer) {
    const fs::path dir = scratchDirectory("skeleton_variations");
    const std::string out = (dir / "out").string();
    const CommandResult r = runRamus(
        "skeleton --example 'African elephant' --variations --count 2 --seed 1 -o '" + out + "'",
        dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(readFile(out + "/skeleton0.glb"), readFile(out + "/skeleton1.glb"));
}

TEST(SkeletonCli, OddLegCountIsAnError) {
    const fs::path dir = scratchDirectory("skeleton_odd");
    const CommandResult r = runRamus("skeleton --legs 3 -o '" + (dir / "o").string() + "'", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("legs"), std::string::npos) << r.err;
}

TEST(SkeletonCli, TooManyLimbsForTheAttachmentsIsAnError) {
    const fs::path dir = scratchDirectory("skeleton_too_many");
    const CommandResult r = runRamus(
        "skeleton --legs 4 --wings 2 --neck-shoulder forbidden -o '" + (dir / "o").string() + "'",
        dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("two limb pairs per girdle"), std::string::npos) << r.err;
}

TEST(SkeletonCli, VariationsNeedASource) {
    const fs::path dir = scratchDirectory("skeleton_no_source");
    const CommandResult r =
        runRamus("skeleton --variations -o '" + (dir / "o").string() + "'", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("--load"), std::string::npos) << r.err;
}

TEST(SkeletonCli, UnknownSpeciesIsAnError) {
    const fs::path dir = scratchDirectory("skeleton_unknown_species");
    const CommandResult r =
        runRamus("skeleton --example Unicorn -o '" + (dir / "o").string() + "'", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("Unicorn"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ramus::testing

namespace ramus::testing {
namespace {

TEST(SkeletonCli, BoneModelResolutionsWriteLargerValidModels) {
    const fs::path dir = scratchDirectory("skeleton_resolutions");
    std::uintmax_t previous = 0;
    for (const char* resolution : {"box", "low", "high"}) {
        const fs::path out = dir / resolution;
        const CommandResult r =
            runRamus("skeleton --legs 4 --seed 3 --png --size 64x64 --resolution " +
                         std::string(resolution) + " -o '" + out.string() + "'",
                     dir);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::uintmax_t size = fs::file_size(out / "skeleton0.glb");
        EXPECT_GT(size, previous) << resolution;
        previous = size;
        EXPECT_TRUE(fs::exists(out / "skeleton0.png"));
        keepForValidation(out / "skeleton0.glb",
                          "cli_skeleton_" + std::string(resolution) + ".glb");
    }
    EXPECT_EQ(runRamus("skeleton --resolution ultra -o '" + dir.string() + "'", dir).exitCode, 2);
    const CommandResult head =
        runRamus("skeleton --resolution low --head unicorn -o '" + (dir / "u").string() + "'", dir);
    EXPECT_EQ(head.exitCode, 1);
    EXPECT_NE(head.err.find("unknown head kind"), std::string::npos) << head.err;
}

}  // namespace
}  // namespace ramus::testing
