// Skeleton generation: bones and joints, the design of one skeleton (everything needed to
// regenerate it), and the stages that turn a design into a posed, mirrored skeleton
// (seed 000 ch. 5, ch. 6, §7.3–7.5; SPEC §F, §G).
//
// Internal frame: the thesis's annotation frame (seed 000 §7.4.1): px, y up, the body along x
// with the head towards −x, the grammar's side of the animal (its left) at +z, mirrored across
// the xy-plane to −z. Conversion to glTF (metres, Y up, front +Z, left +X, feet on y = 0)
// happens on export (skeleton_scene).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/math.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus {

// ---- vocabulary ------------------------------------------------------------------------------

/// The terminals of the bone grammar (seed 000 §5.4), English names as DESIGN.md lists them.
enum class BoneKind : std::uint8_t {
    Root,      ///< Wurzelknochen: zero-size bone at the middle of the back
    Vertebra,  ///< Wirbel
    Rib,       ///< Rippe
    Skull,     ///< Schädel
    Scapula,   ///< Schulterblatt
    UpperArm,  ///< Oberarm
    Forearm,   ///< Unterarm
    Hand,      ///< Hand
    Pelvis,  ///< Beckenknochen (and Beckenknochen2, the double pelvis of G′: see Bone::doubleJoint)
    Thigh,  ///< Oberschenkel
    Shank,  ///< Unterschenkel
    Foot,   ///< Fuß
};
inline constexpr int kBoneKindCount = 12;
/// "root", "vertebra", "rib", "skull", "scapula", "upper_arm", "forearm", "hand", "pelvis",
/// "thigh", "shank", "foot".
std::string_view boneKindName(BoneKind kind);
/// Inverse of boneKindName; nullopt for anything else.
std::optional<BoneKind> parseBoneKind(std::string_view name);

/// Which side of the mid-plane a bone is on. The grammar makes Center and Left bones; the
/// mirror makes the Right twins.
enum class Side : std::uint8_t { Center, Left, Right };
/// "center", "left", "right".
std::string_view sideName(Side side);

/// Part of the spine a vertebra (or a rib, by its vertebra) belongs to.
enum class SpineRegion : std::uint8_t { None, Neck, Back, Tail };
/// "", "neck", "back", "tail".
std::string_view spineRegionName(SpineRegion region);

/// Kind of a limb (seed 000 §5.5): legs touch the ground; arms are the other limbs that are
/// neither wings nor fins.
enum class LimbKind : std::uint8_t { None, Leg, Wing, Arm, Fin };
/// "none", "leg", "wing", "arm", "fin".
std::string_view limbKindName(LimbKind kind);
/// Inverse of limbKindName; nullopt for anything else.
std::optional<LimbKind> parseLimbKind(std::string_view name);

/// The points where a limb pair can attach (seed 000 §5.4, §5.5.3), in priority order.
enum class Attachment : std::uint8_t {
    Hip,        ///< e_b: pelvis on the last back vertebra
    Shoulder,   ///< e_s: shoulder girdle on the first (front) back vertebra
    Hip2,       ///< e_b2 (G′): second hip joint of the double pelvis; needs Hip
    Shoulder2,  ///< e_s2 (G′): shoulder girdle two vertebrae behind Shoulder; needs Shoulder
    Neck,       ///< e_h (G″): shoulder girdle on the neck, three vertebrae below the skull
    Neck2,  ///< e_h2 (G″): second neck girdle, two vertebrae further from the skull; needs Neck
};
inline constexpr int kAttachmentCount = 6;
/// "hip", "shoulder", "hip2", "shoulder2", "neck", "neck2".
std::string_view attachmentName(Attachment attachment);
/// Inverse of attachmentName; nullopt for anything else.
std::optional<Attachment> parseAttachment(std::string_view name);
/// Whether a limb kind may attach there (seed 000 §5.5.3): legs at hips and shoulders, wings
/// and arms at shoulders (including the neck girdles), fins anywhere, no legs on the neck.
/// LimbKind::None is accepted everywhere.
bool attachmentAccepts(Attachment attachment, LimbKind kind);
/// True for Shoulder, Shoulder2, Neck, Neck2 (the limb is a front limb: upper arm, forearm,
/// hand on a scapula); false for Hip, Hip2 (thigh, shank, foot on a pelvis).
bool isFrontAttachment(Attachment attachment);

// ---- bones -----------------------------------------------------------------------------------

/// One rotational degree of freedom of a joint. Angles in degrees; 0 = the child has the
/// orientation `Joint::rest` gives it (for limb joints: the parent's orientation, seed 000 §5.2).
struct JointDof {
    Vec3 axis = Vec3::UnitZ();  ///< unit axis in the joint frame (parent frame turned by rest)
    double angleDeg = 0.0;
    double minDeg = 0.0;  ///< limits, minDeg ≤ angleDeg ≤ maxDeg
    double maxDeg = 0.0;
};

