// The depth walls' planner bound (walls/depth_wall.h depthEyeBound, depthZoneBound) and the
// planner using it (walls/plan.h, PlanOptions::wallKind): the bound holds for every pixel the
// reference reprojection draws and is reached within a factor of two; every planned depth
// texture is within alpha at every eye of its valid region, whatever the depths in the wall's
// span; depth walls with a narrow span need fewer textures than flat walls.
#include "walls/depth_wall.h"
#include "walls/plan.h"
#include "walls/plan_io.h"
#include "walls/wall_setup.h"

#include "config/error.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace cavewall::walls {
namespace {

// The angle at the eye (wall frame) between the pixel at wall point w and the surface point the
// pixel shows: what S saw through the centre of the texel hit, at the stored depth.
double shownError(const DepthImage& image, const WallFrame& f, glm::dvec3 eye, glm::dvec3 sample, glm::dvec2 w,
                  const ReprojectHit& hit) {
    const double i = std::floor(hit.texture.x / f.width * image.width),
                 j = std::floor((f.height - hit.texture.y) / f.height * image.height);
    const glm::dvec2 tc = texelCentre(f, image.width, image.height, int(i), int(j));
    const double ds = -sample.z;
    const glm::dvec3 p(tc + (hit.surface / ds) * (tc - glm::dvec2(sample)), hit.surface);
    const glm::dvec3 a = glm::normalize(p - eye), b = glm::normalize(glm::dvec3(w, 0.0) - eye);
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// A card (x in [1.5, 2.5], y in [1, 2] of the wall frame) at depth 1 in front of a plane at
// depth 4, as S sees it through each texel centre.
DepthImage cardImage(const WallFrame& f, glm::dvec3 s, int width, int height) {
    DepthImage image{width, height, {}};
    const double ds = -s.z;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glm::dvec2 t = texelCentre(f, width, height, i, j);
            const glm::dvec2 c = t + (1.0 / ds) * (t - glm::dvec2(s));
            image.depth.push_back(c.x >= 1.5 && c.x <= 2.5 && c.y >= 1.0 && c.y <= 2.0 ? 1.0f : 4.0f);
        }
    return image;
}

const display::ScreenQuad kPlanWall{{-2, 0, 0}, {2, 0, 0}, {-2, 3, 0}};  // 4 m x 3 m, facing +z

// The skin the march stretches across the card's right edge shows the card's points at ray
// depths up to 4: the widest error is the bound's step term. A bound 2x too loose fails.
TEST(DepthPlan, EyeBoundHoldsForEveryDrawnPixelAndIsReached) {
    const WallFrame f = wallFrame(kPlanWall);
    const glm::dvec3 s(2.0, 1.5, -3.0), e(2.6, 1.5, -3.0);  // the eye moved 0.6 m along +x
    const int n = 512;
    const DepthImage image = cardImage(f, s, n, n * 3 / 4);
    const glm::dvec2 span(1.0, 4.0);
    ASSERT_EQ(depthRange(image), span);
    const double bound = depthEyeBound(f.toWorld(e), f.toWorld(s), kPlanWall, span, std::hypot(4.0 / n, 3.0 / (n * 3 / 4)));
    // Equal distances: v = E - S at every texel, so the step term is (k(4) - k(1)) 0.6 / 3.
    const double k1 = 1.0 / 4.0, k4 = 4.0 / 7.0;
    EXPECT_NEAR(bound, (k4 - k1) * 0.6 / 3.0 + 0.5 * std::hypot(4.0 / n, 3.0 / (n * 3 / 4)) / 3.0, 1e-6);
    double worst = 0.0;
    int drawn = 0;
    for (int row = 0; row < 9; ++row)
        for (int k = 0; k < 2000; ++k) {
            const glm::dvec2 w(f.width * (k + 0.5) / 2000, 1.1 + 0.1 * row);
            const ReprojectHit hit = reproject(image, f, e, s, w, span);
            if (!hit.hit) continue;
            ++drawn;
            worst = std::max(worst, shownError(image, f, e, s, w, hit));
        }
    std::printf("depth eye bound %.5f rad, largest error of %d drawn pixels %.5f rad (ratio %.3f)\n", bound, drawn,
                worst, worst / bound);
    EXPECT_GT(drawn, 16000);  // of 18000: the rest see past the wall's edges (no texel holds that)
    EXPECT_LE(worst, bound);
    EXPECT_GE(worst, 0.5 * bound);
    // The segment form: the exact angle where the span form is linear in k, so at most it, and
    // reached as closely.
    const double segment =
        depthSegmentEyeBound(f.toWorld(e), f.toWorld(s), kPlanWall, span, std::hypot(4.0 / n, 3.0 / (n * 3 / 4)));
    std::printf("segment form %.5f rad (ratio %.3f)\n", segment, worst / segment);
    EXPECT_LE(segment, bound);
    EXPECT_LE(worst, segment);
    EXPECT_GE(worst, 0.5 * segment);
}

// The segment form (depth_wall.h): a near card 2 cm behind the wall with a window onto a plane 4 m
// behind, the window in front of the eye, which moved 0.6 m along +x. The skin across the
// window's left edge shows the card's points at ray depths up to 4: nearly the largest angle a
// ray's part from 0.02 to 4 m subtends, which is where the eye looks straight at the wall. A
// form 25 % too loose fails.
TEST(DepthPlan, SegmentFormHoldsForEveryDrawnPixelAndIsReached) {
    const WallFrame f = wallFrame(kPlanWall);
    const glm::dvec3 s(2.0, 1.5, -3.0), e(2.6, 1.5, -3.0);
    const int n = 512, m = n * 3 / 4;
    DepthImage image{n, m, {}};
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 t = texelCentre(f, n, m, i, j);
            image.depth.push_back(std::abs(t.x - 2.6) < 0.3 && std::abs(t.y - 1.5) < 0.3 ? 4.0f : 0.02f);
        }
    const glm::dvec2 span = depthRange(image);
    const double h = std::hypot(4.0 / n, 3.0 / m);
    const double form = depthSegmentEyeBound(f.toWorld(e), f.toWorld(s), kPlanWall, span, h);
    const double nearDepth = span.x - 1e-6 * (3.0 + span.x), farDepth = span.y + 1e-6 * (3.0 + span.y);  // widened
    EXPECT_NEAR(
        form,
        maxAngularError(f.toWorld(e), f.toWorld(s), nearWall(kPlanWall, f.toWorld(s), nearDepth), farDepth - nearDepth) +
            0.5 * h / 3.0,
        1e-9);
    // Below the flat texture's own error up to the far depth (the form with dNear = 0).
    EXPECT_LT(form, depthSegmentEyeBound(f.toWorld(e), f.toWorld(s), kPlanWall, {0.0, span.y}, h));
    double worst = 0.0;
    for (int row = 0; row < 9; ++row)
        for (int k = 0; k < 2000; ++k) {
            const glm::dvec2 w(f.width * (k + 0.5) / 2000, 1.3 + 0.05 * row);
            const ReprojectHit hit = reproject(image, f, e, s, w, span);
            if (hit.hit) worst = std::max(worst, shownError(image, f, e, s, w, hit));
        }
    std::printf("segment form %.5f rad, largest error drawn %.5f rad (ratio %.3f)\n", form, worst, worst / form);
    EXPECT_LE(worst, form);
    EXPECT_GE(worst, 0.8 * form);
}

