#include "display/display.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cavewall::display {
namespace {

// cave4 drawn mono: one view per screen, from the head (the preset is stereo).
config::DisplayConfig monoCave4() {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    c.stereo = config::StereoMode::Mono;
    return c;
}

TEST(Display, OneViewPerScreenAndEye) {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    c.stereo = config::StereoMode::Mono;  // the preset is stereo
    EXPECT_EQ(Display(c).views({}).size(), 4u);
    c.stereo = config::StereoMode::Separate;
    const Display stereo(c);
    const auto views = stereo.views(stereo.defaultHead());
    ASSERT_EQ(views.size(), 8u);
    EXPECT_EQ(imageStem(stereo, views[0]), "front-left");
    EXPECT_EQ(imageStem(stereo, views[1]), "front-right");
    // Both eyes of the pair are half the separation either side of the head.
    EXPECT_NEAR(glm::distance(views[0].frustum.eye, views[1].frustum.eye), 0.064, 1e-15);
}

TEST(Display, NeighbouringScreensMeetAtTheSharedEdge) {
    // The front and left walls share the edge x = -1.5, z = -1.5. A point on that edge must land
    // on the left border of the front image and the right border of the left image, at the same
    // height, for any eye: that is a seamless corner.
    const Display d(monoCave4());
    const auto views = d.views({{0.7, 1.1, 0.9}, glm::dquat(1, 0, 0, 0)});
    for (double y : {0.1, 1.0, 2.9}) {
        const glm::dvec4 p(-1.5, y, -1.5, 1.0);
        const glm::dvec4 front = views[0].frustum.clipFromFrame() * p;
        const glm::dvec4 left = views[1].frustum.clipFromFrame() * p;
        EXPECT_NEAR(front.x / front.w, -1.0, 1e-12);
        EXPECT_NEAR(left.x / left.w, 1.0, 1e-12);
        EXPECT_NEAR(front.y / front.w, left.y / left.w, 1e-12);
    }
}

// A tilted, off-centre screen (a monitor leaning back, right of the viewer), 0.6 m x 0.34 m.
ScreenQuad leaningMonitor() {
    const glm::dvec3 right = glm::normalize(glm::dvec3(1.0, 0.0, 0.2));
    const glm::dvec3 up = glm::normalize(glm::cross(glm::dvec3(0.1, 0.3, 1.0), right));
    const glm::dvec3 lowerLeft(0.2, 1.0, -0.7);
    return {lowerLeft, lowerLeft + 0.6 * right, lowerLeft + 0.34 * up};
}

TEST(Display, AReframedQuadKeepsItsHeightCentreAndPlane) {
    const ScreenQuad q = leaningMonitor();
    const ScreenBasis b = screenBasis(q);
    const glm::dvec3 centre = q.lowerLeft + 0.5 * (b.width * b.right + b.height * b.up);
    for (const glm::ivec2 window : {glm::ivec2(360, 360), glm::ivec2(1920, 600), glm::ivec2(300, 900)}) {
        SCOPED_TRACE(window.x);
        const ScreenQuad r = reframedQuad(q, window);
        const ScreenBasis rb = screenBasis(r);
        EXPECT_NEAR(rb.height, b.height, 1e-12);
        EXPECT_NEAR(rb.width / rb.height, double(window.x) / window.y, 1e-12);  // the window's shape
        EXPECT_LT(glm::distance(r.lowerLeft + 0.5 * (rb.width * rb.right + rb.height * rb.up), centre), 1e-12);
        EXPECT_LT(glm::distance(rb.right, b.right), 1e-12);
        EXPECT_LT(glm::distance(rb.normal, b.normal), 1e-12);
    }
    // The configured shape gives the configured quad back.
    const ScreenQuad same = reframedQuad(q, {600, 340});
    EXPECT_LT(glm::distance(same.lowerLeft, q.lowerLeft) + glm::distance(same.lowerRight, q.lowerRight) +
                  glm::distance(same.upperLeft, q.upperLeft),
              1e-12);
}

TEST(Display, OnlyAScreenWhoseWindowReframesTakesTheWindowsShape) {
    config::DisplayConfig c = config::loadDisplayConfig("desktop");
    ASSERT_TRUE(c.screens[0].window && c.screens[0].window->reframe);  // the desktop preset reframes
    Display desktop(c);
    const ScreenQuad configured = desktop.quad(0);
    EXPECT_FALSE(desktop.reframe(0, {0, 0}));  // a minimised window keeps the quad
    EXPECT_EQ(desktop.quad(0), configured);
    EXPECT_TRUE(desktop.reframe(0, {500, 500}));
    EXPECT_NEAR(screenBasis(desktop.quad(0)).width, screenBasis(configured).height, 1e-12);
    EXPECT_FALSE(desktop.reframe(0, {500, 500}));  // unchanged
    // The frustum follows: a square window's view is as wide as it is high.
    const ScreenView v = desktop.views(desktop.defaultHead())[0];
    const glm::dvec4 l = v.frustum.clipFromFrame() * glm::dvec4(desktop.quad(0).lowerLeft, 1.0);
    const glm::dvec4 r = v.frustum.clipFromFrame() * glm::dvec4(desktop.quad(0).lowerRight, 1.0);
    EXPECT_NEAR(l.x / l.w, -1.0, 1e-12);
    EXPECT_NEAR(r.x / r.w, 1.0, 1e-12);
    // Back to a wide window: from the configured quad, not the square one.
    EXPECT_TRUE(desktop.reframe(0, {1280, 720}));
    EXPECT_NEAR(screenBasis(desktop.quad(0)).width, screenBasis(configured).height * 1280.0 / 720.0, 1e-12);
    // cave4's screens are headless, and a window without "resize" letterboxes: neither changes.
    Display cave(monoCave4());
    EXPECT_FALSE(cave.reframe(0, {500, 100}));
    c.screens[0].window->reframe = false;
    Display letterbox(c);
    EXPECT_FALSE(letterbox.reframe(0, {500, 500}));
    EXPECT_EQ(letterbox.quad(0), configured);
}

TEST(Display, FrustumJsonHasTheDocumentedFields) {
    const Display d(monoCave4());
    const nlohmann::json j = frustumJson(d, d.views(d.defaultHead()));
    ASSERT_EQ(j["screens"].size(), 4u);
    const auto& s = j["screens"][1];
    EXPECT_EQ(s["name"], "left");
    EXPECT_EQ(s["eye"], "center");
    EXPECT_EQ(s["view"].size(), 16u);
    EXPECT_EQ(s["projection"].size(), 16u);
    EXPECT_TRUE(s["far"].is_null());  // cave4 uses an infinite far plane
    // Column-major: element 11 is column 2, row 3 (the -1 that makes w = -z).
    EXPECT_EQ(s["projection"][11], -1.0);
}

}  // namespace
}  // namespace cavewall::display
