// The plan's overview figure (app/bench/plan_figure.h): storeys, layers and axes.
#include "app/bench/plan_figure.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::bench {
namespace {

using ::testing::HasSubstr;

scenes::Cell cell(const std::string& name, double x0, double floorY) {
    return {name, {{x0, 0.0}, {x0 + 4.0, 0.0}, {x0 + 4.0, 3.0}, {x0, 3.0}}, floorY};
}

scenes::VirtualWall wall(double x, double y, int front, int back) {
    scenes::VirtualWall w;
    w.name = "w";
    w.lowerLeft = {x, y, 0.0};
    w.lowerRight = {x, y, 3.0};
    w.upperLeft = {x, y + 2.5, 0.0};
    w.cells = {front, back};
    return w;
}

// Two cells on the ground floor with a wall between them, one cell 3.5 m up (a second storey)
// and one 0.3 m up (a raised part of the ground floor: less than the 1 m gap, same storey).
scenes::SceneDescription twoStoreys() {
    scenes::SceneDescription d;
    d.name = "lab";
    d.cells = {cell("a", 0.0, 0.0), cell("b", 4.0, 0.3), cell("up", 0.0, 3.5)};
    d.walls = {wall(4.0, 0.0, 0, 1)};
    d.realWalls = {{"r", {0.0, 3.5, 0.0}, {4.0, 3.5, 0.0}, {0.0, 6.0, 0.0}}};
    return d;
}

walls::Plan twoZones() {
    walls::Plan plan;
    walls::Zone texture;
    texture.cell = 0;
    texture.kind = walls::ZoneKind::Texture;
    texture.floorPolygon = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
    walls::Zone geometry = texture;
    geometry.kind = walls::ZoneKind::Geometry;
    geometry.floorPolygon = {{3, 0}, {4, 0}, {4, 3}, {3, 3}};
    plan.zones = {texture, geometry};
    return plan;
}

const PlotSeries& layer(const PlotPanel& panel, const std::string& name) {
    for (const PlotSeries& s : panel.series)
        if (s.name.rfind(name, 0) == 0) return s;
    throw std::runtime_error("no series " + name);
}

TEST(PlanFigure, StoreysAreFloorHeightsAtLeastAGapApart) {
    EXPECT_EQ(storeyFloors(twoStoreys()), (std::vector<double>{0.0, 3.5}));
    EXPECT_EQ(storeyFloors(twoStoreys(), 0.2), (std::vector<double>{0.0, 0.3, 3.5}));
    EXPECT_EQ(storeyFloors(scenes::SceneDescription{}), (std::vector<double>{0.0}));
}

TEST(PlanFigure, OnePanelPerStoreyWithItsOwnCellsWallsAndZones) {
    const Figure figure = planFigure(twoZones(), twoStoreys(), "lab");
    ASSERT_EQ(figure.panels.size(), 2u);
    const PlotPanel& ground = figure.panels[0];
    const PlotPanel& upper = figure.panels[1];
    EXPECT_EQ(ground.title, "lab: storey 1 of 2, floor y 0.00 m, 2 cells, 1 virtual walls");
    EXPECT_EQ(upper.title, "lab: storey 2 of 2, floor y 3.50 m, 1 cells, 0 virtual walls");
    EXPECT_EQ(layer(ground, "cell").shapes.size(), 2u);
    EXPECT_EQ(layer(upper, "cell").shapes.size(), 1u);
    EXPECT_EQ(layer(ground, "virtual wall").shapes.size(), 1u);
    EXPECT_EQ(layer(ground, "texture zone").shapes.size(), 1u);
    EXPECT_EQ(layer(ground, "geometry zone").shapes.size(), 1u);
    EXPECT_TRUE(layer(upper, "geometry zone").shapes.empty());
    // The real wall stands on the upper floor (its foot at y 3.5).
    EXPECT_TRUE(layer(ground, "real wall").shapes.empty());
    ASSERT_EQ(layer(upper, "real wall").shapes.size(), 1u);
    EXPECT_EQ(layer(upper, "real wall").shapes[0][1].x, 4.0);
    // The wall's footprint in the top view: (x, z) of its lower corners.
    const std::vector<PlotPoint>& w = layer(ground, "virtual wall").shapes[0];
    EXPECT_EQ(w[0].x, 4.0);
    EXPECT_EQ(w[1].y, 3.0);
}

TEST(PlanFigure, AxesAreInMetresAtOneScaleWithZDownwards) {
    const Figure figure = planFigure(twoZones(), twoStoreys(), "lab");
    const PlotPanel& panel = figure.panels[0];
    EXPECT_EQ(axisLabel(panel.x), "x (m)");
    EXPECT_THAT(axisLabel(panel.y), HasSubstr("(m)"));
    EXPECT_TRUE(panel.y.reversed);
    EXPECT_TRUE(panel.equalScale);
    EXPECT_GT(figure.legendWidth, 0);
    EXPECT_EQ(figure.columns, 2);
    const std::string script = gnuplotScript(figure, "plan.png");
    EXPECT_THAT(script, HasSubstr("title 'texture zone (one texture shown)'"));
    EXPECT_THAT(script, HasSubstr("title 'virtual wall'"));
    EXPECT_THAT(script, HasSubstr("set multiplot layout 1,2"));
}

}  // namespace
}  // namespace cavewall::bench
