#include "scenes/texture_budget.h"

#include "scenes/loader.h"
#include "tests/scenes/texture_scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::scenes {
namespace {

// An independent sRGB pair, to derive expected levels.
double linear(int level) {
    const double e = level / 255.0;
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}
int level(double l) {
    const double e = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(255.0 * e));
}

Image solid(int width, int height, std::uint8_t value) {
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.assign(static_cast<std::size_t>(width) * height * 4, value);
    return img;
}

TEST(TextureBudget, ReductionFactorIsTheSmallestPowerOfTwoThatFits) {
    struct Row {
        int width, height, maxSide, factor;
    };
    const Row rows[] = {
        {2048, 2048, 2048, 1},  // already fits
        {8192, 8192, 2048, 4},  // 8192 / 4 = 2048
        {8192, 100, 2048, 4},   // the longer side decides
        {100, 8193, 2048, 8},   // ceil(8193 / 4) = 2049 is one too many
        {4097, 1, 4096, 2},     // ceil(4097 / 2) = 2049
        {5, 5, 1, 8},           // down to one pixel: ceil(5 / 8) = 1
    };
    for (const Row& r : rows) {
        SCOPED_TRACE(std::to_string(r.width) + " x " + std::to_string(r.height) + " to " + std::to_string(r.maxSide));
        EXPECT_EQ(reductionFactor(r.width, r.height, r.maxSide), r.factor);
    }
}

TEST(TextureBudget, ReductionAveragesColourInLinearLightAndAlphaAsStored) {
    // Black and white pixels with alpha 0 and 255: the mean light is 0.5 (not level 128, the
    // mean of the codes), alpha the mean of the codes.
    const std::vector<std::uint8_t> rgba = {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0};
    const Image out = reduceImage(rgba.data(), 2, 2, 1, 2);
    ASSERT_EQ(out.width, 1);
    ASSERT_EQ(out.height, 1);
    EXPECT_EQ(out.rgba, (std::vector<std::uint8_t>{188, 188, 188, 128}));  // level(0.5) = 188; 127.5 rounds up
    EXPECT_EQ(level(0.5), 188);
}

TEST(TextureBudget, EdgeBlocksOfOddSizesAverageOnlyThePixelsInside) {
    // 3 x 1 by 2: the second output pixel covers source pixel 2 alone, so it is that pixel.
    const std::vector<std::uint8_t> rgba = {10, 20, 30, 255, 10, 20, 30, 255, 77, 88, 99, 40};
    const Image out = reduceImage(rgba.data(), 3, 1, 1, 2);
    ASSERT_EQ(out.width, 2);
    ASSERT_EQ(out.height, 1);
    EXPECT_EQ(std::vector<std::uint8_t>(out.rgba.begin(), out.rgba.begin() + 4),
              (std::vector<std::uint8_t>{10, 20, 30, 255}));
    EXPECT_EQ(std::vector<std::uint8_t>(out.rgba.begin() + 4, out.rgba.end()),
              (std::vector<std::uint8_t>{77, 88, 99, 40}));
}

TEST(TextureBudget, SixteenBitSamplesKeepTheirHighByte) {
    // Little-endian 16-bit: low byte first. Factor 1 copies the high bytes.
    const std::vector<std::uint8_t> rgba = {0xff, 12, 0x00, 34, 0x80, 56, 0x01, 78};
    const Image out = reduceImage(rgba.data(), 1, 1, 2, 1);
    EXPECT_EQ(out.rgba, (std::vector<std::uint8_t>{12, 34, 56, 78}));
}

TEST(TextureBudget, TheLargestImagesAreHalvedUntilTheSetFits) {
    // 4 + 4 + 1 MB against 5 MB: the first 1024² (the first of two equals) goes to 512² (1 MB),
    // 6 MB is still over, so the second 1024² goes too: 3 MB.
    std::vector<Image> images = {solid(1024, 1024, 9), solid(1024, 1024, 9), solid(512, 512, 9), Image{}};
    for (Image& img : images) {
        img.sourceWidth = img.width * 2;
        img.sourceHeight = img.height * 2;
    }
    const TextureReport r = fitTextures(images, {2048, std::size_t{5} << 20});
    EXPECT_EQ(r.images, 3);  // the empty image is no texture
    EXPECT_EQ(r.halvings, 2);
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(images[i].width, 512);
        EXPECT_EQ(images[i].height, 512);
        EXPECT_EQ(images[i].rgba, std::vector<std::uint8_t>(512 * 512 * 4, 9));  // a flat image stays flat
    }
    EXPECT_EQ(r.keptBytes, std::size_t{3} << 20);
    EXPECT_EQ(r.sourceBytes, std::size_t{36} << 20);  // each source is twice as wide and high
    EXPECT_EQ(r.largestSide, 512);
    EXPECT_EQ(describe(r),
              "textures: 3 images, 36 MB decoded at full size -> 3.0 MB, largest side 512 px (limits: 2048 px, "
              "budget 5.0 MB)");
}

