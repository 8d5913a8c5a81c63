// 3D turtle interpretation of a derived word (seed 002 §2.3.3, §2.4; ABOP §1.5, §2.2–2.4):
// builds a BranchTree (one node per F) plus polygons from `{ . }`.
#pragma once

#include <cstdint>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/lsystem.hpp"

namespace ramus {

/// Turtle settings; angles in degrees, lengths in model units.
struct TurtleParams {
    double defaultStep = 1.0;
    double defaultAngleDegrees = 90.0;
    double initialWidth = 0.0;  ///< width before any `!`; 0 = unset (mesher computes radii)
    Vec3 tropism = Vec3::Zero();
    double susceptibility = 0.0;  ///< e; 0 = no tropism
    TropismMode tropismMode = TropismMode::Rotate;
};

/// Turtle settings taken from a system's header.
TurtleParams turtleParamsFrom(const LSystemSettings& settings);

/// Result of interpretation. Polygon i has vertices
/// polygonVertices[polygonOffsets[i] .. polygonOffsets[i+1]) and grows from tree node
/// polygonNodes[i] (the turtle's node when its `}` closed it; its wind follows that node).
struct TurtleResult {
    BranchTree tree;  ///< root at the origin; initial heading +Y (up), left −X, up-vector +Z
    std::vector<Vec3> polygonVertices;
    std::vector<std::uint32_t> polygonOffsets{0};
    std::vector<NodeId> polygonNodes;

    std::size_t polygonCount() const { return polygonOffsets.size() - 1; }
};

/// Interprets `word` (SPEC §B): F(l) draws and creates a node, f(l) moves (its node's edge is
/// hidden), + - & ^ \ / | $ turn, [ ] push/pop (position, orientation, node, width), !(w) sets
/// width, { . } record polygons; other symbols are ignored. An unbalanced `]` is ignored.
TurtleResult interpretTurtle(const ModuleString& word, const SymbolTable& symbols,
                             const TurtleParams& params);

}  // namespace ramus
