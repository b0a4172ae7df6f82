#include "walls/storeys.h"

#include "scenes/loader.h"
#include "scenes/primitives.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>
#include <string>

namespace cavewall::walls {
namespace {

void box(scenes::Scene& s, glm::dvec3 size, glm::dvec3 centre, const std::string& name) {
    s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)));
    scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre), name);
}

// A 20 m x 20 m building: a 0.3 m slab whose top is at each of `floors`, a roof slab whose top
// is at `roofTop`, and four outer walls (vertical: they add no horizontal area).
scenes::Scene building(const std::vector<double>& floors, double roofTop) {
    scenes::Scene s;
    s.name = "building";
    for (std::size_t i = 0; i < floors.size(); ++i)
        box(s, {20, 0.3, 20}, {0, floors[i] - 0.15, 0}, "slab " + std::to_string(i));
    box(s, {20, 0.3, 20}, {0, roofTop - 0.15, 0}, "roof");
    for (double side : {-10.0, 10.0}) {
        box(s, {0.2, roofTop, 20}, {side, roofTop / 2, 0}, "wall x");
        box(s, {20, roofTop, 0.2}, {0, roofTop / 2, side}, "wall z");
    }
    return s;
}

TEST(Storeys, TwoSlabsAndARoofMakeTwoStoreys) {
    const Storeys found = findStoreys(building({0.0, 4.0}, 8.0));
    ASSERT_EQ(found.storeys.size(), 2u);
    // Floors at the slabs' tops; ceilings at the undersides of the slab and the roof above (0.3 m
    // below their tops). The roof's top is uncovered: no floor.
    EXPECT_NEAR(found.storeys[0].floorY, 0.0, 1e-6);
    EXPECT_NEAR(found.storeys[0].ceilingY, 3.7, 1e-6);
    EXPECT_NEAR(found.storeys[1].floorY, 4.0, 1e-6);
    EXPECT_NEAR(found.storeys[1].ceilingY, 7.7, 1e-6);
    EXPECT_NEAR(found.storeys[0].floorArea, 400.0, 1e-6);  // 20 m x 20 m seen from above
    // The slab's top, 20 m x 20 m about the origin (the walls' tops are higher).
    EXPECT_NEAR(found.storeys[1].floorMin.x, -10.0, 1e-6);
    EXPECT_NEAR(found.storeys[1].floorMax.y, 10.0, 1e-6);
    EXPECT_TRUE(found.stairs.empty());
}

TEST(Storeys, ThreeSlabsMakeThreeStoreys) {
    const Storeys found = findStoreys(building({0.0, 3.5, 7.0}, 10.5));
    ASSERT_EQ(found.storeys.size(), 3u);
    EXPECT_NEAR(found.storeys[0].floorY, 0.0, 1e-6);
    EXPECT_NEAR(found.storeys[1].floorY, 3.5, 1e-6);
    EXPECT_NEAR(found.storeys[2].floorY, 7.0, 1e-6);
    EXPECT_NEAR(found.storeys[2].ceilingY, 10.2, 1e-6);
}

TEST(Storeys, AMezzanineIsNoStorey) {
    // A tall hall (floors 6 m apart) with an 8 m x 10 m gallery at 3 m: 80 m² is a fifth of the
    // 400 m² floor, under the 30 % a floor needs, and its underside is too small to be the
    // ground storey's ceiling.
    scenes::Scene s = building({0.0, 6.0}, 12.0);
    box(s, {8, 0.2, 10}, {-5, 2.9, 0}, "gallery");
    const Storeys found = findStoreys(s);
    ASSERT_EQ(found.storeys.size(), 2u);
    EXPECT_NEAR(found.storeys[0].floorY, 0.0, 1e-6);
    EXPECT_NEAR(found.storeys[0].ceilingY, 5.7, 1e-6);
    EXPECT_NEAR(found.storeys[1].floorY, 6.0, 1e-6);
}

// building() with the upper slab (top at 4 m) cut around a stair well over x [4.8, 6.4],
// z [-0.5, 5.72], and 19 treads 1.2 m wide (x 5 to 6.2), 0.3 m deep, rising 0.2 m from 0.2 m
// to 3.8 m along +z from z = 0.02 to the upper floor's edge.
scenes::Scene stairHouse() {
    scenes::Scene s = building({0.0}, 8.0);
    box(s, {14.8, 0.3, 20}, {-2.6, 3.85, 0}, "slab west");
    box(s, {3.6, 0.3, 20}, {8.2, 3.85, 0}, "slab east");
    box(s, {1.6, 0.3, 4.28}, {5.6, 3.85, 7.86}, "slab north of the well");
    box(s, {1.6, 0.3, 9.5}, {5.6, 3.85, -5.25}, "slab south of the well");
    for (int i = 0; i < 19; ++i) box(s, {1.2, 0.05, 0.3}, {5.6, 0.2 * (i + 1) - 0.025, 0.17 + 0.3 * i}, "tread");
    return s;
}

