// When a view's list is culled (render/occlusion_settings.h): both thresholds must be met, 0
// means no limit, off culls nothing, and the description states the thresholds and the pause.

#include "render/occlusion_settings.h"

#include <gtest/gtest.h>

namespace cavewall::render {
namespace {

TEST(OcclusionSettings, CullsOnlyListsMeetingBothThresholds) {
    const OcclusionSettings s{.on = true, .minTriangles = 1000, .minDraws = 10};
    EXPECT_TRUE(s.culls(1000, 10));
    EXPECT_FALSE(s.culls(999, 10'000));
    EXPECT_FALSE(s.culls(10'000'000, 9));
    EXPECT_FALSE((OcclusionSettings{.on = false, .minTriangles = 0, .minDraws = 0}.culls(1'000'000, 1'000)));
    EXPECT_TRUE((OcclusionSettings{.on = true, .minTriangles = 0, .minDraws = 0}.culls(0, 0)));
}

TEST(OcclusionSettings, DescriptionNamesTheThresholdsOrOff) {
    EXPECT_EQ(describe(OcclusionSettings{.on = true, .minTriangles = 1234, .minDraws = 56, .minSavedShare = 0.25}),
              "on, in views whose list submits at least 1234 triangles in at least 56 draws, paused for 16 frames "
              "in a view where it saved under 25 % of them");
    EXPECT_EQ(describe(OcclusionSettings{.on = true, .minTriangles = 1, .minDraws = 2, .minSavedShare = 0.0}),
              "on, in views whose list submits at least 1 triangles in at least 2 draws");
    EXPECT_EQ(describe(OcclusionSettings{.on = false}), "off");
}

}  // namespace
}  // namespace cavewall::render