// nearWall is the wall as the sampling point sees it on the plane `depth` behind: its corners
// lie on the rays from S through the wall's corners, at that depth.
TEST(DepthPlan, NearWallIsTheWallProjectedFromTheSamplingPoint) {
    const glm::dvec3 s(0.5, 1.5, 3.0);
    const display::ScreenQuad w = nearWall(kPlanWall, s, 1.5);  // S is 3 m in front: scale 1.5
    EXPECT_NEAR(glm::length(w.lowerLeft - (kPlanWall.lowerLeft + 0.5 * (kPlanWall.lowerLeft - s))), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(w.lowerRight - (kPlanWall.lowerRight + 0.5 * (kPlanWall.lowerRight - s))), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(w.upperLeft - (kPlanWall.upperLeft + 0.5 * (kPlanWall.upperLeft - s))), 0.0, 1e-12);
    EXPECT_NEAR(w.lowerLeft.z, -1.5, 1e-12);
    // From behind the wall the plane moves the other way.
    EXPECT_NEAR(nearWall(kPlanWall, {0.5, 1.5, -3.0}, 1.5).lowerLeft.z, 1.5, 1e-12);
    EXPECT_THROW(nearWall(kPlanWall, {0.5, 1.5, 0.0}, 1.5), Error);
}

