// Depth walls (walls/depth_wall.h): the wall frame and depth encoding, the reference
// reprojection against an analytic scene, and the error bound: every pixel whose reprojection
// differs from the truth by more than the texel term lies in an interval the bound predicts,
// and the widest such interval is at least 0.6 of the predicted width (a bound 2x too loose
// fails).
#include "walls/depth_wall.h"

#include "config/error.h"
#include "walls/angular_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace cavewall::walls {
namespace {

const display::ScreenQuad kQuad{{-2, 0, 0}, {2, 0, 0}, {-2, 3, 0}};  // 4 m x 3 m, facing +z

// An analytic scene in the wall frame: a card (x in [1.5, 2.5], y in [1, 2]) at depth 1 in front
// of a back plane at depth 4. The first surface along a ray from `from` (wall frame, z < 0)
// through wall point w: its depth and lateral position.
struct Surface {
    double depth;
    glm::dvec2 at;
};
Surface firstSurface(glm::dvec3 from, glm::dvec2 w) {
    const double d0 = -from.z;
    auto lateral = [&](double d) { return w + (d / d0) * (w - glm::dvec2(from)); };
    const glm::dvec2 c = lateral(1.0);
    if (c.x >= 1.5 && c.x <= 2.5 && c.y >= 1.0 && c.y <= 2.0) return {1.0, c};
    return {4.0, lateral(4.0)};
}

DepthImage bakeAnalytic(const WallFrame& f, glm::dvec3 sample, int width, int height) {
    DepthImage image{width, height, {}};
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            image.depth.push_back(static_cast<float>(firstSurface(sample, texelCentre(f, width, height, i, j)).depth));
    return image;
}

TEST(DepthWall, FrameRoundTripsAndPutsTheViewerInFront) {
    const WallFrame f = wallFrame(kQuad);
    EXPECT_DOUBLE_EQ(f.width, 4.0);
    EXPECT_DOUBLE_EQ(f.height, 3.0);
    const glm::dvec3 eye(0.3, 1.7, 2.5);
    const glm::dvec3 w = f.toWall(eye);
    EXPECT_NEAR(w.z, -2.5, 1e-12);
    EXPECT_NEAR(w.x, 2.3, 1e-12);
    const glm::dvec3 back = f.toWorld(w);
    EXPECT_NEAR(glm::length(back - eye), 0.0, 1e-12);
    EXPECT_THROW(wallFrame({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), Error);
}

TEST(DepthWall, WallKindParsesAndNamesItsInput) {
    EXPECT_EQ(parseWallKind("flat", "--walls"), WallKind::Flat);
    EXPECT_EQ(parseWallKind("depth", "--walls"), WallKind::Depth);
    EXPECT_EQ(wallKindName(WallKind::Depth), "depth");
    try {
        parseWallKind("deep", "--walls");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--walls"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("deep"), std::string::npos);
    }
}

TEST(DepthWall, BufferDepthDecodesToTheDistanceBehindTheWall) {
    const glm::dvec3 sample(0.4, 1.5, 3.0);
    const display::OffAxisFrustum fr =
        display::offAxisFrustum(kQuad, sample, {0.05, std::numeric_limits<double>::infinity()});
    const WallFrame f = wallFrame(kQuad);
    for (double d : {0.0, 0.01, 1.0, 7.5, 120.0}) {
        const glm::dvec3 p = f.toWorld({1.1, 2.2, d});
        const glm::dvec4 clip = fr.clipFromFrame() * glm::dvec4(p, 1.0);
        const float buffer = static_cast<float>(clip.z / clip.w);
        // Float buffer: relative 2^-24 of the view distance (depth_wall.h).
        EXPECT_NEAR(depthFromBuffer(buffer, fr.clipFromView, fr.eyeDistance), d, 1.2e-7 * (3.0 + d) + 1e-9) << d;
    }
    EXPECT_EQ(depthFromBuffer(0.0f, fr.clipFromView, fr.eyeDistance), kNoSurface);
}

TEST(DepthWall, ReprojectedPointIsWhereTheEyeSeesTheSurfacePoint) {
    const glm::dvec3 s(1.0, 1.5, -3.0), e(2.2, 1.1, -1.7);
    for (double d : {0.5, 2.0, 40.0}) {
        const glm::dvec2 t(0.7, 2.4);
        const glm::dvec2 p = t + (d / 3.0) * (t - glm::dvec2(s));  // seen from S through t at depth d
        const double along = 1.7 / (1.7 + d);
        const glm::dvec2 seen = glm::dvec2(e) + along * (p - glm::dvec2(e));
        const glm::dvec2 got = reprojectedPoint(e, s, t, d);
        EXPECT_NEAR(got.x, seen.x, 1e-12);
        EXPECT_NEAR(got.y, seen.y, 1e-12);
    }
}

TEST(DepthWall, BoundFromZeroDepthCoversTheFlatWallsExactError) {
    // With the whole content depth as the "step" from the wall plane, the bound is a bound of
    // the flat wall's error (walls/angular_error.h pointError) for every point up to that depth.
    const WallFrame f = wallFrame(kQuad);
    const glm::dvec3 sWorld(0.0, 1.6, 3.0);
    for (glm::dvec3 eWorld : {glm::dvec3(1.5, 1.2, 2.0), glm::dvec3(-1.9, 2.0, 4.5), glm::dvec3(0.0, 1.6, 0.8)}) {
        const double bound = reprojectionErrorBound(f, f.toWall(eWorld), f.toWall(sWorld), 0.0, 6.0);
        double worst = 0.0;
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j <= 30; ++j)
                for (double d : {0.5, 2.0, 6.0}) {
                    const glm::dvec2 t(4.0 * i / 40, 3.0 * j / 30);
                    const glm::dvec3 tw = f.toWorld({t, 0.0});
                    const glm::dvec3 p = tw + (d / 3.0) * (tw - sWorld);
                    worst = std::max(worst, pointError(eWorld, sWorld, p, kQuad));
                }
        EXPECT_GE(bound, worst);
        // And of the same scale away from the wall (L / D_E overestimates large angles near it).
        if (eWorld.z >= 2.0) {
            EXPECT_LT(bound, 3.0 * worst);
        }
    }
}

// The reference reprojection against the analytic scene, eye 0.6 m to the side of the sampling
// point and 0.5 m closer: away from the bound's intervals it shows the true surface at its true
// direction within the texel term; the intervals hold every other pixel and are not loose.
TEST(DepthWall, ReprojectionMatchesTruthOutsideThePredictedDisocclusion) {
    const WallFrame f = wallFrame(kQuad);
    const glm::dvec3 s(2.0, 1.5, -3.0), e(2.6, 1.5, -2.5);
    const int n = 512;
    const DepthImage image = bakeAnalytic(f, s, n, n * 3 / 4);
    const glm::dvec2 range = depthRange(image);
    EXPECT_EQ(range, glm::dvec2(1.0, 4.0));
    const DepthWallBound bound = depthWallErrorBound(image, f, e, s);
    // The card's steps are 1 -> 4; the one that opens is its right edge (the eye moved to +x),
    // seen by S at x = 2 + 0.5 * 3 / 4, where v is nearly along +x: the step term is that
    // interval, while the undirected stepAngle of the left edge is larger.
    const double de = -e.z;
    const double right = stepAngle(e, s, {2.375, 1.5}, 1.0, 4.0), left = stepAngle(e, s, {1.625, 1.5}, 1.0, 4.0);
    EXPECT_GT(left, 1.2 * right);
    EXPECT_NEAR(bound.steps, right, 0.03 * right);

    // Scan the row through the card's middle (y = 1.5) at a fine pitch.
    double widest = 0.0, run = 0.0;
    int wrong = 0, outside = 0;
    const int samples = 4000;
    for (int k = 0; k < samples; ++k) {
        const glm::dvec2 w(f.width * (k + 0.5) / samples, 1.5);
        const Surface truth = firstSurface(e, w);
        // Content S saw only outside the wall (the border term): not part of this check.
        const glm::dvec2 tTrue = glm::dvec2(s) + (truth.at - glm::dvec2(s)) * (3.0 / (3.0 + truth.depth));
        if (tTrue.x < 0.0 || tTrue.x > f.width) continue;
        const ReprojectHit hit = reproject(image, f, e, s, w, range);
        bool ok = hit.hit;
        if (ok) {
            // The point whose colour the pixel shows: what S saw through the texel hit (the
            // hit itself is always on the eye's ray; a wrong one shows the wrong surface).
            const glm::dvec2 p = hit.texture + (hit.surface / 3.0) * (hit.texture - glm::dvec2(s));
            const glm::dvec3 got(p, hit.surface), want(truth.at, truth.depth), eye(e);
            const double angle =
                std::acos(std::clamp(glm::dot(glm::normalize(got - eye), glm::normalize(want - eye)), -1.0, 1.0));
            ok = angle <= bound.texel + 1e-9;
        }
        if (!ok) {
            ++wrong;
            run += f.width / samples;
            widest = std::max(widest, run);
            // Every wrong pixel is inside a predicted interval: [W(d1), W(d2)] of a card edge.
            bool predicted = false;
            for (double edge : {1.5, 2.5}) {
                const glm::dvec2 t(2.0 + (edge - 2.0) * 3.0 / 4.0, 1.5);  // where S sees the card's edge
                const double a = reprojectedPoint(e, s, t, 1.0).x, b = reprojectedPoint(e, s, t, 4.0).x;
                const double slack = 2.0 * f.width / n;  // a texel either side
                if (w.x >= std::min(a, b) - slack && w.x <= std::max(a, b) + slack) predicted = true;
            }
            if (!predicted) ++outside;
        } else {
            run = 0.0;
        }
    }
    std::printf(
        "reprojection at 512 x 384 texels: %d of %d samples wrong, widest %.4f rad, bound steps %.4f + texel %.5f\n",
        wrong, samples, widest / de, bound.steps, bound.texel);
    EXPECT_GT(wrong, 0);  // the eye does see something S did not
    EXPECT_EQ(outside, 0);
    // The widest wrong interval's angle against the bound's step term: within it, and not
    // below 0.6 of it.
    const double widestAngle = widest / de;
    EXPECT_LE(widestAngle, bound.steps + 2.0 * bound.texel);
    EXPECT_GE(widestAngle, 0.6 * bound.steps);
}

// The refinement within the march's last step against a dense scan of that step: on random
// piecewise-constant depths (some texels empty, the step partly outside the image) and steps of
// at most one texel per axis in every direction, texelCrossing is the scan's first hit within the
// scan's pitch, and shows the depth of the texel the ray is in just after it. (A 6-step
// bisection is 1/64 of a step off at the worst; choosing the wrong middle texel fails too.)
TEST(DepthWall, TexelCrossingIsTheFirstHitWithinTheLastStep) {
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int n = 16;
    const double ds = 3.0;
    DepthImage image{n, n, {}};
    for (int k = 0; k < n * n; ++k)
        image.depth.push_back(unit(rng) < 0.1 ? kNoSurface : static_cast<float>(0.5 + 4.5 * unit(rng)));
    auto depthAt = [&](glm::dvec2 t) {
        const double i = std::floor(t.x), j = std::floor(t.y);
        return i >= 0 && j >= 0 && i < n && j < n ? image.at(int(i), int(j)) : kNoSurface;
    };
    const int scan = 200000;
    int cases = 0, wrongSigma = 0, wrongDepth = 0, twoEdges = 0;
    while (cases < 2000) {
        const glm::dvec2 dir(80.0 * (unit(rng) - 0.5), 80.0 * (unit(rng) - 0.5));
        const double lo = 0.1 + 0.5 * unit(rng);
        const double hi = lo + unit(rng) / std::max(std::abs(dir.x), std::abs(dir.y));
        const glm::dvec2 ta = glm::dvec2(-1.0 + 18.0 * unit(rng), -1.0 + 18.0 * unit(rng)) - lo * dir;
        const float dHi = depthAt(ta + hi * dir);
        if (!hitsDepth(hi, dHi, ds) || hitsDepth(lo, depthAt(ta + lo * dir), ds)) continue;
        ++cases;
        const glm::dvec2 iLo = glm::floor(ta + lo * dir), iHi = glm::floor(ta + hi * dir);
        if (iLo.x != iHi.x && iLo.y != iHi.y) ++twoEdges;
        const TexelCrossing c = texelCrossing(image, ta, ta + dir, ds, lo, hi, dHi);
        const double pitch = (hi - lo) / scan;
        double first = hi;
        for (int k = 0; k <= scan; ++k) {
            const double sigma = lo + pitch * k;
            if (hitsDepth(sigma, depthAt(ta + sigma * dir), ds)) {
                first = sigma;
                break;
            }
        }
        if (!(c.sigma <= first + 1e-12 && c.sigma >= first - pitch - 1e-12)) ++wrongSigma;
        if (c.depth != depthAt(ta + first * dir)) ++wrongDepth;
    }
    EXPECT_GT(twoEdges, 100);  // the three-texel case is exercised
    EXPECT_EQ(wrongSigma, 0);
    EXPECT_EQ(wrongDepth, 0);
}

TEST(DepthWall, AtTheSamplingPointTheStepsCostNothing) {
    const WallFrame f = wallFrame(kQuad);
    const glm::dvec3 s(2.0, 1.5, -3.0);
    const DepthImage image = bakeAnalytic(f, s, 64, 48);
    const DepthWallBound b = depthWallErrorBound(image, f, s, s);
    EXPECT_EQ(b.steps, 0.0);
    EXPECT_EQ(b.border, 0.0);
    EXPECT_GT(b.texel, 0.0);
    for (int i = 0; i < 64; ++i) {
        const glm::dvec2 w = texelCentre(f, 64, 48, i, 20);
        const ReprojectHit hit = reproject(image, f, s, s, w, depthRange(image));
        ASSERT_TRUE(hit.hit);
        EXPECT_NEAR(hit.depth, image.at(i, 20), 1e-4 * 4.0);
        EXPECT_NEAR(glm::length(hit.texture - w), 0.0, 1e-3);
    }
}

// One plane seen from S through neighbouring texels is no jump down to the grazing angle
// kMinGrazing; a steeper change of depth, a card in front of a far plane, and a surface next to
// an empty texel are; texels too coarse to tell a surface's slope are never a jump.
TEST(DepthWall, DepthJumpTellsOneSurfaceFromTwo) {
    const double ds = 3.0, pitch = 0.01;  // 1 cm texels 3 m from S: rays 1/300 rad apart
    // A plane through the depth-1 point on S's axis, tilted so that S's axis meets it at a
    // grazing angle g: the neighbouring ray, pitch further out on the wall, meets it at
    // (D_S + d) = (D_S + 1) sin g / sin(g - delta) (law of sines), the farthest it can be.
    auto planeFar = [&](double g) {
        const double delta = std::atan(pitch / ds);
        return (ds + 1.0) * std::sin(g) / std::sin(g - delta) - ds;
    };
    EXPECT_FALSE(depthJump(1.0, planeFar(kMinGrazing + 0.02), ds, pitch, 0.0));
    EXPECT_FALSE(depthJump(1.0, planeFar(1.2), ds, pitch, 0.0));
    EXPECT_TRUE(depthJump(1.0, planeFar(kMinGrazing - 0.1), ds, pitch, 0.0));
    EXPECT_TRUE(depthJump(1.0, 4.0, ds, pitch, 0.0));  // the card and the back plane
    EXPECT_TRUE(depthJump(1.0, kNoSurface, ds, pitch, 0.0));
    EXPECT_FALSE(depthJump(1.0, 1.0, ds, pitch, 2.0));
    EXPECT_FALSE(depthJump(1.0, 4.0, ds, 0.5 * kMinGrazing * ds, 0.0));  // rays too far apart to tell
    EXPECT_DOUBLE_EQ(jumpPitch(wallFrame(kQuad), 400, 300), 1.5 * std::hypot(0.01, 0.01));
}

// The sheet is cut: from an eye 0.6 m to the side, the interval the card's right edge opens
// (where the eye sees the back plane S did not) shows the back plane's texels, never the card's;
// with the cut turned off, the whole interval shows the card. With the card alone (nothing behind
// it) the interval draws nothing.
TEST(DepthWall, CutSheetsShowTheFarSideInTheGap) {
    const WallFrame f = wallFrame(kQuad);
    const glm::dvec3 s(2.0, 1.5, -3.0), e(2.6, 1.5, -2.5);
    const DepthImage image = bakeAnalytic(f, s, 512, 384);
    DepthImage alone = image;
    for (float& d : alone.depth)
        if (d > 2.0f) d = kNoSurface;
    const glm::dvec2 range = depthRange(image);
    // Where S sees the card's right edge, and where the eye sees that edge on the card and on the
    // back plane: the gap between.
    const glm::dvec2 edge(2.0 + 0.5 * 3.0 / 4.0, 1.5);
    const double a = reprojectedPoint(e, s, edge, 1.0).x, b = reprojectedPoint(e, s, edge, 4.0).x;
    ASSERT_LT(a + 0.02, b);
    ReprojectSettings keep;
    keep.cutSheets = false;
    int gap = 0, card = 0, filled = 0, drawnAlone = 0, sheet = 0;
    for (double x = a + 0.01; x < b - 0.01; x += 0.001) {
        const glm::dvec2 w(x, 1.5);
        if (firstSurface(e, w).depth < 2.0) continue;  // the eye sees the card here
        ++gap;
        const ReprojectHit hit = reproject(image, f, e, s, w, range);
        ASSERT_TRUE(hit.hit) << x;
        card += hit.surface < 2.0;
        filled += hit.filled;
        drawnAlone += reproject(alone, f, e, s, w, depthRange(alone)).hit;
        sheet += reproject(image, f, e, s, w, range, keep).surface < 2.0;
    }
    std::printf(
        "cut sheet: %d gap samples, %d filled, %d show the card, %d drawn with the card alone; kept, %d show the "
        "card\n",
        gap, filled, card, drawnAlone, sheet);
    EXPECT_GT(gap, 50);
    EXPECT_EQ(card, 0);
    EXPECT_GT(filled, gap / 2);
    EXPECT_EQ(drawnAlone, 0);
    EXPECT_EQ(sheet, gap);  // the sheet the cut removes (cutSheets false, for measuring)
}

// The march's skip level (depthBlockMinimum with dilate 1): from any point of a block (or beyond
// the last whole block, clamped to it), every texel within kSkipSteps per axis is at least as far
// as the block's value, and the value is reached (it is a minimum, not just a lower bound).
// The march's depths: half the size, each texel the nearest of the 2 x 2 it covers (so an empty
// texel next to a surface takes the surface's depth, and every value is a baked one); odd sizes
// stay as baked, so a depth texel always covers whole colour texels.
TEST(DepthWall, MarchDepthsAreTheNearestOfEachTwoByTwoBlock) {
    DepthImage image{6, 4, {}};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 6; ++i) image.depth.push_back(1.0f + 0.25f * float(i) + 2.0f * float(j));
    image.depth[0] = kNoSurface;  // block (0, 0): three surfaces and an empty texel
    for (int k : {4, 5, 10, 11}) image.depth[static_cast<std::size_t>(k)] = kNoSurface;  // block (2, 0): empty
    const DepthImage half = marchDepths(image);
    ASSERT_EQ(half.width, 3);
    ASSERT_EQ(half.height, 2);
    for (int bj = 0; bj < 2; ++bj)
        for (int bi = 0; bi < 3; ++bi) {
            float nearest = kNoSurface;
            for (int j = 2 * bj; j < 2 * bj + 2; ++j)
                for (int i = 2 * bi; i < 2 * bi + 2; ++i) nearest = std::min(nearest, image.at(i, j));
            EXPECT_EQ(half.at(bi, bj), nearest) << bi << ", " << bj;
        }
    EXPECT_EQ(half.at(0, 0), 1.25f);       // the empty texel gives way to its neighbours
    EXPECT_EQ(half.at(2, 0), kNoSurface);  // an empty block stays empty
    const glm::dvec2 range = depthRange(image), halfRange = depthRange(half);
    EXPECT_GE(halfRange.x, range.x);
    EXPECT_LE(halfRange.y, range.y);
    EXPECT_EQ(marchDepthSize(6, 4), glm::ivec2(3, 2));
    // Odd sizes are not halved.
    EXPECT_EQ(marchDepthSize(3, 2), glm::ivec2(3, 2));
    EXPECT_EQ(marchDepthSize(1, 1), glm::ivec2(1, 1));
    const DepthImage odd{3, 2, std::vector<float>(6, 2.0f)};
    EXPECT_EQ(marchDepths(odd).width, 3);
    EXPECT_EQ(marchDepths(odd).depth, odd.depth);
}

