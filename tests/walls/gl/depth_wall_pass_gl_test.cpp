// walls::gl::DepthWallPass against full geometry: a wall baked with depth from one sampling point and
// drawn from an eye 0.6 m to the side and 0.5 m closer matches the geometry rendered from that
// eye, except on the pixels walls::depthWallErrorBound predicts (disocclusion at the depth
// steps it opens, and the wall's border); and the widest wrong run is within the bound. The
// flat wall from the same eye is wrong on far more pixels.
#include "display/gl/gl_object.h"
#include "render/gl/scene_renderer.h"
#include "scenes/image_io.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"
#include "tests/walls/gl/card_wall.h"
#include "walls/depth_wall.h"
#include "walls/gl/depth_wall_pass.h"
#include "walls/gl/offscreen_target.h"
#include "walls/gl/wall_pass.h"
#include "walls/gl/wall_quad.h"
#include "walls/gl/wall_renderer.h"
#include "walls/texture_blocks.h"
#include "walls/texture_pager.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace cavewall::testing {
namespace {

constexpr int kWidth = 512, kHeight = 384;     // texels of the bake and pixels of the views: 7.8 mm on the wall
constexpr int kColourTolerance = 40;           // 8-bit sRGB levels per channel
const display::ScreenQuad& kQuad = kCardWall;  // tests/walls/gl/card_wall.h
const glm::dvec3 kSample = kCardWallSample, kEye(0.6, 1.5, 2.5);
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kCardX = 0.7;  // the card's centre, x (cardScene)

bool differs(const scenes::Image& a, const scenes::Image& b, int x, int y, int slack = 2) {
    // Wrong unless some reference pixel within `slack` pixels has the same colour: an edge moves
    // by up to a depth texel (nearest-texel depth, bake texel = view pixel here) and a pixel
    // (rasterising against resampling).
    const std::uint8_t* p = &a.rgba[(std::size_t(y) * a.width + x) * 4];
    for (int dy = -slack; dy <= slack; ++dy)
        for (int dx = -slack; dx <= slack; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= b.width || v >= b.height) continue;
            const std::uint8_t* q = &b.rgba[(std::size_t(v) * b.width + u) * 4];
            if (std::abs(p[0] - q[0]) <= kColourTolerance && std::abs(p[1] - q[1]) <= kColourTolerance &&
                std::abs(p[2] - q[2]) <= kColourTolerance)
                return false;
        }
    return true;
}

class DepthWallPassTest : public GlTest {
protected:
    // The test of the file's header. `halved`: the depths the walkthrough marches
    // (walls::marchDepths: each depth texel the nearest of 2 x 2 colour texels), against the
    // full image's prediction with a depth texel (two pixels here) more allowance either side.
    // This scene's uniform colours hide a misplaced depth (depths shifted by 15 texels pass
    // too): the halving's values are checked in tests/walls/depth_wall_test.cpp, and so is the
    // proven bound of what the halved march draws (walls::marchErrorBound, tight within 0.6
    // against the reference march), which TheShaderMarchesHalvedDepthsAsItsReference ties to
    // the shader.
    void matchesGeometryExceptWherePredicted(bool halved);
    // The shader's march against walls::reproject, pixel by pixel (TheShaderMarchesAsItsReference).
    void marchesAsItsReference(bool halved);
    // `objects` of `scene` baked on kQuad from kSample at kWidth x kHeight: the colour, and the
    // depth into `depth`.
    static scenes::Image bake(const scenes::Scene& scene, const std::vector<int>& objects, walls::DepthImage& depth) {
        walls::gl::WallTextureRenderer baker(scene, 1.0f);
        return baker.render(kQuad, kSample, {kWidth, kHeight}, objects, depth);
    }
};

TEST_F(DepthWallPassTest, MatchesGeometryFromAnotherEyeExceptWhereTheBoundPredicts) {
    matchesGeometryExceptWherePredicted(false);
}

TEST_F(DepthWallPassTest, HalvedDepthsMatchGeometryWithinADepthTexelOfThePrediction) {
    matchesGeometryExceptWherePredicted(true);
}

