#include "tree_output.hpp"

#include <cmath>
#include <cstdio>

#include "cli_checks.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/render.hpp"
#include "ramus/solid_union.hpp"
#include "ramus/tree_json.hpp"
#include "ramus/tree_textures.hpp"

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

void writeTreeOutputs(const TreeOutputs& outputs, const BranchTree& tree, const TreeModel& model,
                      const TubeMeshParams& meshParams) {
    const Mesh& mesh = model.mesh;
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
    if (!outputs.model.empty()) writeScene(model.scene(), outputs.model);
    if (!outputs.treeJson.empty()) {
        writeFileAtomic(outputs.treeJson, encodeTreeJson(tree, computeEdgeRadii(tree, meshParams)));
    }
    if (!outputs.png.empty()) {
        writePng(renderScene(makeSingleMeshScene(mesh, "tree"), render), outputs.png);
    }
}

void StageTimer::lap(std::string name) {
    const auto now = std::chrono::steady_clock::now();
    stages_.emplace_back(std::move(name), std::chrono::duration<double>(now - start_).count());
    start_ = now;
}

void addStageSeconds(nlohmann::ordered_json& stats, const StageTimer& timer) {
    for (const auto& [name, seconds] : timer.stages()) stats[name + "_seconds"] = seconds;
}

void printTreeStats(nlohmann::ordered_json counts, const TreeModel& model,
                    const StageTimer& timer) {
    counts["vertices"] = model.mesh.vertexCount();
    counts["triangles"] = model.mesh.triangleCount();
    counts["leaf_triangles"] = primitiveTriangles(model.mesh, "leaves");
    if (!model.lods.empty()) {
        nlohmann::ordered_json lods = nlohmann::ordered_json::array();
        for (const TreeLod& lod : model.lods) lods.push_back(lod.mesh.triangleCount());
        counts["lod_triangles"] = lods;
    }
    addBarkStats(counts, model.report);
    addStageSeconds(counts, timer);
    std::printf("%s\n", counts.dump().c_str());
}

void addBarkStats(nlohmann::ordered_json& stats, const TreeMeshReport& report) {
    if (report.weldedMeshes > 0) {
        stats["weld_fallbacks"] = report.weldFallbacks;
        stats["weld_crossings"] = report.weldCrossings;
        stats["weld_crossing_tubes"] = report.weldCrossingTubes;
        stats["weld_shared_rings"] = report.weldSharedRings;
        stats["weld_shrunk_junctions"] = report.shrunkJunctions;
    }
    if (report.unionsApplied + report.unionsFailed > 0) {
        stats["unions_applied"] = report.unionsApplied;
        stats["unions_failed"] = report.unionsFailed;
        stats["unions_of_convex_junctions"] = report.unionsOfHulls;
        stats["union_tubed_junctions"] = report.tubedForUnion;
        stats["union_crossings_left"] = report.crossingsLeft;
        stats["union_pinched_edges"] = report.pinchedEdges;
        stats["union_touching_points"] = report.touchingPoints;
        stats["union_crossing_moves"] = report.crossingMoves;
        stats["union_collapsed_edges"] = report.collapsedEdges;
        stats["union_attempts"] = report.unionAttempts;
        stats["union_postponed_moves"] = report.postponedMoves;
        stats["union_reunions"] = report.reunions;
    }
}

std::string barkWarning(const TreeMeshReport& report) {
    if (report.unionsFailed > 0) {
        return "solid union not applied to " + std::to_string(report.unionsFailed) + " of " +
               std::to_string(report.unionsFailed + report.unionsApplied) +
               " bark meshes, which stay welded but overlapping (first: " + report.firstFailure +
               ")";
    }
    if (report.unionsApplied > 0 || report.weldFallbacks + report.weldCrossings == 0) return {};
    return "the welded bark is not one clean surface: " +
           std::to_string(report.weldFallbacks + report.weldCrossingTubes) +
           " crowded junctions were closed as separate capped tubes (" +
           std::to_string(report.weldCrossings) +
           " branches between them too short for the rings at both ends), which overlap; " +
           (solidUnionAvailable()
                ? "the solid union (--union) makes it one surface"
                : "the solid union (--union) would make it one surface, but needs a build with "
                  "CGAL");
}

