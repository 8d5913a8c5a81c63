// Procedural shapes of the default bone models (seed 000 §5.6): one signed-distance function
// per BoneModelKind in the unit cube of include/ramus/bones.hpp, with the box to mesh and the
// model's joint offsets.
#pragma once

#include <vector>

#include "bones/iso_mesher.hpp"
#include "ramus/bones.hpp"

namespace ramus {

/// A bone model before meshing.
struct BoneShape {
    DistanceFunction distance;  ///< unit-cube coordinates, negative inside
    Vec3 lo{0.0, -0.5, -0.5};   ///< box that holds the whole zero set
    Vec3 hi{1.0, 0.5, 0.5};
    Vec3 parentJoint = Vec3::Zero();
    std::vector<Vec3> childJoints{Vec3(1.0, 0.0, 0.0)};
    double widthFromHeight = 0.0;
};

/// A default-library model meshed at a resolution (Low or High) within its triangle budget
/// (builtin_library.cpp); deterministic. BoneLibrary::builtin caches these.
BoneModel buildBoneModel(BoneModelKind kind, BoneResolution resolution);

/// The shape of a model kind (every kind has one).
BoneShape boneShape(BoneModelKind kind);

// Per family (bone_shapes_*.cpp).
BoneShape vertebraShape();
BoneShape tailTipShape();
BoneShape ribShape();
BoneShape scapulaShape();
BoneShape pelvisShape(bool doubleSockets);
BoneShape skullShape(BoneModelKind kind);
BoneShape longBoneShape(BoneModelKind kind);
BoneShape handShape(BoneModelKind kind);

}  // namespace ramus