void DepthWallPassTest::matchesGeometryExceptWherePredicted(bool halved) {
    if (!context) GTEST_SKIP();
    const int slack = halved ? 4 : 2;  // pixels: a depth texel and a pixel, as in differs()
    const scenes::Scene scene = cardScene("depth-wall-test", kCardX);
    const std::vector<int> objects{0, 1};
    const walls::WallFrame frame = walls::wallFrame(kQuad);
    const glm::dvec3 eye = frame.toWall(kEye), sample = frame.toWall(kSample);

    // Bake colour and depth from the sampling point.
    walls::DepthImage depth;
    const scenes::Image colour = bake(scene, objects, depth);
    const glm::dvec2 range = walls::depthRange(depth);
    EXPECT_NEAR(range.x, 1.0, 1e-5);  // the card's face; float depth buffer, depth_wall.h
    EXPECT_NEAR(range.y, 4.0, 1e-5);  // the back plane
    const walls::DepthWallBound bound = walls::depthWallErrorBound(depth, frame, eye, sample);

    // Full geometry from the eye, through the wall as its screen (pixels = wall points).
    const display::OffAxisFrustum frustum = display::offAxisFrustum(kQuad, kEye, {0.05, kInf});
    walls::gl::OffscreenTarget target({kWidth, kHeight});
    renderGeometry(scene, objects, frustum, target);
    const scenes::Image truth = target.read("truth");

    // The depth wall and the flat wall from the same eye.
    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour});
    const walls::gl::DepthTexture depthTexture =
        walls::gl::uploadDepthTexture(halved ? walls::marchDepths(depth) : depth);
    auto drawWith = [&](auto&& draw) {
        EXPECT_EQ(drawOnCleared(target, draw).drawCalls, 1);
        return target.read("wall");
    };
    const walls::gl::DepthWallPass depthPass;
    walls::gl::DepthWallDraw d{kQuad, {}, 1};
    d.layers[0] = {colourTexture.id(), depthTexture.depth.id(), kSample, range, 1.0f, depthTexture.skip.id()};
    const scenes::Image depthWall =
        drawWith([&](display::FrameStats& s) { depthPass.draw({d}, frustum, glm::dmat4(1.0), 0, s); });
    const walls::gl::WallPass flatPass;
    const scenes::Image flatWall = drawWith([&](display::FrameStats& s) {
        flatPass.draw({walls::gl::WallDraw{kQuad, {colourTexture.id()}, {1.0f}, 1}}, frustum, glm::dmat4(1.0), 0, s);
    });

    // The predicted pixels: the interval each opening step exposes, and the border's.
    const double pitch = frame.width / kWidth;
    std::vector<char> predicted(std::size_t(kWidth) * kHeight, 0);  // 1: a step's interval, 2: the border band
    auto mark = [&](glm::dvec2 a, glm::dvec2 b, char kind) {
        const int n = 2 + static_cast<int>(glm::length(b - a) / (0.25 * pitch));
        for (int k = 0; k <= n; ++k) {
            const glm::dvec2 p = a + (b - a) * (double(k) / n);
            const int x = static_cast<int>(std::floor(p.x / pitch)),
                      y = static_cast<int>(std::floor((frame.height - p.y) / pitch));
            for (int dy = -slack; dy <= slack; ++dy)  // either side: depth texel and pixel rounding
                for (int dx = -slack; dx <= slack; ++dx)
                    if (x + dx >= 0 && y + dy >= 0 && x + dx < kWidth && y + dy < kHeight)
                        predicted[std::size_t(y + dy) * kWidth + x + dx] |= kind;
        }
    };
    for (int j = 0; j < kHeight; ++j)
        for (int i = 0; i < kWidth; ++i) {
            const float a = depth.at(i, j);
            const glm::dvec2 t = walls::texelCentre(frame, kWidth, kHeight, i, j);
            if (i == 0 || j == 0 || i == kWidth - 1 || j == kHeight - 1) {
                // The border band: from the edge inwards by v . n_in (walls::borderAngle).
                const glm::dvec2 edge(i == 0            ? 0.0
                                      : i == kWidth - 1 ? frame.width
                                                        : t.x,
                                      j == 0             ? frame.height
                                      : j == kHeight - 1 ? 0.0
                                                         : t.y);
                const glm::dvec2 inward(i == 0            ? 1.0
                                        : i == kWidth - 1 ? -1.0
                                                          : 0.0,
                                        j == 0             ? -1.0
                                        : j == kHeight - 1 ? 1.0
                                                           : 0.0);
                const glm::dvec2 v = walls::parallaxVector(eye, sample, edge);
                if (glm::dot(v, inward) > 0.0) mark(edge, edge + inward * glm::dot(v, inward), 2);
            }
            for (glm::ivec2 n :
                 {glm::ivec2(i + 1, j), glm::ivec2(i, j + 1), glm::ivec2(i - 1, j), glm::ivec2(i, j - 1)}) {
                if (n.x < 0 || n.y < 0 || n.x >= kWidth || n.y >= kHeight) continue;
                const float b = depth.at(n.x, n.y);
                if (!(b > a)) continue;  // from the near texel (a) to the far one (b)
                const glm::dvec2 across = walls::texelCentre(frame, kWidth, kHeight, n.x, n.y) - t;
                if (glm::dot(walls::parallaxVector(eye, sample, t), across) <= 0.0) continue;  // closes
                mark(walls::reprojectedPoint(eye, sample, t, a), walls::reprojectedPoint(eye, sample, t, b), 1);
            }
        }

    int wrongOutside = 0, wrongInside = 0, flatWrong = 0, widestRun = 0;
    for (int y = 0; y < kHeight; ++y) {
        int run = 0;
        for (int x = 0; x < kWidth; ++x) {
            const char mask = predicted[std::size_t(y) * kWidth + x];
            const bool inside = mask != 0;
            flatWrong += differs(flatWall, truth, x, y, slack);
            if (differs(depthWall, truth, x, y, slack)) {
                ++(inside ? wrongInside : wrongOutside);
                // Runs along rows in a step's interval away from the border band (the bound's
                // step term: the eye moved along x, so the opening steps open along rows).
                if (mask == 1)
                    widestRun = std::max(widestRun, ++run);
                else
                    run = 0;
            } else {
                run = 0;
            }
        }
    }
    const double de = -eye.z;
    const double widest = widestRun * pitch / de;  // radians, near the wall's centre row
    std::printf(
        "%sdepth wall %d x %d: wrong outside the prediction %d, inside %d; flat wall wrong %d; widest run %d px "
        "= %.4f rad; bound steps %.4f, texel %.5f, border %.4f\n",
        halved ? "halved " : "", kWidth, kHeight, wrongOutside, wrongInside, flatWrong, widestRun, widest, bound.steps,
        bound.texel, bound.border);
    EXPECT_LE(wrongOutside, kWidth * kHeight / 1000);  // 0.1 %: isolated rounding at tile edges
    EXPECT_GT(wrongInside, 0);                         // the eye does see what S did not
    EXPECT_GT(flatWrong, 4 * (wrongInside + wrongOutside));
    EXPECT_LE(widest, bound.steps + 2.0 * bound.texel + slack * pitch / de);
    // The gap a step opens shows the back plane's texels next to it (cut rubber sheets,
    // walls::reproject), which on this back plane are mostly the right colour: the wrong runs
    // are narrower than the step term (6 pixels, against 20 with the card stretched over the
    // gap). The bound's tightness is checked by the angles of the points shown
    // (tests/walls/depth_wall_test.cpp, MarchBoundHoldsForEveryDrawnPixelAndIsTight).
    if (::testing::Test::HasFailure()) {
        // For a look: the three images and the wrong pixels (red outside, yellow inside the prediction).
        const std::filesystem::path dir = testOutputFolder(halved ? "depth_wall_pass_halved" : "depth_wall_pass");
        scenes::Image wrong = truth;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                std::uint8_t* p = &wrong.rgba[(std::size_t(y) * kWidth + x) * 4];
                const bool inside = predicted[std::size_t(y) * kWidth + x] != 0;
                if (differs(depthWall, truth, x, y, slack)) {
                    p[0] = 255;
                    p[1] = inside ? 255 : 0;
                    p[2] = 0;
                } else if (inside)
                    p[2] = 255;
            }
        scenes::writeImage(dir / "truth.png", truth);
        scenes::writeImage(dir / "depth_wall.png", depthWall);
        scenes::writeImage(dir / "flat_wall.png", flatWall);
        scenes::writeImage(dir / "wrong.png", wrong);
        std::printf("images in %s\n", dir.string().c_str());
    }
}

