#include "config/error.h"
#include "walls/angular_error.h"
#include "walls/plan.h"
#include "walls/visibility.h"
#include "walls/zone_index.h"

#include "tests/walls/test_scenes.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;

glm::dvec2 randomPointIn(const Polygon2& poly, std::mt19937& rng) {
    // Random convex combination biased to cover the whole polygon including its vertices.
    std::uniform_real_distribution<double> u(0, 1);
    glm::dvec2 p(0.0);
    double sum = 0;
    for (const glm::dvec2& v : poly) {
        const double w = std::pow(u(rng), 4);
        p += w * v;
        sum += w;
    }
    return p / sum;
}

double cellArea(const scenes::SceneDescription& d, int cell) { return std::abs(signedArea(d.cells[cell].region)); }

void expectPlanKeepsItsPromises(const scenes::SceneDescription& d, const Plan& plan) {
    const double alpha = glm::radians(plan.alphaDeg);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (const WallSide& side : plan.sides) {
        SCOPED_TRACE("cell " + std::to_string(side.cell) + " wall " + std::to_string(side.wall));
        const ScreenQuad& quad = plan.walls[side.wall].quad;
        double area = 0;
        for (int z = side.firstZone; z < side.firstZone + side.zoneCount; ++z) {
            const Zone& zone = plan.zones[z];
            SCOPED_TRACE("zone " + std::to_string(z) + " " + toString(zone.kind));
            ASSERT_TRUE(isConvex(zone.floorPolygon));
            area += std::abs(signedArea(zone.floorPolygon));
            EXPECT_EQ(zone.textures.empty(), zone.kind == ZoneKind::Geometry);
            if (zone.kind == ZoneKind::Texture) {
                EXPECT_EQ(zone.textures.size(), 1u);
            }
            if (zone.kind == ZoneKind::Blend) {
                EXPECT_TRUE(zone.textures.size() >= 2 || zone.mixesGeometry);
            }
            for (int t : zone.textures) {
                const Texture& tex = plan.textures[t];
                // Blend zones lie inside the region each mixed texture is proven for.
                for (const glm::dvec2& v : zone.floorPolygon) EXPECT_TRUE(containsConvex(tex.validRegion, v, 1e-6));
                // The exact 3D bound over the zone (all eyes, all depths) never exceeds alpha.
                EXPECT_LE(zoneMaxError({zone.floorPolygon, zone.heightRange}, tex.samplingPoint, quad), alpha);
                // And random eyes against random scene points at random depths.
                for (int i = 0; i < 20; ++i) {
                    const glm::dvec2 f = randomPointIn(zone.floorPolygon, rng);
                    const glm::dvec3 eye(f.x, zone.heightRange.x + u(rng) * (zone.heightRange.y - zone.heightRange.x),
                                         f.y);
                    const glm::dvec3 q = quad.lowerLeft + u(rng) * (quad.lowerRight - quad.lowerLeft) +
                                         u(rng) * (quad.upperLeft - quad.lowerLeft);
                    const glm::dvec3 p = q + (0.1 + 100 * std::pow(u(rng), 3)) * (q - tex.samplingPoint);
                    ASSERT_LE(pointError(eye, tex.samplingPoint, p, quad), alpha);
                }
            }
        }
        // Zones tile the cell: areas add up, and random points all find a zone.
        EXPECT_NEAR(area, cellArea(d, side.cell), 1e-6 * cellArea(d, side.cell));
        for (int i = 0; i < 200; ++i) {
            const glm::dvec2 p = randomPointIn(d.cells[side.cell].region, rng);
            EXPECT_GE(findZone(plan, side.cell, side.wall, p), 0);
        }
    }
}

TEST(Plan, HallKeepsTheBoundEverywhere) {
    const auto d = testing::hall();
    const Plan plan = planZones(d);
    ASSERT_EQ(plan.sides.size(), 2u);
    expectPlanKeepsItsPromises(d, plan);
    for (const WallSide& s : plan.sides) {
        // A 0.8 m head range needs x >= 0.4 / tan 10° = 2.3 m just for the height: the geometry
        // strip is at least that deep, and the 10 m deep cell still gets textures.
        EXPECT_GT(s.geometryDistance, 0.4 / std::tan(glm::radians(10.0)));
        EXPECT_LT(s.geometryDistance, 10.0);
        EXPECT_GT(s.textureCount, 0);
    }
    EXPECT_EQ(plan.textures.size(), size_t(plan.sides[0].textureCount + plan.sides[1].textureCount));
}

