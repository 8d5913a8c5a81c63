// Comparing meshes field by field in tests (Mesh has no operator==).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "ramus/mesh.hpp"

namespace ramus::test {

/// Expects every field of `a` and `b` to be equal, one by one (failures name `label`).
inline void expectSameMesh(const Mesh& a, const Mesh& b, const std::string& label) {
    SCOPED_TRACE(label);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.tangents, b.tangents);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.joints, b.joints);
    EXPECT_EQ(a.weights, b.weights);
    ASSERT_EQ(a.attributes.size(), b.attributes.size());
    for (std::size_t i = 0; i < a.attributes.size(); ++i) {
        EXPECT_EQ(a.attributes[i].name, b.attributes[i].name);
        EXPECT_EQ(a.attributes[i].components, b.attributes[i].components);
        EXPECT_EQ(a.attributes[i].values, b.attributes[i].values);
    }
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.primitives.size(), b.primitives.size());
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        EXPECT_EQ(a.primitives[i].firstIndex, b.primitives[i].firstIndex);
        EXPECT_EQ(a.primitives[i].indexCount, b.primitives[i].indexCount);
        EXPECT_EQ(a.primitives[i].material, b.primitives[i].material);
        EXPECT_EQ(a.primitives[i].name, b.primitives[i].name);
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_TRUE(sameMaterial(a.materials[i], b.materials[i]));
    }
}

}  // namespace ramus::test
