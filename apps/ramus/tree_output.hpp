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

/// The mesh of an interpreted L-system: tapered tubes plus its `{ . }` polygons.
Mesh plantMesh(const TurtleResult& shape, const TubeMeshParams& params);

/// The tubes of several trees (colonization roots) in one mesh.
Mesh forestMesh(const std::vector<BranchTree>& trees, const TubeMeshParams& params);

/// Registers -o, --tree-json, --png, --view, --size.
void addTreeOutputOptions(CLI::App& command, TreeOutputs& outputs);

/// Registers the mesher's flags (--leaf-radius, --radius-exponent, …) on `command`.
void addTubeMeshOptions(CLI::App& command, TubeMeshParams& params);

/// Writes every requested output for `tree` and its already built `mesh`.
void writeTreeOutputs(const TreeOutputs& outputs, const BranchTree& tree, const Mesh& mesh,
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

/// Prints --stats as one JSON line: `counts` (in their order), the mesh's "vertices" and
/// "triangles", then "<stage>_seconds" for every stage of `timer`.
void printTreeStats(nlohmann::ordered_json counts, const Mesh& mesh, const StageTimer& timer);

}  // namespace ramus::cli