// Geometry drawn before the pass in front of the wall hides the depth wall (the depth test
// runs at the quad's depth before the shader); everywhere else the pass draws what it draws on
// an empty target.
TEST_F(DepthWallPassTest, GeometryInFrontOfTheWallHidesIt) {
    if (!context) GTEST_SKIP();
    scenes::Scene scene = cardScene("depth-wall-test", kCardX);
    scene.meshes.push_back(scenes::makeBox({1.0f, 0.8f, 0.2f}, {0.1f, 0.8f, 0.2f, 1}));
    scenes::addObject(scene, 2, glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, 1.6, 0.8)), "front");
    const std::vector<int> behind{0, 1}, front{2};

    walls::DepthImage depth;
    const scenes::Image colour = bake(scene, behind, depth);
    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour});
    const walls::gl::DepthTexture depthTexture = walls::gl::uploadDepthTexture(depth);
    const walls::gl::DepthWallPass pass;
    walls::gl::DepthWallDraw d{kQuad, {}, 1};
    d.layers[0] = {colourTexture.id(),    depthTexture.depth.id(), kSample, walls::depthRange(depth), 1.0f,
                   depthTexture.skip.id()};

    const display::OffAxisFrustum frustum = display::offAxisFrustum(kQuad, kEye, {0.05, kInf});
    walls::gl::OffscreenTarget target({kWidth, kHeight});
    auto drawWall = [&] {
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        display::FrameStats stats;
        pass.draw({d}, frustum, glm::dmat4(1.0), 0, stats);
        EXPECT_EQ(stats.drawCalls, 1);
    };
    target.bindAndClear(glm::vec4(0.0f));
    drawWall();
    const scenes::Image wallOnly = target.read("wall");

    renderGeometry(scene, front, frustum, target);
    const scenes::Image occluder = target.read("front");
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, kWidth, kHeight);
    drawWall();
    const scenes::Image both = target.read("both");

    int covered = 0, shown = 0, wrong = 0;
    for (std::size_t i = 0; i < both.rgba.size(); i += 4) {
        const bool hidden = occluder.rgba[i + 3] == 255;
        const scenes::Image& expected = hidden ? occluder : wallOnly;
        covered += hidden;
        shown += !hidden && wallOnly.rgba[i] + wallOnly.rgba[i + 1] + wallOnly.rgba[i + 2] > 0;  // (keeps alpha)
        for (int c = 0; c < 4; ++c) wrong += std::abs(int(both.rgba[i + c]) - int(expected.rgba[i + c])) > 1;
    }
    EXPECT_GT(covered, kWidth * kHeight / 20);  // the box covers a good part of the wall
    EXPECT_GT(shown, kWidth * kHeight / 4);     // and the wall shows around it
    EXPECT_EQ(wrong, 0);
}

