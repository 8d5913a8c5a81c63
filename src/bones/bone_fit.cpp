// Assembly: which model each bone gets and how a unit-cube model is fitted to a bone's box and
// joints (include/ramus/bones.hpp).
//
// Based on: seed 000 §5.6 — models normalised to the unit cube and scaled by the bone's
// extents; offsets to the parent joint and the child joint; the widths of thickness-only axes
// taken relative to another axis ("Vorverarbeitung der Knochenmodelle", third bullet); special
// bones: skulls by head kind, the 3-vertebra tail tip, the double pelvis, hands and feet by limb
// kind with the 45° hoof rule. Mirroring per §7.3: the right twin's frame is the left one's
// reflected in its own z (skeleton/mirror.cpp), so its geometry is reflected in z and its
// triangles turned back to face outwards.
#include <algorithm>
#include <cmath>

#include "ramus/bones.hpp"
#include "ramus/error.hpp"

namespace ramus {
namespace {

bool isTailVertebra(const Bone& bone) {
    return bone.kind == BoneKind::Vertebra && bone.region == SpineRegion::Tail;
}

/// Number of tail vertebrae (their indices run 1…count from the hip outwards).
int tailCount(const Skeleton& skeleton) {
    int count = 0;
    for (const Bone& bone : skeleton.bones)
        count = std::max(count, isTailVertebra(bone) ? bone.index : 0);
    return count;
}

/// The tail vertebra with index `index` (-1 if none).
int tailVertebra(const Skeleton& skeleton, int index) {
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        if (isTailVertebra(skeleton.bones[i]) && skeleton.bones[i].index == index) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

BoneModelKind extremityModel(const Bone& bone) {
    switch (bone.limb) {
        case LimbKind::Wing:
            return BoneModelKind::WingHand;
        case LimbKind::Fin:
            return BoneModelKind::Fin;
        case LimbKind::Leg:
            return bone.hoof ? BoneModelKind::Hoof : BoneModelKind::Hand;
        case LimbKind::Arm:
        case LimbKind::None:
            return BoneModelKind::Hand;
    }
    return BoneModelKind::Hand;
}

/// Length of the tail tip: from the third-last tail vertebra's joint to the end of the last
/// one, measured along the third-last's x axis (the three nearly line up on the tail curve).
double tailTipLength(const Skeleton& skeleton, int first) {
    const int count = tailCount(skeleton);
    const int last = tailVertebra(skeleton, count);
    if (last < 0) return skeleton.bones[static_cast<std::size_t>(first)].extents.x();
    const std::vector<Mat4> world = skeleton.worldTransforms();
    const Mat4& a = world[static_cast<std::size_t>(first)];
    const Mat4& b = world[static_cast<std::size_t>(last)];
    const Vec3 end =
        (b * Vec4(skeleton.bones[static_cast<std::size_t>(last)].extents.x(), 0, 0, 1)).head<3>();
    const Vec3 along = a.topLeftCorner<3, 3>().col(0);
    const double length = (end - a.topRightCorner<3, 1>()).dot(along);
    return length > 0.0 ? length : skeleton.bones[static_cast<std::size_t>(first)].extents.x();
}

}  // namespace

std::optional<BoneModelKind> modelForBone(const Skeleton& skeleton, int boneIndex,
                                          std::string_view headKind) {
    const Bone& bone = skeleton.bones.at(static_cast<std::size_t>(boneIndex));
    switch (bone.kind) {
        case BoneKind::Root:
            return std::nullopt;
        case BoneKind::Vertebra: {
            if (!isTailVertebra(bone)) return BoneModelKind::Vertebra;
            const int count = tailCount(skeleton);
            if (count < 3 || bone.index < count - 2) return BoneModelKind::Vertebra;
            if (bone.index == count - 2) return BoneModelKind::TailTip;
            return std::nullopt;  // drawn by the tail tip
        }
        case BoneKind::Rib:
            return BoneModelKind::Rib;
        case BoneKind::Skull:
            return skullModelForHeadKind(headKind);
        case BoneKind::Scapula:
            return BoneModelKind::Scapula;
        case BoneKind::UpperArm:
            return BoneModelKind::UpperArm;
        case BoneKind::Forearm:
            return BoneModelKind::Forearm;
        case BoneKind::Pelvis:
            return bone.doubleJoint ? BoneModelKind::PelvisDouble : BoneModelKind::Pelvis;
        case BoneKind::Thigh:
            return BoneModelKind::Thigh;
        case BoneKind::Shank:
            return BoneModelKind::Shank;
        case BoneKind::Hand:
        case BoneKind::Foot:
            return extremityModel(bone);
    }
    return std::nullopt;
}

Mesh fitBoneModel(const BoneModel& model, const Bone& bone, std::optional<double> length) {
    Mesh mesh;
    const Vec3 e = bone.extents;
    const double boneLength = length.value_or(e.x());
    const double span = model.childJoints.front().x() - model.parentJoint.x();
    if (!(boneLength > 0.0 && e.y() > 0.0 && e.z() > 0.0 && span > 0.0)) return mesh;
    const Vec3 scale(boneLength / span, e.y(),
                     model.widthFromHeight > 0.0 ? model.widthFromHeight * e.y() : e.z());
    const bool right = bone.side == Side::Right;
    const double flip = right ? -1.0 : 1.0;  // the right twin: reflected in its own z
    const std::size_t n = model.mesh.positions.size();
    mesh.name = std::string(boneKindName(bone.kind));
    mesh.positions.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 u = model.mesh.positions[i].cast<double>() - model.parentJoint;
        mesh.positions[i] =
            Vec3f(static_cast<float>(u.x() * scale.x()), static_cast<float>(u.y() * scale.y()),
                  static_cast<float>(flip * u.z() * scale.z()));
    }
    if (model.mesh.normals.size() == n) {
        // Normals transform with the inverse transpose of the (diagonal) scale.
        mesh.normals.resize(n);
        const Vec3 inverse(1.0 / scale.x(), 1.0 / scale.y(), flip / scale.z());
        for (std::size_t i = 0; i < n; ++i) {
            Vec3 normal = model.mesh.normals[i].cast<double>().cwiseProduct(inverse);
            const double norm = normal.norm();
            normal = norm > 0.0 ? Vec3(normal / norm) : Vec3(1.0, 0.0, 0.0);
            mesh.normals[i] = normal.cast<float>();
        }
    }
    mesh.indices = model.mesh.indices;
    if (right) {
        // A reflection turns counter-clockwise triangles clockwise: swap two corners back.
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
        }
    }
    return mesh;
}

