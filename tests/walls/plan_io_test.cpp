#include "config/error.h"
#include "walls/plan_diagram.h"
#include "walls/plan_io.h"

#include "tests/walls/test_scenes.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;

TEST(PlanIo, JsonRoundTripKeepsZonesAndSamplingPoints) {
    const Plan plan = planZones(testing::hall());
    const std::string text = planToJson(plan).dump();
    const Plan back = planFromJson(text, "plan.json");
    EXPECT_EQ(planToJson(back).dump(), text);  // doubles are written with round-trip precision
    ASSERT_EQ(back.zones.size(), plan.zones.size());
    EXPECT_EQ(back.textures.size(), plan.textures.size());
    for (std::size_t i = 0; i < plan.zones.size(); ++i) {
        EXPECT_EQ(back.zones[i].floorPolygon, plan.zones[i].floorPolygon);
        ASSERT_EQ(back.zones[i].textures.size(), plan.zones[i].textures.size());
        for (std::size_t k = 0; k < plan.zones[i].textures.size(); ++k)
            EXPECT_EQ(back.textures[back.zones[i].textures[k]].samplingPoint,
                      plan.textures[plan.zones[i].textures[k]].samplingPoint);
    }
    // Unknown depth is written as null and read back as infinity.
    EXPECT_TRUE(planToJson(plan)["walls"][0]["depthBehind"].is_null());
    EXPECT_TRUE(std::isinf(back.walls[0].depthBehind));
}

TEST(PlanIo, JsonHasTheIssuesKeys) {
    const nlohmann::json j = planToJson(planZones(testing::hall()));
    EXPECT_EQ(j["alphaDeg"], 10.0);
    EXPECT_EQ(j["walls"][0]["cells"], nlohmann::json::array({0, 1}));
    int kinds = 0;
    for (const auto& z : j["zones"]) {
        const std::string kind = z["kind"];
        EXPECT_EQ(z.contains("samplingPoint"), kind == "texture");
        EXPECT_EQ(z.contains("samplingPoints"), kind == "blend");
        EXPECT_EQ(z["heightRange"], nlohmann::json::array({1.2, 2.0}));
        kinds |= kind == "texture" ? 1 : kind == "blend" ? 2 : 4;
    }
    EXPECT_EQ(kinds, 7);  // all three kinds occur in the hall
}

