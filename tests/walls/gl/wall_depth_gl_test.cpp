// The walls' depth-only passes (WallPass::drawDepth, DepthWallPass::drawDepth): the depth an
// eye sees on a wall, read back as eye distances (display/eye_distance.h) and scored with the
// stereo error (metrics/stereo_error.h) against full geometry seen from the same eye. A depth
// wall gives each pixel the depth of what it shows; a flat wall gives the wall's own depth to
// a scene 1 to 4 m behind it; neither touches colour.
#include "display/eye_distance.h"
#include "metrics/stereo_error.h"
#include "render/gl/scene_renderer.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"
#include "tests/walls/gl/card_wall.h"
#include "walls/depth_wall.h"
#include "walls/gl/depth_wall_pass.h"
#include "walls/gl/offscreen_target.h"
#include "walls/gl/wall_pass.h"
#include "walls/gl/wall_quad.h"
#include "walls/gl/wall_renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace cavewall::testing {
namespace {

constexpr int kFlatWidth = 256, kFlatHeight = 192;     // bake texels and view pixels
const display::ScreenQuad& kFlatQuad = kCardWall;  // tests/walls/gl/card_wall.h
const glm::dvec3 kFlatSample = kCardWallSample;
// The left and right eye 2.5 m in front of the wall, 0.3 m to the right of the sampling point.
const glm::dvec3 kLeft(0.268, 1.5, 2.5), kRight(0.332, 1.5, 2.5);

metrics::DepthImage distances(const walls::gl::OffscreenTarget& target, const display::OffAxisFrustum& frustum,
                              const std::string& name) {
    return {name, kFlatWidth, kFlatHeight, display::eyeDistances(frustum, {kFlatWidth, kFlatHeight}, target.readDepth())};
}

class WallDepthTest : public GlTest {};

TEST_F(WallDepthTest, DepthWallsGiveTheDepthTheEyeSeesFlatWallsTheirOwn) {
    if (!context) GTEST_SKIP();
    const scenes::Scene scene = cardScene("wall-depth-test", 0.4);
    const std::vector<int> objects{0, 1};
    walls::DepthImage depth;
    const scenes::Image colour =
        walls::gl::WallTextureRenderer(scene, 1.0f).render(kFlatQuad, kFlatSample, {kFlatWidth, kFlatHeight}, objects, depth);
    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour});
    const walls::gl::DepthTexture depthTexture = walls::gl::uploadDepthTexture(depth);
    walls::gl::DepthWallDraw depthWall{kFlatQuad, {}, 1};
    depthWall.layers[0] = {colourTexture.id(),    depthTexture.depth.id(), kFlatSample, walls::depthRange(depth), 1.0f,
                           depthTexture.skip.id()};
    const walls::gl::WallDraw flatWall{kFlatQuad, {colourTexture.id()}, {1.0f}, 1};
    const walls::gl::DepthWallPass depthPass;
    const walls::gl::WallPass flatPass;
    walls::gl::OffscreenTarget target({kFlatWidth, kFlatHeight});
    metrics::StereoError depthError, flatError;
    for (const glm::dvec3 eye : {kLeft, kRight}) {
        // Through the wall as the screen, so every pixel shows the wall or what is behind it.
        const display::OffAxisFrustum frustum = display::offAxisFrustum(kFlatQuad, eye, {0.05, 1000.0});
        renderGeometry(scene, objects, frustum, target);
        const metrics::DepthImage truth = distances(target, frustum, "geometry");
        auto depthOnly = [&](auto&& draw, const std::string& name) -> metrics::DepthImage {
            EXPECT_EQ(drawOnCleared(target, draw).drawCalls, 1);
            const scenes::Image image = target.read(name);
            EXPECT_EQ(image.rgba, std::vector<std::uint8_t>(image.rgba.size(), 0)) << name << ": colour was written";
            return distances(target, frustum, name);
        };
        const metrics::DepthImage fromDepthWall =
            depthOnly([&](display::FrameStats& s) { depthPass.drawDepth({depthWall}, frustum, glm::dmat4(1.0), 0, s); },
                      "depth wall");
        const metrics::DepthImage fromFlatWall =
            depthOnly([&](display::FrameStats& s) { flatPass.drawDepth({flatWall}, frustum, glm::dmat4(1.0), 0, s); },
                      "flat wall");
        depthError += metrics::stereoError(fromDepthWall, truth);
        flatError += metrics::stereoError(fromFlatWall, truth);
    }
    // Flat: every pixel the texture covers at the wall, 2.5 to 3.3 m from the eye (vergence 67
    // to 88 arcmin), against 3.5 to 7.2 m behind it (31 to 63 arcmin) or nothing at all: tens of
    // arc minutes. The texture covers the rows of the wall through which the sampling point sees
    // the back plane, 1.5 -+ 3 x 3 / 7 m high, 86 % of its 3 m; the other rows show nothing
    // either way and score 0.
    EXPECT_GT(flatError.meanArcmin(), 20.0);
    EXPECT_NEAR(flatError.shareBeyond(), 6.0 / 7.0, 0.02);
    // Depth: right but for the card's disoccluded edge and the wall's border band, a few
    // pixels wide (walls::depthWallErrorBound), where the error is the card's 30 arcmin against
    // the back plane; elsewhere depth rounding, far under 1 arcmin (llvmpipe: 3.4 % beyond, a
    // mean of 0.8 arcmin, 50 times less than flat).
    EXPECT_LT(depthError.shareBeyond(), 0.05);
    EXPECT_LT(depthError.meanArcmin(), flatError.meanArcmin() / 10.0);
    EXPECT_EQ(depthError.invalidPixels, 0u);
}

