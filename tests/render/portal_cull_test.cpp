// Portal culling (render/portal_cull.h): what a portal shows, that the test never culls a box
// some ray from the eye through the portal reaches, and chains and sets of portals.
#include "render/portal_cull.h"

#include <gtest/gtest.h>

#include <random>

namespace cavewall::render {
namespace {

// A doorway 1 m wide and 2 m high in the plane z = 0, around x = 0.
const display::ScreenQuad kDoor{{-0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}, {-0.5, 2.0, 0.0}};
const glm::dvec3 kEye{0.0, 1.6, 2.0};

scenes::Bounds box(glm::dvec3 lo, glm::dvec3 hi) {
    scenes::Bounds b;
    b.add(lo);
    b.add(hi);
    return b;
}

TEST(PortalCull, ShowsWhatLiesBehindTheDoorwayAndNotBesideIt) {
    EXPECT_TRUE(seenThrough(box({-0.2, 0.0, -3.0}, {0.2, 1.0, -2.0}), kEye, kDoor));
    // Through a 1 m door 2 m away, 3 m behind it the cone spans x in [-1.25, 1.25].
    EXPECT_TRUE(seenThrough(box({1.2, 0.0, -3.0}, {1.5, 1.0, -2.9}), kEye, kDoor));
    EXPECT_FALSE(seenThrough(box({1.3, 0.0, -3.0}, {1.5, 1.0, -2.99}), kEye, kDoor));
    EXPECT_FALSE(seenThrough(box({5.0, 0.0, -3.0}, {6.0, 1.0, -2.0}), kEye, kDoor));
    // Above the lintel, seen from below it.
    EXPECT_FALSE(seenThrough(box({-0.2, 4.0, -6.0}, {0.2, 5.0, -5.0}), kEye, kDoor));
    // From behind the doorway (its back side) it is open: everything is seen through it.
    EXPECT_TRUE(seenThrough(box({5.0, 0.0, -3.0}, {6.0, 1.0, -2.0}), {0.0, 1.6, -2.0}, kDoor));
}

TEST(PortalCull, WhatLiesWhollyInFrontOfTheDoorwayIsNotSeenThroughIt) {
    EXPECT_FALSE(seenThrough(box({5.0, 0.0, 1.0}, {6.0, 1.0, 2.0}), kEye, kDoor));   // beside the eye
    EXPECT_FALSE(seenThrough(box({-0.1, 0.5, 0.5}, {0.1, 1.0, 1.0}), kEye, kDoor));  // before the door
    EXPECT_TRUE(seenThrough(box({-0.1, 0.5, -0.5}, {0.1, 1.0, 0.5}), kEye, kDoor));  // through it
    EXPECT_TRUE(seenThrough(box({-0.1, 0.5, -0.5}, {0.1, 1.0, 0.0}), kEye, kDoor));  // touching it
    EXPECT_FALSE(seenThrough(box({5.0, 0.0, -1.0}, {6.0, 1.0, 0.1}), kEye, kDoor));  // across, aside
}

TEST(PortalCull, AnEyeOnThePlaneOrADegeneratePortalCullsNothing) {
    const scenes::Bounds aside = box({5.0, 0.0, -3.0}, {6.0, 1.0, -2.0});
    EXPECT_TRUE(seenThrough(aside, {3.0, 1.0, 0.5 * kPortalEyeClearance}, kDoor));
    EXPECT_FALSE(seenThrough(aside, {3.0, 1.0, 2.0 * kPortalEyeClearance}, kDoor));
    const display::ScreenQuad flat{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}};
    EXPECT_TRUE(seenThrough(aside, kEye, flat));
    EXPECT_TRUE(seenThrough(scenes::Bounds{}, kEye, kDoor));  // empty bounds: not decided here
}

// Conservative: a box culled for an eye contains no point whose segment to the eye crosses the
// portal, over random eyes, portals and boxes.
TEST(PortalCull, NeverCullsABoxARayThroughThePortalReaches) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto vec = [&](double scale) { return glm::dvec3(u(rng), u(rng), u(rng)) * scale; };
    int culled = 0, reached = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::dvec3 o = vec(2.0), a = vec(1.5), b = vec(1.5);
        const display::ScreenQuad q{o, o + a, o + b};
        const glm::dvec3 eye = vec(4.0), centre = vec(6.0), half = glm::abs(vec(1.5));
        const scenes::Bounds bx = box(centre - half, centre + half);
        if (seenThrough(bx, eye, q)) continue;
        ++culled;
        const glm::dvec3 n = glm::cross(a, b);
        for (int k = 0; k < 200; ++k) {
            const glm::dvec3 p = centre + half * glm::dvec3(u(rng), u(rng), u(rng));
            const double de = glm::dot(n, eye - o), dp = glm::dot(n, p - o);
            if (de * dp >= 0.0) continue;  // no crossing
            const glm::dvec3 x = eye + (p - eye) * (de / (de - dp));
            // x = o + s a + t b: solve in the portal's plane by least squares.
            const glm::dmat2 g(glm::dot(a, a), glm::dot(a, b), glm::dot(a, b), glm::dot(b, b));
            const glm::dvec2 st = glm::inverse(g) * glm::dvec2(glm::dot(x - o, a), glm::dot(x - o, b));
            if (st.x > 1e-9 && st.x < 1 - 1e-9 && st.y > 1e-9 && st.y < 1 - 1e-9) ++reached;
        }
    }
    EXPECT_GT(culled, 200);  // the test did cull
    EXPECT_EQ(reached, 0);
}

