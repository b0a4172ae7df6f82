#include "walls/angular_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace cavewall::walls {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// A 12 m x 3 m wall in the plane z = 0, facing +z (lowerLeft, lowerRight, upperLeft).
const ScreenQuad kWall{{-6, 0, 0}, {6, 0, 0}, {-6, 3, 0}};

double sampledMax(glm::dvec3 eye, glm::dvec3 s, double depth, int n = 300) {
    // Brute force over texels: the exact function must never be below any sample.
    double best = 0;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n / 4; ++j) {
            const glm::dvec3 q(-6 + 12.0 * i / n, 3.0 * j / (n / 4), 0);
            const double h = s.z;  // distance of S from the plane
            const glm::dvec3 p = std::isinf(depth) ? q + 1e7 * (q - s) : q + (depth / h) * (q - s);
            best = std::max(best, pointError(eye, s, p, kWall));
        }
    return best;
}

TEST(AngularError, ZeroAtTheSamplingPointAndForZeroDepth) {
    const glm::dvec3 s(0, 1.6, 4);
    EXPECT_EQ(maxAngularError(s, s, kWall), 0.0);
    EXPECT_EQ(maxAngularError({1, 1.6, 4}, s, kWall, 0.0), 0.0);  // points on the wall have no parallax
}

TEST(AngularError, MatchesTheClosedFormForAnEyeBesideTheSamplingPoint) {
    // Eye and sampling point at the same height and distance x, lateral offset delta: the
    // segment is parallel to the wall, so the largest angle is seen from the wall point in
    // front of its midpoint: 2 atan(delta / 2x). With depth D the segment shrinks to
    // [E, M], M = (E + kS) / (1 + k), k = D / x, so the error is 2 atan(delta k / (2x (1 + k))).
    const double x = 5.0, delta = 1.0;
    const glm::dvec3 s(0, 1.5, x), e(delta, 1.5, x);
    EXPECT_NEAR(maxAngularError(e, s, kWall), 2 * std::atan(delta / (2 * x)), 2 * kErrorTolerance);
    for (double depth : {0.5, 2.0, 10.0}) {
        SCOPED_TRACE(depth);
        const double k = depth / x;
        EXPECT_NEAR(maxAngularError(e, s, kWall, depth), 2 * std::atan(delta * k / (2 * x * (1 + k))),
                    2 * kErrorTolerance);
    }
}

TEST(AngularError, NeverBelowBruteForceAndCloseToIt) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(-7, 7), y(0.5, 2.5), z(0.3, 8), depth(0.1, 30);
    for (int i = 0; i < 40; ++i) {
        const glm::dvec3 e(x(rng), y(rng), z(rng)), s(x(rng), y(rng), z(rng));
        const double d = i % 2 ? depth(rng) : kInfiniteDepth;
        SCOPED_TRACE(i);
        const double exact = maxAngularError(e, s, kWall, d);
        const double brute = sampledMax(e, s, d);
        if (exact >= 89.9 * kDeg) continue;  // the >= 90° path is a coarse bound by design
        EXPECT_GE(exact + 1e-9, brute);
        // A 300 x 75 grid on a 12 m x 3 m wall is 4 cm apart: its maximum is close.
        EXPECT_LT(exact - brute, 0.01);
    }
}

TEST(AngularError, ErrorGrowsWithDepthTowardsTheParallaxAngle) {
    const glm::dvec3 s(0, 1.6, 4), e(1.2, 1.9, 3);
    double previous = 0;
    for (double depth : {0.5, 1.0, 4.0, 16.0, 64.0, 1e4}) {
        const double v = maxAngularError(e, s, kWall, depth);
        EXPECT_GT(v, previous);
        previous = v;
    }
    EXPECT_NEAR(previous, maxAngularError(e, s, kWall), 1e-3);
}

TEST(AngularError, DecisionAgreesWithTheValue) {
    const glm::dvec3 s(0, 1.6, 4), e(0.8, 1.3, 3.5);
    const double v = maxAngularError(e, s, kWall);
    EXPECT_TRUE(errorWithin(e, s, kWall, kInfiniteDepth, v + 1e-6));
    EXPECT_FALSE(errorWithin(e, s, kWall, kInfiniteDepth, v - 1e-6));
}