// A pane of glass 2 m behind the wall, across its whole width, in front of an opaque plane 4 m
// behind it that covers only the left half: where the glass has nothing behind it, the texels
// (drawn, alpha > 0) get the glass's depth, so a depth wall reprojects the pane; where the
// plane shows through it, the plane's depth (what is seen is reprojected at its own depth);
// above the pane and the plane, nothing.
TEST_F(WallDepthTest, GlassWithNothingBehindItHasItsOwnDepth) {
    if (!context) GTEST_SKIP();
    scenes::Scene scene;
    scene.name = "glass-depth-test";
    scene.meshes.push_back(scenes::makeTiledQuad({-5, -1.5, -4}, {5, 0, 0}, {0, 3, 0}, 1, 1, {0.55f, 0.55f, 0.55f, 1},
                                                 {0.55f, 0.55f, 0.55f, 1}));
    scenes::addObject(scene, 0, glm::dmat4(1.0), "plane");
    scenes::Material glass;
    glass.baseColorFactor = {0.0f, 0.4f, 0.6f, 0.1f};
    glass.alphaMode = scenes::AlphaMode::Blend;
    scene.materials.push_back(glass);
    scenes::Mesh pane =
        scenes::makeTiledQuad({-5, 0, -2}, {10, 0, 0}, {0, 1.5, 0}, 1, 1, glm::vec4(1.0f), glm::vec4(1.0f));
    pane.material = 0;
    scene.meshes.push_back(pane);
    scenes::addObject(scene, 1, glm::dmat4(1.0), "glass");
    walls::DepthImage depth;
    const scenes::Image colour =
        walls::gl::WallTextureRenderer(scene, 1.0f).render(kFlatQuad, kFlatSample, {kFlatWidth, kFlatHeight}, {0, 1}, depth);
    // Texels by their wall position: (x, y) in metres on the 4 m x 3 m wall, rows from the top.
    auto at = [&](double x, double y) {
        const int i = static_cast<int>((x + 2.0) / 4.0 * kFlatWidth), j = static_cast<int>((3.0 - y) / 3.0 * kFlatHeight);
        return static_cast<std::size_t>(j) * kFlatWidth + i;
    };
    // The sampling point (0, 1.5, 3) sees the pane (y 0 to 1.5 at z = -2) through wall rows 0.6
    // to 1.5 m and the plane (y -1.5 to 1.5 at z = -4) through rows 0.21 to 1.5 m, on the left.
    const std::size_t glassOnly = at(1.0, 1.2), glassOverPlane = at(-1.0, 1.2), nothing = at(1.0, 2.5);
    EXPECT_GT(colour.rgba[glassOnly * 4 + 3], 0);
    EXPECT_LT(colour.rgba[glassOnly * 4 + 3], 255);
    EXPECT_NEAR(depth.depth[glassOnly], 2.0, 1e-3);
    EXPECT_NEAR(depth.depth[glassOverPlane], 4.0, 1e-3);
    EXPECT_EQ(colour.rgba[nothing * 4 + 3], 0);
    EXPECT_EQ(depth.depth[nothing], walls::kNoSurface);
}

}  // namespace
}  // namespace cavewall::testing
