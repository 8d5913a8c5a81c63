// Mirroring: the right twin of every left bone, in a right-handed frame.
//
// Based on: seed 000 §5.1 step 4 (everything off the spine is mirrored across the xy-plane) and
// §7.3, figs. 7.3 and 7.4: a plain reflection k_l of a bone k has a left-handed frame; the twin's
// frame k_r is k_l followed by T_kx (a reflection of the bone's own z), so for a child of a
// spine bone e, T_kr = T_eg⁻¹ · T_r · T_klg · T_kx, and below a mirrored parent
// T_kr = T_ex · T_k · T_kx. With the bone boxes centred in z (skeleton.hpp), T_kx is the pure
// reflection S = diag(1, 1, −1), which maps the box onto itself. In world terms:
//   world_R = M · world_L · S,   M = S = diag(1, 1, −1) (M in the world, S in the bone frame),
// a proper rotation (det +1), and relative to the twin's parent P_R:
//   local_R = P_R⁻¹ · M · P_L · local_L · S,
// which is S · local_L · S for a mirrored parent (P_R = M · P_L · S) and for a center parent
// that lies in the mid-plane. As a joint: with X = P_R⁻¹ · M · P_L = [Q | u],
//   position_R = Q · position_L + u,  rest_R = Q · rest_L · S,
//   every dof axis a → −S · a = (−aₓ, −a_y, a_z) with the same angle and limits,
// because S · R(a, θ) · S = R(−S · a, θ) (conjugating a rotation by a reflection).
#include <algorithm>
#include <cmath>

#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

const Mat3 kReflectZ = Vec3(1.0, 1.0, -1.0).asDiagonal();

/// Inverse of a rigid transform.
Mat4 rigidInverse(const Mat4& m) {
    Mat4 inverse = Mat4::Identity();
    const Mat3 rotationT = m.topLeftCorner<3, 3>().transpose();
    inverse.topLeftCorner<3, 3>() = rotationT;
    inverse.topRightCorner<3, 1>() = -rotationT * m.topRightCorner<3, 1>();
    return inverse;
}

/// M · world: the world reflection across the xy-plane.
Mat4 reflectWorld(const Mat4& world) {
    Mat4 reflected = world;
    reflected.row(2) *= -1.0;
    return reflected;
}

/// The twin's joint from the left joint and X = P_R⁻¹ · M · P_L (see the file comment).
Joint mirrorJoint(const Joint& left, const Mat4& parentChange) {
    Joint right = left;
    const Mat3 q = parentChange.topLeftCorner<3, 3>();
    right.position = q * left.position + parentChange.topRightCorner<3, 1>();
    right.rest = q * left.rest * kReflectZ;
    for (int i = 0; i < left.dofCount; ++i) right.dofs[i].axis = -(kReflectZ * left.dofs[i].axis);
    return right;
}

/// World transforms of the bones whose frames the twins need, other entries unset: the parents of
/// unmirrored Left bones that are not Left themselves, and their ancestors (below a Left parent
/// the twin's joint is S · local · S, and the twins' own frames are never needed).
std::vector<Mat4> parentWorlds(const Skeleton& skeleton) {
    const std::size_t n = skeleton.bones.size();
    std::vector<char> needed(n, 0);
    for (const Bone& bone : skeleton.bones) {
        if (bone.side != Side::Left || bone.twin >= 0 || bone.parent < 0) continue;
        if (skeleton.bones[bone.parent].side != Side::Left) needed[bone.parent] = 1;
    }
    for (std::size_t i = n; i-- > 0;) {  // parents come before children
        if (needed[i] && skeleton.bones[i].parent >= 0) needed[skeleton.bones[i].parent] = 1;
    }
    std::vector<Mat4> world(n);
    for (std::size_t i = 0; i < n; ++i) {  // as Skeleton::worldTransforms
        if (!needed[i]) continue;
        const Mat4 local = skeleton.bones[i].joint.transform();
        const int parent = skeleton.bones[i].parent;
        world[i] = parent < 0 ? local : Mat4(world[static_cast<std::size_t>(parent)] * local);
    }
    return world;
}

}  // namespace

void mirrorSkeleton(Skeleton& skeleton) {
    const std::size_t leftCount = skeleton.bones.size();
    const std::vector<Mat4> world = parentWorlds(skeleton);
    const auto unmirrored =
        std::count_if(skeleton.bones.begin(), skeleton.bones.end(),
                      [](const Bone& b) { return b.side == Side::Left && b.twin < 0; });
    skeleton.bones.reserve(leftCount + static_cast<std::size_t>(unmirrored));
    // Parents come first, so a left parent's twin exists before its children are mirrored.
    for (std::size_t i = 0; i < leftCount; ++i) {
        const Bone& left = skeleton.bones[i];
        if (left.side != Side::Left || left.twin >= 0) continue;  // mirrored already
        Bone right = left;
        right.side = Side::Right;
        right.twin = static_cast<int>(i);
        Mat4 parentChange = Mat4::Identity();  // X = P_R⁻¹ · M · P_L
        if (left.parent >= 0) {
            const Bone& parent = skeleton.bones[left.parent];
            if (parent.side == Side::Left) {
                right.parent = parent.twin;
                parentChange.topLeftCorner<3, 3>() = kReflectZ;  // exact: S · local · S
            } else {
                const Mat4& parentLeft = world[left.parent];
                parentChange = rigidInverse(parentLeft) * reflectWorld(parentLeft);
            }
        } else {
            parentChange = reflectWorld(Mat4::Identity());
        }
        right.joint = mirrorJoint(left.joint, parentChange);
        skeleton.bones[i].twin = static_cast<int>(skeleton.bones.size());
        skeleton.bones.push_back(right);
    }
}

}  // namespace ramus::detail
