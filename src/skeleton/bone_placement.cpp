// Positions the terminals of the bone grammar: the root on the back, vertebrae chained along
// the spine, ribs, skull, girdles and limb bones (center and left side only).
//
// Based on: seed 000 §5.2 (bones as boxes in their own frames, joints in the parent's frame,
// the zero-size root in the middle of the back), §5.3 (vertebrae on the curve, each as long as
// the chord between consecutive samples; ribs on consecutive back vertebrae from the front),
// §5.4 "Positionierung der terminalen Elemente" (ribs, shoulder blades and pelvis attached to
// their vertebrae, the skull at the end of the neck, limb lengths from q, every other extent a
// free choice); SPEC §F.
//
// Free choices (the thesis fixes them "relatively arbitrarily in the code", §5.4), all in px of
// the 1000 px annotation frame, with B = the back's arc length:
// - vertebra thickness T = clamp(B / 40, 3, 20) (the thesis: 10 px; B / 40 gives 10 px on a
//   400 px back), tail vertebrae tapering linearly to 0.4 T at the tip;
// - body depth at a vertebra D(y) = clamp(0.4 y, 2T, 0.4 B), y its height above the bottom edge
//   the animals stand on (seed 000 §7.4.1); ribs are D long (the thesis: up to 100 px) times a
//   taper from 1 at the shoulder to 0.5 at the hip, hang from the middle of their vertebra
//   tilted 25° outwards from straight down, 0.5 T thick;
// - skull 1.2 D(shoulder) long, 0.5 of that high, 0.45 wide, pointing along (neck's end
//   direction + 2 × forward-20°-down), normalized;
// - scapula 0.5 × upper arm, pelvis 0.5 × thigh, each clamped to [T, 0.3 B], on the distal
//   end of their vertebra, 0.35 D (≥ T) to the side (1.5 T on the neck); the scapula points
//   down and 20° forward, the pelvis down and 30° back; the double pelvis holds its two hip
//   joints 3 thigh thicknesses apart along its y axis (Hip in front, Hip2 behind);
// - limb bones as long as the feature point says, at least kMinLimbBoneLength = 1 px (sampled
//   lengths can be ≤ 0), 0.12 × their length thick, clamped to [0.25 T, 1.5 T].
#include <algorithm>
#include <cmath>

#include "ramus/error.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

constexpr double kMinLimbBoneLength = 1.0;
constexpr double kRibTiltDeg = 25.0;
constexpr double kScapulaAngleDeg = -110.0;  // x axis: down, 20° towards the head (−x)
constexpr double kPelvisAngleDeg = -60.0;    // x axis: down, 30° towards the tail (+x)
constexpr double kSkullDownDeg = 20.0;
constexpr std::uint64_t kGrammarStream = 0x6772616d6d6172ULL;

struct Proportions {
    double back = 0.0;       // B
    double thickness = 0.0;  // T
    double depth(double height) const {
        return std::clamp(0.4 * height, 2.0 * thickness, std::max(0.4 * back, 2.0 * thickness));
    }
};

Mat4 frame(const Vec3& origin, const Mat3& rotation) {
    Mat4 m = Mat4::Identity();
    m.topLeftCorner<3, 3>() = rotation;
    m.topRightCorner<3, 1>() = origin;
    return m;
}

Mat3 rotationZ(double radians) { return Eigen::AngleAxisd(radians, Vec3::UnitZ()).matrix(); }

Vec3 lifted(const Vec2& p) { return {p.x(), p.y(), 0.0}; }

// parent⁻¹ · child for rigid transforms.
Mat4 relative(const Mat4& parent, const Mat4& child) {
    const Mat3 rt = parent.topLeftCorner<3, 3>().transpose();
    Mat4 m = Mat4::Identity();
    m.topLeftCorner<3, 3>() = rt * child.topLeftCorner<3, 3>();
    m.topRightCorner<3, 1>() = rt * (child.topRightCorner<3, 1>() - parent.topRightCorner<3, 1>());
    return m;
}

Limb limbOf(BoneKind kind) {
    switch (kind) {
        case BoneKind::UpperArm:
            return Limb::UpperArm;
        case BoneKind::Forearm:
            return Limb::Forearm;
        case BoneKind::Hand:
            return Limb::Hand;
        case BoneKind::Thigh:
            return Limb::Thigh;
        case BoneKind::Shank:
            return Limb::Shank;
        default:
            return Limb::Foot;
    }
}

