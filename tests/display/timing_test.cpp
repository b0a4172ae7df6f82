// The one percentile of the project (display/timing.h): nearest rank, always a sample.
#include "display/timing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace cavewall::display {
namespace {

TEST(Percentile, NearestRankOnOneToOneHundred) {
    std::vector<double> v(100);
    std::iota(v.begin(), v.end(), 1.0);
    std::reverse(v.begin(), v.end());  // unsorted input
    // Nearest rank on 1..100: the p-th percentile is the ceil(100 p)-th smallest, i.e. 100 p.
    EXPECT_EQ(percentile(v, 0.50), 50.0);
    EXPECT_EQ(percentile(v, 0.95), 95.0);
    EXPECT_EQ(percentile(v, 0.99), 99.0);
    EXPECT_EQ(percentile(v, 1.00), 100.0);
    EXPECT_EQ(percentile(v, 0.0), 1.0);    // rank clamped to 1: the smallest
    EXPECT_EQ(percentile(v, 0.001), 1.0);  // ceil(0.1) = 1
    EXPECT_EQ(percentile(v, 0.011), 2.0);  // ceil(1.1) = 2
}

TEST(Percentile, MedianIsASampleNeverAnInterpolation) {
    EXPECT_EQ(median(std::vector<double>{}), 0.0);
    EXPECT_EQ(median(std::vector<double>{7.0}), 7.0);
    EXPECT_EQ(median(std::vector<double>{3.0, 1.0, 2.0}), 2.0);
    // Even counts: ceil(n / 2) is the lower middle (an interpolated median would give 2.5 and 15).
    EXPECT_EQ(median(std::vector<double>{4.0, 1.0, 3.0, 2.0}), 2.0);
    EXPECT_EQ(median(std::vector<double>{20.0, 10.0}), 10.0);
}

TEST(MsSince, CountsForwardInMilliseconds) {
    const auto start = std::chrono::steady_clock::now() - std::chrono::milliseconds(250);
    // At least the 250 ms put behind `start` (a steady clock never goes back); no upper bound
    // is asserted, a loaded machine may pause between the two calls.
    EXPECT_GE(msSince(start), 250.0);
}

}  // namespace
}  // namespace cavewall::display
