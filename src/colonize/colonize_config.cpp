// Based on: DESIGN.md "Colonization configs" (parameter names of SPEC §C); seed 002 §4.3.1
// (parameters of the colonization actor), §4.3.2 (envelopes with offset, point count, seed),
// §4.4.2 (mesher parameters). Parsed with nlohmann::json; it has no line numbers, so errors
// name the key path instead: "tree.json: envelopes[2].radius: …".
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "colonize/config_reader.hpp"
#include "core/json_text.hpp"
#include "ramus/colonize.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/mesh_volume.hpp"

namespace ramus {

namespace {

using colonize_detail::ConfigReader;
using Json = nlohmann::json;

ShapeKind parseShapeKind(const ConfigReader& r, const Json& value, const std::string& path) {
    static const std::pair<const char*, ShapeKind> kinds[] = {
        {"sphere", ShapeKind::Sphere}, {"ellipsoid", ShapeKind::Ellipsoid},
        {"box", ShapeKind::Box},       {"cylinder", ShapeKind::Cylinder},
        {"cone", ShapeKind::Cone},     {"hemisphere", ShapeKind::Hemisphere},
        {"disc", ShapeKind::Disc},     {"mesh", ShapeKind::Mesh}};
    if (value.is_string()) {
        for (const auto& [name, kind] : kinds) {
            if (value.get<std::string>() == name) return kind;
        }
    }
    r.fail(path, "unknown shape " + value.dump() +
                     "; expected sphere, ellipsoid, box, cylinder, cone, hemisphere, disc or mesh");
}

// The size keys each shape takes (besides shape, center/offset, and points/seed for envelopes).
std::set<std::string> shapeSizeKeys(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::Sphere:
        case ShapeKind::Hemisphere:
            return {"radius"};
        case ShapeKind::Ellipsoid:
            return {"radii"};
        case ShapeKind::Box:
            return {"size"};
        case ShapeKind::Cylinder:
        case ShapeKind::Cone:
            return {"radius", "height"};
        case ShapeKind::Disc:
            return {"radius", "inner_radius"};
        case ShapeKind::Mesh:
            return {"file", "scale"};
    }
    return {};
}

// Reads the closed meshes of "mesh" shapes, each file once, relative to the config's folder.
class MeshFiles {
public:
    MeshFiles(const std::string& configFile, std::size_t maxBytes)
        : folder_(std::filesystem::path(configFile).parent_path()), maxBytes_(maxBytes) {}