bool isLimbBone(BoneKind kind) {
    return kind == BoneKind::UpperArm || kind == BoneKind::Forearm || kind == BoneKind::Hand ||
           kind == BoneKind::Thigh || kind == BoneKind::Shank || kind == BoneKind::Foot;
}

SpineRegion regionOf(SpineSection section) {
    switch (section) {
        case SpineSection::Neck:
            return SpineRegion::Neck;
        case SpineSection::FrontBack:
        case SpineSection::RearBack:
            return SpineRegion::Back;
        case SpineSection::Tail:
            return SpineRegion::Tail;
        default:
            return SpineRegion::None;
    }
}

class Placer {
public:
    Placer(const SkeletonDesign& design, const Spine& spine, const BoneSymbolTree& tree)
        : design_(design), spine_(spine), tree_(tree), features_(design.features()) {}

    Skeleton run();

private:
    void countVertebrae();
    void sampleSections();
    void placeNode(int n);
    Mat4 vertebraFrame(int n);
    Mat4 ribFrame(int n);
    Mat4 skullFrame(int n);
    Mat4 girdleFrame(int n);
    void placeLimbBone(int n);
    int spineAnchor(int n) const;
    Vec3 distalEnd(int n) const;
    Vec3 xAxis(int n) const { return world_[n].block<3, 1>(0, 0); }
    int count(SpineSection section) const { return counts_[static_cast<int>(section)]; }

    const SkeletonDesign& design_;
    const Spine& spine_;
    const BoneSymbolTree& tree_;
    SkeletonFeatures features_;
    Proportions prop_;
    std::vector<int> order_;  // vertebrae: 1-based position in their section from the root
    std::array<int, 5> counts_{};
    std::array<std::vector<Vec2>, 5> samples_;
    Vec2 rootPoint_ = Vec2::Zero();
    std::vector<Mat4> world_;
    Skeleton skeleton_;
};

Skeleton Placer::run() {
    prop_.back = spineLength(spine_, SpinePart::Back);
    prop_.thickness = std::clamp(prop_.back / 40.0, 3.0, 20.0);
    countVertebrae();
    sampleSections();
    world_.assign(tree_.nodes.size(), Mat4::Identity());
    skeleton_.bones.resize(tree_.nodes.size());
    for (std::size_t n = 0; n < tree_.nodes.size(); ++n) placeNode(static_cast<int>(n));
    skeleton_.word = boneWord(tree_);
    skeleton_.metresPerPixel = design_.metresPerPixel;
    return std::move(skeleton_);
}

void Placer::countVertebrae() {
    order_.assign(tree_.nodes.size(), 0);
    for (std::size_t n = 0; n < tree_.nodes.size(); ++n) {
        const BoneSymbolTree::Node& node = tree_.nodes[n];
        if (node.symbol != BoneSymbol::Vertebra) continue;
        const int p = node.parent;
        const bool continues = p >= 0 && tree_.nodes[p].symbol == BoneSymbol::Vertebra &&
                               tree_.nodes[p].section == node.section;
        order_[n] = continues ? order_[p] + 1 : 1;
        int& most = counts_[static_cast<int>(node.section)];
        most = std::max(most, order_[n]);
    }
}

void Placer::sampleSections() {
    struct Run {
        SpineSection section;
        SpinePart part;
        double from, to;
    };
    const double root = spineRootParameter(spine_, design_.spacing);
    rootPoint_ = spinePoint(spine_, SpinePart::Back, root);
    const std::array<Run, 4> runs = {Run{SpineSection::FrontBack, SpinePart::Back, root, 0.0},
                                     Run{SpineSection::RearBack, SpinePart::Back, root, 1.0},
                                     Run{SpineSection::Neck, SpinePart::Neck, 1.0, 0.0},
                                     Run{SpineSection::Tail, SpinePart::Tail, 0.0, 1.0}};
    for (const Run& run : runs) {
        const int n = count(run.section);
        if (n == 0) continue;
        std::vector<Vec2>& points = samples_[static_cast<int>(run.section)];
        points.reserve(static_cast<std::size_t>(n) + 1);
        for (double t : spineSamples(spine_, run.part, run.from, run.to, n, design_.spacing))
            points.push_back(spinePoint(spine_, run.part, t));
    }
}

