// Image metrics, time percentiles and the Pareto front of `cavewall bench` (app/bench/metrics.h).
#include "app/bench/metrics.h"

#include "config/error.h"
#include "metrics/flip.h"
#include "metrics/popping.h"
#include "metrics/ssim.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
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

// `image` with the R, G, B of its left half raised by `delta` (a hard-edged error patch).
scenes::Image leftHalfBrighter(const scenes::Image& image, int delta) {
    scenes::Image out = image;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width / 2; ++x)
            for (int c = 0; c < 3; ++c) {
                std::uint8_t& v = out.rgba[(static_cast<std::size_t>(y) * out.width + x) * 4 + c];
                v = static_cast<std::uint8_t>(std::min(255, v + delta));
            }
    out.name = "brighter";
    return out;
}

ComparedImage compared(int screen, const scenes::Image& test, const scenes::Image& reference, double ppd = 9.0,
                       int eye = 0) {
    return {screen, eye, &test, &reference, ppd};
}

TEST(BenchMetrics, IdenticalFramesHaveNoError) {
    const scenes::Image a = signNoise(flat(40, 30, 128), 50, 3), b = signNoise(flat(40, 30, 90), 20, 4);
    ErrorPool pool(1);
    pool.addFrame(0, {compared(0, a, a)});
    pool.addFrame(3, {compared(0, b, b)});
    const ImageError e = pool.result();
    EXPECT_EQ(e.frames, 2u);
    EXPECT_EQ(e.mse, 0.0);
    EXPECT_TRUE(std::isinf(e.psnrDb) && e.psnrDb > 0);
    EXPECT_TRUE(std::isinf(e.worstFramePsnrDb));
    EXPECT_NEAR(e.meanPsnrDb, kQuantisationPsnrDb, 1e-9);  // capped, labelled only
    EXPECT_NEAR(e.ssim, 1.0, 1e-12);
    EXPECT_EQ(e.flipMean, 0.0);
    EXPECT_EQ(e.flipOverThreshold, 0.0);
    EXPECT_EQ(e.poppingPeak, 0.0);  // the error stays 0 while the picture changes
}

// Why a share and not a percentile: a small wrong patch (a 6 x 6 block of a flat 64 x 64 image
// turned from grey to white: 36 of 4096 pixels, spread a little by FLIP's filters, still far
// under 5 %) leaves FLIP's p95 at 0, while the share over 0.1 sees it.
TEST(BenchMetrics, ASmallWrongPatchShowsInTheShareWhereP95ReadsZero) {
    const scenes::Image ref = flat(64, 64, 100);
    scenes::Image test = ref;
    for (int y = 29; y < 35; ++y)
        for (int x = 29; x < 35; ++x)
            for (int c = 0; c < 3; ++c) test.rgba[(static_cast<std::size_t>(y) * 64 + x) * 4 + c] = 255;
    metrics::FlipOptions options;
    options.pixelsPerDegree = 9.0;
    const metrics::FlipResult f = metrics::flip(test, ref, options);
    ASSERT_EQ(f.p95, 0.0);
    ErrorPool pool(1);
    pool.addFrame(0, {compared(0, test, ref, 9.0)});
    const double share = pool.result().flipOverThreshold;
    EXPECT_GE(share, 36.0 / (64 * 64));  // at least the patch itself
    EXPECT_LT(share, 0.05);
}

TEST(BenchMetrics, PsnrIsPooledOverPixelsWithWorstFrameAndCappedMeanApart) {
    // Two screens; frame 0 both exact, frame 1 screen 0 off by 10 levels everywhere.
    const scenes::Image ref = flat(32, 32, 100), off = signNoise(ref, 10, 7);
    ErrorPool pool(2);
    pool.addFrame(0, {compared(0, ref, ref), compared(1, ref, ref)});
    pool.addFrame(1, {compared(0, off, ref), compared(1, ref, ref)});
    const double imageMse = (10.0 / 255) * (10.0 / 255);
    const ImageError all = pool.result();
    EXPECT_NEAR(all.mse, imageMse / 4, 1e-15);  // one image's error over four images' pixels
    EXPECT_NEAR(all.psnrDb, -10 * std::log10(imageMse / 4), 1e-9);
    EXPECT_EQ(all.worstFrame, 1);
    EXPECT_NEAR(all.worstFramePsnrDb, -10 * std::log10(imageMse / 2), 1e-9);  // frame 1: two screens
    EXPECT_EQ(all.p5FramePsnrDb, all.worstFramePsnrDb);                       // nearest rank of two frames: the lowest
    EXPECT_NEAR(all.meanPsnrDb, 0.5 * (kQuantisationPsnrDb + all.worstFramePsnrDb), 1e-9);
    EXPECT_GT(all.meanPsnrDb, all.psnrDb);  // the capped mean flatters
    EXPECT_NEAR(pool.screenResult(0).psnrDb, -10 * std::log10(imageMse / 2), 1e-9);
    EXPECT_TRUE(std::isinf(pool.screenResult(1).psnrDb));
    EXPECT_LT(all.ssim, 1.0);
    EXPECT_NEAR(all.ssim, (3.0 + metrics::ssim(off, ref)) / 4, 1e-12);  // mean over the four images
}