TEST(Storeys, AStairIsNoStoreyAndIsFoundBetweenTheFloors) {
    const Storeys found = findStoreys(stairHouse());
    ASSERT_EQ(found.storeys.size(), 2u);
    EXPECT_NEAR(found.storeys[1].floorY, 4.0, 1e-6);
    ASSERT_EQ(found.stairs.size(), 1u);
    const Stair& stair = found.stairs[0];
    EXPECT_EQ(stair.from, 0);
    ASSERT_GE(stair.path.size(), 2u);
    // It starts on the ground floor next to the first tread (0.2 m up: in front of it or
    // beside it) and ends on the upper floor just past the last, climbing along +z.
    EXPECT_NEAR(stair.path.front().y, 0.0, 1e-6);
    EXPECT_NEAR(stair.path.back().y, 4.0, 1e-6);
    EXPECT_GT(stair.bottom.y, -0.5);
    EXPECT_LT(stair.bottom.y, 0.32);
    EXPECT_GT(stair.bottom.x, 4.5);
    EXPECT_LT(stair.bottom.x, 6.7);
    EXPECT_GT(stair.top.y, 5.72);
    EXPECT_LT(stair.top.y, 6.5);
    // Every point between the ends stands on a tread: within its width, at its height over
    // its depth.
    for (std::size_t k = 1; k + 1 < stair.path.size(); ++k) {
        const glm::dvec3 p = stair.path[k];
        EXPECT_GT(p.x, 5.0) << k;
        EXPECT_LT(p.x, 6.2) << k;
        const int tread = static_cast<int>(std::floor((p.z - 0.02) / 0.3));
        ASSERT_GE(tread, 0) << k;
        EXPECT_NEAR(p.y, 0.2 * (tread + 1), 1e-6) << k;
    }
}

TEST(Storeys, AStairUnderAClosedSlabIsNone) {
    // The same treads under the whole slab: above 1.8 m they have no headroom.
    scenes::Scene s = building({0.0, 4.0}, 8.0);
    for (int i = 0; i < 19; ++i) box(s, {1.2, 0.05, 0.3}, {5.6, 0.2 * (i + 1) - 0.025, 0.17 + 0.3 * i}, "tread");
    const Storeys found = findStoreys(s);
    ASSERT_EQ(found.storeys.size(), 2u);
    EXPECT_TRUE(found.stairs.empty());
}

TEST(Storeys, AFloorIsItsHeaviestHeightNotARunsMean) {
    // Ceiling tiles' tops at 3.75 m and ducts' at 3.8 to 3.95 m make one run of 5 cm bins with
    // the upper slab's top at 4 m (its mean about 3.88 m); the upper floor is the slab's top,
    // where one walks.
    scenes::Scene s = building({0.0, 4.0}, 8.0);
    box(s, {18, 0.02, 18}, {0, 3.74, 0}, "ceiling tiles");
    for (int i = 0; i < 4; ++i) box(s, {1, 0.05, 18}, {-6.0 + 3.0 * i, 3.775 + 0.05 * i, 0}, "duct");
    const Storeys found = findStoreys(s);
    ASSERT_EQ(found.storeys.size(), 2u);
    EXPECT_NEAR(found.storeys[1].floorY, 4.0, 1e-6);
}

TEST(Storeys, TablesAreNoStairs) {
    // A row of tables 0.75 m high: intermediate area, but all at one height.
    scenes::Scene s = building({0.0, 4.0}, 8.0);
    for (int i = 0; i < 8; ++i) box(s, {1.6, 0.04, 0.8}, {-6.0 + 1.6 * i, 0.73, 3.0}, "table");
    const Storeys found = findStoreys(s);
    EXPECT_EQ(found.storeys.size(), 2u);
    EXPECT_TRUE(found.stairs.empty());
}

TEST(Storeys, AModelWithoutFloorsIsOneStoreyFromBottomToTop) {
    scenes::Scene s;
    box(s, {1, 3, 1}, {0, 1.5, 0}, "pillar");  // covered by nothing: its top is a roof
    const Storeys found = findStoreys(s);
    ASSERT_EQ(found.storeys.size(), 1u);
    EXPECT_NEAR(found.storeys[0].floorY, 0.0, 1e-6);
    EXPECT_NEAR(found.storeys[0].ceilingY, 3.0, 1e-6);
}

TEST(Storeys, StoreyAtPicksTheStoreyByHeight) {
    const std::vector<Storey> two{{0.0, 3.7, 400.0}, {4.0, 7.7, 400.0}};
    EXPECT_EQ(storeyAt(two, 1.7), 0);
    EXPECT_EQ(storeyAt(two, 5.7), 1);
    EXPECT_EQ(storeyAt(two, 3.6), 1);   // within 0.5 m below the upper floor: on its stairs
    EXPECT_EQ(storeyAt(two, -2.0), 0);  // below everything: the lowest
}

TEST(Storeys, TheClinicHasTwoStoreysAndAStair) {
    const std::filesystem::path file = std::filesystem::path(CAVEWALL_REAL_SCENES) / "clinic" / "clinic.gltf";
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const Storeys found = findStoreys(scenes::loadSceneFile(file));
    // As measured: the ground floor's finish at y -0.03 m under a ceiling at 4.3 m (the upper
    // slab's underside), the upper floor at 4.57 m (where its walls start; the suspended
    // ceilings' tops at 2.7 m and the ducts above them join its run of bins, whose mean was
    // 3.98 m) under the roof's underside at 9.22 m. The roof's top is covered by nothing and is
    // no floor. One stair joins them, a U-shaped one near x -37, z -52 to -56.
    ASSERT_EQ(found.storeys.size(), 2u);
    EXPECT_NEAR(found.storeys[0].floorY, -0.03, 0.05);
    EXPECT_NEAR(found.storeys[1].floorY, 4.57, 0.05);
    EXPECT_NEAR(found.storeys[1].ceilingY, 9.22, 0.05);
    ASSERT_EQ(found.stairs.size(), 1u);
    const Stair& stair = found.stairs[0];
    EXPECT_GT(stair.lo.x, -40.0);
    EXPECT_LT(stair.hi.x, -34.0);
    EXPECT_GT(stair.lo.y, -58.0);
    EXPECT_LT(stair.hi.y, -50.0);
}

}  // namespace
}  // namespace cavewall::walls
