#include "walls/auto_walls_limits.h"

#include "config/error.h"
#include "scenes/primitives.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace cavewall::walls {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A scene of one box of `size` centred on `centre`.
scenes::Scene oneBox(glm::dvec3 size, glm::dvec3 centre) {
    scenes::Scene s;
    s.name = "box";
    s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(1.0f)));
    scenes::addObject(s, 0, glm::translate(glm::dmat4(1.0), centre), "box");
    return s;
}

// Each model automatic walls cannot cut is refused with a message about the model, naming it.
TEST(AutoWallsLimits, RefusesModelsWithoutAFloorByWhatIsWrong) {
    const struct {
        const char* name;
        scenes::Scene scene;
        std::string message;
    } cases[] = {
        {"empty", scenes::Scene{}, "m.glb: the model has no triangles (0 objects with geometry"},
        {"one point", oneBox({2e-4, 2e-4, 2e-4}, {1, 2, 3}), "vertices lie within 1 mm of (1, 2, 3)"},
        {"vertical plane", oneBox({10, 3, 0}, {0, 1.5, 0}),
         "m.glb: the model has no floor: it spans 10 m along x, 3 m along y (up) and 0 m along z"},
        {"far", oneBox({10, 1, 10}, {9e5, 0.5, 9e5}),
         "m.glb: coordinates reach 900005 m (the model spans (899995, 0, 899995) to (900005, 1, 900005)): beyond "
         "the ±100000 m limit of scene coordinates, where single-precision positions are 0.0625 m apart; recentre "
         "the model near the origin"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { checkWallsModel(c.scene, "m.glb"); }, ::testing::ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    EXPECT_NO_THROW(checkWallsModel(oneBox({10, 3, 10}, {0, 1.5, 0}), "m.glb"));
}

// Grids over 30 m x 10 m: an nx x nz grid has (nx - 1) walls 10 m long and (nz - 1) 30 m long.
// Shortest first: 1x1 0 m, 2x1 10, 3x1 20, 1x2 30, 2x2 40, 3x2 50. Within 100 m, each within
// 40 m, the first five (100 m in all); within 99 m the first four; within 60 m each is at most
// 24 m: the first three.
TEST(AutoWallsLimits, PlansTheGridsWithTheShortestWallsWithinTheLimit) {
    EXPECT_DOUBLE_EQ(gridWallMetres(2, 2, {30, 10}), 40.0);
    // planned[(nx - 1) * 2 + (nz - 1)]: 1x1 1x2 2x1 2x2 3x1 3x2
    EXPECT_THAT(gridsWithinLimit(3, 2, {30, 10}, 100.0), ElementsAre(true, true, true, true, true, false));
    EXPECT_THAT(gridsWithinLimit(3, 2, {30, 10}, 99.0), ElementsAre(true, true, true, false, true, false));
    EXPECT_THAT(gridsWithinLimit(3, 2, {30, 10}, 60.0), ElementsAre(true, false, true, false, true, false));
    // The one-cell grid has no walls: always planned.
    EXPECT_THAT(gridsWithinLimit(3, 2, {30, 10}, 1e-3), ElementsAre(true, false, false, false, false, false));
}

// The walk cost's eyes: 0.25 m along a path and a 0.5 m grid, widened on a 10 km path and a
// square kilometre to stay within kMaxCostEyes.
TEST(AutoWallsLimits, WidensTheWalkCostsEyesToStayWithinTheCap) {
    double step = 0.0;
    EXPECT_EQ(costEyes({{0, 1.6, 0}, {10, 1.6, 0}}, {}, {}, 1.6, &step).size(), 41u);  // 40 steps and the end
    EXPECT_DOUBLE_EQ(step, 0.25);
    const std::size_t along = costEyes({{0, 1.6, 0}, {1e4, 1.6, 0}}, {}, {}, 1.6, &step).size();
    EXPECT_DOUBLE_EQ(step, 0.5);  // 10 km / 20,000
    EXPECT_EQ(along, kMaxCostEyes + 1);
    EXPECT_EQ(costEyes({}, {0, 0}, {10, 5}, 1.6, &step).size(), 200u);  // 20 x 10 at 0.5 m
    EXPECT_DOUBLE_EQ(step, 0.5);
    const std::size_t square = costEyes({}, {0, 0}, {1000, 1000}, 1.6, &step).size();
    EXPECT_NEAR(step, std::sqrt(1e6 / 2e4), 1e-9);
    EXPECT_LE(square, kMaxCostEyes + 2 * 142);  // at most a row and a column more
    EXPECT_GE(square, kMaxCostEyes - 2 * 142);
}

}  // namespace
}  // namespace cavewall::walls
