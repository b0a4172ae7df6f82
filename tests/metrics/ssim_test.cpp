// SSIM with the standard 11x11 Gaussian window (metrics/ssim.h): its defining properties and
// two values derived by hand from the formula.
#include "metrics/ssim.h"

#include "config/error.h"
#include "tests/metrics/test_images.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

namespace cavewall::metrics {
namespace {

using scenes::Image;

using testing::flatImage;
using ::testing::HasSubstr;
using testing::makeImage;
using testing::Rgb;
using testing::texturedImage;
using ::testing::ThrowsMessage;

// `base` with every R, G, B value moved by a seeded uniform offset in [-amplitude, amplitude].
Image withNoise(const Image& base, int amplitude, unsigned seed) {
    Image out = base;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> n(-amplitude, amplitude);
    for (std::size_t i = 0; i < out.rgba.size(); ++i)
        if (i % 4 != 3) out.rgba[i] = static_cast<std::uint8_t>(std::clamp(out.rgba[i] + n(rng), 0, 255));
    return out;
}

TEST(Ssim, IdenticalImagesScoreOne) {
    const Image a = texturedImage(40, 30, 5);
    EXPECT_EQ(ssim(a, a), 1.0);
    // Also with a window shrunk to fit (5 x 4 pixels: radius 2 across, 1 down).
    const Image small = texturedImage(5, 4, 6);
    EXPECT_EQ(ssim(small, small), 1.0);
}

TEST(Ssim, IsSymmetric) {
    const Image a = texturedImage(32, 24, 1), b = withNoise(a, 20, 2);
    EXPECT_EQ(ssim(a, b), ssim(b, a));
}

TEST(Ssim, FallsAsNoiseGrows) {
    const Image a = texturedImage(48, 48, 3);
    double previous = 1.0;
    for (int amplitude : {2, 4, 8, 16, 32, 64}) {
        SCOPED_TRACE(amplitude);
        const double s = ssim(withNoise(a, amplitude, 9), a);
        EXPECT_LT(s, previous);
        previous = s;
    }
    EXPECT_LT(previous, 0.5);
}

TEST(Ssim, UniformGreysScoreTheirLuminanceTerm) {
    // Flat images: all variances and the covariance are 0, so SSIM is the luminance term alone,
    // (2 mx my + C1) / (mx² + my² + C1) with C1 = (0.01 * 255)² = 6.5025. Grey bytes have luma
    // equal to the byte (the BT.601 weights sum to 1): (2 * 100 * 150 + 6.5025) /
    // (100² + 150² + 6.5025) = 30006.5025 / 32506.5025 = 0.9230923.
    EXPECT_NEAR(ssim(flatImage(20, 20, {100, 100, 100}), flatImage(20, 20, {150, 150, 150})), 0.9230923, 1e-6);
}

TEST(Ssim, InvertedStripesScoreTheirStructureTerm) {
    // Columns alternating 178 / 78 (mean 128, amplitude d = 50) against the same columns
    // swapped. Under the window the weighted means are 128 +- 50 s and 128 -+ 50 s with
    // s = sum_k g_k (-1)^k / sum_k g_k = -1.39e-4 for the 11 taps of sigma 1.5, the variances
    // d² (1 - s²) and the covariance -d² (1 - s²). With s² ~ 2e-8 negligible, SSIM is
    // 1 * (-2 d² + C2) / (2 d² + C2), C2 = (0.03 * 255)² = 58.5225:
    // (-5000 + 58.5225) / (5000 + 58.5225) = -0.976862.
    const auto stripes = [](int phase) {
        return makeImage(24, 16, [phase](int x, int) {
            return (x + phase) % 2 ? Rgb{178, 178, 178} : Rgb{78, 78, 78};
        });
    };
    EXPECT_NEAR(ssim(stripes(0), stripes(1)), -0.976862, 1e-5);
}

TEST(Ssim, DifferentSizesAreAnError) {
    const Image a = flatImage(12, 12, {0, 0, 0}, "a"), b = flatImage(12, 13, {0, 0, 0}, "b");
    EXPECT_THAT([&] { ssim(a, b); }, ThrowsMessage<Error>(HasSubstr("ssim: comparing 'a' with 'b'")));
}

}  // namespace
}  // namespace cavewall::metrics
