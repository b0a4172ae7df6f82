// Pixels that only show in pixels: per-screen viewports of a whole CAVE, the fold-out, and a
// stereo mode's colour masks. Fixed pose, 128 x 128 screens, llvmpipe goldens.
#include "config/display_config.h"
#include "display/display.h"
#include "render/gl/snapshot.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"

#include <glm/gtc/quaternion.hpp>

namespace cavewall::render::gl {
namespace {

using testing::expectMatchesGolden;

// Off-centre (left, forward, below standing height) and turned a little, so no screen's frustum
// is symmetric and the corners have to line up from an unusual eye.
display::HeadPose offCentreHead() {
    return {{-0.6, 1.45, -0.4}, glm::angleAxis(glm::radians(20.0), glm::dvec3(0, 1, 0))};
}

config::DisplayConfig cave128() {
    return config::loadDisplayConfig((testing::testConfigFolder() / "cave4_128.json").string());
}

class RenderGolden : public testing::GlTest {};

TEST_F(RenderGolden, Cave4ScreensAndFoldoutFromAnOffCentreEye) {
    const display::Display cave(cave128());
    Snapshotter snapshotter(cave, scenes::builtinTestScene(), *context);
    const Snapshot frame = snapshotter.render(offCentreHead());
    ASSERT_EQ(frame.images.size(), 4u);
    for (const scenes::ScreenImage& image : frame.images) {
        SCOPED_TRACE(image.stem);
        expectMatchesGolden(image.pixels, "cave4-" + image.stem);
    }
    // 128 px over 3 m: three screens across (left, floor, right), two down (front, floor).
    EXPECT_EQ(frame.foldout.width, 384);
    EXPECT_EQ(frame.foldout.height, 256);
    expectMatchesGolden(frame.foldout, "cave4-foldout");
}

TEST_F(RenderGolden, AnaglyphWritesTheLeftEyeToRedAndTheRightEyeToGreenAndBlue) {
    config::DisplayConfig config = cave128();
    config.stereo = config::StereoMode::Anaglyph;
    config.viewer.eyeSeparation = 0.2;  // the widest allowed, so the two images clearly differ
    config.screens.resize(1);           // the front screen is enough for the masks
    const display::Display cave(config);
    Snapshotter snapshotter(cave, scenes::builtinTestScene(), *context);
    const Snapshot frame = snapshotter.render(offCentreHead());
    ASSERT_EQ(frame.images.size(), 1u);
    expectMatchesGolden(frame.images[0].pixels, "cave4-front-anaglyph");
}

TEST_F(RenderGolden, SideBySidePutsTheEyesIntoTheTwoHalves) {
    config::DisplayConfig config = cave128();
    config.stereo = config::StereoMode::SideBySide;
    config.viewer.eyeSeparation = 0.2;
    config.screens.resize(1);
    const display::Display cave(config);
    Snapshotter snapshotter(cave, scenes::builtinTestScene(), *context);
    expectMatchesGolden(snapshotter.render(offCentreHead()).images[0].pixels, "cave4-front-side-by-side");
}

}  // namespace
}  // namespace cavewall::render::gl