void Placer::placeNode(int n) {
    const BoneSymbolTree::Node& node = tree_.nodes[n];
    Bone& bone = skeleton_.bones[n];
    bone.kind = boneSymbolKind(node.symbol);
    bone.parent = node.parent;
    bone.doubleJoint = node.symbol == BoneSymbol::Pelvis2;
    const bool center = bone.kind == BoneKind::Root || bone.kind == BoneKind::Vertebra ||
                        bone.kind == BoneKind::Skull;
    bone.side = center ? Side::Center : Side::Left;
    if (!center && bone.kind != BoneKind::Rib) {
        bone.attachment = node.attachment.value_or(Attachment::Hip);
        bone.limb = design_.limb(bone.attachment);
    }
    if (isLimbBone(bone.kind) && node.parent >= 0) return placeLimbBone(n);
    Mat4 world;
    switch (bone.kind) {
        case BoneKind::Root:
            world = frame(lifted(rootPoint_), Mat3::Identity());
            break;
        case BoneKind::Vertebra:
            world = vertebraFrame(n);
            break;
        case BoneKind::Rib:
            world = ribFrame(n);
            break;
        case BoneKind::Skull:
            world = skullFrame(n);
            break;
        default:
            world = girdleFrame(n);
            break;
    }
    world_[n] = world;
    const Mat4 local = node.parent >= 0 ? relative(world_[node.parent], world) : world;
    bone.joint.position = local.topRightCorner<3, 1>();
    bone.joint.rest = local.topLeftCorner<3, 3>();
}

Mat4 Placer::vertebraFrame(int n) {
    const BoneSymbolTree::Node& node = tree_.nodes[n];
    Bone& bone = skeleton_.bones[n];
    const std::vector<Vec2>& points = samples_[static_cast<int>(node.section)];
    const int k = order_[n];
    const Vec2 chord = points[k] - points[k - 1];
    const double length = chord.norm();
    Vec3 direction = node.section == SpineSection::RearBack || node.section == SpineSection::Tail
                         ? Vec3::UnitX()
                         : Vec3(-Vec3::UnitX());
    if (length > 1e-9) {
        direction = lifted(chord / length);
    } else if (node.parent >= 0 && tree_.nodes[node.parent].symbol == BoneSymbol::Vertebra) {
        direction = xAxis(node.parent);
    }
    double thickness = prop_.thickness;
    if (node.section == SpineSection::Tail)
        thickness *= 1.0 - 0.6 * (k - 1) / static_cast<double>(count(SpineSection::Tail));
    bone.region = regionOf(node.section);
    bone.index = node.section == SpineSection::RearBack ? count(SpineSection::FrontBack) + k : k;
    bone.extents = Vec3(length, thickness, thickness);
    return frame(lifted(points[k - 1]), rotationZ(std::atan2(direction.y(), direction.x())));
}

// The nearest vertebra among n and its ancestors; −1 when there is none.
int Placer::spineAnchor(int n) const {
    while (n >= 0 && tree_.nodes[n].symbol != BoneSymbol::Vertebra) n = tree_.nodes[n].parent;
    return n;
}

Vec3 Placer::distalEnd(int n) const {
    return (world_[n] * Vec4(skeleton_.bones[n].extents.x(), 0.0, 0.0, 1.0)).head<3>();
}

Mat4 Placer::ribFrame(int n) {
    Bone& bone = skeleton_.bones[n];
    const int vertebra = spineAnchor(n);
    const double thickness = prop_.thickness;
    Vec3 origin = Vec3(0.0, 0.0, 0.5 * thickness);
    double taper = 1.0;
    if (vertebra >= 0) {
        const Bone& v = skeleton_.bones[vertebra];
        bone.region = v.region;
        bone.index = v.index;
        origin += (world_[vertebra] * Vec4(0.5 * v.extents.x(), 0.0, 0.0, 1.0)).head<3>();
        // Position from the shoulder vertebra (0) to the hip vertebra (backCount).
        const int front = count(SpineSection::FrontBack);
        const int backCount = std::max(1, front + count(SpineSection::RearBack) - 1);
        const int fromShoulder = tree_.nodes[vertebra].section == SpineSection::FrontBack
                                     ? front - v.index
                                     : v.index - 1;
        taper = 1.0 - 0.5 * std::clamp(fromShoulder / static_cast<double>(backCount), 0.0, 1.0);
    }
    const double tilt = degToRad(kRibTiltDeg);
    Mat3 rotation;
    rotation.col(0) = Vec3(0.0, -std::cos(tilt), std::sin(tilt));
    rotation.col(1) = Vec3::UnitX();
    rotation.col(2) = Vec3(0.0, std::sin(tilt), std::cos(tilt));
    bone.extents = Vec3(prop_.depth(origin.y()) * taper, 0.5 * thickness, 0.5 * thickness);
    return frame(origin, rotation);
}