// marchErrorBound against the reference march, over a grid of pixels on the whole wall: the
// largest angle between a drawn pixel's direction and the true direction of the point whose
// colour it shows (what S saw through the colour texel, at its full depth) is within the bound,
// with halved depths (an even size, the card's edges inside 2 x 2 blocks) and full ones (an odd
// size is not halved), and at least 0.6 of it (a bound 2x too loose fails). The bound is no
// larger than the planner's for the span the image lies in.
struct MarchCheck {
    double worst = 0.0;  // radians
    int drawn = 0;
};
MarchCheck worstMarchedAngle(const DepthImage& full, const WallFrame& f, glm::dvec3 e, glm::dvec3 s, int samples) {
    const DepthImage march = marchDepths(full);
    const glm::dvec2 range = depthRange(full);
    const double hx = f.width / full.width, hy = f.height / full.height, ds = -s.z;
    MarchCheck check;
    for (int y = 0; y < samples * 3 / 4; ++y)
        for (int x = 0; x < samples; ++x) {
            const glm::dvec2 w(f.width * (x + 0.5) / samples, f.height * (y + 0.5) / (samples * 3 / 4));
            const ReprojectHit hit = reproject(march, f, e, s, w, range);
            if (!hit.hit) continue;
            // The colour texel the pixel samples (nearest), and the point S saw through it.
            const int i = std::clamp(static_cast<int>(std::floor(hit.texture.x / hx)), 0, full.width - 1);
            const int j = std::clamp(static_cast<int>(std::floor((f.height - hit.texture.y) / hy)), 0, full.height - 1);
            const double d = full.at(i, j);
            if (!std::isfinite(d)) continue;  // an empty texel draws nothing
            const glm::dvec2 t = texelCentre(f, full.width, full.height, i, j);
            const glm::dvec3 shown(t + (d / ds) * (t - glm::dvec2(s)), d), pixel(w, 0.0);
            const double c = glm::dot(glm::normalize(shown - e), glm::normalize(pixel - e));
            check.worst = std::max(check.worst, std::acos(std::clamp(c, -1.0, 1.0)));
            ++check.drawn;
        }
    return check;
}

