// What `cavewall display` reports about a configuration (display/display_summary.h).
#include "display/display_summary.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

namespace cavewall::display {
namespace {

using ::testing::HasSubstr;

// cave4, mono, with a 1.5 x 1 m screen in the front wall's plane, its left 0.5 m over the front wall
// from 1 to 2 m up: the two cover 0.5 x 1 = 0.5 m² twice.
config::DisplayConfig caveWithOverlap() {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    config::Screen extra = c.screens[0];
    extra.name = "extra";
    extra.lowerLeft = {1.0, 1.0, -1.5};
    extra.lowerRight = {2.5, 1.0, -1.5};
    extra.upperLeft = {1.0, 2.0, -1.5};
    c.screens.push_back(extra);
    c.stereo = config::StereoMode::Mono;  // the preset is stereo
    return c;
}

TEST(DisplaySummary, Cave4NormalsPointInwardsAndPixelsPerDegreeComeFromTheHead) {
    const std::vector<ScreenFacts> screens = screenFacts(config::loadDisplayConfig("cave4"));
    ASSERT_EQ(screens.size(), 4u);
    const glm::dvec3 middle(0.0, 1.5, 0.0);  // the centre of the 3 m cube
    for (const ScreenFacts& s : screens) {
        SCOPED_TRACE(s.name);
        EXPECT_GT(glm::dot(s.basis.normal, middle - s.centre), 1.49);  // 1.5 m: straight at it
        EXPECT_DOUBLE_EQ(s.basis.width, 3.0);
    }
    // The front wall is 1.5 m from the head [0, 1.7, 0] and 3 m / 1024 pixels wide:
    // 1.5 / (3 / 1024) * pi / 180 = 8.936 pixels per degree; the floor, 1.7 m below, 10.13.
    EXPECT_NEAR(screens[0].pixelsPerDegree, 8.936, 1e-3);
    EXPECT_NEAR(screens[3].pixelsPerDegree, 10.128, 1e-3);
    EXPECT_EQ(screens[0].upperRight, glm::dvec3(1.5, 3.0, -1.5));
}

TEST(DisplaySummary, Cave4SharesFiveEdgesAndOverlapsNowhere) {
    const std::vector<ScreenFacts> screens = screenFacts(config::loadDisplayConfig("cave4"));
    const std::vector<SharedEdge> edges = sharedEdges(screens);
    // front-left, front-right, front-floor, left-floor, right-floor; left and right face each
    // other 3 m apart and share nothing.
    ASSERT_EQ(edges.size(), 5u);
    EXPECT_EQ(edges[0].a, 0);
    EXPECT_EQ(edges[0].b, 1);
    EXPECT_NEAR(glm::length(edges[0].to - edges[0].from), 3.0, 1e-12);
    EXPECT_NEAR(edges[0].from.x, -1.5, 1e-12);
    EXPECT_NEAR(edges[0].from.z, -1.5, 1e-12);
    for (const SharedEdge& e : edges) EXPECT_FALSE(e.a == 1 && e.b == 2);
    EXPECT_TRUE(screenOverlaps(screens).empty());
}

TEST(DisplaySummary, ScreensInOnePlaneCoveringTheSameAreaAreAnOverlap) {
    const std::vector<ScreenOverlap> overlaps = screenOverlaps(screenFacts(caveWithOverlap()));
    ASSERT_EQ(overlaps.size(), 1u);
    EXPECT_EQ(overlaps[0].a, 0);
    EXPECT_EQ(overlaps[0].b, 4);
    EXPECT_NEAR(overlaps[0].area, 0.5, 1e-9);
    for (const glm::dvec3& p : overlaps[0].polygon) {
        EXPECT_NEAR(p.z, -1.5, 1e-12);
        EXPECT_GE(p.x, 1.0 - 1e-12);
        EXPECT_LE(p.x, 1.5 + 1e-12);
    }
}

TEST(DisplaySummary, TilesSideBySideShareEdgesButDoNotOverlap) {
    const std::vector<ScreenFacts> screens = screenFacts(config::loadDisplayConfig("powerwall"));
    EXPECT_EQ(sharedEdges(screens).size(), 4u);  // the 2 x 2 grid's inner cross, in four halves
    EXPECT_TRUE(screenOverlaps(screens).empty());
}

TEST(DisplaySummary, TextNamesEveryScreenTheModesAndTheFindings) {
    std::ostringstream out;
    printDisplaySummary(out, caveWithOverlap(), "lab.json");
    const std::string text = out.str();
    EXPECT_THAT(text, HasSubstr("display 'cave4' (lab.json): 5 screens, stereo mono, near 0.05 m, far infinite"));
    EXPECT_THAT(text, HasSubstr("  front   3.00 x 3.00    1024 x 1024  [0, 0, 1]                 8.9\n"));
    EXPECT_THAT(text, HasSubstr("  left    3.00 x 3.00    1024 x 1024  [1, 0, 0]"));
    EXPECT_THAT(text, HasSubstr("default head [0, 1.7, 0] m\n"));
    EXPECT_THAT(text, HasSubstr("tracking: caveFromTracker identity, latency 0 ms"));
    EXPECT_THAT(text, HasSubstr("shared edge: front and left, "));
    EXPECT_THAT(text, HasSubstr("overlap: front and extra cover the same 0.500 m²"));
}

TEST(DisplaySummary, StereoListsBothEyesAndACalibrationItsRows) {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    c.stereo = config::StereoMode::Separate;
    c.tracking.caveFromTracker[3] = glm::dvec4(0.1, 0.0, -0.2, 1.0);  // translation column
    std::ostringstream out;
    printDisplaySummary(out, c, "cave4.json");
    // Eyes 32 mm either side of the head along +x (looking down -z).
    EXPECT_THAT(out.str(), HasSubstr("eyes 64 mm apart: left [-0.032, 1.7, 0], right [0.032, 1.7, 0]"));
    EXPECT_THAT(out.str(), HasSubstr("caveFromTracker [[1, 0, 0, 0.1], [0, 1, 0, 0], [0, 0, 1, -0.2], [0, 0, 0, 1]]"));
}

}  // namespace
}  // namespace cavewall::display
