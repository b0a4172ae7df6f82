// The golden-image machinery itself (GL-free): comparison figures and atomic PNG files.
#include "config/error.h"
#include "metrics/image_compare.h"
#include "scenes/image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace cavewall::metrics {
namespace {

using scenes::Image;

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A 100 x 100 gradient, so every pixel differs from its neighbours.
Image gradient() {
    Image image{"gradient", 100, 100, std::vector<std::uint8_t>(100 * 100 * 4)};
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) {
            std::uint8_t* p = &image.rgba[(y * 100 + x) * 4];
            p[0] = static_cast<std::uint8_t>(2 * x);
            p[1] = static_cast<std::uint8_t>(2 * y);
            p[2] = 128;
            p[3] = 255;
        }
    return image;
}

std::uint8_t& red(Image& image, int x, int y) { return image.rgba[(y * image.width + x) * 4]; }

std::filesystem::path scratch(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("cavewall-image-test-" + std::to_string(::getpid())) / name;
}

TEST(ImageCompare, IdenticalImagesPassWithZeroFigures) {
    const ImageComparison r = compareImages(gradient(), gradient());
    EXPECT_TRUE(r.passes());
    EXPECT_EQ(r.maxDelta, 0);
    EXPECT_EQ(r.meanDelta, 0.0);
    EXPECT_EQ(r.badFraction, 0.0);
    EXPECT_TRUE(r.worst.empty());
    EXPECT_TRUE(compareImages(gradient(), gradient(), ImageTolerance::exact()).passes());
}

TEST(ImageCompare, AChangedBlockFailsWithTheRightFigures) {
    Image changed = gradient();
    // A 4 x 5 block 40 levels brighter in red: 20 of 10 000 pixels.
    for (int y = 10; y < 15; ++y)
        for (int x = 20; x < 24; ++x) red(changed, x, y) += 40;
    red(changed, 90, 90) += 7;  // and one pixel a little off, so the ranking has a tail
    const ImageComparison r = compareImages(changed, gradient());
    EXPECT_FALSE(r.passes());
    EXPECT_EQ(r.maxDelta, 40);
    // Mean: (20 x 40 + 7) / 10 000.
    EXPECT_DOUBLE_EQ(r.meanDelta, 807.0 / 10000.0);
    // Bad pixels (Δ > 3): the 20 block pixels and the single one.
    EXPECT_DOUBLE_EQ(r.badFraction, 21.0 / 10000.0);
    ASSERT_EQ(r.worst.size(), 10u);
    // Ties keep row-major order: the block's top-left pixel first.
    EXPECT_EQ(r.worst.front(), (PixelDelta{20, 10, 40}));
    EXPECT_THAT(r.describe(), HasSubstr("max Δ 40"));
    EXPECT_THAT(r.describe(), HasSubstr("(20, 10: 40)"));
    // The mean alone (0.08 ≤ 0.3) would pass: it is the 0.21 % bad share that fails.
    EXPECT_LE(r.meanDelta, r.tolerance.maxMeanDelta);
}

TEST(ImageCompare, SmallNoiseWithinTolerancePasses) {
    Image noisy = gradient();
    for (int x = 0; x < 100; x += 2) red(noisy, x, 50) += 3;  // Δ = 3 is not "bad"
    red(noisy, 5, 5) += 50;                                   // 1 bad pixel = 0.01 % ≤ 0.1 %
    const ImageComparison r = compareImages(noisy, gradient());
    EXPECT_TRUE(r.passes()) << r.describe();
    EXPECT_FALSE(compareImages(noisy, gradient(), ImageTolerance::exact()).passes());
}

TEST(ImageCompare, DifferentSizesNeverPass) {
    Image small = gradient();
    small.height = 50;
    small.rgba.resize(100 * 50 * 4);
    const ImageComparison r = compareImages(small, gradient());
    EXPECT_FALSE(r.sameSize);
    EXPECT_FALSE(r.passes());
    EXPECT_EQ(r.describe(), "images differ in size");
}

TEST(ImageCompare, DifferenceImageMarksBadPixelsRed) {
    Image changed = gradient();
    red(changed, 3, 4) = 255;
    const Image diff = differenceImage(changed, gradient());
    const std::uint8_t* bad = &diff.rgba[(4 * 100 + 3) * 4];
    EXPECT_GT(bad[0], 200);  // Δ = 255 - 6 saturates the red scale
    EXPECT_EQ(bad[1], 0);
    const std::uint8_t* same = &diff.rgba[0];
    EXPECT_EQ(same[0], same[1]);  // unchanged pixels are grey
}

TEST(ImageIo, WritesAndReadsBackExactly) {
    const auto file = scratch("nested/folder/gradient.png");
    scenes::writeImage(file, gradient());
    const Image back = scenes::readImage(file);
    EXPECT_EQ(back.width, 100);
    EXPECT_TRUE(compareImages(back, gradient(), ImageTolerance::exact()).passes());
    // Atomic write: only the final file is left in the folder, no temporary.
    int files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(file.parent_path())) ++files;
    EXPECT_EQ(files, 1);
    std::filesystem::remove_all(scratch(""));
}

TEST(ImageIo, BadInputNamesTheFile) {
    const auto missing = scratch("missing.png");
    EXPECT_THAT([&] { scenes::readImage(missing); }, ThrowsMessage<Error>(HasSubstr("missing.png: cannot read image")));
    const auto text = scratch("not-an-image.png");
    std::filesystem::create_directories(text.parent_path());
    std::ofstream(text) << "hello";
    EXPECT_THAT([&] { scenes::readImage(text); }, ThrowsMessage<Error>(HasSubstr("not-an-image.png")));
    Image broken = gradient();
    broken.rgba.resize(10);
    EXPECT_THAT([&] { scenes::writeImage(scratch("broken.png"), broken); },
                ThrowsMessage<Error>(HasSubstr("expected 100 x 100 RGBA pixels, got 10 bytes")));
    std::filesystem::remove_all(scratch(""));
}

}  // namespace
}  // namespace cavewall::metrics
