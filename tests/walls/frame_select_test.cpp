#include "walls/frame_select.h"

#include "tests/walls/test_scenes.h"
#include "walls/angular_error.h"
#include "walls/polygon2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

namespace cavewall::walls {
namespace {

struct Fixture {
    scenes::SceneDescription description = testing::hall();
    Plan plan;
    VisibilityTable table;
    Fixture(double alphaDeg, double blendWidth) {
        PlanOptions o;
        o.alphaDeg = alphaDeg;
        o.blendWidth = blendWidth;
        plan = planZones(description, o);
        table = computeVisibility(description);
    }
};

std::map<int, double> weightsOf(const WallBlend& w) {
    std::map<int, double> m(w.textures.begin(), w.textures.end());
    m[-1] = w.geometryWeight;  // -1: geometry
    return m;
}

class FrameSelectTest : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(FrameSelectTest, WeightsAreAPartitionOfUnityInsideEachTexturesProvenRegion) {
    const Fixture f(GetParam().first, GetParam().second);
    const FrameSelector selector(f.plan, f.table, f.description);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> x(-5.999, 5.999), z(0.001, 9.999);
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec2 p(x(rng), z(rng));
        const WallBlend w = selector.blendAt(0, p);  // side 0: cell "front" looking at the wall
        double sum = w.geometryWeight;
        for (const auto& [id, weight] : w.textures) {
            sum += weight;
            // The bound holds for every texture drawn with non-zero weight.
            ASSERT_TRUE(containsConvex(f.plan.textures[id].validRegion, p, 1e-9))
                << "texture " << id << " drawn at " << p.x << "," << p.y << " outside its proven region";
        }
        ASSERT_NEAR(sum, 1.0, 1e-12);
        ASSERT_GE(w.zone, 0);
        const Zone& zone = f.plan.zones[w.zone];
        // Only what the zone lists is drawn: its textures, and geometry in geometry zones or
        // texture-to-geometry blends.
        for (const auto& [id, weight] : w.textures)
            ASSERT_NE(std::find(zone.textures.begin(), zone.textures.end(), id), zone.textures.end());
        if (w.geometryWeight > 0) {
            ASSERT_TRUE(zone.kind == ZoneKind::Geometry || zone.mixesGeometry);
        }
        if (zone.kind == ZoneKind::Texture) {
            ASSERT_EQ(w.textures.size(), 1u);
        }
        if (zone.kind == ZoneKind::Geometry) {
            ASSERT_EQ(w.geometryWeight, 1.0);
        }
    }
}

TEST_P(FrameSelectTest, WeightsAreContinuousAlongAnyWalk) {
    const Fixture f(GetParam().first, GetParam().second);
    const FrameSelector selector(f.plan, f.table, f.description);
    const double step = 5e-4, b = f.plan.options.blendWidth;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> x(-5.9, 5.9), z(0.1, 9.9);
    for (int walk = 0; walk < 10; ++walk) {
        const glm::dvec2 a(x(rng), z(rng)), c(x(rng), z(rng));
        const int n = int(glm::length(c - a) / step);
        auto previous = weightsOf(selector.blendAt(0, a));
        for (int i = 1; i <= n; ++i) {
            auto current = weightsOf(selector.blendAt(0, a + (c - a) * (double(i) / n)));
            // Each tent has slope 1/b; a product of two at most 2/b; normalising by a sum that
            // is 1 keeps that. A jump (popping) would be of order 1.
            for (const auto& [id, w] : current) {
                const double before = previous.count(id) ? previous[id] : 0.0;
                ASSERT_LE(std::abs(w - before), 2.0 * step / b + 1e-9) << "weight of " << id << " jumps at step " << i;
            }
            previous = std::move(current);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AlphaAndBlend, FrameSelectTest,
                         ::testing::Values(std::pair{10.0, 0.2}, std::pair{15.0, 0.3}, std::pair{20.0, 0.1}));

TEST(FrameSelect, CellsAndGeometryFollowTheEye) {
    const Fixture f(10.0, 0.2);
    const FrameSelector selector(f.plan, f.table, f.description);
    // Far from the wall in the front cell: textures only, the back cell is not drawn.
    const FrameSelection far = selector.select({0.0, 1.7, 9.0});
    EXPECT_EQ(far.cell, 0);
    EXPECT_EQ(far.geometryCells, std::vector<int>{0});
    ASSERT_EQ(far.walls.size(), 1u);
    EXPECT_EQ(far.walls[0].geometryWeight, 0.0);
    // Right at the wall: the geometry zone, the back cell is drawn as geometry.
    const FrameSelection near = selector.select({0.0, 1.7, 0.05});
    EXPECT_EQ(near.walls[0].geometryWeight, 1.0);
    EXPECT_EQ(near.geometryCells, (std::vector<int>{0, 1}));
    // On the other side the roles swap.
    EXPECT_EQ(selector.select({0.0, 1.7, -9.0}).cell, 1);
    // Outside the model: everything as geometry, no walls.
    const FrameSelection outside = selector.select({50.0, 1.7, 0.0});
    EXPECT_TRUE(outside.allGeometry());
    EXPECT_EQ(outside.geometryCells, (std::vector<int>{0, 1}));
}

// Two storeys of the hall, the upper one 4 m up over the same floor regions (listed after the
// lower ones): an eye upstairs is in the upper cell over it, not the lower one that comes first.
TEST(FrameSelect, TheEyesCellIsOnItsOwnStorey) {
    scenes::SceneDescription d = testing::hall();
    const int lower = static_cast<int>(d.cells.size());
    for (int c = 0; c < lower; ++c) {
        scenes::Cell up = d.cells[c];
        up.name += " upstairs";
        up.floorY = 4.0;
        d.cells.push_back(up);
    }
    for (std::size_t w = 0, n = d.walls.size(); w < n; ++w) {
        scenes::VirtualWall up = d.walls[w];
        up.name += " upstairs";
        for (glm::dvec3* p : {&up.lowerLeft, &up.lowerRight, &up.upperLeft}) p->y += 4.0;
        up.cells = {up.cells[0] + lower, up.cells[1] + lower};
        d.walls.push_back(up);
    }
    const Plan plan = planZones(d, {});
    const VisibilityTable table = computeVisibility(d);
    const FrameSelector selector(plan, table, d);
    EXPECT_EQ(selector.select({0.0, 1.7, 9.0}).cell, 0);
    const FrameSelection up = selector.select({0.0, 5.7, 9.0});
    EXPECT_EQ(up.cell, lower);
    EXPECT_EQ(up.geometryCells, std::vector<int>{lower});
    EXPECT_EQ(selector.select({0.0, 5.7, -9.0}).cell, lower + 1);
    // Below the lowest floor the lowest storey's cell.
    EXPECT_EQ(selector.select({0.0, -3.0, 9.0}).cell, 0);
}

TEST(FrameSelect, ANeighbourDrawnAsGeometryShowsWhatLiesBeyondItsFarWalls) {
    const scenes::SceneDescription d = testing::threeInARow();
    PlanOptions o;
    o.alphaDeg = 20.0;
    const Plan plan = planZones(d, o);
    const VisibilityTable table = computeVisibility(d);
    const FrameSelector selector(plan, table, d);
    // In A's geometry zone of A|B: B is geometry, and B|C shows textures planned for this eye
    // region (Plan::beyond), proven within alpha here although the eye is outside B.
    const glm::dvec3 eye{0.0, 1.7, 0.05};
    const FrameSelection near = selector.select(eye);
    ASSERT_EQ(near.cell, 0);
    EXPECT_EQ(near.geometryCells, (std::vector<int>{0, 1}));
    ASSERT_EQ(near.walls.size(), 1u);
    EXPECT_EQ(near.walls[0].geometryWeight, 1.0);
    ASSERT_EQ(near.beyond.size(), 1u);
    const WallBlend& bc = near.beyond[0];
    EXPECT_EQ(bc.wall, 1);
    EXPECT_EQ(bc.side, 0);              // B is B|C's front cell
    EXPECT_EQ(bc.geometryWeight, 0.0);  // 10 m from B|C: a texture is proven
    ASSERT_FALSE(bc.textures.empty());
    double sum = 0.0;
    for (const auto& [id, w] : bc.textures) {
        sum += w;
        const Texture& t = plan.textures[id];
        EXPECT_EQ(t.wall, 1);
        EXPECT_TRUE(containsConvex(t.validRegion, {eye.x, eye.z})) << "texture " << id;
        EXPECT_LE(maxAngularError(eye, t.samplingPoint, plan.walls[1].quad), glm::radians(20.0) + kErrorTolerance);
        // Baked from A, where the eyes that draw it are, not from B.
        EXPECT_GT(t.samplingPoint.z, 0.0);
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    // Far from A|B nothing is drawn beyond: B is a texture.
    EXPECT_TRUE(selector.select({0.0, 1.7, 9.0}).beyond.empty());
}

}  // namespace
}  // namespace cavewall::walls
