// The projector correction pass on llvmpipe: identity, complementary blends, a keystone.
#include "display/gl/projector_pass.h"
#include "display/gl/gl_object.h"
#include "tests/support/gl/gl_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace cavewall::testing {
namespace {

constexpr int kSize = 64;

// An sRGB texture holding `image` (rows top first, as read back), so that reading the texture's
// framebuffer gives `image` again.
display::gl::GlObject sourceTexture(const scenes::Image& image) {
    display::gl::GlObject t = display::gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_SRGB8_ALPHA8, image.width, image.height);
    for (int row = 0; row < image.height; ++row)  // GL's row 0 is the bottom
        glTextureSubImage2D(t.id(), 0, 0, image.height - 1 - row, image.width, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                            image.rgba.data() + static_cast<std::size_t>(row) * image.width * 4);
    return t;
}

// Mid-grey to bright colours that vary per pixel in every channel (the blend test's bound below
// holds for any level; bright content keeps the halves off the darkest codes).
scenes::Image pattern(int size) {
    scenes::Image img{"pattern", size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size * 4)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * size + x) * 4];
            p[0] = static_cast<std::uint8_t>(60 + (x * 7 + y * 3) % 196);
            p[1] = static_cast<std::uint8_t>(60 + (x * 5 + y * 11) % 196);
            p[2] = static_cast<std::uint8_t>(60 + (x * 13 + y) % 196);
            p[3] = 255;
        }
    return img;
}

scenes::Image warped(const display::ScreenCorrection& c, const scenes::Image& image) {
    const display::gl::GlObject source = sourceTexture(image);
    display::gl::ProjectorPass pass(c, {image.width, image.height});
    pass.apply(source.id());
    return pass.read();
}

double toLinear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}
double toSrgb(double linear) {
    return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

class ProjectorPassTest : public GlTest {};

TEST_F(ProjectorPassTest, IdentityWarpLeavesTheImageByteIdentical) {
    // Output pixel centres land on texel centres, so linear filtering reads one texel, and the
    // sRGB decode-encode round trip is exact for 8-bit codes.
    const scenes::Image image = pattern(kSize);
    display::ScreenCorrection identity;
    identity.warp = display::identityWarp(5, 3);  // a finer grid is the same map
    EXPECT_EQ(warped(identity, image).rgba, image.rgba);
}

TEST_F(ProjectorPassTest, ComplementaryBlendsAddUpToOneProjector) {
    // Projector A fades out and B fades in over the middle half (16-bit ramps summing to exactly
    // 65535). Their light adds: decode both outputs, sum, encode. Each output is rounded to the
    // nearest code (0.5 level); as a half's code is below the full image's and the sRGB decode is
    // convex, each rounding moves the sum by at most half a level of the full image's code, so
    // the sum is within 1 level. llvmpipe computes each output up to 0.8 levels off the exact
    // value (not 0.5), which the bound still covers for this content (its worst is printed).
    const scenes::Image image = pattern(kSize);
    display::BlendMask a{kSize, 1, std::vector<std::uint16_t>(kSize)}, b = a;
    for (int x = 0; x < kSize; ++x) {
        const double t = std::clamp((x + 0.5 - kSize / 4.0) / (kSize / 2.0), 0.0, 1.0);
        a.weights[x] = static_cast<std::uint16_t>(std::lround(65535.0 * (1.0 - t)));
        b.weights[x] = static_cast<std::uint16_t>(65535 - a.weights[x]);
    }
    display::ScreenCorrection ca, cb;
    ca.blend = a;
    cb.blend = b;
    const scenes::Image outA = warped(ca, image), outB = warped(cb, image);
    double worst = 0.0, worstA = 0.0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double wA = a.weights[(i / 4) % kSize] / 65535.0;
        worstA = std::max(worstA, std::abs(toSrgb(wA * toLinear(image.rgba[i] / 255.0)) * 255.0 - outA.rgba[i]));
        const double sum = toLinear(outA.rgba[i] / 255.0) + toLinear(outB.rgba[i] / 255.0);
        worst = std::max(worst, std::abs(toSrgb(sum) * 255.0 - image.rgba[i]));
    }
    EXPECT_LE(worst, 1.0);
    std::printf("complementary blends: worst difference %.3f levels; A against exact %.3f\n", worst, worstA);
    // Outside the overlap, A alone shows the image unchanged.
    EXPECT_EQ(outA.rgba[4 * 2], image.rgba[4 * 2]);
}

