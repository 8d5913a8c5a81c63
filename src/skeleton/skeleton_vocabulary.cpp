// Names of the skeleton vocabulary, joint transforms, bone names and world transforms
// (include/ramus/skeleton.hpp; names per DESIGN.md).
#include <algorithm>
#include <charconv>
#include <cstdio>

#include "core/enum_names.hpp"
#include "ramus/skeleton.hpp"

namespace ramus {
namespace {

using detail::nameOf;
using detail::parseName;

constexpr std::array<std::string_view, kBoneKindCount> kBoneKindNames = {
    "root",    "vertebra", "rib",    "skull", "scapula", "upper_arm",
    "forearm", "hand",     "pelvis", "thigh", "shank",   "foot"};
constexpr std::array<std::string_view, 3> kSideNames = {"center", "left", "right"};
constexpr std::array<std::string_view, 4> kRegionNames = {"", "neck", "back", "tail"};
constexpr std::array<std::string_view, 5> kLimbKindNames = {"none", "leg", "wing", "arm", "fin"};
constexpr std::array<std::string_view, kAttachmentCount> kAttachmentNames = {
    "hip", "shoulder", "hip2", "shoulder2", "neck", "neck2"};
constexpr std::array<std::string_view, 3> kNeckShoulderNames = {"allowed", "forced", "forbidden"};
constexpr std::array<std::string_view, 2> kSpacingNames = {"arc_length", "parameter"};

Mat3 rotationAbout(const Vec3& axis, double degrees) {
    return Eigen::AngleAxisd(degToRad(degrees), axis.normalized()).toRotationMatrix();
}

}  // namespace

std::string_view boneKindName(BoneKind kind) { return nameOf(kBoneKindNames, kind); }
std::optional<BoneKind> parseBoneKind(std::string_view name) {
    return parseName<BoneKind>(kBoneKindNames, name);
}
std::string_view sideName(Side side) { return nameOf(kSideNames, side); }
std::string_view spineRegionName(SpineRegion region) { return nameOf(kRegionNames, region); }
std::string_view limbKindName(LimbKind kind) { return nameOf(kLimbKindNames, kind); }
std::optional<LimbKind> parseLimbKind(std::string_view name) {
    return parseName<LimbKind>(kLimbKindNames, name);
}
std::string_view attachmentName(Attachment attachment) {
    return nameOf(kAttachmentNames, attachment);
}
std::optional<Attachment> parseAttachment(std::string_view name) {
    return parseName<Attachment>(kAttachmentNames, name);
}
std::string_view neckShoulderName(NeckShoulder value) { return nameOf(kNeckShoulderNames, value); }
std::optional<NeckShoulder> parseNeckShoulder(std::string_view name) {
    return parseName<NeckShoulder>(kNeckShoulderNames, name);
}
std::string_view spineSpacingName(SpineSpacing spacing) { return nameOf(kSpacingNames, spacing); }
std::optional<SpineSpacing> parseSpineSpacing(std::string_view name) {
    return parseName<SpineSpacing>(kSpacingNames, name);
}

bool isFrontAttachment(Attachment attachment) {
    return attachment != Attachment::Hip && attachment != Attachment::Hip2;
}

bool attachmentAccepts(Attachment attachment, LimbKind kind) {
    switch (kind) {
        case LimbKind::None:
        case LimbKind::Fin:
            return true;
        case LimbKind::Leg:
            return attachment != Attachment::Neck && attachment != Attachment::Neck2;
        case LimbKind::Wing:
        case LimbKind::Arm:
            return isFrontAttachment(attachment);
    }
    return false;
}

Mat4 Joint::transform() const {
    Mat3 rotation = rest;
    for (int i = 0; i < dofCount; ++i)
        rotation = rotation * rotationAbout(dofs[i].axis, dofs[i].angleDeg);
    Mat4 result = Mat4::Identity();
    result.topLeftCorner<3, 3>() = rotation;
    result.topRightCorner<3, 1>() = position;
    return result;
}

std::string Bone::name() const {
    std::string result(boneKindName(kind));
    const bool limbOrGirdle = limb != LimbKind::None;
    if (region != SpineRegion::None) {
        result += '_';
        result += spineRegionName(region);
    } else if (limbOrGirdle && attachment != Attachment::Hip &&
               attachment != Attachment::Shoulder) {
        result += '_';
        result += attachmentName(attachment);
    }
    if (index > 0) {  // "_%02d"
        char digits[16] = {'_', '0'};
        char* first = index < 10 ? digits + 2 : digits + 1;
        const char* end = std::to_chars(first, digits + sizeof digits, index).ptr;
        result.append(digits, static_cast<std::size_t>(end - digits));
    }
    if (side == Side::Left) result += "_L";
    if (side == Side::Right) result += "_R";
    return result;
}

std::vector<Mat4> Skeleton::worldTransforms() const {
    std::vector<Mat4> world(bones.size());
    for (std::size_t i = 0; i < bones.size(); ++i) {
        const Mat4 local = bones[i].joint.transform();
        const int parent = bones[i].parent;
        world[i] = parent < 0 ? local : Mat4(world[static_cast<std::size_t>(parent)] * local);
    }
    return world;
}

}  // namespace ramus