// Blended layers share one march (walls::gl::DepthWallPass header): the heaviest layer's hit depth,
// else the next layer's. Two layers of one texture therefore draw exactly what it draws alone,
// and a heaviest layer with nothing in it (no depth anywhere) falls back to the next layer's
// march: [empty 0.5, real 0.5] draws what [real 0.5] draws; a lighter layer is sampled where
// the heaviest layer's ray landed, whatever its own depth says. A second texture from another
// sampling point, blended in, shows its own colours where the first layer's ray lands.
TEST_F(DepthWallPassTest, BlendedLayersShareTheHeaviestLayersMarch) {
    if (!context) GTEST_SKIP();
    const scenes::Scene scene = cardScene("depth-wall-test", kCardX);
    const std::vector<int> objects{0, 1};
    walls::DepthImage depth, otherDepth;
    scenes::Image colour, other;
    const glm::dvec3 otherSample(-0.8, 1.4, 2.6);
    {
        walls::gl::WallTextureRenderer baker(scene, 1.0f);
        colour = baker.render(kQuad, kSample, {kWidth, kHeight}, objects, depth);
        other = baker.render(kQuad, otherSample, {kWidth, kHeight}, objects, otherDepth);
    }
    scenes::Image emptyColour = colour;
    std::fill(emptyColour.rgba.begin(), emptyColour.rgba.end(), std::uint8_t(0));
    const walls::DepthImage emptyDepth{kWidth, kHeight,
                                       std::vector<float>(std::size_t(kWidth) * kHeight, walls::kNoSurface)};
    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour}),
                                otherColour = walls::gl::uploadWallTexture({other});
    const display::gl::GlObject emptyTexture = walls::gl::uploadWallTexture({emptyColour});
    const walls::gl::DepthTexture depthTexture = walls::gl::uploadDepthTexture(depth),
                                  otherDepthTexture = walls::gl::uploadDepthTexture(otherDepth);
    const walls::gl::DepthTexture emptyDepthTexture = walls::gl::uploadDepthTexture(emptyDepth);
    const walls::gl::DepthWallLayer real{
        colourTexture.id(), depthTexture.depth.id(), kSample, walls::depthRange(depth), 1.0f, depthTexture.skip.id()};
    const walls::gl::DepthWallLayer second{
        otherColour.id(),           otherDepthTexture.depth.id(), otherSample, walls::depthRange(otherDepth), 1.0f,
        otherDepthTexture.skip.id()};
    const walls::gl::DepthWallLayer nothing{
        emptyTexture.id(), emptyDepthTexture.depth.id(), kSample, glm::dvec2(0.0), 1.0f, emptyDepthTexture.skip.id()};

    const display::OffAxisFrustum frustum = display::offAxisFrustum(kQuad, kEye, {0.05, kInf});
    walls::gl::OffscreenTarget target({kWidth, kHeight});
    const walls::gl::DepthWallPass pass;
    auto draw = [&](std::vector<std::pair<walls::gl::DepthWallLayer, float>> layers) {
        walls::gl::DepthWallDraw d{kQuad, {}, 0};
        for (auto [layer, weight] : layers) {
            layer.weight = weight;
            d.layers[d.count++] = layer;
        }
        drawOnCleared(target, [&](display::FrameStats& stats) { pass.draw({d}, frustum, glm::dmat4(1.0), 0, stats); });
        return target.read("wall");
    };
    auto largestDifference = [](const scenes::Image& a, const scenes::Image& b) {
        int most = 0;
        for (std::size_t i = 0; i < a.rgba.size(); ++i)
            most = std::max(most, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
        return most;
    };
    const scenes::Image alone = draw({{real, 1.0f}});
    EXPECT_LE(largestDifference(draw({{real, 0.7f}, {real, 0.3f}}), alone), 1);
    const scenes::Image half = draw({{real, 0.5f}});
    EXPECT_LE(largestDifference(draw({{nothing, 0.5f}, {real, 0.5f}}), half), 1);
    // Shared, not marched per layer: a lighter layer with the same colour and no depth at all
    // is sampled where the heaviest layer's ray landed (its own march would find nothing).
    const walls::gl::DepthWallLayer colourOnly{
        colourTexture.id(), emptyDepthTexture.depth.id(), kSample, glm::dvec2(0.0), 1.0f, emptyDepthTexture.skip.id()};
    const scenes::Image shared = draw({{real, 0.5f}, {colourOnly, 0.5f}});
    EXPECT_LE(largestDifference(shared, alone), 1);
    EXPECT_GT(largestDifference(shared, half), 1);
    // The other texture blended in changes the image (it is drawn), but less than a texture
    // alone from the other point would: where the card is, both layers show the card.
    const scenes::Image blended = draw({{real, 0.5f}, {second, 0.5f}});
    EXPECT_GT(largestDifference(blended, alone), 1);
    int cardPixels = 0, cardKept = 0;
    for (std::size_t i = 0; i < alone.rgba.size(); i += 4) {
        const bool card = alone.rgba[i] > 150 && alone.rgba[i + 1] < 90;  // red
        cardPixels += card;
        cardKept += card && blended.rgba[i] > 150 && blended.rgba[i + 1] < 90;
    }
    EXPECT_GT(cardPixels, kWidth * kHeight / 50);
    EXPECT_GT(cardKept, cardPixels * 9 / 10);
}

}  // namespace
}  // namespace cavewall::testing

