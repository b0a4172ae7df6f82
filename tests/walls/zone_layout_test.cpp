#include "walls/plan_io.h"
#include "walls/zone_layout.h"

#include "tests/walls/test_scenes.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cavewall::walls {
namespace {

// The inputs planZones gave its sides, recovered from the planned sides' frames.
std::vector<SideInput> inputsOf(const Plan& plan, const scenes::SceneDescription& d) {
    std::vector<SideInput> inputs;
    for (const WallSide& s : plan.sides)
        inputs.push_back({s.cell,
                          s.wall,
                          s.side,
                          {s.origin, s.along, s.inward},
                          d.cells[s.cell].region,
                          plan.walls[s.wall].quad,
                          d.headHeightRange});
    return inputs;
}

// A plan holding only the walls and options of `plan`, before any side is planned.
Plan wallsOnly(const Plan& plan) {
    Plan p;
    p.alphaDeg = plan.alphaDeg;
    p.options = plan.options;
    p.walls = plan.walls;
    return p;
}

void expectSameSides(const std::vector<WallSide>& a, const std::vector<WallSide>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        SCOPED_TRACE("side " + std::to_string(i));
        EXPECT_EQ(a[i].cell, b[i].cell);
        EXPECT_EQ(a[i].wall, b[i].wall);
        EXPECT_EQ(a[i].side, b[i].side);
        EXPECT_EQ(a[i].firstZone, b[i].firstZone);
        EXPECT_EQ(a[i].zoneCount, b[i].zoneCount);
        EXPECT_EQ(a[i].textureCount, b[i].textureCount);
        EXPECT_EQ(a[i].geometryDistance, b[i].geometryDistance);
        EXPECT_EQ(a[i].hasGeometry, b[i].hasGeometry);
        ASSERT_EQ(a[i].rows.size(), b[i].rows.size());
        for (std::size_t r = 0; r < a[i].rows.size(); ++r) {
            EXPECT_EQ(a[i].rows[r].near, b[i].rows[r].near);
            EXPECT_EQ(a[i].rows[r].far, b[i].rows[r].far);
            EXPECT_EQ(a[i].rows[r].cuts, b[i].rows[r].cuts);
            EXPECT_EQ(a[i].rows[r].textures, b[i].rows[r].textures);
        }
    }
}

TEST(ZoneLayout, PlanSidesEqualsPlanningEachSideInTurn) {
    // planSides computes the layouts in parallel and numbers them afterwards; the result must
    // be what planSide gives called once per input in order: same zones, textures and ids.
    for (const scenes::SceneDescription& d : {testing::threeInARow(), testing::obliqueCells(), testing::hall()}) {
        SCOPED_TRACE(d.name);
        const Plan planned = planZones(d);
        const std::vector<SideInput> inputs = inputsOf(planned, d);
        ASSERT_GE(inputs.size(), 2u);
        Plan serial = wallsOnly(planned), parallel = wallsOnly(planned);
        for (const SideInput& in : inputs) serial.sides.push_back(planSide(serial, in, serial.zones));
        parallel.sides = planSides(parallel, inputs, parallel.zones);
        EXPECT_GT(serial.textures.size(), inputs.size());
        expectSameSides(parallel.sides, serial.sides);
        // Zones (polygons, kinds, texture ids) and textures (sampling points) to the last bit.
        EXPECT_EQ(planToJson(parallel).dump(), planToJson(serial).dump());
    }
}

TEST(ZoneLayout, PlanSidesAfterExistingSidesContinuesTheirIds) {
    // planBeyond calls planSides once per level on a plan that already holds textures.
    const scenes::SceneDescription d = testing::threeInARow();
    const Plan planned = planZones(d);
    const std::vector<SideInput> inputs = inputsOf(planned, d);
    const std::vector<SideInput> firstHalf(inputs.begin(), inputs.begin() + 2),
        secondHalf(inputs.begin() + 2, inputs.end());
    Plan serial = wallsOnly(planned), batched = wallsOnly(planned);
    for (const SideInput& in : inputs) serial.sides.push_back(planSide(serial, in, serial.zones));
    batched.sides = planSides(batched, firstHalf, batched.zones);
    for (WallSide& s : planSides(batched, secondHalf, batched.zones)) batched.sides.push_back(std::move(s));
    ASSERT_EQ(inputs.size(), 4u);  // A|B and B|C, each from both sides
    expectSameSides(batched.sides, serial.sides);
    EXPECT_EQ(planToJson(batched).dump(), planToJson(serial).dump());
}

}  // namespace
}  // namespace cavewall::walls
