// The BranchTree as JSON, for tools outside ramus (`--tree-json`):
// {"nodes":[{"id":0,"parent":-1,"position":[x,y,z],"radius":r,"branch_depth":z},…]}
#pragma once

#include <span>
#include <string>

#include "ramus/branch_tree.hpp"

namespace ramus {

/// Encodes `tree` with one radius per node (`radii` indexed by node id, e.g. from
/// computeEdgeRadii). Nodes in id order, so parents precede children. Numbers use up to 17
/// significant digits, so values round-trip exactly. Hidden edges get "hidden": true.
std::string encodeTreeJson(const BranchTree& tree, std::span<const double> radii);

}  // namespace ramus
