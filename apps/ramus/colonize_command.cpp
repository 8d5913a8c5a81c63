// `ramus colonize CONFIG.json …`: sample the envelopes, grow by space colonization, mesh,
// write (docs/colonize.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "ramus/colonize.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/tree_json.hpp"
#include "ramus/tube_mesher.hpp"
#include "tree_output.hpp"

namespace ramus::cli {

namespace {

struct ColonizeOptions {
    std::string config;
    std::vector<std::string> seed;  // 0 or 1 value; a vector tells "absent" from "0"
    std::string points;
    std::size_t maxPoints = 50'000'000;
    std::size_t maxNodes = ColonizeParams{}.maxNodes;
    int maxIterations = kDefaultMaxIterations;
    std::size_t maxFileMiB = kMaxInputFileBytes >> 20;
    bool stats = false;
    TreeOutputs outputs;
    TubeMeshParams mesh;  // flags; applied over the config's "mesh" object when given
    AssetOptions assets;
    CLI::App* command = nullptr;
};

// Mesher settings: defaults, then the config's "mesh" object, then the flags given.
TubeMeshParams meshParams(const ColonizeOptions& o, const ColonizeConfig& config) {
    TubeMeshParams p;
    applyMeshOverrides(config, p);
    const CLI::App& c = *o.command;
    if (c.count("--leaf-radius")) p.leafRadius = o.mesh.leafRadius;
    if (c.count("--radius-exponent")) p.radiusExponent = o.mesh.radiusExponent;
    if (c.count("--trunk-multiplier")) p.trunkMultiplier = o.mesh.trunkMultiplier;
    if (c.count("--min-segments")) p.minSegments = o.mesh.minSegments;
    if (c.count("--max-segments")) p.maxSegments = o.mesh.maxSegments;
    if (c.count("--curve-reduction")) p.curveReduction = o.mesh.curveReduction;
    if (c.count("--no-caps")) p.capTips = false;
    if (p.maxSegments < p.minSegments) {
        throw Error("max_segments " + std::to_string(p.maxSegments) + " is below min_segments " +
                    std::to_string(p.minSegments) + "; expected max_segments >= min_segments");
    }
    return p;
}

// One tree: the usual tree JSON; several: {"trees":[…]} with one such object per root.
std::string encodeForest(const std::vector<BranchTree>& trees, const TubeMeshParams& mesh) {
    if (trees.size() == 1) return encodeTreeJson(trees[0], computeEdgeRadii(trees[0], mesh));
    std::string text = "{\"trees\":[";
    for (std::size_t t = 0; t < trees.size(); ++t) {
        if (t > 0) text += ",";
        std::string one = encodeTreeJson(trees[t], computeEdgeRadii(trees[t], mesh));
        while (!one.empty() && (one.back() == '\n' || one.back() == ' ')) one.pop_back();
        text += one;
    }
    return text + "]}\n";
}

/// --max-points: checked on the envelopes' counts before sampling, and on all points after.
void checkPointCount(std::size_t count, std::size_t limit, const char* what) {
    if (count > limit) {
        throw Error(std::string(what) + " " + std::to_string(count) +
                    " attraction points, above the limit of " + std::to_string(limit) +
                    "; expected fewer points, or a larger --max-points");
    }
}

void run(ColonizeOptions& o) {
    const std::size_t maxFileBytes = o.maxFileMiB << 20;
    ColonizeConfig config = loadColonizeConfig(o.config, maxFileBytes);
    if (!o.seed.empty()) config.seed = parseSeed(o.seed.front());
    config.params.maxNodes = o.maxNodes;
    checkIterationLimit(config, o.maxIterations, o.config);
    std::size_t requested = 0;
    for (const Envelope& e : config.envelopes) requested += e.pointCount;
    checkPointCount(requested, o.maxPoints, "the envelopes ask for");
    const TubeMeshParams mesh = meshParams(o, config);
    const AssetSettings assets = applyAssetOptions(mesh, o.assets, configAssets(config));
    if (!o.stats && !o.outputs.any()) {
        o.outputs.model = std::filesystem::path(o.config).stem().string() + ".glb";
        std::fprintf(stderr, "writing %s (use -o to choose the output)\n", o.outputs.model.c_str());
    }

    StageTimer timer;
    std::vector<Vec3> points = configAttractionPoints(config);
    if (!o.points.empty()) {
        const std::vector<Vec3> extra =
            removePointsInside(readPointsFile(o.points, maxFileBytes), config.obstacles);
        points.insert(points.end(), extra.begin(), extra.end());
    }
    checkPointCount(points.size(), o.maxPoints, "the config and --points give");
    timer.lap("sample");

    const ColonizeResult result = growFromConfig(config, points);
    timer.lap("grow");
    for (const std::string& w : result.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

    timer.restart();
    const TreeModel model = forestModel(result.trees, assets.mesh, assets.lods);
    warnOfBarkCompromises(model);
    timer.lap("mesh");

    TreeOutputs outputs = o.outputs;
    outputs.treeJson.clear();  // written below, for all trees
    writeTreeOutputs(outputs, result.trees.front(), model, mesh);
    if (!o.outputs.treeJson.empty()) {
        writeFileAtomic(o.outputs.treeJson, encodeForest(result.trees, mesh));
    }
    if (o.stats) {
        nlohmann::ordered_json stats;
        stats["trees"] = result.trees.size();
        stats["attractors"] = result.attractors;
        stats["attractors_left"] = result.attractorsLeft;
        stats["iterations"] = result.iterations;
        stats["nodes"] = result.nodeCount();
        printTreeStats(std::move(stats), model, timer);
    }
}

}  // namespace

void addColonizeCommand(CLI::App& app) {
    auto options = std::make_shared<ColonizeOptions>();
    CLI::App* cmd =
        app.add_subcommand("colonize", "grow trees by space colonization from a config (.json)");
    options->command = cmd;
    cmd->add_option("CONFIG", options->config, "the colonization config (docs/colonize.md)")
        ->required();
    cmd->add_option("--seed", options->seed, "base seed mixed into every envelope's seed")
        ->expected(1);
    cmd->add_option("--points", options->points,
                    "extra attraction points from a .xyz, .txt, .csv or ASCII .ply file");
    cmd->add_option("--max-points", options->maxPoints,
                    "stop with an error when there would be more attraction points")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--max-nodes", options->maxNodes,
                    "stop with an error when the trees would grow more nodes")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--max-iterations", options->maxIterations,
                    "stop with an error when the config's max_iterations is above this")
        ->check(CLI::Range(1, 100'000'000))
        ->capture_default_str();
    cmd->add_option("--max-file-size", options->maxFileMiB,
                    "largest config, point or mesh file to read, in MiB")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20))
        ->capture_default_str();
    cmd->add_flag("--stats", options->stats, "print statistics as one JSON object");
    addTreeOutputOptions(*cmd, options->outputs);
    addTubeMeshOptions(*cmd, options->mesh);
    addAssetOptions(*cmd, options->assets);
    cmd->callback([options] { run(*options); });
}

}  // namespace ramus::cli