TEST(Plan, AStoreyAboveServesHeadsOverItsOwnFloor) {
    // The hall and a copy of it 4 m higher (cells with floorY 4, walls raised by 4 m): the
    // upper storey's heads are the hall's head range raised by 4 m, so its zones are the hall's
    // zones with heights 4 m higher and its textures keep the same bound.
    const auto hall = testing::hall();
    auto d = hall;
    const int n = static_cast<int>(hall.cells.size());
    for (scenes::Cell c : hall.cells) {
        c.name += " upstairs";
        c.floorY += 4.0;
        d.cells.push_back(c);
    }
    for (scenes::VirtualWall w : hall.walls) {
        w.name += " upstairs";
        for (glm::dvec3* p : {&w.lowerLeft, &w.lowerRight, &w.upperLeft}) p->y += 4.0;
        for (int& c : w.cells) c += c >= 0 ? n : 0;
        d.walls.push_back(w);
    }
    // Stacked cells share their outlines in plan but no open boundary: each storey sees only
    // itself.
    const VisibilityTable table = computeVisibility(d);
    for (int a = 0; a < n; ++a)
        for (int b = n; b < 2 * n; ++b) {
            EXPECT_EQ(table.at(a, b), CellVisibility::Hidden) << a << " -> " << b;
            EXPECT_EQ(table.at(b, a), CellVisibility::Hidden) << b << " -> " << a;
        }
    const Plan one = planZones(hall), two = planZones(d);
    expectPlanKeepsItsPromises(d, two);
    ASSERT_EQ(two.zones.size(), 2 * one.zones.size());
    ASSERT_EQ(two.textures.size(), 2 * one.textures.size());
    for (std::size_t i = 0; i < one.zones.size(); ++i) {
        const Zone& up = two.zones[one.zones.size() + i];
        EXPECT_EQ(up.kind, one.zones[i].kind);
        EXPECT_NEAR(up.heightRange.x, one.zones[i].heightRange.x + 4.0, 1e-9);
        EXPECT_NEAR(up.heightRange.y, one.zones[i].heightRange.y + 4.0, 1e-9);
    }
    for (std::size_t i = 0; i < one.textures.size(); ++i)
        EXPECT_NEAR(two.textures[one.textures.size() + i].maxError, one.textures[i].maxError, 1e-9);
}

TEST(Plan, ObliqueWallAndNonRectangularCells) {
    const auto d = testing::obliqueCells();
    // The wall's normal is cross(lowerRight - lowerLeft, upperLeft - lowerLeft): check the
    // fixture puts the pentagon in front, as scene_description.h requires.
    const scenes::VirtualWall& w = d.walls[0];
    const glm::dvec3 n = glm::cross(w.lowerRight - w.lowerLeft, w.upperLeft - w.lowerLeft);
    const glm::dvec2 c = centroid(d.cells[0].region);
    ASSERT_GT(glm::dot(n, glm::dvec3(c.x, 0, c.y) - w.lowerLeft), 0.0);
    for (double alphaDeg : {8.0, 15.0}) {
        SCOPED_TRACE(alphaDeg);
        PlanOptions o;
        o.alphaDeg = alphaDeg;
        const Plan plan = planZones(d, o);
        EXPECT_GT(plan.textures.size(), 0u);
        expectPlanKeepsItsPromises(d, plan);
    }
}

TEST(Plan, RowsDescribeTheLayout) {
    const auto d = testing::hall();
    const Plan plan = planZones(d);
    const double halfBlend = 0.5 * plan.options.blendWidth;
    for (const WallSide& s : plan.sides) {
        SCOPED_TRACE(s.cell);
        ASSERT_FALSE(s.rows.empty());
        EXPECT_TRUE(s.hasGeometry);
        // Rows are contiguous from the geometry border to the cell's far end (10 m).
        EXPECT_EQ(s.rows.front().near, s.geometryDistance);
        for (std::size_t r = 0; r + 1 < s.rows.size(); ++r) EXPECT_EQ(s.rows[r].far, s.rows[r + 1].near);
        EXPECT_NEAR(s.rows.back().far, 10.0, 1e-12);
        for (const PlannedRow& row : s.rows) {
            ASSERT_EQ(row.textures.size(), row.cuts.size() + 1);
            for (std::size_t k = 0; k < row.textures.size(); ++k) {
                const double lo = k == 0 ? -1e9 : row.cuts[k - 1] - halfBlend;
                const double hi = k == row.cuts.size() ? 1e9 : row.cuts[k] + halfBlend;
                // Each texture's proven region is its column widened by half a blend strip.
                for (const glm::dvec2& p : plan.textures[row.textures[k]].validRegion) {
                    const glm::dvec2 local(glm::dot(p - s.origin, s.along), glm::dot(p - s.origin, s.inward));
                    EXPECT_GE(local.x, lo - 1e-9);
                    EXPECT_LE(local.x, hi + 1e-9);
                    EXPECT_GE(local.y, row.validated.x - 1e-9);
                    EXPECT_LE(local.y, row.validated.y + 1e-9);
                }
            }
        }
    }
}

