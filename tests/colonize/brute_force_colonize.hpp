// The brute-force reference of space colonization: the definition in ramus/colonize.hpp taken
// literally, O(points × nodes) per iteration, no spatial index, no time coherence. The fast
// implementation must produce the same nodes in the same order.
#pragma once

#include <span>

#include "ramus/colonize.hpp"

namespace ramus::testing {

/// Same contract as ramus::colonize (warnings are not produced).
ColonizeResult bruteForceColonize(const ColonizeParams& params, std::span<const Vec3> points,
                                  std::span<const Shape> obstacles = {});

}  // namespace ramus::testing
