// Contact sheets (issue 8): layout arithmetic, tile placement and labels.
#include <gtest/gtest.h>

#include "ramus/error.hpp"
#include "ramus/render.hpp"

namespace ramus {
namespace {

Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image;
    image.width = w;
    image.height = h;
    image.rgba.resize(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = r, image.rgba[i + 1] = g, image.rgba[i + 2] = b, image.rgba[i + 3] = 255;
    }
    return image;
}

std::array<std::uint8_t, 4> pixel(const Image& image, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
    return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2], image.rgba[i + 3]};
}

TEST(ContactSheet, TilesRowByRowWithGaps) {
    SheetParams params;
    params.columns = 2;
    params.gap = 4;
    params.labels = false;
    const Image sheet = composeContactSheet({{solid(10, 6, 255, 0, 0), "a"},
                                             {solid(10, 6, 0, 255, 0), "b"},
                                             {solid(10, 6, 0, 0, 255), "c"}},
                                            params);
    EXPECT_EQ(sheet.width, 2 * (10 + 4) + 4);
    EXPECT_EQ(sheet.height, 2 * (6 + 4) + 4);
    EXPECT_EQ(pixel(sheet, 4, 4), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
    EXPECT_EQ(pixel(sheet, 18 + 9, 4 + 5), (std::array<std::uint8_t, 4>{0, 255, 0, 255}));
    EXPECT_EQ(pixel(sheet, 4, 14), (std::array<std::uint8_t, 4>{0, 0, 255, 255}));
    // The gap between tiles and the empty fourth cell keep the background.
    EXPECT_EQ(pixel(sheet, 15, 5), (std::array<std::uint8_t, 4>{255, 255, 255, 255}));
    EXPECT_EQ(pixel(sheet, 22, 17), (std::array<std::uint8_t, 4>{255, 255, 255, 255}));
}

TEST(ContactSheet, DefaultsToASquareLayout) {
    std::vector<SheetTile> tiles(5, SheetTile{solid(8, 8, 0, 0, 0), ""});
    SheetParams params;
    params.gap = 0;
    params.labels = false;
    const Image sheet = composeContactSheet(tiles, params);
    EXPECT_EQ(sheet.width, 3 * 8);   // ceil(sqrt(5)) = 3 columns
    EXPECT_EQ(sheet.height, 2 * 8);  // 2 rows
}

TEST(ContactSheet, CentresSmallerTilesInTheirCell) {
    SheetParams params;
    params.gap = 0;
    params.labels = false;
    params.columns = 2;
    const Image sheet = composeContactSheet(
        {{solid(10, 10, 0, 0, 0), "big"}, {solid(2, 2, 255, 0, 0), "small"}}, params);
    EXPECT_EQ(pixel(sheet, 10 + 4, 4), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
    EXPECT_EQ(pixel(sheet, 10, 0), (std::array<std::uint8_t, 4>{255, 255, 255, 255}));
}

TEST(ContactSheet, DrawsLabelsUnderTheTiles) {
    SheetParams params;
    params.gap = 0;
    const Image labelled =
        composeContactSheet({{solid(120, 20, 255, 255, 255), "elephant"}}, params);
    params.labels = false;
    const Image plain = composeContactSheet({{solid(120, 20, 255, 255, 255), "elephant"}}, params);
    EXPECT_GT(labelled.height, plain.height);
    int dark = 0;
    for (int y = 20; y < labelled.height; ++y) {
        for (int x = 0; x < labelled.width; ++x) dark += pixel(labelled, x, y)[0] < 128 ? 1 : 0;
    }
    EXPECT_GT(dark, 40);  // the letters' strokes
}

TEST(ContactSheet, RefusesNoTilesAndHugeSheets) {
    EXPECT_THROW(composeContactSheet({}), Error);
    std::vector<SheetTile> tiles(3, SheetTile{solid(8000, 16, 0, 0, 0), ""});
    SheetParams params;
    params.columns = 3;
    EXPECT_THROW(composeContactSheet(tiles, params), Error);
}

}  // namespace
}  // namespace ramus
