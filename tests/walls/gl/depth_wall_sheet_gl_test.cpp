// walls::gl::DepthWallPass cuts rubber sheets: a red card 1 m behind the wall in front of a grey back
// plane 4 m behind it, baked with depth from one sampling point and drawn from an eye 0.6 m to
// the side. Where full geometry from that eye shows the back plane (the gap the card's edge
// opens, which S never saw), the depth wall shows no red: the gap is filled from the back
// plane's texels (walls::reproject, "Cutting rubber sheets"). A march that connects the card to
// the back plane stretches the card's edge over the gap, 20 pixels wide here (1,800 pixels),
// and fails.
#include "display/gl/gl_object.h"
#include "render/gl/scene_renderer.h"
#include "scenes/image_io.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"
#include "walls/depth_wall.h"
#include "walls/gl/depth_wall_pass.h"
#include "walls/gl/offscreen_target.h"
#include "walls/gl/wall_quad.h"
#include "walls/gl/wall_renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <vector>

namespace cavewall::testing {
namespace {

constexpr int kSheetWidth = 512, kSheetHeight = 384;                           // texels of the bake and pixels of the views
const display::ScreenQuad kSheetQuad{{-2, 0, 0}, {2, 0, 0}, {-2, 3, 0}};  // 4 m x 3 m at z = 0, facing +z
const glm::dvec3 kSheetSample(0.0, 1.5, 3.0), kSheetEye(0.6, 1.5, 2.5);
constexpr double kSheetInf = std::numeric_limits<double>::infinity();

// The near box: a red card (1 m x 1 m x 2 cm, thin, so that the eye sees no side of it) 1 m
// behind the wall; a uniform grey back plane 4 m behind it. Ambient light alone.
scenes::Scene silhouetteScene() {
    scenes::Scene s;
    s.name = "depth-sheet-test";
    s.meshes.push_back(scenes::makeTiledQuad({-5, -1.5, -4}, {10, 0, 0}, {0, 6, 0}, 1, 1, {0.5f, 0.5f, 0.5f, 1},
                                             {0.5f, 0.5f, 0.5f, 1}));
    scenes::addObject(s, 0, glm::dmat4(1.0), "back");
    s.meshes.push_back(scenes::makeBox({1.0f, 1.0f, 0.02f}, {0.9f, 0.1f, 0.1f, 1}));
    // Its right edge, x = 1.2083 m, is seen by S (3 m before the wall, 4 m before the card) at
    // texel 372.0 of the wall: on a boundary of the halved depths' 2 x 2 blocks, so that halving
    // keeps the edge where the colour has it.
    scenes::addObject(s, 1, glm::translate(glm::dmat4(1.0), glm::dvec3(0.25 / 0.75 * 2.125, 1.9, -1.01)), "card");
    return s;
}

// Any share of the card's colour: the back plane is grey (red = green = blue), and a sheet
// sampled at the card's edge mixes the two (217, 148, 148).
bool red(const scenes::Image& image, int x, int y) {
    const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
    return p[0] > p[1] + 24 && p[0] > p[2] + 24;
}

// Red anywhere within `slack` pixels of (x, y): an edge moves by up to a depth texel and a pixel.
bool redNear(const scenes::Image& image, int x, int y, int slack) {
    for (int dy = -slack; dy <= slack; ++dy)
        for (int dx = -slack; dx <= slack; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u >= 0 && v >= 0 && u < image.width && v < image.height && red(image, u, v)) return true;
        }
    return false;
}

class DepthWallSheetTest : public GlTest {
protected:
    void noSheetInTheGap(bool halved);
};

void DepthWallSheetTest::noSheetInTheGap(bool halved) {
    if (!context) GTEST_SKIP();
    const int slack = halved ? 4 : 2;
    const scenes::Scene scene = silhouetteScene();
    const std::vector<int> objects{0, 1};
    walls::DepthImage depth;
    const scenes::Image colour =
        walls::gl::WallTextureRenderer(scene, 1.0f).render(kSheetQuad, kSheetSample, {kSheetWidth, kSheetHeight}, objects, depth);
    const glm::dvec2 range = walls::depthRange(depth);

    const display::OffAxisFrustum frustum = display::offAxisFrustum(kSheetQuad, kSheetEye, {0.05, kSheetInf});
    walls::gl::OffscreenTarget target({kSheetWidth, kSheetHeight});
    scenes::Image truth;
    {
        render::gl::SceneRenderer renderer(scene, render::gl::RenderSettings{glm::vec4(0.0f), 1.0f});
        render::gl::ViewTarget view;
        view.framebuffer = target.framebuffer();
        view.viewport = {0, 0, kSheetWidth, kSheetHeight};
        view.clearColor = glm::vec4(0.0f);
        render::DrawFilter filter;
        filter.objects = &objects;
        renderer.renderFrustum(frustum, glm::dmat4(1.0), view, filter);
        truth = target.read("truth");
    }

    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour});
    const walls::gl::DepthTexture depthTexture = walls::gl::uploadDepthTexture(halved ? walls::marchDepths(depth) : depth);
    target.bindAndClear(glm::vec4(0.0f));
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    walls::gl::DepthWallDraw d{kSheetQuad, {}, 1};
    d.layers[0].colour = colourTexture.id();
    d.layers[0].depth = depthTexture.depth.id();
    d.layers[0].samplingPoint = kSheetSample;
    d.layers[0].range = range;
    d.layers[0].weight = 1.0f;
    d.layers[0].skip = depthTexture.skip.id();
    d.layers[0].content = walls::contentRect(depth);
    d.layers[0].depthTexels = halved ? glm::ivec2(kSheetWidth / 2, kSheetHeight / 2) : glm::ivec2(kSheetWidth, kSheetHeight);
    display::FrameStats stats;
    walls::gl::DepthWallPass().draw({d}, frustum, glm::dmat4(1.0), 0, stats);
    const scenes::Image wall = target.read("wall");

    // Per row, the widest run of the card's colour where the reference shows the back plane.
    int redTruth = 0, redWall = 0, inGap = 0, widest = 0;
    for (int y = 0; y < kSheetHeight; ++y)
        for (int x = 0, run = 0; x < kSheetWidth; ++x) {
            redTruth += red(truth, x, y);
            const bool wallRed = red(wall, x, y), gap = wallRed && !redNear(truth, x, y, slack);
            redWall += wallRed;
            inGap += gap;
            run = gap ? run + 1 : 0;
            widest = std::max(widest, run);
        }
    std::printf(
        "%scut sheet: card %d px in the reference, %d px in the depth wall, %d of them over the back plane, at most %d "
        "in a row\n",
        halved ? "halved " : "", redTruth, redWall, inGap, widest);
    EXPECT_GT(redTruth, 5000);              // the card is there
    EXPECT_GT(redWall, redTruth * 9 / 10);  // and the depth wall draws it
    // No sheet: at most a pixel where the back plane's hit lies within a texel of the card's
    // edge and the colour filter mixes in the card's texel (as on flat walls).
    EXPECT_LE(widest, 1);
    if (::testing::Test::HasFailure()) {
        const std::filesystem::path dir = testOutputFolder(halved ? "depth_wall_sheet_halved" : "depth_wall_sheet");
        scenes::writeImage(dir / "truth.png", truth);
        scenes::writeImage(dir / "depth_wall.png", wall);
        std::printf("images in %s\n", dir.string().c_str());
    }
}

TEST_F(DepthWallSheetTest, TheGapShowsNoNearColour) { noSheetInTheGap(false); }

TEST_F(DepthWallSheetTest, TheGapShowsNoNearColourWithHalvedDepths) { noSheetInTheGap(true); }

}  // namespace
}  // namespace cavewall::testing
