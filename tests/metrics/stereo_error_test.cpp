// The stereo error (metrics/stereo_error.h): identical depths score exactly 0; a flat wall
// standing in for a deep scene scores far worse than a per-texel depth with small noise;
// background, invalid depths and bad input are handled as the header says.
#include "metrics/stereo_error.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

namespace cavewall::metrics {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kArcminPerRadian = 180.0 * 60.0 / 3.14159265358979323846;

DepthImage depthImage(const std::string& name, int width, int height, const std::function<float(int, int)>& at) {
    DepthImage d{name, width, height, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) d.metres.push_back(at(x, y));
    return d;
}

// A deep scene behind a wall at 3 m: depth 3 m in column 0 rising linearly to 30 m in the last
// column, every row alike.
DepthImage deepScene(int width = 64, int height = 16) {
    return depthImage("deep", width, height, [width](int x, int) { return 3.0f + 27.0f * x / (width - 1); });
}

// A deterministic value in [-1, 1] per pixel (a small integer hash, no library generator).
double noise(int x, int y) {
    std::uint32_t h = static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return static_cast<double>(h % 20001u) / 10000.0 - 1.0;
}

TEST(StereoError, IdenticalDepthsScoreExactlyZero) {
    const DepthImage deep = deepScene();
    const StereoError e = stereoError(deep, deep);
    EXPECT_EQ(e.pixels, 64u * 16u);
    EXPECT_EQ(e.sumArcmin, 0.0);
    EXPECT_EQ(e.meanArcmin(), 0.0);
    EXPECT_EQ(e.maxArcmin, 0.0);
    EXPECT_EQ(e.beyond, 0u);
    EXPECT_EQ(e.invalidPixels, 0u);
}

TEST(StereoError, VergenceIsAboutInterocularOverDistance) {
    // b / z = 0.064 / 2 rad = 110.0 arcmin; 2 atan(b / 2z) is smaller by (b/z)^3 / 12 rad, a
    // relative 1e-4 here.
    EXPECT_NEAR(vergenceArcmin(2.0, 0.064), 0.032 * kArcminPerRadian, 0.032 * kArcminPerRadian * 1e-3);
    EXPECT_EQ(vergenceArcmin(std::numeric_limits<double>::infinity(), 0.064), 0.0);
    // At the eye-to-eye distance itself the angle is 2 atan(1/2) = 53.13 degrees, not b/z = 1 rad.
    EXPECT_NEAR(vergenceArcmin(0.064, 0.064), 2.0 * std::atan(0.5) * kArcminPerRadian, 1e-9);
}

TEST(StereoError, BackgroundHasNoDisparity) {
    const DepthImage sky = depthImage("sky", 4, 4, [](int, int) { return kInf; });
    EXPECT_EQ(stereoError(sky, sky).sumArcmin, 0.0);  // background against background
    // A surface at 30 m shown as background: its whole vergence, 0.064 / 30 rad = 7.33 arcmin.
    const DepthImage far = depthImage("far", 4, 4, [](int, int) { return 30.0f; });
    const StereoError e = stereoError(sky, far);
    EXPECT_NEAR(e.meanArcmin(), vergenceArcmin(30.0, 0.064), 1e-9);
    EXPECT_NEAR(e.meanArcmin(), 7.33, 0.01);
    EXPECT_EQ(e.shareBeyond(), 1.0);
}

TEST(StereoError, FlatWallScoresWorseThanPerTexelDepth) {
    const DepthImage reference = deepScene();
    // The flat wall shows everything at the wall's 3 m.
    const DepthImage flat = depthImage("flat", 64, 16, [](int, int) { return 3.0f; });
    // The depth wall keeps each texel's depth, within +-1 % (a bake's quantisation and march).
    const DepthImage depth = depthImage("depth", 64, 16, [&](int x, int y) {
        return static_cast<float>(reference.metres[y * 64 + x] * (1.0 + 0.01 * noise(x, y)));
    });
    const StereoError flatError = stereoError(flat, reference), depthError = stereoError(depth, reference);
    // Flat: v(3 m) - v(z) with z uniform over 3..30 m; v(3 m) = 73.3 arcmin and the mean of
    // b / z over the columns is about b ln(10) / 27 = 18.8 arcmin, so about 54.6 arcmin.
    EXPECT_NEAR(flatError.meanArcmin(), 54.6, 1.5);
    // Every column but the first (3.43 m: 73.3 - 64.1 arcmin) is off by more than 1 arcmin.
    EXPECT_NEAR(flatError.shareBeyond(), 63.0 / 64.0, 1e-12);
    // Depth: a depth 1 % short moves v by v(z) (1 / 0.99 - 1), at most 73.3 x 0.0101 = 0.741
    // arcmin at 3 m; on average less than half of it.
    EXPECT_LT(depthError.maxArcmin, 0.75);
    EXPECT_LT(depthError.meanArcmin(), 0.2);
    EXPECT_EQ(depthError.beyond, 0u);
    EXPECT_GT(flatError.meanArcmin(), 100.0 * depthError.meanArcmin());
}

TEST(StereoError, ThresholdCountsPixelsStrictlyBeyond) {
    // Two columns: 2 m against 2 m (0) and 1 m against 2 m (about 110 arcmin).
    const DepthImage reference = depthImage("ref", 2, 1, [](int, int) { return 2.0f; });
    const DepthImage test = depthImage("test", 2, 1, [](int x, int) { return x == 0 ? 2.0f : 1.0f; });
    const double off = vergenceArcmin(1.0, 0.064) - vergenceArcmin(2.0, 0.064);
    EXPECT_EQ(stereoError(test, reference).shareBeyond(), 0.5);
    EXPECT_EQ(stereoError(test, reference, {.thresholdArcmin = off}).beyond, 0u);  // not beyond: equal
    EXPECT_NEAR(stereoError(test, reference).meanArcmin(), off / 2.0, 1e-12);
    // Pooling two pairs counts every pixel once.
    StereoError pooled = stereoError(test, reference);
    pooled += stereoError(reference, reference);
    EXPECT_EQ(pooled.pixels, 4u);
    EXPECT_NEAR(pooled.meanArcmin(), off / 4.0, 1e-12);
    EXPECT_EQ(pooled.maxArcmin, stereoError(test, reference).maxArcmin);
}

TEST(StereoError, InvalidDepthsAreCountedNotScored) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const DepthImage reference = depthImage("ref", 4, 1, [](int, int) { return 5.0f; });
    const float bad[4] = {nan, -1.0f, 0.0f, 5.0f};  // NaN, negative and zero are invalid
    const DepthImage test = depthImage("test", 4, 1, [&](int x, int) { return bad[x]; });
    const StereoError e = stereoError(test, reference);
    EXPECT_EQ(e.invalidPixels, 3u);
    EXPECT_EQ(e.pixels, 1u);
    EXPECT_EQ(e.sumArcmin, 0.0);
    EXPECT_FALSE(std::isnan(e.meanArcmin()));
    // Invalid in the reference counts the same.
    EXPECT_EQ(stereoError(reference, test).invalidPixels, 3u);
    // Nothing valid: a mean of 0, not NaN.
    const DepthImage none = depthImage("none", 2, 2, [nan](int, int) { return nan; });
    EXPECT_EQ(stereoError(none, none).meanArcmin(), 0.0);
    EXPECT_EQ(stereoError(none, none).shareBeyond(), 0.0);
}

TEST(StereoError, BadInputSaysWhatAndWhere) {
    const DepthImage a = depthImage("a", 4, 4, [](int, int) { return 2.0f; });
    const DepthImage wide = depthImage("wide", 8, 4, [](int, int) { return 2.0f; });
    DepthImage short_ = a;
    short_.name = "short";
    short_.metres.pop_back();
    struct Case {
        const char* name;
        std::function<void()> call;
        const char* message;
    };
    const Case cases[] = {
        {"sizes", [&] { stereoError(wide, a); }, "'wide' against 'a': sizes differ (expected 4x4, got 8x4)"},
        {"data", [&] { stereoError(short_, a); }, "depth image 'short' is 4x4 with 15 depths"},
        {"empty",
         [&] {
             stereoError(DepthImage{"e", 0, 0, {}}, a);
         },
         "depth image 'e' is 0x0"},
        {"interocular", [&] { stereoError(a, a, {.interocularMetres = 0.0}); }, "interocular distance"},
        {"threshold", [&] { stereoError(a, a, {.thresholdArcmin = -1.0}); }, "threshold: expected arc minutes >= 0"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT(c.call, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

}  // namespace
}  // namespace cavewall::metrics
