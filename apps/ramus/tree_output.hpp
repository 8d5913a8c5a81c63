// Options and file writing shared by the commands that grow trees (lsystem, colonize):
// meshing flags, and the outputs -o / --tree-json / --png.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "ramus/branch_tree.hpp"
#include "ramus/mesh.hpp"
#include "ramus/tube_mesher.hpp"

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

/// Registers -o, --tree-json, --png, --view, --size.
void addTreeOutputOptions(CLI::App& command, TreeOutputs& outputs);

/// Registers the mesher's flags (--leaf-radius, --radius-exponent, …) on `command`.
void addTubeMeshOptions(CLI::App& command, TubeMeshParams& params);

/// Writes every requested output for `tree` and its already built `mesh`.
void writeTreeOutputs(const TreeOutputs& outputs, const BranchTree& tree, const Mesh& mesh,
                      const TubeMeshParams& meshParams);

}  // namespace ramus::cli