TEST(DepthWall, MarchBoundHoldsForEveryDrawnPixelAndIsTight) {
    const WallFrame f = wallFrame(kQuad);
    const glm::dvec3 s(2.0, 1.5, -3.0);
    for (const glm::ivec2 size : {glm::ivec2(500, 374), glm::ivec2(499, 375)}) {
        const DepthImage image = bakeAnalytic(f, s, size.x, size.y);
        const bool halved = marchDepths(image).width != image.width;
        EXPECT_EQ(halved, size.x % 2 == 0);
        for (const glm::dvec3 e :
             {glm::dvec3(2.6, 1.5, -2.5), glm::dvec3(1.2, 2.1, -2.0), glm::dvec3(2.0, 1.5, -4.5)}) {
            SCOPED_TRACE(std::to_string(size.x) + " x " + std::to_string(size.y) + ", eye x " + std::to_string(e.x));
            const MarchBound bound = marchErrorBound(image, f, e, s, depthRange(image));
            const MarchCheck check = worstMarchedAngle(image, f, e, s, 400);
            std::printf(
                "march %s %d x %d, eye (%.1f, %.1f, %.1f): worst drawn pixel %.5f rad of %d, bound %.5f "
                "(depth %.5f + texel %.5f)\n",
                halved ? "halved" : "full", size.x, size.y, e.x, e.y, e.z, check.worst, check.drawn, bound.total(),
                bound.depth, bound.texel);
            EXPECT_GT(check.drawn, 400 * 300 / 2);
            EXPECT_LE(check.worst, bound.total() + 1e-9);
            EXPECT_GE(check.worst, 0.6 * bound.total());
            const double diagonal = std::hypot(f.width / size.x, f.height / size.y);
            EXPECT_LE(bound.total(), depthEyeBound(f.toWorld(e), f.toWorld(s), kQuad, {1.0, 4.0}, diagonal) + 1e-12);
        }
    }
}