BoneMeshSource boneMeshSource(const Skeleton& skeleton, const BoneLibrary& library,
                              BoneResolution resolution, std::string_view headKind) {
    if (resolution == BoneResolution::Box) {
        return [](int, const Bone& bone) { return boneBoxMesh(bone); };
    }
    // Check the head kind and the library once, before any bone is fitted.
    (void)skullModelForHeadKind(headKind);
    for (int k = 0; k < kBoneModelKindCount; ++k) {
        (void)library.model(static_cast<BoneModelKind>(k), resolution);
    }
    return [&skeleton, &library, resolution, head = std::string(headKind)](int index,
                                                                           const Bone& bone) {
        const std::optional<BoneModelKind> kind = modelForBone(skeleton, index, head);
        if (!kind) return Mesh{};
        std::optional<double> length;
        if (*kind == BoneModelKind::TailTip) length = tailTipLength(skeleton, index);
        return fitBoneModel(library.model(*kind, resolution), bone, length);
    };
}

Scene skeletonSceneAt(const Skeleton& skeleton, BoneResolution resolution,
                      std::string_view headKind, const BoneLibrary* library) {
    SkeletonSceneParams params;
    if (resolution != BoneResolution::Box) {
        const BoneLibrary& models = library ? *library : BoneLibrary::builtin(resolution);
        params.boneMesh = boneMeshSource(skeleton, models, resolution, headKind);
    }
    return skeletonToScene(skeleton, params);
}

}  // namespace ramus
