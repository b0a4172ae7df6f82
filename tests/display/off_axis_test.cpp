#include "display/off_axis.h"

#include "config/display_config.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace cavewall::display {
namespace {

// The front wall of cave4: 3 m x 3 m at z = -1.5, floor to 3 m, 1024 px square.
const ScreenQuad kFront{{-1.5, 0, -1.5}, {1.5, 0, -1.5}, {-1.5, 3, -1.5}};
constexpr double kPixels = 1024.0;
constexpr DepthRange kDepth{0.05, 1000.0};

// NDC of a frame point through a frustum (double).
glm::dvec3 ndc(const OffAxisFrustum& f, glm::dvec3 p) {
    const glm::dvec4 c = f.clipFromFrame() * glm::dvec4(p, 1.0);
    return glm::dvec3(c) / c.w;
}

glm::dvec3 pointOnScreen(const ScreenQuad& s, double u, double v) {
    return s.lowerLeft + u * (s.lowerRight - s.lowerLeft) + v * (s.upperLeft - s.lowerLeft);
}

bool allFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Every screen point lands on its own NDC position, whatever the eye: this is what makes
// neighbouring screens of a CAVE meet seamlessly.
void expectScreenPointsOnTheirNdc(const ScreenQuad& s, glm::dvec3 eye, double minEyeDistance, double tolPx) {
    const OffAxisFrustum f = offAxisFrustum(s, eye, kDepth, minEyeDistance);
    ASSERT_EQ(f.guard, EyeGuard::None);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 50; ++i) {
        const double u = unit(rng), v = unit(rng);
        const glm::dvec3 n = ndc(f, pointOnScreen(s, u, v));
        // Half the image is one NDC unit, so an NDC error e is e * pixels / 2 pixels.
        EXPECT_NEAR(n.x, 2 * u - 1, 2 * tolPx / kPixels)
            << "u " << u << " eye " << eye.x << "," << eye.y << "," << eye.z;
        EXPECT_NEAR(n.y, 2 * v - 1, 2 * tolPx / kPixels) << "v " << v;
    }
}

TEST(OffAxis, RandomEyesMapEveryScreenPointToItsOwnNdc) {
    const config::DisplayConfig cave = config::loadDisplayConfig("cave4");
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> inside(-1.4, 1.4), height(0.1, 2.9);
    for (const auto& screen : cave.screens) {
        SCOPED_TRACE(screen.name);
        const ScreenQuad q{screen.lowerLeft, screen.lowerRight, screen.upperLeft};
        for (int i = 0; i < 20; ++i)
            expectScreenPointsOnTheirNdc(q, {inside(rng), height(rng), inside(rng)}, 1e-3, 1e-6);
    }
}

TEST(OffAxis, CornersMapToPlusMinusOne) {
    const OffAxisFrustum f = offAxisFrustum(kFront, {0.3, 1.2, 0.4}, kDepth);
    EXPECT_NEAR(ndc(f, kFront.lowerLeft).x, -1.0, 1e-12);
    EXPECT_NEAR(ndc(f, kFront.lowerLeft).y, -1.0, 1e-12);
    EXPECT_NEAR(ndc(f, kFront.lowerRight).x, 1.0, 1e-12);
    EXPECT_NEAR(ndc(f, kFront.upperLeft).y, 1.0, 1e-12);
    const glm::dvec3 upperRight = kFront.lowerRight + kFront.upperLeft - kFront.lowerLeft;
    EXPECT_NEAR(ndc(f, upperRight).x, 1.0, 1e-12);
    EXPECT_NEAR(ndc(f, upperRight).y, 1.0, 1e-12);
}

