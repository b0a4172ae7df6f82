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
