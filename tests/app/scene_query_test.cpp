// The scene query behind walk navigation (app/scene_query.h): floors and walls from the
// scene's structure, and the navigator walking into a wall with it.
#include "app/scene_query.h"

#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace cavewall::app {
namespace {

// A 10 m x 10 m floor (top at y = 0), a 0.3 m step (top at y = 0.3) over x in [2, 4], and a
// wall whose face is at x = 4.8 (0.2 m thick, 3 m high), all structure; a content box that
// must neither carry nor block.
scenes::Scene room() {
    scenes::Scene s;
    auto add = [&](glm::vec3 size, glm::dvec3 centre, scenes::Role role) {
        s.meshes.push_back(scenes::makeBox(size, glm::vec4(1.0f)));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre), "box",
                          role);
    };
    add({10, 0.2f, 10}, {0, -0.1, 0}, scenes::Role::Structure);
    add({2, 0.3f, 10}, {3, 0.15, 0}, scenes::Role::Structure);
    add({0.2f, 3, 10}, {4.9, 1.5, 0}, scenes::Role::Structure);
    add({1, 1, 1}, {-2, 0.5, 0}, scenes::Role::Content);
    return s;
}

TEST(SceneQuery, FindsTheFloorBelowAndIgnoresContent) {
    const SceneQuery query(room());
    struct Case {
        const char* name;
        glm::dvec3 point;
        double maxDrop;
        std::optional<double> expected;
    };
    const Case cases[] = {
        {"open floor", {0, 1.0, 0}, 5.0, 0.0},          // the floor's top face
        {"on the step", {3, 1.0, 0}, 5.0, 0.3},         // the step's top is the highest floor below
        {"below the step top", {3, 0.2, 0}, 5.0, 0.0},  // under the step's top: the floor beneath
        {"too far to drop", {0, 3.0, 0}, 1.0, std::nullopt},
        {"content is no floor", {-2, 2.0, 0}, 5.0, 0.0},  // the content box's top (y = 1) is skipped
        {"outside the room", {20, 1.0, 0}, 5.0, std::nullopt},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const auto floor = query.floorBelow(c.point, c.maxDrop);
        ASSERT_EQ(floor.has_value(), c.expected.has_value());
        // Vertex data is float: positions are exact to about 1e-7 m.
        if (floor) {
            EXPECT_NEAR(*floor, *c.expected, 1e-6);
        }
    }
}

TEST(SceneQuery, CastsRaysAgainstStructureOnly) {
    const SceneQuery query(room());
    // From x = 0 towards +x at head height: the wall face at x = 4.8.
    const auto wall = query.castRay({0, 1.7, 0}, {1, 0, 0}, 20.0);
    ASSERT_TRUE(wall);
    EXPECT_NEAR(*wall, 4.8, 1e-6);
    EXPECT_FALSE(query.castRay({0, 1.7, 0}, {1, 0, 0}, 4.0));    // beyond maxDistance
    EXPECT_FALSE(query.castRay({0, 0.5, 0}, {-1, 0, 0}, 20.0));  // through the content box: nothing
}

TEST(SceneQuery, WalkNavigationStopsAtTheWallAndClimbsTheStep) {
    const SceneQuery query(room());
    input::Navigator nav({}, &query);
    nav.setMode(input::NavMode::Walk);
    // Facing +x (yaw -pi/2 turns the CAVE's front, -z, to +x), trigger held: walk forwards.
    nav.setWorldFromCave({0, 0, 0}, -glm::half_pi<double>());
    const input::Pose head{{0, 1.7, 0}, {1, 0, 0, 0}}, hand{{0.2, 1.3, -0.35}, {1, 0, 0, 0}};
    nav.handle({input::EventType::ButtonDown, 0.0, 0, {}});
    nav.setTracking(head, hand, {1u, {0.0, 0.0}});
    double highest = 0.0;
    for (int i = 0; i < 600; ++i) {
        nav.update(1.0 / 60.0);
        highest = std::max(highest, nav.origin().y);
    }
    const glm::dvec3 eye = glm::dvec3(nav.worldFromCave() * glm::dvec4(head.position, 1.0));
    // Ten seconds at up to 3 m/s would pass x = 4.8; the wall stops the head bodyRadius
    // (0.3 m) short of its face, and the CAVE floor climbed the 0.3 m step (lower than the
    // navigator's 0.4 m stepHeight) on the way.
    EXPECT_LE(eye.x, 4.8 - 0.3 + 1e-6);
    EXPECT_GT(eye.x, 4.8 - 0.3 - 0.1);
    EXPECT_NEAR(highest, 0.3, 1e-6);
}

}  // namespace
}  // namespace cavewall::app
