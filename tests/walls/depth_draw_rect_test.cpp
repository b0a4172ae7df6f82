// The depth wall's draw rectangle (walls/depth_wall.h, contentRect and depthDrawRect): the
// texels around every finite depth, and a rectangle that holds every pixel the march can hit.
#include "walls/depth_wall.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace cavewall::walls {
namespace {

const display::ScreenQuad kRectWall{{-2, 0, 0}, {2, 0, 0}, {-2, 3, 0}};  // 4 m x 3 m, facing +z

// contentRect: whole texels around every finite depth, as fractions (t down from the top row).
TEST(DepthDrawRect, ContentRectIsTheTexelsAroundEveryFiniteDepth) {
    DepthImage image{8, 4, std::vector<float>(32, kNoSurface)};
    EXPECT_TRUE(contentRect(image).empty());
    image.depth[1 * 8 + 2] = 1.0f;  // texel (2, 1)
    image.depth[2 * 8 + 5] = 3.0f;  // texel (5, 2)
    const TextureRect r = contentRect(image);
    EXPECT_EQ(r.lo, glm::dvec2(2.0 / 8, 1.0 / 4));
    EXPECT_EQ(r.hi, glm::dvec2(6.0 / 8, 3.0 / 4));
    EXPECT_EQ(depthTextureData(image).content.lo, r.lo);
}

// Seen from the sampling point itself, content at any depth lies on the rays through its own
// texels: the draw rectangle is the content rectangle, whatever the range.
TEST(DepthDrawRect, FromTheSamplingPointItIsTheContent) {
    const WallFrame f = wallFrame(kRectWall);
    const glm::dvec3 s(1.1, 1.4, -2.5);
    const TextureRect content{{0.2, 0.3}, {0.45, 0.8}};
    const TextureRect r = depthDrawRect(f, s, s, content, {0.5, 30.0}, 0.0);
    EXPECT_NEAR(r.lo.x, 0.2, 1e-12);
    EXPECT_NEAR(r.lo.y, 0.3, 1e-12);
    EXPECT_NEAR(r.hi.x, 0.45, 1e-12);
    EXPECT_NEAR(r.hi.y, 0.8, 1e-12);
    // Grown by the margin (metres on the 4 m x 3 m wall) and clipped to the wall.
    const TextureRect wider = depthDrawRect(f, s, s, {{0.0, 0.3}, {0.45, 0.8}}, {0.5, 30.0}, 0.3);
    EXPECT_NEAR(wider.lo.x, 0.0, 1e-12);
    EXPECT_NEAR(wider.lo.y, 0.2, 1e-12);
    EXPECT_NEAR(wider.hi.x, 0.525, 1e-12);
    EXPECT_NEAR(wider.hi.y, 0.9, 1e-12);
}

// Nothing to draw: no content, a range that is not finite and ordered, an eye or a sampling
// point behind the wall.
TEST(DepthDrawRect, EmptyWhereNothingCanBeHit) {
    const WallFrame f = wallFrame(kRectWall);
    const glm::dvec3 s(1.0, 1.5, -2.0), e(2.5, 1.0, -1.5);
    const TextureRect content{{0.1, 0.1}, {0.4, 0.5}};
    EXPECT_FALSE(depthDrawRect(f, e, s, content, {1.0, 5.0}, 0.0).empty());
    EXPECT_TRUE(depthDrawRect(f, e, s, {{0.3, 0.1}, {0.3, 0.5}}, {1.0, 5.0}, 0.0).empty());
    EXPECT_TRUE(depthDrawRect(f, e, s, content, {1.0, std::numeric_limits<double>::infinity()}, 0.0).empty());
    EXPECT_TRUE(depthDrawRect(f, e, s, content, {5.0, 1.0}, 0.0).empty());
    EXPECT_TRUE(depthDrawRect(f, e, s, content, {-1.0, 1.0}, 0.0).empty());
    EXPECT_TRUE(depthDrawRect(f, {2.5, 1.0, 1.5}, s, content, {1.0, 5.0}, 0.0).empty());
    EXPECT_TRUE(depthDrawRect(f, e, {1.0, 1.5, 2.0}, content, {1.0, 5.0}, 0.0).empty());
}

// Every pixel whose march hits lies in the rectangle: random depth images (a random block of
// finite depths), random sampling points and eyes in front of the wall, the reference march
// (reproject, the shader's algorithm) on a grid of wall points. And the rectangle is tight: it
// is the box of the eight corners' images, each of which a content point reaches, so each of
// its sides inside the wall lies within a texel of some hit on a fine enough grid.
TEST(DepthDrawRect, HoldsEveryPixelTheMarchHits) {
    const WallFrame f = wallFrame(kRectWall);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int n = 32;
    int hitsOutside = 0, hits = 0, cases = 0;
    double smallest = 1.0;
    for (int c = 0; c < 40; ++c) {
        DepthImage image{n, n, std::vector<float>(std::size_t(n) * n, kNoSurface)};
        const int x0 = int(unit(rng) * (n - 4)), y0 = int(unit(rng) * (n - 4));
        const int x1 = x0 + 1 + int(unit(rng) * (n - x0 - 1)), y1 = y0 + 1 + int(unit(rng) * (n - y0 - 1));
        for (int j = y0; j < y1; ++j)
            for (int i = x0; i < x1; ++i)
                if (unit(rng) < 0.7 || (i == x0 && j == y0) || (i == x1 - 1 && j == y1 - 1))
                    image.depth[std::size_t(j) * n + i] = static_cast<float>(0.2 + 8.0 * unit(rng));
        const glm::dvec2 range = depthRange(image);
        const glm::dvec3 s(4.0 * unit(rng), 3.0 * unit(rng), -(1.0 + 3.0 * unit(rng)));
        const glm::dvec3 e(-2.0 + 8.0 * unit(rng), 3.0 * unit(rng), -(0.5 + 4.0 * unit(rng)));
        const TextureRect r = depthDrawRect(f, e, s, contentRect(image), range, 0.0);
        // Empty where the content's image misses the wall: then no pixel may hit either.
        if (!r.empty()) {
            ++cases;
            smallest = std::min(smallest, (r.hi.x - r.lo.x) * (r.hi.y - r.lo.y));
        }
        const int grid = 96;
        for (int j = 0; j < grid; ++j)
            for (int i = 0; i < grid; ++i) {
                const double u = (i + 0.5) / grid, t = (j + 0.5) / grid;
                const ReprojectHit h = reproject(image, f, e, s, {u * f.width, (1.0 - t) * f.height}, range);
                if (!h.hit) continue;
                ++hits;
                if (r.empty() || u < r.lo.x || u > r.hi.x || t < r.lo.y || t > r.hi.y) ++hitsOutside;
            }
    }
    EXPECT_GT(cases, 30);
    EXPECT_GT(hits, 10000);
    EXPECT_EQ(hitsOutside, 0);
    EXPECT_LT(smallest, 0.1);  // the rectangles are not simply the whole wall
}

// Tight: the rectangle is no larger than the corners' images need. With the eye's parallax the
// near and far corners' images spread apart, and the rectangle is exactly their box: the far
// corners alone (or the near ones alone) give a smaller box, which misses hits.
TEST(DepthDrawRect, NeedsBothEndsOfTheRange) {
    const WallFrame f = wallFrame(kRectWall);
    const int n = 64;
    DepthImage image{n, n, std::vector<float>(std::size_t(n) * n, kNoSurface)};
    for (int j = 20; j < 40; ++j)
        for (int i = 20; i < 40; ++i) image.depth[std::size_t(j) * n + i] = (i + j) % 2 ? 1.0f : 6.0f;
    const glm::dvec3 s(2.0, 1.5, -3.0), e(3.5, 1.5, -2.0);
    const glm::dvec2 range = depthRange(image);
    const TextureRect both = depthDrawRect(f, e, s, contentRect(image), range, 0.0);
    const TextureRect nearOnly = depthDrawRect(f, e, s, contentRect(image), {1.0, 1.0}, 0.0);
    const TextureRect farOnly = depthDrawRect(f, e, s, contentRect(image), {6.0, 6.0}, 0.0);
    int nearMisses = 0, farMisses = 0, outside = 0;
    for (int j = 0; j < 200; ++j)
        for (int i = 0; i < 200; ++i) {
            const double u = (i + 0.5) / 200, t = (j + 0.5) / 200;
            if (!reproject(image, f, e, s, {u * f.width, (1.0 - t) * f.height}, range).hit) continue;
            auto in = [&](const TextureRect& r) { return u >= r.lo.x && u <= r.hi.x && t >= r.lo.y && t <= r.hi.y; };
            outside += !in(both);
            nearMisses += !in(nearOnly);
            farMisses += !in(farOnly);
        }
    EXPECT_EQ(outside, 0);
    EXPECT_GT(nearMisses, 0);
    EXPECT_GT(farMisses, 0);
}

}  // namespace
}  // namespace cavewall::walls
