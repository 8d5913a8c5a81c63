// A skeleton as a glTF-ready scene (DESIGN.md "glTF"; SPEC §H): one joint node per bone under
// the root bone's node, one skin over all of them, and one skinned mesh per bone in bind pose,
// every vertex bound rigidly to its bone's joint (issue 6: "one mesh per bone bound to its
// joint", so each bone is its own object in Blender and poses with its joint).
//
// Axes: the internal px frame (skeleton.hpp: y up, head towards −x, left side at +z) becomes
// glTF's (metres, Y up, front +Z, left +X, ground on y = 0):
//     p_gltf = s · R · (p − (0, groundHeight, 0)),  s = metresPerPixel,
//     R = [[0, 0, 1], [0, 1, 0], [−1, 0, 0]]  (a rotation: internal z → X, −x → Z).
// Joint nodes are rigid (no scale): a bone's node sits at its joint, and its frame is the bone
// frame turned so that node +Y runs along the bone (bone +x), node +X is bone −y and node +Z is
// bone +z. Animation tools (Blender) take +Y as the bone direction.
#pragma once

#include <functional>
#include <string>

#include "ramus/math.hpp"
#include "ramus/mesh.hpp"
#include "ramus/scene.hpp"
#include "ramus/skeleton.hpp"

namespace ramus {

/// The mesh of one bone in the bone's own frame (px; skeleton.hpp's Bone: x ∈ [0, length] from
/// the joint towards the child, y and z centred): triangles counter-clockwise seen from
/// outside, the frame right-handed for left, right and center bones alike. Normals, tangents and
/// uvs are optional (kept when they cover every vertex); the mesh's name, materials,
/// primitives, joints, weights and custom attributes are replaced. An empty mesh draws
/// nothing for that bone. The bone-model library plugs its scaled models in here (bones.hpp).
/// `boneIndex` is the bone's index in Skeleton::bones.
using BoneMeshSource = std::function<Mesh(int boneIndex, const Bone& bone)>;

/// The bone's box: x ∈ [0, extents.x], y ∈ ±extents.y/2, z ∈ ±extents.z/2 (px, bone frame).
/// 24 vertices (4 per face, flat unit normals), 12 counter-clockwise triangles seen from
/// outside, no uvs or tangents, no materials. Empty when an extent is ≤ 0 or not finite (the
/// zero-size root bone has no box).
Mesh boneBoxMesh(const Bone& bone);

/// The default bone material: ivory (linear RGB ≈ 0.80, 0.74, 0.60), dielectric, roughness 0.7.
Material boneMaterial();

/// Options of skeletonToScene.
struct SkeletonSceneParams {
    /// The mesh of each bone; empty = boneBoxMesh (boxes, written without a per-bone Mesh).
    BoneMeshSource boneMesh;
    /// Material of every bone; each bone mesh has one primitive named after its kind with a
    /// copy of this material named "<material.name>_<kind>" (e.g. "bone_vertebra"), so glTF
    /// importers get one material slot and OBJ files one usemtl per kind.
    Material material = boneMaterial();
    /// Name of the skin.
    std::string skinName = "skeleton";
};

/// The 4×4 transform internal px frame → glTF metres (see the file comment); maps the point
/// (x, groundHeight, z) to y = 0.
Mat4 skeletonToGltf(const Skeleton& skeleton);

/// The glTF node frame of a bone: (bone frame → node frame) maps node +Y to bone +x, node +X
/// to bone −y and node +Z to bone +z, i.e. node coordinates v ↦ kBoneFromNode · v in the bone
/// frame. A rotation (determinant +1).
Mat3 boneFromNode();

/// The scene of a skeleton:
/// - nodes 0 … n−1: bone i → node i named Bone::name(), parent = the parent bone's node, so the
///   root bone's node is the single root joint; local transforms are rigid (translation in
///   metres, rotation; scale 1), the world frame of node i is the bone frame turned by
///   boneFromNode() and converted by skeletonToGltf (without its scale). extras (JSON):
///   "kind", "side", "region" (vertebrae, ribs), "index" (when > 0), "limb" and "attachment"
///   (girdle and limb bones), "double_joint" (double pelvis), "extents_m" ([length, height,
///   width] in metres) and "joint": {"rest_rotation": [x, y, z, w] — the node's local rotation
///   with all joint angles 0 —, "dofs": [{"axis": [x, y, z], "angle_deg", "min_deg",
///   "max_deg"}]}; the axes are unit vectors in the node's own frame at rest, and the node's
///   local rotation is rest_rotation · rot(axis₀, angle₀) · rot(axis₁, angle₁).
/// - nodes n, n+1, …: one per bone with a mesh, in bone order, named "<bone name>_mesh": root
///   nodes with the identity transform holding that bone's mesh with skin 0 (glTF ignores a
///   skinned node's transform; they are not joints).
/// - skin 0: joints 0 … n−1 (bone order), skeleton = node 0, inverse bind matrices = the
///   inverse world matrix of each joint node.
/// - meshes, one per bone with a mesh (the zero-size root and bones whose source mesh is empty
///   have none), in bone order, named Bone::name(): the bone's mesh in bind pose (glTF world
///   coordinates), one primitive named after the bone kind; each vertex has joints
///   (bone, 0, 0, 0) and weights (1, 0, 0, 0).
/// - extras: "ground_height_px", "metres_per_pixel", "heel_contact".
/// An empty skeleton (no bones) gives an empty scene. Precondition: bones[0] is the root and
/// parents come before children (Skeleton's invariants), joint rotations are orthonormal, at
/// most 65536 bones (16-bit joint indices).
Scene skeletonToScene(const Skeleton& skeleton, const SkeletonSceneParams& params = {});

}  // namespace ramus