// The segment form per eye is the largest angle the part [dNear, dFar] of S's ray through a
// wall point subtends at the eye (sampled densely over the wall), plus the texel term; it is at
// most the span form and the flat texture's error (dNear = 0), and shrinks as dNear grows.
TEST(DepthPlan, SegmentEyeFormIsTheLargestAngleOfTheRaysParts) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const WallFrame f = wallFrame(kPlanWall);
    for (int i = 0; i < 40; ++i) {
        const glm::dvec3 s(-1.5 + 3.0 * u(rng), 1.0 + u(rng), 1.0 + 3.0 * u(rng));
        const glm::dvec3 e(-2.5 + 5.0 * u(rng), 1.0 + u(rng), 0.5 + 4.0 * u(rng));
        const double nearDepth = 3.0 * u(rng), farDepth = nearDepth + 0.5 + 20.0 * u(rng), h = 0.01 * u(rng);
        const glm::dvec2 span(nearDepth, farDepth);
        const double form = depthSegmentEyeBound(e, s, kPlanWall, span, h);
        const double texel = 0.5 * h * std::max(1.0 / e.z, 1.0 / s.z);
        const glm::dvec3 sw = f.toWall(s);
        double sampled = 0.0;
        for (int a = 0; a <= 80; ++a)
            for (int b = 0; b <= 60; ++b) {
                const glm::dvec3 t(f.width * a / 80.0, f.height * b / 60.0, 0.0);
                auto at = [&](double d) { return f.toWorld(t + (d / -sw.z) * (t - sw)); };
                const glm::dvec3 p = glm::normalize(at(nearDepth) - e), q = glm::normalize(at(farDepth) - e);
                sampled = std::max(sampled, std::atan2(glm::length(glm::cross(p, q)), glm::dot(p, q)));
            }
        EXPECT_LE(sampled, form - texel + 1e-9) << "case " << i;
        EXPECT_GE(sampled, 0.99 * (form - texel)) << "case " << i;
        EXPECT_LE(form, depthEyeBound(e, s, kPlanWall, span, h) + 1e-12) << "case " << i;
        EXPECT_LE(form, depthSegmentEyeBound(e, s, kPlanWall, {0.0, farDepth}, h) + 1e-12) << "case " << i;
        EXPECT_LT(depthSegmentEyeBound(e, s, kPlanWall, {nearDepth + 1.0, farDepth + 1.0}, h), form) << "case " << i;
    }
}

