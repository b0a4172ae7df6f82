// Virtual walls under a void reach the ceiling of the storey above (walls/void_walls.h).
#include "walls/void_walls.h"

#include "scenes/primitives.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace cavewall::walls {
namespace {

void addBox(scenes::Scene& s, glm::dvec3 lo, glm::dvec3 hi, const char* name) {
    s.meshes.push_back(scenes::makeBox(glm::vec3(hi - lo), glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)));
    scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), (lo + hi) / 2.0), name);
}

scenes::Cell cell(const char* name, double x0, double x1, double floorY) {
    return {name, {{x0, -6.0}, {x1, -6.0}, {x1, 6.0}, {x0, 6.0}}, floorY};
}

scenes::VirtualWall wall(const char* name, double x, double bottom, double top, int a, int b,
                         scenes::WallKind kind = scenes::WallKind::Virtual) {
    return {name, {x, bottom, -6.0}, {x, bottom, 6.0}, {x, top, -6.0}, {a, b}, kind};
}

// A 30 m x 12 m hall of two storeys (floors at 0 and 3.3 m, ceilings at 3.2 and 6.5 m) whose
// upper floor covers x in [0, 20] only: over x in [-10, 0] the ground floor is open to the roof,
// an atrium. Ground cells A (x -10..-5, under the atrium), B (-5..5, half under it) and D (5..20,
// under the upper floor); upper cell C over [0, 20].
TEST(VoidWalls, AWallUnderTheAtriumReachesTheUpperCeilingAndTheOthersKeepTheirs) {
    scenes::Scene scene;
    addBox(scene, {-10.0, -0.3, -6.0}, {20.0, 0.0, 6.0}, "ground slab");
    addBox(scene, {0.0, 3.2, -6.0}, {20.0, 3.3, 6.0}, "upper slab");
    addBox(scene, {-10.0, 6.5, -6.0}, {20.0, 6.8, 6.0}, "roof");
    scenes::SceneDescription d;
    d.cells = {cell("A", -10.0, -5.0, 0.0), cell("B", -5.0, 5.0, 0.0), cell("D", 5.0, 20.0, 0.0),
               cell("C", 0.0, 20.0, 3.3)};
    d.walls = {wall("A|B", -5.0, 0.0, 3.2, 0, 1),  // under the atrium
               wall("B|D", 5.0, 0.0, 3.2, 1, 2),   // 5 m from it, under the upper floor
               wall("A|B door", -5.0, 0.0, 2.1, 0, 1, scenes::WallKind::Portal),
               wall("C upper", 10.0, 3.3, 6.5, 3, -1)};
    const std::vector<Storey> storeys = {{.floorY = 0.0, .ceilingY = 3.2}, {.floorY = 3.3, .ceilingY = 6.5}};
    EXPECT_EQ(raiseWallsUnderVoids(d, scene, storeys), 1);
    EXPECT_DOUBLE_EQ(d.walls[0].upperLeft.y, 6.5);  // the atrium's: to the upper ceiling
    EXPECT_DOUBLE_EQ(d.walls[1].upperLeft.y, 3.2);  // under the upper floor: its own ceiling
    EXPECT_DOUBLE_EQ(d.walls[2].upperLeft.y, 2.1);  // a doorway keeps its lintel
    EXPECT_DOUBLE_EQ(d.walls[3].upperLeft.y, 6.5);  // the top storey's: unchanged

    // With the upper floor over the whole hall there is no void: nothing is raised.
    scenes::Scene closed;
    addBox(closed, {-10.0, -0.3, -6.0}, {20.0, 0.0, 6.0}, "ground slab");
    addBox(closed, {-10.0, 3.2, -6.0}, {20.0, 3.3, 6.0}, "upper slab");
    addBox(closed, {-10.0, 6.5, -6.0}, {20.0, 6.8, 6.0}, "roof");
    d.walls[0].upperLeft.y = 3.2;
    EXPECT_EQ(raiseWallsUnderVoids(d, closed, storeys), 0);
    EXPECT_DOUBLE_EQ(d.walls[0].upperLeft.y, 3.2);
    // One storey: nothing to reach.
    EXPECT_EQ(raiseWallsUnderVoids(d, scene, {{.floorY = 0.0, .ceilingY = 3.2}}), 0);
}

}  // namespace
}  // namespace cavewall::walls
