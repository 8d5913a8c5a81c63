// Limb kinds per attachment point.
//
// Based on: seed 000 §5.5 "Bestimmung von Art und Anzahl" (priority legs, wings, arms, fins;
// v_b and v_f clamped; the 200 px fin rule), §5.5.3 (G′ and G″ attachment points, wings and
// arms only at shoulders), §6.1 (user counts override), §6.3 (variations: one attachment
// changed, p = 0.5 add/change, p = 0.2 move).
#include "skeleton/limb_assignment.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "ramus/error.hpp"

namespace ramus::detail {
namespace {

using A = Attachment;
constexpr int at(Attachment a) { return static_cast<int>(a); }

constexpr std::array<Attachment, 4> kLegOrder = {A::Hip, A::Shoulder, A::Hip2, A::Shoulder2};
constexpr std::array<Attachment, 4> kFrontOrder = {A::Shoulder, A::Shoulder2, A::Neck, A::Neck2};
constexpr std::array<Attachment, 4> kForcedFrontOrder = {A::Neck, A::Neck2, A::Shoulder,
                                                         A::Shoulder2};
constexpr std::array<Attachment, 6> kFinOrder = {A::Hip,       A::Shoulder, A::Hip2,
                                                 A::Shoulder2, A::Neck,     A::Neck2};
constexpr std::array<LimbKind, 4> kLimbKinds = {LimbKind::Leg, LimbKind::Wing, LimbKind::Arm,
                                                LimbKind::Fin};

using Allowed = std::array<bool, kAttachmentCount>;

std::vector<Attachment> orderFor(LimbKind kind, const SkeletonInputs& inputs) {
    switch (kind) {
        case LimbKind::Leg:
            return {kLegOrder.begin(), kLegOrder.end()};
        case LimbKind::Wing:
        case LimbKind::Arm:
            if (inputs.neckShoulder == NeckShoulder::Forced) {
                return {kForcedFrontOrder.begin(), kForcedFrontOrder.end()};
            }
            return {kFrontOrder.begin(), kFrontOrder.end()};
        default:
            return {kFinOrder.begin(), kFinOrder.end()};
    }
}

const std::optional<int>& userCount(const SkeletonInputs& inputs, LimbKind kind) {
    switch (kind) {
        case LimbKind::Leg:
            return inputs.legs;
        case LimbKind::Wing:
            return inputs.wings;
        case LimbKind::Arm:
            return inputs.arms;
        default:
            return inputs.fins;
    }
}

std::string attachmentList(const std::vector<Attachment>& order) {
    std::string list;
    for (Attachment a : order) {
        if (!list.empty()) list += ", ";
        list += attachmentName(a);
    }
    return list;
}

/// Places `count` limbs (pairs = count / 2) of a kind at the first free allowed attachments.
void placeUserLimbs(LimbLayout& layout, const Allowed& allowed, LimbKind kind, int count,
                    const SkeletonInputs& inputs) {
    const std::vector<Attachment> order = orderFor(kind, inputs);
    int pairs = count / 2;
    int freeCount = 0;
    for (Attachment a : order) {
        if (!allowed[at(a)] || layout[at(a)] != LimbKind::None) continue;
        ++freeCount;
        if (pairs > 0) {
            layout[at(a)] = kind;
            --pairs;
        }
    }
    if (pairs == 0) return;
    const std::string name(limbKindName(kind));
    throw Error("input '" + name + "s': " + std::to_string(count) + " " + name + "s need " +
                std::to_string(count / 2) + " free attachment points (" + attachmentList(order) +
                "), only " + std::to_string(freeCount) +
                " are free; allow two limb pairs per girdle or a second shoulder on the neck, "
                "or ask for fewer limbs");
}

double limbLength(const SkeletonFeatures& features, bool front) {
    const int first = front ? static_cast<int>(Limb::UpperArm) : static_cast<int>(Limb::Thigh);
    return features.limbs[first] + features.limbs[first + 1] + features.limbs[first + 2];
}

bool isFree(const LimbLayout& layout, const Allowed& allowed, Attachment a) {
    return allowed[at(a)] && layout[at(a)] == LimbKind::None;
}

/// The thesis's rules for the kinds the user gave no count for (§5.5). Every random number is
/// drawn whether or not it is used, so one decision does not shift the others.
void placeRandomLimbs(LimbLayout& layout, const Allowed& allowed, const SkeletonFeatures& features,
                      const SkeletonInputs& inputs, Rng& rng) {
    const double vb = std::clamp(features.legs, 0.0, 2.0);
    const double vf = std::clamp(features.wings, 0.0, 1.0);
    const double hindDraw = rng.uniform01(), frontDraw = rng.uniform01();
    const double wingDraw = rng.uniform01(), armDraw = rng.uniform01();
    if (!inputs.legs) {
        const bool hind = vb <= 1.0 ? hindDraw < vb : true;
        const bool front = vb > 1.0 && frontDraw < vb - 1.0;
        if (hind && isFree(layout, allowed, A::Hip)) layout[at(A::Hip)] = LimbKind::Leg;
        if (front && isFree(layout, allowed, A::Shoulder)) layout[at(A::Shoulder)] = LimbKind::Leg;
    }
    if (!inputs.wings && wingDraw < vf && isFree(layout, allowed, A::Shoulder)) {
        layout[at(A::Shoulder)] = LimbKind::Wing;
    }
    if (!inputs.arms && armDraw < vf && isFree(layout, allowed, A::Shoulder)) {
        layout[at(A::Shoulder)] = LimbKind::Arm;
    }
    if (!inputs.fins) {
        for (Attachment a : {A::Hip, A::Shoulder}) {
            const bool small = limbLength(features, isFrontAttachment(a)) < kFinMaxLimbLength;
            if (small && isFree(layout, allowed, a)) layout[at(a)] = LimbKind::Fin;
        }
    }
}

/// A forced neck girdle must carry a limb: an arm pair, else a wing pair, else fins — the
/// first kind whose count the user left open.
void fillForcedNeck(LimbLayout& layout, const Allowed& allowed, const SkeletonInputs& inputs) {
    if (inputs.neckShoulder != NeckShoulder::Forced || layout[at(A::Neck)] != LimbKind::None) {
        return;
    }
    if (!allowed[at(A::Neck)]) {
        throw Error("input 'second shoulder on neck': forced, but the skeleton has no neck");
    }
    for (LimbKind kind : {LimbKind::Arm, LimbKind::Wing, LimbKind::Fin}) {
        if (!userCount(inputs, kind)) {
            layout[at(A::Neck)] = kind;
            return;
        }
    }
    throw Error(
        "input 'second shoulder on neck': forced, but the counts of wings, arms and fins leave "
        "no limb for it");
}

/// Whether a layout keeps the user's counts and a forced neck girdle.
bool keepsInputs(const LimbLayout& layout, const SkeletonInputs& inputs) {
    for (LimbKind kind : kLimbKinds) {
        const std::optional<int>& count = userCount(inputs, kind);
        if (count && 2 * std::count(layout.begin(), layout.end(), kind) != *count) return false;
    }
    return inputs.neckShoulder != NeckShoulder::Forced || layout[at(A::Neck)] != LimbKind::None;
}

Attachment pickAttachment(const std::vector<Attachment>& candidates, Rng& rng) {
    return candidates[rng.uniformInt(static_cast<std::uint32_t>(candidates.size()))];
}

/// §6.3 on one attachment: add to an empty one, or remove and maybe move an occupied one.
void varyAttachment(LimbLayout& layout, const Allowed& allowed, Attachment chosen, Rng& rng) {
    const double changeDraw = rng.uniform01(), moveDraw = rng.uniform01();
    const double kindDraw = rng.uniform01(), placeDraw = rng.uniform01();
    if (changeDraw >= 0.5) return;
    const LimbKind current = layout[at(chosen)];
    if (current == LimbKind::None) {
        std::vector<LimbKind> fitting;
        for (LimbKind kind : kLimbKinds) {
            if (attachmentAccepts(chosen, kind)) fitting.push_back(kind);
        }
        layout[at(chosen)] =
            fitting[static_cast<std::size_t>(kindDraw * static_cast<double>(fitting.size()))];
        return;
    }
    layout[at(chosen)] = LimbKind::None;
    if (moveDraw >= 0.2) return;
    std::vector<Attachment> targets;
    for (int a = 0; a < kAttachmentCount; ++a) {
        const auto target = static_cast<Attachment>(a);
        if (target != chosen && isFree(layout, allowed, target) &&
            attachmentAccepts(target, current)) {
            targets.push_back(target);
        }
    }
    if (targets.empty()) return;
    layout[at(targets[static_cast<std::size_t>(placeDraw * static_cast<double>(targets.size()))])] =
        current;
}

}  // namespace

std::array<bool, kAttachmentCount> allowedAttachments(const SkeletonInputs& inputs,
                                                      const Spine& spine) {
    Allowed allowed{};
    allowed[at(A::Hip)] = allowed[at(A::Shoulder)] = true;
    allowed[at(A::Hip2)] = allowed[at(A::Shoulder2)] = inputs.twoPerGirdle;
    bool neck = false;
    switch (inputs.neckShoulder) {
        case NeckShoulder::Forbidden:
            break;
        case NeckShoulder::Forced:
            neck = spine.hasNeck;
            break;
        case NeckShoulder::Allowed:
            neck = spine.hasNeck && spineLength(spine, SpinePart::Neck) >= kNeckGirdleMinLength;
            break;
    }
    allowed[at(A::Neck)] = neck;
    allowed[at(A::Neck2)] = neck && inputs.twoPerGirdle;
    return allowed;
}

LimbLayout assignLimbs(const SkeletonFeatures& features, const Spine& spine,
                       const SkeletonInputs& inputs, Rng& rng) {
    const Allowed allowed = allowedAttachments(inputs, spine);
    LimbLayout layout{};
    for (LimbKind kind : kLimbKinds) {
        if (const std::optional<int>& count = userCount(inputs, kind)) {
            placeUserLimbs(layout, allowed, kind, *count, inputs);
        }
    }
    placeRandomLimbs(layout, allowed, features, inputs, rng);
    fillForcedNeck(layout, allowed, inputs);
    normalizeLimbLayout(layout);
    return layout;
}

LimbLayout varyLimbs(const LimbLayout& source, const SkeletonFeatures& /*features*/,
                     const Spine& spine, const SkeletonInputs& inputs, Rng& rng) {
    Allowed allowed = allowedAttachments(inputs, spine);
    for (int a = 0; a < kAttachmentCount; ++a) {
        if (source[a] != LimbKind::None) allowed[a] = true;  // the source's own layout stays valid
    }
    std::vector<Attachment> candidates;
    for (int a = 0; a < kAttachmentCount; ++a) {
        if (allowed[a]) candidates.push_back(static_cast<Attachment>(a));
    }
    LimbLayout layout = source;
    varyAttachment(layout, allowed, pickAttachment(candidates, rng), rng);
    normalizeLimbLayout(layout);
    return keepsInputs(layout, inputs) ? layout : source;
}

void normalizeLimbLayout(LimbLayout& layout) {
    constexpr std::array<std::pair<Attachment, Attachment>, 3> kPairs = {
        {{A::Hip, A::Hip2}, {A::Shoulder, A::Shoulder2}, {A::Neck, A::Neck2}}};
    for (const auto& [primary, secondary] : kPairs) {
        if (layout[at(primary)] == LimbKind::None) {
            std::swap(layout[at(primary)], layout[at(secondary)]);
        }
    }
}

}  // namespace ramus::detail
