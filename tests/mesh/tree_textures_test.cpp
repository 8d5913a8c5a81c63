// Procedural textures: deterministic, seamless across both borders, sizes, leaf silhouette.
#include "ramus/tree_textures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ramus/error.hpp"
#include "ramus/leaves.hpp"

namespace ramus {
namespace {

TEST(BarkTexture, IsDeterministicAndDependsOnTheSeed) {
    BarkTextureParams p;
    p.width = 64;
    p.height = 128;
    const Image a = makeBarkTexture(p), b = makeBarkTexture(p);
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_EQ(a.width, 64);
    EXPECT_EQ(a.height, 128);
    p.seed = 1;
    EXPECT_NE(makeBarkTexture(p).rgba, a.rgba);
}

// Seamless: the step across a border (last column → first, last row → first) is no larger
// than the steps between neighbours inside the image.
TEST(BarkTexture, TilesSeamlesslyInUAndV) {
    BarkTextureParams p;
    p.width = 128;
    p.height = 256;
    const std::vector<float> h = barkHeightField(p);
    const int w = p.width, hgt = p.height;
    auto at = [&](int x, int y) { return h[static_cast<std::size_t>(y) * w + x]; };
    float inside = 0.0f, acrossU = 0.0f, acrossV = 0.0f;
    for (int y = 0; y < hgt; ++y) {
        for (int x = 0; x + 1 < w; ++x)
            inside = std::max(inside, std::abs(at(x + 1, y) - at(x, y)));
        acrossU = std::max(acrossU, std::abs(at(0, y) - at(w - 1, y)));
    }
    float insideV = 0.0f;
    for (int x = 0; x < w; ++x) {
        for (int y = 0; y + 1 < hgt; ++y)
            insideV = std::max(insideV, std::abs(at(x, y + 1) - at(x, y)));
        acrossV = std::max(acrossV, std::abs(at(x, 0) - at(x, hgt - 1)));
    }
    EXPECT_LE(acrossU, inside);
    EXPECT_LE(acrossV, insideV);
    for (float v : h) {
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
    }
}

TEST(BarkTexture, NormalMapPointsOutOfTheSurface) {
    BarkTextureParams p;
    p.width = 32;
    p.height = 64;
    const Image n = makeBarkNormalMap(p);
    for (std::size_t i = 0; i < n.rgba.size(); i += 4) {
        const double x = n.rgba[i] / 127.5 - 1.0, y = n.rgba[i + 1] / 127.5 - 1.0,
                     z = n.rgba[i + 2] / 127.5 - 1.0;
        ASSERT_GT(z, 0.2);
        ASSERT_NEAR(std::sqrt(x * x + y * y + z * z), 1.0, 0.02);
    }
}

TEST(BarkTexture, SizesMustBePowersOfTwo) {
    BarkTextureParams p;
    p.width = 100;
    EXPECT_THROW(makeBarkTexture(p), Error);
    p.width = 8;
    EXPECT_THROW(makeBarkTexture(p), Error);
    p = BarkTextureParams{};
    p.furrows = 0;
    EXPECT_THROW(makeBarkTexture(p), Error);
    EXPECT_THROW(makeLeafTexture(300), Error);
}

TEST(LeafTexture, IsOpaqueInsideTheOutlineAndClearOutside) {
    const int size = 64;
    const Image leaf = makeLeafTexture(size);
    auto alpha = [&](int x, int y) {
        return leaf.rgba[(static_cast<std::size_t>(y) * size + x) * 4 + 3];
    };
    EXPECT_EQ(alpha(size / 2, size / 2), 255);  // the middle of the blade
    EXPECT_EQ(alpha(0, 0), 0);                  // corners
    EXPECT_EQ(alpha(size - 1, size - 1), 0);
    EXPECT_EQ(alpha(size / 4, 1), 0);  // beside the pointed tip
    // Row by row the opaque run is as wide as the outline says (±1 pixel).
    for (int py = 4; py < size - 4; ++py) {
        int opaque = 0;
        for (int px = 0; px < size; ++px) opaque += alpha(px, py) == 255;
        const double expected = 2.0 * leafOutlineHalfWidth(1.0 - (py + 0.5) / size) * size;
        EXPECT_NEAR(opaque, expected, 2.0);
    }
    const TreeTextures textures = makeTreeTextures();
    EXPECT_EQ(textures.barkAspect, 2.0);
    EXPECT_EQ(textures.barkColor->width, 256);
    EXPECT_EQ(textures.barkColor->height, 512);
}

}  // namespace
}  // namespace ramus