// The zone form (zoneDepthBound of nearWall) covers every eye's form, sampled inside the zone and
// on its border; on a zone of the planner's size (1 m, 2 m from the wall) it is reached closely,
// at a vertex, whose depth it grows by 1 / (1 - eta). A finite far depth and a larger near
// depth make it smaller. (The large zone reaches 1 m from the wall: eta >= 1 there, and the
// form is the depth-independent one.)
TEST(DepthPlan, SegmentZoneFormCoversEveryEyeOfTheZone) {
    const ZoneVolume large{{{-1, 1}, {2, 1.5}, {2.5, 4}, {-1.5, 3}}, {1.2, 2.0}};
    const ZoneVolume planned{{{0.2, 2.0}, {1.2, 2.0}, {1.2, 3.0}, {0.2, 3.0}}, {1.2, 2.0}};
    const glm::dvec3 s(0.7, 1.6, 2.4);
    const double h = 0.004;
    for (const ZoneVolume* z : {&large, &planned})
        for (double nearDepth : {0.0, 0.3, 2.0, 10.0})
            for (double farDepth : {nearDepth + 0.5, nearDepth + 5.0, nearDepth + 1e6}) {
                const ZoneVolume& zone = *z;
                const glm::dvec2 span(nearDepth, farDepth);
                const double bound = depthSegmentZoneBound(zone, s, kPlanWall, span, h);
                double worst = 0.0;
                std::mt19937 rng(3);
                std::uniform_real_distribution<double> u(0.0, 1.0);
                for (int k = 0; k < 400; ++k) {
                    // A point of the zone: a vertex, or a random mix of its vertices.
                    glm::dvec2 p(0.0);
                    if (k < 8) {
                        p = zone.floor[k % 4];
                    } else {
                        double total = 0.0;
                        for (const glm::dvec2& v : zone.floor) {
                            const double w = u(rng);
                            p += w * v;
                            total += w;
                        }
                        p /= total;
                    }
                    const glm::dvec3 e(p.x, k < 8 ? (k < 4 ? 1.2 : 2.0) : 1.2 + 0.8 * u(rng), p.y);
                    const double eye = depthSegmentEyeBound(e, s, kPlanWall, span, h);
                    EXPECT_LE(eye, bound + 1e-9) << "near " << nearDepth << " far " << farDepth;
                    worst = std::max(worst, eye);
                }
                std::printf("near %.1f far %.1f: zone form %.5f rad, largest eye %.5f (ratio %.3f)\n", nearDepth,
                            farDepth, bound, worst, worst / bound);
                if (z == &planned) {
                    EXPECT_GE(worst, 0.8 * bound) << "near " << nearDepth << " far " << farDepth;
                }
                EXPECT_LE(bound, depthSegmentZoneBound(zone, s, kPlanWall, {nearDepth, nearDepth + 1e6}, h) + 1e-12);
                if (nearDepth > 0.0) {
                    EXPECT_LT(bound, depthSegmentZoneBound(zone, s, kPlanWall, {0.0, farDepth}, h));
                }
            }
}

TEST(DepthPlan, EyeBoundShrinksWithTheSpanAndIsSymmetricAcrossTheWall) {
    const glm::dvec3 s(0.5, 1.5, 3.0), e(1.5, 1.7, 2.0);
    const double wide = depthEyeBound(e, s, kPlanWall, {0.0, 1e9}, 0.0),
                 narrow = depthEyeBound(e, s, kPlanWall, {2.0, 3.0}, 0.0);
    EXPECT_GT(wide, 3.0 * narrow);
    EXPECT_LT(depthEyeBound(e, s, kPlanWall, {2.0, 2.0}, 0.0), 1e-5);  // one depth: exact but for the widening
    // The same eye and sampling point mirrored behind the wall (a texture of the back side).
    const glm::dvec3 em(e.x, e.y, -e.z), sm(s.x, s.y, -s.z);
    EXPECT_NEAR(depthEyeBound(em, sm, kPlanWall, {2.0, 3.0}, 0.01), depthEyeBound(e, s, kPlanWall, {2.0, 3.0}, 0.01), 1e-12);
    // An eye on the other side of the plane, or on it, proves nothing.
    EXPECT_GT(depthEyeBound(em, s, kPlanWall, {2.0, 3.0}, 0.0), 3.0);
    EXPECT_GT(depthEyeBound({1, 1, 0}, s, kPlanWall, {2.0, 3.0}, 0.0), 3.0);
}