    std::shared_ptr<const MeshVolume> load(const ConfigReader& r, const Json& value,
                                           const std::string& path) {
        if (!value.is_string() || value.get<std::string>().empty()) {
            r.fail(path, "expected a mesh file name (.obj, .glb, .gltf), got " + value.dump());
        }
        std::filesystem::path file(value.get<std::string>());
        if (file.is_relative()) file = folder_ / file;
        const std::string key = file.lexically_normal().string();
        auto it = loaded_.find(key);
        if (it != loaded_.end()) return it->second;
        try {
            auto mesh = std::make_shared<const MeshVolume>(readMeshVolume(key, maxBytes_));
            return loaded_.emplace(key, std::move(mesh)).first->second;
        } catch (const Error& e) {
            r.fail(path, e.what());
        }
    }

private:
    std::filesystem::path folder_;
    std::size_t maxBytes_;
    std::map<std::string, std::shared_ptr<const MeshVolume>> loaded_;
};

// The keys of a "mesh" shape: file (required) and scale (default 1).
void parseMeshKeys(const ConfigReader& r, const Json& j, const std::string& path, Shape& s,
                   MeshFiles& meshes) {
    if (!j.contains("file")) r.fail(path, "missing key \"file\" for a mesh");
    if (j.contains("scale")) {
        s.scale = r.number(j["scale"], ConfigReader::join(path, "scale"), 0.0, ConfigReader::kMax,
                           true, "factor on the mesh file's coordinates");
    }
    s.mesh = meshes.load(r, j["file"], ConfigReader::join(path, "file"));
}

Shape parseShape(const ConfigReader& r, const Json& j, const std::string& path, bool envelope,
                 MeshFiles& meshes) {
    if (!j.is_object()) r.fail(path, "expected an object {\"shape\": …}, got " + j.dump());
    if (!j.contains("shape")) r.fail(path, "missing key \"shape\"");
    Shape s;
    s.kind = parseShapeKind(r, j["shape"], ConfigReader::join(path, "shape"));
    std::set<std::string> allowed = shapeSizeKeys(s.kind);
    for (const char* k : {"shape", "center", "offset", "description"}) allowed.insert(k);
    if (envelope) allowed.insert({"points", "seed"});
    r.checkKeys(j, path, allowed, std::string(" for a ") + shapeKindName(s.kind));
    if (j.contains("center") && j.contains("offset")) {
        r.fail(ConfigReader::join(path, "offset"), "give either center or offset, not both");
    }
    const char* anchor = j.contains("offset") ? "offset" : "center";
    if (j.contains(anchor)) {
        s.offset = r.vec3(j[anchor], ConfigReader::join(path, anchor), ConfigReader::kLowest, false,
                          "model units");
    }
    if (s.kind == ShapeKind::Mesh) {
        parseMeshKeys(r, j, path, s, meshes);
        return s;
    }
    for (const std::string& key : shapeSizeKeys(s.kind)) {
        const std::string keyPath = ConfigReader::join(path, key);
        if (key == "inner_radius") {
            if (j.contains(key)) {
                s.innerRadius =
                    r.number(j[key], keyPath, 0.0, ConfigReader::kMax, false, "model units");
            }
            continue;
        }
        if (!j.contains(key))
            r.fail(path, "missing key \"" + key + "\" for a " + shapeKindName(s.kind));
        if (key == "radius")
            s.radius = r.number(j[key], keyPath, 0.0, ConfigReader::kMax, true, "model units");
        if (key == "height")
            s.height = r.number(j[key], keyPath, 0.0, ConfigReader::kMax, true, "model units");
        if (key == "radii") s.radii = r.vec3(j[key], keyPath, 0.0, true, "model units");
        if (key == "size") s.size = r.vec3(j[key], keyPath, 0.0, true, "model units");
    }
    if (s.kind == ShapeKind::Disc && s.innerRadius >= s.radius) {
        r.fail(ConfigReader::join(path, "inner_radius"),
               "must be below radius " + Json(s.radius).dump() + " (model units), got " +
                   Json(s.innerRadius).dump());
    }
    if (!envelope && s.kind == ShapeKind::Disc && s.innerRadius > 0.0) {
        r.fail(ConfigReader::join(path, "inner_radius"), "obstacle discs cannot have a hole");
    }
    return s;
}

std::vector<Vec3> parseRoots(const ConfigReader& r, const Json& j) {
    if (j.contains("root") && j.contains("roots")) r.fail("roots", "give either root or roots");
    if (j.contains("root"))
        return {r.vec3(j["root"], "root", ConfigReader::kLowest, false, "model units")};
    if (!j.contains("roots")) return {Vec3::Zero()};
    const Json& list = j["roots"];
    if (!list.is_array() || list.empty()) {
        r.fail("roots", "expected a non-empty array of [x, y, z] positions, got " + list.dump());
    }
    std::vector<Vec3> roots;
    for (std::size_t i = 0; i < list.size(); ++i) {
        roots.push_back(r.vec3(list[i], "roots[" + std::to_string(i) + "]", ConfigReader::kLowest,
                               false, "model units"));
    }
    return roots;
}

void parseMesh(const ConfigReader& r, const Json& j, ColonizeConfig::MeshOverrides& m) {
    if (!j.is_object()) r.fail("mesh", "expected an object, got " + j.dump());
    r.checkKeys(
        j, "mesh",
        {"leaf_radius", "radius_exponent", "trunk_multiplier", "min_segments", "max_segments",
         "cap_tips", "uv_aspect", "wind", "textures", "weld", "union", "convex_junctions", "lods"},
        "");
    colonize_detail::parseMeshAssetKeys(r, j, m);
    const double kMax = ConfigReader::kMax;
    if ((m.hasLeafRadius = j.contains("leaf_radius"))) {
        m.leafRadius = r.number(j["leaf_radius"], "mesh.leaf_radius", 0.0, kMax, false,
                                "model units; 0 = automatic");
    }
    if ((m.hasRadiusExponent = j.contains("radius_exponent"))) {
        m.radiusExponent = r.number(j["radius_exponent"], "mesh.radius_exponent", 0.0, kMax, true,
                                    "Murray exponent g");
    }
    if ((m.hasTrunkMultiplier = j.contains("trunk_multiplier"))) {
        m.trunkMultiplier =
            r.number(j["trunk_multiplier"], "mesh.trunk_multiplier", 0.0, kMax, true, "factor");
    }
    if ((m.hasMinSegments = j.contains("min_segments"))) {
        m.minSegments = static_cast<int>(
            r.integer(j["min_segments"], "mesh.min_segments", 3, 256, "ring vertices"));
    }
    if ((m.hasMaxSegments = j.contains("max_segments"))) {
        m.maxSegments = static_cast<int>(
            r.integer(j["max_segments"], "mesh.max_segments", 3, 256, "ring vertices"));
    }
    if (m.hasMinSegments && m.hasMaxSegments && m.maxSegments < m.minSegments) {
        r.fail("mesh.max_segments", "must be >= mesh.min_segments " +
                                        std::to_string(m.minSegments) + ", got " +
                                        std::to_string(m.maxSegments));
    }
    if ((m.hasCapTips = j.contains("cap_tips")))
        m.capTips = r.boolean(j["cap_tips"], "mesh.cap_tips");
}

}  // namespace

