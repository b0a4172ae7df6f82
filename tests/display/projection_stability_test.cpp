#include "display/projection_stability.h"

#include <gtest/gtest.h>

#include <iostream>

namespace cavewall::display {
namespace {

void expectAllPass(const std::vector<StabilityRow>& rows) {
    ASSERT_FALSE(rows.empty());
    for (const StabilityRow& r : rows) {
        SCOPED_TRACE(r.name);
        std::cout << r.name << ": float " << r.floatError << ", cavewall " << r.cavewallError << " " << r.unit << "\n";
        EXPECT_LE(r.cavewallError, r.tolerance);
    }
}

TEST(ProjectionStability, EyeDistancesFromOneNanometreToThousandKilometres) {
    const auto rows = eyeDistanceCases();
    expectAllPass(rows);
    // The contrast is real: float cannot even place an eye 1 nm from a screen 1.5 m from the
    // origin (its step there is 1.2e-7 m), so the naive float path is far off.
    EXPECT_GT(rows.front().floatError, 1.0);
}

TEST(ProjectionStability, WorldOffsetsToTenThousandKilometres) {
    const auto rows = worldOffsetCases();
    expectAllPass(rows);
    // Float world maths at 1e7 m has a 1 m step: the screen itself is only 3 m wide.
    EXPECT_GT(rows.back().floatError, 10.0);
}

TEST(ProjectionStability, ReversedZKeepsDepthOrderToOneBillion) {
    const auto rows = depthOrderCases();
    expectAllPass(rows);
    // Conventional [-1, 1] float depth collapses most of a 1e9 range.
    EXPECT_GT(rows[2].floatError, 100.0);
}

TEST(ProjectionStability, MillimetreAndKilometreScreens) { expectAllPass(screenSizeCases()); }

TEST(ProjectionStability, WarpFallsBackBeforeItsFloatErrorShows) {
    const auto rows = warpConditionCases();
    expectAllPass(rows);
    // Without the guard, the float warp 1 µm from the wall plane is visibly off; with it,
    // cavewall draws geometry there instead.
    EXPECT_GT(rows.back().condition, 1e4);
    EXPECT_GT(rows.back().floatError, rows.back().tolerance);
    EXPECT_LT(rows.front().condition, 100.0);
}

}  // namespace
}  // namespace cavewall::display