/// The joint that connects a bone to its parent, expressed in the parent's frame (seed 000
/// §5.2): its position, the rest orientation and 0–2 degrees of freedom.
struct Joint {
    Vec3 position = Vec3::Zero();  ///< px, in the parent bone's frame
    Mat3 rest = Mat3::Identity();  ///< orientation at all angles 0, relative to the parent
    int dofCount = 0;              ///< 0, 1 or 2
    std::array<JointDof, 2> dofs{};

    /// The bone's local transform (bone frame → parent frame):
    /// translate(position) · rest · R(dofs[0]) · R(dofs[1]) for the used dofs.
    Mat4 transform() const;
};

/// A bone: a box in its own right-handed frame. The frame's origin is the joint to the parent
/// (the proximal end); the box spans x ∈ [0, extents.x] (the length, pointing to the child
/// joint), y ∈ [−extents.y/2, extents.y/2], z ∈ [−extents.z/2, extents.z/2]. (The thesis puts
/// the origin at a box corner; centring y and z puts the joint on the bone's axis, where
/// animation tools want it, and makes the mirror's T_kx a pure reflection.)
struct Bone {
    BoneKind kind = BoneKind::Root;
    Side side = Side::Center;
    SpineRegion region = SpineRegion::None;   ///< vertebrae and ribs
    LimbKind limb = LimbKind::None;           ///< girdle and limb bones: the limb they carry
    Attachment attachment = Attachment::Hip;  ///< girdle and limb bones (when limb != None)
    /// Vertebrae: 1-based number within the region, counted from the root outwards (back: the
    /// front half 1…w_rv from the root to the shoulder, the rear half continuing w_rv+1…);
    /// ribs: the number of their vertebra; 0 for other bones.
    int index = 0;
    int parent = -1;           ///< index into Skeleton::bones; −1 only for the root
    int twin = -1;             ///< the mirror twin (left ↔ right); −1 for center bones
    bool doubleJoint = false;  ///< a pelvis with two hip joints (Beckenknochen2, seed 000 §5.5.3)
    /// Hand/foot bones of legs: the foot stands steeper than 45° to the ground, so it gets a hoof
    /// rather than a hand-like foot (seed 000 §5.5.2, §5.6). Set by the leg placement.
    bool hoof = false;
    Joint joint;
    Vec3 extents = Vec3::Zero();  ///< px: length (x), height (y), width (z)

    /// Node name per DESIGN.md: <kind>[_<region>][_<index>][_L|_R], e.g. "vertebra_neck_03",
    /// "rib_back_02_L", "thigh_L"; limb and girdle bones at a secondary attachment carry it as
    /// the region ("thigh_hip2_L", "upper_arm_neck_R"); indices have two digits.
    std::string name() const;
};

/// A generated skeleton in the internal frame (see the file comment).
struct Skeleton {
    std::vector<Bone> bones;  ///< bones[0] is the root; parents come before their children
    /// The grammar's bracketed word: terminal names (boneKindName, "pelvis2" for the double
    /// pelvis) separated by spaces, "(" and ")" around children, e.g. "root ( vertebra … ) …".
    std::string word;
    double groundHeight = 0.0;      ///< y of the ground plane (px), seed 000 §5.5.1
    double heelProbability = 0.0;   ///< probability that heel/wrist touch the ground, §5.5.1
    bool heelContact = false;       ///< the legs stand on heel/wrist (drawn with that probability)
    double metresPerPixel = 0.001;  ///< scale from the px frame to metres (SkeletonDesign)

    /// Bone frame → world (internal frame), for every bone.
    std::vector<Mat4> worldTransforms() const;
};

// ---- inputs and design -----------------------------------------------------------------------

/// Second shoulder girdle on the neck (grammar G″, seed 000 §5.5.3, §6.1).
enum class NeckShoulder : std::uint8_t { Allowed, Forced, Forbidden };
/// "allowed", "forced", "forbidden".
std::string_view neckShoulderName(NeckShoulder value);
std::optional<NeckShoulder> parseNeckShoulder(std::string_view name);

/// How vertebrae are spaced along each spine Bézier (seed 000 §5.3).
enum class SpineSpacing : std::uint8_t {
    ArcLength,  ///< equal arc length (the thesis's wished improvement). Default.
    Parameter,  ///< at t = i/n, as the thesis's implementation does
};
/// "arc_length", "parameter".
std::string_view spineSpacingName(SpineSpacing spacing);
std::optional<SpineSpacing> parseSpineSpacing(std::string_view name);

