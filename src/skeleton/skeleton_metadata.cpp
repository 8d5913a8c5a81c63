// Skeleton metadata files (docs/skeleton.md "Metadata format"): the design that regenerates a
// skeleton, plus its bones for other tools.
//
// Based on: seed 000 §6.2 (save the PCA point, limb kinds per attachment point, joint angles,
// vertebra and rib counts and head kind, enough to regenerate the model exactly; the thesis
// wished for the bone hierarchy and joint limits in the file as well) and SPEC §G.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"
#include "skeleton/number_text.hpp"

namespace ramus {

namespace {

using Json = nlohmann::json;

// ---- writing ----------------------------------------------------------------------------------

std::string jsonString(std::string_view s) {
    return Json(std::string(s)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

// JSON has no NaN or infinity: a non-finite number (never produced for a valid design) becomes
// null, which loading rejects.
void appendNumber(std::string& out, double value) {
    if (std::isfinite(value)) {
        detail::appendShortest(out, value);
    } else {
        out += "null";
    }
}

void appendVector(std::string& out, const Vec3& v) {
    out += '[';
    for (int i = 0; i < 3; ++i) {
        if (i > 0) out += ", ";
        appendNumber(out, v[i]);
    }
    out += ']';
}

// Row-major: [[row 0], [row 1], …].
template <typename Matrix>
void appendMatrix(std::string& out, const Matrix& m) {
    out += '[';
    for (int r = 0; r < m.rows(); ++r) {
        out += r > 0 ? ", [" : "[";
        for (int c = 0; c < m.cols(); ++c) {
            if (c > 0) out += ", ";
            appendNumber(out, m(r, c));
        }
        out += ']';
    }
    out += ']';
}

void appendFeatures(std::string& out, const SkeletonDesign& design) {
    out += "    \"feature_point\": [";
    for (int i = 0; i < design.featurePoint.size(); ++i) {
        if (i > 0) out += (i % 4 == 0) ? ",\n                      " : ", ";
        appendNumber(out, design.featurePoint[i]);
    }
    out += "],\n    \"features\": {";
    for (int i = 0; i < kFeatureCount && i < design.featurePoint.size(); ++i) {
        out += i > 0 ? ",\n      " : "\n      ";
        out += jsonString(featureName(i)) + ": ";
        appendNumber(out, unscaleFeatureValue(i, design.featurePoint[i]));
    }
    out += "\n    },\n";
}

void appendLimbs(std::string& out, const SkeletonDesign& design) {
    out += "    \"limbs\": {";
    for (int a = 0; a < kAttachmentCount; ++a) {
        if (a > 0) out += ", ";
        out += jsonString(attachmentName(static_cast<Attachment>(a))) + ": " +
               jsonString(limbKindName(design.limbs[a]));
    }
    out += "},\n    \"wing_angles\": {";
    bool first = true;
    for (int a = 0; a < kAttachmentCount; ++a) {
        if (design.limbs[a] != LimbKind::Wing) continue;
        const WingAngles& w = design.wingAngles[a];
        out += first ? "\n      " : ",\n      ";
        first = false;
        out += jsonString(attachmentName(static_cast<Attachment>(a))) + ": {\"shoulder_front\": ";
        appendNumber(out, w.shoulderFront);
        out += ", \"shoulder_side\": ";
        appendNumber(out, w.shoulderSide);
        out += ", \"elbow\": ";
        appendNumber(out, w.elbow);
        out += ", \"wrist\": ";
        appendNumber(out, w.wrist);
        out += '}';
    }
    out += first ? "},\n" : "\n    },\n";
}

void appendDesign(std::string& out, const SkeletonDesign& design) {
    out += "  \"design\": {\n";
    appendFeatures(out, design);
    out += "    \"vertebrae\": {\"neck\": " + std::to_string(design.neckVertebrae) +
           ", \"back_front\": " + std::to_string(design.frontBackVertebrae) +
           ", \"back_rear\": " + std::to_string(design.rearBackVertebrae) +
           ", \"tail\": " + std::to_string(design.tailVertebrae) + "},\n";
    out += "    \"ribs\": " + std::to_string(design.ribs) + ",\n";
    appendLimbs(out, design);
    out += "    \"heel_draw\": ";
    appendNumber(out, design.heelDraw);
    out += ",\n    \"head_kind\": " + jsonString(design.headKind) + ",\n";
    out += "    \"spacing\": " + jsonString(spineSpacingName(design.spacing)) + ",\n";
    out += "    \"grammar_seed\": \"" + std::to_string(design.grammarSeed) + "\",\n";
    out += "    \"metres_per_pixel\": ";
    appendNumber(out, design.metresPerPixel);
    out += "\n  },\n";
}

void appendJoint(std::string& out, const Joint& joint) {
    out += "        \"joint\": {\"position\": ";
    appendVector(out, joint.position);
    out += ", \"rest\": ";
    appendMatrix(out, joint.rest);
    out += ",\n                  \"dofs\": [";
    for (int d = 0; d < joint.dofCount && d < 2; ++d) {
        const JointDof& dof = joint.dofs[d];
        out += d > 0 ? ", {\"axis\": " : "{\"axis\": ";
        appendVector(out, dof.axis);
        out += ", \"angle\": ";
        appendNumber(out, dof.angleDeg);
        out += ", \"min\": ";
        appendNumber(out, dof.minDeg);
        out += ", \"max\": ";
        appendNumber(out, dof.maxDeg);
        out += '}';
    }
    out += "]}";
}

std::string nameOrNull(std::string_view name) { return name.empty() ? "null" : jsonString(name); }

void appendBone(std::string& out, const Bone& bone, const Mat4& world) {
    const bool hasLimb = bone.limb != LimbKind::None;
    out += "      {\"name\": " + jsonString(bone.name()) +
           ", \"kind\": " + jsonString(boneKindName(bone.kind)) +
           ", \"side\": " + jsonString(sideName(bone.side)) +
           ", \"region\": " + nameOrNull(spineRegionName(bone.region)) + ",\n";
    out += "        \"limb\": " + jsonString(limbKindName(bone.limb)) + ", \"attachment\": " +
           (hasLimb ? jsonString(attachmentName(bone.attachment)) : std::string("null")) +
           ", \"index\": " + std::to_string(bone.index) +
           ", \"parent\": " + std::to_string(bone.parent) +
           ", \"twin\": " + std::to_string(bone.twin) +
           ", \"double_joint\": " + (bone.doubleJoint ? "true" : "false") + ",\n";
    out += "        \"extents\": ";
    appendVector(out, bone.extents);
    out += ",\n        \"local\": ";
    appendMatrix(out, bone.joint.transform());
    out += ",\n        \"world\": ";
    appendMatrix(out, world);
    out += ",\n";
    appendJoint(out, bone.joint);
    out += '}';
}

void appendSkeleton(std::string& out, const Skeleton& skeleton) {
    out += "  \"skeleton\": {\n";
    out += "    \"frame\": {\"units\": \"px\", \"y_axis\": \"up\", \"head\": \"-x\", ";
    out += "\"left\": \"+z\"},\n    \"metres_per_pixel\": ";
    appendNumber(out, skeleton.metresPerPixel);
    out += ",\n    \"ground_height\": ";
    appendNumber(out, skeleton.groundHeight);
    out += ",\n    \"heel_probability\": ";
    appendNumber(out, skeleton.heelProbability);
    out += ",\n    \"heel_contact\": ";
    out += skeleton.heelContact ? "true" : "false";
    out += ",\n    \"word\": " + jsonString(skeleton.word) + ",\n    \"bones\": [";
    const std::vector<Mat4> world = skeleton.worldTransforms();
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        out += i > 0 ? ",\n" : "\n";
        appendBone(out, skeleton.bones[i], world[i]);
    }
    out += skeleton.bones.empty() ? "]\n  }\n" : "\n    ]\n  }\n";
}

}  // namespace

std::string skeletonMetadataJson(const SkeletonDesign& design, const Skeleton& skeleton,
                                 std::string_view name, std::uint64_t seed) {
    std::string out = "{\n  \"format\": \"ramus-skeleton\",\n  \"version\": ";
    out += std::to_string(kSkeletonMetadataVersion) + ",\n";
    out += "  \"name\": " + jsonString(name) + ",\n";
    out += "  \"seed\": \"" + std::to_string(seed) + "\",\n";
    appendDesign(out, design);
    appendSkeleton(out, skeleton);
    out += "}\n";
    return out;
}

void writeSkeletonMetadata(const std::string& path, const SkeletonDesign& design,
                           const Skeleton& skeleton, std::string_view name, std::uint64_t seed) {
    writeFileAtomic(path, skeletonMetadataJson(design, skeleton, name, seed));
}

}  // namespace ramus
