// Limits and non-finite numbers at the command line (issue 8, "Limits everywhere"): one test per
// limit flag and per kind of bad number; each error names the input (flag or file), the place
// and the limit, exits with 1 (2 for usage errors) and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_test_util.hpp"
#include "ramus/file_util.hpp"

namespace ramus::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// --- ramus lsystem ---

TEST(LimitsCli, LsystemMemoryLimitStopsAParametricWord) {
    const fs::path dir = scratchDirectory("limits_lsystem_memory");
    // 12 + 16 · 8 = 140 bytes per module; step k holds 210 · 2^k bytes: 1.7 MiB at step 13.
    std::string params, values;
    for (int i = 0; i < 16; ++i) {
        params += (i ? ",p" : "p") + std::to_string(i);
        values += (i ? ",0" : "0");
    }
    const fs::path input = writeInput(dir, "wide.lsys",
                                      "derivations: 13\naxiom: A(" + values + ")\nA(" + params +
                                          ") -> A(" + params + ") A(" + params + ")\n");
    const CommandResult r =
        runRamus("lsystem " + quoted(input) + " --max-memory 1 -o " + quoted(dir / "t.glb"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("wide.lsys: derivation step 13 of 13 would exceed the memory limit of "
                         "1 MiB (1048576 bytes)"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.glb"));
    const CommandResult ok =
        runRamus("lsystem " + quoted(input) + " -n 12 --max-memory 1 --stats", dir);
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_EQ(json::parse(ok.out)["modules"], 4096);
}

TEST(LimitsCli, LsystemMemoryFlagOutsideItsRangeIsAUsageError) {
    const fs::path dir = scratchDirectory("limits_lsystem_memory_flag");
    const fs::path input = writeInput(dir, "t.lsys", "axiom: F\n");
    for (const char* value : {"0", "-5", "nan"}) {
        const CommandResult r =
            runRamus("lsystem " + quoted(input) + " --max-memory " + value + " --stats", dir);
        EXPECT_EQ(r.exitCode, 2) << value;
        EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
    }
}

TEST(LimitsCli, LsystemSetRejectsNonFiniteValues) {
    const fs::path dir = scratchDirectory("limits_lsystem_set");
    const fs::path input = writeInput(dir, "t.lsys", "#define a 1\naxiom: F(a)\n");
    for (const char* value : {"nan", "inf", "-infinity"}) {
        const CommandResult r =
            runRamus("lsystem " + quoted(input) + " --set a=" + value + " --stats", dir);
        EXPECT_EQ(r.exitCode, 1) << value;
        EXPECT_NE(r.err.find("--set: the value of 'a=" + std::string(value) +
                             "' is not finite; expected a finite number"),
                  std::string::npos)
            << r.err;
    }
    const CommandResult big = runRamus("lsystem " + quoted(input) + " --set a=1e999 --stats", dir);
    EXPECT_EQ(big.exitCode, 1);
    EXPECT_NE(big.err.find("--set: the value of 'a=1e999' is outside the range of a double"),
              std::string::npos)
        << big.err;
}

TEST(LimitsCli, LsystemFileNumbersBeyondDoubleRangeAreLocated) {
    const fs::path dir = scratchDirectory("limits_lsystem_literal");
    const fs::path input =
        writeInput(dir, "t.lsys", "#define a 2\naxiom: F(a)\nF(x) -> F(1e999)\n");
    const CommandResult r = runRamus("lsystem " + quoted(input) + " --stats", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("t.lsys:3:11: number '1e999' is out of range"), std::string::npos)
        << r.err;
}

// --- ramus skeleton ---

TEST(LimitsCli, SkeletonCountAboveTheLimitStopsBeforeWriting) {
    const fs::path dir = scratchDirectory("limits_skeleton_count");
    const CommandResult r =
        runRamus("skeleton --count 4 --max-count 3 -o " + quoted(dir / "out"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("--count: 4 skeletons are above the limit of 3"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("--max-count"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "skeleton0.glb"));
}

TEST(LimitsCli, SkeletonCountHasADefaultLimit) {
    const fs::path dir = scratchDirectory("limits_skeleton_default");
    const CommandResult r = runRamus("skeleton --count 10001 -o " + quoted(dir / "out"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("--count: 10001 skeletons are above the limit of 10000"),
              std::string::npos)
        << r.err;
}

TEST(LimitsCli, SkeletonNumericFlagsRejectNonFiniteNumbers) {
    const fs::path dir = scratchDirectory("limits_skeleton_nonfinite");
    for (const char* flag : {"--height", "--length", "--neck-y", "--tail-x"}) {
        for (const char* value : {"nan", "inf", "-inf", "1e999"}) {
            const CommandResult r = runRamus(
                "skeleton " + std::string(flag) + " " + value + " -o " + quoted(dir / "out"), dir);
            EXPECT_EQ(r.exitCode, 2) << flag << " " << value;
            EXPECT_NE(r.err.find(std::string(flag) + ": expected a number in ["), std::string::npos)
                << r.err;
        }
    }
    EXPECT_FALSE(fs::exists(dir / "out" / "skeleton0.glb"));
}

// --- ramus colonize ---

const char* kFarPoint = R"({"step": 1, "max_iterations": 200,
  "envelopes": [{"shape": "sphere", "center": [0, 5000, 0], "radius": 1, "points": 1}]})";

TEST(LimitsCli, ColonizeIterationsAboveTheLimitStopBeforeGrowth) {
    const fs::path dir = scratchDirectory("limits_colonize_iterations");
    const fs::path config = writeInput(dir, "far.json", kFarPoint);
    const CommandResult r = runRamus(
        "colonize " + quoted(config) + " --max-iterations 199 -o " + quoted(dir / "t.glb"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("far.json: max_iterations: 200 is above the limit of 199 iterations"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.glb"));
    const CommandResult ok =
        runRamus("colonize " + quoted(config) + " --max-iterations 200 --stats", dir);
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
}

TEST(LimitsCli, ColonizePointFilesAboveTheSizeLimitAreRefused) {
    const fs::path dir = scratchDirectory("limits_colonize_file_size");
    const fs::path config = writeInput(dir, "far.json", kFarPoint);
    std::string points;
    while (points.size() <= (std::size_t{1} << 20)) points += "1 2 3\n";
    const fs::path file = writeInput(dir, "many.xyz", points);
    const CommandResult r = runRamus(
        "colonize " + quoted(config) + " --points " + quoted(file) + " --max-file-size 1 --stats",
        dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("many.xyz: the file is larger than the input limit of 1048576 bytes"),
              std::string::npos)
        << r.err;
}

TEST(LimitsCli, ColonizePointFilesWithNonFiniteNumbersNameTheLine) {
    const fs::path dir = scratchDirectory("limits_colonize_points_nonfinite");
    const fs::path config = writeInput(dir, "far.json", kFarPoint);
    const fs::path file = writeInput(dir, "bad.csv", "x,y,z\n1,2,3\n4,nan,6\n");
    const CommandResult r =
        runRamus("colonize " + quoted(config) + " --points " + quoted(file) + " --stats", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("bad.csv:3: coordinate 'nan' is not finite"), std::string::npos) << r.err;
}

// --- ramus batch ---

json oneJob(int count) {
    return {{"jobs", {{{"kind", "skeleton"}, {"count", count}, {"output", "s_{index}.glb"}}}}};
}

TEST(LimitsCli, BatchItemsAboveTheLimitFailBeforeAnyItem) {
    const fs::path dir = scratchDirectory("limits_batch_items");
    json manifest = oneJob(3);
    manifest["jobs"].push_back(oneJob(2)["jobs"][0]);
    manifest["jobs"][1]["output"] = "t_{n}.glb";
    const fs::path path = writeInput(dir, "m.json", manifest.dump());
    const CommandResult r =
        runRamus("batch " + quoted(path) + " --max-items 4 -o " + quoted(dir / "out"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("m.json: jobs: 5 items in jobs[0..1] are above the limit of 4"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "s_0.glb"));
}

TEST(LimitsCli, BatchJobCountAboveTheLimitNamesTheJob) {
    const fs::path dir = scratchDirectory("limits_batch_job");
    const fs::path path = writeInput(dir, "m.json", oneJob(20'000'000).dump());
    const CommandResult r = runRamus("batch " + quoted(path) + " -o " + quoted(dir / "out"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("m.json: jobs[0].count: 20000000 items are above the limit of 10000000"),
              std::string::npos)
        << r.err;
}

TEST(LimitsCli, BatchManifestNumbersBeyondDoubleRangeAreLocated) {
    const fs::path dir = scratchDirectory("limits_batch_number");
    const fs::path path =
        writeInput(dir, "m.json",
                   "{\"jobs\": [{\"kind\": \"skeleton\",\n  \"inputs\": {\"height_m\": 1e999},"
                   " \"output\": \"s.glb\"}]}");
    const CommandResult r = runRamus("batch " + quoted(path) + " -o " + quoted(dir / "out"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("m.json:2:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("number '1e999' is out of range"), std::string::npos) << r.err;
}

TEST(LimitsCli, BatchLsystemSetValuesMustBeFiniteNumbersInRange) {
    const fs::path dir = scratchDirectory("limits_batch_set");
    const json manifest = {{"jobs",
                            {{{"kind", "lsystem"},
                              {"inputs",
                               {{"file", RAMUS_SOURCE_DIR "/examples/lsystems/abop_1_24d.lsys"},
                                {"set", {{"a", 1e301}}}}},
                              {"output", "p.glb"}}}}};
    const fs::path path = writeInput(dir, "m.json", manifest.dump());
    const CommandResult r = runRamus("batch " + quoted(path) + " -o " + quoted(dir / "out"), dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("m.json: jobs[0].inputs.set.a: expected a number in [-1e+300, 1e+300]"),
              std::string::npos)
        << r.err;
}

// --- ramus pca, ramus species ---

TEST(LimitsCli, PcaConditionsAndJitterMustBeFinite) {
    const fs::path dir = scratchDirectory("limits_pca");
    const CommandResult condition = runRamus("pca sample --condition weight=nan", dir);
    EXPECT_EQ(condition.exitCode, 1);
    EXPECT_NE(condition.err.find("--condition: the value of 'weight=nan' is not finite"),
              std::string::npos)
        << condition.err;
    const CommandResult jitter = runRamus("pca sample --jitter inf", dir);
    EXPECT_EQ(jitter.exitCode, 2);
    EXPECT_NE(jitter.err.find("--jitter: expected a finite number >= 0"), std::string::npos)
        << jitter.err;
}

TEST(LimitsCli, SpeciesImportNumbersMustBeFinite) {
    const fs::path dir = scratchDirectory("limits_species");
    const fs::path svg = writeInput(dir, "a.svg", "<svg viewBox=\"0 0 10 10\"/>");
    for (const char* flag : {"--weight", "--wings", "--legs"}) {
        const CommandResult r =
            runRamus("species import-svg " + quoted(svg) + " " + flag + " nan", dir);
        EXPECT_EQ(r.exitCode, 2) << flag;
        EXPECT_NE(r.err.find(std::string(flag) + ": expected a finite number >= 0"),
                  std::string::npos)
            << r.err;
    }
}

}  // namespace
}  // namespace ramus::testing
