// User bone libraries on the command line (issue 6 item 3): `ramus bones export` writes the
// default library as files, `ramus skeleton --bones DIR` and batch jobs' "bones" load it back
// with byte-identical output; `ramus bones check`; errors name the file. Plus the head kind an
// example species picks (its class's skull) and that saved metadata regenerates it.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_util.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton_io.hpp"

namespace ramus::testing {
namespace {

namespace fs = std::filesystem;

TEST(BonesCli, ExportedDefaultLibraryGivesByteIdenticalSkeletons) {
    const fs::path dir = scratchDirectory("bones_round_trip");
    const fs::path library = dir / "library";
    const CommandResult exported = runRamus("bones export '" + library.string() + "'", dir);
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    EXPECT_TRUE(fs::exists(library / "bones.json"));
    EXPECT_TRUE(fs::exists(library / "low" / "vertebra.obj"));
    EXPECT_TRUE(fs::exists(library / "high" / "skull_reptile.obj"));
    for (const char* resolution : {"low", "high"}) {
        const std::string flags =
            "skeleton --legs 4 --wings 2 --two-per-girdle --seed 6 "
            "--resolution " +
            std::string(resolution);
        const fs::path builtin = dir / (std::string(resolution) + "_builtin");
        const fs::path user = dir / (std::string(resolution) + "_user");
        ASSERT_EQ(runRamus(flags + " -o '" + builtin.string() + "'", dir).exitCode, 0);
        const CommandResult r =
            runRamus(flags + " --bones '" + library.string() + "' -o '" + user.string() + "'", dir);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        for (const char* file :
             {"skeleton0.glb", "skeleton0.obj", "skeleton0.mtl", "skeleton0.json"}) {
            EXPECT_EQ(readFile((builtin / file).string()), readFile((user / file).string()))
                << resolution << " " << file;
        }
        keepForValidation(user / "skeleton0.glb",
                          "cli_bones_user_" + std::string(resolution) + ".glb");
    }
    const CommandResult check = runRamus("bones check '" + library.string() + "'", dir);
    ASSERT_EQ(check.exitCode, 0) << check.err;
    EXPECT_NE(check.out.find("skull_bird"), std::string::npos) << check.out;
    EXPECT_EQ(check.out.find("over budget"), std::string::npos) << check.out;
}

TEST(BonesCli, BatchJobsLoadTheLibraryNamedInTheirInputs) {
    const fs::path dir = scratchDirectory("bones_batch");
    ASSERT_EQ(
        runRamus("bones export '" + (dir / "lib").string() + "' --resolution low", dir).exitCode,
        0);
    auto manifest = [](bool bones) {
        nlohmann::json inputs = {{"resolution", "low"}, {"legs", 4}};
        if (bones) inputs["bones"] = "lib";  // relative to the manifest's folder
        return nlohmann::json{
            {"seed", 7},
            {"jobs",
             {{{"kind", "skeleton"}, {"count", 2}, {"inputs", inputs}, {"output", "s{n}.obj"}}}}};
    };
    for (bool bones : {false, true}) {
        const fs::path path = dir / (bones ? "user.json" : "builtin.json");
        writeFileAtomic(path.string(), manifest(bones).dump(2));
        const fs::path out = dir / (bones ? "user" : "builtin");
        const CommandResult r =
            runRamus("batch '" + path.string() + "' -o '" + out.string() + "'", dir);
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    for (const char* file : {"s0.obj", "s1.obj", "s1.json"}) {
        EXPECT_EQ(readFile((dir / "builtin" / file).string()),
                  readFile((dir / "user" / file).string()))
            << file;
    }
    nlohmann::json box = manifest(true);
    box["jobs"][0]["inputs"]["resolution"] = "box";
    writeFileAtomic((dir / "box.json").string(), box.dump(2));
    const CommandResult r = runRamus(
        "batch '" + (dir / "box.json").string() + "' -o '" + (dir / "o").string() + "'", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("jobs[0].inputs.bones: the box resolution draws boxes"), std::string::npos)
        << r.err;
}

TEST(BonesCli, LibraryErrorsNameTheFileAndTheProblem) {
    const fs::path dir = scratchDirectory("bones_errors");
    const fs::path library = dir / "lib";
    fs::create_directories(library);
    writeFileAtomic((library / "bones.json").string(),
                    "{\"version\": 1, \"models\": {\"skull\": {}}}");
    const CommandResult r = runRamus("skeleton --resolution low --bones '" + library.string() +
                                         "' -o '" + (dir / "o").string() + "'",
                                     dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find((library / "bones.json").string() +
                         ":1:36: models.skull: unknown bone model kind \"skull\""),
              std::string::npos)
        << r.err;
    const CommandResult box = runRamus(
        "skeleton --bones '" + library.string() + "' -o '" + (dir / "o").string() + "'", dir);
    EXPECT_EQ(box.exitCode, 1);
    EXPECT_NE(box.err.find("--bones: the box resolution"), std::string::npos) << box.err;
}

TEST(BonesCli, AnExampleSpeciesPicksTheSkullOfItsClass) {
    const fs::path dir = scratchDirectory("bones_example_head");
    struct Case {
        const char* flags;
        const char* head;
    };
    for (const Case& c :
         {Case{"--example Pigeon", "bird"}, Case{"--example Crocodile", "reptile"},
          Case{"--example Frog", "reptile"}, Case{"--example 'Horse (warmblood)'", "herbivore"},
          Case{"--example Pigeon --head carnivore", "carnivore"},
          Case{"--example Pigeon --variations --count 2", "bird"}, Case{"--legs 4", ""}}) {
        const fs::path out = dir / "out";
        fs::remove_all(out);
        const CommandResult r =
            runRamus("skeleton " + std::string(c.flags) + " -o '" + out.string() + "'", dir);
        ASSERT_EQ(r.exitCode, 0) << c.flags << ": " << r.err;
        EXPECT_EQ(readSkeletonMetadata((out / "skeleton0.json").string()).design.headKind, c.head)
            << c.flags;
    }
}

TEST(BonesCli, TheExampleHeadKindRegeneratesFromTheMetadata) {
    const fs::path dir = scratchDirectory("bones_example_load");
    const std::string first = (dir / "first").string(), second = (dir / "second").string();
    ASSERT_EQ(runRamus("skeleton --example Swan --resolution low -o '" + first + "'", dir).exitCode,
              0);
    const CommandResult r = runRamus(
        "skeleton --load '" + first + "/skeleton0.json' --resolution low -o '" + second + "'", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* file : {"skeleton0.glb", "skeleton0.obj", "skeleton0.json"}) {
        EXPECT_EQ(readFile(first + "/" + file), readFile(second + "/" + file)) << file;
    }
    // The bird skull is drawn: the same skeleton with the default (herbivore) skull differs.
    const std::string third = (dir / "third").string();
    ASSERT_EQ(
        runRamus("skeleton --example Swan --head herbivore --resolution low -o '" + third + "'",
                 dir)
            .exitCode,
        0);
    EXPECT_NE(readFile(first + "/skeleton0.glb"), readFile(third + "/skeleton0.glb"));
}

}  // namespace
}  // namespace ramus::testing
