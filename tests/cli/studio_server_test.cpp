// The studio's JSON API against a real `ramus serve` on a free loopback port (issue 7 checks):
// good requests, malformed JSON, huge bodies, a runaway L-system, bad configs, concurrency.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_test_util.hpp"
#include "ramus/file_util.hpp"
#include "ramus/lsystem.hpp"

// After Eigen (via ramus headers): httplib.h pulls in <resolv.h>, whose `_res` macro breaks
// Eigen's headers.
#include <httplib.h>

extern char** environ;

namespace ramus::testing {
namespace {

using nlohmann::json;

/// `ramus serve --port 0` as a child process; the port comes from its first line of output.
class StudioServer {
public:
    /// `limits`: more `serve` flags (the defaults of the shared server below are generous).
    explicit StudioServer(const std::vector<std::string>& limits = {}) {
        int fds[2];
        if (pipe(fds) != 0) return;
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
        posix_spawn_file_actions_addclose(&actions, fds[0]);
        const std::string bin = ramusBinary();
        std::vector<std::string> args = {
            bin,          "serve", "--port",  "0", "--root",        RAMUS_SOURCE_DIR,
            "--jobs",     "2",     "--queue", "2", "--max-modules", "200000",
            "--max-body", "100000"};
        args.insert(args.end(), limits.begin(), limits.end());
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        if (posix_spawn(&pid_, bin.c_str(), &actions, nullptr, argv.data(), environ) != 0) {
            pid_ = -1;
        }
        posix_spawn_file_actions_destroy(&actions);
        close(fds[1]);
        std::string line;
        char c = 0;
        while (read(fds[0], &c, 1) == 1 && c != '\n') line += c;
        close(fds[0]);
        const std::size_t colon = line.rfind(':');
        if (colon != std::string::npos) port_ = std::atoi(line.c_str() + colon + 1);
    }
    ~StudioServer() {
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }
    int port() const { return port_; }
    bool running() const { return pid_ > 0 && port_ > 0; }

private:
    pid_t pid_ = -1;
    int port_ = 0;
};

StudioServer& server() {
    static StudioServer instance;
    return instance;
}

/// A second server with tight limits, for the tests of each limit.
StudioServer& tightServer() {
    static StudioServer instance({"--max-memory", "1", "--max-nodes", "300", "--max-iterations",
                                  "400", "--max-derivations", "12", "--max-skeletons", "3"});
    return instance;
}

httplib::Client client(const StudioServer& to = server()) {
    httplib::Client c("127.0.0.1", to.port());
    c.set_read_timeout(60, 0);
    return c;
}

struct Reply {
    int status = 0;
    json body;
};

Reply post(const std::string& path, const std::string& body, const StudioServer& to = server()) {
    auto c = client(to);
    auto res = c.Post(path.c_str(), body, "application/json");
    if (!res) return {};
    return {res->status, json::parse(res->body, nullptr, false)};
}

Reply post(const std::string& path, const json& body, const StudioServer& to = server()) {
    return post(path, body.dump(), to);
}

std::string decodeBase64(const std::string& text) {
    auto value = [](char ch) -> int {
        if (ch >= 'A' && ch <= 'Z') return ch - 'A';
        if (ch >= 'a' && ch <= 'z') return ch - 'a' + 26;
        if (ch >= '0' && ch <= '9') return ch - '0' + 52;
        return ch == '+' ? 62 : ch == '/' ? 63 : -1;
    };
    std::string out;
    int bits = 0, buffer = 0;
    for (char ch : text) {
        const int v = value(ch);
        if (v < 0) break;
        buffer = (buffer << 6) | v;
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += static_cast<char>((buffer >> bits) & 0xFF);
        }
    }
    return out;
}

/// Checks a base64 GLB and keeps it for the glTF validator.
void expectGlb(const json& glb, const std::string& name) {
    ASSERT_TRUE(glb.is_string());
    const std::string bytes = decodeBase64(glb.get<std::string>());
    ASSERT_GT(bytes.size(), 20u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    const auto dir = scratchDirectory("studio_" + name);
    writeFileAtomic((dir / (name + ".glb")).string(), bytes);
    keepForValidation(dir / (name + ".glb"), "studio_" + name + ".glb");
}

class Studio : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(server().running()) << "ramus serve did not start"; }
};

