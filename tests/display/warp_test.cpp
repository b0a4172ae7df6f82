#include "display/warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace cavewall::display {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A virtual wall 6 m wide, 4 m high, across a hall at z = -10, facing +Z (towards the viewer).
const ScreenQuad kWall{{-3, 0, -10}, {3, 0, -10}, {-3, 4, -10}};
const glm::dvec3 kSamplingPoint{0.5, 1.7, -4.0};
// The current view: cave4's front screen seen from an eye elsewhere in the zone.
const ScreenQuad kScreen{{-1.5, 0, -1.5}, {1.5, 0, -1.5}, {-1.5, 3, -1.5}};
constexpr double kNearB = 0.05;

struct Views {
    OffAxisFrustum a;
    glm::dmat4 clipFromWorldA, clipFromWorldB, warp;
};

// The current view B: the front screen of a CAVE carried along with the eye (as navigation does),
// the eye 1.6 m up in the CAVE's centre.
glm::dmat4 clipFromWorldAt(glm::dvec3 eye) {
    const glm::dvec3 shift = eye - glm::dvec3(0, 1.6, 0);
    const ScreenQuad screen{kScreen.lowerLeft + shift, kScreen.lowerRight + shift, kScreen.upperLeft + shift};
    return offAxisFrustum(screen, eye, {kNearB, kInf}).clipFromFrame();
}

Views views(glm::dvec3 eyeB) {
    Views v;
    v.a = offAxisFrustum(kWall, kSamplingPoint, {0.05, kInf});
    v.clipFromWorldA = v.a.clipFromFrame();
    v.clipFromWorldB = clipFromWorldAt(eyeB);
    v.warp = warpMatrix(v.a, kWall, v.clipFromWorldB, kNearB);
    return v;
}

glm::dvec3 ndc(glm::dvec4 c) { return glm::dvec3(c) / c.w; }

glm::dvec3 warped(const Views& v, glm::dvec3 x) { return ndc(v.warp * v.clipFromWorldA * glm::dvec4(x, 1)); }
glm::dvec3 seenByB(const Views& v, glm::dvec3 x) { return ndc(v.clipFromWorldB * glm::dvec4(x, 1)); }

// Where the ray from the sampling point through x meets the wall plane: x's image on the texture.
glm::dvec3 textureImage(glm::dvec3 x) {
    const double t = (-10.0 - kSamplingPoint.z) / (x.z - kSamplingPoint.z);
    return kSamplingPoint + t * (x - kSamplingPoint);
}

TEST(Warp, GeometryOnTheWallPlaneStaysPut) {
    // C0 continuity: a floor or side wall crossing the wall plane is continuous there.
    const Views v = views({0.3, 1.5, 0.6});
    for (glm::dvec3 q :
         {glm::dvec3(-3, 0, -10), glm::dvec3(3, 4, -10), glm::dvec3(1.2, 0.0, -10), glm::dvec3(-2, 3.3, -10)}) {
        const glm::dvec3 w = warped(v, q), b = seenByB(v, q);
        EXPECT_NEAR(w.x, b.x, 1e-12);
        EXPECT_NEAR(w.y, b.y, 1e-12);
    }
}

TEST(Warp, GeometryBehindTheWallLandsOnItsTextureImage) {
    const Views v = views({-0.4, 1.2, 0.9});
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> x(-6, 6), y(0, 4), depth(0.1, 40);
    for (int i = 0; i < 100; ++i) {
        const glm::dvec3 p{x(rng), y(rng), -10.0 - depth(rng)};
        const glm::dvec3 w = warped(v, p), img = seenByB(v, textureImage(p));
        EXPECT_NEAR(w.x, img.x, 1e-9);
        EXPECT_NEAR(w.y, img.y, 1e-9);
    }
}

TEST(Warp, WarpedDepthIsBehindTheWallAndKeepsTheSamplingPointsOrder) {
    const Views v = views({0.2, 1.6, 0.3});
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.1, -0.05, -1.0));
    double previous = kInf;
    for (double t = 7.0; t < 200.0; t *= 1.2) {  // from the wall plane (t ≈ 6.0) deeper along one ray
        const glm::dvec3 p = kSamplingPoint + t * dir;
        const double d = warped(v, p).z;
        EXPECT_LE(d, seenByB(v, textureImage(p)).z + 1e-15);  // never in front of the wall (reversed-Z)
        EXPECT_LT(d, previous);                               // deeper from the sampling point is deeper on screen
        EXPECT_GT(d, 0.0);
        previous = d;
    }
}

TEST(Warp, AtTheSamplingPointTheWarpIsTheTrueProjection) {
    // Seen from the sampling point itself, every point and its texture image are on one ray.
    const Views v = views(kSamplingPoint);
    const glm::dvec3 p{2.0, 0.5, -25.0};
    EXPECT_NEAR(warped(v, p).x, seenByB(v, p).x, 1e-12);
    EXPECT_NEAR(warped(v, p).y, seenByB(v, p).y, 1e-12);
}

TEST(Warp, ConditionGrowsWithoutBoundAsTheEyeApproachesTheWallPlane) {
    // Far from the wall the condition is of order 1; close to it, it grows like 1/distance.
    double previous = 0.0;
    for (double distance : {0.5, 1e-1, 1e-2, 1e-3, 1e-4, 1e-6}) {
        SCOPED_TRACE(distance);
        const double c = warpCondition(views({0.3, 1.6, -10.0 + distance}).warp);
        EXPECT_GT(c, previous);
        previous = c;
    }
    EXPECT_LT(warpCondition(views({0.3, 1.6, -2.0}).warp), 10.0);
    EXPECT_GT(warpCondition(views({0.3, 1.6, -10.0 + 1e-4}).warp), kMaxWarpCondition);  // 0.1 mm: the guard trips
}

TEST(Warp, ConditionOfSimpleMatrices) {
    EXPECT_NEAR(warpCondition(glm::dmat4(1.0)), 1.0, 1e-12);
    glm::dmat4 m(1.0);
    m[1][1] = 1e-3;
    EXPECT_NEAR(warpCondition(m), 1e3, 1e-6);
    m[1][1] = 0.0;
    EXPECT_TRUE(std::isinf(warpCondition(m)));
}

}  // namespace
}  // namespace cavewall::display
