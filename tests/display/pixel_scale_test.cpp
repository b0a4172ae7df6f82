// Pixels per radian and per unit of error (display/pixel_scale.h), checked against the ray
// geometry it summarises: turning a ray by a tiny angle and measuring where it hits.
#include "display/pixel_scale.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace cavewall::display {
namespace {

// cave4's front wall (3 m x 3 m at z = -1.5, floor to 3 m) and an eye off its centre: 1.8 m
// in front, 0.4 m right of and 0.3 m below the centre.
const ScreenQuad kFrontWall{{-1.5, 0, -1.5}, {1.5, 0, -1.5}, {-1.5, 3, -1.5}};
const glm::dvec3 kEye{0.4, 1.2, 0.3};
constexpr DepthRange kNearFar{0.05, 1000.0};
constexpr int kSidePixels = 1024;

// The same 3 m x 3 m screen turned and moved to a general position, so that no dot product
// below is trivially a coordinate.
ScreenQuad tilted() {
    const glm::dmat3 r = glm::mat3_cast(glm::angleAxis(0.7, glm::normalize(glm::dvec3(0.3, 1.0, -0.2))));
    const glm::dvec3 o(2.0, 0.5, -1.0);
    return {o + r * (kFrontWall.lowerLeft - kEye), o + r * (kFrontWall.lowerRight - kEye), o + r * (kFrontWall.upperLeft - kEye)};
}
const glm::dvec3 kTiltedEye{2.0, 0.5, -1.0};  // where kEye went

std::array<glm::dvec3, 4> corners(const ScreenQuad& s) {
    return {s.lowerLeft, s.lowerRight, s.upperLeft, s.lowerRight + s.upperLeft - s.lowerLeft};
}

TEST(PixelScale, ViewScreenIsTheScreenInTheViewFrame) {
    const ScreenQuad quads[] = {kFrontWall, tilted()};
    const glm::dvec3 eyes[] = {kEye, kTiltedEye};
    for (int i = 0; i < 2; ++i) {
        SCOPED_TRACE(i == 0 ? "front wall" : "tilted screen");
        const ScreenQuad& q = quads[i];
        const OffAxisFrustum f = offAxisFrustum(q, eyes[i], kNearFar);
        ASSERT_EQ(f.guard, EyeGuard::None);
        const ViewScreen s = viewScreen(f, {kSidePixels, kSidePixels});
        // The view frame has the eye at the origin and the screen's right, up and normal as its
        // axes: a corner's view coordinates are its offsets from the eye along them.
        const glm::dvec3 right = glm::normalize(q.lowerRight - q.lowerLeft);
        const glm::dvec3 up = glm::normalize(q.upperLeft - q.lowerLeft);
        const glm::dvec3 normal = glm::cross(right, up);
        const glm::dvec3 upperRight = q.lowerRight + q.upperLeft - q.lowerLeft;
        EXPECT_NEAR(s.left, glm::dot(q.lowerLeft - eyes[i], right), 1e-9);
        EXPECT_NEAR(s.bottom, glm::dot(q.lowerLeft - eyes[i], up), 1e-9);
        EXPECT_NEAR(s.right, glm::dot(upperRight - eyes[i], right), 1e-9);
        EXPECT_NEAR(s.top, glm::dot(upperRight - eyes[i], up), 1e-9);
        EXPECT_NEAR(s.distance, glm::dot(eyes[i] - q.lowerLeft, normal), 1e-9);
        // 3 m over 1024 pixels either way.
        EXPECT_NEAR(s.pixelSize, 3.0 / kSidePixels, 1e-15);
    }
    // For the front wall the numbers are plain: the eye is 1.9 m from the left edge, 1.1 m from
    // the right, 1.2 m above the floor, 1.8 m below the top and 1.8 m in front.
    const ViewScreen s = viewScreen(offAxisFrustum(kFrontWall, kEye, kNearFar), {kSidePixels, kSidePixels});
    EXPECT_NEAR(s.left, -1.9, 1e-9);
    EXPECT_NEAR(s.right, 1.1, 1e-9);
    EXPECT_NEAR(s.bottom, -1.2, 1e-9);
    EXPECT_NEAR(s.top, 1.8, 1e-9);
    EXPECT_NEAR(s.distance, 1.8, 1e-9);
}

TEST(PixelScale, AScreenRectangleAndItsFrustumGiveTheSameScreen) {
    // The rectangle-and-eye form (used for the walls' error in pixels) and the frustum form
    // (used by the renderer) describe one screen; within 1 mm of the plane both keep 1 mm.
    const ScreenQuad quads[] = {kFrontWall, tilted(), kFrontWall};
    const glm::dvec3 eyes[] = {kEye, kTiltedEye, glm::dvec3(0.2, 1.4, -1.5 + 1e-4)};
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        const ViewScreen a = viewScreen(quads[i], eyes[i], {1920, 1080});
        const ViewScreen b = viewScreen(offAxisFrustum(quads[i], eyes[i], kNearFar), {1920, 1080});
        EXPECT_NEAR(a.left, b.left, 1e-9);
        EXPECT_NEAR(a.right, b.right, 1e-9);
        EXPECT_NEAR(a.bottom, b.bottom, 1e-9);
        EXPECT_NEAR(a.top, b.top, 1e-9);
        EXPECT_NEAR(a.distance, b.distance, 1e-12);
        EXPECT_NEAR(a.pixelSize, b.pixelSize, 1e-15);
        EXPECT_NEAR(maxPixelsPerRadian(a), maxPixelsPerRadian(b), 1e-9 * maxPixelsPerRadian(b));
    }
}