// The zone bound is at least every eye's bound in the zone (sampled inside and on its border).
TEST(DepthPlan, ZoneBoundCoversEveryEyeOfTheZone) {
    const ZoneVolume zone{{{-1, 1}, {2, 1.5}, {2.5, 4}, {-1.5, 3}}, {1.2, 2.0}};
    const glm::dvec3 s(0.3, 1.6, 2.2);
    const glm::dvec2 span(0.7, 6.0);
    const double bound = depthZoneBound(zone, s, kPlanWall, span, 0.004);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 4000; ++i) {
        // A random convex combination of the floor vertices, at a random head height.
        double w[4], sum = 0.0;
        for (double& x : w) sum += x = -std::log(u(rng) + 1e-300);
        glm::dvec2 p(0.0);
        for (int k = 0; k < 4; ++k) p += (w[k] / sum) * zone.floor[k];
        const glm::dvec3 eye(p.x, 1.2 + 0.8 * u(rng), p.y);
        worst = std::max(worst, depthEyeBound(eye, s, kPlanWall, span, 0.004));
    }
    std::printf("zone bound %.4f rad, largest per-eye bound of 4000 eyes %.4f rad (ratio %.3f)\n", bound, worst,
                worst / bound);
    EXPECT_LE(worst, bound);
    // This zone spans 1 to 4 m from the wall: the zone bound takes the nearest distance with the
    // largest parallax of any eye, so it is looser than at one eye (0.44 here), not unbounded.
    EXPECT_GE(worst, 0.4 * bound);
}

// The planner's predicates (depthZoneWithin, depthSegmentZoneWithin) stop early; they must give
// the bounds' answer. Random zones, sampling points, spans and texels, with alpha on both sides
// of each bound and at it: the span form exactly; the segment form too, except within the
// bound's own tolerance of alpha (it decides, the bound bisects to kErrorTolerance).
TEST(DepthPlan, WithinPredicatesGiveTheBoundsAnswer) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int spanYes = 0, spanNo = 0, segmentYes = 0, segmentNo = 0;
    for (int i = 0; i < 300; ++i) {
        const double x = -3.0 + 6.0 * u(rng), z = 0.5 + 5.0 * u(rng), w = 0.2 + 2.0 * u(rng), d = 0.2 + 2.0 * u(rng);
        const ZoneVolume zone{{{x, z}, {x + w, z}, {x + w + 0.3 * u(rng), z + d}, {x - 0.3 * u(rng), z + d}},
                              {1.2, 2.0}};
        const glm::dvec3 s(x + w * u(rng), 1.6, z + d * u(rng));
        const double nearDepth = 2.0 * u(rng);
        const glm::dvec2 span(nearDepth, u(rng) < 0.1 ? kInfiniteDepth : nearDepth + 8.0 * u(rng));
        const double h = 0.02 * u(rng);
        const double spanBound = depthZoneBound(zone, s, kPlanWall, span, h),
                     segmentBound = depthSegmentZoneBound(zone, s, kPlanWall, span, h);
        for (double f : {0.5, 0.9, 0.99, 1.0, 1.01, 1.1, 2.0}) {
            const double alpha = std::min(f * spanBound, 1.5);
            const bool spanWithin = depthZoneWithin(zone, s, kPlanWall, span, h, alpha);
            EXPECT_EQ(spanWithin, spanBound <= alpha) << "zone " << i << " alpha " << alpha << " bound " << spanBound;
            (spanWithin ? spanYes : spanNo) += 1;
            const double segmentAlpha = std::min(f * segmentBound, 1.5);
            const bool segmentWithin = depthSegmentZoneWithin(zone, s, kPlanWall, span, h, segmentAlpha);
            if (std::abs(segmentBound - segmentAlpha) > 1e-8) {
                EXPECT_EQ(segmentWithin, segmentBound <= segmentAlpha)
                    << "zone " << i << " alpha " << segmentAlpha << " bound " << segmentBound;
            }
            (segmentWithin ? segmentYes : segmentNo) += 1;
        }
    }
    // Both answers occur, often.
    EXPECT_GT(std::min({spanYes, spanNo, segmentYes, segmentNo}), 300);
    // No zone, an eye on the other side: not within, whatever alpha.
    const glm::dvec3 s(0.0, 1.6, 2.0);
    EXPECT_FALSE(depthZoneWithin({{}, {1.2, 2.0}}, s, kPlanWall, {0.5, 2.0}, 0.01, 1.5));
    EXPECT_FALSE(depthSegmentZoneWithin({{}, {1.2, 2.0}}, s, kPlanWall, {0.5, 2.0}, 0.01, 1.5));
    const ZoneVolume across{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, {1.2, 2.0}};
    EXPECT_FALSE(depthZoneWithin(across, s, kPlanWall, {0.5, 2.0}, 0.01, 1.5));
    EXPECT_FALSE(depthSegmentZoneWithin(across, s, kPlanWall, {0.5, 2.0}, 0.01, 1.5));
}

