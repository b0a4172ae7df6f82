// Reduced textures render as the full-size ones do at a CAVE's resolution: the reduction is
// the box filter the GPU's MIP levels apply anyway.
#include "display/display.h"
#include "render/gl/snapshot.h"
#include "render/view_all.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "tests/support/gl/gl_test_support.h"
#include "tests/scenes/texture_scene.h"

namespace cavewall::render::gl {
namespace {

const display::HeadPose kEye{{0, 0, 0}, glm::dquat(1, 0, 0, 0)};

class TextureBudget : public testing::GlTest {
protected:
    scenes::Image render(const scenes::Scene& scene) {
        const glm::dmat4 place = render::viewAll(display, kEye, scene.bounds()).worldFromCave;
        Snapshotter s(display, scene, *context);
        return std::move(s.render(kEye, place).images.at(0).pixels);
    }
    const display::Display display{testing::oneScreenDisplay(128, 0.01)};
};

TEST_F(TextureBudget, ReducedTexturesRenderCloseToFullSizeOnes) {
    const auto file = scenes::testing::writeTexturedQuads("texture-budget-render", {{2048, 2048}, {1024, 2048}});
    // Full size: no reduction (2048 is within 16384 a side, 24 MB within the budget).
    const scenes::Scene full = scenes::loadSceneFile(file, nullptr, {16384, std::size_t{1} << 30});
    // 256 px a side at most, then halved to 256 kB: 2048² goes to 256² (256 kB) and then to 128²,
    // 1024 x 2048 to 128 x 256; 192 kB in all.
    const scenes::Scene reduced = scenes::loadSceneFile(file, nullptr, {256, std::size_t{256} << 10});
    ASSERT_EQ(reduced.images.size(), 2u);
    EXPECT_EQ(glm::ivec2(reduced.images[0].width, reduced.images[0].height), glm::ivec2(128, 128));
    EXPECT_EQ(glm::ivec2(reduced.images[1].width, reduced.images[1].height), glm::ivec2(128, 256));
    ASSERT_EQ(full.images.size(), 2u);
    EXPECT_EQ(full.images[0].width, 2048);

    const scenes::Image a = render(full), b = render(reduced);
    // Each quad covers about 60 x 60 pixels of the 128² screen, so 128 texels a side is still
    // more than the screen shows, and the reduction is the box filter the GPU's MIP levels
    // apply: the project's golden tolerance holds (llvmpipe gives identical frames).
    const metrics::ImageComparison c = metrics::compareImages(b, a);
    EXPECT_TRUE(c.passes()) << c.describe();
    if (!c.passes()) {
        scenes::writeImage(testing::testOutputFolder("texture_budget") / "full.png", a);
        scenes::writeImage(testing::testOutputFolder("texture_budget") / "reduced.png", b);
    }
    // The control: reduced below what the screen resolves (4 texels a side, two per quadrant),
    // the quadrants' edges blur over many pixels, and the same comparison fails.
    const scenes::Scene tooSmall = scenes::loadSceneFile(file, nullptr, {4, std::size_t{1} << 30});
    EXPECT_FALSE(metrics::compareImages(render(tooSmall), a).passes());
}

}  // namespace
}  // namespace cavewall::render::gl