// On random piecewise-constant depths (blocks of random depth, some empty, steps everywhere) the
// claim holds for every drawn pixel whatever the eye: halved and full, near and far eyes.
TEST(DepthWall, MarchBoundHoldsOnRandomDepths) {
    const WallFrame f = wallFrame(kQuad);
    const glm::dvec3 s(2.0, 1.5, -3.0);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> depth(0.05, 6.0), unit(0.0, 1.0);
    for (const glm::ivec2 size : {glm::ivec2(96, 72), glm::ivec2(95, 71)}) {
        DepthImage image{size.x, size.y, std::vector<float>(std::size_t(size.x) * size.y)};
        // Patches of 1 to 7 texels a side, drawn over each other.
        std::fill(image.depth.begin(), image.depth.end(), 3.0f);
        for (int p = 0; p < 400; ++p) {
            const int w = 1 + static_cast<int>(unit(random) * 7), h = 1 + static_cast<int>(unit(random) * 7);
            const int x0 = static_cast<int>(unit(random) * size.x), y0 = static_cast<int>(unit(random) * size.y);
            const float d = unit(random) < 0.1 ? kNoSurface : static_cast<float>(depth(random));
            for (int j = y0; j < std::min(size.y, y0 + h); ++j)
                for (int i = x0; i < std::min(size.x, x0 + w); ++i) image.depth[std::size_t(j) * size.x + i] = d;
        }
        for (int trial = 0; trial < 6; ++trial) {
            const glm::dvec3 e(4.0 * unit(random), 3.0 * unit(random), -(0.4 + 4.0 * unit(random)));
            SCOPED_TRACE(std::to_string(size.x) + " x " + std::to_string(size.y) + ", trial " + std::to_string(trial));
            const MarchBound bound = marchErrorBound(image, f, e, s, depthRange(image));
            const MarchCheck check = worstMarchedAngle(image, f, e, s, 160);
            EXPECT_GT(check.drawn, 0);
            EXPECT_LE(check.worst, bound.total() + 1e-9);
        }
    }
}

