#include "walls/storeys.h"

#include "scenes/loader.h"
#include "scenes/primitives.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

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

TEST(Storeys, AStairIsNoStoreyAndIsFoundBetweenTheFloors) {
    // 19 treads 1.2 m wide (x 5 to 6.2), 0.3 m deep, rising 0.2 m from 0.2 m to 3.8 m along +z
    // from z = 0.02: each tread is small, so no tread height is a floor.
    scenes::Scene s = building({0.0, 4.0}, 8.0);
    for (int i = 0; i < 19; ++i) box(s, {1.2, 0.05, 0.3}, {5.6, 0.2 * (i + 1) - 0.025, 0.17 + 0.3 * i}, "tread");
    const Storeys found = findStoreys(s);
    ASSERT_EQ(found.storeys.size(), 2u);
    EXPECT_NEAR(found.storeys[1].floorY, 4.0, 1e-6);
    ASSERT_EQ(found.stairs.size(), 1u);
    const Stair& stair = found.stairs[0];
    EXPECT_EQ(stair.from, 0);
    // Treads strictly between 0.5 m and 3.5 m (a quarter of the 2 m headroom from each floor)
    // are the 3rd to the 17th, their triangles' centres (a third of the way across a tread) at
    // x 5.4 and 5.8 and z 0.72 to 5.02: the 1 m columns x 5 to 6, z 0 to 6.
    EXPECT_EQ(stair.lo, glm::dvec2(5.0, 0.0));
    EXPECT_EQ(stair.hi, glm::dvec2(6.0, 6.0));
    EXPECT_EQ(stair.bottom, glm::dvec2(5.5, 0.5));  // the 3rd tread's column
    EXPECT_EQ(stair.top, glm::dvec2(5.5, 4.5));     // the 17th's (the first of its two columns)
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

TEST(Storeys, TheClinicHasTwoStoreys) {
    const std::filesystem::path file = std::filesystem::path(CAVEWALL_REAL_SCENES) / "clinic" / "clinic.gltf";
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const Storeys found = findStoreys(scenes::loadSceneFile(file));
    // As measured: the ground floor's finish at y 0.03 m under a ceiling at 3.43 m (the slab
    // and ceiling void between them, 0.55 m), the upper floor at 3.98 m under the roof's
    // underside at 9.22 m. The roof's top is covered by nothing and is no floor. No group of
    // upward facets between the floors (within 60 m²) climbs in steps of 0.5 m or less: no
    // stair is found in this model.
    ASSERT_EQ(found.storeys.size(), 2u);
    EXPECT_NEAR(found.storeys[0].floorY, 0.03, 0.05);
    EXPECT_NEAR(found.storeys[0].ceilingY, 3.43, 0.05);
    EXPECT_NEAR(found.storeys[1].floorY, 3.98, 0.05);
    EXPECT_NEAR(found.storeys[1].ceilingY, 9.22, 0.05);
    EXPECT_TRUE(found.stairs.empty());
}

}  // namespace
}  // namespace cavewall::walls