TEST(TextureBudget, ABudgetTooSmallForOnePixelEachStopsAtOnePixel) {
    std::vector<Image> images = {solid(4, 2, 50), solid(1, 1, 60)};
    const TextureReport r = fitTextures(images, {2048, 1});
    EXPECT_EQ(images[0].width, 1);
    EXPECT_EQ(images[0].height, 1);
    EXPECT_EQ(r.keptBytes, 8u);  // two 1 x 1 images; the budget cannot be met
    EXPECT_EQ(r.halvings, 2);
}

TEST(TextureBudget, ThousandsAreSeparatedInTheLine) {
    TextureReport r;
    r.images = 41;
    r.sourceBytes = std::size_t{11008} << 20;
    r.keptBytes = std::size_t{512} << 20;
    r.largestSide = 2048;
    EXPECT_EQ(describe(r),
              "textures: 41 images, 11,008 MB decoded at full size -> 512 MB, largest side 2048 px (limits: 2048 "
              "px, budget 512 MB)");
}

// The loader reduces at decode and the scene fits the budget; the line says what happened.
TEST(TextureBudget, LoadedScenesKeepReducedImagesWithinTheLimits) {
    const auto file = testing::writeTexturedQuads("texture-budget-load", {{2048, 2048}, {2048, 1024}, {500, 1500}});
    const TextureLimits limits{512, std::size_t{3} << 19};  // 1.5 MB
    const Scene scene = loadSceneFile(file, nullptr, limits);
    ASSERT_EQ(scene.images.size(), 3u);
    // At decode: 2048 / 4 = 512, 2048 x 1024 / 4, 1500 / 4 = 375 (500 / 4 = 125). That is
    // 1 MB + 0.5 MB + 187,500 bytes, over 1.5 MB, so the largest, 512², is halved: 0.9 MB.
    const glm::ivec2 expected[] = {{256, 256}, {512, 256}, {125, 375}};
    const glm::ivec2 source[] = {{2048, 2048}, {2048, 1024}, {500, 1500}};
    std::size_t total = 0;
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        const Image& img = scene.images[i];
        EXPECT_EQ(glm::ivec2(img.width, img.height), expected[i]);
        EXPECT_EQ(glm::ivec2(img.sourceWidth, img.sourceHeight), source[i]);
        EXPECT_LE(std::max(img.width, img.height), limits.maxSide);
        ASSERT_EQ(img.rgba.size(), static_cast<std::size_t>(img.width) * img.height * 4);
        total += img.rgba.size();
        // Inside the top-left quadrant the checker (+-kChecker around 200, 60, 60) averages in
        // linear light.
        const std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(img.height / 4) * img.width + img.width / 4) * 4];
        for (int c = 0; c < 3; ++c) {
            const int base = c == 0 ? 200 : 60;
            EXPECT_NEAR(p[c], level(0.5 * (linear(base + testing::kChecker) + linear(base - testing::kChecker))), 1)
                << "channel " << c;
        }
    }
    EXPECT_LE(total, limits.budgetBytes);
    ASSERT_EQ(scene.notes.size(), 1u);
    // Full size: 16 MB + 8 MB + 3,000,000 bytes = 26.9 MB; kept 974,220 bytes = 0.93 MB.
    EXPECT_EQ(scene.notes[0],
              "textures: 3 images, 27 MB decoded at full size -> 0.9 MB, largest side 512 px (limits: 512 px, "
              "budget 1.5 MB)");
}

TEST(TextureBudget, ImagesWithinTheLimitsAreKeptAsInTheFile) {
    const auto file = testing::writeTexturedQuads("texture-budget-kept", {{64, 32}});
    const Scene scene = loadSceneFile(file);
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].rgba, testing::quadrantImage(64, 32).rgba);
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_EQ(scene.notes[0],
              "textures: 1 image, 0.0 MB decoded at full size -> 0.0 MB, largest side 64 px (limits: 2048 px, budget "
              "512 MB)");
}

}  // namespace
}  // namespace cavewall::scenes