TEST(AngularError, ZoneMaximumIsAtAVertexAndBoundsRandomEyesAndPoints) {
    const ZoneVolume zone{{{-1, 4}, {1, 4}, {1, 6}, {-1, 6}}, {1.2, 2.0}};
    const glm::dvec3 s(0, 1.6, 5);
    const double bound = zoneMaxError(zone, s, kWall);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 eye(-1 + 2 * u(rng), 1.2 + 0.8 * u(rng), 4 + 2 * u(rng));
        const glm::dvec3 q(-6 + 12 * u(rng), 3 * u(rng), 0);
        const double depth = 0.01 + 50 * u(rng) * u(rng);
        const glm::dvec3 p = q + (depth / s.z) * (q - s);  // a scene point shown at texel q
        ASSERT_LE(pointError(eye, s, p, kWall), bound + 1e-12);
        ASSERT_LE(maxAngularError(eye, s, kWall), bound + 1e-12);
    }
}

TEST(AngularError, FiniteDepthZoneMaximumIsBracketedByEyes) {
    const ZoneVolume zone{{{-1, 3}, {1, 3}, {1.5, 5}, {-1, 5}}, {1.2, 2.0}};
    const glm::dvec3 s(0, 1.6, 4);
    const double infinite = zoneMaxError(zone, s, kWall);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (double depth : {1.0, 5.0, 30.0}) {
        SCOPED_TRACE(depth);
        const double bound = zoneMaxError(zone, s, kWall, depth);
        // A finite depth never errs more than the depth-independent bound.
        EXPECT_LE(bound, infinite);
        // Brute force over eyes (vertices, and random points of the zone): the bound is never
        // below any of them and within its tolerance of the best.
        double best = 0;
        for (const glm::dvec2& v : zone.floor)
            for (double y : {1.2, 2.0}) best = std::max(best, maxAngularError({v.x, y, v.y}, s, kWall, depth));
        for (int i = 0; i < 300; ++i) {
            const double a = u(rng), b = u(rng);
            const glm::dvec2 f = (1 - a) * ((1 - b) * zone.floor[0] + b * zone.floor[1]) +
                                 a * ((1 - b) * zone.floor[3] + b * zone.floor[2]);
            best = std::max(best, maxAngularError({f.x, 1.2 + 0.8 * u(rng), f.y}, s, kWall, depth));
        }
        EXPECT_GE(bound, best);
        EXPECT_LE(bound - best, 2e-4);
    }
    EXPECT_LT(zoneMaxError(zone, s, kWall, 1.0), 0.5 * infinite);  // shallow content errs far less
}

// zoneDepthBound (one eye per vertex at a grown depth) is never below any eye of the zone, with
// eyes on a grid through the whole zone (floor and height), random planner-sized zones, sampling
// points and depths; the best eye reaches at least 0.75 of it on every zone and 0.95 on the median
// zone (a bound 1.3x too loose fails), it is at most the depth-independent bound, and
// zoneWithinDepth gives its answer.
TEST(AngularError, FiniteDepthZoneBoundCoversEveryEyeAndIsTight) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    int yes = 0, no = 0;
    std::vector<double> ratios;
    for (int i = 0; i < 60; ++i) {
        const double x = -4 + 6 * u(rng), z = 1.5 + 5 * u(rng), w = 0.5 + 1.5 * u(rng), d = 0.5 + 1.5 * u(rng);
        const ZoneVolume zone{{{x, z}, {x + w, z}, {x + w + 0.2 * u(rng), z + d}, {x - 0.2 * u(rng), z + d}},
                              {1.2, 2.0}};
        const glm::dvec3 s(x + w * u(rng), 1.6, z + d * u(rng));
        const double depth = 0.5 + 50 * u(rng) * u(rng);
        const double bound = zoneDepthBound(zone, s, kWall, depth);
        EXPECT_LE(bound, zoneMaxError(zone, s, kWall) + 1e-12) << "zone " << i;
        double best = 0;
        for (int a = 0; a <= 10; ++a)
            for (int b = 0; b <= 10; ++b)
                for (double y : {1.2, 1.4, 1.6, 1.8, 2.0}) {
                    const glm::dvec2 f =
                        (1 - a / 10.0) * ((1 - b / 10.0) * zone.floor[0] + (b / 10.0) * zone.floor[1]) +
                        (a / 10.0) * ((1 - b / 10.0) * zone.floor[3] + (b / 10.0) * zone.floor[2]);
                    best = std::max(best, maxAngularError({f.x, y, f.y}, s, kWall, depth));
                }
        EXPECT_GE(bound, best) << "zone " << i << " depth " << depth;
        if (bound > 1e-3) ratios.push_back(best / bound);  // a zone around S's rays errs nearly nothing
        for (double f : {0.9, 0.99, 1.01, 1.1}) {
            const bool within = zoneWithinDepth(zone, s, kWall, depth, f * bound);
            EXPECT_EQ(within, bound <= f * bound) << "zone " << i;
            (within ? yes : no) += 1;
        }
    }
    std::sort(ratios.begin(), ratios.end());
    ASSERT_GT(ratios.size(), 40u);
    const double median = ratios[ratios.size() / 2];
    std::printf("best eye / bound over %zu zones: least %.3f, median %.3f\n", ratios.size(), ratios.front(), median);
    EXPECT_GE(ratios.front(), 0.75);
    EXPECT_GE(median, 0.95);
    EXPECT_GT(std::min(yes, no), 60);
}