TEST(Plan, ZoneIndexAgreesWithLinearSearch) {
    for (const auto& d : {testing::hall(), testing::obliqueCells()}) {
        SCOPED_TRACE(d.name);
        const Plan plan = planZones(d);
        const ZoneIndex index(plan);
        std::mt19937 rng(4);
        std::uniform_real_distribution<double> x(-14, 14), z(-14, 14);
        int inside = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::dvec2 p(x(rng), z(rng));
            for (const WallSide& s : plan.sides) {
                const int expected = findZone(plan, s.cell, s.wall, p);
                ASSERT_EQ(index.find(s.cell, s.wall, p), expected);
                inside += expected >= 0;
            }
        }
        EXPECT_GT(inside, 1000);  // the points do hit the cells
        EXPECT_EQ(index.find(0, 0, {std::nan(""), 0}), -1);
    }
}

TEST(Plan, BlendStripsPrecedeGeometry) {
    const auto d = testing::hall();
    const Plan plan = planZones(d);
    for (const WallSide& s : plan.sides) {
        // Just beyond the geometry border (towards the cell) we are in a texture->geometry blend.
        const double dG = s.geometryDistance + 0.5 * plan.options.blendWidth;
        const glm::dvec2 p(0.3, s.side == 0 ? dG : -dG);
        const int z = findZone(plan, s.cell, s.wall, p);
        ASSERT_GE(z, 0);
        EXPECT_EQ(plan.zones[z].kind, ZoneKind::Blend);
        EXPECT_TRUE(plan.zones[z].mixesGeometry);
        const int g = findZone(plan, s.cell, s.wall, {0.3, s.side == 0 ? 0.1 : -0.1});
        EXPECT_EQ(plan.zones[g].kind, ZoneKind::Geometry);
    }
}

TEST(Plan, AlphaEdgeCases) {
    const auto d = testing::hall();
    for (double alphaDeg : {1e-4, 0.5, 3.0, 30.0, 60.0, 89.0, 90.0}) {
        SCOPED_TRACE(alphaDeg);
        PlanOptions o;
        o.alphaDeg = alphaDeg;
        const Plan plan = planZones(d, o);  // a hang is ctest's timeout, not a clock read here
        expectPlanKeepsItsPromises(d, plan);
        if (alphaDeg < 1e-3) {
            EXPECT_TRUE(plan.textures.empty());  // all geometry
        }
        // Near 90° almost any eye in front of the wall is within the bound.
        if (alphaDeg >= 60) {
            EXPECT_LT(plan.sides[0].geometryDistance, 1.0);
        }
    }
}

TEST(Plan, GeometryStripShrinksAsAlphaGrows) {
    const auto d = testing::hall();
    double previous = 1e9;
    for (double alphaDeg : {5.0, 10.0, 20.0, 40.0}) {
        PlanOptions o;
        o.alphaDeg = alphaDeg;
        const Plan plan = planZones(d, o);
        std::printf("alpha %g: geometry strip %.2f m, %zu textures, %zu zones\n", alphaDeg,
                    plan.sides[0].geometryDistance, plan.textures.size(), plan.zones.size());
        // A larger alpha proves zones nearer the wall (the cone around each texel widens).
        EXPECT_LT(plan.sides[0].geometryDistance, previous);
        previous = plan.sides[0].geometryDistance;
    }
}

TEST(Plan, OptionsAreValidated) {
    struct Bad {
        const char* name;
        PlanOptions options;
        const char* message;
    };
    PlanOptions zeroAlpha, bigAlpha, thinZones, badBlend;
    zeroAlpha.alphaDeg = 0;
    bigAlpha.alphaDeg = 91;
    thinZones.minZoneSize = 0.3;
    thinZones.blendWidth = 0.2;
    badBlend.blendWidth = -1;
    const Bad cases[] = {
        {"zero alpha", zeroAlpha, "alpha: expected an angle in (0, 90] degrees, got 0"},
        {"alpha above 90", bigAlpha, "got 91"},
        {"zones thinner than two blends", thinZones,
         "minZoneSize: expected more than twice blendWidth (0.4 m), got 0.3 m"},
        {"negative blend", badBlend, "blendWidth: expected a finite width >= 0 m, got -1"},
    };
    for (const Bad& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { planZones(testing::hall(), c.options); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

}  // namespace
// A 1e308 extent would make the planner spin forever: absurd cells are refused up front.
TEST(Plan, AbsurdCellsAreRefusedNotPlanned) {
    for (double size : {3e4, 1e308}) {
        SCOPED_TRACE(size);
        scenes::SceneDescription d = testing::hall();
        d.cells[0].region = {{6, 0}, {6, size}, {-6, size}, {-6, 0}};
        EXPECT_THAT([&] { planZones(d); }, ThrowsMessage<Error>(HasSubstr("cell 'front': extent of ")));
        EXPECT_THAT([&] { planZones(d); },
                    ThrowsMessage<Error>(HasSubstr(" m is too large to plan (expected at most 20000 m)")));
    }
}

}  // namespace cavewall::walls
