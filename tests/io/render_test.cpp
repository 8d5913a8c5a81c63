#include "ramus/render.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/io_fixtures.hpp"
#include "ramus/error.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace ramus {
namespace {

using testing::makeCube;

struct Rgba {
    int r, g, b, a;
};

Rgba rgbaAt(const Image& image, int x, int y) {
    const std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
    return {p[0], p[1], p[2], p[3]};
}

bool isWhite(const Image& image, int x, int y) {
    const Rgba p = rgbaAt(image, x, y);
    return p.r == 255 && p.g == 255 && p.b == 255 && p.a == 255;
}

// Columns and rows that hold at least one non-background (non-white) pixel.
struct Coverage {
    int left = -1, right = -1, top = -1, bottom = -1;
    int width() const { return right - left + 1; }
    int height() const { return bottom - top + 1; }
};

Coverage coverage(const Image& image) {
    Coverage c;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (isWhite(image, x, y)) continue;
            if (c.left < 0 || x < c.left) c.left = x;
            if (x > c.right) c.right = x;
            if (c.top < 0) c.top = y;
            c.bottom = y;
        }
    }
    return c;
}

int coveredInColumn(const Image& image, int x) {
    int n = 0;
    for (int y = 0; y < image.height; ++y) n += isWhite(image, x, y) ? 0 : 1;
    return n;
}

int coveredInRow(const Image& image, int y) {
    int n = 0;
    for (int x = 0; x < image.width; ++x) n += isWhite(image, x, y) ? 0 : 1;
    return n;
}

Image render(const Scene& scene, View view, int size = 200) {
    RenderParams params;
    params.width = size;
    params.height = size;
    params.view = view;
    return renderScene(scene, params);
}

// A 4 × 1 × 0.25 box (x × y × z): each view sees a different aspect ratio.
Scene makeSlab() {
    Scene scene = makeSingleMeshScene(makeCube(0.5f), "slab");
    scene.nodes[0].scale = Vec3(4.0, 1.0, 0.25);
    return scene;
}

// A unit cube with a small cube on its front (+Z): shows which way the front faces.
Scene makeCubeWithNose() {
    Scene scene;
    scene.meshes = {makeCube(0.5f), makeCube(0.1f, {0.0f, 0.0f, 0.6f})};
    return scene;
}

TEST(Render, CubeCoversTheMiddleAndLeavesTheCornersBackground) {
    const Image image = render(makeSingleMeshScene(makeCube()), View::ThreeQuarter, 64);
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 64);
    ASSERT_EQ(image.rgba.size(), 64u * 64u * 4u);
    EXPECT_FALSE(isWhite(image, 32, 32));
    EXPECT_EQ(rgbaAt(image, 32, 32).a, 255);
    for (auto [x, y] : {std::pair{0, 0}, {63, 0}, {0, 63}, {63, 63}}) {
        EXPECT_TRUE(isWhite(image, x, y)) << x << "," << y;
    }
}

TEST(Render, FaceTowardTheCameraHasTheLitBaseColour) {
    // Front view sees the +Z face, normal (0, 0, 1) in camera space: intensity = 0.2 ambient
    // + 0.75·0.6046 (key) + 0.2·0.7035 (fill) = 0.7941; 0.8 · 0.7941 = 0.6353 linear
    // → sRGB 1.055·0.6353^(1/2.4) − 0.055 = 0.8183 → 209.
    const Image image = render(makeSingleMeshScene(makeCube()), View::Front, 64);
    const Rgba p = rgbaAt(image, 32, 32);
    EXPECT_NEAR(p.r, 209, 1);
    EXPECT_EQ(p.r, p.g);
    EXPECT_EQ(p.g, p.b);
}

TEST(Render, MaterialColourShowsInThePixels) {
    Mesh cube = makeCube();
    cube.materials = {Material{"red", {0.9f, 0.05f, 0.05f, 1.0f}}};
    const Rgba p = rgbaAt(render(makeSingleMeshScene(cube), View::ThreeQuarter, 64), 32, 32);
    EXPECT_GT(p.r, 150);
    EXPECT_LT(p.g, 100);
    EXPECT_LT(p.b, 100);
}