TEST(PixelScale, PixelSizeIsTheSmallerOfWidthAndHeightPerPixel) {
    const OffAxisFrustum f = offAxisFrustum(kFrontWall, kEye, kNearFar);
    // 3 m over 1920 px across is finer than 3 m over 1080 px up: 1.5625 mm.
    EXPECT_NEAR(viewScreen(f, {1920, 1080}).pixelSize, 3.0 / 1920, 1e-15);
    EXPECT_NEAR(viewScreen(f, {800, 1200}).pixelSize, 3.0 / 1200, 1e-15);
    EXPECT_NEAR(viewScreen(f, {512, 512}).pixelSize, 3.0 / 512, 1e-15);
}

TEST(PixelScale, WholeScreenMaximumIsAtTheFarthestCorner) {
    const ScreenQuad quads[] = {kFrontWall, tilted()};
    const glm::dvec3 eyes[] = {kEye, kTiltedEye};
    for (int i = 0; i < 2; ++i) {
        SCOPED_TRACE(i == 0 ? "front wall" : "tilted screen");
        const ViewScreen s = viewScreen(offAxisFrustum(quads[i], eyes[i], kNearFar), {kSidePixels, kSidePixels});
        // r_max: the eye's distance to its farthest corner, straight from the frame positions.
        double r2 = 0.0;
        for (const glm::dvec3& c : corners(quads[i])) r2 = std::max(r2, glm::dot(c - eyes[i], c - eyes[i]));
        const double h = 1.8, p = 3.0 / kSidePixels;
        EXPECT_NEAR(maxPixelsPerRadian(s), r2 / (h * p), 1e-9 * r2 / (h * p));
    }
    // Front wall: the farthest corner is the upper left, (-1.9, 1.8) from the eye's foot point:
    // r^2 = 1.9^2 + 1.8^2 + 1.8^2 = 10.09.
    const ViewScreen s = viewScreen(offAxisFrustum(kFrontWall, kEye, kNearFar), {kSidePixels, kSidePixels});
    EXPECT_NEAR(maxPixelsPerRadian(s), 10.09 / (1.8 * 3.0 / kSidePixels), 1e-6);
}

// Where the ray from the eye (view origin) along `d` meets the screen plane z = -h.
glm::dvec3 hit(const ViewScreen& s, glm::dvec3 d) { return d * (s.distance / -d.z); }

// Pixels the hit point of the ray along unit `u` moves when the ray turns by `angle` about the
// unit axis `axis` (perpendicular to u).
double movedPixels(const ViewScreen& s, glm::dvec3 u, glm::dvec3 axis, double angle) {
    const glm::dvec3 turned = u * std::cos(angle) + glm::cross(axis, u) * std::sin(angle);
    return glm::length(hit(s, turned) - hit(s, u)) / s.pixelSize;
}

