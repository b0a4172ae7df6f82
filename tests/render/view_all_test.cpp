// viewAll: placing the CAVE so a whole model is in view (render/view_all.h).
#include "config/display_config.h"
#include "render/view_all.h"
#include "tests/render/render_test_scenes.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::render {
namespace {

using testing::oneScreen;

scenes::Bounds boxOf(glm::dvec3 min, glm::dvec3 max) {
    scenes::Bounds b;
    b.add(min);
    b.add(max);
    return b;
}

// Every corner of `b` in the NDC of `screen` seen from `head`, with worldFromCave applied.
void expectCornersInside(const display::Display& d, const display::HeadPose& head, const scenes::Bounds& b,
                         const ViewAll& v) {
    const display::OffAxisFrustum f =
        display::offAxisFrustum(d.quad(v.screen), head.position, d.depthRange(), d.config().minEyeDistance);
    const glm::dmat4 clipFromWorld = f.clipFromFrame() * glm::inverse(v.worldFromCave);
    double largest = 0.0;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
        const glm::dvec4 clip = clipFromWorld * glm::dvec4(corner, 1.0);
        SCOPED_TRACE(i);
        ASSERT_GT(clip.w, 0.0);  // in front of the eye
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 1.0);
        EXPECT_LE(std::abs(ndc.y), 1.0);
        EXPECT_GT(ndc.z, 0.0);  // reversed-Z: beyond the near plane means depth below 1
        EXPECT_LT(ndc.z, 1.0);
        largest = std::max({largest, std::abs(ndc.x), std::abs(ndc.y)});
    }
    EXPECT_GT(largest, 0.4);  // framed, not a speck: the sphere touches the pyramid's sides
}

TEST(ViewAll, FramesABoxFarFromTheOriginInTheSymmetricFrustum) {
    const display::Display d(oneScreen());
    const display::HeadPose head{{0, 0, 0}, glm::dquat(1, 0, 0, 0)};
    const scenes::Bounds b = boxOf({1000, 50, -3000}, {1004, 52, -2990});
    const ViewAll v = viewAll(d, head, b);
    ASSERT_EQ(v.screen, 0);
    // The 90° pyramid's side planes are 45° from the centre ray: the sphere of radius r
    // touches them at distance r / cos 45° = r √2.
    const double r = 0.5 * glm::length(b.size());
    EXPECT_NEAR(v.distance, r * std::sqrt(2.0), 1e-9 * r);
    expectCornersInside(d, head, b, v);
    // Translation only: the model keeps its size and orientation.
    EXPECT_EQ(glm::dmat3(v.worldFromCave), glm::dmat3(1.0));
}

TEST(ViewAll, PicksTheScreenTheHeadFaces) {
    const display::Display d(config::loadDisplayConfig(CAVEWALL_SOURCE_DIR "/tests/support/cave4_128.json"));
    const scenes::Bounds b = boxOf({-5, 0, -5}, {5, 3, 5});
    struct Case {
        const char* name;
        double yawDeg;  // positive turns left (about +Y)
        const char* screen;
    };
    const Case cases[] = {{"ahead", 0.0, "front"}, {"turned left", 90.0, "left"}, {"turned right", -90.0, "right"}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const display::HeadPose head{{0.2, 1.7, 0.3}, glm::angleAxis(glm::radians(c.yawDeg), glm::dvec3(0, 1, 0))};
        const ViewAll v = viewAll(d, head, b);
        ASSERT_GE(v.screen, 0);
        EXPECT_EQ(d.screens()[v.screen].name, c.screen);
        expectCornersInside(d, head, b, v);
    }
}

TEST(ViewAll, EmptyBoundsLeaveTheCaveWhereItIs) {
    const display::Display d(oneScreen());
    const ViewAll v = viewAll(d, d.defaultHead(), scenes::Bounds{});
    EXPECT_EQ(v.screen, -1);
    EXPECT_EQ(v.worldFromCave, glm::dmat4(1.0));
}

}  // namespace
}  // namespace cavewall::render
