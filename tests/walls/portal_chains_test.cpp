// The chains of walls each cell drawn as geometry is seen through (walls/portal_chains.h), and
// the portal sets of a frame over a scene's objects.
#include "walls/portal_chains.h"

#include <gtest/gtest.h>

namespace cavewall::walls {
namespace {

using Chains = std::vector<std::vector<int>>;

// Four cells in a row, 0 | 1 | 2 | 3 along x, walls w0 (0|1), w1 (1|2), w2 (2|3) at x = 1, 2, 3;
// cell 3 also sees cell 0 through an open boundary (a Geometry entry). From cell 0, the far
// wall w1 of neighbour 1 is a beyond side, and w2 one at the second level.
struct Row {
    Plan plan;
    VisibilityTable table;
    Row() {
        for (int w = 0; w < 3; ++w) {
            PlannedWall p;
            p.id = w;
            const double x = w + 1.0;
            p.quad = {{x, 0.0, 0.0}, {x, 0.0, 1.0}, {x, 2.0, 0.0}};
            p.cells = {w, w + 1};
            plan.walls.push_back(p);
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

TEST(PortalChains, NeighboursThroughTheirWallsAndCellsBeyondThroughTheChain) {
    const Row row;
    const PortalChains chains(row.plan, row.table);
    EXPECT_EQ(chains.chains(0, 1), (Chains{{0}}));
    EXPECT_EQ(chains.chains(0, 2), (Chains{{0, 1}}));
    EXPECT_EQ(chains.chains(1, 0), (Chains{{0}}));
    EXPECT_EQ(chains.chains(1, 2), (Chains{{1}}));
    EXPECT_EQ(chains.chains(2, 3), (Chains{{2}}));
    // Without test: the eye's own cell, an open boundary, and out of range.
    EXPECT_TRUE(chains.chains(1, 1).empty());
    EXPECT_TRUE(chains.chains(0, 3).empty());
    EXPECT_TRUE(chains.chains(3, 0).empty());
    EXPECT_TRUE(chains.chains(-1, 1).empty());
    EXPECT_TRUE(chains.chains(0, 4).empty());
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
    const PortalChains chains(row.plan, row.table);
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
    EXPECT_EQ(sets.portals.size(), 3u);
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
    EXPECT_EQ(sets.objectSet[7], -1);                 // cell 3: open boundary
    EXPECT_EQ(sets.objectSet[8], -1);                 // a cell the description does not have
    EXPECT_EQ(sets.objectSet[3], sets.objectSet[1]);  // one set per combination of cells

    chains.frameSets(0, {true, true, true, false}, scene, sets);
    EXPECT_EQ(chainsOf(2), (Chains{{0, 1}}));
    EXPECT_EQ(chainsOf(3), (Chains{{0}, {0, 1}}));
    EXPECT_EQ(chainsOf(7), (Chains{{0, 1}}));

    chains.frameSets(-1, {true, true, true, true}, scene, sets);  // outside every cell
    EXPECT_TRUE(sets.portals.empty());
    EXPECT_EQ(sets.objectSet, std::vector<int>(scene.objects.size(), -1));
}

}  // namespace
}  // namespace cavewall::walls