// The eight corners of a view-space box.
std::vector<glm::dvec3> boxCorners(glm::dvec3 lo, glm::dvec3 hi) {
    std::vector<glm::dvec3> out;
    for (int i = 0; i < 8; ++i) out.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    return out;
}

// The screen rectangle where the box's points can appear (projections' bounds clipped to the
// screen), computed here again; false when empty.
bool region(const ViewScreen& s, const std::vector<glm::dvec3>& points, double& x0, double& x1, double& y0,
            double& y1) {
    x0 = y0 = std::numeric_limits<double>::infinity();
    x1 = y1 = -x0;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 q = hit(s, p);
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
    }
    x0 = std::max(x0, s.left);
    x1 = std::min(x1, s.right);
    y0 = std::max(y0, s.bottom);
    y1 = std::min(y1, s.top);
    return x0 <= x1 && y0 <= y1;
}

TEST(PixelScale, NoTinyTurnMovesAHitFartherThanTheBoundAndTheFarCornerReachesIt) {
    const ViewScreen s = viewScreen(offAxisFrustum(kFrontWall, kEye, kNearFar), {kSidePixels, kSidePixels});
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
    // Small enough that the second-order growth of the movement (relative d tan(incidence),
    // below 2e-8 here) stays far inside the 1e-6 slack, large enough that double rounding of
    // the hit points (~1e-16 m against movements of ~1e-8 m) does too.
    const double d = 1e-8;
    int boxes = 0, beside = 0;
    for (int b = 0; b < 200; ++b) {
        const glm::dvec3 centre(3 * sym(rng), 1.5 * sym(rng) + 0.3, -0.3 - 5 * unit(rng));
        const glm::dvec3 half(0.05 + unit(rng), 0.05 + unit(rng), 0.05 + 0.2 * unit(rng));
        const std::vector<glm::dvec3> points = boxCorners(centre - half, centre + half);
        if (centre.z + half.z >= 0.0) continue;  // only boxes wholly in front here
        const double bound = maxPixelsPerRadian(s, points);
        double x0, x1, y0, y1;
        if (!region(s, points, x0, x1, y0, y1)) {
            ++beside;
            EXPECT_EQ(bound, 0.0) << "box centre " << centre.x << ", " << centre.y << ", " << centre.z;
            continue;
        }
        ++boxes;
        SCOPED_TRACE("box " + std::to_string(b));
        ASSERT_GT(bound, 0.0);
        for (int k = 0; k < 50; ++k) {
            const glm::dvec3 onScreen(x0 + (x1 - x0) * unit(rng), y0 + (y1 - y0) * unit(rng), -s.distance);
            const glm::dvec3 u = glm::normalize(onScreen);
            const glm::dvec3 axis = glm::normalize(glm::cross(u, glm::dvec3(sym(rng), sym(rng), sym(rng))));
            const double moved = movedPixels(s, u, axis, d);
            EXPECT_LE(moved, bound * d * (1 + 1e-6)) << "ray " << u.x << ", " << u.y << ", " << u.z;
        }
        // The region's corner farthest from the foot point: turning there in the incidence plane
        // (about the axis normal x u) moves the hit at r^2 / (h p) pixels per radian, the bound.
        const double farX = std::abs(x0) > std::abs(x1) ? x0 : x1, farY = std::abs(y0) > std::abs(y1) ? y0 : y1;
        const glm::dvec3 far(farX, farY, -s.distance);
        const glm::dvec3 u = glm::normalize(far);
        const double r = glm::length(far);
        for (double sign : {1.0, -1.0}) {
            const double moved = movedPixels(s, u, glm::normalize(glm::cross(glm::dvec3(0, 0, 1), u)), sign * d);
            EXPECT_NEAR(moved / (bound * d), 1.0, 1e-3) << "turning in the incidence plane at the far corner";
        }
        // Across the incidence plane the hit moves at r / p pixels per radian (header).
        const glm::dvec3 across = glm::normalize(glm::cross(u, glm::cross(glm::dvec3(0, 0, 1), u)));
        if (far.x != 0.0 || far.y != 0.0) {
            EXPECT_NEAR(movedPixels(s, u, across, d) / (r / s.pixelSize * d), 1.0, 1e-6) << "turning across it";
        }
    }
    // Not a trivial pass: most boxes were seen, some were beside the screen (measured: 162 and
    // 38), and the random rays came close to the bound (largest moved / (bound d): 0.996).
    EXPECT_GT(boxes, 100);
    EXPECT_GT(beside, 5);
}

