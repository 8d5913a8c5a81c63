// The studio's L-system, colonization and examples endpoints (studio_api.hpp, docs/studio.md).
#include "serve/studio_api.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ramus/colonize.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/species.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/turtle.hpp"
#include "serve/studio_request.hpp"

namespace ramus::studio {
namespace {

namespace fs = std::filesystem;

// The request's "mesh" object: the tube settings, and whether the bark is welded into one
// surface ("weld") or also united ("union", implies weld), as `ramus lsystem --weld / --union`,
// and whether welded junctions keep their convex hulls ("convex_junctions", as
// `--convex-junctions`: only with weld or union).
TreeMeshParams meshParamsFrom(const nlohmann::json& request) {
    TreeMeshParams mesh;
    TubeMeshParams& params = mesh.tube;
    const nlohmann::json* object = optionalMember(request, "mesh", nlohmann::json::value_t::object);
    if (!object) return mesh;
    for (const auto& [key, value] : object->items()) {
        const std::string path = "mesh." + key;
        if (key == "leaf_radius") {
            params.leafRadius = numberIn(value, path, 0.0, 1e9);
        } else if (key == "radius_exponent") {
            params.radiusExponent = numberIn(value, path, 0.01, 100.0);
        } else if (key == "trunk_multiplier") {
            params.trunkMultiplier = numberIn(value, path, 0.01, 100.0);
        } else if (key == "min_segments") {
            params.minSegments = integerIn(value, path, 3, 64);
        } else if (key == "max_segments") {
            params.maxSegments = integerIn(value, path, 3, 64);
        } else if (key == "curve_reduction") {
            params.curveReduction = numberIn(value, path, 0.0, 0.999999);
        } else if (key == "cap_tips") {
            params.capTips = boolean(value, path);
        } else if (key == "weld") {
            mesh.weldJunctions = boolean(value, path);
        } else if (key == "union") {
            mesh.solidUnion = boolean(value, path);
        } else if (key == "convex_junctions") {
            mesh.convexJunctions = boolean(value, path);
        } else {
            throw ApiError(400, path +
                                    ": unknown key; expected leaf_radius, radius_exponent, "
                                    "trunk_multiplier, min_segments, max_segments, "
                                    "curve_reduction, cap_tips, weld, union or "
                                    "convex_junctions");
        }
    }
    if (params.maxSegments < params.minSegments) {
        throw ApiError(400, "mesh.max_segments: expected at least mesh.min_segments (" +
                                std::to_string(params.minSegments) + "), got " +
                                std::to_string(params.maxSegments));
    }
    mesh.weldJunctions = mesh.weldJunctions || mesh.solidUnion;
    if (mesh.convexJunctions && !mesh.weldJunctions) {
        throw ApiError(400,
                       "mesh.convex_junctions: only with mesh.weld or mesh.union (the tube "
                       "bark has no junctions to keep convex)");
    }
    return mesh;
}

/// The tree's GLB as base64, after checking the triangle budget.
std::string treeGlb(Mesh mesh, const StudioLimits& limits) {
    checkTriangles(mesh.triangleCount(), limits);
    return base64(encodeGlb(makeSingleMeshScene(std::move(mesh), "tree")));
}

/// Attraction points for display: every k-th point so at most `limit` remain.
nlohmann::json shownPoints(const std::vector<Vec3>& points, std::size_t limit) {
    nlohmann::json flat = nlohmann::json::array();
    if (points.empty() || limit == 0) return flat;
    const std::size_t stride = (points.size() + limit - 1) / limit;
    for (std::size_t i = 0; i < points.size(); i += stride) {
        for (int k = 0; k < 3; ++k) flat.push_back(static_cast<float>(points[i][k]));
    }
    return flat;
}

/// Refuses what would make the server read its own disk: "file" shapes and point files.
void refuseFileReferences(const nlohmann::json& config) {
    if (config.contains("points")) {
        throw ApiError(400,
                       "config.points: point files are not available in the studio; "
                       "expected envelopes only");
    }
    for (const char* list : {"envelopes", "obstacles"}) {
        const auto it = config.find(list);
        if (it == config.end() || !it->is_array()) continue;
        for (std::size_t i = 0; i < it->size(); ++i) {
            if ((*it)[i].is_object() && (*it)[i].contains("file")) {
                throw ApiError(400, std::string("config.") + list + "[" + std::to_string(i) +
                                        "].file: mesh shapes are not available in the studio; "
                                        "expected sphere, ellipsoid, box, cylinder, cone, "
                                        "hemisphere or disc");
            }
        }
    }
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The files of `dir` with extension `ext`, sorted by name.
std::vector<fs::path> filesIn(const fs::path& dir, const std::string& ext) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (entry.is_regular_file() && entry.path().extension() == ext) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

nlohmann::json ApiError::body() const {
    nlohmann::json error = {{"message", what()}, {"status", status_}};
    if (where_.is_object()) error.update(where_);
    return {{"error", error}};
}

nlohmann::json lsystemRequest(const nlohmann::json& request, const StudioLimits& limits) {
    const Deadline deadline(limits.timeSeconds);
    requireObject(request, "request");
    const std::string text = requiredString(request, "text");
    ParseOptions parseOptions;
    if (const auto* set = optionalMember(request, "set", nlohmann::json::value_t::object)) {
        for (const auto& [name, value] : set->items()) {
            parseOptions.constantOverrides.emplace_back(
                name, numberIn(value, "set." + name, -1e300, 1e300));
        }
    }
    DeriveOptions derive;
    derive.maxModules = limits.maxModules;
    derive.maxMemoryBytes = limits.maxMemoryBytes;
    if (request.contains("derivations")) {
        derive.derivations =
            integerIn(request["derivations"], "derivations", 0, limits.maxDerivations);
    }
    if (request.contains("seed")) {
        derive.overrideSeed = true;
        derive.seed = seedFrom(request["seed"], "seed");
    }
    const TreeMeshParams meshParams = meshParamsFrom(request);
    StageTimer clock;
    const LSystem system =
        withTextErrors([&] { return parseLSystem(text, "input.lsys", parseOptions); });
    if (derive.derivations < 0 && system.settings.derivations > limits.maxDerivations) {
        throw ApiError(
            413, "derivations: the text asks for " + std::to_string(system.settings.derivations) +
                     " steps; the studio allows at most " + std::to_string(limits.maxDerivations));
    }
    const ModuleString word = withTextErrors([&] { return deriveLSystem(system, derive); });
    clock.lap("derive");
    deadline.check("derivation");
    const TurtleResult shape =
        interpretTurtle(word, system.symbols, turtleParamsFrom(system.settings));
    clock.lap("interpret");
    deadline.check("turtle interpretation");
    cli::AssetSettings assets;  // as `ramus lsystem` with the request's mesher settings
    assets.mesh = meshParams;
    assets = withTextErrors([&] { return cli::finishAssets(std::move(assets)); });
    cli::TreeModel model = cli::plantModel(shape, assets.mesh, {});
    clock.lap("mesh");
    deadline.check("meshing");
    nlohmann::ordered_json stats = {{"modules", word.size()},
                                    {"nodes", shape.tree.size()},
                                    {"edges", shape.tree.edgeCount()},
                                    {"polygons", shape.polygonCount()},
                                    {"vertices", model.mesh.vertexCount()},
                                    {"triangles", model.mesh.triangleCount()}};
    cli::addBarkStats(stats, model.report);
    nlohmann::json warnings = nlohmann::json::array();
    if (const std::string bark = cli::barkWarning(model.report); !bark.empty()) {
        warnings.push_back(bark);
    }
    std::string glb = treeGlb(std::move(model.mesh), limits);
    clock.lap("encode");
    cli::addStageSeconds(stats, clock);
    return {{"glb", std::move(glb)}, {"stats", stats}, {"warnings", warnings}};
}

nlohmann::json colonizeRequest(const nlohmann::json& request, const StudioLimits& limits) {
    const Deadline deadline(limits.timeSeconds);
    requireObject(request, "request");
    const nlohmann::json* configJson =
        optionalMember(request, "config", nlohmann::json::value_t::object);
    if (!configJson) throw ApiError(400, "config: expected an object (a colonize config)");
    refuseFileReferences(*configJson);
    ColonizeConfig config =
        withTextErrors([&] { return parseColonizeConfig(configJson->dump(), "config.json"); });
    if (request.contains("seed")) config.seed = seedFrom(request["seed"], "seed");
    std::size_t requested = 0;
    for (const Envelope& e : config.envelopes) requested += e.pointCount;
    if (requested > limits.maxPoints) {
        throw ApiError(413, "config.envelopes: " + std::to_string(requested) +
                                " attraction points requested; the studio allows at most " +
                                std::to_string(limits.maxPoints));
    }
    if (config.params.maxIterations > limits.maxIterations) {
        throw ApiError(413,
                       "config.max_iterations: " + std::to_string(config.params.maxIterations) +
                           "; the studio allows at most " + std::to_string(limits.maxIterations));
    }
    config.params.maxNodes = limits.maxNodes;
    StageTimer clock;
    const std::vector<Vec3> points = configAttractionPoints(config);
    clock.lap("sample");
    ColonizeResult result;
    try {
        result = growFromConfig(config, points);
    } catch (const Error& e) {  // the node limit (the config itself was checked above)
        throw ApiError(413, std::string(e.what()) + " (the studio allows at most " +
                                std::to_string(limits.maxNodes) + " nodes)");
    }
    clock.lap("grow");
    deadline.check("growth");
    // The config's whole asset (leaves, textures, weld) as `ramus colonize` makes it; the view
    // shows the full detail, so LODs are left out.
    const cli::AssetSettings assets = withTextErrors([&] { return cli::colonizeAssets(config); });
    cli::TreeModel model = cli::forestModel(result.trees, assets.mesh, {});
    clock.lap("mesh");
    deadline.check("meshing");
    nlohmann::ordered_json stats = {{"trees", result.trees.size()},
                                    {"attractors", result.attractors},
                                    {"attractors_left", result.attractorsLeft},
                                    {"iterations", result.iterations},
                                    {"nodes", result.nodeCount()},
                                    {"vertices", model.mesh.vertexCount()},
                                    {"triangles", model.mesh.triangleCount()}};
    cli::addBarkStats(stats, model.report);
    std::vector<std::string> warnings = result.warnings;
    if (std::string bark = cli::barkWarning(model.report); !bark.empty()) {
        warnings.push_back(std::move(bark));
    }
    std::string glb = treeGlb(std::move(model.mesh), limits);
    clock.lap("encode");
    cli::addStageSeconds(stats, clock);
    return {{"glb", std::move(glb)},
            {"stats", stats},
            {"warnings", warnings},
            {"points", shownPoints(points, limits.maxShownPoints)}};
}

nlohmann::json examplesResponse(const std::string& root) {
    nlohmann::json lsystems = nlohmann::json::array();
    for (const fs::path& file : filesIn(fs::path(root) / "examples" / "lsystems", ".lsys")) {
        lsystems.push_back({{"name", file.stem().string()}, {"text", readText(file)}});
    }
    nlohmann::json colonize = nlohmann::json::array();
    for (const fs::path& file : filesIn(fs::path(root) / "examples" / "colonize", ".json")) {
        nlohmann::json config = nlohmann::json::parse(readText(file), nullptr, false);
        if (config.is_discarded() || !config.is_object()) continue;
        try {
            refuseFileReferences(config);  // mesh-based examples need files the studio refuses
        } catch (const ApiError&) {
            continue;
        }
        colonize.push_back({{"name", file.stem().string()}, {"config", config}});
    }
    nlohmann::json species = nlohmann::json::array();
    for (const SpeciesRecord& s : builtinSpecies()) {
        species.push_back(
            {{"name", s.name}, {"name_de", s.nameDe}, {"class", animalClassName(s.animalClass)}});
    }
    return {{"lsystems", lsystems},
            {"colonize", colonize},
            {"species", species},
            {"head_kinds", headKindNames()},
            {"resolutions", nlohmann::json::array({"box", "low", "high"})}};
}

std::string base64(std::string_view bytes) {
    static constexpr char kAlphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const auto a = static_cast<unsigned char>(bytes[i]);
        const auto b = static_cast<unsigned char>(bytes[i + 1]);
        const auto c = static_cast<unsigned char>(bytes[i + 2]);
        out += kAlphabet[a >> 2];
        out += kAlphabet[((a & 3) << 4) | (b >> 4)];
        out += kAlphabet[((b & 15) << 2) | (c >> 6)];
        out += kAlphabet[c & 63];
    }
    if (i < bytes.size()) {
        const auto a = static_cast<unsigned char>(bytes[i]);
        const bool two = i + 1 < bytes.size();
        const auto b = two ? static_cast<unsigned char>(bytes[i + 1]) : 0u;
        out += kAlphabet[a >> 2];
        out += kAlphabet[((a & 3) << 4) | (b >> 4)];
        out += two ? kAlphabet[(b & 15) << 2] : '=';
        out += '=';
    }
    return out;
}

}  // namespace ramus::studio
