// Beyond a neighbour drawn as geometry (Plan::beyond in walls/plan.h, FrameSelection::beyond in
// walls/frame_select.h): the far walls of that neighbour are planned for the eyes that draw
// them, and the selector draws only textures proven there.
#include "tests/walls/test_scenes.h"
#include "walls/angular_error.h"
#include "walls/frame_select.h"
#include "walls/plan.h"
#include "walls/plan_io.h"
#include "walls/visibility.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace cavewall::walls {
namespace {

scenes::VirtualWall wall(const char* name, glm::dvec2 a, glm::dvec2 b, int front, int back) {
    scenes::VirtualWall w;
    w.name = name;
    w.lowerLeft = {a.x, 0, a.y};
    w.lowerRight = {b.x, 0, b.y};
    w.upperLeft = {a.x, 4, a.y};
    w.cells = {front, back};
    return w;
}

// A 2 x 2 grid of 10 m cells: A (x in [-10, 0], z in [0, 10]), B (x in [0, 10], z in [0, 10]),
// C (x in [-10, 0], z in [-10, 0]), D (x in [0, 10], z in [-10, 0]). From A, the far walls of B
// and C (B|D and C|D) are perpendicular to the wall A looks through, and their planes run along
// A's border.
scenes::SceneDescription grid() {
    scenes::SceneDescription d;
    d.name = "grid";
    d.cells.push_back({"A", {{-10, 0}, {0, 0}, {0, 10}, {-10, 10}}, 0.0});
    d.cells.push_back({"B", {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, 0.0});
    d.cells.push_back({"C", {{-10, -10}, {0, -10}, {0, 0}, {-10, 0}}, 0.0});
    d.cells.push_back({"D", {{0, -10}, {10, -10}, {10, 0}, {0, 0}}, 0.0});
    d.walls.push_back(wall("A|B", {0, 0}, {0, 10}, 0, 1));  // normal -x, towards A
    d.walls.push_back(wall("C|D", {0, -10}, {0, 0}, 2, 3));
    d.walls.push_back(wall("A|C", {-10, 0}, {0, 0}, 0, 2));  // normal +z, towards A
    d.walls.push_back(wall("B|D", {0, 0}, {10, 0}, 1, 3));
    d.headHeightRange = {1.3, 1.9};
    return d;
}

struct Case {
    const char* name;
    scenes::SceneDescription (*scene)();
    double alphaDeg;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class BeyondTest : public ::testing::TestWithParam<Case> {
protected:
    scenes::SceneDescription description = GetParam().scene();
    Plan plan;
    VisibilityTable table;
    std::mt19937_64 rng{7};

    void SetUp() override {
        PlanOptions o;
        o.alphaDeg = GetParam().alphaDeg;
        plan = planZones(description, o);
        table = computeVisibility(description);
    }
    double alpha() const { return glm::radians(GetParam().alphaDeg) + kErrorTolerance; }
    // A uniformly random eye over a convex floor polygon times the head height range.
    glm::dvec3 eyeIn(const Polygon2& polygon) {
        glm::dvec2 lo(1e300), hi(-1e300);
        for (const glm::dvec2& p : polygon) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (;;) {
            const glm::dvec2 p = lo + (hi - lo) * glm::dvec2(u(rng), u(rng));
            if (!containsConvex(polygon, p)) continue;
            const glm::dvec2 h = description.headHeightRange;
            return {p.x, h.x + (h.y - h.x) * u(rng), p.y};
        }
    }
    double errorOf(int texture, glm::dvec3 eye) const {
        const Texture& t = plan.textures[texture];
        return maxAngularError(eye, t.samplingPoint, plan.walls[t.wall].quad);
    }
};

TEST_P(BeyondTest, ZonesTileTheEyeRegionAndEveryTextureIsWithinAlphaThere) {
    ASSERT_FALSE(plan.beyond.empty());
    int textures = 0;
    for (const BeyondSide& b : plan.beyond) {
        SCOPED_TRACE("eye cell " + std::to_string(b.eyeCell) + ", far wall " + plan.walls[b.side.wall].name);
        // The region lies in the eye's cell and outside the neighbour whose wall it serves.
        for (const glm::dvec2& p : b.eyeRegion)
            ASSERT_TRUE(containsConvex(description.cells[b.eyeCell].region, p, 1e-9));
        EXPECT_NE(b.eyeCell, b.side.cell);
        double area = 0.0;
        for (int z = b.side.firstZone; z < b.side.firstZone + b.side.zoneCount; ++z) {
            const Zone& zone = plan.beyondZones[z];
            EXPECT_EQ(zone.cell, b.side.cell);
            EXPECT_EQ(zone.wall, b.side.wall);
            area += std::abs(signedArea(zone.floorPolygon));
        }
        EXPECT_NEAR(area, std::abs(signedArea(b.eyeRegion)), 1e-6);  // zones tile the region
        textures += b.side.textureCount;
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 eye = eyeIn(b.eyeRegion);
            int found = 0;
            for (int z = b.side.firstZone; z < b.side.firstZone + b.side.zoneCount; ++z) {
                const Zone& zone = plan.beyondZones[z];
                if (!containsConvex(zone.floorPolygon, {eye.x, eye.z})) continue;
                ++found;
                for (int t : zone.textures) {
                    EXPECT_EQ(plan.textures[t].wall, b.side.wall);
                    ASSERT_LE(errorOf(t, eye), alpha())
                        << "texture " << t << " at " << eye.x << "," << eye.y << "," << eye.z;
                }
            }
            ASSERT_GE(found, 1) << "no zone holds " << eye.x << "," << eye.z;
        }
    }
    EXPECT_GT(textures, 0);  // not all geometry: the textures above were checked
}

TEST_P(BeyondTest, TheSelectorDrawsOnlyProvenBeyondTexturesWithWeightsSummingToOne) {
    const FrameSelector selector(plan, table, description);
    int drawn = 0;
    for (int c = 0; c < int(description.cells.size()); ++c)
        for (int i = 0; i < 1500; ++i) {
            const glm::dvec3 eye = eyeIn(description.cells[c].region);
            const FrameSelection f = selector.select(eye);
            for (const WallBlend& w : f.beyond) {
                double sum = w.geometryWeight;
                for (const auto& [id, weight] : w.textures) {
                    sum += weight;
                    ASSERT_GT(weight, 0.0);
                    ASSERT_EQ(plan.textures[id].wall, w.wall);
                    ASSERT_LE(errorOf(id, eye), alpha()) << "texture " << id << " at " << eye.x << "," << eye.z;
                    ++drawn;
                }
                ASSERT_NEAR(sum, 1.0, 1e-12);
                // Drawn only beyond a neighbour that is drawn as geometry.
                const auto& cells = plan.walls[w.wall].cells;
                ASSERT_TRUE(std::binary_search(f.geometryCells.begin(), f.geometryCells.end(), cells[w.side]));
            }
        }
    EXPECT_GT(drawn, 100);  // the random eyes do reach the geometry zones
}

// Along a line through the region that draws a neighbour, the far wall's weights change by at
// most 2 step / blendWidth per step: each is a product of two tents of slope 1 / blendWidth
// whose sum is already 1 (no renormalisation inside the region).
TEST_P(BeyondTest, BeyondWeightsAreContinuousAlongAWalk) {
    const FrameSelector selector(plan, table, description);
    const double step = 1e-3, b = plan.options.blendWidth;
    int compared = 0;
    for (const BeyondSide& side : plan.beyond) {
        std::map<int, double> previous;
        bool had = false;
        const glm::dvec2 from = centroid(side.eyeRegion);
        // Along the via wall's direction, where most column borders are crossed.
        const glm::dvec2 along = side.viaWall < 0 ? glm::dvec2(1, 0) : side.side.along;
        for (double s = -12.0; s <= 12.0; s += step) {
            const glm::dvec2 p = from + s * along;
            const FrameSelection f = selector.select({p.x, 1.6, p.y});
            std::map<int, double> now;
            bool has = false;
            for (const WallBlend& w : f.beyond)
                if (w.wall == side.side.wall && f.cell == side.eyeCell && containsConvex(side.eyeRegion, p)) {
                    has = true;
                    for (const auto& [id, weight] : w.textures) now[id] = weight;
                    now[-1] = w.geometryWeight;
                }
            if (has && had) {
                std::map<int, double> all = previous;
                for (const auto& [id, weight] : now) all[id] = 0.0;
                for (const auto& [id, unused] : all) {
                    const double a = previous.count(id) ? previous[id] : 0.0, c = now.count(id) ? now[id] : 0.0;
                    ASSERT_LE(std::abs(a - c), 2.0 * step / b + 1e-9) << "texture " << id << " at s = " << s;
                }
                ++compared;
            }
            previous = now;
            had = has;
        }
    }
    EXPECT_GT(compared, 1000);
}

// `plan --json` carries the beyond zones with the eye region they serve, and reads them back.
TEST_P(BeyondTest, JsonCarriesTheBeyondZonesAndReadsThemBack) {
    const nlohmann::json j = planToJson(plan);
    ASSERT_EQ(j.at("beyondZones").size(), plan.beyondZones.size());
    std::size_t k = 0;
    for (const BeyondSide& b : plan.beyond)
        for (int z = 0; z < b.side.zoneCount; ++z, ++k) {
            const nlohmann::json& zone = j["beyondZones"][k];
            EXPECT_EQ(zone.at("eyeCell"), b.eyeCell);
            EXPECT_EQ(zone.at("viaWall"), b.viaWall);
            EXPECT_EQ(zone.at("cell"), b.side.cell);
            EXPECT_EQ(zone.at("wall"), b.side.wall);
        }
    const std::string text = j.dump();
    const Plan back = planFromJson(text, "plan.json");
    ASSERT_EQ(back.beyond.size(), plan.beyond.size());
    EXPECT_EQ(planToJson(back).dump(), text);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BeyondTest,
                         ::testing::Values(Case{"parallel_10", testing::threeInARow, 10.0},
                                           Case{"parallel_20", testing::threeInARow, 20.0},
                                           Case{"perpendicular_10", grid, 10.0}, Case{"perpendicular_30", grid, 30.0}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace cavewall::walls
