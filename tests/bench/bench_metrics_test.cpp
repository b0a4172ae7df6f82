// Image metrics, time percentiles and the Pareto front of `cavewall bench` (app/bench/metrics.h).
#include "app/bench/metrics.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace cavewall::bench {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

scenes::Image flat(int w, int h, std::uint8_t level) {
    scenes::Image image{"flat", w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4, level)};
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
    return image;
}

// `base` with every R, G and B value moved by +delta or -delta, signs random (seeded).
scenes::Image signNoise(const scenes::Image& base, int delta, unsigned seed) {
    scenes::Image out = base;
    std::mt19937 rng(seed);
    for (std::size_t i = 0; i < out.rgba.size(); ++i)
        if (i % 4 != 3) out.rgba[i] = static_cast<std::uint8_t>(out.rgba[i] + (rng() & 1 ? delta : -delta));
    out.name = "noisy";
    return out;
}

TEST(BenchMetrics, IdenticalImagesHaveNoError) {
    const scenes::Image a = signNoise(flat(40, 30, 128), 50, 3);
    const ImageError e = compareForBench(a, a);
    EXPECT_EQ(e.rmse, 0.0);
    EXPECT_EQ(e.mse, 0.0);
    EXPECT_TRUE(std::isinf(e.psnrDb) && e.psnrDb > 0);
    EXPECT_NEAR(e.ssim, 1.0, 1e-12);  // every window: equal means and variances, cov = var
}

TEST(BenchMetrics, SignNoiseHasKnownPsnr) {
    // Every colour value is off by exactly 10 levels, so RMSE = 10/255 whatever the signs, and
    // PSNR = 20 log10(255 / 10) = 28.1308 dB. Alpha (equal) is not counted.
    const scenes::Image a = flat(64, 48, 128);
    for (unsigned seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(seed);
        const ImageError e = compareForBench(signNoise(a, 10, seed), a);
        EXPECT_NEAR(e.rmse, 10.0 / 255.0, 1e-6);
        EXPECT_NEAR(e.psnrDb, 28.1308, 1e-3);
        EXPECT_LT(e.ssim, 0.9);  // structure: noise against a flat image
    }
}

TEST(BenchMetrics, SsimOfFlatImagesFollowsTheLuminanceTerm) {
    // Flat images have zero (co)variances, so SSIM reduces to the mean term
    // (2 * 100 * 110 + C1) / (100^2 + 110^2 + C1) with C1 = (0.01 * 255)^2 = 6.5025.
    const double expected = (2.0 * 100 * 110 + 6.5025) / (100.0 * 100 + 110.0 * 110 + 6.5025);
    EXPECT_NEAR(ssimLuminance(flat(32, 32, 100), flat(32, 32, 110)), expected, 1e-9);
    // Smaller than one 8x8 window: one window of the whole image, same value.
    EXPECT_NEAR(ssimLuminance(flat(5, 3, 100), flat(5, 3, 110)), expected, 1e-9);
}

TEST(BenchMetrics, SsimIsSymmetricAndDropsWithNoise) {
    const scenes::Image a = signNoise(flat(32, 32, 128), 20, 7);
    const scenes::Image b = signNoise(flat(32, 32, 128), 20, 8);
    EXPECT_NEAR(ssimLuminance(a, b), ssimLuminance(b, a), 1e-12);
    // Independent noise patterns are nearly uncorrelated: far below 1.
    EXPECT_LT(ssimLuminance(a, b), 0.3);
}

TEST(BenchMetrics, DifferentSizesAreAnError) {
    EXPECT_THAT([] { compareForBench(flat(4, 4, 0), flat(4, 5, 0)); },
                ThrowsMessage<Error>(HasSubstr("expected two RGBA images of the same size, got 4x4 and 4x5")));
}

TEST(BenchMetrics, PsnrFromMse) {
    EXPECT_NEAR(psnrFromMse(1e-4), 40.0, 1e-12);  // -10 log10(1e-4)
    EXPECT_NEAR(psnrFromMse(1.0), 0.0, 1e-12);    // the largest possible error
    EXPECT_TRUE(std::isinf(psnrFromMse(0.0)));
}

TEST(BenchMetrics, PoolAveragesSquaredError) {
    ErrorPool pool;
    EXPECT_TRUE(std::isinf(pool.result().psnrDb));  // nothing compared: identical
    pool.add({0.01, 0.1, 20.0, 0.5});
    pool.add({0.03, std::sqrt(0.03), 15.2, 0.7});
    // Pooled as all pixels together: mean MSE 0.02, RMSE sqrt(0.02), PSNR -10 log10(0.02).
    const ImageError e = pool.result();
    EXPECT_NEAR(e.mse, 0.02, 1e-15);
    EXPECT_NEAR(e.rmse, std::sqrt(0.02), 1e-15);
    EXPECT_NEAR(e.psnrDb, 16.9897, 1e-4);
    EXPECT_NEAR(e.ssim, 0.6, 1e-15);
    EXPECT_EQ(pool.count(), 2u);
}

TEST(BenchMetrics, MeanPsnrAveragesImagesAndCapsIdenticalOnes) {
    ErrorPool pool;
    ImageError a;  // 20 dB
    a.mse = 1e-2, a.psnrDb = 20.0, a.meanPsnrDb = 20.0;
    ImageError same;  // identical images: infinite PSNR, counted at the quantisation limit
    same.psnrDb = std::numeric_limits<double>::infinity();
    pool.add(a);
    pool.add(same);
    const ImageError r = pool.result();
    EXPECT_NEAR(r.meanPsnrDb, 0.5 * (20.0 + kQuantisationPsnrDb), 1e-12);
    EXPECT_NEAR(r.psnrDb, -10.0 * std::log10(0.5e-2), 1e-12);  // pooled: 23 dB
    EXPECT_GE(r.meanPsnrDb, r.psnrDb);
    EXPECT_NEAR(kQuantisationPsnrDb, 10.0 * std::log10(12.0 * 255.0 * 255.0), 1e-4);
}

TEST(BenchMetrics, NearestRankPercentiles) {
    std::vector<double> samples;
    for (int i = 100; i >= 1; --i) samples.push_back(i);  // order must not matter
    const TimeStats s = timeStats(samples);
    // Nearest rank on 1..100: the p-th percentile is the value ceil(p * 100).
    EXPECT_EQ(s.p50, 50.0);
    EXPECT_EQ(s.p95, 95.0);
    EXPECT_EQ(s.p99, 99.0);
    EXPECT_NEAR(s.mean, 50.5, 1e-12);
    const TimeStats one = timeStats({7.0});
    EXPECT_EQ(one.p50, 7.0);
    EXPECT_EQ(one.p99, 7.0);
    EXPECT_EQ(timeStats({}).p50, 0.0);
}

TEST(BenchMetrics, ParetoFront) {
    struct Case {
        const char* name;
        std::vector<TradeOff> points;
        std::vector<std::size_t> front;
    };
    const Case cases[] = {
        // (3, 4) is dominated by (2, 3); equal points (2, 3) are both kept; sorted by time.
        {"mixed", {{1, 5}, {2, 3}, {3, 4}, {4, 1}, {2, 3}}, {0, 1, 4, 3}},
        // One point dominates everything else.
        {"dominant", {{5, 5}, {1, 1}, {2, 3}}, {1}},
        // Same time, different error: only the lower error.
        {"tie in time", {{2, 1}, {2, 0.5}}, {1}},
        {"empty", {}, {}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_EQ(paretoFront(c.points), c.front);
    }
}

}  // namespace
}  // namespace cavewall::bench
