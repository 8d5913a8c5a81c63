// Internal: decoding glTF accessors (tinygltf's model) into plain numbers, with bounds checks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/tinygltf_config.hpp"
#include "ramus/error.hpp"

namespace ramus::io {

/// The model being read and the path used in error messages.
struct Reader {
    const tinygltf::Model& model;
    const std::string& path;

    [[noreturn]] void fail(const std::string& what) const { throw Error(path + ": " + what); }
};

/// accessors[index], or Error naming `what` when it does not exist.
const tinygltf::Accessor& accessorAt(const Reader& r, int index, const char* what);

/// All elements of accessor `index` as numbers (count × components, row by row): float,
/// normalized or plain integer components, byte strides and sparse substitution handled.
/// MAT4 elements have 16 components (column-major). Throws Error when the element type
/// differs from `components` or the data runs past its buffer view or buffer.
std::vector<double> readAccessor(const Reader& r, int index, int components, const char* what);

/// The primitive's vertex indices (0..vertexCount-1 in order when it has none); Error for float
/// indices or indices >= vertexCount.
std::vector<std::uint32_t> readIndices(const Reader& r, const tinygltf::Primitive& p,
                                       std::size_t vertexCount);

}  // namespace ramus::io