TEST(PixelScale, BoxesBesideBehindAndAround) {
    const ViewScreen s = viewScreen(offAxisFrustum(kFrontWall, kEye, kNearFar), {kSidePixels, kSidePixels});
    const double whole = maxPixelsPerRadian(s);
    struct Case {
        const char* name;
        glm::dvec3 lo, hi;
        double expected;
    };
    // The screen spans x in [-1.9, 1.1], y in [-1.2, 1.8] at z = -1.8 (view frame).
    const Case cases[] = {
        // The least projected x is 5 * 1.8 / 3 = 3 > 1.1; the least projected y 4 * 1.8 / 2 =
        // 3.6 > 1.8.
        {"right of the screen", {5, -0.5, -3}, {6, 0.5, -2}, 0.0},
        {"above the screen", {-0.5, 4, -2}, {0.5, 5, -1.9}, 0.0},
        {"a corner behind the eye", {-0.5, -0.5, -2}, {0.5, 0.5, 0.5}, whole},
        {"a face on the eye plane", {-0.5, -0.5, -2}, {0.5, 0.5, 0.0}, whole},
        {"around the eye", {-1, -1, -1}, {1, 1, 1}, whole},
        // A box whose projection covers the screen gets the whole screen's value.
        {"covering the screen", {-4, -4, -1.0}, {4, 4, -0.5}, whole},
        // Straight ahead, tiny and far: the foot point, where a radian covers h / p pixels.
        {"at the foot point", {-1e-9, -1e-9, -100}, {1e-9, 1e-9, -99}, s.distance / s.pixelSize},
        // On the screen plane (z = -h) points project onto themselves: the region is
        // [0.45, 0.9]^2, its far corner (0.9, 0.9), r^2 = 0.81 + 0.81 + 3.24 = 4.86.
        {"up and right", {0.45, 0.45, -1.8}, {0.9, 0.9, -1.8}, 4.86 / (s.distance * s.pixelSize)},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::vector<glm::dvec3> points = boxCorners(c.lo, c.hi);
        EXPECT_NEAR(maxPixelsPerRadian(s, points), c.expected, 1e-9 * std::max(1.0, c.expected));
    }
    // A single point behind the eye among points in front is enough for the whole screen.
    const std::vector<glm::dvec3> mixed = {{0, 0, -2}, {0.1, 0.1, -2.5}, {0, 0, 1e-3}};
    EXPECT_EQ(maxPixelsPerRadian(s, mixed), whole);
}