TEST(Render, FrontSideAndTopSeeTheSlabsThreeAspectRatios) {
    // 200 px with a 6 % margin on each side: the longer side spans 176 px.
    const Coverage front = coverage(render(makeSlab(), View::Front));
    EXPECT_NEAR(front.width(), 176, 2);
    EXPECT_NEAR(front.height(), 44, 2);  // 4 : 1
    const Coverage side = coverage(render(makeSlab(), View::Side));
    EXPECT_NEAR(side.width(), 44, 2);  // z : y = 0.25 : 1
    EXPECT_NEAR(side.height(), 176, 2);
    const Coverage top = coverage(render(makeSlab(), View::Top));
    EXPECT_NEAR(top.width(), 176, 2);  // x : z = 4 : 0.25
    EXPECT_NEAR(top.height(), 11, 2);
}

TEST(Render, SideViewShowsTheFrontOnTheRight) {
    const Image image = render(makeCubeWithNose(), View::Side);
    const Coverage c = coverage(image);
    const int nearRight = coveredInColumn(image, c.right - 2);
    const int nearLeft = coveredInColumn(image, c.left + 2);
    EXPECT_LT(nearRight, nearLeft / 3);  // the nose is a fifth of the cube's height
}

TEST(Render, TopViewShowsTheFrontAtTheBottom) {
    const Image image = render(makeCubeWithNose(), View::Top);
    const Coverage c = coverage(image);
    EXPECT_LT(coveredInRow(image, c.bottom - 2), coveredInRow(image, c.top + 2) / 3);
}

TEST(Render, ViewsGiveDifferentImages) {
    const Scene scene = makeCubeWithNose();
    const std::vector<Image> images = {render(scene, View::Side), render(scene, View::Front),
                                       render(scene, View::Top), render(scene, View::ThreeQuarter)};
    for (std::size_t i = 0; i < images.size(); ++i) {
        for (std::size_t j = i + 1; j < images.size(); ++j) {
            EXPECT_NE(images[i].rgba, images[j].rgba) << i << " vs " << j;
        }
    }
}

TEST(Render, EmptySceneIsBackgroundOnly) {
    RenderParams params;
    params.width = 40;
    params.height = 30;
    params.background = Vec4f(0.0f, 0.0f, 0.0f, 0.0f);
    const Image image = renderScene(Scene{}, params);
    EXPECT_EQ(image.rgba, std::vector<std::uint8_t>(40 * 30 * 4, 0));
    const Image white = renderScene(makeSingleMeshScene(Mesh{}), RenderParams{});
    EXPECT_EQ(white.rgba, std::vector<std::uint8_t>(800 * 800 * 4, 255));
}

TEST(Render, RenderingIsDeterministic) {
    const Scene scene = testing::makeHierarchyScene();
    EXPECT_EQ(render(scene, View::ThreeQuarter).rgba, render(scene, View::ThreeQuarter).rgba);
}

TEST(Render, BackFacesAreCulledUnlessTheMaterialIsDoubleSided) {
    Mesh tri;
    tri.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};  // clockwise seen from +Z
    tri.indices = {0, 1, 2};
    Scene scene = makeSingleMeshScene(tri);
    const Image culled = render(scene, View::Front, 32);
    EXPECT_EQ(coverage(culled).left, -1);
    scene.meshes[0].materials = {Material{"both", {0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 0.5f, true}};
    const Image shown = render(scene, View::Front, 32);
    EXPECT_GT(coverage(shown).width(), 20);
}

TEST(Render, SharedEdgesLeaveNoCracks) {
    // A flat 1 × 1 square facing the camera, cut into jittered triangles: every pixel inside
    // must get exactly the square's colour (no background through cracks).
    Mesh grid;
    const int n = 23;
    for (int y = 0; y <= n; ++y) {
        for (int x = 0; x <= n; ++x) {
            const bool border = x == 0 || y == 0 || x == n || y == n;
            const float jx = border ? 0.0f : 0.3f * std::sin(float(x * 7 + y * 13));
            const float jy = border ? 0.0f : 0.3f * std::cos(float(x * 11 + y * 5));
            grid.positions.emplace_back((x + jx) / n, (y + jy) / n, 0.0f);
        }
    }
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const auto i = static_cast<std::uint32_t>(y * (n + 1) + x);
            const std::uint32_t r = n + 1;
            grid.indices.insert(grid.indices.end(), {i, i + 1, i + r + 1, i, i + r + 1, i + r});
        }
    }
    const Image image = render(makeSingleMeshScene(grid), View::Front, 101);
    const Coverage c = coverage(image);
    const Rgba centre = rgbaAt(image, 50, 50);
    for (int y = c.top + 1; y < c.bottom; ++y) {
        for (int x = c.left + 1; x < c.right; ++x) {
            const Rgba p = rgbaAt(image, x, y);
            ASSERT_EQ(p.r, centre.r) << x << "," << y;
            ASSERT_EQ(p.a, 255) << x << "," << y;
        }
    }
}

