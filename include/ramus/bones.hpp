// Bone models: what turns a generated skeleton's boxes into bones (seed 000 §5.6; SPEC §G).
//
// Every model lives in the thesis's unit cube (seed 000 §5.6 "Vorverarbeitung"): the bone's box
// is x ∈ [0, 1] (from the joint to the parent towards the child), y ∈ [−½, ½] (the bone's
// height) and z ∈ [−½, ½] (its width), in the bone frame of skeleton.hpp for a Left or Center
// bone. Lengths that must match are exact cube edges (a vertebra's body runs from x = 0 to
// x = 1 so that neighbours meet); small processes may stick out of the cube. A model also
// carries the offsets the thesis stored per bone (§5.6 "Offsets zwischen Knochen"): where the
// joint to the parent and the joints to the children sit, in the same unit coordinates, so that
// the fitted model's articulations land on the skeleton's joints whatever its size.
//
// The default library is ours (no third-party meshes): every model is a blend of smooth
// signed-distance shapes, meshed once per process and resolution and reused. A user library is
// a directory with a manifest (docs/bones.md) naming per model an OBJ or glTF file and its
// offsets, so models and offsets are swappable without code changes (the thesis's wish);
// writeBoneLibrary writes the default library out as such a directory, a template to edit.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/math.hpp"
#include "ramus/mesh.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_scene.hpp"
#include "ramus/species.hpp"

namespace ramus {

/// How detailed the bone meshes are (seed 000 §6.1 "resolution"): the plain boxes, or real
/// bone models at a low or a high triangle budget (boneTriangleBudget).
enum class BoneResolution : std::uint8_t { Box, Low, High };
/// "box", "low", "high".
std::string_view boneResolutionName(BoneResolution resolution);
/// Inverse of boneResolutionName; nullopt for anything else.
std::optional<BoneResolution> parseBoneResolution(std::string_view name);

/// The models a library holds: one per bone kind, with the variants the thesis names (§5.6
/// "Spezielle Knochen"): the 3-vertebra tail tip, the double pelvis, skulls by head kind, and
/// hands/feet by limb kind.
enum class BoneModelKind : std::uint8_t {
    Vertebra,        ///< centrum, neural arch, spinous and transverse processes
    TailTip,         ///< the last three tail vertebrae as one tapering model
    Rib,             ///< curved, tapering, meeting its vertebra at x = 0
    SkullHerbivore,  ///< long horse-like skull
    SkullCarnivore,  ///< carnivore skull with jaw and a row of teeth
    SkullBird,       ///< bird skull with a beak
    SkullReptile,    ///< long flat crocodilian skull
    Scapula,         ///< shoulder blade
    Pelvis,          ///< one hip socket per side
    PelvisDouble,    ///< Beckenknochen2: two hip sockets per side (two limb pairs, G′)
    UpperArm,        ///< humerus: shaft, head, condyles
    Forearm,         ///< radius and ulna side by side
    Thigh,           ///< femur: shaft, head, condyles
    Shank,           ///< tibia and fibula side by side
    Hand,            ///< hand with digits (arms, fins by default, legs with a flat foot)
    Hoof,            ///< hoof (legs whose foot stands steeper than 45°, Bone::hoof)
    WingHand,        ///< wing: elongated digits
    Fin,             ///< flipper paddle
};
inline constexpr int kBoneModelKindCount = 18;
/// Names as in manifests and on the command line: "vertebra", "tail_tip", "rib",
/// "skull_herbivore", "skull_carnivore", "skull_bird", "skull_reptile", "scapula", "pelvis",
/// "pelvis_double", "upper_arm", "forearm", "thigh", "shank", "hand", "hoof", "wing_hand",
/// "fin".
std::string_view boneModelKindName(BoneModelKind kind);
/// Inverse of boneModelKindName; nullopt for anything else.
std::optional<BoneModelKind> parseBoneModelKind(std::string_view name);

/// Head kinds a user can choose (SkeletonInputs::headKind): "herbivore", "carnivore", "bird",
/// "reptile", each naming the model Skull<Kind>.
inline constexpr std::array<std::string_view, 4> kHeadKinds = {"herbivore", "carnivore", "bird",
                                                               "reptile"};
/// The skull model of a head kind; an empty name gives the default (herbivore). Throws Error
/// for an unknown name, listing the known ones.
BoneModelKind skullModelForHeadKind(std::string_view headKind);
/// The head kind that fits an animal class where it is known: bird → "bird", reptile and
/// amphibian → "reptile", fish → "reptile", mammal → "herbivore".
std::string_view defaultHeadKind(AnimalClass animalClass);

/// One bone model in unit-cube coordinates (see the file comment).
struct BoneModel {
    /// Closed, outward-facing (counter-clockwise seen from outside) triangle mesh with unit
    /// normals; no uvs, tangents, joints, weights, primitives or materials.
    Mesh mesh;
    /// Where the joint to the parent sits (unit coordinates); the fitted model puts this point
    /// on the bone's joint, i.e. the bone frame's origin. Usually (0, 0, 0).
    Vec3 parentJoint = Vec3::Zero();
    /// Where the joints to the children sit (unit coordinates), the first being the one along
    /// the bone (x = its end) that fixes the model's length: the fitted model puts it at
    /// x = bone length. Usually {(1, 0, 0)}; the double pelvis lists both hip sockets per side
    /// after it. Never empty.
    std::vector<Vec3> childJoints{Vec3(1.0, 0.0, 0.0)};
    /// How the model's z (width) is scaled (seed 000 §5.6, third bullet): by the bone's width
    /// when 0, else by this factor times the bone's height, so thickness follows the given
    /// height and the bone does not look squashed.
    double widthFromHeight = 0.0;
};

/// Triangle budget of a model at a resolution (docs/bones.md has the table): Box → 12;
/// Low and High per model kind. Every model of the default library stays within it; a user
/// model may exceed it (the budget is a guide for authors then, not a limit).
int boneTriangleBudget(BoneModelKind kind, BoneResolution resolution);

/// A set of bone models, one per model kind and resolution (Low and High; Box needs none).
/// Cheap to copy (models are shared and immutable).
class BoneLibrary {
public:
    /// The default library at a resolution (Low or High): every model kind, built
    /// procedurally on the first call per resolution (thread-safe) and kept for the life of the
    /// process. The returned library holds only that resolution's models.
    static const BoneLibrary& builtin(BoneResolution resolution);

