// The picture of a display configuration (app/bench/display_figure.h): panels, screens, head,
// normals, shared edges, overlaps.
#include "app/bench/display_figure.h"

#include "tests/display/cave_with_overlap.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

namespace cavewall::bench {
namespace {

const PlotSeries& series(const PlotPanel& panel, const std::string& name) {
    for (const PlotSeries& s : panel.series)
        if (s.name == name) return s;
    throw std::runtime_error("no series '" + name + "' in panel '" + panel.title + "'");
}

bool hasLabel(const PlotPanel& panel, const std::string& text) {
    return std::any_of(panel.labels.begin(), panel.labels.end(),
                       [&](const PlotLabel& l) { return l.text.find(text) != std::string::npos; });
}

TEST(DisplayFigure, TwoEqualScalePanelsInMetresWithOneLegend) {
    const Figure figure = displayFigure(config::loadDisplayConfig("cave4"));
    ASSERT_EQ(figure.panels.size(), 2u);
    EXPECT_EQ(figure.panels[0].title, "cave4: from the front (x-y, looking down -z)");
    EXPECT_EQ(figure.panels[1].title, "cave4: from above (x-z, looking down -y)");
    for (const PlotPanel& p : figure.panels) {
        EXPECT_TRUE(p.equalScale);
        EXPECT_EQ(p.x.unit, "m");
        EXPECT_EQ(p.y.unit, "m");
    }
    EXPECT_TRUE(figure.panels[1].y.reversed);  // from above, +z (towards the viewer) is down
    EXPECT_GT(figure.legendWidth, 0);
    EXPECT_NO_THROW(checkFigure(figure, "cave4.png"));
}

TEST(DisplayFigure, EveryScreenHasANamedOutlineAndALabelInBothPanels) {
    const Figure figure = displayFigure(config::loadDisplayConfig("cave4"));
    for (const PlotPanel& p : figure.panels)
        for (const std::string name : {"front", "left", "right", "floor"}) {
            SCOPED_TRACE(p.title + ": " + name);
            EXPECT_EQ(series(p, name).style, SeriesStyle::Outlines);
            ASSERT_EQ(series(p, name).shapes.size(), 1u);
            EXPECT_EQ(series(p, name).shapes[0].size(), 4u);
            EXPECT_TRUE(hasLabel(p, name));
        }
    // From above the floor is its full 3 x 3 m square: corners (x, z) = (-1.5, 1.5) first.
    const std::vector<PlotPoint>& floor = series(figure.panels[1], "floor").shapes[0];
    EXPECT_EQ(floor[0].x, -1.5);
    EXPECT_EQ(floor[0].y, 1.5);
    EXPECT_EQ(floor[2].y, -1.5);
}

TEST(DisplayFigure, TheHeadIsMarkedAndItsViewGoesTowardsTheFrontWall) {
    const Figure figure = displayFigure(config::loadDisplayConfig("cave4"));
    const PlotSeries& front = series(figure.panels[0], kHeadSeries);
    ASSERT_EQ(front.points.size(), 1u);
    EXPECT_EQ(front.points[0].x, 0.0);
    EXPECT_EQ(front.points[0].y, 1.7);  // the default head, 1.7 m up
    const PlotSeries& view = series(figure.panels[1], kViewSeries);
    ASSERT_EQ(view.shapes.size(), 1u);
    EXPECT_LT(view.shapes[0][1].y, view.shapes[0][0].y);  // towards -z, the front wall
    // Looking down -z, the view direction points out of the front view: no arrow there.
    EXPECT_TRUE(series(figure.panels[0], kViewSeries).shapes.empty());
}

// Each normal's arrow starts at its screen's centre and ends nearer the CAVE's middle (x = z = 0
// from above, y = 1.5 from the front): the front sides face inwards. An arrow pointing out of a
// panel is left out: from above the floor's, from the front the front wall's.
TEST(DisplayFigure, Cave4NormalsPointInwards) {
    const Figure figure = displayFigure(config::loadDisplayConfig("cave4"));
    const PlotPoint middle[] = {{0.0, 1.5}, {0.0, 0.0}};
    for (std::size_t p = 0; p < 2; ++p) {
        const PlotSeries& normals = series(figure.panels[p], kNormalSeries);
        EXPECT_EQ(normals.style, SeriesStyle::Arrows);
        ASSERT_EQ(normals.shapes.size(), 3u);
        for (const std::vector<PlotPoint>& arrow : normals.shapes) {
            const auto distance = [&](const PlotPoint& q) { return std::hypot(q.x - middle[p].x, q.y - middle[p].y); };
            EXPECT_LT(distance(arrow[1]), distance(arrow[0]) - 0.4);  // half a metre long, straight in
        }
    }
}

TEST(DisplayFigure, SharedEdgesOverlapsEyesAndTrackingVolumeAreDrawn) {
    config::DisplayConfig c = test::caveWithOverlap();
    c.stereo = config::StereoMode::Separate;
    c.tracking.volume = {glm::dvec3(-2, 0, -2), glm::dvec3(2, 2.5, 2)};
    const Figure figure = displayFigure(c);
    const PlotPanel& front = figure.panels[0];
    EXPECT_EQ(series(front, kSharedEdgeSeries).shapes.size(), 5u);
    ASSERT_EQ(series(front, kOverlapSeries).shapes.size(), 1u);
    EXPECT_EQ(series(front, kTrackingSeries).shapes.size(), 1u);
    // Stereo: both eyes, 64 mm apart, named with the separation.
    const PlotSeries& left = series(front, "left eye (eyes 64 mm apart)");
    const PlotSeries& right = series(front, "right eye (eyes 64 mm apart)");
    EXPECT_NEAR(right.points[0].x - left.points[0].x, 0.064, 1e-12);
}

TEST(DisplayFigure, ScreensSeenEdgeOnBehindEachOtherShareALabel) {
    const Figure figure = displayFigure(config::loadDisplayConfig("powerwall"));
    const PlotPanel& above = figure.panels[1];
    EXPECT_TRUE(hasLabel(above, "lower-left, upper-left"));
    EXPECT_TRUE(hasLabel(above, "lower-right, upper-right"));
}

}  // namespace
}  // namespace cavewall::bench
