// Names of the bone-model vocabulary and the choice of skull by head kind (include/ramus/bones.hpp;
// seed 000 §5.6 "Spezielle Knochen", §6.1 "head kind").
#include <string>

#include "core/enum_names.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"

namespace ramus {
namespace {

using detail::nameOf;
using detail::parseName;

constexpr std::array<std::string_view, 3> kResolutionNames = {"box", "low", "high"};
constexpr std::array<std::string_view, kBoneModelKindCount> kModelKindNames = {
    "vertebra",   "tail_tip",      "rib",     "skull_herbivore", "skull_carnivore",
    "skull_bird", "skull_reptile", "scapula", "pelvis",          "pelvis_double",
    "upper_arm",  "forearm",       "thigh",   "shank",           "hand",
    "hoof",       "wing_hand",     "fin"};
constexpr std::array<BoneModelKind, kHeadKinds.size()> kSkullModels = {
    BoneModelKind::SkullHerbivore, BoneModelKind::SkullCarnivore, BoneModelKind::SkullBird,
    BoneModelKind::SkullReptile};

}  // namespace

std::string_view boneResolutionName(BoneResolution resolution) {
    return nameOf(kResolutionNames, resolution);
}
std::optional<BoneResolution> parseBoneResolution(std::string_view name) {
    return parseName<BoneResolution>(kResolutionNames, name);
}
std::string_view boneModelKindName(BoneModelKind kind) { return nameOf(kModelKindNames, kind); }
std::optional<BoneModelKind> parseBoneModelKind(std::string_view name) {
    return parseName<BoneModelKind>(kModelKindNames, name);
}

BoneModelKind skullModelForHeadKind(std::string_view headKind) {
    if (headKind.empty()) return BoneModelKind::SkullHerbivore;
    std::string known;
    for (std::size_t i = 0; i < kHeadKinds.size(); ++i) {
        if (kHeadKinds[i] == headKind) return kSkullModels[i];
        known += (i == 0 ? "" : ", ") + std::string(kHeadKinds[i]);
    }
    throw Error("unknown head kind \"" + std::string(headKind) + "\"; expected one of " + known);
}

std::string_view defaultHeadKind(AnimalClass animalClass) {
    switch (animalClass) {
        case AnimalClass::Bird:
            return "bird";
        case AnimalClass::Mammal:
            return "herbivore";
        case AnimalClass::Fish:
        case AnimalClass::Amphibian:
        case AnimalClass::Reptile:
            return "reptile";
    }
    return "herbivore";
}

}  // namespace ramus
