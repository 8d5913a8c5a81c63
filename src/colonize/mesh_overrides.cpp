// The config's "mesh" object applied to the tube mesher's settings (include/ramus/colonize.hpp).
#include "ramus/colonize.hpp"

namespace ramus {

void applyMeshOverrides(const ColonizeConfig& config, TubeMeshParams& params) {
    const ColonizeConfig::MeshOverrides& m = config.mesh;
    if (m.hasLeafRadius) params.leafRadius = m.leafRadius;
    if (m.hasRadiusExponent) params.radiusExponent = m.radiusExponent;
    if (m.hasTrunkMultiplier) params.trunkMultiplier = m.trunkMultiplier;
    if (m.hasMinSegments) params.minSegments = m.minSegments;
    if (m.hasMaxSegments) params.maxSegments = m.maxSegments;
    if (m.hasCapTips) params.capTips = m.capTips;
}

}  // namespace ramus