// Halving seals a hole narrower than a depth texel: a near plane (0.5 m) with one-texel holes
// onto depth 5 m is marched as the plane, and the pixels that sample a hole's colour show it at
// the plane's depth. The bound counts that (k(d_c) - k(m_B), the step inside the block) and is
// tight for it. Two rings of blocks along the edges (5 m outside, 1.87 m inside: each step half
// the holes' in k) keep the border's steps below the holes', so without that term the bound
// would be about half the error. The eye is as far from the wall as S: v is the same everywhere.
TEST(DepthWall, MarchBoundCountsHolesHalvingSeals) {
    const WallFrame f = wallFrame(kQuad);
    const glm::dvec3 s(2.0, 1.5, -3.0), e(2.6, 1.7, -3.0);
    DepthImage image{64, 48, std::vector<float>(64 * 48, 0.5f)};
    for (int j = 0; j < 48; ++j)
        for (int i = 0; i < 64; ++i) {
            const int ring = std::min(std::min(i, 63 - i), std::min(j, 47 - j));
            if (ring < 4) image.depth[std::size_t(j) * 64 + i] = ring < 2 ? 5.0f : 1.87f;
        }
    // Holes near the eye's foot (texel 41.6, 20.8), where the angle is nearly |W - W_P| / D_E.
    for (int j = 13; j <= 29; j += 4)
        for (int i = 33; i <= 49; i += 4) image.depth[std::size_t(j) * 64 + i] = 5.0f;
    const DepthImage march = marchDepths(image);
    EXPECT_EQ(march.at(20, 10), 0.5f);  // the block of hole (41, 21): sealed
    const MarchBound bound = marchErrorBound(image, f, e, s, depthRange(image));
    const MarchCheck check = worstMarchedAngle(image, f, e, s, 400);
    std::printf("sealed holes: worst drawn pixel %.5f rad, bound %.5f (depth %.5f + texel %.5f)\n", check.worst,
                bound.total(), bound.depth, bound.texel);
    EXPECT_GT(bound.depth, 5.0 * bound.texel);
    EXPECT_LE(check.worst, bound.total() + 1e-9);
    EXPECT_GE(check.worst, 0.6 * bound.total());
}