TEST(BenchMetrics, FlipPoolsAllPixelsAtEachImagesPpdAndKeepsTheWorstMap) {
    const scenes::Image ref = signNoise(flat(48, 40, 120), 30, 11);
    const scenes::Image small = leftHalfBrighter(ref, 12), large = leftHalfBrighter(ref, 60);
    ErrorPool pool(2);
    pool.addFrame(0, {compared(0, small, ref, 9.0), compared(1, ref, ref, 9.0)});
    pool.addFrame(2, {compared(0, large, ref, 30.0), compared(1, ref, ref, 9.0)});
    metrics::FlipOptions at9, at30;
    at9.pixelsPerDegree = 9.0;
    at30.pixelsPerDegree = 30.0;
    const metrics::FlipResult f0 = metrics::flip(small, ref, at9), f2 = metrics::flip(large, ref, at30);
    ASSERT_NE(metrics::flip(large, ref, at9).mean, f2.mean);  // the ppd matters for this pair
    const ImageError all = pool.result();
    EXPECT_NEAR(all.flipMean, (f0.mean + f2.mean) / 4, 1e-9);  // identical images add zeros
    // The share over kFlipThreshold counts every pixel of all four images: the identical pairs
    // add pixels and none over it.
    auto over = [](const metrics::FlipResult& f) {
        return std::count_if(f.errors.begin(), f.errors.end(), [](float v) { return v > kFlipThreshold; });
    };
    const auto pixels = static_cast<double>(f0.errors.size() + f2.errors.size());
    ASSERT_GT(over(f2), 0);
    EXPECT_EQ(all.flipOverThreshold, static_cast<double>(over(f0) + over(f2)) / (2.0 * pixels));
    EXPECT_EQ(pool.screenResult(0).flipOverThreshold, static_cast<double>(over(f0) + over(f2)) / pixels);
    EXPECT_EQ(pool.screenResult(1).flipOverThreshold, 0.0);
    EXPECT_NEAR(pool.screenResult(0).flipMean, (f0.mean + f2.mean) / 2, 1e-9);
    EXPECT_EQ(pool.screenResult(1).flipMean, 0.0);
    const FlipMap& worst = pool.worstFlip();
    EXPECT_EQ(worst.frame, 2);
    EXPECT_EQ(worst.screen, 0);
    EXPECT_NEAR(worst.mean, f2.mean, 1e-12);
    EXPECT_EQ(worst.image.rgba, metrics::flipErrorImage(f2).rgba);
}

TEST(BenchMetrics, PoppingFollowsEachScreenAndEyeAcrossComparedFrames) {
    const scenes::Image ref = flat(64, 64, 100), left = flat(64, 64, 30), right = flat(64, 64, 220);
    const scenes::Image jumped = leftHalfBrighter(ref, 40);
    ErrorPool pool(1);
    // Two eyes of very different pictures, both exact: no popping unless eyes were mixed up.
    pool.addFrame(0, {compared(0, left, left, 9, 0), compared(0, right, right, 9, 1)});
    pool.addFrame(3, {compared(0, left, left, 9, 0), compared(0, right, right, 9, 1)});
    EXPECT_EQ(pool.result().poppingPeak, 0.0);
    // Eye 0 switches: its error jumps by 40 levels over half the image while the picture holds.
    pool.addFrame(6, {compared(0, ref, ref, 9, 0), compared(0, right, right, 9, 1)});
    pool.addFrame(9, {compared(0, jumped, ref, 9, 0), compared(0, right, right, 9, 1)});
    const double expected = metrics::framePairPopping(ref, ref, jumped, ref);
    EXPECT_GT(expected, 30.0);  // about 40 levels / 1 level floor in the switched tiles
    const ImageError e = pool.result();
    // Eye 0 from frame 3 to 6 changes picture but not error (0); the jump scores `expected`.
    EXPECT_NEAR(e.poppingPeak, expected, 1e-9);
    // Pairs: 3 per eye; only one is non-zero.
    EXPECT_NEAR(e.poppingRms, std::sqrt(expected * expected / 6), 1e-9);
}

TEST(BenchMetrics, DifferentSizesAreAnError) {
    const scenes::Image a = flat(4, 4, 0), b = flat(4, 5, 0);
    ErrorPool pool(1);
    EXPECT_THROW(pool.addFrame(0, {compared(0, a, b)}), Error);
}

TEST(BenchMetrics, NothingComparedIsIdentical) {
    const ImageError e = ErrorPool(3).result();
    EXPECT_EQ(e.frames, 0u);
    EXPECT_TRUE(std::isinf(e.psnrDb));
    EXPECT_EQ(e.flipMean, 0.0);
    EXPECT_EQ(ErrorPool(3).worstFlip().image.width, 0);
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
