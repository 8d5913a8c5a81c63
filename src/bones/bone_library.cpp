// BoneLibrary storage: one shared, immutable model per model kind and resolution
// (include/ramus/bones.hpp). The default library's models come from builtin_library.cpp.
#include <string>

#include "ramus/bones.hpp"
#include "ramus/error.hpp"

namespace ramus {
namespace {

/// Slot of a resolution in BoneLibrary::models_; Box has no models.
std::size_t resolutionSlot(BoneModelKind kind, BoneResolution resolution) {
    if (resolution == BoneResolution::Box) {
        throw Error("bone model " + std::string(boneModelKindName(kind)) +
                    ": the box resolution has no bone models; expected low or high");
    }
    return resolution == BoneResolution::Low ? 0 : 1;
}

}  // namespace

bool BoneLibrary::has(BoneModelKind kind, BoneResolution resolution) const {
    if (resolution == BoneResolution::Box) return false;
    return models_[static_cast<std::size_t>(kind)][resolutionSlot(kind, resolution)] != nullptr;
}

const BoneModel& BoneLibrary::model(BoneModelKind kind, BoneResolution resolution) const {
    const auto& slot = models_[static_cast<std::size_t>(kind)][resolutionSlot(kind, resolution)];
    if (!slot) {
        throw Error("the bone library has no " + std::string(boneResolutionName(resolution)) +
                    "-resolution model for " + std::string(boneModelKindName(kind)));
    }
    return *slot;
}

void BoneLibrary::set(BoneModelKind kind, BoneResolution resolution, BoneModel model) {
    models_[static_cast<std::size_t>(kind)][resolutionSlot(kind, resolution)] =
        std::make_shared<const BoneModel>(std::move(model));
}

}  // namespace ramus
