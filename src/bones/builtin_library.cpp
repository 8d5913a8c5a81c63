// The default bone library (seed 000 §5.6): every model kind meshed once per process and
// resolution from its signed-distance shape (bones/bone_shapes.hpp).
//
// Based on: seed 000 §5.6 (bone models in the unit cube, resolutions of §6.1); meshing by
// marching tetrahedra (Doi & Koide 1991, bones/iso_mesher.cpp), the grid chosen per model as the
// finest within the triangle budget.
#include <array>
#include <string>

#include "bones/bone_shapes.hpp"
#include "bones/iso_mesher.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"

namespace ramus {
namespace {

/// Low-resolution budgets per model kind (BoneModelKind order); High is kHighFactor times.
constexpr std::array<int, kBoneModelKindCount> kLowBudget = {
    400,   // vertebra
    400,   // tail_tip
    150,   // rib
    1200,  // skull_herbivore
    1200,  // skull_carnivore
    1000,  // skull_bird
    1200,  // skull_reptile
    250,   // scapula
    600,   // pelvis
    800,   // pelvis_double
    300,   // upper_arm
    300,   // forearm
    300,   // thigh
    300,   // shank
    400,   // hand
    200,   // hoof
    400,   // wing_hand
    300,   // fin
};
constexpr int kHighFactor = 6;
constexpr int kMaxCellsLongest = 96;

BoneLibrary buildLibrary(BoneResolution resolution) {
    BoneLibrary library;
    for (int k = 0; k < kBoneModelKindCount; ++k) {
        const auto kind = static_cast<BoneModelKind>(k);
        library.set(kind, resolution, buildBoneModel(kind, resolution));
    }
    return library;
}

}  // namespace

BoneModel buildBoneModel(BoneModelKind kind, BoneResolution resolution) {
    const BoneShape shape = boneShape(kind);
    BoneModel model;
    model.mesh = meshIsosurfaceWithinBudget(shape.distance, shape.lo, shape.hi,
                                            boneTriangleBudget(kind, resolution), kMaxCellsLongest);
    model.mesh.name = std::string(boneModelKindName(kind));
    model.parentJoint = shape.parentJoint;
    model.childJoints = shape.childJoints;
    model.widthFromHeight = shape.widthFromHeight;
    return model;
}

int boneTriangleBudget(BoneModelKind kind, BoneResolution resolution) {
    const int low = kLowBudget[static_cast<std::size_t>(kind)];
    switch (resolution) {
        case BoneResolution::Box:
            return 12;
        case BoneResolution::Low:
            return low;
        case BoneResolution::High:
            return low * kHighFactor;
    }
    return low;
}

const BoneLibrary& BoneLibrary::builtin(BoneResolution resolution) {
    if (resolution == BoneResolution::Low) {
        static const BoneLibrary low = buildLibrary(BoneResolution::Low);
        return low;
    }
    if (resolution == BoneResolution::High) {
        static const BoneLibrary high = buildLibrary(BoneResolution::High);
        return high;
    }
    throw Error(
        "the default bone library has no models for the box resolution; expected low "
        "or high");
}

}  // namespace ramus