// Depth images whose depths are anywhere in the wall's span: blocks of random depth.
DepthImage blockImage(int width, int height, glm::dvec2 span, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(span.x, span.y);
    const int blocks = 6;
    std::vector<float> depth(blocks * blocks);
    for (float& d : depth) d = static_cast<float>(u(rng));
    depth[0] = static_cast<float>(span.x);
    depth[1] = static_cast<float>(span.y);  // the extremes occur
    DepthImage image{width, height, {}};
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            image.depth.push_back(depth[(j * blocks / height) * blocks + i * blocks / width]);
    return image;
}

Plan planHall(WallKind kind, glm::dvec2 span, double alphaDeg = 10.0) {
    PlanOptions o;
    o.alphaDeg = alphaDeg;
    o.wallKind = kind;
    o.maxResolution = 64;  // coarse texels: the texel term counts
    return planZones(testing::hall(), o, {span});
}

// Every texture planned for depth walls: its stored bound is within alpha, and at eyes all over
// its valid region (vertices, edge midpoints, centroid; both head heights) every pixel the
// reference reprojection draws from depth images with depths in the span is within alpha.
TEST(DepthPlan, EveryPlannedDepthTextureIsWithinAlphaWhereverItIsDrawn) {
    const glm::dvec2 span(1.5, 9.0);
    const Plan plan = planHall(WallKind::Depth, span);
    ASSERT_FALSE(plan.textures.empty());
    const double alpha = glm::radians(plan.alphaDeg);
    std::mt19937 rng(11);
    double worstMeasured = 0.0, worstBound = 0.0;
    for (const Texture& t : plan.textures) {
        SCOPED_TRACE("texture " + std::to_string(t.id));
        EXPECT_LE(t.maxError, alpha);
        EXPECT_GT(t.maxError, 0.0);
        const PlannedWall& wall = plan.walls[t.wall];
        const int side = wall.cells[0] == t.cell ? 0 : 1;
        const WallFrame f = wallFrame(quadSeenFrom(wall.quad, side));
        const glm::dvec3 s = f.toWall(t.samplingPoint);
        ASSERT_LT(s.z, 0.0);
        const DepthImage image = blockImage(t.resolution.x, t.resolution.y, span, rng);
        std::vector<glm::dvec2> eyes(t.validRegion.begin(), t.validRegion.end());
        for (std::size_t i = 0; i < t.validRegion.size(); ++i)
            eyes.push_back(0.5 * (t.validRegion[i] + t.validRegion[(i + 1) % t.validRegion.size()]));
        eyes.push_back(centroid(t.validRegion));
        for (const glm::dvec2& p : eyes)
            for (double y : {1.2, 2.0}) {
                const glm::dvec3 eyeWorld(p.x, y, p.y), e = f.toWall(eyeWorld);
                const double bound = textureErrorAt(plan, t, eyeWorld);
                EXPECT_LE(bound, t.maxError + 1e-12);
                worstBound = std::max(worstBound, bound);
                for (int k = 0; k < 16; ++k)
                    for (int m = 0; m < 12; ++m) {
                        const glm::dvec2 w(f.width * (k + 0.5) / 16, f.height * (m + 0.5) / 12);
                        const ReprojectHit hit = reproject(image, f, e, s, w, depthRange(image));
                        if (!hit.hit) continue;
                        const double error = shownError(image, f, e, s, w, hit);
                        worstMeasured = std::max(worstMeasured, error);
                        ASSERT_LE(error, bound + 1e-12) << "eye " << p.x << ", " << y << ", " << p.y;
                    }
            }
    }
    std::printf("%zu depth textures at alpha 10°: largest per-eye bound %.3f°, largest measured error %.3f°\n",
                plan.textures.size(), glm::degrees(worstBound), glm::degrees(worstMeasured));
    EXPECT_LE(worstMeasured, alpha);
}

