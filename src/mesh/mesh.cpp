#include "ramus/mesh.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>

namespace ramus {

bool sameMaterial(const Material& a, const Material& b) {
    return a.name == b.name && a.baseColor == b.baseColor && a.metallic == b.metallic &&
           a.roughness == b.roughness && a.doubleSided == b.doubleSided &&
           a.alphaMask == b.alphaMask && a.alphaCutoff == b.alphaCutoff &&
           a.baseColorTexture == b.baseColorTexture && a.normalTexture == b.normalTexture;
}

const VertexAttribute* findAttribute(const Mesh& mesh, std::string_view name) {
    for (const VertexAttribute& a : mesh.attributes) {
        if (a.name == name) return &a;
    }
    return nullptr;
}

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

// Appends `from` (a vector, const or about to be dropped) to `into`; an empty `into` takes a
// dropped vector whole instead of copying it (a tree asset's bark was copied into an empty mesh,
// then again when its leaves were appended: a quarter of BM_TreeAsset's time, page faults for
// the fresh copies included).
template <typename T, typename From>
void appendValues(std::vector<T>& into, From&& from) {
    if constexpr (!std::is_lvalue_reference_v<From>) {
        if (into.empty()) {
            into = std::move(from);
            return;
        }
    }
    into.insert(into.end(), from.begin(), from.end());
}

template <typename T, typename From>
void appendAttribute(std::vector<T>& into, From&& from, bool keep) {
    if (keep) {
        appendValues(into, std::forward<From>(from));
    } else {
        into.clear();
    }
}
// Custom attributes survive an append when both sides have them (same name and width) for all
// their vertices; an empty mesh takes the other's, and appending a mesh without vertices (e.g.
// a tree's leaves when it has none) keeps them: there is no vertex to lack them.
template <typename Other>
void appendCustomAttributes(Mesh& mesh, Other&& other, bool wasEmpty) {
    if (wasEmpty) {
        mesh.attributes = std::forward<Other>(other).attributes;
        return;
    }
    if (other.positions.empty()) return;
    const std::size_t vertexCount = mesh.positions.size();
    std::vector<VertexAttribute> kept;
    for (VertexAttribute& a : mesh.attributes) {
        const VertexAttribute* b = findAttribute(other, a.name);
        const auto width = static_cast<std::size_t>(a.components);
        if (b == nullptr || b->components != a.components ||
            a.values.size() != width * vertexCount ||
            b->values.size() != width * other.positions.size()) {
            continue;
        }
        a.values.insert(a.values.end(), b->values.begin(), b->values.end());
        kept.push_back(std::move(a));
    }
    mesh.attributes = std::move(kept);
}

// appendMesh for a mesh to copy from (const Mesh&) or to take arrays from (Mesh&&).
template <typename Other>
void appendMeshFrom(Mesh& mesh, Other&& other) {
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
    // Every size of `other` is read before its arrays may be taken.
    const bool normals = keep(mesh.normals.size(), other.normals.size());
    const bool tangents = keep(mesh.tangents.size(), other.tangents.size());
    const bool uvs = keep(mesh.uvs.size(), other.uvs.size());
    // Joints and weights only make sense together: keep both or neither.
    const bool skinned = keep(mesh.joints.size(), other.joints.size()) &&
                         keep(mesh.weights.size(), other.weights.size());
    appendAttribute(mesh.normals, std::forward<Other>(other).normals, normals);
    appendAttribute(mesh.tangents, std::forward<Other>(other).tangents, tangents);
    appendAttribute(mesh.uvs, std::forward<Other>(other).uvs, uvs);
    appendAttribute(mesh.joints, std::forward<Other>(other).joints, skinned);
    appendAttribute(mesh.weights, std::forward<Other>(other).weights, skinned);
    appendCustomAttributes(mesh, std::forward<Other>(other), wasEmpty);
    if (vertexBase == 0 && mesh.indices.empty()) {
        appendValues(mesh.indices, std::forward<Other>(other).indices);  // nothing to re-base
    } else {
        mesh.indices.reserve(mesh.indices.size() + other.indices.size());
        for (std::uint32_t i : other.indices) mesh.indices.push_back(i + vertexBase);
    }
    appendValues(mesh.positions, std::forward<Other>(other).positions);
    mesh.primitives = std::move(primitives);
}

}  // namespace

void appendMesh(Mesh& mesh, const Mesh& other) { appendMeshFrom(mesh, other); }

void appendMesh(Mesh& mesh, Mesh&& other) { appendMeshFrom(mesh, std::move(other)); }