// With slack, a doorway stands for one anywhere within that distance of it: 3 m behind the
// door, the cone through the door grown by 0.3 m and moved 0.3 m forward spans |x| < 2.35.
TEST(PortalCull, SlackWidensTheDoorwayAcrossAndAlongItsPlane) {
    const scenes::Bounds past = box({1.3, 0.0, -3.0}, {1.5, 1.0, -2.99});
    PortalSets sets{{kDoor}, 0.3, {{0}}, {{0}}, {0}};
    EXPECT_FALSE(seenThrough(past, kEye, kDoor));
    EXPECT_TRUE(PortalView(sets, kEye).visible(0, past));
    EXPECT_FALSE(PortalView(sets, kEye).visible(0, box({2.5, 0.0, -3.0}, {2.7, 1.0, -2.99})));
    // An eye within the slack of the doorway's plane sees everything through it.
    EXPECT_TRUE(PortalView(sets, {0.0, 1.6, 0.2}).visible(0, box({9.0, 0.0, -3.0}, {9.5, 1.0, -2.99})));
}

// Conservative with slack: no line of sight through the slab of the grown doorway, at any
// depth within the slack, reaches a culled box.
TEST(PortalCull, SlackNeverCullsWhatALineThroughTheSlabReaches) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double slack = 0.3;
    const PortalSets sets{{kDoor}, slack, {{0}}, {{0}}, {0}};
    int culled = 0, reached = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::dvec3 eye(2.0 * u(rng), 1.6 + u(rng), 0.35 + 2.0 * std::abs(u(rng)));
        const PortalView view(sets, eye);
        // A point of the slab: x in the door grown by the slack, y likewise, z within it.
        const glm::dvec3 through(0.8 * u(rng), 1.0 + 1.3 * u(rng), slack * u(rng));
        const glm::dvec3 p = eye + (through - eye) * (1.0 + 4.0 * std::abs(u(rng)));
        const scenes::Bounds bx = box(p - 0.01, p + 0.01);
        const scenes::Bounds aside = box(glm::dvec3(u(rng) * 6.0, 1.0, -4.0), glm::dvec3(u(rng) * 6.0 + 0.1, 1.1, -3.9));
        culled += view.visible(0, aside) ? 0 : 1;
        reached += view.visible(0, bx) ? 0 : 1;
    }
    EXPECT_GT(culled, 200);  // the test did cull
    EXPECT_EQ(reached, 0);
}

TEST(PortalCull, AChainShowsWhatEveryPortalShowsAndASetWhatAnyChainDoes) {
    // A second doorway 4 m behind the first, 3 m to the side: nothing is seen through both.
    const display::ScreenQuad side{{2.5, 0.0, -4.0}, {3.5, 0.0, -4.0}, {2.5, 2.0, -4.0}};
    const scenes::Bounds ahead = box({-0.2, 0.0, -8.0}, {0.2, 1.0, -7.0});
    PortalSets sets{{kDoor, side}, 0.0, {{0}, {0, 1}, {1}}, {{1}, {1, 2}, {}}, {0, 1, 2, -1}};
    const PortalView view(sets, kEye);
    EXPECT_TRUE(seenThrough(ahead, kEye, kDoor));
    EXPECT_FALSE(seenThrough(ahead, kEye, side));
    EXPECT_FALSE(view.visible(0, ahead));  // through both doorways: no
    EXPECT_FALSE(view.visible(1, ahead));  // through both, or through the side one alone
    sets.sets[1].push_back(0);             // or through the first alone
    EXPECT_TRUE(PortalView(sets, kEye).visible(1, ahead));
    EXPECT_FALSE(view.visible(2, ahead));  // a set without chains shows nothing
    EXPECT_TRUE(view.visible(3, ahead));   // no set: no test
    EXPECT_TRUE(view.visible(4, ahead));   // past objectSet's end: no test
}

}  // namespace
}  // namespace cavewall::render