void warnOfBarkCompromises(const TreeModel& model) {
    const std::string warning = barkWarning(model.report);
    if (!warning.empty()) std::fprintf(stderr, "warning: %s\n", warning.c_str());
}

namespace {

TreeMeshInput plantInput(const TurtleResult& shape) {
    return TreeMeshInput{&shape.tree, shape.polygonVertices, shape.polygonOffsets,
                         shape.polygonNodes};
}

std::vector<TreeMeshInput> forestInputs(const std::vector<BranchTree>& trees) {
    std::vector<TreeMeshInput> inputs;
    for (const BranchTree& tree : trees) inputs.push_back(TreeMeshInput{&tree, {}, {}, {}});
    return inputs;
}

TreeModel modelOf(std::span<const TreeMeshInput> inputs, const TreeMeshParams& params,
                  const std::vector<double>& lods) {
    TreeModel model;
    if (lods.empty()) {
        model.mesh = buildTreeMesh(inputs, params, &model.report);
    } else {
        model.lods = buildTreeLods(inputs, params, lods, &model.report);
        model.mesh = model.lods.front().mesh;
        model.mesh.name = "tree";
    }
    return model;
}

}  // namespace

TreeModel plantModel(const TurtleResult& shape, const TreeMeshParams& params,
                     const std::vector<double>& lods) {
    const TreeMeshInput input = plantInput(shape);
    return modelOf({&input, 1}, params, lods);
}

TreeModel forestModel(const std::vector<BranchTree>& trees, const TreeMeshParams& params,
                      const std::vector<double>& lods) {
    return modelOf(forestInputs(trees), params, lods);
}

Scene TreeModel::scene() const {
    if (lods.empty()) return makeSingleMeshScene(mesh, "tree");
    Scene scene;
    SceneNode root;
    root.name = "tree";
    scene.nodes.push_back(root);
    for (std::size_t i = 0; i < lods.size(); ++i) {
        scene.meshes.push_back(lods[i].mesh);
        SceneNode node;
        node.name = lods[i].mesh.name;
        node.parent = 0;
        node.mesh = static_cast<int>(i);
        nlohmann::ordered_json extras;
        extras["lod"] = i;
        extras["ratio"] = lods[i].ratio;
        extras["triangles"] = lods[i].mesh.triangleCount();
        extras["target_triangles"] = lods[i].targetTriangles;
        node.extrasJson = extras.dump();
        scene.nodes.push_back(std::move(node));
    }
    return scene;
}

namespace {

// "1,0.4,0.15" → ratios in (0, 1].
std::vector<double> parseLodRatios(const std::string& text) {
    std::vector<double> ratios;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        double value = 0.0;
        if (!CLI::detail::lexical_cast(item, value) || !(value > 0.0 && value <= 1.0)) {
            throw Error("--lods: invalid ratio '" + item +
                        "'; expected comma-separated numbers in (0, 1], e.g. 1,0.4,0.15");
        }
        ratios.push_back(value);
        start = comma + 1;
    }
    if (ratios.size() > 16)
        throw Error("--lods: " + std::to_string(ratios.size()) + " levels; expected at most 16");
    return ratios;
}

std::array<float, 4> parseAtlas(const std::string& text) {
    std::array<float, 4> atlas{};
    std::size_t start = 0;
    for (int i = 0; i < 4; ++i) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        double value = -1.0;
        if (start > text.size() ||
            !CLI::detail::lexical_cast(text.substr(start, comma - start), value) ||
            !(value >= 0.0 && value <= 1.0) || (i == 3 && comma != text.size())) {
            throw Error("--leaf-atlas: invalid region '" + text +
                        "'; expected u0,v0,u1,v1 with each in [0, 1], e.g. 0,0,0.5,0.5");
        }
        atlas[i] = static_cast<float>(value);
        start = comma + 1;
    }
    if (!(atlas[2] > atlas[0] && atlas[3] > atlas[1])) {
        throw Error("--leaf-atlas: region '" + text + "' is empty; expected u1 > u0 and v1 > v0");
    }
    return atlas;
}