// A wall's quad (the walls' error in pixels, walkthrough/frame_planner.h) counts only where its
// part in front of the eye can appear.
TEST(PixelScale, InFrontCountsOnlyThePartBeforeTheEye) {
    // cave4's front screen from its centre axis at 1.5 m: x and y in [-1.5, 1.5], 3 / 1024 m pixels.
    const ViewScreen centred{-1.5, 1.5, -1.5, 1.5, 1.5, 3.0 / kSidePixels};
    // A wall seen head-on, small and 10 m away on the axis: it projects to [-0.015, 0.015]^2 by
    // 1.5 / 10, so a radian covers r^2 / (h p) = (2.25 + 2 * 0.015^2) / (1.5 * 3 / 1024) = 512.15
    // pixels (h / p = 512 at the foot point): 10 degrees are 89.38 pixels, 8.94 a degree.
    const std::vector<glm::dvec3> headOn = {{-0.1, -0.1, -10}, {0.1, -0.1, -10}, {-0.1, 0.1, -10}, {0.1, 0.1, -10}};
    const double perRadian = (2.25 + 2 * 0.015 * 0.015) / (1.5 * 3.0 / kSidePixels);
    EXPECT_NEAR(maxPixelsPerRadianInFront(centred, headOn), perRadian, 1e-9 * perRadian);
    EXPECT_NEAR(glm::radians(10.0) * perRadian, 89.38, 0.01);
    // A wall crossing the eye's plane, eye 1 m right of the centre (x in [-2.5, 0.5]): its left
    // edge (x = -1, z = -3) projects to x = -0.5, and it crosses z = 0 at x = 0.5 (t = 0.75
    // from z = -3 to 1), whose rays point off to +x beyond the screen: x in [-0.5, 0.5], y all
    // of [-1.5, 1.5]. Far corner (0.5, 1.5): r^2 = 0.25 + 2.25 + 2.25 = 4.75. The whole
    // screen's far corner (-2.5, 1.5) gives 10.75, what maxPixelsPerRadian says of any point
    // behind the eye.
    const ViewScreen offCentre{-2.5, 0.5, -1.5, 1.5, 1.5, 3.0 / kSidePixels};
    const std::vector<glm::dvec3> crossing = {{-1, -0.5, -3}, {-1, 0.5, -3}, {1, -0.5, 1}, {1, 0.5, 1}};
    const double part = 4.75 / (1.5 * 3.0 / kSidePixels);
    EXPECT_NEAR(maxPixelsPerRadianInFront(offCentre, crossing), part, 1e-9 * part);
    EXPECT_NEAR(maxPixelsPerRadian(offCentre, crossing), 10.75 / (1.5 * 3.0 / kSidePixels), 1e-6);
    // All behind the eye, or beside the screen: nothing of it shows.
    const std::vector<glm::dvec3> behind = {{-1, -1, 0.5}, {1, -1, 0.5}, {-1, 1, 2}, {1, 1, 2}};
    EXPECT_EQ(maxPixelsPerRadianInFront(centred, behind), 0.0);
    const std::vector<glm::dvec3> beside = {{5, -0.5, -3}, {6, -0.5, -3}, {5, 0.5, -3}, {6, 0.5, 1}};
    EXPECT_EQ(maxPixelsPerRadianInFront(centred, beside), 0.0);
    // Wholly in front it is maxPixelsPerRadian's value.
    const std::vector<glm::dvec3> inFront = {{0.45, 0.45, -1.5}, {0.9, 0.45, -1.5}, {0.45, 0.9, -2}, {0.9, 0.9, -2}};
    EXPECT_EQ(maxPixelsPerRadianInFront(centred, inFront), maxPixelsPerRadian(centred, inFront));
}

TEST(PixelScale, NearestDistanceIsZeroInsideAndExactOutside) {
    struct Case {
        const char* name;
        std::vector<glm::dvec3> points;
        double expected;
    };
    const Case cases[] = {
        {"eye inside", {{-1, -1, -1}, {1, 2, 3}}, 0.0},
        {"eye on a face", {{0, -1, -1}, {1, 1, 1}}, 0.0},
        // Nearest point (1, 0, -2): only x and z are outside the slab ranges.
        {"beside a face's edge", {{1, -1, -3}, {2, 1, -2}}, std::sqrt(5.0)},
        // Nearest point is the corner (1, 3, -5).
        {"off a corner", {{2, 4, -6}, {1, 3, -5}}, std::sqrt(35.0)},
        {"in front of a face", {{-1, -1, -7}, {1, 1, -4}}, 4.0},
        {"one point", {{3, 4, 0}}, 5.0},
        // The box around the points, x in [1, 3], y and z in [-5, 5]: its face x = 1 is 1 away,
        // though the nearest of the points themselves, (2, 0, 0), is 2 away.
        {"box around scattered points", {{1, 5, 5}, {3, -5, -5}, {2, 0, 0}}, 1.0},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_NEAR(nearestDistance(c.points), c.expected, 1e-12);
    }
    // Against the definition: no point of a random box is nearer than the answer, and the
    // origin clamped into the box (the nearest point) is exactly that far.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> sym(-3.0, 3.0), unit(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 a(sym(rng), sym(rng), sym(rng)), b(sym(rng), sym(rng), sym(rng));
        const std::vector<glm::dvec3> points = {a, b};
        const glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
        const double got = nearestDistance(points);
        EXPECT_NEAR(got, glm::length(glm::clamp(glm::dvec3(0.0), lo, hi)), 1e-12);
        for (int k = 0; k < 20; ++k) {
            const glm::dvec3 p = lo + (hi - lo) * glm::dvec3(unit(rng), unit(rng), unit(rng));
            EXPECT_LE(got, glm::length(p) + 1e-12);
        }
    }
}