namespace cavewall::testing {
namespace {

// The pass's march against its reference, walls::reproject (the shader is that algorithm in
// float; walls/gl/depth_wall_pass.cpp): random block depths (some blocks empty), a colour
// texture whose every texel has its own colour, sampled nearest, and three eyes, one moved
// diagonally (rays crossing both texture axes). Every pixel must show the texel the reference
// hits at its centre, or nothing where the reference hits nothing; where the reference's hit
// lies within 1/100 texel of a texel edge (hits on a texel's side are exactly on one), either
// neighbour passes. Also at most 3 steps, so that steps span several texels and are bisected
// before the crossing. A march that steps or refines otherwise fails: the crossing's middle
// texel on the wrong axis (337-909 wrong pixels against at most 76), no crossing, or no
// bisection of the long steps (464-5364).
TEST_F(DepthWallPassTest, TheShaderMarchesAsItsReference) { marchesAsItsReference(false); }

// The same with the depths the walkthrough marches (walls::marchDepths of a colour-sized image):
// colour texels half the depth texels' size, so the colour the shader samples at the hit is
// where the reference's hit says, to the colour texel.
TEST_F(DepthWallPassTest, TheShaderMarchesHalvedDepthsAsItsReference) { marchesAsItsReference(true); }

void DepthWallPassTest::marchesAsItsReference(bool halved) {
    if (!context) GTEST_SKIP();
    constexpr int tw = 64, th = 48, vw = 320, vh = 240;                  // depth texels; pixels of the view (5 a texel)
    const int scale = halved ? 2 : 1, cw = tw * scale, ch = th * scale;  // colour texels
    const walls::WallFrame frame = walls::wallFrame(kQuad);
    std::srand(17);
    walls::DepthImage depth{cw, ch, std::vector<float>(std::size_t(cw) * ch)};
    for (int by = 0; by < ch; by += 4 * scale)
        for (int bx = 0; bx < cw; bx += 4 * scale) {
            const int r = std::rand() % 16;
            const float d = r == 0 ? walls::kNoSurface : 1.0f + 3.0f * float(r) / 15.0f;
            for (int j = by; j < by + 4 * scale; ++j)
                for (int i = bx; i < bx + 4 * scale; ++i) depth.depth[std::size_t(j) * cw + i] = d;
        }
    if (halved) depth = walls::marchDepths(std::move(depth));
    ASSERT_EQ(glm::ivec2(depth.width, depth.height), glm::ivec2(tw, th));
    const glm::dvec2 range = walls::depthRange(depth);
    // Each colour texel's id in red and green (4i + 2, 5j + 2; halved 2i + 1, 2j + 1).
    const glm::ivec2 idStep = halved ? glm::ivec2(2, 2) : glm::ivec2(4, 5),
                     idBase = halved ? glm::ivec2(1) : glm::ivec2(2);
    scenes::Image colour{"ids", cw, ch, std::vector<std::uint8_t>(std::size_t(cw) * ch * 4, 255)};
    for (int j = 0; j < ch; ++j)
        for (int i = 0; i < cw; ++i) {
            std::uint8_t* p = &colour.rgba[(std::size_t(j) * cw + i) * 4];
            p[0] = static_cast<std::uint8_t>(idStep.x * i + idBase.x);
            p[1] = static_cast<std::uint8_t>(idStep.y * j + idBase.y);
            p[2] = 128;
        }
    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour});
    const walls::gl::DepthTexture depthTexture = walls::gl::uploadDepthTexture(depth);
    const display::gl::GlObject nearest = display::gl::createSampler();
    glSamplerParameteri(nearest.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(nearest.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(nearest.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(nearest.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    walls::gl::OffscreenTarget target({vw, vh});

    const glm::dvec3 sample(0.0, 1.5, 3.0);
    const glm::dvec3 eyes[] = {{0.6, 1.5, 2.5}, {-0.9, 2.4, 2.2}, {1.5, 0.4, 3.4}};
    // The default settings, and at most 3 steps: longer steps, bisected before the crossing.
    for (const walls::ReprojectSettings settings : {walls::ReprojectSettings{}, walls::ReprojectSettings{3, 6}})
        for (const glm::dvec3& eyeWorld : eyes) {
            const walls::gl::DepthWallPass pass(settings);
            SCOPED_TRACE(::testing::Message() << "eye " << eyeWorld.x << ", " << eyeWorld.y << ", " << eyeWorld.z
                                              << ", at most " << settings.maxSteps << " steps");
            const display::OffAxisFrustum frustum = display::offAxisFrustum(kQuad, eyeWorld, {0.05, kInf});
            walls::gl::DepthWallDraw d{kQuad, {}, 1};
            d.layers[0] = {colourTexture.id(), depthTexture.depth.id(), sample, range, 1.0f, depthTexture.skip.id()};
            drawOnCleared(
                target, [&](display::FrameStats& stats) { pass.draw({d}, frustum, glm::dmat4(1.0), nearest.id(), stats); });
            const scenes::Image got = target.read("march");
            const glm::dvec3 eye = frame.toWall(eyeWorld), s = frame.toWall(sample);
            int hits = 0, wrong = 0, edges = 0;
            for (int y = 0; y < vh; ++y)
                for (int x = 0; x < vw; ++x) {
                    const std::uint8_t* p = &got.rgba[(std::size_t(y) * vw + x) * 4];
                    const glm::dvec2 w((x + 0.5) * frame.width / vw, frame.height - (y + 0.5) * frame.height / vh);
                    const walls::ReprojectHit ref = walls::reproject(depth, frame, eye, s, w, range, settings);
                    // The pass leaves the target's alpha as it was (blending): blue marks a hit.
                    const bool shown = p[2] > 64;
                    if (!ref.hit) {
                        wrong += shown;
                        continue;
                    }
                    ++hits;
                    const glm::dvec2 t(ref.texture.x / frame.width * cw,
                                       (frame.height - ref.texture.y) / frame.height * ch);
                    const int gi = (int(p[0]) - idBase.x + idStep.x / 2) / idStep.x;  // nearest id
                    const int gj = (int(p[1]) - idBase.y + idStep.y / 2) / idStep.y;
                    const bool same = shown && gi == int(std::floor(t.x)) && gj == int(std::floor(t.y));
                    if (same) continue;
                    const double fx = t.x - std::floor(t.x), fy = t.y - std::floor(t.y);
                    const bool nearEdge = std::min(fx, 1.0 - fx) < 0.01 || std::min(fy, 1.0 - fy) < 0.01;
                    const bool neighbour =
                        shown && std::abs(gi - int(std::floor(t.x))) <= 1 && std::abs(gj - int(std::floor(t.y))) <= 1;
                    if (nearEdge && neighbour)
                        ++edges;
                    else
                        ++wrong;
                }
            std::printf(
                "march against reference%s, at most %d steps: %d of %d pixels hit, %d on a texel edge, %d wrong\n",
                halved ? " (halved depths)" : "", settings.maxSteps, hits, vw * vh, edges, wrong);
            EXPECT_GT(hits, vw * vh / 2);
            EXPECT_LE(wrong, vw * vh / 1000);  // float against double: a few pixels at most
        }
}

// The pass draws each wall only over walls::depthDrawRect (the union of its layers', grown by a
// depth texel): a card alone behind the wall, seen from an eye to the side, draws the same
// pixels as the whole wall does (up to a few the float march may round the other way), from a
// rectangle of under a tenth of the wall; a content rectangle that misses the card draws almost
// none of it (so the rectangle is what the pass draws).
TEST_F(DepthWallPassTest, DrawsOnlyWhereAMarchCanHit) {
    if (!context) GTEST_SKIP();
    const scenes::Scene scene = cardScene("depth-wall-test", kCardX);
    const std::vector<int> objects{1};  // the card, no back plane
    walls::DepthImage depth;
    const scenes::Image colour = bake(scene, objects, depth);
    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour});
    const walls::gl::DepthTexture depthTexture = walls::gl::uploadDepthTexture(depth);
    const walls::TextureRect content = walls::contentRect(depth);
    const glm::dvec2 range = walls::depthRange(depth);
    const walls::WallFrame frame = walls::wallFrame(kQuad);
    const walls::TextureRect drawn =
        walls::depthDrawRect(frame, frame.toWall(kEye), frame.toWall(kSample), content, range, 0.0);
    EXPECT_LT((drawn.hi.x - drawn.lo.x) * (drawn.hi.y - drawn.lo.y), 0.1);

    const display::OffAxisFrustum frustum = display::offAxisFrustum(kQuad, kEye, {0.05, kInf});
    walls::gl::OffscreenTarget target({kWidth, kHeight});
    const walls::gl::DepthWallPass pass;
    auto draw = [&](walls::TextureRect rect, glm::ivec2 texels) {
        walls::gl::DepthWallDraw d{kQuad, {}, 1};
        d.layers[0] = {
            colourTexture.id(), depthTexture.depth.id(), kSample, range, 1.0f, depthTexture.skip.id(), rect, texels};
        drawOnCleared(target, [&](display::FrameStats& stats) { pass.draw({d}, frustum, glm::dmat4(1.0), 0, stats); });
        return target.read("wall");
    };
    // The whole wall: the default content and a one-texel texture, whose margin is the wall.
    const scenes::Image whole = draw({}, {1, 1});
    const scenes::Image cropped = draw(content, {kWidth, kHeight});
    const scenes::Image missing = draw({{0.0, 0.0}, {0.1, 0.1}}, {kWidth, kHeight});
    auto lit = [](const scenes::Image& im, std::size_t i) { return im.rgba[i] + im.rgba[i + 1] + im.rgba[i + 2] > 0; };
    int wholePixels = 0, croppedPixels = 0, missingPixels = 0, different = 0;
    for (std::size_t i = 0; i < whole.rgba.size(); i += 4) {
        wholePixels += lit(whole, i);
        croppedPixels += lit(cropped, i);
        missingPixels += lit(missing, i);
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(whole.rgba[i + c]) - int(cropped.rgba[i + c])) > 1) {
                ++different;
                break;
            }
    }
    EXPECT_GT(wholePixels, kWidth * kHeight / 30);
    EXPECT_LE(different, wholePixels / 500);
    EXPECT_LE(std::abs(wholePixels - croppedPixels), wholePixels / 500);
    EXPECT_LT(missingPixels, wholePixels / 10);
}