// The default textures, made once per process (they are pure functions of fixed settings).
const TreeTextures& defaultTextures() {
    static const TreeTextures textures = makeTreeTextures();
    return textures;
}

}  // namespace

void addAssetOptions(CLI::App& command, AssetOptions& o) {
    o.command = &command;
    command.add_flag("--leaves", o.leaves, "generate leaves near the branch tips (docs/export.md)");
    command.add_option("--leaf-shape", o.leafShape, "blade (12 triangles) or card (a quad)")
        ->check(CLI::IsMember({"blade", "card"}));
    command.add_option("--leaves-per-tip", o.leaf.perTip, "leaves at every tip")
        ->check(CLI::Range(0, 1000));
    command
        .add_option("--leaves-per-length", o.leaf.perLength,
                    "leaves per model unit along branches near tips")
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"));
    command
        .add_option("--leaf-zone", o.leaf.zone,
                    "distance from a tip where --leaves-per-length applies (0 = 4 leaf lengths)")
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"));
    command.add_option("--leaf-size", o.leaf.size, "leaf length (0 = the mean edge length)")
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"));
    command.add_option("--leaf-width", o.leaf.widthRatio, "leaf width / length")
        ->check(finiteNumber(0.0, false, 4.000001, "a number in (0, 4]"));
    command
        .add_option("--phyllotaxis", o.leaf.phyllotaxisDegrees,
                    "azimuth step between leaves, degrees (137.5 = golden angle)")
        ->check(finiteNumber(-360.000001, false, 360.000001, "an angle in [-360, 360]"));
    command
        .add_option("--leaf-tilt", o.leaf.tiltDegrees, "angle of a leaf from its branch, degrees")
        ->check(finiteNumber(-180.000001, false, 180.000001, "an angle in [-180, 180]"));
    command.add_option("--leaf-seed", o.leaf.seed, "seed of the leaves' random variation");
    command.add_option("--leaf-atlas", o.atlas, "leaf texture region u0,v0,u1,v1 (glTF UVs)");
    command.add_flag("--wind", o.wind,
                     "write wind vertex attributes _WIND, _WIND_PIVOT, _WIND_LEAF");
    command.add_flag("--no-textures", o.noTextures, "no procedural bark and leaf textures");
    command.add_flag("--weld", o.weld,
                     "mesh each tree as one closed surface (welded junctions, docs/welded.md) "
                     "instead of overlapping tubes");
    command.add_flag("--union", o.solidUnion,
                     "with --weld (implied): unite the welded pieces and self-crossing branches "
                     "into one surface without self-intersections (docs/welded.md; slower)");
    command.add_flag("--convex-junctions", o.convexJunctions,
                     "with --weld: keep each junction the convex hull of its rings (fewer "
                     "triangles; webs over crotches where branches leave at small angles)");
    command
        .add_option("--uv-aspect", o.uvAspect,
                    "bark texture height / width (default: the built-in texture's, 2)")
        ->check(finiteNumber(0.0, false, 1e6, "a number in (0, 1e6]"));
    command.add_option("--lods", o.lods, "levels of detail as triangle ratios, e.g. 1,0.4,0.15");
}

