// LDR-FLIP (metrics/flip.h) against the properties the paper states and the numbers its formulas
// give for uniform patches, where neither filter changes anything.
#include "metrics/flip.h"
#include "metrics/flip_color.h"

#include "config/error.h"
#include "tests/metrics/test_images.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace cavewall::metrics {
namespace {

using scenes::Image;

using testing::flatImage;
using ::testing::HasSubstr;
using testing::makeImage;
using testing::Rgb;
using testing::texturedImage;
using ::testing::ThrowsMessage;

FlipResult flipAt(const Image& test, const Image& reference, double ppd) {
    return flip(test, reference, {ppd, ColorEncoding::Srgb});
}

TEST(FlipColor, WhiteIsTheReferenceAndTheRemapHitsItsKnots) {
    // White is the reference white: Yy = 100, Cx = Cz = 0, L* = 100, a* = b* = 0.
    const glm::dvec3 white = opponentFromLinear({1, 1, 1});
    EXPECT_NEAR(white.x, 100.0, 1e-9);
    EXPECT_NEAR(glm::length(glm::dvec2(white.y, white.z)), 0.0, 1e-9);
    EXPECT_NEAR(glm::distance(huntLabFromOpponent(white), glm::dvec3(100, 0, 0)), 0.0, 1e-6);
    // Green against blue is the largest difference, HyAB 203.30 (derived in BlackAgainstWhite
    // below): it maps to 1, and 0.4^(1 / 0.7) of it, where e^0.7 = 0.4 cmax, to 0.95.
    const double top =
        hyab(huntLabFromOpponent(opponentFromLinear({0, 1, 0})), huntLabFromOpponent(opponentFromLinear({0, 0, 1})));
    EXPECT_NEAR(top, 203.30, 1e-2);
    EXPECT_NEAR(flipColorError(top), 1.0, 1e-5);
    EXPECT_NEAR(flipColorError(top * std::pow(0.4, 1 / 0.7)), 0.95, 1e-5);
    EXPECT_EQ(flipColorError(0.0), 0.0);
    // Out-of-gamut colours are clamped to the RGB cube first: "whiter than white" is white.
    EXPECT_NEAR(glm::distance(huntLabFromOpponent(opponentFromLinear({2, 2, 2})), glm::dvec3(100, 0, 0)), 0.0, 1e-6);
}

TEST(Flip, IdenticalImagesGiveZeroEverywhere) {
    const Image a = texturedImage(48, 40, 7);
    for (double ppd : {1.0, 9.0, 17.0, 67.0}) {
        SCOPED_TRACE(ppd);
        const FlipResult r = flipAt(a, a, ppd);
        ASSERT_EQ(r.errors.size(), 48u * 40u);
        EXPECT_EQ(*std::max_element(r.errors.begin(), r.errors.end()), 0.0f);
        EXPECT_EQ(r.mean, 0.0);
        EXPECT_EQ(r.max, 0.0);
    }
}

TEST(Flip, ErrorsAreInZeroOneAndSummariesMatchTheMap) {
    // Two unrelated noise images: the largest differences of colour and of features at once.
    const Image a = texturedImage(40, 32, 1, 100), b = texturedImage(40, 32, 2, 100);
    for (double ppd : {1.0, 9.0, 67.0, 300.0}) {
        SCOPED_TRACE(ppd);
        const FlipResult r = flipAt(a, b, ppd);
        for (float e : r.errors) ASSERT_TRUE(e >= 0.0f && e <= 1.0f) << e;
        const double mean =
            std::accumulate(r.errors.begin(), r.errors.end(), 0.0) / static_cast<double>(r.errors.size());
        EXPECT_NEAR(r.mean, mean, 1e-9);
        EXPECT_EQ(r.max, *std::max_element(r.errors.begin(), r.errors.end()));
        EXPECT_LE(r.p50, r.p95);
        EXPECT_LE(r.p95, r.max);
        EXPECT_GT(r.mean, 0.1);
    }
}

TEST(Flip, IsSymmetric) {
    // HyAB and the absolute feature differences do not depend on which image is the reference.
    const Image a = texturedImage(32, 32, 3), b = texturedImage(32, 32, 4, 30);
    EXPECT_EQ(flipAt(a, b, 20).errors, flipAt(b, a, 20).errors);
}

TEST(Flip, BlackAgainstWhiteIsNearOne) {
    // Uniform patches: the CSF kernels sum to 1 and the feature kernels to 0, so each pixel
    // scores its colour difference alone. White is L* = 100, black L* = 0, both a* = b* = 0:
    // HyAB = 100, 100^0.7 = 25.119. Hunt green (L* 87.73, a* -75.61, b* 72.98) against Hunt
    // blue (32.30, 25.58, -34.84): HyAB = 55.44 + hypot(101.19, 107.81) = 203.30, cmax =
    // 203.30^0.7 = 41.275 and pc cmax = 16.51 < 25.119, so the error is
    // 0.95 + (25.119 - 16.51) / (41.275 - 16.51) * 0.05 = 0.9674.
    const FlipResult r = flipAt(flatImage(24, 24, {255, 255, 255}), flatImage(24, 24, {0, 0, 0}), 67);
    EXPECT_NEAR(r.mean, 0.9674, 1e-3);
    EXPECT_NEAR(r.max - *std::min_element(r.errors.begin(), r.errors.end()), 0.0, 1e-3);
}

TEST(Flip, GrowsWithAColourShift) {
    // A smooth picture (no features) against copies with more and more red: HyAB grows with
    // the shift and the remapping is increasing, so the mean must too.
    const auto shifted = [](int red) {
        return makeImage(48, 48, [red](int x, int y) { return Rgb{std::min(255, 60 + 2 * x + red), 90 + y, 140}; });
    };
    const Image reference = shifted(0);
    double previous = 0.0;
    for (int red : {2, 4, 8, 16, 32, 64}) {
        SCOPED_TRACE(red);
        const double mean = flipAt(shifted(red), reference, 17).mean;
        EXPECT_GT(mean, previous);
        previous = mean;
    }
}

TEST(Flip, GrowsWithAnEdgeDisplacement) {
    // A black | white edge moved right by d pixels: d columns change from white to black (each
    // about the black-white error) and both edges' neighbourhoods differ in features.
    const auto edgeAt = [](int x0) {
        return makeImage(64, 32, [x0](int x, int) { return x < x0 ? Rgb{0, 0, 0} : Rgb{255, 255, 255}; });
    };
    const Image reference = edgeAt(24);
    double previous = 0.0;
    for (int d : {1, 2, 4, 8, 16}) {
        SCOPED_TRACE(d);
        const double mean = flipAt(edgeAt(24 + d), reference, 17).mean;
        EXPECT_GT(mean, previous);
        previous = mean;
    }
}

TEST(Flip, AFinePatternIsHiddenAtHighPixelsPerDegree) {
    // A grating of 1-pixel black and white columns against uniform grey of the same mean light
    // (byte 188: linear 0.503). The grating's frequency is ppd / 2 cycles per degree, so the
    // higher the ppd, the finer it is to the eye. The achromatic CSF exp(-0.0047 f²) passes
    // 0.89 of it at 10 ppd (f = 5), 0.62 at 20 ppd (f = 10), 0.15 at 40 ppd and 5e-4 at 80 ppd:
    // the filtered grating tends to the grey, and the feature kernels (sigma 0.041 ppd pixels)
    // average the columns out. So the mean error must fall as ppd grows, i.e. rise as ppd falls
    // (the paper's viewing-distance dependence: seen from farther away, detail vanishes).
    // Below 10 ppd the grating is fully visible and the error saturates (about 0.95).
    const Image grating = makeImage(64, 64, [](int x, int) { return x % 2 ? Rgb{255, 255, 255} : Rgb{0, 0, 0}; });
    const Image grey = flatImage(64, 64, {188, 188, 188});
    std::vector<double> means;
    for (double ppd : {5.0, 10.0, 20.0, 40.0, 80.0}) means.push_back(flipAt(grey, grating, ppd).mean);
    EXPECT_GE(means[0], means[1] - 1e-3);  // saturated
    for (std::size_t i = 2; i < means.size(); ++i) EXPECT_LT(means[i], means[i - 1] - 0.02) << i;
    EXPECT_GT(means[1], 0.9);  // plainly visible on a CAVE wall (9-17 ppd)
    EXPECT_LT(means[4], 0.1);  // nearly invisible at a desktop's 67+ ppd
}

TEST(Flip, SeesColourAtEqualLuminanceAndDimsItInTheDark) {
    // Red (255, 0, 0) against green (0, 148, 0): linear luminance 0.2127 and 0.2118, equal
    // within 0.5 %, so edge and point detectors see almost nothing, yet FLIP finds the colours
    // very different. Uniform patches, so the error is the colour term alone: Hunt-Lab
    // (53.24, 42.64, 35.78) against (53.14, -30.53, 29.46), HyAB 73.54, 73.54^0.7 = 20.18 >
    // pc cmax = 16.51: 0.95 + (20.18 - 16.51) / 24.77 * 0.05 = 0.9576.
    const FlipResult bright = flipAt(flatImage(16, 16, {0, 148, 0}), flatImage(16, 16, {255, 0, 0}), 17);
    EXPECT_NEAR(bright.mean, 0.9576, 1e-3);
    // The same pair at a quarter of the light, (64, 0, 0) against (0, 33, 0), again of equal
    // luminance (0.0109): L* is 9.7, so the Hunt adjustment scales a* and b* by 0.097. HyAB
    // 4.81, 4.81^0.7 = 3.00 < 16.51: 0.95 / 16.51 * 3.00 = 0.173. Without the adjustment the
    // chroma difference (49.3) would score 0.88.
    const FlipResult dark = flipAt(flatImage(16, 16, {0, 33, 0}), flatImage(16, 16, {64, 0, 0}), 17);
    EXPECT_NEAR(dark.mean, 0.1728, 1e-3);
}

TEST(Flip, LinearEncodingReadsBytesAsLight) {
    // Byte 128 is linear 0.502 when linear, 0.216 when sRGB-encoded; against black the first is
    // the brighter, larger difference.
    const Image grey = flatImage(8, 8, {128, 128, 128}), black = flatImage(8, 8, {0, 0, 0});
    const double linear = flip(grey, black, {17, ColorEncoding::Linear}).mean;
    const double srgb = flip(grey, black, {17, ColorEncoding::Srgb}).mean;
    EXPECT_GT(linear, srgb);
}

TEST(Flip, DifferentSizesAreAnError) {
    Image a = flatImage(4, 4, {0, 0, 0}, "a"), b = flatImage(4, 5, {0, 0, 0}, "b");
    EXPECT_THAT(
        [&] { flip(a, b); },
        ThrowsMessage<Error>(HasSubstr(
            "flip: comparing 'a' with 'b': expected two non-empty RGBA images of the same size, got 4x4 and 4x5")));
}

TEST(Flip, ErrorImageMapsZeroToBlackAndOneToPaleYellow) {
    FlipResult r;
    r.width = 3;
    r.height = 1;
    r.errors = {0.0f, 0.5f, 1.0f};
    const Image image = flipErrorImage(r);
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 1);
    const std::vector<std::uint8_t> expected{0, 0, 0, 255, 184, 50, 110, 255, 255, 250, 190, 255};
    EXPECT_EQ(image.rgba, expected);
}

}  // namespace
}  // namespace cavewall::metrics