TEST_F(Studio, ListsExamplesSpeciesAndHeadKinds) {
    auto c = client();
    auto res = c.Get("/api/examples");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
    const json body = json::parse(res->body);
    EXPECT_GE(body["lsystems"].size(), 20u);
    EXPECT_GE(body["colonize"].size(), 3u);
    EXPECT_EQ(body["species"].size(), 44u);
    EXPECT_EQ(body["head_kinds"].size(), 4u);
    bool koch = false;
    for (const json& e : body["lsystems"]) koch = koch || e["name"] == "koch_island";
    EXPECT_TRUE(koch);
}

TEST_F(Studio, DerivesAnLSystemWithTheLibrarysModuleCount) {
    const std::string text = readFile(RAMUS_SOURCE_DIR "/examples/lsystems/koch_island.lsys");
    const Reply r = post("/api/lsystem", json{{"text", text}, {"derivations", 2}});
    ASSERT_EQ(r.status, 200) << r.body.dump();
    DeriveOptions options;
    options.derivations = 2;
    const std::size_t modules = deriveLSystem(parseLSystem(text), options).size();
    EXPECT_EQ(r.body["stats"]["modules"], modules);
    EXPECT_GT(r.body["stats"]["triangles"].get<int>(), 0);
    expectGlb(r.body["glb"], "koch_island");
}

// The bark options of the L-system panel: welding a dense plant (ABOP 1.27: crowded junctions)
// leaves pieces, which the reply counts and warns of; convex junctions keep the hulls the weld
// otherwise shrinks onto the branches (fewer triangles); the union (on a small tree, within the
// time budget) makes it one surface, without a warning; a wrong type names the key, and convex
// junctions without welding are refused.
TEST_F(Studio, WeldsAndUnitesTheBarkAndWarnsOfPieces) {
    const std::string dense = readFile(RAMUS_SOURCE_DIR "/examples/lsystems/abop_1_27.lsys");
    const Reply welded = post("/api/lsystem", json{{"text", dense}, {"mesh", {{"weld", true}}}});
    ASSERT_EQ(welded.status, 200) << welded.body.dump().substr(0, 300);
    EXPECT_GT(welded.body["stats"]["weld_crossing_tubes"].get<int>(), 0);
    ASSERT_EQ(welded.body["warnings"].size(), 1u);
    EXPECT_NE(welded.body["warnings"][0].get<std::string>().find("not one clean surface"),
              std::string::npos);
    const Reply tubes = post("/api/lsystem", json{{"text", dense}});
    EXPECT_FALSE(tubes.body["stats"].contains("weld_fallbacks"));
    EXPECT_TRUE(tubes.body["warnings"].empty());
    EXPECT_NE(tubes.body["stats"]["triangles"], welded.body["stats"]["triangles"]);
    const Reply convex =
        post("/api/lsystem",
             json{{"text", dense}, {"mesh", {{"weld", true}, {"convex_junctions", true}}}});
    ASSERT_EQ(convex.status, 200) << convex.body.dump().substr(0, 300);
    EXPECT_GT(welded.body["stats"]["weld_shrunk_junctions"].get<int>(), 0);
    EXPECT_EQ(convex.body["stats"]["weld_shrunk_junctions"], 0);
    EXPECT_LT(convex.body["stats"]["triangles"].get<int>(),
              welded.body["stats"]["triangles"].get<int>());

    const std::string small = readFile(RAMUS_SOURCE_DIR "/examples/lsystems/tree_3d.lsys");
    const Reply united = post(
        "/api/lsystem", json{{"text", small}, {"derivations", 3}, {"mesh", {{"union", true}}}});
    ASSERT_EQ(united.status, 200) << united.body.dump().substr(0, 300);
    EXPECT_EQ(united.body["stats"]["unions_applied"], 1);
    EXPECT_EQ(united.body["stats"]["union_crossings_left"], 0);
    EXPECT_EQ(united.body["stats"]["union_attempts"], 1);
    EXPECT_EQ(united.body["stats"]["union_postponed_moves"], 0);
    EXPECT_EQ(united.body["stats"]["union_reunions"], 0);
    EXPECT_EQ(united.body["stats"]["union_touching_points"], 0);
    EXPECT_EQ(united.body["stats"]["union_collapsed_edges"], 0);
    EXPECT_TRUE(united.body["warnings"].empty()) << united.body["warnings"].dump();

    const Reply wrong = post("/api/lsystem", json{{"text", small}, {"mesh", {{"weld", "yes"}}}});
    EXPECT_EQ(wrong.status, 400);
    EXPECT_NE(wrong.body["error"]["message"].get<std::string>().find("mesh.weld"),
              std::string::npos)
        << wrong.body.dump();
    const Reply tubesConvex =
        post("/api/lsystem", json{{"text", small}, {"mesh", {{"convex_junctions", true}}}});
    EXPECT_EQ(tubesConvex.status, 400);
    EXPECT_NE(tubesConvex.body["error"]["message"].get<std::string>().find("mesh.convex_junctions"),
              std::string::npos)
        << tubesConvex.body.dump();
}