// The largest eigenvalue of a symmetric matrix by cyclic Jacobi rotations (independent of the
// closed form under test).
double largestEigenvalue(glm::dmat3 a) {
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = a[1][0] * a[1][0] + a[2][0] * a[2][0] + a[2][1] * a[2][1];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-40 * diag || off == 0.0) break;
        for (auto [p, q] : {std::array{0, 1}, std::array{0, 2}, std::array{1, 2}}) {
            if (a[q][p] == 0.0) continue;
            const double theta = (a[q][q] - a[p][p]) / (2.0 * a[q][p]);
            const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
            const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
            glm::dmat3 j(1.0);  // j[column][row]
            j[p][p] = c;
            j[q][q] = c;
            j[q][p] = s;
            j[p][q] = -s;
            a = glm::transpose(j) * a * j;
        }
    }
    EXPECT_LE(a[1][0] * a[1][0] + a[2][0] * a[2][0] + a[2][1] * a[2][1],
              1e-30 * (a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2]) + 1e-300)
        << "Jacobi did not converge";
    return std::max({a[0][0], a[1][1], a[2][2]});
}

double referenceStretch(const glm::dmat3& m) {
    return std::sqrt(std::max(0.0, largestEigenvalue(glm::transpose(m) * m)));
}

glm::dmat3 diag(double a, double b, double c) {
    return {glm::dvec3(a, 0, 0), glm::dvec3(0, b, 0), glm::dvec3(0, 0, c)};
}

glm::dmat3 rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return glm::mat3_cast(glm::normalize(glm::dquat(g(rng), g(rng), g(rng), g(rng))));
}

TEST(PixelScale, MaxStretchOfKnownMatrices) {
    std::mt19937_64 rng(3);
    struct Case {
        const char* name;
        glm::dmat3 m;
        double expected;
    };
    const glm::dmat3 r1 = rotation(rng), r2 = rotation(rng);
    const glm::dvec3 u(1, 2, 2), v(0, 3, 4);  // |u| = 3, |v| = 5
    const Case cases[] = {
        {"identity", glm::dmat3(1.0), 1.0},
        {"rotation", r1, 1.0},  // rotations keep lengths
        {"reflection", diag(-1, 1, 1) * r1, 1.0},
        // A diagonal matrix stretches its axes by the absolute diagonal entries, no more.
        {"diag(1, 2, 3)", diag(1, 2, 3), 3.0},
        {"diag(-4, 2, 3)", diag(-4, 2, 3), 4.0},
        // Singular values are kept by rotations on either side.
        {"rotated diag(1, 2, 3)", r1 * diag(1, 2, 3) * r2, 3.0},
        {"uniform scale 2.5, rotated", 2.5 * r1, 2.5},
        {"two equal largest singular values", r1 * diag(2, 2, 1) * r2, 2.0},
        {"nearly equal", r1 * diag(2, 2 + 1e-9, 2 - 1e-9) * r2, 2 + 1e-9},
        {"spread 1e6 to 1e-6", r1 * diag(1e-6, 1, 1e6) * r2, 1e6},
        // u v^T stretches v's direction by |u| |v| and sends the rest to 0.
        {"rank 1", glm::outerProduct(u, v), 15.0},
        {"zero", glm::dmat3(0.0), 0.0},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        // Closed form and the header's "a few ulps up": within 1e-11 relative of the exact value.
        EXPECT_NEAR(maxStretch(c.m), c.expected, 1e-11 * c.expected + 1e-300);
        EXPECT_GE(maxStretch(c.m), c.expected * (1 - 1e-15)) << "the bound is never below the stretch";
    }
}