TEST(DepthPlan, NarrowSpansNeedFewerTexturesThanFlatWalls) {
    const Plan flat = planHall(WallKind::Flat, {1.5, 9.0});
    const Plan depth = planHall(WallKind::Depth, {1.5, 9.0});
    std::printf("reference hall at alpha 10°: %zu flat textures, %zu depth textures (span 1.5 .. 9 m)\n",
                flat.textures.size(), depth.textures.size());
    EXPECT_LT(depth.textures.size(), flat.textures.size());
    // Whatever the span, the flat form keeps depth walls within the texel term of flat walls.
    const Plan wide = planHall(WallKind::Depth, {0.0, 1e9});
    std::printf("span 0 .. 1e9 m: %zu depth textures\n", wide.textures.size());
    EXPECT_LE(double(wide.textures.size()), 1.1 * double(flat.textures.size()));
    // Depth walls keep the flat walls' geometry strip (plan.h): each side's border at least the
    // flat plan's, the same on most sides.
    ASSERT_EQ(depth.sides.size(), flat.sides.size());
    int same = 0;
    for (std::size_t i = 0; i < flat.sides.size(); ++i) {
        EXPECT_GE(depth.sides[i].geometryDistance, flat.sides[i].geometryDistance - 1e-12) << "side " << i;
        same += depth.sides[i].geometryDistance == flat.sides[i].geometryDistance;
    }
    EXPECT_GE(2 * same, int(flat.sides.size()));
    // The flat plan does not depend on the span; each texture reports its own kind's bound.
    EXPECT_EQ(flat.textures.size(), planHall(WallKind::Flat, {0.0, 1e9}).textures.size());
    for (const Texture& t : depth.textures)
        EXPECT_NEAR(t.maxError,
                    depthTextureBound({t.validRegion, testing::hall().headHeightRange}, t.samplingPoint,
                                      depth.walls[t.wall].quad, {1.5, 9.0}, depth.options),
                    1e-15);
}

TEST(DepthPlan, SpansAreCheckedAndCarriedByTheJson) {
    PlanOptions o;
    o.wallKind = WallKind::Depth;
    try {
        planZones(testing::hall(), o, {{3.0, 2.0}});
        FAIL() << "expected an Error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("wall 'middle': expected a depth span 0 <= near <= far"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(planZones(testing::hall(), o, {{1.0, 2.0}, {1.0, 2.0}}), Error);
    const Plan plan = planZones(testing::hall(), o, {{1.5, 9.0}});
    const nlohmann::json j = planToJson(plan);
    EXPECT_EQ(j.at("wallKind"), "depth");
    EXPECT_EQ(j.at("walls")[0].at("depthNear"), 1.5);
    ASSERT_EQ(j.at("textures").size(), plan.textures.size());
    EXPECT_EQ(j.at("textures")[0].at("maxError").get<double>(), plan.textures[0].maxError);
    const Plan back = planFromJson(j.dump(), "plan.json");
    EXPECT_EQ(back.options.wallKind, WallKind::Depth);
    EXPECT_EQ(back.walls[0].depthNear, 1.5);
    EXPECT_EQ(back.walls[0].depthBehind, 9.0);
    EXPECT_EQ(back.textures[0].maxError, plan.textures[0].maxError);
}

// The bake's resolution (gl::WallBaker bakes at bakeResolution): the plan's, capped keeping the
// aspect; depth walls' sides even.
TEST(BakeResolution, PlanResolutionIsCappedKeepingTheAspect) {
    struct Case {
        glm::ivec2 planned;
        int cap;
        glm::ivec2 expected;
    };
    const Case cases[] = {
        {{100, 50}, 1024, {100, 50}},       // within the cap: as planned
        {{4000, 1000}, 1024, {1024, 256}},  // scaled by 1024 / 4000, aspect 4:1 kept
        {{300, 3000}, 64, {6, 64}},         // 300 * 64 / 3000 = 6.4 rounds to 6
        {{5000, 1}, 16, {16, 1}},           // never below one texel
        {{0, 0}, 16, {1, 1}},               // a plan without resolutions still bakes one texel
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(c.planned.x) + " x " + std::to_string(c.planned.y) + " cap " +
                     std::to_string(c.cap));
        EXPECT_EQ(bakeResolution(c.planned, c.cap), c.expected);
    }
    // Depth walls: even sides, so that the march reads halved depths; never past the cap.
    EXPECT_EQ(bakeResolution({101, 51}, 1024, WallKind::Depth), glm::ivec2(102, 52));
    EXPECT_EQ(bakeResolution({4000, 1000}, 1024, WallKind::Depth), glm::ivec2(1024, 256));
    EXPECT_EQ(bakeResolution({5000, 1}, 16, WallKind::Depth), glm::ivec2(16, 2));
    EXPECT_EQ(bakeResolution({17, 3}, 17, WallKind::Depth), glm::ivec2(16, 4));
}