namespace colonize_detail {

void parseGrowthKeys(const ConfigReader& r, const Json& j, ColonizeParams& p,
                     const std::string& prefix) {
    auto at = [&prefix](const char* key) { return ConfigReader::join(prefix, key); };
    const double kMax = ConfigReader::kMax;
    if (j.contains("influence_radius")) {
        p.influenceRadius = r.number(j["influence_radius"], at("influence_radius"), 0.0, kMax, true,
                                     "model units, d_i");
    }
    if (j.contains("kill_radius")) {
        p.killRadius =
            r.number(j["kill_radius"], at("kill_radius"), 0.0, kMax, true, "model units, d_k");
    }
    if (!(p.killRadius < p.influenceRadius)) {
        r.fail(at("kill_radius"), "must be below influence_radius " +
                                      Json(p.influenceRadius).dump() + " (model units), got " +
                                      Json(p.killRadius).dump());
    }
    if (j.contains("step"))
        p.step = r.number(j["step"], at("step"), 0.0, kMax, true, "model units, D");
    if (j.contains("tropism")) {
        p.tropism = r.vec3(j["tropism"], at("tropism"), ConfigReader::kLowest, false,
                           "unitless vector T added to the direction sum");
    }
    if (j.contains("max_iterations")) {
        p.maxIterations = static_cast<int>(
            r.integer(j["max_iterations"], at("max_iterations"), 0, 100'000'000, "iterations"));
    }
    if (j.contains("max_degree")) {
        p.maxDegree = static_cast<int>(r.integer(j["max_degree"], at("max_degree"), 0, 1'000'000,
                                                 "children per node; 0 = unlimited"));
    }
    if (j.contains("max_branch_depth")) {
        p.maxBranchDepth =
            static_cast<int>(r.integer(j["max_branch_depth"], at("max_branch_depth"), 0, 1'000'000,
                                       "branch depth Z; 0 = unlimited"));
    }
    if (j.contains("max_no_growth")) {
        p.maxNoGrowth = static_cast<int>(r.integer(j["max_no_growth"], at("max_no_growth"), 0,
                                                   100'000'000, "iterations; 0 = off"));
    }
    if (j.contains("weighted_growth")) {
        p.weightedGrowth = r.boolean(j["weighted_growth"], at("weighted_growth"));
        if (p.weightedGrowth && p.maxBranchDepth < 1) {
            r.fail(at("weighted_growth"),
                   "needs max_branch_depth >= 1 (the depth where the step "
                   "falls to D), got max_branch_depth " +
                       std::to_string(p.maxBranchDepth));
        }
    }
}

}  // namespace colonize_detail

namespace {

void parseGrowth(const ConfigReader& r, const Json& j, ColonizeParams& p) {
    colonize_detail::parseGrowthKeys(r, j, p, "");
    p.roots = parseRoots(r, j);
}

// "envelopes" (shapes with a point count and a seed) and "obstacles" (plain shapes).
void parseShapeLists(const ConfigReader& r, const Json& j, ColonizeConfig& c, MeshFiles& meshes) {
    for (const char* key : {"envelopes", "obstacles"}) {
        if (!j.contains(key)) continue;
        const Json& list = j[key];
        if (!list.is_array()) r.fail(key, "expected an array of shapes, got " + list.dump());
        const bool envelope = std::string(key) == "envelopes";
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string path = std::string(key) + "[" + std::to_string(i) + "]";
            const Shape shape = parseShape(r, list[i], path, envelope, meshes);
            if (!envelope) {
                c.obstacles.push_back(shape);
                continue;
            }
            Envelope e;
            e.shape = shape;
            e.seed = i;
            if (!list[i].contains("points")) r.fail(path, "missing key \"points\" (point count N)");
            e.pointCount = static_cast<std::uint32_t>(r.integer(
                list[i]["points"], path + ".points", 0, 50'000'000, "attraction points N"));
            if (list[i].contains("seed")) e.seed = r.seed(list[i]["seed"], path + ".seed");
            c.envelopes.push_back(e);
        }
    }
}

}  // namespace

