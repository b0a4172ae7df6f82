#include "display/stereo.h"

#include <gtest/gtest.h>

namespace cavewall::display {
namespace {

using config::StereoMode;

TEST(Stereo, EyesSitAlongTheHeadsXAxis) {
    const glm::dvec3 head{0.5, 1.7, 0.2};
    const glm::dquat ahead(1, 0, 0, 0);
    EXPECT_EQ(eyePosition(head, ahead, 0.064, Eye::Left), head + glm::dvec3(-0.032, 0, 0));
    EXPECT_EQ(eyePosition(head, ahead, 0.064, Eye::Right), head + glm::dvec3(0.032, 0, 0));
    EXPECT_EQ(eyePosition(head, ahead, 0.064, Eye::Center), head);
    // Turned 90° left (yaw +90° about +Y), the head's +X axis becomes -Z, so the right eye
    // moves towards the front wall.
    const glm::dquat left90 = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
    const glm::dvec3 r = eyePosition(head, left90, 0.064, Eye::Right);
    EXPECT_NEAR(r.z, head.z - 0.032, 1e-15);
    EXPECT_NEAR(r.x, head.x, 1e-15);
}

TEST(Stereo, PassesCoverTheImageForEveryMode) {
    const glm::ivec2 res{1001, 600};  // odd width: halves must still cover every pixel
    EXPECT_EQ(eyePasses(StereoMode::Mono, res).size(), 1u);
    const auto sbs = eyePasses(StereoMode::SideBySide, res);
    ASSERT_EQ(sbs.size(), 2u);
    EXPECT_EQ(sbs[0].viewport, (Viewport{0, 0, 500, 600}));
    EXPECT_EQ(sbs[1].viewport, (Viewport{500, 0, 501, 600}));
    const auto tb = eyePasses(StereoMode::TopBottom, res);
    EXPECT_EQ(tb[0].eye, Eye::Left);
    EXPECT_EQ(tb[0].viewport, (Viewport{0, 300, 1001, 300}));  // left eye on top (GL origin is lower-left)
    EXPECT_EQ(tb[1].viewport, (Viewport{0, 0, 1001, 300}));
    const auto sep = eyePasses(StereoMode::Separate, res);
    EXPECT_EQ(sep[0].image, 0);
    EXPECT_EQ(sep[1].image, 1);
    EXPECT_EQ(imagesPerScreen(StereoMode::Separate), 2);
    const auto ana = eyePasses(StereoMode::Anaglyph, res);
    EXPECT_EQ(ana[0].colorMask, glm::bvec4(true, false, false, true));  // left: red
    EXPECT_EQ(ana[1].colorMask, glm::bvec4(false, true, true, true));   // right: cyan
    EXPECT_TRUE(eyePasses(StereoMode::QuadBuffer, res)[1].backRight);
}

}  // namespace
}  // namespace cavewall::display
