#include "app/cluster.h"

#include <gtest/gtest.h>

namespace cavewall::app {
namespace {

TEST(FrameState, RoundTripsExactly) {
    FrameState s;
    s.frame = 123456789012345ull;
    s.time = 1.0 / 3.0;
    s.headPosition = {0.1, 1.7, -0.3};
    s.headOrientation = glm::angleAxis(0.3, glm::normalize(glm::dvec3(0.2, 1, 0.1)));
    s.worldFromCave[3] = glm::dvec4(1e7, 2.5, -3e6, 1);
    s.payload = {1, 2, 3, 250};
    s.quit = true;
    FrameState back;
    ASSERT_TRUE(decode(encode(s), back));
    // Bit-exact: every rank must render the same frame as rank 0.
    EXPECT_EQ(back.frame, s.frame);
    EXPECT_EQ(back.time, s.time);
    EXPECT_EQ(back.headPosition, s.headPosition);
    EXPECT_EQ(back.headOrientation, s.headOrientation);
    EXPECT_EQ(back.worldFromCave, s.worldFromCave);
    EXPECT_EQ(back.payload, s.payload);
    EXPECT_TRUE(back.quit);
}

TEST(FrameState, RejectsTruncatedAndPaddedBytes) {
    FrameState s;
    s.payload = {9, 9};
    const auto bytes = encode(s);
    FrameState back;
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        SCOPED_TRACE(n);
        EXPECT_FALSE(decode(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + static_cast<long>(n)), back));
    }
    auto padded = bytes;
    padded.push_back(0);
    EXPECT_FALSE(decode(padded, back));
}

}  // namespace
}  // namespace cavewall::app
