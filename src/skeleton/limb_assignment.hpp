// Which limb kind goes to which attachment point (seed 000 §5.5, §5.5.3, §6.1, §6.3).
#pragma once

#include <array>

#include "ramus/rng.hpp"
#include "ramus/skeleton.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {

/// Neck arc length (px) from which a shoulder girdle fits on the neck. The thesis only says
/// "long enough" (§5.5.3); 200 px is where the long-necked species of the data begin (birds,
/// horse, giraffe, camel: 230–500 px), while short necks stay below 150 px.
inline constexpr double kNeckGirdleMinLength = 200.0;
/// Total limb length (px) below which a free girdle gets a fin (§5.5, its footnote: 200 px).
inline constexpr double kFinMaxLimbLength = 200.0;

using LimbLayout = std::array<LimbKind, kAttachmentCount>;

/// The attachments the inputs allow on this spine: hip and shoulder always; hip2 and
/// shoulder2 with two pairs per girdle (G′); the neck girdle when the neck is long enough (or
/// when forced and there is a neck), not when forbidden; neck2 also needs two pairs per girdle.
std::array<bool, kAttachmentCount> allowedAttachments(const SkeletonInputs& inputs,
                                                      const Spine& spine);

/// The limb layout of a new skeleton: the user's counts first (legs, wings, arms, fins), then
/// the thesis's random rules for every kind without a count (§5.5): legs from v_b, a wing and
/// then an arm at a free shoulder with probability v_f, fins at free girdles whose limb is
/// shorter than kFinMaxLimbLength. A forced neck girdle gets the first wing/arm pairs (or an
/// arm pair if no count fixes arms). Throws Error when the counts need more attachments than
/// the inputs allow.
LimbLayout assignLimbs(const SkeletonFeatures& features, const Spine& spine,
                       const SkeletonInputs& inputs, Rng& rng);

/// A variation of a layout (§6.3): one allowed attachment is picked; empty → a fitting limb
/// with p = 0.5; occupied → removed with p = 0.5 and then moved to another free fitting
/// attachment with p = 0.2. A change that breaks a user count or a forced neck girdle is not
/// made.
LimbLayout varyLimbs(const LimbLayout& source, const SkeletonFeatures& features, const Spine& spine,
                     const SkeletonInputs& inputs, Rng& rng);

/// Moves a limb at a secondary attachment (hip2, shoulder2, neck2) whose primary one is empty
/// to the primary one, as the grammar needs (e_b = 0 ⇒ e_b2 = 0, …).
void normalizeLimbLayout(LimbLayout& layout);

}  // namespace ramus::detail
