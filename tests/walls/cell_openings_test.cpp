// The openings of each cell (walls/cell_openings.h) and the portal sets of a frame over a
// scene's objects.
#include "walls/cell_openings.h"

#include <gtest/gtest.h>

namespace cavewall::walls {
namespace {

// Four 1 m cells in a row, 0 | 1 | 2 | 3 along x (z in [0, 1]), walls w0 (0|1), w1 (1|2), w2
// (2|3) at x = 1, 2, 3. Real walls close cell 0 but for z = 1, x in [0.5, 1]; the other cells
// are open all round.
struct Row {
    scenes::SceneDescription description;
    Plan plan;
    Row() {
        for (int c = 0; c < 4; ++c) description.cells.push_back({"c", {{c, 0}, {c + 1, 0}, {c + 1, 1}, {c, 1}}, 0.0});
        auto real = [&](glm::dvec2 a, glm::dvec2 b) {
            description.realWalls.push_back({"r", {a.x, 0, a.y}, {b.x, 0, b.y}, {a.x, 3, a.y}});
        };
        real({0, 0}, {1, 0});
        real({0, 0}, {0, 1});
        real({0, 1}, {0.5, 1});
        for (int w = 0; w < 3; ++w) {
            PlannedWall p;
            p.id = w;
            const double x = w + 1.0;
            p.quad = {{x, 0.0, 0.0}, {x, 0.0, 1.0}, {x, 2.0, 0.0}};
            p.cells = {w, w + 1};
            plan.walls.push_back(p);
            description.walls.push_back({"w", p.quad.lowerLeft, p.quad.lowerRight, p.quad.upperLeft, p.cells});
        }
    }
};

// Wall w looked through from its front (cells[0]) is portal 2w, from its back 2w + 1; the open
// boundary parts follow the six.
TEST(CellOpenings, ACellsWallsFacingItThenItsOpenBoundary) {
    const Row row;
    const CellOpenings cells(row.plan, row.description, scenes::Scene{});
    // Cell 0: w0 and its one open part, z = 1 for x in [0.5, 1], reaching far up and down.
    EXPECT_EQ(cells.openings(0), (std::vector<int>{0, 6}));
    const display::ScreenQuad& open = cells.portals().at(6);
    EXPECT_EQ(glm::dvec2(open.lowerLeft.x, open.lowerLeft.z), glm::dvec2(1.0, 1.0));  // normal towards -z
    EXPECT_EQ(glm::dvec2(open.lowerRight.x, open.lowerRight.z), glm::dvec2(0.5, 1.0));
    EXPECT_LT(open.lowerLeft.y, -100.0);
    EXPECT_GT(open.upperLeft.y, 100.0);
    // Cell 1: w0 from its back, w1 from its front, its two open sides.
    EXPECT_EQ(cells.openings(1).size(), 4u);
    EXPECT_EQ(cells.openings(1)[0], 1);
    EXPECT_EQ(cells.openings(1)[1], 2);
    // Cell 3: w2 from its back and three open sides.
    EXPECT_EQ(cells.openings(3).size(), 4u);
    EXPECT_TRUE(cells.openings(-1).empty());
    EXPECT_TRUE(cells.openings(4).empty());
    // Each wall's portal faces the cell it is looked through from.
    for (int w = 0; w < 3; ++w)
        for (int s = 0; s < 2; ++s) {
            const display::ScreenQuad& q = cells.portals().at(2 * w + s);
            const glm::dvec3 normal = glm::cross(q.lowerRight - q.lowerLeft, q.upperLeft - q.lowerLeft);
            const int cell = row.plan.walls[w].cells[s];
            EXPECT_GT(glm::dot(normal, glm::dvec3(cell + 0.5, 1.0, 0.5) - q.lowerLeft), 0.0) << w << " " << s;
        }
}

TEST(CellOpenings, AViewSeesThroughTheOpeningsOfItsCellOnly) {
    const Row row;
    const CellOpenings cells(row.plan, row.description, scenes::Scene{});
    PortalSets sets;
    sets.portals = cells.portals();
    sets.chains = {{0}, {6}};
    sets.sets = {{0, 1}};
    sets.objectSet = {0, 0, 0};
    // From (0.75, 1.7, 0.5): a box past the open part is seen through it, one past w0 through w0,
    // one past the real walls west of the cell through neither.
    const render::PortalView view(sets, {0.75, 1.7, 0.5});
    scenes::Bounds north, east, west;
    north.add({0.6, 0.0, 3.0});
    north.add({1.0, 1.0, 3.5});
    east.add({1.5, 0.0, 0.4});
    east.add({1.8, 1.0, 0.6});
    west.add({-3.0, 0.0, 0.2});
    west.add({-2.5, 1.0, 0.8});
    EXPECT_TRUE(view.visible(0, north));
    EXPECT_TRUE(view.visible(1, east));
    EXPECT_FALSE(view.visible(2, west));
}

scenes::Object object(int cell, std::vector<int> more = {}, scenes::Role role = scenes::Role::Content) {
    scenes::Object o;
    o.cell = cell;
    o.moreCells = std::move(more);
    o.role = role;
    return o;
}

TEST(CellOpenings, FrameSetsTestTheObjectsOfOtherDrawnCells) {
    const Row row;
    scenes::Scene scene;
    scene.objects = {object(0),
                     object(1),
                     object(2),
                     object(1, {2}),
                     object(0, {1}),
                     object(-1),
                     object(1, {}, scenes::Role::Structure),
                     object(7)};
    // Over or under the eye cell's floor (another storey, seen through a void); in its wall band
    // (within half a metre of its floor box: in or on its walls); beside that.
    scenes::Object above = object(1), inWall = object(1), beside = object(1);
    above.worldBounds.add({0.2, 5.0, 0.2});
    above.worldBounds.add({0.4, 6.0, 0.4});
    inWall.worldBounds.add({1.3, 0.0, 0.2});
    inWall.worldBounds.add({1.45, 1.0, 0.4});
    beside.worldBounds.add({1.55, 0.0, 0.2});
    beside.worldBounds.add({1.8, 1.0, 0.4});
    scene.objects.push_back(above);
    scene.objects.push_back(inWall);
    scene.objects.push_back(beside);
    const CellOpenings cells(row.plan, row.description, scene);
    PortalSets sets;
    cells.frameSets(0, {true, true, false, true}, scene, sets);
    ASSERT_EQ(sets.objectSet.size(), scene.objects.size());
    // Cell 0's openings, w0 and its open part, one chain each.
    EXPECT_EQ(sets.portals, (std::vector<display::ScreenQuad>{cells.portals().at(0), cells.portals().at(6)}));
    EXPECT_EQ(sets.chains, (std::vector<std::vector<int>>{{0}, {1}}));
    EXPECT_EQ(sets.sets, (std::vector<std::vector<int>>{{0, 1}}));
    EXPECT_EQ(sets.objectSet, (std::vector<int>{-1, 0, -1, 0, -1, -1, -1, -1, -1, -1, 0}));
    // (the eye's cell, a neighbour, a cell not drawn, drawn through cell 1, reaching the eye's
    // cell, no cell, structure, a cell the description does not have, above, in its wall, beside)

    cells.frameSets(-1, {true, true, true, true}, scene, sets);  // outside every cell
    EXPECT_TRUE(sets.portals.empty());
    EXPECT_EQ(sets.objectSet, std::vector<int>(scene.objects.size(), -1));
}

// A window: a pane of glass (a blended object) in cell 0's west wall, x in [-0.06, -0.04], is
// an opening of cell 0 facing into it; a box west of the wall is seen through it, one far south
// of it is not.
TEST(CellOpenings, GlassInTheEyeCellsWallsIsAnOpening) {
    const Row row;
    scenes::Scene scene;
    scene.materials.push_back({});
    scene.materials.back().alphaMode = scenes::AlphaMode::Blend;
    scene.meshes.emplace_back();
    scene.meshes.back().material = 0;
    scenes::Object pane = object(-1), west = object(1), south = object(1);
    pane.worldBounds.add({-0.06, 1.0, 0.3});
    pane.worldBounds.add({-0.04, 2.0, 0.7});
    west.worldBounds.add({-3.0, 1.2, 0.4});
    west.worldBounds.add({-2.8, 1.6, 0.6});
    south.worldBounds.add({-3.0, 1.2, -12.2});
    south.worldBounds.add({-2.8, 1.6, -12.0});
    scene.objects = {pane, west, south};
    const CellOpenings cells(row.plan, row.description, scene);
    // Cell 0: w0, its open part, then the window; no other cell has one.
    ASSERT_EQ(cells.openings(0).size(), 3u);
    EXPECT_EQ(cells.openings(0)[2], 7);
    EXPECT_EQ(cells.openings(1).size(), 4u);
    PortalSets sets;
    cells.frameSets(0, {true, true, true, true}, scene, sets);
    ASSERT_EQ(sets.portals.size(), 3u);
    EXPECT_EQ(sets.sets, (std::vector<std::vector<int>>{{0, 1, 2}}));
    EXPECT_EQ(sets.chains.back(), std::vector<int>{2});
    const display::ScreenQuad& q = sets.portals.back();
    const glm::dvec3 normal = glm::cross(q.lowerRight - q.lowerLeft, q.upperLeft - q.lowerLeft);
    EXPECT_GT(normal.x, 0.0);  // into the cell
    EXPECT_EQ(sets.objectSet, (std::vector<int>{-1, 0, 0}));
    const render::PortalView view(sets, {0.5, 1.5, 0.5});
    EXPECT_TRUE(view.visible(1, west.worldBounds));
    EXPECT_FALSE(view.visible(2, south.worldBounds));
    // A pane straddling the cell's edge (the boundary drawn through the middle of the wall) too.
    scene.objects[0].worldBounds = {};
    scene.objects[0].worldBounds.add({-0.01, 1.0, 0.3});
    scene.objects[0].worldBounds.add({0.01, 2.0, 0.7});
    const CellOpenings straddling(row.plan, row.description, scene);
    straddling.frameSets(0, {true, true, true, true}, scene, sets);
    ASSERT_EQ(sets.portals.size(), 3u);
    EXPECT_TRUE(render::PortalView(sets, {0.5, 1.5, 0.5}).visible(1, west.worldBounds));
    // Without glass the same box is hidden by the real wall.
    scene.materials.back().alphaMode = scenes::AlphaMode::Opaque;
    const CellOpenings opaque(row.plan, row.description, scene);
    opaque.frameSets(0, {true, true, true, true}, scene, sets);
    EXPECT_EQ(sets.portals.size(), 2u);
    EXPECT_FALSE(render::PortalView(sets, {0.5, 1.5, 0.5}).visible(1, west.worldBounds));
}

TEST(CellOpenings, ACellWithoutOpeningsTestsNothing) {
    Row row;
    row.description.realWalls.push_back({"r", {0.5, 0, 1}, {1, 0, 1}, {0.5, 3, 1}});  // close the gap
    row.plan.walls.clear();
    row.description.walls.clear();
    row.description.realWalls.push_back({"r", {1, 0, 0}, {1, 0, 1}, {1, 3, 0}});
    const CellOpenings cells(row.plan, row.description, scenes::Scene{});
    EXPECT_TRUE(cells.openings(0).empty());
    scenes::Scene scene;
    scene.objects = {object(1)};
    PortalSets sets;
    cells.frameSets(0, {true, true, true, true}, scene, sets);
    EXPECT_EQ(sets.objectSet, std::vector<int>{-1});
}

}  // namespace
}  // namespace cavewall::walls
