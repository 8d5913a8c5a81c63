#include "ramus/scene.hpp"

namespace ramus {

Mat4 Scene::worldTransform(int node) const {
    Mat4 world = Mat4::Identity();
    for (int i = node; i >= 0; i = nodes[static_cast<std::size_t>(i)].parent) {
        const SceneNode& n = nodes[static_cast<std::size_t>(i)];
        Eigen::Affine3d local =
            Eigen::Translation3d(n.translation) * n.rotation * Eigen::Scaling(n.scale);
        world = local.matrix() * world;
    }
    return world;
}

Scene makeSingleMeshScene(Mesh mesh, std::string nodeName) {
    Scene scene;
    scene.meshes.push_back(std::move(mesh));
    SceneNode node;
    node.name = std::move(nodeName);
    node.mesh = 0;
    scene.nodes.push_back(std::move(node));
    return scene;
}

}  // namespace ramus
