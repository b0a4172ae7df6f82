// How objects are given to cells (scenes/cell_assignment.h), on a synthetic two-storey building.
//
// Ground floor: one cell G, x [-4, 4], z [-2, 2], floor at y 0. Upper floor (y 3): rooms A,
// x [-4, -0.1], and B, x [0.1, 4], as a floor plan finds them: each stops at the face of the
// 0.2 m partition between them (x [-0.1, 0.1]). A's north wall runs on past the partition
// along B (x [-4.2, 6]), and one ceiling board covers both rooms.
#include "scenes/cell_assignment.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::scenes {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

constexpr int kG = 0, kA = 1, kB = 2;

std::vector<Cell> building() {
    auto rect = [](double x0, double x1) { return std::vector<glm::dvec2>{{x0, 2}, {x1, 2}, {x1, -2}, {x0, -2}}; };
    return {{"G", rect(-4, 4), 0.0}, {"A", rect(-4, -0.1), 3.0}, {"B", rect(0.1, 4), 3.0}};
}

Object box(const char* name, glm::dvec3 min, glm::dvec3 max) {
    Object o;
    o.name = name;
    o.worldBounds.add(min);
    o.worldBounds.add(max);
    return o;
}

Scene buildingScene() {
    Scene s;
    s.objects = {
        box("partition", {-0.1, 3, -2}, {0.1, 6, 2}),      // 0: between A and B
        box("north wall", {-4.2, 3, 2}, {6, 6, 2.2}),      // 1: centre over B
        box("ceiling", {-4, 5.7, -2}, {4, 5.75, 2}),       // 2: one board over A and B
        box("desk", {-3, 3, -1}, {-2, 3.8, 0}),            // 3: inside A
        box("slab", {-4, 2.4, -2}, {4, 3, 2}),             // 4: G's ceiling, A's and B's floor
        box("ground wall", {-0.1, 0, -2}, {0.1, 2.4, 2}),  // 5: downstairs, under the partition
        box("shed", {20, 0, 20}, {22, 2, 22}),             // 6: outside every cell
    };
    return s;
}

TEST(CellAssignment, UpperRoomHoldsItsWallsAndCeilingThatCrossIntoTheNextRoom) {
    Scene s = buildingScene();
    assignCells(s, building());
    // Centres outside A (in the partition, over B, on the border): each is still A's.
    EXPECT_THAT(cellsOf(s.objects[0]), ElementsAre(kA, kB)) << "partition";
    EXPECT_THAT(cellsOf(s.objects[1]), ElementsAre(kA, kB)) << "north wall: more of it is along A";
    EXPECT_THAT(cellsOf(s.objects[2]), ElementsAre(kA, kB)) << "ceiling";
    // None of the upper floor's objects belongs to the ground floor below it.
    for (int i : {0, 1, 2, 3}) {
        SCOPED_TRACE(s.objects[i].name);
        EXPECT_FALSE(anyCellOf(s.objects[i], [](int c) { return c == kG; }));
    }
}

TEST(CellAssignment, ObjectsInsideOneCellStayInIt) {
    Scene s = buildingScene();
    assignCells(s, building());
    EXPECT_EQ(s.objects[3].cell, kA);
    EXPECT_THAT(s.objects[3].moreCells, IsEmpty());
    EXPECT_EQ(s.objects[5].cell, kG) << "ground floor wall";
    EXPECT_THAT(s.objects[5].moreCells, IsEmpty()) << "it ends 0.6 m under the upper rooms' floor";
}

TEST(CellAssignment, SlabBetweenStoreysBelongsToBoth) {
    Scene s = buildingScene();
    assignCells(s, building());
    EXPECT_THAT(cellsOf(s.objects[4]), ::testing::UnorderedElementsAre(kG, kA, kB));
}

TEST(CellAssignment, ObjectOutsideEveryCellHasNone) {
    Scene s = buildingScene();
    assignCells(s, building());
    EXPECT_EQ(s.objects[6].cell, -1);
    EXPECT_THAT(s.objects[6].moreCells, IsEmpty());
}

TEST(CellAssignment, ObjectsOfSeveralCellsArePagedWithThem) {
    Scene s = buildingScene();
    assignCells(s, building());
    EXPECT_TRUE(pagedWithCell(s.objects[0], 3)) << "partition: in two cells";
    EXPECT_TRUE(pagedWithCell(s.objects[3], 3)) << "desk: in one";
    EXPECT_FALSE(pagedWithCell(s.objects[0], 2)) << "partition: cell B beyond the description";
}

TEST(CellAssignment, ReachJoinsAWallToTheRoomWhoseFaceItStandsOn) {
    const std::vector<Cell> cells = building();
    // A wall 0.2 m beyond A's west edge at x -4: outside A, within the reach.
    const Bounds wall = box("west wall", {-4.4, 3, -2}, {-4.2, 6, 2}).worldBounds;
    EXPECT_EQ(cellsOfBox(cells, wall).cell, kA);
    EXPECT_EQ(cellsOfBox(cells, wall, 0.1).cell, -1) << "reach 0.1 m";
}

}  // namespace
}  // namespace cavewall::scenes
