#include "app/bench/path.h"

#include <gtest/gtest.h>

namespace cavewall::bench {
namespace {

TEST(BenchPath, PiecesGetFramesInProportionToTheirLength) {
    // A ground floor's 300 m and an upper floor's 100 m: three frames to one, all 40 used.
    EXPECT_EQ(framesPerPiece({300.0, 100.0}, 40), (std::vector<long>{30, 10}));
    // One piece takes every frame.
    EXPECT_EQ(framesPerPiece({12.0}, 7), (std::vector<long>{7}));
    // A short piece still gets two frames (it is walked), while frames last.
    EXPECT_EQ(framesPerPiece({1000.0, 1.0}, 50), (std::vector<long>{48, 2}));
    EXPECT_EQ(framesPerPiece({1.0, 1000.0}, 50), (std::vector<long>{2, 48}));
    EXPECT_EQ(framesPerPiece({5.0, 5.0, 5.0}, 2), (std::vector<long>{2, 0, 0}));
}

}  // namespace
}  // namespace cavewall::bench
