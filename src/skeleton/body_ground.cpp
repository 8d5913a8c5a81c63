// Keeping the body above the ground the legs stand on.
//
// Based on: seed 000 §5.5.1 (the ground height from 0.8 of the leg lengths) and §7.5 (its
// problems with short legs). The thesis raises the ground when the annotated legs are too short
// to reach y = 0, which can put ribs, a sagging belly or a drooping tail below it; issue 5
// requires that no bone is below the ground. Ribs are a free choice, so they are shortened;
// when the body itself reaches lower, the ground goes down to the body and legs too short for
// that are lengthened (the thesis notes the annotated leg lengths are too short, §5.5.1).
#include <algorithm>
#include <cmath>
#include <limits>

#include "skeleton/limbs.hpp"

namespace ramus::detail {

void fitRibsAboveGround(Skeleton& skeleton, std::span<const Mat4> world, double groundHeight) {
    constexpr double kMinRibLength = 1.0;
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        Bone& rib = skeleton.bones[i];
        if (rib.kind != BoneKind::Rib || rib.side != Side::Left) continue;
        const Mat4& w = world[i];
        // Lowest corner = base + min(0, slope · length): base from the corners at x = 0.
        const double slope = w(1, 0);
        const double base = w(1, 3) - 0.5 * (std::abs(w(1, 1)) * rib.extents.y() +
                                             std::abs(w(1, 2)) * rib.extents.z());
        if (slope >= 0.0 || base + slope * rib.extents.x() >= groundHeight) continue;
        rib.extents.x() = std::max(kMinRibLength, (base - groundHeight) / -slope);
    }
}

double lowestBodyPoint(const Skeleton& skeleton, std::span<const Mat4> world,
                       std::span<const LimbChain> chains) {
    std::vector<bool> legBone(skeleton.bones.size(), false);
    for (const LimbChain& chain : chains) {
        if (chain.kind != LimbKind::Leg) continue;
        for (int b : chain.bones) legBone[static_cast<std::size_t>(b)] = true;
    }
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        if (legBone[i]) continue;
        lowest = std::min(lowest, lowestBoxPoint(world[i], skeleton.bones[i].extents));
    }
    return lowest;
}

void lengthenLeg(Skeleton& skeleton, const LimbChain& chain, double factor) {
    for (int k = 0; k < 3; ++k) {
        Bone& bone = skeleton.bones[static_cast<std::size_t>(chain.bones[k])];
        bone.extents.x() *= factor;
        if (k > 0) bone.joint.position.x() *= factor;  // at the parent's (lengthened) end
    }
}

}  // namespace ramus::detail
