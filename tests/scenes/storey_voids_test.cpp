// Voids between storeys (scenes/storey_voids.h) and the objects a cell under a void holds
// and the upper cells beside a void (scenes/cell_assignment.h), on a synthetic two-storey
// voidBuilding.
//
// Ground floor: one cell G, x [-14, 10], z [-3, 3], its slab at y 0 all along. Upper floor
// (y 4): rooms A, x [-10, -0.1], and B, x [0.1, 4], each stopping at the face of the 0.2 m
// partition between them; the upper slab is two boards, x [-10, -0.1] and [0.1, 4] (a joint
// under the partition), so x [4, 10] is a double-height hall: a void. A roof at y 8 covers
// x [-10, 10]. x [-14, -10] is a one-storey wing with its roof at y 4.6: no void.
#include "scenes/cell_assignment.h"
#include "scenes/region.h"
#include "scenes/storey_voids.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::scenes {
namespace {

using ::testing::Contains;
using ::testing::Not;

constexpr int kGround = 0, kUpperA = 1, kUpperB = 2;

std::vector<glm::dvec2> rect(double x0, double x1) { return {{x0, 3}, {x1, 3}, {x1, -3}, {x0, -3}}; }

std::vector<Cell> voidBuilding() {
    return {{"G", rect(-14, 10), 0.0}, {"A", rect(-10, -0.1), 4.0}, {"B", rect(0.1, 4), 4.0}};
}

// A horizontal board x [x0, x1], z [-3, 3] at height y.
void board(Scene& s, double x0, double x1, double y) {
    Mesh m;
    m.positions = {{x0, y, -3}, {x1, y, -3}, {x1, y, 3}, {x0, y, 3}};
    m.indices = {0, 2, 1, 0, 3, 2};
    for (const glm::vec3& p : m.positions) m.bounds.add(glm::dvec3(p));
    s.meshes.push_back(m);
    addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::dmat4(1.0), "board");
}

// An object with the world box [min, max] and no triangles.
int box(Scene& s, glm::dvec3 min, glm::dvec3 max) {
    Object o;
    o.mesh = 0;  // the empty mesh
    o.worldBounds.add(min);
    o.worldBounds.add(max);
    s.objects.push_back(o);
    return static_cast<int>(s.objects.size()) - 1;
}

Scene voidBuildingScene() {
    Scene s;
    s.meshes.push_back({});  // 0: empty, for the boxes
    board(s, -14, 10, 0.0);  // ground slab
    board(s, -10, -0.1, 4.0);
    board(s, 0.1, 4, 4.0);
    board(s, -10, 10, 8.0);   // roof
    board(s, -14, -10, 4.6);  // the wing's roof
    return s;
}

std::vector<double> tops() { return {4.0, INFINITY, INFINITY}; }

TEST(StoreyVoids, TheHallOpenToTheStoreyAboveIsAVoidTheJointUnderAPartitionIsNot) {
    const Scene s = voidBuildingScene();
    std::vector<PlanRect> bounds;
    for (const Cell& c : voidBuilding()) bounds.push_back(regionBounds(c.region));
    const std::vector<PlanMask> voids = cellVoids(s, voidBuilding(), tops(), bounds);
    ASSERT_EQ(voids.size(), 3u);
    EXPECT_TRUE(voids[kUpperA].empty()) << "A has nothing above it";
    EXPECT_NEAR(voids[kGround].area(), 6.0 * 6.0, 6.0 * 0.25 * 2) << "the hall x [4, 10]";
    EXPECT_GT(voids[kGround].count({5, -2}, {9, 2}), 0);
    EXPECT_EQ(voids[kGround].count({-0.2, -3}, {0.2, 3}), 0) << "the joint under the partition";
    EXPECT_EQ(voids[kGround].count({-8, -3}, {3.7, 3}), 0) << "under the upper slab";
    EXPECT_EQ(voids[kGround].count({-14, -3}, {-10.1, 3}), 0) << "the one-storey wing";
}