TEST_F(ProjectorPassTest, BlackLevelIsAddedWhereTheProjectorIsAlone) {
    scenes::Image black{"black", 4, 1, std::vector<std::uint8_t>(16, 0)};
    for (int x = 0; x < 4; ++x) black.rgba[x * 4 + 3] = 255;
    display::ScreenCorrection c;
    c.blend = display::BlendMask{4, 1, {65535, 65535, 32768, 0}};
    c.blackLevel = glm::vec3(0.2f, 0.0f, 0.5f);
    const scenes::Image out = warped(c, black);
    // Pixel 0: alone (blend 1) on black: the black level, sRGB-encoded (0.2 -> 124, 0.5 -> 188).
    EXPECT_NEAR(out.rgba[0], std::lround(toSrgb(0.2) * 255.0), 1);
    EXPECT_EQ(out.rgba[1], 0);
    EXPECT_NEAR(out.rgba[2], std::lround(toSrgb(0.5) * 255.0), 1);
    // Pixel 3: blend 0 (the other projector's area): nothing added.
    EXPECT_EQ(out.rgba[12], 0);
    EXPECT_EQ(out.rgba[14], 0);
}

TEST_F(ProjectorPassTest, KeystoneMovesAMarkerWhereTheHomographySends) {
    // A symmetric keystone: x' = 0.5 + (x - 0.5) / (1 + k y), y' = y / (1 + k y), a projective
    // map (numerators and denominator linear in x, y), sampled on a 17 x 17 grid.
    constexpr double k = 0.25;
    const auto keystone = [](glm::dvec2 p) {
        return glm::dvec2(0.5 + (p.x - 0.5) / (1.0 + k * p.y), p.y / (1.0 + k * p.y));
    };
    display::ScreenCorrection c;
    c.warp = display::identityWarp(17, 17);
    for (display::WarpNode& n : c.warp.nodes) n.xy = glm::vec2(keystone(glm::dvec2(n.uv)));
    // A 3 x 3 white marker on black centred on texel (44, 38) from the bottom-left.
    constexpr int kMarkerX = 44, kMarkerY = 38;
    scenes::Image image{"marker", kSize, kSize, std::vector<std::uint8_t>(kSize * kSize * 4, 0)};
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int row = kSize - 1 - (kMarkerY + dy);
            std::fill_n(&image.rgba[(static_cast<std::size_t>(row) * kSize + kMarkerX + dx) * 4], 3, 255);
        }
    const scenes::Image out = warped(c, image);
    glm::dvec2 centroid(0.0);
    double weight = 0.0;
    for (int row = 0; row < kSize; ++row)
        for (int x = 0; x < kSize; ++x) {
            const double w = toLinear(out.rgba[(static_cast<std::size_t>(row) * kSize + x) * 4] / 255.0);
            centroid += w * glm::dvec2(x + 0.5, kSize - 1 - row + 0.5);
            weight += w;
        }
    ASSERT_GT(weight, 0.0);
    centroid /= weight;
    const glm::dvec2 expected = keystone(glm::dvec2(kMarkerX + 0.5, kMarkerY + 0.5) / double(kSize)) * double(kSize);
    EXPECT_LE(glm::length(centroid - expected), 1.0)
        << centroid.x << ", " << centroid.y << " against " << expected.x << ", " << expected.y;
    // And it moved: the unwarped marker is several pixels away.
    EXPECT_GT(glm::length(expected - glm::dvec2(kMarkerX + 0.5, kMarkerY + 0.5)), 5.0);
}

TEST_F(ProjectorPassTest, InvalidNodesLeaveTheirCellsBlack) {
    const scenes::Image image = pattern(kSize);
    display::ScreenCorrection c;
    c.warp = display::identityWarp(3, 3);
    c.warp.nodes[8].valid = false;  // top-right node: the top-right quarter has no triangles
    const scenes::Image out = warped(c, image);
    EXPECT_EQ(out.rgba[(static_cast<std::size_t>(2) * kSize + kSize - 3) * 4], 0);  // near the top-right
    const std::size_t bottomLeft = (static_cast<std::size_t>(kSize - 3) * kSize + 2) * 4;
    EXPECT_EQ(out.rgba[bottomLeft], image.rgba[bottomLeft]);
}

}  // namespace
}  // namespace cavewall::testing
