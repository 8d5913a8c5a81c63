#include "ramus/mesh.hpp"

namespace ramus {

Aabb Mesh::bounds() const {
    Aabb box;
    for (const Vec3f& p : positions) box.add(p.cast<double>());
    return box;
}

namespace {
// Primitives of a mesh, with the implicit "one primitive over everything" made explicit.
std::vector<MeshPrimitive> explicitPrimitives(const Mesh& mesh) {
    if (!mesh.primitives.empty() || mesh.indices.empty()) return mesh.primitives;
    return {MeshPrimitive{0, static_cast<std::uint32_t>(mesh.indices.size()), 0, mesh.name}};
}

template <typename T>
void appendAttribute(std::vector<T>& into, const std::vector<T>& from, bool keep) {
    if (keep) {
        into.insert(into.end(), from.begin(), from.end());
    } else {
        into.clear();
    }
}
}  // namespace

void appendMesh(Mesh& mesh, const Mesh& other) {
    const bool wasEmpty = mesh.positions.empty();
    const auto vertexBase = static_cast<std::uint32_t>(mesh.positions.size());
    const auto indexBase = static_cast<std::uint32_t>(mesh.indices.size());
    // A mesh drawn without materials uses an implicit default: make it explicit first, so the
    // other mesh's material indices are re-based past it.
    if (mesh.materials.empty() && !mesh.indices.empty()) mesh.materials.push_back(Material{});
    const auto materialBase = static_cast<std::uint32_t>(mesh.materials.size());

    std::vector<MeshPrimitive> primitives = explicitPrimitives(mesh);
    for (MeshPrimitive p : explicitPrimitives(other)) {
        p.firstIndex += indexBase;
        p.material += materialBase;
        primitives.push_back(std::move(p));
    }
    mesh.materials.insert(mesh.materials.end(), other.materials.begin(), other.materials.end());
    if (other.materials.empty() && !other.indices.empty()) mesh.materials.push_back(Material{});

    auto keep = [&](std::size_t mine, std::size_t theirs) {
        return (wasEmpty || mine == vertexBase) && theirs == other.positions.size();
    };
    appendAttribute(mesh.normals, other.normals, keep(mesh.normals.size(), other.normals.size()));
    appendAttribute(mesh.tangents, other.tangents,
                    keep(mesh.tangents.size(), other.tangents.size()));
    appendAttribute(mesh.uvs, other.uvs, keep(mesh.uvs.size(), other.uvs.size()));
    // Joints and weights only make sense together: keep both or neither.
    const bool skinned = keep(mesh.joints.size(), other.joints.size()) &&
                         keep(mesh.weights.size(), other.weights.size());
    appendAttribute(mesh.joints, other.joints, skinned);
    appendAttribute(mesh.weights, other.weights, skinned);
    mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
    mesh.indices.reserve(mesh.indices.size() + other.indices.size());
    for (std::uint32_t i : other.indices) mesh.indices.push_back(i + vertexBase);
    mesh.primitives = std::move(primitives);
}

}  // namespace ramus