AssetSettings applyAssetOptions(const TubeMeshParams& tube, const AssetOptions& o,
                                AssetSettings s) {
    const CLI::App& c = *o.command;
    const TubeMeshParams base = s.mesh.tube;
    s.mesh.tube = tube;
    s.mesh.tube.uvAspect = base.uvAspect;
    s.mesh.tube.windAttributes = base.windAttributes || c.count("--wind") > 0;
    LeafParams& leaf = s.mesh.leaf;
    if (c.count("--leaves")) s.mesh.leaves = true;
    if (!o.leafShape.empty()) leaf.shape = parseLeafShape(o.leafShape);
    if (c.count("--leaves-per-tip")) leaf.perTip = o.leaf.perTip;
    if (c.count("--leaves-per-length")) leaf.perLength = o.leaf.perLength;
    if (c.count("--leaf-zone")) leaf.zone = o.leaf.zone;
    if (c.count("--leaf-size")) leaf.size = o.leaf.size;
    if (c.count("--leaf-width")) leaf.widthRatio = o.leaf.widthRatio;
    if (c.count("--phyllotaxis")) leaf.phyllotaxisDegrees = o.leaf.phyllotaxisDegrees;
    if (c.count("--leaf-tilt")) leaf.tiltDegrees = o.leaf.tiltDegrees;
    if (c.count("--leaf-seed")) leaf.seed = o.leaf.seed;
    if (!o.atlas.empty()) leaf.atlas = parseAtlas(o.atlas);
    if (c.count("--no-textures")) s.textures = false;
    if (c.count("--uv-aspect")) {
        s.mesh.tube.uvAspect = o.uvAspect;
        s.uvAspectGiven = true;
    }
    if (!o.lods.empty()) s.lods = parseLodRatios(o.lods);
    if (c.count("--weld")) s.mesh.weldJunctions = true;
    if (c.count("--union")) s.mesh.weldJunctions = s.mesh.solidUnion = true;
    if (c.count("--convex-junctions")) s.mesh.convexJunctions = true;
    return finishAssets(std::move(s));
}

AssetSettings configAssets(const ColonizeConfig& config) {
    AssetSettings s;
    const ColonizeConfig::MeshOverrides& m = config.mesh;
    s.mesh.tube.windAttributes = m.hasWind && m.wind;
    if (m.hasUvAspect) {
        s.mesh.tube.uvAspect = m.uvAspect;
        s.uvAspectGiven = true;
    }
    if (m.hasTextures) s.textures = m.textures;
    s.mesh.weldJunctions = (m.hasWeld && m.weld) || (m.hasSolidUnion && m.solidUnion);
    s.mesh.solidUnion = m.hasSolidUnion && m.solidUnion;
    s.mesh.convexJunctions = m.hasConvexJunctions && m.convexJunctions;
    s.lods = m.lods;
    s.mesh.leaves = config.hasLeaves;
    if (config.hasLeaves) s.mesh.leaf = config.leaves;
    if (config.hasGround) s.mesh.leaf.minHeight = config.ground;  // bare root systems
    return s;
}

AssetSettings colonizeAssets(const ColonizeConfig& config) {
    AssetSettings s = configAssets(config);
    TubeMeshParams tube;
    applyMeshOverrides(config, tube);
    tube.uvAspect = s.mesh.tube.uvAspect;
    tube.windAttributes = s.mesh.tube.windAttributes;
    s.mesh.tube = tube;
    return finishAssets(std::move(s));
}

AssetSettings finishAssets(AssetSettings s) {
    validateLeafParams(s.mesh.leaf);
    // Before any growing or meshing: a build without CGAL says so at once.
    if (s.mesh.solidUnion && !solidUnionAvailable()) throw Error(std::string(kSolidUnionMissing));
    if (s.mesh.convexJunctions && !s.mesh.weldJunctions) {
        throw Error(
            "convex junctions are welded junctions kept as hulls: expected --weld or "
            "--union with --convex-junctions (\"weld\": true with "
            "\"convex_junctions\" in a config)");
    }
    if (s.textures) {
        const TreeTextures& t = defaultTextures();
        Material& bark = s.mesh.tube.material;
        bark.baseColor = Vec4f::Ones();
        bark.baseColorTexture = t.barkColor;
        bark.normalTexture = t.barkNormal;
        if (!s.uvAspectGiven) s.mesh.tube.uvAspect = t.barkAspect;
        LeafParams& leaf = s.mesh.leaf;
        leaf.material.baseColor = Vec4f::Ones();
        leaf.material.baseColorTexture = t.leafColor;
        leaf.material.alphaMask = true;
    }
    return s;
}

}  // namespace ramus::cli
