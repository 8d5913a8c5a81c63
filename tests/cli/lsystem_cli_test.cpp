#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.hpp"

namespace ramus::testing {
namespace {

namespace fs = std::filesystem;

const char* kTree =
    "derivations: 3\n"
    "angle: 30\n"
    "axiom: X\n"
    "X -> F[+X][-X]FX\n"
    "F -> FF\n";

const char* kStochastic =
    "derivations: 5\n"
    "angle: 25\n"
    "axiom: F\n"
    "F -> F[+F]F[-F]F : 1\n"
    "F -> F[+F]F : 1\n"
    "F -> F[-F]F : 1\n";

TEST(LsystemCli, WritesEveryRequestedOutputAndPrintsStats) {
    const fs::path dir = scratchDirectory("outputs");
    const fs::path input = writeInput(dir, "tree.lsys", kTree);
    const CommandResult r = runRamus(
        "lsystem " + input.string() + " -o " + (dir / "t.glb").string() + " --png " +
            (dir / "t.png").string() + " --tree-json " + (dir / "t.json").string() + " --stats",
        dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto stats = nlohmann::json::parse(r.out);
    for (const char* key : {"modules", "nodes", "edges", "vertices", "triangles", "derive_seconds",
                            "interpret_seconds", "mesh_seconds"}) {
        EXPECT_TRUE(stats.contains(key)) << key;
    }
    EXPECT_GT(stats["triangles"].get<int>(), 0);
    EXPECT_TRUE(fs::exists(dir / "t.glb"));
    EXPECT_TRUE(fs::exists(dir / "t.png"));
    const auto tree = nlohmann::json::parse(readFile((dir / "t.json").string()));
    EXPECT_EQ(tree["nodes"].size(), stats["nodes"].get<std::size_t>());
    EXPECT_EQ(tree["nodes"][0]["parent"], -1);
    keepForValidation(dir / "t.glb", "cli_lsystem_tree.glb");
}

TEST(LsystemCli, ObjOutputWritesTheMaterialLibraryToo) {
    const fs::path dir = scratchDirectory("obj");
    const fs::path input = writeInput(dir, "tree.lsys", kTree);
    const CommandResult r =
        runRamus("lsystem " + input.string() + " -o " + (dir / "t.obj").string(), dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "t.obj"));
    EXPECT_TRUE(fs::exists(dir / "t.mtl"));
}

TEST(LsystemCli, SameSeedGivesByteIdenticalFilesOtherSeedsDiffer) {
    const fs::path dir = scratchDirectory("seeds");
    const fs::path input = writeInput(dir, "bush.lsys", kStochastic);
    auto make = [&](const std::string& seed, const std::string& name) {
        const CommandResult r = runRamus(
            "lsystem " + input.string() + " --seed " + seed + " -o " + (dir / name).string(), dir);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return readFile((dir / name).string());
    };
    const std::string a = make("1", "a.glb"), b = make("1", "b.glb"), c = make("2", "c.glb");
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(LsystemCli, PrintWritesTheDerivedWord) {
    const fs::path dir = scratchDirectory("print");
    const fs::path input = writeInput(dir, "koch.lsys", "axiom: F-F\nF -> F+F\n");
    const CommandResult r = runRamus("lsystem " + input.string() + " -n 2 --print", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "F+F+F+F-F+F+F+F\n");
}

TEST(LsystemCli, SetOverridesAConstant) {
    const fs::path dir = scratchDirectory("set");
    const fs::path input = writeInput(dir, "c.lsys", "#define a 2\naxiom: F(a)\n");
    const CommandResult r =
        runRamus("lsystem " + input.string() + " -n 0 --set a=7.5 --print", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "F(7.5)\n");
}

TEST(LsystemCli, SyntaxErrorNamesFileLineAndColumnAndExitsWithOne) {
    const fs::path dir = scratchDirectory("syntax");
    const fs::path input = writeInput(dir, "bad.lsys", "axiom: F\nF -> F(1+)\n");
    const CommandResult r = runRamus("lsystem " + input.string() + " --print", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err.rfind("error: " + input.string() + ":2:", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("expected"), std::string::npos) << r.err;
}

TEST(LsystemCli, MissingFileIsAnErrorNotACrash) {
    const fs::path dir = scratchDirectory("missing");
    const CommandResult r = runRamus("lsystem " + (dir / "nope.lsys").string(), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("nope.lsys"), std::string::npos);
}

TEST(LsystemCli, UnknownFlagIsAUsageError) {
    const fs::path dir = scratchDirectory("usage");
    EXPECT_EQ(runRamus("lsystem --frobnicate x.lsys", dir).exitCode, 2);
    EXPECT_EQ(runRamus("lsystem", dir).exitCode, 2);
}

TEST(LsystemCli, UnsupportedOutputFormatLeavesNoFile) {
    const fs::path dir = scratchDirectory("format");
    const fs::path input = writeInput(dir, "tree.lsys", kTree);
    const CommandResult r =
        runRamus("lsystem " + input.string() + " -o " + (dir / "t.fbx").string(), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find(".glb"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.fbx"));
}

TEST(LsystemCli, ModuleLimitStopsARunawaySystem) {
    const fs::path dir = scratchDirectory("limit");
    const fs::path input = writeInput(dir, "runaway.lsys", "axiom: A\nA -> AA\n");
    const CommandResult r = runRamus(
        "lsystem " + input.string() + " -n 40 --max-modules 100000 -o " + (dir / "r.glb").string(),
        dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("100000"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "r.glb"));
}

TEST(LsystemCli, BadPreviewSizeIsRejectedBeforeWritingAnything) {
    const fs::path dir = scratchDirectory("size");
    const fs::path input = writeInput(dir, "tree.lsys", kTree);
    const CommandResult r =
        runRamus("lsystem " + input.string() + " -o " + (dir / "t.glb").string() + " --png " +
                     (dir / "t.png").string() + " --size 10x",
                 dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("WIDTHxHEIGHT"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.glb"));
}

}  // namespace
}  // namespace ramus::testing

namespace ramus::testing {
namespace {

TEST(LsystemCli, MesherFlagsRejectNonFiniteNumbers) {
    const fs::path dir = scratchDirectory("lsystem_nonfinite");
    const fs::path input = writeInput(dir, "tree.lsys", kTree);
    for (const char* flag :
         {"--leaf-radius", "--radius-exponent", "--trunk-multiplier", "--curve-reduction"}) {
        for (const char* value : {"nan", "inf", "-inf"}) {
            const CommandResult r = runRamus("lsystem '" + input.string() + "' " + flag + " " +
                                                 value + " -o '" + (dir / "t.glb").string() + "'",
                                             dir);
            EXPECT_EQ(r.exitCode, 2) << flag << " " << value;
            EXPECT_NE(r.err.find(std::string(flag) + ": expected"), std::string::npos) << r.err;
        }
    }
    EXPECT_FALSE(fs::exists(dir / "t.glb"));
}

}  // namespace
}  // namespace ramus::testing
