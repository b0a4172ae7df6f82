// display::eyeDistances: depth back to the distance from the eye, tested by round trips
// through the projection it inverts.
#include "display/eye_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cavewall::display {
namespace {

// cave4's front wall, 3 m x 3 m at z = -1.5, seen from an eye off centre.
const ScreenQuad kCave4Front{{-1.5, 0, -1.5}, {1.5, 0, -1.5}, {-1.5, 3, -1.5}};

// The window depth of a frame point (reversed-Z [0, 1]) and the pixel it falls in.
struct Projected {
    double depth;
    glm::ivec2 pixel;  // row 0 at the top
};
Projected project(const OffAxisFrustum& f, glm::dvec3 p, glm::ivec2 size) {
    const glm::dvec4 c = f.clipFromFrame() * glm::dvec4(p, 1.0);
    const glm::dvec3 ndc = glm::dvec3(c) / c.w;
    return {ndc.z, {static_cast<int>((ndc.x + 1.0) / 2.0 * size.x), static_cast<int>((1.0 - ndc.y) / 2.0 * size.y)}};
}

TEST(EyeDistance, RoundTripsPointsBehindTheScreen) {
    for (const double far : {1000.0, std::numeric_limits<double>::infinity()}) {
        SCOPED_TRACE(far);
        const glm::dvec3 eye(0.3, 1.6, 0.2);
        const OffAxisFrustum f = offAxisFrustum(kCave4Front, eye, {0.05, far});
        const glm::ivec2 size(64, 48);
        // Points at 2 m to 30 m seen through the wall; the pixel centre is within half a pixel of
        // the point's direction, so the distance read back is the depth plane's distance along
        // the pixel centre's ray: equal within the ray's angle change over half a pixel (< 1 %).
        for (const glm::dvec3 p :
             {glm::dvec3(0.1, 1.5, -3.0), glm::dvec3(-1.0, 2.0, -10.0), glm::dvec3(2.0, 0.5, -30.0)}) {
            const Projected q = project(f, p, size);
            std::vector<float> depth(static_cast<std::size_t>(size.x) * size.y, 0.0f);
            depth[static_cast<std::size_t>(q.pixel.y) * size.x + q.pixel.x] = static_cast<float>(q.depth);
            const std::vector<float> d = eyeDistances(f, size, depth);
            const double expected = glm::length(p - f.eye);
            EXPECT_NEAR(d[static_cast<std::size_t>(q.pixel.y) * size.x + q.pixel.x], expected, 0.01 * expected);
            EXPECT_TRUE(std::isinf(d[0]));  // depth 0: nothing drawn, infinitely far
        }
    }
}

TEST(EyeDistance, ScreenCentreOfACentredEyeIsTheScreenDistance) {
    // Eye 1.5 m in front of the wall's centre; a 2 x 2 viewport's pixel centres are at +-0.75 m
    // across and up, so each is sqrt(1.5^2 + 2 * 0.75^2) = 1.837 m away on the screen plane.
    const OffAxisFrustum f = offAxisFrustum(kCave4Front, {0.0, 1.5, 0.0}, {0.05, 1000.0});
    const Projected centre = project(f, {0.75, 2.25, -1.5}, {2, 2});
    const std::vector<float> d = eyeDistances(f, {2, 2}, std::vector<float>(4, static_cast<float>(centre.depth)));
    for (float v : d) EXPECT_NEAR(v, std::sqrt(1.5 * 1.5 + 2 * 0.75 * 0.75), 1e-4);
}

TEST(EyeDistance, InvalidDepthIsNaN) {
    const OffAxisFrustum f = offAxisFrustum(kCave4Front, {0.0, 1.5, 0.0}, {0.05, 1000.0});
    const std::vector<float> d = eyeDistances(f, {3, 1}, {std::numeric_limits<float>::quiet_NaN(), -0.5f, 1.5f});
    for (float v : d) EXPECT_TRUE(std::isnan(v));
}

}  // namespace
}  // namespace cavewall::display
