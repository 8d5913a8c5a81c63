// What exporters and the preview renderer consume: meshes placed by a node hierarchy.
#pragma once

#include <string>
#include <vector>

#include "ramus/math.hpp"
#include "ramus/mesh.hpp"

namespace ramus {

/// A node of the scene hierarchy (glTF node). Its transform is relative to its parent.
struct SceneNode {
    std::string name;
    int parent = -1;  ///< index into Scene::nodes; parents come before children
    Vec3 translation = Vec3::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    Vec3 scale = Vec3::Ones();
    int mesh = -1;           ///< index into Scene::meshes, or -1
    std::string extrasJson;  ///< a JSON object written as the node's "extras", or empty
    /// extrasJson is a compact, valid JSON object made by a generator (e.g. a skeleton's bone
    /// extras): the GLB writer copies it without validating it again (builds with
    /// RAMUS_ENABLE_ASSERTS still check it). Leave false for text from anywhere else.
    bool extrasCompact = false;
    /// Index into Scene::skins that deforms this node's mesh, or -1. A skinned node must hold a
    /// mesh with joints and weights; glTF ignores its transform, so keep it a root node with the
    /// identity transform (the validator warns otherwise).
    int skin = -1;
};

/// A glTF skin (§3.7.3): the joint nodes that deform a mesh and their inverse bind matrices.
/// A vertex's position is Σ weightᵢ · world(joints[jointᵢ]) · inverseBindMatrices[jointᵢ] · p.
struct Skin {
    std::string name;
    std::vector<int> joints;  ///< node indices, distinct; Mesh::joints index into this list
    int skeleton = -1;        ///< the joints' common root node (an ancestor of all), or -1
    /// One per joint (world → joint space at bind time), bottom row (0, 0, 0, 1); empty means
    /// identity matrices.
    std::vector<Mat4> inverseBindMatrices;
};

/// A scene in glTF's conventions: Y up, metres, front +Z. Empty nodes + one mesh means the
/// exporter makes one root node for the mesh.
struct Scene {
    std::vector<Mesh> meshes;
    std::vector<SceneNode> nodes;
    std::vector<Skin> skins;  ///< referenced by SceneNode::skin; empty for rigid scenes
    std::string generator = "ramus";
    std::string extrasJson;  ///< a JSON object written as the scene's "extras", or empty

    /// World transform of node i (parent chain applied).
    Mat4 worldTransform(int node) const;
};

/// A scene with one node holding `mesh`.
Scene makeSingleMeshScene(Mesh mesh, std::string nodeName = "tree");

}  // namespace ramus