    /// The model of a kind at a resolution (Low or High). Throws Error for Box (no models) or
    /// when the library lacks the model (naming the kind and the resolution).
    const BoneModel& model(BoneModelKind kind, BoneResolution resolution) const;
    /// Whether the library has that model.
    bool has(BoneModelKind kind, BoneResolution resolution) const;
    /// Sets (replaces) a model.
    void set(BoneModelKind kind, BoneResolution resolution, BoneModel model);

private:
    std::array<std::array<std::shared_ptr<const BoneModel>, 2>, kBoneModelKindCount> models_{};
};

/// Loads a user library at a resolution (Low or High; like builtin, the library holds only
/// that resolution's models): `directory`/bones.json (docs/bones.md "User bone libraries")
/// names per model kind a mesh file (.obj, .gltf or .glb, relative to the directory) for both
/// resolutions or one per resolution, and the model's offsets. Kinds the manifest leaves out
/// come from BoneLibrary::builtin(resolution). Every loaded mesh is checked (closed, outward,
/// no degenerate triangles). Throws Error naming the file (the manifest with line and column,
/// or the mesh file) and what is missing or wrong (unknown kind, missing mesh or offset, file
/// not found, open or inward mesh, bad offset, unsupported version).
BoneLibrary loadBoneLibrary(const std::string& directory, BoneResolution resolution);

/// Writes `library`'s models as OBJ files (`low/<kind>.obj`, `high/<kind>.obj`, floats in the
/// shortest form that reads back identical) plus bones.json into `directory` (created if
/// missing; every file written atomically, the manifest last), so that loadBoneLibrary
/// reproduces every model exactly (positions, normals, triangles, offsets). Kinds the library
/// lacks at both resolutions are left out. Throws Error when a kind's low and high models have
/// different offsets (a manifest entry has one set) or a file cannot be written.
void writeBoneLibrary(const BoneLibrary& library, const std::string& directory);

/// Which model a bone gets (seed 000 §5.6): vertebrae → Vertebra (the third-last tail vertebra
/// → TailTip, the last two → none, when the tail has at least three), ribs → Rib, the skull →
/// the head kind's skull, scapula, pelvis (doubleJoint → PelvisDouble), long bones by kind,
/// hands and feet by limb kind: wing → WingHand, fin → Fin, leg → Hoof when Bone::hoof else
/// Hand, arm → Hand. nullopt for the root and for bones drawn by another bone's model.
std::optional<BoneModelKind> modelForBone(const Skeleton& skeleton, int boneIndex,
                                          std::string_view headKind);

/// The model fitted to a bone box (px, bone frame; see BoneMeshSource): parentJoint → origin,
/// the first child joint's x → bone length (x scale), y scaled by the height, z by the width
/// (or widthFromHeight × height); for Side::Right bones the geometry is reflected in z and the
/// triangles are turned back to face outwards. `length` overrides the x extent (the tail tip
/// spans three vertebrae).
Mesh fitBoneModel(const BoneModel& model, const Bone& bone, std::optional<double> length = {});

/// The BoneMeshSource of skeletonToScene for a skeleton at a resolution: Box → boneBoxMesh;
/// Low/High → each bone's model from `library` fitted to its box (modelForBone, fitBoneModel),
/// the tail tip stretched over the last three tail vertebrae. The returned function refers to
/// `skeleton` and `library`, which must outlive it.
BoneMeshSource boneMeshSource(const Skeleton& skeleton, const BoneLibrary& library,
                              BoneResolution resolution, std::string_view headKind);

/// The skeleton's scene (skeletonToScene) with its bones at `resolution`: boxes, or the models
/// of `library` (nullptr = BoneLibrary::builtin(resolution)) fitted by boneMeshSource. Throws
/// Error for an unknown head kind or a library without the models.
Scene skeletonSceneAt(const Skeleton& skeleton, BoneResolution resolution,
                      std::string_view headKind, const BoneLibrary* library = nullptr);

}  // namespace ramus
