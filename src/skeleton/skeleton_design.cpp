// designSkeleton and varySkeletonDesign: from the user's inputs to every random choice of one
// skeleton (seed 000 §5.1 steps 0–2, §5.3, §5.5, §5.5.3, §6.1, §6.3).
//
// Based on: seed 000 §5.3 (vertebra and rib counts), §5.5 (limb kinds and counts from v_b and
// v_f, priority legs > wings > arms > fins, the 200 px fin rule), §5.5.3 (G′, G″ attachment
// points), §6.1 (inputs → PCA conditions), §6.3 (variations); SPEC §F, §G.
#include <algorithm>
#include <cmath>
#include <string>

#include "ramus/error.hpp"
#include "ramus/skeleton_io.hpp"
#include "skeleton/limb_assignment.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus {
namespace {

/// Legs above 4 pairs… the thesis allows up to 8 legs (4 pairs) as a condition; above 2 pairs it
/// "sometimes" conditions on a smaller value (§6.1), because a four-legged spine carries extra
/// legs well. We use a four-legged spine (2 pairs) with this probability.
constexpr double kReduceManyLegsProbability = 0.5;
/// Neck y length (px) a forced second shoulder conditions on when the user gave none (§5.5.3:
/// the forced girdle becomes a neck-length condition). Long-necked species of the data have
/// 220–400 px.
constexpr double kForcedNeckYLength = 250.0;

void checkCount(const std::optional<int>& count, const char* input, int maximum) {
    if (!count) return;
    const int n = *count;
    if (n < 0 || n % 2 != 0 || n > maximum) {
        throw Error("input '" + std::string(input) + "': expected an even number from 0 to " +
                    std::to_string(maximum) + ", got " + std::to_string(n));
    }
}

void checkLength(const std::optional<double>& value, const char* input, bool positive) {
    if (!value) return;
    if (!std::isfinite(*value) || (positive && *value <= 0.0)) {
        throw Error("input '" + std::string(input) + "': expected a finite" +
                    (positive ? " positive" : "") + " number, got " + std::to_string(*value));
    }
}

void validateInputs(const SkeletonInputs& inputs) {
    checkCount(inputs.legs, "legs", 8);
    checkCount(inputs.wings, "wings", 2 * kAttachmentCount);
    checkCount(inputs.arms, "arms", 2 * kAttachmentCount);
    checkCount(inputs.fins, "fins", 2 * kAttachmentCount);
    checkLength(inputs.neckYLength, "neck y length", false);
    checkLength(inputs.tailXLength, "tail x length", false);
    checkLength(inputs.heightMetres, "height", true);
    checkLength(inputs.lengthMetres, "length", true);
    if (inputs.heightMetres && inputs.lengthMetres) {
        throw Error("inputs 'height' and 'length': expected at most one of them, got both");
    }
}

/// The PCA conditions the inputs imply (§6.1).
std::vector<Condition> conditionsFor(const SkeletonInputs& inputs, Rng& rng) {
    std::vector<Condition> conditions;
    if (inputs.legs) {
        double pairs = *inputs.legs / 2.0;
        if (pairs > 2.0 && rng.uniform01() < kReduceManyLegsProbability) pairs = 2.0;
        conditions.push_back(Condition::legs(pairs));
    }
    if (inputs.wings) conditions.push_back(Condition::wings(std::min(1.0, *inputs.wings / 2.0)));
    if (inputs.neckYLength) {
        conditions.push_back(Condition::neckYLength(*inputs.neckYLength));
    } else if (inputs.neckShoulder == NeckShoulder::Forced) {
        conditions.push_back(Condition::neckYLength(kForcedNeckYLength));
    }
    if (inputs.tailXLength) conditions.push_back(Condition::tailXLength(*inputs.tailXLength));
    return conditions;
}

Eigen::VectorXd choosePoint(const SkeletonStats& stats, const SkeletonInputs& inputs, Rng& rng) {
    if (inputs.example) return stats.fromExample(*inputs.example);
    const std::vector<Condition> conditions = conditionsFor(inputs, rng);
    // Without conditions the model is the plain PCA; skip re-running the eigen-decomposition.
    if (conditions.empty()) return stats.sample(rng, inputs.spread);
    return stats.sampleConditioned(conditions, rng, inputs.spread);
}

int uniformCount(Rng& rng, int lo, int hi) {
    return lo + static_cast<int>(rng.uniformInt(static_cast<std::uint32_t>(hi - lo + 1)));
}

/// Vertebra and rib counts (§5.3): neck 7, or 10–30 for winged animals; back 13 + 12; tail
/// 5–20; ribs uniform in [0, back vertebrae].
void drawCounts(SkeletonDesign& design, const detail::Spine& spine, Rng& rng) {
    const bool winged = std::count(design.limbs.begin(), design.limbs.end(), LimbKind::Wing) > 0;
    design.frontBackVertebrae = 13;
    design.rearBackVertebrae = 12;
    const int neck = winged ? uniformCount(rng, 10, 30) : 7;
    design.neckVertebrae = spine.hasNeck ? neck : 0;
    const int tail = uniformCount(rng, 5, 20);
    design.tailVertebrae = spine.hasTail ? tail : 0;
    design.ribs = uniformCount(rng, 0, design.frontBackVertebrae + design.rearBackVertebrae);
}

WingAngles drawWingAngles(Rng& rng) {
    WingAngles angles;
    angles.shoulderFront = rng.uniform(130.0, 170.0);
    angles.shoulderSide = rng.uniform(0.0, 45.0);
    angles.elbow = rng.uniform(-45.0, 0.0);
    angles.wrist = rng.uniform(0.0, 90.0);
    return angles;
}

void drawWingAnglesForAll(SkeletonDesign& design, Rng& rng) {
    for (int a = 0; a < kAttachmentCount; ++a) {
        design.wingAngles[a] = drawWingAngles(rng);
    }
}

std::uint64_t drawSeed(Rng& rng) {
    const std::uint64_t high = rng.nextU32();
    return (high << 32) | rng.nextU32();
}

/// Size from the weight, or from the user's height/length measured on the built skeleton.
void chooseSize(SkeletonDesign& design, const SkeletonInputs& inputs) {
    design.metresPerPixel = skeletonScaleFromWeight(design.features().weightKg);
    if (inputs.heightMetres || inputs.lengthMetres) {
        design.metresPerPixel =
            skeletonScaleForExtent(buildSkeleton(design), inputs.heightMetres, inputs.lengthMetres);
    }
}

}  // namespace