TEST(OffAxis, CentredEyeGivesSymmetricFrustum) {
    // The eye on the normal through the screen centre sees the screen symmetrically, so the
    // off-axis terms vanish and the x/y scales are 2d/width and 2d/height.
    const OffAxisFrustum f = offAxisFrustum(kFront, {0, 1.5, 0.5}, kDepth);
    EXPECT_NEAR(f.clipFromView[2][0], 0.0, 1e-15);
    EXPECT_NEAR(f.clipFromView[2][1], 0.0, 1e-15);
    EXPECT_DOUBLE_EQ(f.clipFromView[0][0], 2.0 * 2.0 / 3.0);  // d = 2 m, width 3 m
    EXPECT_DOUBLE_EQ(f.eyeDistance, 2.0);
}

TEST(OffAxis, ViewFramePutsEyeAtOriginLookingDownMinusZ) {
    const glm::dvec3 eye{0.2, 1.1, -0.3};
    const OffAxisFrustum f = offAxisFrustum(kFront, eye, kDepth);
    const glm::dvec4 e = f.viewFromFrame * glm::dvec4(eye, 1.0);
    EXPECT_NEAR(glm::length(glm::dvec3(e)), 0.0, 1e-15);
    // The front wall's normal is +Z in the cave, and +Z in view: the view is a pure translation.
    const glm::dvec4 ll = f.viewFromFrame * glm::dvec4(kFront.lowerLeft, 1.0);
    EXPECT_NEAR(ll.z, -1.2, 1e-15);  // the screen plane is 1.2 m ahead
}

TEST(OffAxis, EyeDistancesFromMicrometresToThousandKilometres) {
    for (double d = 1e-6; d <= 1e6; d *= 10) {
        SCOPED_TRACE(d);
        // An off-centre eye, not only on the axis: 0.7 m right of the left edge, 0.9 m up.
        expectScreenPointsOnTheirNdc(kFront, {-0.8, 0.9, -1.5 + d}, 1e-9, 1e-6);
    }
}

TEST(OffAxis, WorldOffsetsToTenThousandKilometres) {
    for (double offset : {1e3, 1e5, 1e7}) {
        SCOPED_TRACE(offset);
        const glm::dvec3 o{offset, -0.5 * offset, offset};
        const ScreenQuad moved{kFront.lowerLeft + o, kFront.lowerRight + o, kFront.upperLeft + o};
        expectScreenPointsOnTheirNdc(moved, glm::dvec3(0.4, 1.3, 0.2) + o, 1e-3, 1e-6);
    }
}

TEST(OffAxis, EyeRelativeFloatMatricesDoNotJitterFarFromTheOrigin) {
    // A 1 cm feature 1 m in front of the eye, with the whole scene 1e7 m from the origin: the
    // float model-view is eye-relative, so its image matches the unshifted scene to well under
    // a pixel (a naive float world transform would be off by metres: float's step at 1e7 is 1 m).
    const glm::dvec3 eye{0.1, 1.5, 0.0};
    const glm::dvec3 local{0.01, 0.0, -1.0};
    auto projectFloat = [&](glm::dvec3 o) {
        const ScreenQuad s{kFront.lowerLeft + o, kFront.lowerRight + o, kFront.upperLeft + o};
        const OffAxisFrustum f = offAxisFrustum(s, eye + o, kDepth);
        const glm::dmat4 frameFromModel = glm::translate(glm::dmat4(1.0), eye + o);
        const glm::vec4 c =
            glm::mat4(f.clipFromView) * eyeRelativeModelView(f, frameFromModel) * glm::vec4(glm::vec3(local), 1.0f);
        return glm::dvec2(c.x / c.w, c.y / c.w);
    };
    const glm::dvec2 reference = projectFloat(glm::dvec3(0.0));
    const glm::dvec2 far = projectFloat(glm::dvec3(1e7, 1e7, -1e7));
    EXPECT_LT(glm::length(far - reference) * kPixels / 2, 1e-3);
}

// Float depth as the GPU computes it, from float matrices: z_clip / w_clip.
float floatDepth(const OffAxisFrustum& f, double distance) {
    const glm::vec4 c = glm::mat4(f.clipFromView) * glm::vec4(0.0f, 0.0f, static_cast<float>(-distance), 1.0f);
    return c.z / c.w;
}

