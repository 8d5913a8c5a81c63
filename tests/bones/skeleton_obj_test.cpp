// Skeleton OBJ files (issue 6 item 4): one `o`/`g` group per bone, named like the bone's glTF
// node, its triangles with the bone kind's material.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "ramus/bones.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus {
namespace {

struct Group {
    std::vector<std::string> materials;
    std::size_t faces = 0;
};

/// Per `o` group of an OBJ text: its usemtl lines and face count, and the group order.
std::map<std::string, Group> groupsOf(const std::string& obj, std::vector<std::string>& order) {
    std::map<std::string, Group> groups;
    std::istringstream in(obj);
    std::string current;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("o ", 0) == 0) {
            current = line.substr(2);
            order.push_back(current);
        }
        if (line.rfind("usemtl ", 0) == 0) groups[current].materials.push_back(line.substr(7));
        if (line.rfind("f ", 0) == 0) ++groups[current].faces;
    }
    return groups;
}

std::string objOf(const Scene& scene, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ramus_bones_obj";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / (name + ".obj")).string();
    writeObj(scene, path);
    return readFile(path);
}

Skeleton quadruped() {
    SkeletonInputs inputs;
    inputs.legs = 4;
    Rng rng = Rng::forStream(5, 0);
    return buildSkeleton(designSkeleton(SkeletonStats::builtin(), inputs, rng));
}

TEST(SkeletonObj, EveryBoxedBoneIsOneGroupNamedLikeItsNode) {
    const Skeleton s = quadruped();
    std::vector<std::string> order;
    const std::map<std::string, Group> groups =
        groupsOf(objOf(skeletonSceneAt(s, BoneResolution::Box, ""), "box"), order);
    std::vector<std::string> expected;
    for (const Bone& bone : s.bones) {
        if (bone.extents.minCoeff() > 0.0) expected.push_back(bone.name());  // the root has none
    }
    EXPECT_EQ(order, expected);  // bone (joint) order, one group each
    for (const Bone& bone : s.bones) {
        if (bone.extents.minCoeff() <= 0.0) continue;
        const Group& g = groups.at(bone.name());
        EXPECT_EQ(g.faces, 12u) << bone.name();  // its box
        EXPECT_EQ(g.materials,
                  std::vector<std::string>{"bone_" + std::string(boneKindName(bone.kind))})
            << bone.name();
    }
    ASSERT_TRUE(groups.count("thigh_L"));
    EXPECT_EQ(groups.at("thigh_L").materials, std::vector<std::string>{"bone_thigh"});
}

TEST(SkeletonObj, BoneModelsKeepTheirTrianglesPerGroup) {
    const Skeleton s = quadruped();
    const BoneResolution low = BoneResolution::Low;
    const BoneLibrary& library = BoneLibrary::builtin(low);
    std::vector<std::string> order;
    const std::map<std::string, Group> groups =
        groupsOf(objOf(skeletonSceneAt(s, low, "carnivore"), "low"), order);
    std::size_t withModel = 0;
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        const std::optional<BoneModelKind> kind = modelForBone(s, static_cast<int>(i), "carnivore");
        if (!kind) {
            EXPECT_FALSE(groups.count(s.bones[i].name())) << s.bones[i].name();
            continue;
        }
        ++withModel;
        EXPECT_EQ(groups.at(s.bones[i].name()).faces,
                  library.model(*kind, low).mesh.triangleCount())
            << s.bones[i].name();
    }
    EXPECT_EQ(order.size(), withModel);
}

}  // namespace
}  // namespace ramus