TEST(CellAssignment, ObjectsSeenOverAVoidJoinTheCellBelowObjectsOverTheSlabDoNot) {
    Scene s = voidBuildingScene();
    const int rail = box(s, {3.8, 4, -3}, {4, 5, 3});          // the gallery's rail at the void's edge
    const int lamp = box(s, {6, 6, -0.5}, {7, 6.5, 0.5});      // hangs in the hall
    const int wall = box(s, {1.5, 4, 2.8}, {2, 8, 3.2});       // 2 m from the void, 4 m high: seen at 45°
    const int desk = box(s, {-8, 4, -1}, {-7, 4.8, 0});        // in A, over the slab
    const int partition = box(s, {-0.1, 4, -3}, {0.1, 7, 3});  // over the joint
    const int roof = box(s, {-10, 8, -3}, {10, 8.2, 3});       // over the hall: in no upper storey's top
    assignCells(s, voidBuilding());
    EXPECT_THAT(cellsOf(s.objects[rail]), Contains(kGround));
    EXPECT_THAT(cellsOf(s.objects[rail]), Contains(kUpperB));
    EXPECT_THAT(cellsOf(s.objects[lamp]), Contains(kGround));
    EXPECT_THAT(cellsOf(s.objects[wall]), Contains(kGround));
    EXPECT_THAT(cellsOf(s.objects[desk]), Not(Contains(kGround)));
    EXPECT_THAT(cellsOf(s.objects[desk]), Contains(kUpperA));
    EXPECT_THAT(cellsOf(s.objects[partition]), Not(Contains(kGround)));
    EXPECT_THAT(cellsOf(s.objects[roof]), Contains(kGround));
    // Without the upper slab's second board the whole of x [0.1, 10] is open: the partition joins.
    Scene open = voidBuildingScene();
    open.objects.erase(open.objects.begin() + 2);
    const int partition2 = box(open, {-0.1, 4, -3}, {0.1, 7, 3});
    assignCells(open, voidBuilding());
    EXPECT_THAT(cellsOf(open.objects[partition2]), Contains(kGround));
}

TEST(CellAssignment, ObjectsUnderAVoidJoinTheUpperCellBesideItObjectsUnderTheSlabDoNot) {
    Scene s = voidBuildingScene();
    const int sofa = box(s, {6, 0, -1}, {7, 0.8, 0});             // in the hall, under the void
    const int shelf = box(s, {2, 0, 2.5}, {2.5, 2, 3});           // under B's slab, 1.5 m from the void
    const int cabinet = box(s, {-8, 0, -1}, {-7, 2, 0});          // under A's slab, 11 m from the void
    const int bench = box(s, {-1.2, 0, -1}, {-0.5, 0.5, 0});      // 4.5 m from the void: out of 45° sight
    const int lamp = box(s, {9.5, 3, -0.5}, {10, 3.5, 0.5});      // 1 m under the upper floor, 5.5 m out
    const int outdoors = box(s, {10.5, -0.4, -1}, {11, 0.5, 0});  // beside the hall, in no cell
    const int slabEdge = box(s, {3.9, 3.7, -3}, {4.1, 4, 3});     // the upper slab's edge, in B already
    assignCells(s, voidBuilding());
    EXPECT_EQ(s.objects[sofa].cell, kGround) << "the hall still holds its own objects";
    EXPECT_THAT(cellsOf(s.objects[sofa]), Contains(kUpperB)) << "B borders the void";
    EXPECT_THAT(cellsOf(s.objects[sofa]), Not(Contains(kUpperA))) << "A lies 4.1 m from the void";
    EXPECT_THAT(cellsOf(s.objects[shelf]), Contains(kUpperB)) << "seen at 45° under the slab's edge";
    EXPECT_THAT(cellsOf(s.objects[cabinet]), Not(Contains(kUpperA)));
    EXPECT_THAT(cellsOf(s.objects[cabinet]), Not(Contains(kUpperB)));
    EXPECT_THAT(cellsOf(s.objects[bench]), Not(Contains(kUpperB)));
    EXPECT_THAT(cellsOf(s.objects[slabEdge]), Contains(kUpperB));
    EXPECT_THAT(cellsOf(s.objects[slabEdge]), Contains(kGround));
    EXPECT_THAT(cellsOf(s.objects[lamp]), Not(Contains(kUpperB))) << "B's eye at 2 m sees it only below 45°";
    EXPECT_EQ(s.objects[outdoors].cell, -1) << "still drawn with every cell";
    EXPECT_TRUE(s.objects[outdoors].moreCells.empty());
}

TEST(CellAssignment, ABuildingWithoutAVoidKeepsUpperObjectsUpstairs) {
    Scene s = voidBuildingScene();
    board(s, 4, 10, 4.0);  // the hall floored over
    const int lamp = box(s, {6, 6, -0.5}, {7, 6.5, 0.5});
    const int sofa = box(s, {6, 0, -1}, {7, 0.8, 0});
    assignCells(s, voidBuilding());
    EXPECT_THAT(cellsOf(s.objects[lamp]), Not(Contains(kGround)));
    EXPECT_THAT(cellsOf(s.objects[sofa]), ::testing::ElementsAre(kGround)) << "no upper cell looks down on it";
}

}  // namespace
}  // namespace cavewall::scenes