std::uint32_t appendVertexCopy(Mesh& to, const Mesh& from, std::uint32_t v) {
    const auto made = static_cast<std::uint32_t>(to.positions.size());
    auto copy = [&](auto& into, const auto& values) {
        if (values.empty()) return;
        auto value = values[v];  // a copy first: `into` may be `values`, and grow
        into.push_back(value);
    };
    copy(to.positions, from.positions);
    copy(to.normals, from.normals);
    copy(to.tangents, from.tangents);
    copy(to.uvs, from.uvs);
    copy(to.joints, from.joints);
    copy(to.weights, from.weights);
    for (std::size_t a = 0; a < from.attributes.size(); ++a) {
        const auto width = static_cast<std::size_t>(from.attributes[a].components);
        const std::vector<float>& values = from.attributes[a].values;
        std::vector<float>& into = to.attributes[a].values;
        for (std::size_t i = 0; i < width; ++i) {
            const float value = values[width * v + i];  // as in copy()
            into.push_back(value);
        }
    }
    return made;
}

void removeUnusedVertices(Mesh& mesh) {
    const std::size_t count = mesh.positions.size();
    std::vector<std::uint32_t> remap(count, 0);
    for (std::uint32_t i : mesh.indices) remap[i] = 1;
    // Used vertices come in long runs (whole rings): each run is moved down array by array.
    auto moveRun = [](auto& values, std::size_t width, std::size_t from, std::size_t to,
                      std::size_t run) {
        if (values.empty() || from == to) return;
        const auto begin = values.begin() + static_cast<std::ptrdiff_t>(width * from);
        std::copy(begin, begin + static_cast<std::ptrdiff_t>(width * run),
                  values.begin() + static_cast<std::ptrdiff_t>(width * to));  // to < from
    };
    std::uint32_t kept = 0;
    for (std::size_t i = 0; i < count;) {
        if (remap[i] == 0) {
            ++i;
            continue;
        }
        std::size_t end = i;
        for (; end < count && remap[end] != 0; ++end) {
            remap[end] = kept + static_cast<std::uint32_t>(end - i);
        }
        const std::size_t run = end - i;
        moveRun(mesh.positions, 1, i, kept, run);
        moveRun(mesh.normals, 1, i, kept, run);
        moveRun(mesh.tangents, 1, i, kept, run);
        moveRun(mesh.uvs, 1, i, kept, run);
        moveRun(mesh.joints, 1, i, kept, run);
        moveRun(mesh.weights, 1, i, kept, run);
        for (VertexAttribute& a : mesh.attributes) {
            moveRun(a.values, static_cast<std::size_t>(a.components), i, kept, run);
        }
        kept += static_cast<std::uint32_t>(run);
        i = end;
    }
    for (std::uint32_t& i : mesh.indices) i = remap[i];
    auto shrink = [&](auto& values) {
        if (!values.empty()) values.resize(kept);
    };
    shrink(mesh.positions);
    shrink(mesh.normals);
    shrink(mesh.tangents);
    shrink(mesh.uvs);
    shrink(mesh.joints);
    shrink(mesh.weights);
    for (VertexAttribute& a : mesh.attributes) {
        a.values.resize(static_cast<std::size_t>(a.components) * kept);
    }
}

void mergePrimitivesByMaterial(Mesh& mesh) {
    if (mesh.primitives.empty()) return;
    // Distinct materials in first-use order; each primitive's group.
    std::vector<Material> materials;
    std::vector<std::uint32_t> group(mesh.primitives.size());
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const std::uint32_t m = mesh.primitives[p].material;
        const Material material = m < mesh.materials.size() ? mesh.materials[m] : Material{};
        std::size_t g = 0;
        while (g < materials.size() && !sameMaterial(materials[g], material)) ++g;
        if (g == materials.size()) materials.push_back(material);
        group[p] = static_cast<std::uint32_t>(g);
    }
    std::vector<std::uint32_t> indices;
    indices.reserve(mesh.indices.size());
    std::vector<MeshPrimitive> primitives;
    for (std::uint32_t g = 0; g < materials.size(); ++g) {
        MeshPrimitive merged{static_cast<std::uint32_t>(indices.size()), 0, g, {}};
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            if (group[p] != g) continue;
            const MeshPrimitive& prim = mesh.primitives[p];
            if (merged.name.empty()) merged.name = prim.name;
            indices.insert(indices.end(), mesh.indices.begin() + prim.firstIndex,
                           mesh.indices.begin() + prim.firstIndex + prim.indexCount);
            merged.indexCount += prim.indexCount;
        }
        primitives.push_back(std::move(merged));
    }
    mesh.indices = std::move(indices);
    mesh.primitives = std::move(primitives);
    mesh.materials = std::move(materials);
}

}  // namespace ramus
