// The popping metric (metrics/popping.h): a texture switched in one frame scores worse than the
// same change cross-faded; a steady error scores nothing however the picture moves.
#include "metrics/popping.h"

#include "config/error.h"
#include "tests/metrics/test_images.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace cavewall::metrics {
namespace {

using scenes::Image;

using ::testing::HasSubstr;
using testing::makeImage;
using testing::Rgb;
using testing::texturedImage;
using ::testing::ThrowsMessage;

// `base` with `offset` levels added to R, G and B of the pixels `where` selects.
Image offsetImage(const Image& base, int offset, const std::function<bool(int, int)>& where = {}) {
    Image out = base;
    for (int y = 0; y < base.height; ++y)
        for (int x = 0; x < base.width; ++x)
            if (!where || where(x, y))
                for (int c = 0; c < 3; ++c) {
                    std::uint8_t& v = out.rgba[(static_cast<std::size_t>(y) * base.width + x) * 4 + c];
                    v = static_cast<std::uint8_t>(v + offset);
                }
    return out;
}

// Runs 8 frames of a static reference whose test image carries error(k) levels at frame k.
PoppingSummary runStatic(const std::function<int(int)>& error) {
    const Image reference = texturedImage(64, 64, 11);
    PoppingMeter meter;
    for (int k = 0; k < 8; ++k) meter.addFrame(k, offsetImage(reference, error(k)), reference);
    return meter.summary();
}

TEST(Popping, AHardSwitchScoresWorseThanACrossFade) {
    // The error image goes from A = +20 levels to B = -20 levels on a reference that holds still
    // (dR = 0, so each pair divides by the floor of one level). Hard: frames 0-3 show A, 4-7 B:
    // one pair changes by 40 levels RMS, popping 40; the other six score 0. Cross-fade over four
    // frames: +20, +20, +10, 0, -10, -20, -20, -20: four pairs of 10 levels each.
    //   peak: 40 against 10 (n = 4 times lower)
    //   RMS over 7 pairs: sqrt(40² / 7) = 15.12 against sqrt(4 * 10² / 7) = 7.56 (sqrt n lower)
    // The mean would tie (40 / 7 both): the header says why it is not the summary.
    const PoppingSummary hard = runStatic([](int k) { return k < 4 ? 20 : -20; });
    const PoppingSummary fade = runStatic([](int k) { return 20 - 10 * std::clamp(k - 1, 0, 4); });
    ASSERT_EQ(hard.pairs, 7u);
    ASSERT_EQ(fade.pairs, 7u);
    EXPECT_NEAR(hard.peak, 40.0, 1e-9);
    EXPECT_EQ(hard.peakFrame, 4);
    EXPECT_NEAR(fade.peak, 10.0, 1e-9);
    EXPECT_NEAR(hard.rms, std::sqrt(1600.0 / 7.0), 1e-9);
    EXPECT_NEAR(fade.rms, std::sqrt(400.0 / 7.0), 1e-9);
    EXPECT_GT(hard.peak, fade.peak);
    EXPECT_GT(hard.rms, fade.rms);
}

TEST(Popping, ASteadyErrorDoesNotPopHoweverThePictureMoves) {
    // The reference pans one pixel per frame; the test is always the reference + 20 levels, so
    // E_t - E_{t-1} = 0 in every pixel.
    const Image wide = texturedImage(80, 48, 12);
    PoppingMeter meter;
    for (int k = 0; k < 6; ++k) {
        const Image reference = makeImage(48, 48, [&](int x, int y) {
            const std::uint8_t* p = &wide.rgba[(static_cast<std::size_t>(y) * wide.width + x + k) * 4];
            return Rgb{p[0], p[1], p[2]};
        });
        const std::optional<double> p = meter.addFrame(k, offsetImage(reference, 20), reference);
        EXPECT_EQ(p.has_value(), k > 0);
        if (p) {
            EXPECT_EQ(*p, 0.0);
        }
    }
    EXPECT_EQ(meter.summary().peak, 0.0);
}

TEST(Popping, ASwitchOnOneTileIsNotDilutedByTheRest) {
    // A 40-level switch confined to one 32 x 32 tile of a 256 x 256 screen scores what a
    // full-screen switch scores (40); an RMS over the whole screen would show 40 / 8 = 5.
    const Image reference = texturedImage(256, 256, 13);
    const auto inTile = [](int x, int y) { return x >= 96 && x < 128 && y >= 32 && y < 64; };
    const double local =
        framePairPopping(offsetImage(reference, 20, inTile), reference, offsetImage(reference, -20, inTile), reference);
    const double whole =
        framePairPopping(offsetImage(reference, 20), reference, offsetImage(reference, -20), reference);
    EXPECT_NEAR(local, 40.0, 1e-9);
    EXPECT_NEAR(whole, 40.0, 1e-9);
}

TEST(Popping, ThePicturesOwnChangeMasksTheSwitch) {
    // The same 40-level switch while the whole reference brightens by 40 levels (a light
    // switched on): dE = dR = 40 levels, popping 1.
    const Image before = texturedImage(64, 64, 14);
    const Image after = offsetImage(before, 40);
    EXPECT_NEAR(framePairPopping(offsetImage(before, 20), before, offsetImage(after, -20), after), 1.0, 1e-9);
}

TEST(Popping, RestartStartsANewChain) {
    const Image reference = texturedImage(16, 16, 15);
    PoppingMeter meter;
    EXPECT_FALSE(meter.addFrame(0, reference, reference));
    EXPECT_TRUE(meter.addFrame(1, reference, reference));
    meter.restart();
    // A different size is fine after a restart (another screen), and is not compared.
    const Image other = texturedImage(8, 8, 16);
    EXPECT_FALSE(meter.addFrame(2, other, other));
    EXPECT_EQ(meter.summary().pairs, 1u);
}

TEST(Popping, ASizeChangeWithoutRestartIsAnError) {
    PoppingMeter meter;
    const Image a = texturedImage(16, 16, 1, 12, "a"), b = texturedImage(16, 8, 2, 12, "b");
    meter.addFrame(0, a, a);
    EXPECT_THAT([&] { meter.addFrame(1, b, b); }, ThrowsMessage<Error>(HasSubstr("popping: comparing 'a' with 'b'")));
}

}  // namespace
}  // namespace cavewall::metrics
