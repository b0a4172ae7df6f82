#include "input/navigator.h"
#include "input/pose_math.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::input {
namespace {

constexpr double kDt = 1.0 / 90.0;

// A test world: floor at y = 0, a 0.3 m platform for 5 <= x < 8, a pit (floor at -3) for
// x < -5, and a wall filling the plane x = 10.
class TestWorld : public WorldQuery {
public:
    std::optional<double> floorBelow(const glm::dvec3& p, double maxDrop) const override {
        const double floor = p.x < -5.0 ? -3.0 : (p.x >= 5.0 && p.x < 8.0) ? 0.3 : 0.0;
        if (floor > p.y || p.y - floor > maxDrop) return std::nullopt;
        return floor;
    }
    std::optional<double> castRay(const glm::dvec3& o, const glm::dvec3& d, double maxDistance) const override {
        if (d.x <= 0.0 || o.x >= 10.0) return std::nullopt;
        const double t = (10.0 - o.x) / d.x;
        return t <= maxDistance ? std::optional<double>(t) : std::nullopt;
    }
};

const Pose kHead{{0.0, 1.7, 0.0}, {1, 0, 0, 0}};

Pose handPointing(double yaw, double pitch) { return {{0.2, 1.3, -0.3}, yawPitchRoll(yaw, pitch)}; }

void run(Navigator& nav, double seconds) {
    for (int i = 0; i < std::lround(seconds / kDt); ++i) nav.update(kDt);
}

void press(Navigator& nav, int button, bool down) {
    nav.handle({down ? EventType::ButtonDown : EventType::ButtonUp, 0.0, button, {}});
}

TEST(Navigator, FlyGoesWhereTheWandPointsWithLimitedAcceleration) {
    Navigator nav;
    // Pointing 30° up, straight ahead (-Z).
    nav.setTracking(kHead, handPointing(0.0, M_PI / 6), {});
    press(nav, 0, true);
    run(nav, 0.5);
    // 4 m/s² for 0.5 s: 2 m/s, not yet the 3 m/s top speed; 1 m travelled (at² / 2).
    EXPECT_NEAR(glm::length(nav.velocity()), 2.0, 1e-9);
    EXPECT_NEAR(glm::length(nav.origin()), 0.5 * 4.0 * 0.25, 0.03);
    run(nav, 2.0);
    EXPECT_NEAR(glm::length(nav.velocity()), 3.0, 1e-9);
    // The direction is the wand's: up at 30°, so y / |horizontal| = tan 30°.
    EXPECT_NEAR(nav.origin().y / -nav.origin().z, std::tan(M_PI / 6), 1e-9);
    EXPECT_NEAR(nav.origin().x, 0.0, 1e-12);
    press(nav, 0, false);
    run(nav, 0.5);
    EXPECT_NEAR(glm::length(nav.velocity()), 1.0, 1e-9);  // braking at 4 m/s² too
}

TEST(Navigator, JoystickSetsTheSpeedAndTurnsAboutTheHead) {
    Navigator nav;
    WandState wand;
    wand.joystick = {0.0, 0.55};  // past the 0.1 dead zone: (0.55 - 0.1) / 0.9 = half speed
    nav.setTracking({{0.5, 1.7, 0.5}, {1, 0, 0, 0}}, handPointing(0.0, 0.0), wand);
    run(nav, 2.0);
    EXPECT_NEAR(glm::length(nav.velocity()), 1.5, 1e-9);
    const glm::dvec3 headBefore = glm::dvec3(nav.worldFromCave() * glm::dvec4(0.5, 1.7, 0.5, 1.0));
    wand.joystick = {1.0, 0.0};  // full right: turn right (negative yaw) at 1 rad/s
    nav.setTracking({{0.5, 1.7, 0.5}, {1, 0, 0, 0}}, handPointing(0.0, 0.0), wand);
    const double yaw = nav.yaw();
    nav.update(0.1);
    EXPECT_NEAR(nav.yaw() - yaw, -0.1, 1e-12);
    // Turning alone keeps the head where it is in the world (it moves only by velocity * dt).
    const glm::dvec3 headAfter = glm::dvec3(nav.worldFromCave() * glm::dvec4(0.5, 1.7, 0.5, 1.0));
    EXPECT_LT(glm::distance(headAfter, headBefore + nav.velocity() * 0.1), 0.2);
}

TEST(Navigator, WalkStaysOnTheFloorClimbsStepsAndStopsAtWalls) {
    TestWorld world;
    Navigator nav({}, &world);
    nav.setMode(NavMode::Walk);
    // Pointing 45° up towards +X: walking ignores the pitch and goes along the floor.
    nav.setTracking(kHead, handPointing(-M_PI / 2, M_PI / 4), {});
    press(nav, 0, true);
    run(nav, 2.0);
    EXPECT_NEAR(nav.origin().y, 0.0, 1e-12);
    EXPECT_GT(nav.origin().x, 3.0);
    run(nav, 1.0);  // onto the platform
    ASSERT_GE(nav.origin().x, 5.0);
    EXPECT_NEAR(nav.origin().y, 0.3, 1e-12);  // the step was climbed: eye 1.7 m above the new floor
    run(nav, 5.0);
    // The wall at x = 10 stops the head (at cave x = 0) bodyRadius = 0.3 m before it.
    EXPECT_NEAR(nav.origin().x, 9.7, 1e-9);
    EXPECT_LT(glm::length(nav.velocity()), 1e-9);  // stopped (up to the wand's rounding in z)
    EXPECT_NEAR(nav.origin().y, 0.0, 1e-12);       // past the platform, back on the floor
}

TEST(Navigator, WalkSlidesAlongWalls) {
    TestWorld world;
    Navigator nav({}, &world);
    nav.setMode(NavMode::Walk);
    nav.setWorldFromCave({9.0, 0.0, 0.0}, 0.0);
    // Towards the wall at 45° (+X and -Z): the X part is blocked, the -Z part goes on.
    nav.setTracking(kHead, handPointing(-M_PI / 4, 0.0), {});
    press(nav, 0, true);
    run(nav, 3.0);
    EXPECT_NEAR(nav.origin().x, 9.7, 1e-9);  // stopped bodyRadius before the wall
    EXPECT_LT(nav.origin().z, -2.0);         // but slid along it
    EXPECT_NEAR(nav.velocity().x, 0.0, 1e-12);
    EXPECT_LT(nav.velocity().z, -1.0);
}

TEST(Navigator, WalkFallsIntoPitsWithGravity) {
    TestWorld world;
    Navigator nav({}, &world);
    nav.setMode(NavMode::Walk);
    nav.setWorldFromCave({-4.9, 0.0, 0.0}, 0.0);
    nav.setTracking(kHead, handPointing(M_PI / 2, 0.0), {});  // towards -X
    press(nav, 0, true);
    run(nav, 0.3);
    press(nav, 0, false);
    ASSERT_LT(nav.origin().x, -5.0);
    EXPECT_LT(nav.origin().y, 0.0);   // falling
    EXPECT_GT(nav.origin().y, -3.0);  // not teleported
    run(nav, 2.0);
    EXPECT_NEAR(nav.origin().y, -3.0, 1e-12);  // landed on the pit floor: sqrt(2 * 3 / 9.81) ≈ 0.8 s
}

TEST(Navigator, GrabMovesTheWorldWithTheHand) {
    Navigator nav;
    nav.setMode(NavMode::Grab);
    nav.setWorldFromCave({1.0, 0.0, 2.0}, 0.3);
    const Pose start = handPointing(0.0, 0.0);
    nav.setTracking(kHead, start, {});
    const glm::dvec3 grabbed = glm::dvec3(nav.worldFromCave() * glm::dvec4(start.position, 1.0));
    press(nav, 0, true);
    // Move the hand 0.5 m right and turn it 30° left.
    const Pose moved{start.position + glm::dvec3(0.5, 0.0, 0.0), yawPitchRoll(M_PI / 6, 0.0)};
    nav.setTracking(kHead, moved, {});
    nav.update(kDt);
    // The grabbed world point is still in the hand, and the world turned with it.
    EXPECT_NEAR(glm::distance(glm::dvec3(nav.worldFromCave() * glm::dvec4(moved.position, 1.0)), grabbed), 0.0, 1e-12);
    EXPECT_NEAR(nav.yaw(), 0.3 - M_PI / 6, 1e-12);
    // Released: moving the hand no longer moves the world.
    press(nav, 0, false);
    const glm::dmat4 held = nav.worldFromCave();
    nav.setTracking(kHead, start, {});
    nav.update(kDt);
    EXPECT_EQ(nav.worldFromCave(), held);
}

TEST(Navigator, GuidedFollowsTheRiverWithinSoftBanks) {
    Navigator nav;
    nav.setGuidePath({{0, 0, 0}, {100, 0, 0}});  // the river flows towards +X
    nav.setMode(NavMode::Guided);
    nav.setTracking(kHead, handPointing(0.0, 0.0), {});
    run(nav, 10.0);
    // Carried at the 1 m/s pace; the CAVE's front turned to the flow (yaw -90°, time constant 2 s).
    EXPECT_NEAR(nav.guideDistance(), 10.0, 1e-9);
    EXPECT_NEAR(nav.yaw(), -M_PI / 2, 0.02);
    EXPECT_NEAR(nav.origin().x, 10.0, 0.2);
    // Steer hard to the right bank: the wand points to cave +X, which after the turn is world +Z.
    nav.setTracking(kHead, handPointing(-M_PI / 2, 0.0), {});
    press(nav, 0, true);
    double widest = 0.0;
    for (int i = 0; i < 4 * 90; ++i) {
        nav.update(kDt);
        widest = std::max(widest, std::fabs(nav.origin().z));
    }
    // Free steering within the 2 m corridor, then the bank pushes back: at 3 m/s against a 1 s
    // pull-back the excess settles near 3 m, never running away.
    EXPECT_GT(widest, 3.0);
    EXPECT_LT(widest, 5.5);
    press(nav, 0, false);
    run(nav, 6.0);
    // Let go: pulled back softly to the edge of the corridor; the current kept going.
    EXPECT_LT(std::fabs(nav.origin().z), 2.05);
    EXPECT_GT(std::fabs(nav.origin().z), 1.5);
    EXPECT_NEAR(nav.guideDistance(), 20.0, 1e-9);
    run(nav, 100.0);
    EXPECT_NEAR(nav.guideDistance(), 100.0, 1e-9);  // stops at the end of the path
}

TEST(Navigator, ModesSpeedAndBadInput) {
    Navigator nav;
    EXPECT_EQ(nav.mode(), NavMode::Fly);
    press(nav, 1, true);
    EXPECT_EQ(nav.mode(), NavMode::Walk);
    press(nav, 1, false);
    press(nav, 1, true);
    press(nav, 1, true);
    press(nav, 1, true);
    EXPECT_EQ(nav.mode(), NavMode::Fly);  // four presses cycle back
    nav.handle({EventType::SelectMode, 0.0, 3, {}});
    EXPECT_EQ(nav.mode(), NavMode::Guided);
    nav.handle({EventType::SelectMode, 0.0, 9, {}});
    EXPECT_EQ(nav.mode(), NavMode::Guided);  // unknown modes are ignored
    nav.handle({EventType::SelectMode, 0.0, 0, {}});
    nav.handle({EventType::SpeedScale, 0.0, 0, {2.0, 0.0}});
    nav.handle({EventType::SpeedScale, 0.0, 0, {NAN, 0.0}});  // ignored
    nav.setTracking(kHead, handPointing(0.0, 0.0), {});
    press(nav, 0, true);
    run(nav, 3.0);
    EXPECT_NEAR(glm::length(nav.velocity()), 6.0, 1e-9);  // twice the 3 m/s top speed
    const glm::dmat4 before = nav.worldFromCave();
    nav.update(NAN);
    nav.update(-1.0);
    nav.setTracking({{NAN, 0, 0}, {1, 0, 0, 0}}, handPointing(0.0, 0.0), {{0}, {NAN, NAN}});
    EXPECT_EQ(nav.worldFromCave(), before);
    nav.update(kDt);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) ASSERT_TRUE(std::isfinite(nav.worldFromCave()[c][r]));
}

TEST(Navigator, HandCursorRayInTheCaveFrame) {
    TestWorld world;
    Navigator nav({}, &world);
    nav.setTracking(kHead, handPointing(-M_PI / 2, 0.0), {});  // pointing at +X
    HandCursor c = nav.handCursor();
    EXPECT_EQ(c.rayOrigin, glm::dvec3(0.2, 1.3, -0.3));
    EXPECT_NEAR(glm::distance(c.rayDirection, glm::dvec3(1, 0, 0)), 0.0, 1e-12);
    EXPECT_TRUE(c.hit);
    EXPECT_NEAR(c.rayLength, 9.8, 1e-12);                     // from x = 0.2 to the wall at x = 10
    nav.setTracking(kHead, handPointing(M_PI / 2, 0.0), {});  // away from the wall
    c = nav.handCursor();
    EXPECT_FALSE(c.hit);
    EXPECT_EQ(c.rayLength, 20.0);  // pickDistance
}

}  // namespace
}  // namespace cavewall::input