TEST(PixelScale, MaxStretchOfRandomMatricesIsTheLargestStretch) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> sym(-1.0, 1.0), exponent(-3.0, 3.0);
    std::normal_distribution<double> g;
    for (int i = 0; i < 300; ++i) {
        SCOPED_TRACE(i);
        glm::dmat3 m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = sym(rng);
        m *= std::pow(10.0, exponent(rng));
        const double got = maxStretch(m);
        double largest = 0.0;
        for (int k = 0; k < 1000; ++k) {
            const glm::dvec3 v = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
            largest = std::max(largest, glm::length(m * v));
        }
        EXPECT_GE(got, largest) << "a unit vector is stretched more than the bound";
        const double reference = referenceStretch(m);
        EXPECT_NEAR(got, reference, 1e-9 * reference) << "Jacobi gives " << reference;
        // The random search comes close from below (1000 directions: within a few per cent).
        EXPECT_GT(largest, 0.9 * reference);
    }
}

TEST(PixelScale, PixelsPerDegreeOfACaveWallFromItsCentre) {
    // cave4's front wall (3 m wide) from the middle of the CAVE, 1.5 m in front of it: the
    // nearest screen point is the foot point, 1.5 m away, where one radian covers 1.5 m, i.e.
    // 1.5 / (3 / 1024) = 512 pixels: 512 * pi / 180 = 8.936 pixels per degree. At 1920 pixels,
    // 960 per radian, 16.755 per degree.
    const glm::dvec3 centre{0.0, 1.5, 0.0};
    EXPECT_NEAR(minPixelsPerDegree(viewScreen(kFrontWall, centre, {1024, 1024})), 8.936, 1e-3);
    EXPECT_NEAR(minPixelsPerDegree(viewScreen(kFrontWall, centre, {1920, 1920})), 16.755, 1e-3);
    // From the frustum's side the same.
    const OffAxisFrustum f = offAxisFrustum(kFrontWall, centre, kNearFar);
    EXPECT_NEAR(minPixelsPerDegree(viewScreen(f, {1024, 1024})), 8.936, 1e-3);
}

// The pixels per degree at screen point p (view frame, on the plane z = -h) along screen
// direction `step`: one pixel step's visual angle, measured from the two rays.
double measuredPixelsPerDegree(const ViewScreen& s, glm::dvec2 p, glm::dvec2 step) {
    const glm::dvec3 a(p, -s.distance), b(p + step * s.pixelSize * 1e-3, -s.distance);
    // atan2 of the cross and dot products: acos loses half the digits of so small an angle.
    const double radians = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
    return 1e-3 / (radians * 180.0 / std::numbers::pi);
}

TEST(PixelScale, MinPixelsPerDegreeIsTheLeastAnywhereOnTheScreen) {
    // Over a grid of screen points and directions, no pixel looks larger than the bound says,
    // and the nearest point (here beside the screen for the second eye) comes within 0.1 % of it.
    const glm::dvec3 eyes[] = {kEye, {2.4, 3.5, 0.3}};  // in front; beside and above the wall
    for (const glm::dvec3& eye : eyes) {
        SCOPED_TRACE(eye.x);
        const ViewScreen s = viewScreen(kFrontWall, eye, {kSidePixels, kSidePixels});
        const double bound = minPixelsPerDegree(s);
        double least = std::numeric_limits<double>::infinity();
        constexpr int kSteps = 60;
        for (int i = 0; i <= kSteps; ++i)
            for (int j = 0; j <= kSteps; ++j)
                for (int d = 0; d < 36; ++d) {
                    const glm::dvec2 p(s.left + (s.right - s.left) * i / kSteps,
                                       s.bottom + (s.top - s.bottom) * j / kSteps);
                    const double angle = d * std::numbers::pi / 36;  // 5° steps over a half turn
                    least = std::min(least, measuredPixelsPerDegree(s, p, {std::cos(angle), std::sin(angle)}));
                }
        EXPECT_GE(least, bound * (1 - 1e-6));
        EXPECT_LE(least, bound * 1.001);
    }
}

}  // namespace
}  // namespace cavewall::display
