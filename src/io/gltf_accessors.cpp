// Based on: the glTF 2.0 specification (Khronos), §3.6.2 accessors: element layout, byte
// strides, normalized integers (§3.11 conversion rules), sparse accessors (§3.6.2.3).
#include "io/gltf_accessors.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "ramus/error.hpp"

namespace ramus::io {

namespace {

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        case TINYGLTF_TYPE_MAT4:
            return 16;  // inverse bind matrices: columns are 4-byte aligned for every type
        default:
            return 0;  // MAT2/MAT3 columns need padding for 1- and 2-byte types: not read
    }
}

std::size_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

template <typename T>
T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// One component as a number; normalized integers map to [0, 1] or [-1, 1] (glTF §3.11).
double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const double v = load<std::int8_t>(p);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? load<std::uint8_t>(p) / 255.0 : load<std::uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const double v = load<std::int16_t>(p);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return normalized ? load<std::uint16_t>(p) / 65535.0 : load<std::uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return load<std::uint32_t>(p);
        default:
            return load<float>(p);
    }
}

// The bytes of buffer view `view` from `offset`, checked to hold at least `needed` bytes.
const unsigned char* viewBytes(const Reader& r, int view, std::size_t offset, std::size_t needed) {
    if (view < 0 || view >= static_cast<int>(r.model.bufferViews.size())) {
        r.fail("buffer view " + std::to_string(view) + " does not exist");
    }
    const tinygltf::BufferView& v = r.model.bufferViews[view];
    if (v.buffer < 0 || v.buffer >= static_cast<int>(r.model.buffers.size())) {
        r.fail("buffer view " + std::to_string(view) + " refers to a missing buffer");
    }
    const std::vector<unsigned char>& data = r.model.buffers[v.buffer].data;
    if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset ||
        offset > v.byteLength || needed > v.byteLength - offset) {
        r.fail("buffer view " + std::to_string(view) + " is too short for the data it holds");
    }
    return data.data() + v.byteOffset + offset;
}

// Sparse accessors: replace the listed elements (glTF §3.6.2.3).
void applySparse(const Reader& r, const tinygltf::Accessor& a, int components,
                 std::vector<double>& out) {
    const auto count = static_cast<std::size_t>(std::max(a.sparse.count, 0));
    const int indexType = a.sparse.indices.componentType;
    const std::size_t indexSize = componentSize(indexType);
    const std::size_t valueSize = componentSize(a.componentType) * components;
    if (indexSize == 0 || indexType == TINYGLTF_COMPONENT_TYPE_FLOAT || count > a.count) {
        r.fail("sparse accessor '" + a.name + "' is malformed");
    }
    const unsigned char* indices = viewBytes(
        r, a.sparse.indices.bufferView,
        static_cast<std::size_t>(std::max(a.sparse.indices.byteOffset, 0)), count * indexSize);
    const unsigned char* values = viewBytes(
        r, a.sparse.values.bufferView,
        static_cast<std::size_t>(std::max(a.sparse.values.byteOffset, 0)), count * valueSize);
    for (std::size_t i = 0; i < count; ++i) {
        const double target = readComponent(indices + i * indexSize, indexType, false);
        if (target >= static_cast<double>(a.count)) r.fail("sparse accessor index out of range");
        const auto t = static_cast<std::size_t>(target);
        for (int c = 0; c < components; ++c) {
            out[t * components + c] =
                readComponent(values + i * valueSize + c * (valueSize / components),
                              a.componentType, a.normalized);
        }
    }
}

}  // namespace

const tinygltf::Accessor& accessorAt(const Reader& r, int index, const char* what) {
    if (index < 0 || index >= static_cast<int>(r.model.accessors.size())) {
        r.fail(std::string(what) + " accessor " + std::to_string(index) + " does not exist");
    }
    return r.model.accessors[index];
}

// All elements of accessor `index` as numbers (count × components), checked against the
// expected element type and the buffer bounds.
std::vector<double> readAccessor(const Reader& r, int index, int components, const char* what) {
    const tinygltf::Accessor& a = accessorAt(r, index, what);
    const std::size_t cs = componentSize(a.componentType);
    if (componentCount(a.type) != components || cs == 0) {
        r.fail(std::string(what) + " accessor " + std::to_string(index) + " has " +
               std::to_string(componentCount(a.type)) + " components; expected " +
               std::to_string(components));
    }
    const std::size_t elementSize = cs * components;
    std::size_t stride = elementSize;
    if (a.bufferView >= 0 && a.bufferView < static_cast<int>(r.model.bufferViews.size())) {
        stride = std::max(stride, r.model.bufferViews[a.bufferView].byteStride);
    }
    // Without a buffer view the elements are zeros (then replaced by sparse values): bound
    // their number, since no data in the file backs it.
    const std::size_t maxElements = a.bufferView >= 0
                                        ? std::numeric_limits<std::uint32_t>::max() / stride
                                        : std::size_t{1} << 24;
    if (a.count > maxElements || (a.bufferView < 0 && !a.sparse.isSparse && a.count > 0)) {
        r.fail(std::string(what) + " accessor " + std::to_string(index) + " has no valid data");
    }
    const unsigned char* base = nullptr;
    if (a.bufferView >= 0 && a.count > 0) {
        base = viewBytes(r, a.bufferView, a.byteOffset, stride * (a.count - 1) + elementSize);
    }
    std::vector<double> out(a.count * components, 0.0);
    if (base != nullptr) {
        for (std::size_t i = 0; i < a.count; ++i) {
            for (int c = 0; c < components; ++c) {
                out[i * components + c] =
                    readComponent(base + i * stride + c * cs, a.componentType, a.normalized);
            }
        }
    }
    if (a.sparse.isSparse) applySparse(r, a, components, out);
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (!std::isfinite(out[i])) {
            r.fail(std::string(what) + " accessor " + std::to_string(index) + " element " +
                   std::to_string(i / components) + " is not a finite number");
        }
    }
    return out;
}

std::vector<std::uint32_t> readIndices(const Reader& r, const tinygltf::Primitive& p,
                                       std::size_t vertexCount) {
    std::vector<std::uint32_t> indices;
    if (p.indices < 0) {  // non-indexed: vertices in order
        indices.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) indices[i] = static_cast<std::uint32_t>(i);
        return indices;
    }
    if (accessorAt(r, p.indices, "indices").componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        r.fail("indices accessor " + std::to_string(p.indices) +
               " holds floats; expected integers");
    }
    const std::vector<double> values = readAccessor(r, p.indices, 1, "indices");
    indices.reserve(values.size());
    for (double v : values) {
        if (v < 0.0 || v >= static_cast<double>(vertexCount)) {
            r.fail("index " + std::to_string(static_cast<long long>(v)) +
                   " is out of range; expected < " + std::to_string(vertexCount));
        }
        indices.push_back(static_cast<std::uint32_t>(v));
    }
    return indices;
}

}  // namespace ramus::io
