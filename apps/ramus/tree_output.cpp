#include "tree_output.hpp"

#include <cmath>
#include <cstdio>

#include "cli_checks.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/render.hpp"
#include "ramus/tree_json.hpp"

namespace ramus::cli {

void checkIterationLimit(const ColonizeConfig& config, int limit, const std::string& configName) {
    if (config.params.maxIterations > limit) {
        throw Error(configName +
                    ": max_iterations: " + std::to_string(config.params.maxIterations) +
                    " is above the limit of " + std::to_string(limit) +
                    " iterations; expected fewer, or a larger --max-iterations");
    }
}

void addTreeOutputOptions(CLI::App& command, TreeOutputs& outputs) {
    command.add_option("-o,--output", outputs.model, "write the model: OUT.glb or OUT.obj");
    command.add_option("--tree-json", outputs.treeJson, "write the branch tree as JSON");
    command.add_option("--png", outputs.png, "write a PNG preview");
    command.add_option("--view", outputs.view, "preview view: side|front|top|three-quarter")
        ->capture_default_str();
    command.add_option("--size", outputs.size, "preview size WxH")->capture_default_str();
}

void addTubeMeshOptions(CLI::App& command, TubeMeshParams& params) {
    command
        .add_option("--leaf-radius", params.leafRadius,
                    "tip radius r0 for Murray's rule, model units (0 = 4% of mean edge)")
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"));
    command.add_option("--radius-exponent", params.radiusExponent, "Murray exponent g (> 0)")
        ->check(finiteNumber(0.0, false, kHugeNumber, "a finite number > 0"))
        ->capture_default_str();
    command
        .add_option("--trunk-multiplier", params.trunkMultiplier,
                    "root ring radius = multiplier x root edge radius")
        ->check(finiteNumber(0.0, false, kHugeNumber, "a finite number > 0"))
        ->capture_default_str();
    command.add_option("--min-segments", params.minSegments, "ring vertices, thinnest branches")
        ->check(CLI::Range(3, 256))
        ->capture_default_str();
    command.add_option("--max-segments", params.maxSegments, "ring vertices, thickest branches")
        ->check(CLI::Range(3, 256))
        ->capture_default_str();
    command
        .add_option("--curve-reduction", params.curveReduction,
                    "max_K in [0,1): skip rings where a chain is this straight (0 = off)")
        ->check(finiteNumber(0.0, true, 1.0, "a number in [0, 1)"));
    command
        .add_option(
            "--no-caps",
            [&params](const CLI::results_t&) {
                params.capTips = false;
                return true;
            },
            "leave branch tips open")
        ->expected(0);
}

void writeTreeOutputs(const TreeOutputs& outputs, const BranchTree& tree, const Mesh& mesh,
                      const TubeMeshParams& meshParams) {
    if (mesh.positions.empty() && (!outputs.model.empty() || !outputs.png.empty())) {
        std::fprintf(stderr, "warning: the tree has no drawn branches; the model is empty\n");
    }
    // Validate everything before writing anything, so bad flags leave no files behind.
    RenderParams render;
    if (!outputs.png.empty()) {
        render.view = parseView(outputs.view);
        const ImageSize size = ramus::parseImageSize(outputs.size);
        render.width = size.width;
        render.height = size.height;
    }
    const Scene scene = makeSingleMeshScene(mesh, "tree");
    if (!outputs.model.empty()) writeScene(scene, outputs.model);
    if (!outputs.treeJson.empty()) {
        writeFileAtomic(outputs.treeJson, encodeTreeJson(tree, computeEdgeRadii(tree, meshParams)));
    }
    if (!outputs.png.empty()) writePng(renderScene(scene, render), outputs.png);
}

void StageTimer::lap(std::string name) {
    const auto now = std::chrono::steady_clock::now();
    stages_.emplace_back(std::move(name), std::chrono::duration<double>(now - start_).count());
    start_ = now;
}

void addStageSeconds(nlohmann::ordered_json& stats, const StageTimer& timer) {
    for (const auto& [name, seconds] : timer.stages()) stats[name + "_seconds"] = seconds;
}

void printTreeStats(nlohmann::ordered_json counts, const Mesh& mesh, const StageTimer& timer) {
    counts["vertices"] = mesh.vertexCount();
    counts["triangles"] = mesh.triangleCount();
    addStageSeconds(counts, timer);
    std::printf("%s\n", counts.dump().c_str());
}

Mesh plantMesh(const TurtleResult& shape, const TubeMeshParams& params) {
    Mesh mesh = buildTubeMesh(shape.tree, params);
    if (shape.polygonCount() > 0) {
        appendMesh(mesh, buildPolygonMesh(shape.polygonVertices, shape.polygonOffsets));
    }
    return mesh;
}

Mesh forestMesh(const std::vector<BranchTree>& trees, const TubeMeshParams& params) {
    Mesh mesh;
    for (const BranchTree& tree : trees) appendMesh(mesh, buildTubeMesh(tree, params));
    return mesh;
}

}  // namespace ramus::cli