SkeletonDesign designSkeleton(const SkeletonStats& stats, const SkeletonInputs& inputs, Rng& rng) {
    validateInputs(inputs);
    SkeletonDesign design;
    design.featurePoint = choosePoint(stats, inputs, rng);
    design.spacing = inputs.spacing;
    design.headKind = inputs.headKind;
    const SkeletonFeatures features = design.features();
    const detail::Spine spine = detail::makeSpine(features);
    design.limbs = detail::assignLimbs(features, spine, inputs, rng);
    drawCounts(design, spine, rng);
    drawWingAnglesForAll(design, rng);
    design.heelDraw = rng.uniform01();
    design.grammarSeed = drawSeed(rng);
    chooseSize(design, inputs);
    return design;
}

SkeletonDesign varySkeletonDesign(const SkeletonStats& stats, const SkeletonDesign& source,
                                  const SkeletonInputs& inputs, Rng& rng) {
    validateInputs(inputs);
    SkeletonDesign design = source;
    design.featurePoint = stats.vary(source.featurePoint, rng);
    const SkeletonFeatures features = design.features();
    const detail::Spine spine = detail::makeSpine(features);
    design.limbs = detail::varyLimbs(source.limbs, features, spine, inputs, rng);
    drawCounts(design, spine, rng);
    for (int a = 0; a < kAttachmentCount; ++a) {
        const bool newWing = design.limbs[a] == LimbKind::Wing && source.limbs[a] != LimbKind::Wing;
        if (newWing) design.wingAngles[a] = drawWingAngles(rng);
    }
    design.heelDraw = rng.uniform01();
    design.grammarSeed = drawSeed(rng);
    chooseSize(design, inputs);
    return design;
}

}  // namespace ramus
