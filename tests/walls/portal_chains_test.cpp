// The chains of walls each cell drawn as geometry is seen through (walls/portal_chains.h), and
// the portal sets of a frame over a scene's objects.
#include "walls/portal_chains.h"

#include <gtest/gtest.h>

namespace cavewall::walls {
namespace {

using Chains = std::vector<std::vector<int>>;

// Four 1 m cells in a row, 0 | 1 | 2 | 3 along x (z in [0, 1]), walls w0 (0|1), w1 (1|2), w2
// (2|3) at x = 1, 2, 3; cell 3 also sees cell 0 through an open boundary (a Geometry entry, as
// if joined around the row). From cell 0, the far wall w1 of neighbour 1 is a beyond side, and
// w2 one at the second level. Real walls close cell 0 but for z = 1, x in [0.5, 1]; the other
// cells are open all round.
struct Row {
    scenes::SceneDescription description;
    Plan plan;
    VisibilityTable table;
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
        BeyondSide first;
        first.eyeCell = 0;
        first.viaWall = 0;
        first.side.wall = 1;
        first.side.side = 0;  // cell 1 in front: the cell behind is 2
        BeyondSide second = first;
        second.viaWall = 1;
        second.side.wall = 2;
        second.parent = 0;
        plan.beyond = {first, second};
        table.cellCount = 4;
        table.entries.assign(16, CellVisibility::Hidden);
        table.walls.resize(16);
        table.entries[3 * 4 + 0] = table.entries[0 * 4 + 3] = CellVisibility::Geometry;
    }
};

// Wall w looked through from its front (cells[0]) is portal 2w, from its back 2w + 1.
TEST(PortalChains, NeighboursThroughTheirWallsAndCellsBeyondThroughTheChain) {
    const Row row;
    const PortalChains chains(row.plan, row.table, row.description);
    EXPECT_EQ(chains.chains(0, 1), (Chains{{0}}));
    EXPECT_EQ(chains.chains(0, 2), (Chains{{0, 2}}));
    EXPECT_EQ(chains.chains(1, 0), (Chains{{1}}));
    EXPECT_EQ(chains.chains(1, 2), (Chains{{2}}));
    EXPECT_EQ(chains.chains(2, 3), (Chains{{4}}));
    // Each wall's portal faces the cell it is looked through from.
    for (int w = 0; w < 3; ++w)
        for (int s = 0; s < 2; ++s) {
            const display::ScreenQuad& q = chains.portals().at(2 * w + s);
            const glm::dvec3 normal = glm::cross(q.lowerRight - q.lowerLeft, q.upperLeft - q.lowerLeft);
            const int cell = row.plan.walls[w].cells[s];
            EXPECT_GT(glm::dot(normal, glm::dvec3(cell + 0.5, 1.0, 0.5) - q.lowerLeft), 0.0) << w << " " << s;
        }
    // Without test: the eye's own cell, and out of range.
    EXPECT_TRUE(chains.chains(1, 1).empty());
    EXPECT_TRUE(chains.chains(-1, 1).empty());
    EXPECT_TRUE(chains.chains(0, 4).empty());
}

TEST(PortalChains, CellsATextureShowsAreSeenThroughItsWall) {
    Row row;
    row.table.walls[0 * 4 + 3] = {0};  // cell 3 shows in w0's textures from cell 0
    row.table.entries[3 * 4 + 0] = row.table.entries[0 * 4 + 3] = CellVisibility::Texture;
    const PortalChains chains(row.plan, row.table, row.description);
    EXPECT_EQ(chains.chains(0, 3), (Chains{{0}, {0, 2, 4}}));
}

TEST(PortalChains, ACellSeenDirectlyIsSeenThroughAnyOpeningOfTheEyesCell) {
    const Row row;
    const PortalChains chains(row.plan, row.table, row.description);
    // Cell 0: its wall w0 and its one open part, z = 1 for x in [0.5, 1], reaching far up and down.
    const Chains fromZero = chains.chains(0, 3);
    ASSERT_EQ(fromZero.size(), 2u);
    EXPECT_EQ(fromZero[0], std::vector<int>{0});
    EXPECT_EQ(fromZero[1], std::vector<int>{6});  // after the walls' six
    const display::ScreenQuad& open = chains.portals().at(fromZero[1].at(0));
    // Its normal into cell 0 (towards -z): from (1, 1) to (0.5, 1).
    EXPECT_EQ(glm::dvec2(open.lowerLeft.x, open.lowerLeft.z), glm::dvec2(1.0, 1.0));
    EXPECT_EQ(glm::dvec2(open.lowerRight.x, open.lowerRight.z), glm::dvec2(0.5, 1.0));
    EXPECT_LT(open.lowerLeft.y, -100.0);
    EXPECT_GT(open.upperLeft.y, 100.0);
    // Cell 3: its wall w2 and three open sides.
    EXPECT_EQ(chains.chains(3, 0).size(), 4u);
    // From (0.75, 1.7, 0.5): a box past the open part is seen through it; one past the real
    // walls west of the cell is seen through neither opening.
    PortalSets sets;
    sets.portals = chains.portals();
    sets.chains = fromZero;
    sets.sets = {{0, 1}};
    sets.objectSet = {0, 0};
    const render::PortalView view(sets, {0.75, 1.7, 0.5});
    scenes::Bounds north, west;
    north.add({0.6, 0.0, 3.0});
    north.add({1.0, 1.0, 3.5});
    west.add({-3.0, 0.0, 0.2});
    west.add({-2.5, 1.0, 0.8});
    EXPECT_TRUE(view.visible(0, north));
    EXPECT_FALSE(view.visible(1, west));
}

scenes::Object object(int cell, std::vector<int> more = {}, scenes::Role role = scenes::Role::Content) {
    scenes::Object o;
    o.cell = cell;
    o.moreCells = std::move(more);
    o.role = role;
    return o;
}

TEST(PortalChains, FrameSetsGiveEachObjectTheChainsOfItsDrawnCells) {
    const Row row;
    const PortalChains chains(row.plan, row.table, row.description);
    scenes::Scene scene;
    scene.objects = {object(0),
                     object(1),
                     object(2),
                     object(1, {2}),
                     object(0, {1}),
                     object(-1),
                     object(1, {}, scenes::Role::Structure),
                     object(2, {3}),
                     object(7)};
    PortalSets sets;
    chains.frameSets(0, {true, true, false, true}, scene, sets);
    ASSERT_EQ(sets.objectSet.size(), scene.objects.size());
    EXPECT_EQ(sets.portals, chains.portals());
    auto chainsOf = [&](int object) {
        Chains out;
        const int set = sets.objectSet[object];
        if (set >= 0)
            for (int c : sets.sets[set]) out.push_back(sets.chains[c]);
        return out;
    };
    EXPECT_EQ(sets.objectSet[0], -1);                 // the eye's cell
    EXPECT_EQ(chainsOf(1), (Chains{{0}}));            // the neighbour
    EXPECT_EQ(sets.objectSet[2], -1);                 // cell 2 is not drawn: not drawn through cell 2
    EXPECT_EQ(chainsOf(3), (Chains{{0}}));            // cells 1 and 2: only 1 is drawn
    EXPECT_EQ(sets.objectSet[4], -1);                 // reaches the eye's cell
    EXPECT_EQ(sets.objectSet[5], -1);                 // no cell
    EXPECT_EQ(sets.objectSet[6], -1);                 // structure
    EXPECT_EQ(chainsOf(7), chains.chains(0, 3));      // cell 3: any opening of cell 0
    EXPECT_EQ(sets.objectSet[8], -1);                 // a cell the description does not have
    EXPECT_EQ(sets.objectSet[3], sets.objectSet[1]);  // one set per combination of cells

    chains.frameSets(0, {true, true, true, false}, scene, sets);
    EXPECT_EQ(chainsOf(2), (Chains{{0, 2}}));
    EXPECT_EQ(chainsOf(3), (Chains{{0}, {0, 2}}));
    EXPECT_EQ(chainsOf(7), (Chains{{0, 2}}));

    // Over or under the eye cell's floor (another storey, seen through a void): without test.
    scenes::Object above = object(1), beside = object(1);
    above.worldBounds.add({0.2, 5.0, 0.2});
    above.worldBounds.add({0.4, 6.0, 0.4});
    beside.worldBounds.add({1.2, 0.0, 0.2});
    beside.worldBounds.add({1.4, 1.0, 0.4});
    beside.worldBounds.add({0.995, 0.5, 0.3});  // touches cell 0's edge, within a centimetre
    scene.objects.push_back(above);
    scene.objects.push_back(beside);
    chains.frameSets(0, {true, true, false, false}, scene, sets);
    EXPECT_EQ(sets.objectSet[9], -1);
    EXPECT_EQ(chainsOf(10), (Chains{{0}}));

    chains.frameSets(-1, {true, true, true, true}, scene, sets);  // outside every cell
    EXPECT_TRUE(sets.portals.empty());
    EXPECT_EQ(sets.objectSet, std::vector<int>(scene.objects.size(), -1));
}

}  // namespace
}  // namespace cavewall::walls