TEST(OffAxis, ReversedZKeepsDepthOrderForNearFarRatiosToOneBillion) {
    for (double far : {1e6, std::numeric_limits<double>::infinity()}) {
        SCOPED_TRACE(far);
        const DepthRange depth{1e-3, far};  // ratio 1e9 (or infinite)
        const OffAxisFrustum f = offAxisFrustum(kFront, {0, 1.5, 0.5}, depth);
        EXPECT_NEAR(floatDepth(f, depth.near), 1.0f, 1e-6f);
        if (std::isfinite(far)) {
            EXPECT_NEAR(floatDepth(f, far), 0.0f, 1e-6f);
        }
        // Distances 0.1 % apart over the whole range stay strictly ordered in float.
        float previous = 2.0f;
        for (double z = depth.near; z <= 1e6; z *= 1.001) {
            const float d = floatDepth(f, z);
            ASSERT_LT(d, previous) << "at " << z << " m";
            ASSERT_GT(d, 0.0f) << "at " << z << " m";
            previous = d;
        }
    }
}

TEST(OffAxis, GuardPolicyForEyesTooCloseBehindOrBroken) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    struct Case {
        const char* name;
        glm::dvec3 eye;
        EyeGuard guard;
    } cases[] = {
        {"in front", {0, 1.5, -1.0}, EyeGuard::None},
        {"too close", {0.2, 1.5, -1.5 + 1e-5}, EyeGuard::TooClose},
        {"on the plane", {0.2, 1.5, -1.5}, EyeGuard::Behind},
        {"behind", {0.2, 1.5, -4.0}, EyeGuard::Behind},
        {"NaN", {nan, 1.5, 0.0}, EyeGuard::NonFinite},
        {"Inf", {0.0, inf, 0.0}, EyeGuard::NonFinite},
        {"-Inf", {0.0, 0.0, -inf}, EyeGuard::NonFinite},
    };
    const double minDistance = 1e-3;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const OffAxisFrustum f = offAxisFrustum(kFront, c.eye, kDepth, minDistance);
        EXPECT_EQ(f.guard, c.guard);
        EXPECT_TRUE(allFinite(f.viewFromFrame));
        EXPECT_TRUE(allFinite(f.clipFromView));
        EXPECT_GE(f.eyeDistance, minDistance);
        if (c.guard == EyeGuard::TooClose || c.guard == EyeGuard::Behind) {
            // Moved along the normal only, to exactly the minimum distance.
            EXPECT_DOUBLE_EQ(f.eye.x, c.eye.x);
            EXPECT_DOUBLE_EQ(f.eye.y, c.eye.y);
            EXPECT_NEAR(f.eyeDistance, minDistance, 1e-15);
            EXPECT_NEAR(f.eye.z, -1.5 + minDistance, 1e-12);
        }
    }
}

TEST(OffAxis, TinyAndHugeScreens) {
    // 1 mm and 1 km screens, eye at a proportionate distance: same exactness in pixels.
    for (double size : {1e-3, 1e3}) {
        SCOPED_TRACE(size);
        const ScreenQuad s{{0, 0, 0}, {size, 0, 0}, {0, size, 0}};
        expectScreenPointsOnTheirNdc(s, {0.3 * size, 0.6 * size, 0.7 * size}, 1e-9, 1e-6);
    }
}

TEST(OffAxis, InfiniteFarMapsFarPointsTowardsZeroDepth) {
    const OffAxisFrustum f = offAxisFrustum(kFront, {0, 1.5, 0.5}, {0.05, std::numeric_limits<double>::infinity()});
    EXPECT_GT(floatDepth(f, 1e12), 0.0f);
    EXPECT_LT(floatDepth(f, 1e12), 1e-12f);
}

}  // namespace
}  // namespace cavewall::display
