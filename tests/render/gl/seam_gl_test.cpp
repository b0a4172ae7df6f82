// A straight edge crossing from one screen to its neighbour must continue across the shared
// screen edge: the pixel rows it occupies at the two images' touching columns agree.
#include "config/display_config.h"
#include "display/display.h"
#include "render/gl/snapshot.h"
#include "scenes/primitives.h"
#include "scenes/image_io.h"
#include "tests/support/gl/gl_test_support.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iostream>
#include <optional>

namespace cavewall::render::gl {
namespace {

// A long thin white bar beyond the front-left corner, tilted about two axes so that it runs
// at a slant across both the front and the left screen.
scenes::Scene barScene() {
    scenes::Scene scene;
    scene.meshes.push_back(scenes::makeBox({9.0f, 0.12f, 0.12f}, glm::vec4(1.0f)));
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(-4.0, 1.1, -4.0));
    m = glm::rotate(m, glm::radians(25.0), glm::dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(15.0), glm::dvec3(0, 0, 1));
    scenes::addObject(scene, 0, m, "bar");
    return scene;
}

// The mean row of bar pixels (bright red channel) in column `x`, or nullopt when none.
std::optional<double> barRow(const scenes::Image& image, int x) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        if (image.rgba[(std::size_t(y) * image.width + x) * 4] > 100) {
            sum += y;
            ++count;
        }
    if (count == 0) return std::nullopt;
    return sum / count;
}

class Seam : public testing::GlTest {};

TEST_F(Seam, BarMeetsItselfAtTheFrontLeftEdgeFromAnOffCentreEye) {
    config::DisplayConfig config = config::loadDisplayConfig((testing::testConfigFolder() / "cave4_128.json").string());
    config.screens.resize(2);  // front, left
    for (auto& s : config.screens) s.resolution = {256, 256};
    const display::Display cave(config);
    Snapshotter snapshotter(cave, barScene(), *context);
    const display::HeadPose head{{0.5, 1.6, 0.5}, glm::dquat(1, 0, 0, 0)};
    const Snapshot frame = snapshotter.render(head);
    const scenes::Image& front = frame.images[0].pixels;
    const scenes::Image& left = frame.images[1].pixels;

    // The shared edge x = z = -1.5 is the front image's left border and the left image's right
    // border (both walls' corners list it): column 0 of one touches column 255 of the other.
    const auto frontRow = barRow(front, 0);
    const auto leftRow = barRow(left, left.width - 1);
    ASSERT_TRUE(frontRow.has_value()) << "the bar must reach the front image's left border";
    ASSERT_TRUE(leftRow.has_value()) << "the bar must reach the left image's right border";
    // Neighbouring pixel columns one pixel apart: the slanted bar moves well under a pixel
    // between them, so its rows must agree within one pixel.
    EXPECT_NEAR(*frontRow, *leftRow, 1.0);
    std::cout << "bar row at the shared edge: front " << *frontRow << ", left " << *leftRow << "\n";

    // The bar really is slanted in both images (a test that a horizontal bar passes proves
    // little): 60 columns in, its row has moved by several pixels.
    const auto frontInside = barRow(front, 60), leftInside = barRow(left, left.width - 61);
    ASSERT_TRUE(frontInside && leftInside);
    EXPECT_GT(std::abs(*frontInside - *frontRow), 3.0);
    EXPECT_GT(std::abs(*leftInside - *leftRow), 3.0);
    if (HasFailure()) {
        scenes::writeImage(testing::testOutputFolder("seam") / "front.png", front);
        scenes::writeImage(testing::testOutputFolder("seam") / "left.png", left);
    }
}

}  // namespace
}  // namespace cavewall::render::gl
