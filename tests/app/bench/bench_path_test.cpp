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

// A warp-morph spans the stretch of the walk it spans in `cavewall run`: 0.5 s at 1 m/s is half a
// metre, which a path walked at 50 m/s covers in 0.01 s; a path walked slower keeps the 0.5 s.
TEST(BenchPath, AWarpMorphSpansTheSameStretchOfTheWalkAtAnyPace) {
    EyePath path;
    path.pace = 50.0;
    EXPECT_DOUBLE_EQ(morphSecondsOn(path, 0.5, 1.0), 0.01);
    path.pace = 1.0;
    EXPECT_DOUBLE_EQ(morphSecondsOn(path, 0.5, 1.0), 0.5);
    path.pace = 0.5;
    EXPECT_DOUBLE_EQ(morphSecondsOn(path, 0.5, 1.0), 0.5);
}

}  // namespace
}  // namespace cavewall::bench