ColonizeConfig parseColonizeConfig(const std::string& jsonText, const std::string& fileName,
                                   std::size_t maxFileBytes) {
    const Json j = detail::parseJsonText(jsonText, fileName);
    const ConfigReader r(fileName);
    if (!j.is_object()) throw Error(fileName + ": expected a JSON object at the top level");
    r.checkKeys(j, "",
                {"description",
                 "seed",
                 "influence_radius",
                 "kill_radius",
                 "step",
                 "tropism",
                 "max_iterations",
                 "max_degree",
                 "max_branch_depth",
                 "max_no_growth",
                 "weighted_growth",
                 "angle_reduction",
                 "curve_reduction",
                 "root",
                 "roots",
                 "envelopes",
                 "obstacles",
                 "points_file",
                 "mesh",
                 "leaves",
                 "ground",
                 "root_growth"},
                "");
    ColonizeConfig c;
    c.maxFileBytes = maxFileBytes;
    if (j.contains("description") && !j["description"].is_string()) {
        r.fail("description", "expected a string, got " + j["description"].dump());
    }
    if (j.contains("seed")) c.seed = r.seed(j["seed"], "seed");
    parseGrowth(r, j, c.params);
    if (j.contains("angle_reduction")) {
        c.reduceBranchAngles = r.boolean(j["angle_reduction"], "angle_reduction");
    }
    if (j.contains("curve_reduction")) {
        c.curveReduction = r.number(j["curve_reduction"], "curve_reduction", 0.0, 0.999999, false,
                                    "max_K, dot product of unit edge directions; 0 = off");
    }
    MeshFiles meshes(fileName, maxFileBytes);
    parseShapeLists(r, j, c, meshes);
    if (j.contains("points_file")) {
        if (!j["points_file"].is_string() || j["points_file"].get<std::string>().empty()) {
            r.fail("points_file", "expected a file name, got " + j["points_file"].dump());
        }
        c.pointsFile = j["points_file"].get<std::string>();
    }
    if (j.contains("mesh")) parseMesh(r, j["mesh"], c.mesh);
    if ((c.hasLeaves = j.contains("leaves")))
        colonize_detail::parseLeaves(r, j["leaves"], c.leaves);
    colonize_detail::parseRootSystem(r, j, c);
    return c;
}

ColonizeConfig loadColonizeConfig(const std::string& path, std::size_t maxFileBytes) {
    ColonizeConfig config = parseColonizeConfig(readFile(path, maxFileBytes), path, maxFileBytes);
    if (!config.pointsFile.empty()) {
        const std::filesystem::path file(config.pointsFile);
        if (file.is_relative()) {
            config.pointsFile = (std::filesystem::path(path).parent_path() / file).string();
        }
    }
    return config;
}

std::vector<Vec3> configAttractionPoints(const ColonizeConfig& config) {
    std::vector<Vec3> points = sampleAttractionPoints(config.envelopes, {}, config.seed);
    if (!config.pointsFile.empty()) {
        const std::vector<Vec3> extra = readPointsFile(config.pointsFile, config.maxFileBytes);
        points.insert(points.end(), extra.begin(), extra.end());
    }
    return removePointsInside(points, config.obstacles);
}

namespace {

ColonizeResult growAndReduce(const ColonizeConfig& config, const ColonizeParams& params,
                             std::span<const Vec3> points) {
    ColonizeResult result = colonize(params, points, config.obstacles);
    for (BranchTree& tree : result.trees) {
        if (config.reduceBranchAngles) tree = reduceBranchAngles(tree);
        if (config.curveReduction > 0.0) tree = reduceCurves(tree, config.curveReduction);
    }
    return result;
}

// Appends the non-root nodes of `roots` (same root position) below tree's root, in id order.
void graftRootSystem(BranchTree& tree, const BranchTree& roots) {
    std::vector<NodeId> id(roots.size(), 0);
    for (std::size_t i = 1; i < roots.size(); ++i) {
        const BranchNode& n = roots.nodes()[i];
        id[i] = tree.addChild(id[static_cast<std::size_t>(n.parent)], n.position);
    }
}

}  // namespace

ColonizeResult growFromConfig(const ColonizeConfig& config, std::span<const Vec3> points) {
    if (!config.hasGround) return growAndReduce(config, config.params, points);
    std::vector<Vec3> crown, below;
    for (const Vec3& p : points) (p.y() < config.ground ? below : crown).push_back(p);
    ColonizeResult result = growAndReduce(config, config.params, crown);
    if (below.empty()) return result;
    ColonizeParams rootParams = config.rootGrowth;
    rootParams.roots = config.params.roots;
    rootParams.maxNodes = config.params.maxNodes > result.nodeCount()
                              ? config.params.maxNodes - result.nodeCount()
                              : 1;
    const ColonizeResult roots = growAndReduce(config, rootParams, below);
    for (std::size_t t = 0; t < result.trees.size(); ++t) {
        graftRootSystem(result.trees[t], roots.trees[t]);
    }
    result.attractors += roots.attractors;
    result.attractorsLeft += roots.attractorsLeft;
    result.iterations = std::max(result.iterations, roots.iterations);
    for (const std::string& w : roots.warnings) result.warnings.push_back("root system: " + w);
    return result;
}

}  // namespace ramus