/// The user's inputs (the thesis GUI, seed 000 fig. 6.1). An empty optional has no influence
/// (unlike 0). Counts are of single limbs (even numbers), as in the GUI.
struct SkeletonInputs {
    std::optional<int> legs;            ///< floored legs, even, 0…8 (condition legs = n/2)
    std::optional<int> wings;           ///< even ≥ 0 (condition wings = min(1, n/2))
    std::optional<int> arms;            ///< even ≥ 0, not a PCA condition
    std::optional<int> fins;            ///< even ≥ 0, not a PCA condition
    std::optional<double> neckYLength;  ///< px, condition on P0.y − P3.y
    std::optional<double> tailXLength;  ///< px, condition on P9.x − P6.x
    bool twoPerGirdle = false;          ///< allow G′ (two limb pairs per girdle)
    NeckShoulder neckShoulder = NeckShoulder::Allowed;
    std::string headKind;                ///< bone-library skull kind; empty = the default
    std::optional<std::string> example;  ///< construct from this species (English/German)
    SpineSpacing spacing = SpineSpacing::ArcLength;
    /// How widely random PCA points spread. Thesis (λ·N(0, 1), what the thesis's implementation
    /// and its figures use) is the default because it keeps random skeletons plausible; Model
    /// (N(0, λ), the distribution the thesis describes) gives wilder variety.
    SampleSpread spread = SampleSpread::Thesis;
    std::optional<double> heightMetres;  ///< overrides the size from the weight
    std::optional<double> lengthMetres;  ///< overrides the size from the weight
};

/// Wing joint angles in degrees, drawn once per wing from the thesis's wing intervals (SPEC §F):
/// shoulder front 130…170, shoulder side 0…45, elbow −45…0, wrist 0…90.
struct WingAngles {
    double shoulderFront = 150.0;
    double shoulderSide = 20.0;
    double elbow = -20.0;
    double wrist = 45.0;
    bool operator==(const WingAngles&) const = default;
};

/// Everything that determines one skeleton: the sampled PCA point and every random choice made
/// from it. buildSkeleton(design) is a pure function, so saving a design and loading it again
/// regenerates identical files (seed 000 §6.2).
struct SkeletonDesign {
    /// The 29 scaled features (skeleton_stats.hpp).
    Eigen::VectorXd featurePoint = Eigen::VectorXd::Zero(kFeatureCount);
    int neckVertebrae = 7;        ///< w_h: 0 without a neck, else ≥ 7 (10–30 with wings)
    int frontBackVertebrae = 13;  ///< w_rv ≥ 3: root → shoulder
    int rearBackVertebrae = 12;   ///< w_rh ≥ 1: root → hip
    int tailVertebrae = 0;        ///< w_s: 0 without a tail, else 5–20
    int ribs = 0;                 ///< r ∈ [0, w_rv + w_rh], from the shoulder vertebra back
    std::array<LimbKind, kAttachmentCount> limbs{};         ///< per Attachment
    std::array<WingAngles, kAttachmentCount> wingAngles{};  ///< used where limbs[a] == Wing
    /// A uniform number in [0, 1): the legs stand on heel/wrist iff it is below the heel
    /// probability, which only the built skeleton knows (seed 000 §5.5.1).
    double heelDraw = 0.5;
    std::string headKind;  ///< empty = the bone library's default skull
    SpineSpacing spacing = SpineSpacing::ArcLength;
    std::uint64_t grammarSeed = 0;  ///< picks among alternative grammar rules
    double metresPerPixel = 0.001;  ///< real size (see skeletonScaleFromWeight)

    LimbKind limb(Attachment a) const { return limbs[static_cast<int>(a)]; }
    SkeletonFeatures features() const { return fromFeaturePoint(featurePoint); }
};

// ---- pipeline --------------------------------------------------------------------------------

/// Draws a design from the inputs (seed 000 §5.1 steps 0–2, §5.3, §5.5, §6.1): the PCA point
/// (from the example species, or sampled under the conditions the inputs imply), vertebra and
/// rib counts, the limb kind at every attachment (user counts first, then v_b, v_f and the fin
/// rule in the thesis's priority legs, wings, arms, fins), wing angles, the heel draw and the
/// size. Throws Error for invalid inputs (odd or negative counts, legs > 8) and impossible
/// combinations (more limb pairs than attachments allow), naming the input.
SkeletonDesign designSkeleton(const SkeletonStats& stats, const SkeletonInputs& inputs, Rng& rng);

/// A variation of a design (seed 000 §6.3): each PCA coordinate from N(qᵢ, λᵢ/2), vertebra and
/// rib counts redrawn, and one attachment point changed (empty → a fitting limb with p = 0.5;
/// occupied → changed with p = 0.5, and then moved elsewhere with p = 0.2 when possible). The
/// user's counts in `inputs` (if any) still hold.
SkeletonDesign varySkeletonDesign(const SkeletonStats& stats, const SkeletonDesign& source,
                                  const SkeletonInputs& inputs, Rng& rng);

/// Builds the skeleton of a design: spine, grammar G″ (word and bone tree), limb poses and leg
/// placement, mirroring (seed 000 §5.1 steps 3–4). Pure and deterministic.
Skeleton buildSkeleton(const SkeletonDesign& design);

/// Metres per px from a weight (kg): the allometric rule fitted on the 44 species
/// (docs/skeleton.md).
double skeletonScaleFromWeight(double weightKg);

}  // namespace ramus
