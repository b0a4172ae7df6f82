// Where a viewer starts in a model without a walk path (app/start_pose.h).
#include "app/start_pose.h"

#include "config/display_config.h"
#include "render/view_all.h"
#include "scenes/loader.h"
#include "scenes/primitives.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <filesystem>

namespace cavewall::app {
namespace {

constexpr double kEye = 1.7;

void addBox(scenes::Scene& s, glm::dvec3 centre, glm::dvec3 size, const char* name) {
    s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)));
    scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre), name);
}

// A 20 m x 12 m two-storey building: slabs whose tops are at y = 0, 3.3 and 6.6, four outer
// walls, and a 1 m table in the middle of the ground floor.
scenes::Scene building() {
    scenes::Scene s;
    for (double top : {0.0, 3.3, 6.6}) addBox(s, {0.0, top - 0.15, 0.0}, {20.0, 0.3, 12.0}, "slab");
    addBox(s, {0.0, 3.3, -6.1}, {20.0, 6.6, 0.2}, "wall north");
    addBox(s, {0.0, 3.3, 6.1}, {20.0, 6.6, 0.2}, "wall south");
    addBox(s, {-10.1, 3.3, 0.0}, {0.2, 6.6, 12.0}, "wall west");
    addBox(s, {10.1, 3.3, 0.0}, {0.2, 6.6, 12.0}, "wall east");
    addBox(s, {0.0, 0.4, 0.0}, {1.0, 0.8, 1.0}, "table");
    return s;
}

bool inside(const scenes::Bounds& b, const glm::dvec3& p) {
    return glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max));
}

TEST(StartPose, StandsOnTheLowestSlabUnderTheCentreNotOnTheTable) {
    const scenes::Scene s = building();
    const std::optional<StartPose> pose = findFloorStart(s, kEye);
    ASSERT_TRUE(pose);
    EXPECT_TRUE(pose->onFloor);
    // The ground slab's top (the meshes are float); the table (1 m wide) is not large.
    EXPECT_NEAR(pose->floorY, 0.0, 1e-6);
    // The centre column comes first: (0, 0), 1.7 m above the ground floor.
    EXPECT_NEAR(glm::distance(pose->eye, glm::dvec3(0.0, kEye, 0.0)), 0.0, 1e-6);
    // Of the 16 directions, 22.5° apart, the longest views run 22.5° off the building's long
    // axis: 9.9 m / sin 67.5° = 10.7 m to an end wall (along the axis 9.9 m; 45° off it,
    // 5.9 m / sin 45° = 8.3 m to a side wall).
    EXPECT_NEAR(std::abs(std::sin(pose->yaw)), std::sin(glm::radians(67.5)), 1e-9);
}

TEST(StartPose, AColumnInTheMiddleMovesTheStartBesideIt) {
    scenes::Scene s = building();
    addBox(s, {0.0, 3.3, 0.0}, {3.0, 6.6, 3.0}, "solid core");  // 3 m square, floor to roof
    const std::optional<StartPose> pose = findFloorStart(s, kEye);
    ASSERT_TRUE(pose);
    EXPECT_NEAR(pose->floorY, 0.0, 1e-6);
    // Not inside the core: the centre column's eye meets the core's back faces on every side.
    EXPECT_TRUE(std::abs(pose->eye.x) > 1.5 || std::abs(pose->eye.z) > 1.5) << pose->eye.x << ", " << pose->eye.z;
}

TEST(StartPose, AModelWithoutAFloorIsShownWhole) {
    scenes::Scene s;
    addBox(s, {5.0, 0.0, -3.0}, {0.2, 0.2, 0.2}, "small box");  // its top is no floor to stand on
    EXPECT_FALSE(findFloorStart(s, kEye));
    EXPECT_FALSE(findFloorStart(scenes::Scene{}, kEye));  // nothing at all
    const config::DisplayConfig desktop = config::loadDisplayConfig("desktop");
    const display::Display display(desktop);
    const StartPose pose = startPose(s, display, kEye);
    EXPECT_FALSE(pose.onFloor);
    // The view-all eye: the default head where render::viewAll moves the CAVE.
    const render::ViewAll all = render::viewAll(display, display.defaultHead(), s.bounds());
    EXPECT_EQ(pose.eye, glm::dvec3(all.worldFromCave * glm::dvec4(display.defaultHead().position, 1.0)));
    EXPECT_EQ(pose.yaw, 0.0);
}

TEST(StartPose, InsideTheClinicAtEyeHeightAboveAFloor) {
    const std::filesystem::path file = std::filesystem::path(CAVEWALL_REAL_SCENES) / "clinic" / "clinic.gltf";
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const scenes::Scene clinic = scenes::loadSceneFile(file);
    const scenes::Bounds b = clinic.bounds();
    const auto start = std::chrono::steady_clock::now();
    const std::optional<StartPose> pose = findFloorStart(clinic, kEye);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(pose);
    RecordProperty("search_seconds", std::to_string(seconds));
    EXPECT_TRUE(inside(b, pose->eye)) << pose->eye.x << ", " << pose->eye.y << ", " << pose->eye.z;
    EXPECT_NEAR(pose->eye.y - pose->floorY, kEye, 1e-9);

    // A two-storey building: the floor found is the ground floor, in the lower half of the box.
    EXPECT_LT(pose->floorY, b.centre().y);
    EXPECT_LT(seconds, 30.0);
}

}  // namespace
}  // namespace cavewall::app
