// Separable convolution and percentiles under the image metrics (metrics/image_filter.h).
#include "metrics/image_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace cavewall::metrics {
namespace {

TEST(ImageFilter, GaussianKernelIsNormalisedAndSymmetric) {
    const std::vector<float> k = gaussianKernel(1.5, 5);
    ASSERT_EQ(k.size(), 11u);
    EXPECT_NEAR(std::accumulate(k.begin(), k.end(), 0.0), 1.0, 1e-6);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(k[i], k[10 - i]);
    // Neighbouring taps differ by exp(-(2i + 1) / (2 sigma²)): exp(-1 / 4.5) from 0 to 1.
    EXPECT_NEAR(k[6] / k[5], std::exp(-1.0 / 4.5), 1e-6);
}

TEST(ImageFilter, SeparableFilterMatchesTheDirectSumWithClampedEdges) {
    Plane in(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) in.at(x, y) = static_cast<float>((x * 7 + y * 3) % 11);
    const std::vector<float> h{0.25f, 0.5f, 0.25f}, v{-1.0f, 0.0f, 1.0f};
    const Plane out = convolveSeparable(in, h, v);
    const auto clamped = [&](int x, int y) { return in.at(std::clamp(x, 0, 6), std::clamp(y, 0, 4)); };
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            double expected = 0.0;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) expected += v[j + 1] * h[i + 1] * clamped(x + i, y + j);
            EXPECT_NEAR(out.at(x, y), expected, 1e-5) << x << "," << y;
        }
    // An empty kernel leaves that direction alone.
    EXPECT_EQ(convolveSeparable(in, {}, {}).values, in.values);
}

TEST(ImageFilter, PercentileIsTheNearestRank) {
    std::vector<float> v(20);
    std::iota(v.begin(), v.end(), 1.0f);  // 1..20
    EXPECT_EQ(percentile(v, 0.0), 1.0);
    EXPECT_EQ(percentile(v, 0.5), 10.0);   // ceil(10) = 10th
    EXPECT_EQ(percentile(v, 0.95), 19.0);  // ceil(19) = 19th
    EXPECT_EQ(percentile(v, 0.96), 20.0);  // ceil(19.2) = 20th
    EXPECT_EQ(percentile(v, 1.0), 20.0);
    EXPECT_EQ(percentile(std::vector<float>{}, 0.5), 0.0);
}

TEST(ImageFilter, PercentilesAgreeWithSeparateCalls) {
    std::vector<float> v(101);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>((i * 37) % 101);  // 0..100 shuffled
    const std::vector<double> qs{0.0, 0.05, 0.5, 0.95, 0.99, 1.0};
    const std::vector<double> p = percentiles(v, qs);
    ASSERT_EQ(p.size(), qs.size());
    for (std::size_t i = 0; i < qs.size(); ++i) EXPECT_EQ(p[i], percentile(v, qs[i])) << qs[i];
    // Nearest rank of 101 values 0..100: ceil(0.95 * 101) = 96th smallest = 95.
    EXPECT_EQ(p[3], 95.0);
}

}  // namespace
}  // namespace cavewall::metrics
