// The desktop navigation (input/desktop_navigator.h) driven by scripted window events.
#include "input/desktop_navigator.h"
#include "input/pose_math.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::input {
namespace {

constexpr double kStep = 1.0 / 60.0;

// The desktop preset's head: 1.2 m high, looking down -Z.
const Pose kDeskHead{{0.0, 1.2, 0.0}, {1.0, 0.0, 0.0, 0.0}};

// Floor at y = 0 everywhere; a wall filling the plane x = 10.
class Room : public WorldQuery {
public:
    std::optional<double> floorBelow(const glm::dvec3& p, double maxDrop) const override {
        if (p.y < 0.0 || p.y > maxDrop) return std::nullopt;
        return 0.0;
    }
    std::optional<double> castRay(const glm::dvec3& o, const glm::dvec3& d, double maxDistance) const override {
        if (d.x <= 0.0 || o.x >= 10.0) return std::nullopt;
        const double t = (10.0 - o.x) / d.x;
        return t <= maxDistance ? std::optional<double>(t) : std::nullopt;
    }
};

DesktopNavigatorConfig config(double speed = 2.0) {
    DesktopNavigatorConfig c;
    c.speed = speed;
    return c;
}

void key(DesktopNavigator& nav, int code, bool down) {
    nav.handle({down ? EventType::KeyDown : EventType::KeyUp, 0.0, code, {}});
}

void mouse(DesktopNavigator& nav, double dx, double dy) { nav.handle({EventType::MouseMove, 0.0, 0, {dx, dy}}); }

void run(DesktopNavigator& nav, double seconds) {
    for (long i = 0; i < std::lround(seconds / kStep); ++i) nav.update(kStep);
}

// Where the head looks in the world.
glm::dvec3 viewDirection(const DesktopNavigator& nav) {
    return glm::dvec3(nav.worldFromCave() * glm::dvec4(forwardOf(nav.head().orientation), 0.0));
}

// The unit direction of a view turned by yaw (left positive) and pitch (up positive).
glm::dvec3 direction(double yawDeg, double pitchDeg) {
    const double y = glm::radians(yawDeg), p = glm::radians(pitchDeg);
    return {-std::sin(y) * std::cos(p), std::sin(p), -std::cos(y) * std::cos(p)};
}

TEST(DesktopNavigator, SetEyePutsTheHeadThereLookingAlongTheYaw) {
    DesktopNavigator nav(config(), kDeskHead);
    nav.setEye({3.0, 1.7, -4.0}, glm::radians(90.0));
    EXPECT_NEAR(glm::distance(nav.eyeWorld(), glm::dvec3(3.0, 1.7, -4.0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(viewDirection(nav), direction(90.0, 0.0)), 0.0, 1e-12);  // yaw 90°: towards -X
}

TEST(DesktopNavigator, AMouseMoveOfNPixelsTurnsByNTimesTheDegreesPerPixel) {
    DesktopNavigator nav(config(), kDeskHead);
    nav.setEye({1.0, 1.7, 2.0}, 0.0);
    mouse(nav, 100.0, 0.0);  // 100 px right at 0.15°/px: 15° to the right, yaw -15°
    EXPECT_NEAR(glm::degrees(nav.yaw()), -15.0, 1e-12);
    mouse(nav, 0.0, -40.0);  // 40 px up: 6° up
    EXPECT_NEAR(glm::degrees(nav.pitch()), 6.0, 1e-12);
    EXPECT_NEAR(glm::distance(viewDirection(nav), direction(-15.0, 6.0)), 0.0, 1e-12);
    // The world turns about the head: the eye stays where it was.
    EXPECT_NEAR(glm::distance(nav.eyeWorld(), glm::dvec3(1.0, 1.7, 2.0)), 0.0, 1e-12);
    mouse(nav, 0.0, -100000.0);  // far up: pitch stops at 89°
    EXPECT_NEAR(glm::degrees(nav.pitch()), 89.0, 1e-12);
}

TEST(DesktopNavigator, WMovesAlongTheViewBySpeedTimesDt) {
    DesktopNavigator nav(config(2.0), kDeskHead);
    nav.setEye({0.0, 1.7, 0.0}, 0.0);
    mouse(nav, -200.0, -100.0);  // 30° left, 15° up
    key(nav, 'W', true);
    nav.update(0.25);
    // Fly has no acceleration: 2 m/s × 0.25 s = 0.5 m along the view, pitch included.
    EXPECT_NEAR(glm::distance(nav.eyeWorld(), glm::dvec3(0.0, 1.7, 0.0) + 0.5 * direction(30.0, 15.0)), 0.0, 1e-12);
    key(nav, 'W', false);
    const glm::dvec3 stopped = nav.eyeWorld();
    nav.update(0.25);
    EXPECT_EQ(nav.eyeWorld(), stopped);  // released: no drift
}

TEST(DesktopNavigator, ADStrafeAndQEGoDownAndUp) {
    DesktopNavigator nav(config(2.0), kDeskHead);
    nav.setEye({0.0, 1.7, 0.0}, glm::radians(90.0));  // looking down -X: right is -Z
    mouse(nav, 0.0, -200.0);                          // looking 30° up: strafing stays level
    key(nav, 'D', true);
    nav.update(0.5);
    EXPECT_NEAR(glm::distance(nav.eyeWorld(), glm::dvec3(0.0, 1.7, -1.0)), 0.0, 1e-12);
    key(nav, 'A', true);  // both: no sideways motion
    nav.update(0.5);
    EXPECT_NEAR(glm::distance(nav.eyeWorld(), glm::dvec3(0.0, 1.7, -1.0)), 0.0, 1e-12);
    key(nav, 'A', false);
    key(nav, 'D', false);
    key(nav, 'E', true);
    nav.update(0.5);
    EXPECT_NEAR(nav.eyeWorld().y, 2.7, 1e-12);  // straight up, 1 m
    key(nav, 'E', false);
    key(nav, 'Q', true);
    nav.update(1.0);
    EXPECT_NEAR(nav.eyeWorld().y, 0.7, 1e-12);  // fly goes through floors: nothing blocks
}

TEST(DesktopNavigator, ShiftAndTheWheelScaleTheSpeed) {
    DesktopNavigator nav(config(2.0), kDeskHead);
    EXPECT_EQ(nav.speed(), 2.0);
    key(nav, kKeyShift, true);
    EXPECT_EQ(nav.speed(), 8.0);  // × 4 while held
    key(nav, kKeyShift, false);
    nav.handle({EventType::Scroll, 0.0, 0, {0.0, 2.0}});
    EXPECT_NEAR(nav.speed(), 2.0 * 1.5625, 1e-12);  // two steps of × 1.25
    nav.handle({EventType::Scroll, 0.0, 0, {0.0, 1000.0}});
    EXPECT_NEAR(nav.speed(), 2.0 * 20.0, 1e-12);  // at most × 20
    nav.handle({EventType::Scroll, 0.0, 0, {0.0, -2000.0}});
    EXPECT_NEAR(nav.speed(), 2.0 * 0.05, 1e-12);  // at least × 0.05
}

TEST(DesktopNavigator, NumberKeysSelectTheModesAndControlKeepsLettersForTheSession) {
    DesktopNavigator nav(config(), kDeskHead);
    EXPECT_EQ(nav.mode(), NavMode::Fly);
    const std::pair<int, NavMode> keys[] = {
        {'2', NavMode::Walk}, {'3', NavMode::Grab}, {'4', NavMode::Guided}, {'1', NavMode::Fly}};
    for (const auto& [code, mode] : keys) {
        key(nav, code, true);
        key(nav, code, false);
        EXPECT_EQ(nav.mode(), mode);
    }
    nav.setEye({0.0, 1.7, 0.0}, 0.0);
    key(nav, kKeyControl, true);
    key(nav, 'Q', true);  // Ctrl+Q quits the session; it must not also fly down
    nav.update(0.5);
    EXPECT_EQ(nav.eyeWorld(), glm::dvec3(0.0, 1.7, 0.0));
}

TEST(DesktopNavigator, WalkKeepsTheEyeAtEyeHeightAndWallsBlock) {
    const Room room;
    DesktopNavigator nav(config(2.0), kDeskHead, &room);
    nav.setEye({0.0, 3.0, 0.0}, glm::radians(-90.0));  // looking down +X, towards the wall at x = 10
    key(nav, '2', true);
    run(nav, 2.0);
    // The body falls to the floor; the standing eye is 1.7 m above it, not the desk's 1.2 m.
    EXPECT_NEAR(nav.eyeWorld().y, 1.7, 1e-9);
    mouse(nav, 0.0, 300.0);  // looking 45° down: walking stays on the floor
    key(nav, 'W', true);
    run(nav, 1.0);
    // Acceleration 8 × 2 = 16 m/s²; step i (of 60 in 1 s) moves min(2, 16 i / 60) / 60 m: 7 steps
    // speeding up (16 / 60 × (1 + ... + 7) / 60 = 0.12444 m), then 53 at 2 m/s (1.76667 m).
    EXPECT_NEAR(nav.eyeWorld().x, 16.0 / 60.0 * 28.0 / 60.0 + 2.0 * 53.0 / 60.0, 1e-9);
    EXPECT_NEAR(nav.eyeWorld().y, 1.7, 1e-9);
    run(nav, 10.0);
    EXPECT_NEAR(nav.eyeWorld().x, 10.0 - 0.3, 1e-6);  // stopped the body radius from the wall
}

TEST(DesktopNavigator, GrabDragsTheWorldWithTheMouse) {
    DesktopNavigator nav(config(2.0), kDeskHead);
    nav.setEye({0.0, 1.7, 0.0}, 0.0);
    key(nav, '3', true);
    nav.handle({EventType::ButtonDown, 0.0, 0, {}});
    mouse(nav, 100.0, 0.0);  // the hand 100 px right: 100 × 2 m/s × 0.01 s = 2 m
    nav.update(kStep);
    // The world sticks to the hand and moves right with it: the eye goes 2 m left in the world.
    EXPECT_NEAR(glm::distance(nav.eyeWorld(), glm::dvec3(-2.0, 1.7, 0.0)), 0.0, 1e-9);
    EXPECT_EQ(nav.yaw(), 0.0);  // dragging does not look around
    nav.handle({EventType::ButtonUp, 0.0, 0, {}});
    mouse(nav, 100.0, 0.0);  // without the button the mouse looks again
    EXPECT_NEAR(glm::degrees(nav.yaw()), -15.0, 1e-12);
}

TEST(DesktopNavigator, TheHandSitsAtTheViewCentreAndItsRayStopsAtWalls) {
    const Room room;
    DesktopNavigator nav(config(), kDeskHead, &room);
    nav.setEye({4.0, 1.7, 0.0}, glm::radians(-90.0));  // looking down +X: the wall 6 m ahead
    mouse(nav, 0.0, -100.0);                           // and 15° up: the world turns, not the head
    const HandCursor c = nav.handCursor();
    EXPECT_NEAR(glm::distance(c.hand.position, glm::dvec3(0.0, 1.2, -0.5)), 0.0, 1e-12);  // 0.5 m ahead
    EXPECT_TRUE(c.hit);
    // From the hand, 0.5 m towards the wall, along a ray 15° up: (6 - 0.5 cos 15°) / cos 15°.
    EXPECT_NEAR(c.rayLength, 6.0 / std::cos(glm::radians(15.0)) - 0.5, 1e-9);
}

TEST(DesktopNavigator, SpeedFollowsTheModelsSize) {
    EXPECT_EQ(viewSpeed(60.0), 3.0);    // a 60 m building: crossed in 20 s
    EXPECT_EQ(viewSpeed(1000.0), 5.0);  // a 1 km plant: no faster than a brisk run
    EXPECT_EQ(viewSpeed(0.2), 0.05);    // a 20 cm object still moves
    EXPECT_EQ(viewSpeed(0.0), 1.0);     // no size: walking pace
    EXPECT_EQ(viewSpeed(NAN), 1.0);
    // Standing on a floor inside: at most a brisk walk, however large the building.
    EXPECT_EQ(viewSpeed(96.0, true), kWalkingSpeed);  // a 96 m clinic: 4.8 m/s would be a run
    EXPECT_EQ(viewSpeed(20.0, true), 1.0);            // a small house keeps diagonal / 20
}

}  // namespace
}  // namespace cavewall::input