TEST(AngularError, SeedRuleReferenceCase) {
    // Ebbesmeyer (1997) eq. 3-4 at alpha = 10°: a zone half-width of 1 m needs x_Tmin =
    // 1 / tan 10° = 5.671 m, and a 12 m wide scene needs 12 / (2 * 1) = 6 textures per wall (the
    // paper's six).
    const double alpha = 10 * kDeg;
    const double xMin = seedMinDistance(1.0, alpha);
    EXPECT_NEAR(xMin, 5.67128, 1e-5);
    EXPECT_EQ(seedTextureCount(12.0, xMin, alpha), 6);
    EXPECT_NEAR(seedError2D(1.0, xMin), alpha, 1e-12);
}

TEST(AngularError, SeedRuleUnderestimatesTheTrue3DError) {
    // Ebbesmeyer's zone: sampling point B at x_Tmin in front of the wall at eye height, the
    // viewer B' moved 1 m (delta b) parallel to the wall. The paper predicts exactly 10°.
    const double alpha = 10 * kDeg, xMin = seedMinDistance(1.0, alpha);
    const glm::dvec3 b(0, 1.6, xMin);
    struct Case {
        const char* name;
        glm::dvec3 eye;
    };
    const Case cases[] = {
        // Even in 2D the worst wall point is in front of the midpoint of BB': 2 atan(0.5 / x) > atan(1 / x).
        {"same height, parallel", {1.0, 1.6, xMin}},        {"head 0.4 m higher", {1.0, 2.0, xMin}},
        {"0.5 m towards the wall", {1.0, 1.6, xMin - 0.5}}, {"0.5 m away from the wall", {1.0, 1.6, xMin + 0.5}},
        {"lower and closer", {1.0, 1.2, xMin - 0.5}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_GT(maxAngularError(c.eye, b, kWall), alpha);
    }
    EXPECT_NEAR(maxAngularError(cases[0].eye, b, kWall), 2 * std::atan(0.5 / xMin), 1e-6);
    // Moving towards the wall is worse than moving away, and height adds to it.
    EXPECT_GT(maxAngularError(cases[2].eye, b, kWall), maxAngularError(cases[3].eye, b, kWall));
    EXPECT_GT(maxAngularError(cases[4].eye, b, kWall), maxAngularError(cases[2].eye, b, kWall));
}

TEST(AngularError, DegenerateInputsNeverGiveNaN) {
    const glm::dvec3 s(0, 1.6, 4);
    const double nan = std::nan("");
    EXPECT_FALSE(std::isnan(maxAngularError({nan, 1, 1}, s, kWall)));
    EXPECT_FALSE(std::isnan(maxAngularError({0, 1.5, 0}, s, kWall)));   // eye on the wall
    EXPECT_FALSE(std::isnan(maxAngularError({0, 1.5, -1}, s, kWall)));  // eye behind it
    EXPECT_FALSE(errorWithin({nan, 1, 1}, s, kWall, kInfiniteDepth, 0.1));
    EXPECT_GE(maxAngularError({0, 1.5, 0.001}, s, kWall), 80 * kDeg);  // grazing: near 90° and more
}

TEST(AngularError, ZoneWithinIsEveryEyeWithin) {
    // zoneWithin checks the zone's eyes (floor vertices at both head heights) in its own order;
    // the answer must be the plain conjunction of errorWithin over all of them. Alphas just
    // below each eye's own error make the eyes fail one at a time, worst first, so a zone
    // that skipped any eye would pass where the conjunction fails.
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> x(-9, 9), z(0.3, 12), size(0.2, 4), y(1.2, 2.0);
    int passed = 0, failed = 0;
    for (int n = 0; n < 30; ++n) {
        const glm::dvec2 c(x(rng), z(rng));
        const double w = size(rng), d = size(rng);
        // A convex quad: a rectangle with one corner pulled in, not aligned with the wall.
        const ZoneVolume zone{
            {{c.x - w, c.y}, {c.x + w, c.y + 0.3 * d}, {c.x + 0.7 * w, c.y + d}, {c.x - w, c.y + 0.8 * d}}, {1.2, 2.0}};
        const glm::dvec3 s(x(rng), y(rng), z(rng));
        std::vector<double> alphas;
        double worst = 0;
        for (const glm::dvec2& p : zone.floor)
            for (double h : {zone.heightRange.x, zone.heightRange.y}) {
                const double e = maxAngularError({p.x, h, p.y}, s, kWall);
                alphas.push_back(e * (1 - 1e-6));
                worst = std::max(worst, e);
            }
        alphas.push_back(worst * (1 + 1e-6));  // every eye within
        for (double alpha : alphas) {
            if (!(alpha > 0) || alpha > 0.5 * 3.14159265358979323846) continue;
            bool all = true;
            for (const glm::dvec2& p : zone.floor)
                for (double h : {zone.heightRange.x, zone.heightRange.y})
                    all = all && errorWithin({p.x, h, p.y}, s, kWall, kInfiniteDepth, alpha);
            SCOPED_TRACE("zone " + std::to_string(n) + ", alpha " + std::to_string(alpha));
            EXPECT_EQ(zoneWithin(zone, s, kWall, alpha), all);
            (all ? passed : failed)++;
        }
    }
    // Both answers occur often, so the comparison is not vacuous.
    EXPECT_GT(passed, 15);
    EXPECT_GT(failed, 150);
}

TEST(AngularError, ZoneWithinChecksTheEyeLeastLikelyToFail) {
    // zoneWithin tries the eyes far from the sampling point for their distance to the wall
    // first. Here the worst eye is the one nearest S for its distance, so it is tried last:
    // 0.3 m beside S at S's distance (0.3 / 10 = 0.03) against 0.5 m behind S (0.5 / 10.5 =
    // 0.048). Beside S the eye sees texels up to about atan(0.3 / 10) = 1.7° off, behind S
    // about 1.2° (wall points 6 m aside): with alpha just below the worst eye's error, that
    // eye alone fails.
    const glm::dvec3 s(0, 1.6, 10);
    const ZoneVolume zone{{{0.3, 10}, {0.05, 10.5}, {-0.05, 10.5}}, {1.6, 1.6}};
    std::vector<double> errors;
    for (const glm::dvec2& p : zone.floor) errors.push_back(maxAngularError({p.x, 1.6, p.y}, s, kWall));
    EXPECT_NEAR(errors[0], std::atan(0.3 / 10), 0.3 * std::atan(0.3 / 10));
    EXPECT_GT(errors[0], 1.1 * std::max(errors[1], errors[2]));
    EXPECT_TRUE(zoneWithin(zone, s, kWall, errors[0] * (1 + 1e-6)));
    EXPECT_FALSE(zoneWithin(zone, s, kWall, errors[0] * (1 - 1e-6)));
}

}  // namespace
}  // namespace cavewall::walls
