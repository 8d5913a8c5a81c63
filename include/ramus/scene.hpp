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
};

/// A scene in glTF's conventions: Y up, metres, front +Z. Empty nodes + one mesh means the
/// exporter makes one root node for the mesh.
struct Scene {
    std::vector<Mesh> meshes;
    std::vector<SceneNode> nodes;
    std::string generator = "ramus";
    std::string extrasJson;  ///< a JSON object written as the scene's "extras", or empty

    /// World transform of node i (parent chain applied).
    Mat4 worldTransform(int node) const;
};

/// A scene with one node holding `mesh`.
Scene makeSingleMeshScene(Mesh mesh, std::string nodeName = "tree");

}  // namespace ramus