TEST(DepthWall, BlockMinimumBoundsEveryTexelAStepRunCanReach) {
    for (const auto& [w, h] : {std::pair{64, 48}, std::pair{67, 21}, std::pair{8, 8}}) {
        SCOPED_TRACE(std::to_string(w) + " x " + std::to_string(h));
        DepthImage image{w, h, {}};
        unsigned state = 12345u;
        for (int k = 0; k < w * h; ++k) {
            state = state * 1664525u + 1013904223u;
            image.depth.push_back(state % 7 == 0 ? kNoSurface : 0.5f + float(state >> 8) / float(1u << 24) * 20.0f);
        }
        const DepthImage m = depthBlockMinimum(image, kSkipBlock, 1);
        ASSERT_EQ(m.width, w / kSkipBlock);
        ASSERT_EQ(m.height, h / kSkipBlock);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int bx = std::min(x / kSkipBlock, m.width - 1), by = std::min(y / kSkipBlock, m.height - 1);
                const float value = m.at(bx, by);
                for (int j = std::max(0, y - kSkipSteps); j <= std::min(h - 1, y + kSkipSteps); ++j)
                    for (int i = std::max(0, x - kSkipSteps); i <= std::min(w - 1, x + kSkipSteps); ++i)
                        ASSERT_GE(image.at(i, j), value) << "from " << x << ", " << y << " to " << i << ", " << j;
            }
        for (int by = 0; by < m.height; ++by)
            for (int bx = 0; bx < m.width; ++bx) {
                const float value = m.at(bx, by);
                bool reached = false;
                for (int j = 0; j < h && !reached; ++j)
                    for (int i = 0; i < w && !reached; ++i) reached = image.at(i, j) == value;
                EXPECT_TRUE(reached) << bx << ", " << by;
            }
    }
    // Plain block minima (dilate 0) as the lower MIP levels hold them.
    DepthImage ramp{4, 4, {}};
    for (int k = 0; k < 16; ++k) ramp.depth.push_back(float(k));
    const DepthImage half = depthBlockMinimum(ramp, 2, 0);
    EXPECT_EQ(half.depth, (std::vector<float>{0.0f, 2.0f, 8.0f, 10.0f}));
    EXPECT_THROW(depthBlockMinimum(ramp, 8, 1), Error);  // no whole block
    EXPECT_THROW(depthBlockMinimum(ramp, 0, 0), Error);
    EXPECT_THROW(depthBlockMinimum(ramp, 2, -1), Error);
}

}  // namespace
}  // namespace cavewall::walls
