// buildSkeleton: the generation steps 3–4 of seed 000 §5.1 (grammar with positions, limbs,
// mirror) run on a design. Each stage lives in its own file (skeleton_build.hpp).
#include "skeleton/skeleton_build.hpp"

namespace ramus {

Skeleton buildSkeleton(const SkeletonDesign& design) {
    const detail::Spine spine = detail::makeSpine(design.features());
    Skeleton skeleton = detail::placeBones(design, spine);
    detail::poseLimbs(skeleton, design);
    detail::mirrorSkeleton(skeleton);
    return skeleton;
}

}  // namespace ramus