TEST_F(Studio, ReportsASyntaxErrorAtItsLineAndColumn) {
    const Reply r = post("/api/lsystem", json{{"text", "axiom: F\nF -> F(+F\n"}});
    ASSERT_EQ(r.status, 400) << r.body.dump();
    EXPECT_EQ(r.body["error"]["line"], 2);
    EXPECT_GT(r.body["error"]["column"].get<int>(), 0);
    EXPECT_NE(r.body["error"]["message"].get<std::string>().find("input.lsys:2:"),
              std::string::npos);
}

TEST_F(Studio, StopsARunawayLSystemAtTheModuleLimit) {
    const Reply r =
        post("/api/lsystem", json{{"text", "axiom: A\nA -> AA\n"}, {"derivations", 40}});
    ASSERT_EQ(r.status, 400) << r.body.dump();
    EXPECT_NE(r.body["error"]["message"].get<std::string>().find("module limit"),
              std::string::npos);
}

TEST_F(Studio, RejectsMalformedJson) {
    const Reply r = post("/api/lsystem", std::string("{\"text\": "));
    ASSERT_EQ(r.status, 400);
    EXPECT_NE(r.body["error"]["message"].get<std::string>().find("malformed JSON"),
              std::string::npos);
    // A number beyond double range is a 400 too, not a server error.
    const Reply overflow = post("/api/lsystem", std::string("{\"text\": \"x\", \"seed\": 1e400}"));
    EXPECT_EQ(overflow.status, 400);
}