// The flat pass draws each wall only over the union of its textures' covered rectangles
// (walls::coveredRect, grown by kCoveredMargin texels): the card's flat texture from the same
// eye draws exactly what the whole wall draws; a rectangle that misses the card draws nothing.
TEST_F(DepthWallPassTest, FlatWallsDrawOnlyTheirCoveredRectangle) {
    if (!context) GTEST_SKIP();
    const scenes::Scene scene = cardScene("depth-wall-test", kCardX);
    const std::vector<int> objects{1};
    walls::DepthImage depth;
    const scenes::Image colour = bake(scene, objects, depth);
    const display::gl::GlObject colourTexture = walls::gl::uploadWallTexture({colour});
    const walls::TextureRect covered = walls::coveredRect(walls::TextureLevels({colour}), walls::kCoveredMargin);
    EXPECT_LT((covered.hi.x - covered.lo.x) * (covered.hi.y - covered.lo.y), 0.1);
    const display::OffAxisFrustum frustum = display::offAxisFrustum(kQuad, kEye, {0.05, kInf});
    walls::gl::OffscreenTarget target({kWidth, kHeight});
    const walls::gl::WallPass pass;
    auto draw = [&](walls::TextureRect rect) {
        walls::gl::WallDraw d{kQuad, {colourTexture.id()}, {1.0f}, 1, {}};
        d.contents[0] = rect;
        drawOnCleared(target, [&](display::FrameStats& stats) { pass.draw({d}, frustum, glm::dmat4(1.0), 0, stats); });
        return target.read("wall");
    };
    const scenes::Image whole = draw({}), cropped = draw(covered), missing = draw({{0.0, 0.0}, {0.1, 0.1}});
    int lit = 0, missingLit = 0, different = 0;
    for (std::size_t i = 0; i < whole.rgba.size(); i += 4) {
        lit += whole.rgba[i] + whole.rgba[i + 1] + whole.rgba[i + 2] > 0;
        missingLit += missing.rgba[i] + missing.rgba[i + 1] + missing.rgba[i + 2] > 0;
        for (int c = 0; c < 4; ++c)
            if (whole.rgba[i + c] != cropped.rgba[i + c]) {
                ++different;
                break;
            }
    }
    EXPECT_GT(lit, kWidth * kHeight / 30);
    EXPECT_EQ(different, 0);
    EXPECT_EQ(missingLit, 0);
}

}  // namespace
}  // namespace cavewall::testing
