// Options and file writing shared by the commands that grow trees (lsystem, colonize):
// meshing flags, and the outputs -o / --tree-json / --png.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/colonize.hpp"
#include "ramus/mesh.hpp"
#include "ramus/scene.hpp"
#include "ramus/tree_asset.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/turtle.hpp"

namespace ramus::cli {

/// Where to write a grown tree; empty = not wanted.
struct TreeOutputs {
    std::string model;     ///< -o: .glb or .obj
    std::string treeJson;  ///< --tree-json
    std::string png;       ///< --png
    std::string view = "three-quarter";
    std::string size = "800x800";

    bool any() const { return !model.empty() || !treeJson.empty() || !png.empty(); }
};

/// Default of `ramus colonize --max-iterations`, also the limit of batch colonize jobs.
inline constexpr int kDefaultMaxIterations = 100'000;

/// Error naming `configName` and the limit when the config's max_iterations is above `limit`.
void checkIterationLimit(const ColonizeConfig& config, int limit, const std::string& configName);

/// A grown tree's meshes: the full mesh, or levels of detail.
struct TreeModel {
    Mesh mesh;                  ///< full detail (LOD 0 when there are LODs); previews draw it
    std::vector<TreeLod> lods;  ///< empty without --lods
    TreeMeshReport report;      ///< what the solid union did (--union)
    /// What -o writes: one node "tree" with the mesh, or a node "tree" with one child node
    /// "tree_LOD<i>" per level (extras: lod, ratio, triangles, target_triangles).
    Scene scene() const;
};

/// The model of an L-system or of a forest: buildTreeMesh, or buildTreeLods for `lods`.
TreeModel plantModel(const TurtleResult& shape, const TreeMeshParams& params,
                     const std::vector<double>& lods);
TreeModel forestModel(const std::vector<BranchTree>& trees, const TreeMeshParams& params,
                      const std::vector<double>& lods);

/// Flags of the asset features (issue 9): leaves, wind, textures, LODs.
struct AssetOptions {
    LeafParams leaf;
    std::string leafShape;
    std::string atlas;
    double uvAspect = 1.0;
    std::string lods;  ///< "1,0.4,0.15"
    bool leaves = false, wind = false, noTextures = false, weld = false, solidUnion = false;
    bool convexJunctions = false;
    CLI::App* command = nullptr;
};

/// Registers --leaves, --leaf-shape, --leaves-per-tip, --leaves-per-length, --leaf-zone,
/// --leaf-size, --leaf-width, --phyllotaxis, --leaf-tilt, --leaf-seed, --leaf-atlas, --wind,
/// --no-textures, --uv-aspect, --lods, --weld, --union.
void addAssetOptions(CLI::App& command, AssetOptions& options);

/// Asset settings before the flags: defaults, or what a colonization config says.
struct AssetSettings {
    TreeMeshParams mesh;
    bool textures = true;        ///< attach the default bark and leaf textures
    bool uvAspectGiven = false;  ///< else uvAspect follows the bark texture
    std::vector<double> lods;    ///< empty = no LODs
};

/// `base` with `tube` as its tube settings (keeping base's uvAspect and wind), then the asset
/// flags that were given, then the default textures unless disabled: bark colour and normal
/// map (baseColor white, uvAspect = their height / width unless given) and the leaf texture
/// with an alpha mask.
AssetSettings applyAssetOptions(const TubeMeshParams& tube, const AssetOptions& options,
                                AssetSettings base);

/// The asset settings a colonization config gives (its "mesh" asset keys and "leaves"),
/// before any flags: what `ramus colonize` starts from and what batches use as they are.
AssetSettings configAssets(const ColonizeConfig& config);

/// `s` finished without flags: the default textures unless s.textures is false, and the
/// combination checks of applyAssetOptions (batches and the studio use this).
AssetSettings finishAssets(AssetSettings s);

/// Everything a colonization config says about its asset, without flags: its "mesh" object
/// (tube settings and asset keys) and "leaves", finished — so a batch item or a studio request
/// gives the same asset as `ramus colonize CONFIG` without flags.
AssetSettings colonizeAssets(const ColonizeConfig& config);

/// Registers -o, --tree-json, --png, --view, --size.
void addTreeOutputOptions(CLI::App& command, TreeOutputs& outputs);

/// Registers the mesher's flags (--leaf-radius, --radius-exponent, …) on `command`.
void addTubeMeshOptions(CLI::App& command, TubeMeshParams& params);

/// Writes every requested output for `tree` and its already built `model`.
void writeTreeOutputs(const TreeOutputs& outputs, const BranchTree& tree, const TreeModel& model,
                      const TubeMeshParams& meshParams);

/// Wall-clock seconds of a command's stages, in order, for --stats.
class StageTimer {
public:
    /// Starts timing the next stage now (what ran since the last lap is not counted).
    void restart() { start_ = std::chrono::steady_clock::now(); }
    /// Ends the stage that started at the last restart or lap, recording it as `name`.
    void lap(std::string name);
    /// The recorded stages: name and seconds, in order.
    const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::vector<std::pair<std::string, double>> stages_;
};

/// Adds "<stage>_seconds" for every stage of `timer` to `stats`.
void addStageSeconds(nlohmann::ordered_json& stats, const StageTimer& timer);

/// Prints --stats as one JSON line: `counts` (in their order), the mesh's "vertices",
/// "triangles", "leaf_triangles", with LODs "lod_triangles", the bark's (addBarkStats), then
/// "<stage>_seconds" for every stage of `timer`.
void printTreeStats(nlohmann::ordered_json counts, const TreeModel& model, const StageTimer& timer);

/// Adds, when the bark was welded, "weld_fallbacks", "weld_crossings", "weld_shared_rings" and
/// "weld_shrunk_junctions", and with the union
/// "unions_applied", "unions_failed", "unions_of_convex_junctions", "union_crossings_left",
/// "union_pinched_edges", "union_touching_points", "union_crossing_moves",
/// "union_collapsed_edges", "union_attempts", "union_postponed_moves" and "union_reunions" to
/// `stats`.
void addBarkStats(nlohmann::ordered_json& stats, const TreeMeshReport& report);

/// What a user should know about the bark: the solid union left meshes as they were (and why),
/// or welding without the union left several pieces or self-crossings (and what to do); empty
/// when neither.
std::string barkWarning(const TreeMeshReport& report);

/// barkWarning as a warning on stderr.
void warnOfBarkCompromises(const TreeModel& model);

}  // namespace ramus::cli
