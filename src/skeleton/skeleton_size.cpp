// Real size of a skeleton: metres per px of the annotation frame.
//
// Based on: seed 000 §7.4.1 (each skeleton image was scaled to fill the 1000×1000 px frame, so
// 1000 px are the larger side of the skeleton) and its future work ("use the weight in the
// algorithm"). The rule extent = a·W^b is fitted by least squares on log(extent) against
// log(W) over the 44 species: weights from data/species/species.json, typical extents from
// data/species/sizes.csv. The fit (recomputed by the test SkeletonSize.RuleConstantsMatchTheFit)
// gives a = 0.38222, b = 0.34603 (close to isometric 1/3), rms log residual 0.307 (a factor of
// 1.36); the constants in skeleton_io.hpp are these rounded to 4 significant digits.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ramus/error.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus {

double skeletonExtentFromWeight(double weightKg) {
    // NaN fails every comparison: the negated test sends it to the minimum as well.
    const double w = !(weightKg >= kSizeRuleMinWeightKg) ? kSizeRuleMinWeightKg
                                                         : std::min(weightKg, kMaxWeightKg);
    return kSizeRuleCoefficient * std::pow(w, kSizeRuleExponent);
}

double skeletonScaleFromWeight(double weightKg) {
    return skeletonExtentFromWeight(weightKg) / 1000.0;
}

namespace {

// The bounding box of all bone boxes (each bone spans x ∈ [0, len], y, z ∈ ±extent/2 in its
// own frame) in the internal frame.
Aabb skeletonBox(const Skeleton& skeleton) {
    Aabb box;
    const std::vector<Mat4> world = skeleton.worldTransforms();
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        const Vec3& e = skeleton.bones[i].extents;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 local((corner & 1) ? e.x() : 0.0, (corner & 2) ? 0.5 * e.y() : -0.5 * e.y(),
                             (corner & 4) ? 0.5 * e.z() : -0.5 * e.z());
            box.add((world[i] * local.homogeneous()).head<3>());
        }
    }
    return box;
}

double checkedExtent(double metres, const char* what) {
    if (!std::isfinite(metres) || metres <= 0.0) {
        throw Error(std::string("skeleton ") + what + ": expected a finite number of metres > 0");
    }
    return metres;
}

}  // namespace

double skeletonScaleForExtent(const Skeleton& skeleton, std::optional<double> heightMetres,
                              std::optional<double> lengthMetres) {
    if (heightMetres && lengthMetres) {
        throw Error("skeleton size: give a height or a length, not both");
    }
    if (!heightMetres && !lengthMetres) return skeleton.metresPerPixel;
    const bool byHeight = heightMetres.has_value();
    const double metres =
        byHeight ? checkedExtent(*heightMetres, "height") : checkedExtent(*lengthMetres, "length");
    const Aabb box = skeletonBox(skeleton);
    const int axis = byHeight ? 1 : 0;
    const double px = skeleton.bones.empty() ? 0.0 : box.max[axis] - box.min[axis];
    if (!(px > 0.0) || !std::isfinite(px)) {
        throw Error(std::string("skeleton ") + (byHeight ? "height" : "length") +
                    ": the skeleton has no extent along that axis to scale");
    }
    return metres / px;
}

}  // namespace ramus