// The cap keeps each texture's aspect, as the bake's does (bakeResolution): a depth plan
// capped at the bake's size proves its texel term for exactly the texels baked, and a wall
// wider than high is not baked square (clamping each side alone gave the depth bake of the
// plant 1.42x the flat bake's texels). Flat zones do not depend on the
// cap, so the two plans' textures correspond.
TEST(DepthPlan, ACapKeepsEachTexturesAspect) {
    PlanOptions o;
    o.maxResolution = 4096;
    const Plan full = planZones(testing::obliqueCells(), o);
    o.maxResolution = 64;
    const Plan capped = planZones(testing::obliqueCells(), o);
    ASSERT_EQ(full.textures.size(), capped.textures.size());
    int scaled = 0;
    for (std::size_t i = 0; i < full.textures.size(); ++i) {
        const glm::ivec2 a = full.textures[i].resolution, b = capped.textures[i].resolution;
        SCOPED_TRACE(std::to_string(a.x) + " x " + std::to_string(a.y) + " -> " + std::to_string(b.x) + " x " +
                     std::to_string(b.y));
        EXPECT_EQ(b, capResolution(glm::dvec2(a), 64));
        if (std::max(a.x, a.y) <= 64) {
            EXPECT_EQ(b, a);
            continue;
        }
        ++scaled;
        const double scale = 64.0 / std::max(a.x, a.y);  // both sides by one factor, to the nearest texel
        EXPECT_NEAR(b.x, a.x * scale, 0.5 + 1e-9);
        EXPECT_NEAR(b.y, a.y * scale, 0.5 + 1e-9);
        EXPECT_EQ(std::max(b.x, b.y), 64);
    }
    EXPECT_GT(scaled, 0);  // the 7 m x 3 m wall's near textures exceed 64 texels
    EXPECT_EQ(capResolution({300, 3000}, 64), glm::ivec2(6, 64));  // 6.4 rounds to 6
    EXPECT_EQ(capResolution({5000, 1}, 16), glm::ivec2(16, 1));    // never below one texel
    EXPECT_EQ(capResolution({0, 0}, 16), glm::ivec2(1, 1));
}

TEST(DepthPlan, PlanOptionsForDepthWallsKeepTheBakedTexelSize) {
    PlanOptions o;
    EXPECT_EQ(planOptionsFor(o, WallKind::Depth, 512).maxResolution, 512);
    EXPECT_EQ(planOptionsFor(o, WallKind::Depth, 512).wallKind, WallKind::Depth);
    EXPECT_EQ(planOptionsFor(o, WallKind::Flat, 512).maxResolution, o.maxResolution);
}

}  // namespace
}  // namespace cavewall::walls