TEST(PlanIo, BadDocumentsNameThePath) {
    const struct {
        const char* name;
        const char* json;
        const char* message;
    } cases[] = {
        {"missing zones", R"({"alphaDeg": 10, "walls": []})", "plan.json: missing required key 'zones'"},
        {"bad kind",
         R"({"alphaDeg": 10, "walls": [{"id": 0, "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "cells": [0, 1], "depthBehind": 2}],
                         "zones": [{"id": 0, "cell": 0, "wall": 0, "kind": "mesh", "floorPolygon": [[0,1],[1,1],[1,2]], "heightRange": [1, 2]}]})",
         "plan.json: zones[0].kind: expected one of \"texture\", \"blend\", \"geometry\", got \"mesh\""},
        {"wall out of range", R"({"alphaDeg": 10, "walls": [], "zones": [{"id": 0, "cell": 0, "wall": 3}]})",
         "zones[0].wall: expected an integer in [0, -1], got 3"},
        {"alpha zero", R"({"alphaDeg": 0, "walls": [], "zones": []})",
         "alphaDeg: expected a number in [1e-09, 90], got 0"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { planFromJson(c.json, "plan.json"); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(PlanIo, SummaryCountsMatchThePlan) {
    const auto d = testing::hall();
    const Plan plan = planZones(d);
    const PlanTotals t = planTotals(plan);
    EXPECT_EQ(t.textureZones + t.blendZones + t.geometryZones, int(plan.zones.size()));
    EXPECT_EQ(t.geometryZones, 2);  // one strip per side of the one wall
    EXPECT_EQ(t.textures, int(plan.textures.size()));
    // RGBA8 is 4 bytes per texel, the MIP chain adds a third.
    EXPECT_DOUBLE_EQ(t.gpuBytes, t.texels * 4 * 4 / 3.0);
    std::ostringstream out;
    printPlanSummary(out, plan, d);
    EXPECT_THAT(out.str(), HasSubstr("front            middle"));
    EXPECT_THAT(out.str(), HasSubstr(std::to_string(t.textures) + " textures"));
    EXPECT_THAT(out.str(), HasSubstr("texel density: 10 px/degree"));
}

// A depth plan's GPU and disk estimates add each texture's depths as the bake makes them: even
// sides (bakeResolution), halved for the march (marchDepthSize), so an odd planned side does not
// count full depths; on disk 2 bytes a depth texel.
TEST(PlanIo, DepthTotalsCountTheHalvedDepthsOfTheBakedSize) {
    Plan plan = planZones(testing::hall());
    ASSERT_GE(plan.textures.size(), 2u);
    plan.options.wallKind = WallKind::Depth;
    plan.options.maxResolution = 512;
    plan.textures[0].resolution = {101, 51};  // baked 102 x 52, marched 51 x 26
    plan.textures[1].resolution = {64, 32};   // baked as planned, marched 32 x 16
    double depthBytes = double(depthTextureBytes(51, 26)) + double(depthTextureBytes(32, 16));
    double diskBytes = 2.0 * (51 * 26 + 32 * 16);
    for (std::size_t i = 2; i < plan.textures.size(); ++i) {
        const glm::ivec2 r = bakeResolution(plan.textures[i].resolution, 512, WallKind::Depth);
        depthBytes += double(depthTextureBytes(r.x / 2, r.y / 2));
        diskBytes += 2.0 * (r.x / 2) * (r.y / 2);
    }
    const PlanTotals t = planTotals(plan);
    EXPECT_DOUBLE_EQ(t.gpuBytes - t.texels * 4 * 4 / 3.0, depthBytes);
    EXPECT_DOUBLE_EQ(t.diskBytes - t.texels * 4 * 4 / 3.0, diskBytes);
}

TEST(PlanIo, TexelDensityRule) {
    // 10 px/degree at 5.73 m: one texel spans 0.1° there, i.e. 5.73 * tan(0.1°) = 1.0 cm.
    EXPECT_NEAR(texelSize(5.7296, 10.0), 0.01, 1e-5);
    const Plan plan = planZones(testing::hall());
    for (const Texture& t : plan.textures) {
        EXPECT_GE(t.resolution.x, 1);
        EXPECT_LE(t.resolution.x, plan.options.maxResolution);
        // The wall is 12 m x 3 m: texels are square, so the aspect ratio is about 4.
        EXPECT_NEAR(double(t.resolution.x) / t.resolution.y, 4.0, 0.05);
    }
}

TEST(PlanIo, DiagramShowsZonesByKind) {
    const auto d = testing::hall();
    const Plan plan = planZones(d);
    const scenes::Image image = planDiagram(plan, d, nullptr, 200);
    ASSERT_EQ(image.width, 200);
    ASSERT_EQ(image.rgba.size(), std::size_t(image.width) * image.height * 4);
    auto pixelAt = [&](glm::dvec2 world) {
        // The panel maps the 12 m x 20 m hall into 200 - 16 pixels along its longer side.
        const double scale = (200 - 16) / 20.0;
        const int x = int(8 + (world.x + 6) * scale), y = int(8 + (world.y + 10) * scale);
        const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
        return glm::ivec3(p[0], p[1], p[2]);
    };
    // Near the wall both sides are geometry (red); far away they are textures (green).
    const glm::ivec3 geometry = pixelAt({-4.5, 0.6}), texture = pixelAt({-4.5, 9.0});
    EXPECT_GT(geometry.r, geometry.g + 60);
    EXPECT_GT(texture.g, texture.r + 30);
}

}  // namespace
}  // namespace cavewall::walls