TEST(Render, MirroredNodesStillShowTheirOutsides) {
    Scene mirrored = makeSingleMeshScene(makeCube());
    mirrored.nodes[0].scale = Vec3(-1.0, 1.0, 1.0);
    const Image a = render(makeSingleMeshScene(makeCube()), View::ThreeQuarter, 100);
    const Image b = render(mirrored, View::ThreeQuarter, 100);
    int different = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        different += std::abs(a.rgba[i] - b.rgba[i]) > 2;
    EXPECT_LT(different, 100) << "of " << a.rgba.size();
}

TEST(Render, AGlbReadBackRendersLikeTheSceneItWasWrittenFrom) {
    // The path of `ramus render`: GLB file → readGltf → renderScene → PNG.
    const Scene scene = testing::makeHierarchyScene();
    const std::string path = (testing::scratchDir("render_glb") / "tree.glb").string();
    writeGlb(scene, path);
    testing::exportForValidator(scene, "render_source");
    const Image direct = render(scene, View::ThreeQuarter);
    const Image viaFile = render(readGltf(path), View::ThreeQuarter);
    EXPECT_EQ(viaFile.rgba, direct.rgba);
}

TEST(Render, SizeOutOfRangeIsAnError) {
    RenderParams params;
    params.width = 0;
    EXPECT_THROW(renderScene(Scene{}, params), Error);
}

TEST(Png, EncodesASignedPngThatDecodesToTheSamePixels) {
    RenderParams params;
    params.width = 48;
    params.height = 24;
    const Image image = renderScene(makeSingleMeshScene(makeCube()), params);
    const std::string png = encodePng(image);
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n"));
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()),
                                            static_cast<int>(png.size()), &w, &h, &channels, 4);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(w, 48);
    EXPECT_EQ(h, 24);
    EXPECT_EQ(std::vector<std::uint8_t>(pixels, pixels + w * h * 4), image.rgba);
    stbi_image_free(pixels);
    EXPECT_EQ(encodePng(image), png);
}

TEST(Png, WritePngWritesTheEncodedBytes) {
    const Image image = renderScene(Scene{}, RenderParams{16, 16});
    const std::string path = (testing::scratchDir("png") / "empty.png").string();
    writePng(image, path);
    EXPECT_EQ(std::filesystem::file_size(path), encodePng(image).size());
}

TEST(Png, EmptyOrInconsistentImageIsAnError) {
    EXPECT_THROW(encodePng(Image{}), Error);
    EXPECT_THROW(encodePng(Image{2, 2, std::vector<std::uint8_t>(15)}), Error);
}

TEST(RenderOptions, ParsesEveryViewName) {
    EXPECT_EQ(parseView("side"), View::Side);
    EXPECT_EQ(parseView("front"), View::Front);
    EXPECT_EQ(parseView("top"), View::Top);
    EXPECT_EQ(parseView("three-quarter"), View::ThreeQuarter);
    EXPECT_EQ(parseView("threequarter"), View::ThreeQuarter);
    EXPECT_EQ(parseView("3q"), View::ThreeQuarter);
}

TEST(RenderOptions, UnknownViewListsTheAcceptedNames) {
    try {
        parseView("sideways");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "unknown view 'sideways'; expected one of side, front, top, three-quarter");
    }
}

TEST(RenderOptions, ParsesImageSizes) {
    const ImageSize a = parseImageSize("800x600");
    EXPECT_EQ(a.width, 800);
    EXPECT_EQ(a.height, 600);
    const ImageSize b = parseImageSize("16X8192");
    EXPECT_EQ(b.width, 16);
    EXPECT_EQ(b.height, 8192);
}

TEST(RenderOptions, ImageSizeOutsideTheRangeIsAnError) {
    EXPECT_THROW(parseImageSize("15x100"), Error);
    EXPECT_THROW(parseImageSize("100x8193"), Error);
    EXPECT_THROW(parseImageSize("-800x600"), Error);
}

TEST(RenderOptions, MalformedImageSizeIsAnErrorShowingTheExpectedForm) {
    for (const char* text : {"800", "800x", "x600", "800x600x2", "800 x 600", "abc", ""}) {
        try {
            parseImageSize(text);
            FAIL() << "expected an error for '" << text << "'";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()),
                      "invalid image size '" + std::string(text) +
                          "'; expected WIDTHxHEIGHT with each between 16 and 8192, e.g. 800x600");
        }
    }
}

}  // namespace
}  // namespace ramus
