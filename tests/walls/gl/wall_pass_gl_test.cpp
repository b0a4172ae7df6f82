// walls::gl::WallPass mixes one to four textures (one program per count): every covered pixel is the
// weighted sum of the textures in linear light, blended premultiplied over what was there, and
// a texture that is not there (id 0) is left out of the sum.
#include "display/gl/gl_object.h"
#include "tests/support/gl/gl_test_support.h"
#include "walls/gl/wall_pass.h"
#include "walls/gl/wall_quad.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace cavewall::testing {
namespace {

constexpr int kSize = 16;

double linearOf(int byte) {
    const double v = byte / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

int byteOf(double linear) {
    const double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(v * 255.0));
}

class WallPassTest : public GlTest {
protected:
    // A 2 x 2 texture of one opaque colour (one MIP level below it, the same colour).
    display::gl::GlObject solid(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        auto image = [&](int s) {
            scenes::Image i{"solid", s, s, {}};
            for (int p = 0; p < s * s; ++p) i.rgba.insert(i.rgba.end(), {r, g, b, 255});
            return i;
        };
        return walls::gl::uploadWallTexture({image(2), image(1)});
    }

    // The centre pixel (R, G, B) after drawing `draw` over an opaque black background: the wall
    // quad is the whole screen (2 m x 2 m at 1 m; the eye at the origin).
    std::vector<int> drawCentre(const walls::gl::WallDraw& draw) {
        display::gl::GlObject color = display::gl::createTexture(GL_TEXTURE_2D),
                              depth = display::gl::createTexture(GL_TEXTURE_2D),
                              framebuffer = display::gl::createFramebuffer();
        glTextureStorage2D(color.id(), 1, GL_SRGB8_ALPHA8, kSize, kSize);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
        glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
        glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer.id());
        glViewport(0, 0, kSize, kSize);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        glEnable(GL_FRAMEBUFFER_SRGB);
        glDepthMask(GL_TRUE);
        glClearDepth(0.0);  // reversed-Z: nothing drawn yet
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const display::ScreenQuad screen{{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}};
        const display::OffAxisFrustum frustum = display::offAxisFrustum(screen, glm::dvec3(0.0), {0.05, INFINITY});
        walls::gl::WallDraw d = draw;
        d.quad = {{-2, -2, -2}, {2, -2, -2}, {-2, 2, -2}};  // fills the screen from behind it
        display::FrameStats stats;
        pass->draw({d}, frustum, glm::dmat4(1.0), 0, stats);
        std::vector<std::uint8_t> pixel(4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
        glReadPixels(kSize / 2, kSize / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
        drawCalls = stats.drawCalls;
        return {pixel[0], pixel[1], pixel[2]};
    }

    void SetUp() override {
        GlTest::SetUp();
        if (!context) return;
        pass.emplace();
    }

    void TearDown() override {
        pass.reset();  // its programs go while the context is still there
        GlTest::TearDown();
    }

    std::optional<walls::gl::WallPass> pass;  // built once the context is current
    int drawCalls = 0;
};

TEST_F(WallPassTest, EachCountOfTexturesSumsItsWeightedColours) {
    if (!context) GTEST_SKIP();
    const std::uint8_t colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {200, 200, 200}};
    std::vector<display::gl::GlObject> textures;
    for (const auto& c : colours) textures.push_back(solid(c[0], c[1], c[2]));
    for (int count = 1; count <= walls::kMaxWallTextures; ++count) {
        SCOPED_TRACE(count);
        walls::gl::WallDraw d{{}, {}, {}, count};
        for (int i = 0; i < count; ++i) d.textures[i] = textures[i].id(), d.weights[i] = 1.0f / count;
        const std::vector<int> got = drawCentre(d);
        // Opaque textures, weights summing to 1, over black: the pixel is the weighted sum of
        // the linear colours, sRGB-encoded; 8-bit storage and filtering allow 1 level.
        for (int ch = 0; ch < 3; ++ch) {
            double sum = 0.0;
            for (int i = 0; i < count; ++i) sum += linearOf(colours[i][ch]) / count;
            EXPECT_NEAR(got[ch], byteOf(sum), 1) << "channel " << ch;
        }
    }
}

TEST_F(WallPassTest, AMissingTextureIsLeftOutAndAWallWithNoneIsNotDrawn) {
    if (!context) GTEST_SKIP();
    const display::gl::GlObject red = solid(255, 0, 0);
    // The missing texture's weight goes nowhere: half the red over black.
    std::vector<int> got = drawCentre({{}, {0, red.id()}, {0.5f, 0.5f}, 2});
    EXPECT_NEAR(got[0], byteOf(0.5), 1);
    EXPECT_EQ(got[1], 0);
    EXPECT_EQ(drawCalls, 1);
    got = drawCentre({{}, {0, 0}, {0.5f, 0.5f}, 2});
    EXPECT_EQ(got, (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(drawCalls, 0);
}

}  // namespace
}  // namespace cavewall::testing