TEST_F(Studio, RejectsAHugeBodyWithAJsonError) {
    const Reply r = post("/api/lsystem", json{{"text", std::string(300'000, 'F')}});
    ASSERT_EQ(r.status, 413);
    EXPECT_NE(r.body["error"]["message"].get<std::string>().find("too large"), std::string::npos);
}

TEST_F(Studio, RejectsAWrongTypeNamingTheField) {
    const Reply r = post("/api/skeleton", json{{"legs", "four"}});
    ASSERT_EQ(r.status, 400);
    EXPECT_NE(r.body["error"]["message"].get<std::string>().find("legs"), std::string::npos);
}

TEST_F(Studio, GeneratesSkeletonsWithMetadata) {
    const Reply r = post("/api/skeleton", json{{"legs", 4}, {"count", 2}, {"seed", 7}});
    ASSERT_EQ(r.status, 200) << r.body.dump();
    ASSERT_EQ(r.body["skeletons"].size(), 2u);
    EXPECT_EQ(r.body["skeletons"][1]["name"], "skeleton1");
    EXPECT_EQ(r.body["skeletons"][0]["metadata"]["seed"], "7");
    expectGlb(r.body["skeletons"][0]["glb"], "skeleton_4_legs");
    // The same request gives the same model (seeded).
    const Reply again = post("/api/skeleton", json{{"legs", 4}, {"count", 2}, {"seed", 7}});
    EXPECT_EQ(again.body["skeletons"][0]["glb"], r.body["skeletons"][0]["glb"]);
}

TEST_F(Studio, GeneratesSkeletonsWithBoneModels) {
    const Reply r =
        post("/api/skeleton", json{{"legs", 2}, {"resolution", "low"}, {"head", "bird"}});
    ASSERT_EQ(r.status, 200) << r.body.dump();
    expectGlb(r.body["skeletons"][0]["glb"], "skeleton_low_bird");
    const Reply bad = post("/api/skeleton", json{{"resolution", "ultra"}});
    EXPECT_EQ(bad.status, 400);
}

TEST_F(Studio, RegeneratesASavedSkeleton) {
    const Reply first = post("/api/skeleton", json{{"wings", 2}, {"seed", 3}});
    ASSERT_EQ(first.status, 200) << first.body.dump();
    json saved = first.body["skeletons"][0]["metadata"];
    saved.erase("skeleton");  // the bone list is informative; the design regenerates it
    const Reply again = post("/api/skeleton", json{{"saved", saved}});
    ASSERT_EQ(again.status, 200) << again.body.dump();
    EXPECT_EQ(again.body["skeletons"][0]["glb"], first.body["skeletons"][0]["glb"]);
}

TEST_F(Studio, ColonizesAConfigAndReturnsItsPoints) {
    const json config = json::parse(readFile(RAMUS_SOURCE_DIR "/examples/colonize/broadleaf.json"));
    const Reply r = post("/api/colonize", json{{"config", config}});
    ASSERT_EQ(r.status, 200) << r.body.dump();
    EXPECT_GT(r.body["stats"]["nodes"].get<int>(), 100);
    EXPECT_EQ(r.body["points"].size() % 3, 0u);
    EXPECT_GT(r.body["points"].size(), 0u);
    expectGlb(r.body["glb"], "broadleaf");
}

TEST_F(Studio, RefusesConfigsThatReadServerFiles) {
    const json config = {{"envelopes", {{{"shape", "mesh"}, {"file", "/etc/passwd"}}}}};
    const Reply r = post("/api/colonize", json{{"config", config}});
    ASSERT_EQ(r.status, 400);
    EXPECT_NE(r.body["error"]["message"].get<std::string>().find("envelopes[0].file"),
              std::string::npos);
}

TEST_F(Studio, AnswersConcurrentRequestsOrSaysItIsBusy) {
    std::atomic<int> ok{0}, busy{0}, other{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 8; ++t) {
        threads.emplace_back([&, t] {
            const Reply r = post("/api/skeleton", json{{"legs", 4}, {"seed", t}, {"count", 4}});
            (r.status == 200 ? ok : r.status == 503 ? busy : other)++;
        });
    }
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(other.load(), 0);
    EXPECT_GE(ok.load(), 4);  // 2 running + 2 queued at least
    EXPECT_EQ(ok.load() + busy.load(), 8);
    // Still alive afterwards.
    EXPECT_EQ(post("/api/skeleton", json{{"legs", 2}}).status, 200);
}

TEST_F(Studio, UnknownRoutesGetAJson404) {
    auto c = client();
    auto res = c.Get("/api/nothing");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 404);
    EXPECT_TRUE(json::parse(res->body).contains("error"));
}

}  // namespace
}  // namespace ramus::testing

namespace ramus::testing {
namespace {

std::string messageOf(const Reply& r) {
    if (!r.body.is_object() || !r.body.contains("error")) return "(no error)";
    return r.body["error"].value("message", "(no message)");
}

TEST(StudioLimits, AParametricWordStopsAtTheMemoryLimit) {
    ASSERT_TRUE(tightServer().running());
    // A(p0, …, p31) doubles each step: 12 + 32 · 8 = 268 bytes per module, so step k holds
    // 268 · 3 · 2^(k−1) bytes: 823 296 at step 11, 1 646 592 (over 1 MiB) at step 12 — with
    // only 4096 modules, far below the module limit of 200 000.
    std::string params, values;
    for (int i = 0; i < 32; ++i) {
        params += (i ? ",p" : "p") + std::to_string(i);
        values += (i ? ",1" : "1");
    }
    const std::string text =
        "axiom: A(" + values + ")\nA(" + params + ") -> A(" + params + ") A(" + params + ")";
    const Reply ok = post("/api/lsystem", json{{"text", text}, {"derivations", 11}}, tightServer());
    EXPECT_EQ(ok.status, 200) << ok.body.dump().substr(0, 300);
    const Reply r = post("/api/lsystem", json{{"text", text}, {"derivations", 12}}, tightServer());
    ASSERT_EQ(r.status, 400) << r.body.dump();
    EXPECT_NE(messageOf(r).find("input.lsys: derivation step 12 of 12 would exceed the memory "
                                "limit of 1 MiB (1048576 bytes)"),
              std::string::npos)
        << messageOf(r);
}

TEST(StudioLimits, DerivationsAboveTheLimitAreRefused) {
    ASSERT_TRUE(tightServer().running());
    const Reply r =
        post("/api/lsystem", json{{"text", "axiom: F"}, {"derivations", 13}}, tightServer());
    ASSERT_EQ(r.status, 400) << r.body.dump();
    EXPECT_NE(messageOf(r).find("derivations: expected an integer in [0, 12]"), std::string::npos)
        << messageOf(r);
}

TEST(StudioLimits, ColonizationStopsAtTheNodeLimit) {
    ASSERT_TRUE(tightServer().running());
    // One point far away: the trunk grows one node per iteration towards it, 399 in all.
    const json config = {
        {"step", 1},
        {"max_iterations", 399},
        {"envelopes",
         {{{"shape", "sphere"}, {"center", {0, 2000, 0}}, {"radius", 1}, {"points", 1}}}}};
    const Reply r = post("/api/colonize", json{{"config", config}}, tightServer());
    ASSERT_EQ(r.status, 413) << r.body.dump();
    EXPECT_NE(messageOf(r).find("the studio allows at most 300 nodes"), std::string::npos)
        << messageOf(r);
}

TEST(StudioLimits, IterationsAboveTheLimitAre413BeforeAnyGrowth) {
    ASSERT_TRUE(tightServer().running());
    const json config = {{"max_iterations", 401},
                         {"envelopes", {{{"shape", "sphere"}, {"radius", 1}, {"points", 1}}}}};
    const Reply r = post("/api/colonize", json{{"config", config}}, tightServer());
    ASSERT_EQ(r.status, 413) << r.body.dump();
    EXPECT_NE(messageOf(r).find("config.max_iterations: 401; the studio allows at most 400"),
              std::string::npos)
        << messageOf(r);
}

TEST(StudioLimits, SkeletonCountAboveTheLimitIsRefused) {
    ASSERT_TRUE(tightServer().running());
    const Reply r = post("/api/skeleton", json{{"count", 4}}, tightServer());
    ASSERT_EQ(r.status, 400) << r.body.dump();
    EXPECT_NE(messageOf(r).find("count: expected an integer in [1, 3]"), std::string::npos)
        << messageOf(r);
}

TEST(StudioLimits, NonFiniteLimitFlagsAreUsageErrors) {
    const std::filesystem::path dir = scratchDirectory("serve_nonfinite");
    for (const char* value : {"nan", "inf", "0"}) {
        const CommandResult r = runRamus(std::string("serve --port 0 --time-limit ") + value, dir);
        EXPECT_EQ(r.exitCode, 2) << value;
        EXPECT_NE(r.err.find("--time-limit: expected a number of seconds"), std::string::npos)
            << r.err;
    }
}

}  // namespace
}  // namespace ramus::testing