Mat4 Placer::skullFrame(int n) {
    const int parent = tree_.nodes[n].parent;
    const Vec3 origin = parent >= 0 ? distalEnd(parent) : lifted(spine_.points[0]);
    // Mostly forward and a little down, as skulls sit on a neck, turned a third of the way
    // towards the neck's own direction.
    const double down = degToRad(kSkullDownDeg);
    const Vec3 forward(-std::cos(down), -std::sin(down), 0.0);
    Vec3 direction = forward;
    if (parent >= 0) {
        const Vec3 mixed = xAxis(parent).normalized() + 2.0 * forward;
        if (mixed.norm() > 0.1) direction = mixed.normalized();
    }
    const double length = 1.2 * prop_.depth(spine_.points[3].y());
    skeleton_.bones[n].extents = Vec3(length, 0.5 * length, 0.45 * length);
    return frame(origin, rotationZ(std::atan2(direction.y(), direction.x())));
}

Mat4 Placer::girdleFrame(int n) {
    Bone& bone = skeleton_.bones[n];
    const int vertebra = spineAnchor(n);
    const bool scapula = bone.kind == BoneKind::Scapula;
    Vec3 origin = lifted(rootPoint_);
    double side = prop_.thickness;
    if (vertebra >= 0) {
        origin = distalEnd(vertebra);
        side = tree_.nodes[vertebra].section == SpineSection::Neck
                   ? 1.5 * prop_.thickness
                   : std::max(prop_.thickness, 0.35 * prop_.depth(origin.y()));
    }
    origin.z() = side;
    const double limb = features_.limb(scapula ? Limb::UpperArm : Limb::Thigh);
    const double length =
        std::clamp(0.5 * limb, prop_.thickness, std::max(prop_.thickness, 0.3 * prop_.back));
    bone.extents = Vec3(length, prop_.thickness, 0.5 * prop_.thickness);
    const double angle = degToRad(scapula ? kScapulaAngleDeg : kPelvisAngleDeg);
    return frame(origin, rotationZ(angle));
}

void Placer::placeLimbBone(int n) {
    const BoneSymbolTree::Node& node = tree_.nodes[n];
    Bone& bone = skeleton_.bones[n];
    const Bone& parent = skeleton_.bones[node.parent];
    const double length = std::max(features_.limb(limbOf(bone.kind)), kMinLimbBoneLength);
    const double thickness =
        std::clamp(0.12 * length, 0.25 * prop_.thickness, 1.5 * prop_.thickness);
    bone.extents = Vec3(length, thickness, thickness);
    bone.joint.position = Vec3(parent.extents.x(), 0.0, 0.0);
    if (parent.doubleJoint) {
        // Two hip joints side by side along the pelvis's y axis (towards the tail).
        const double spacing = 3.0 * thickness;
        bone.joint.position.y() =
            bone.attachment == Attachment::Hip2 ? 0.5 * spacing : -0.5 * spacing;
    }
    bone.joint.rest = Mat3::Identity();
    bone.joint.dofCount = 0;
    world_[n] = world_[node.parent] * bone.joint.transform();
}

}  // namespace

Skeleton placeBones(const SkeletonDesign& design, const Spine& spine,
                    const BoneRuleDictionary& rules) {
    const GrammarParams params = grammarParams(design, spine);
    Rng rng = Rng::forStream(design.grammarSeed, kGrammarStream);
    const BoneSymbolTree tree = deriveBoneTree(params, rules, rng);
    return Placer(design, spine, tree).run();
}

Skeleton placeBones(const SkeletonDesign& design, const Spine& spine) {
    return placeBones(design, spine, defaultBoneRules());
}

}  // namespace ramus::detail
