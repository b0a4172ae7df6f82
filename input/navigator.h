#pragma once
// Navigation and the hand cursor: a pure state machine. Events, the tracked head and hand
// (cave frame) and update(dt) go in; worldFromCave() comes out. No clock, no I/O, no scene:
// floor and collision queries come through the injected WorldQuery.
//
// The CAVE moves through the world as a rigid, upright body: worldFromCave = translate(origin)
// * rotateY(yaw), so the floor stays level (no motion sickness from a tilted world).
//
// Controls (button 0 = trigger, button 1 = mode button, from ButtonDown/ButtonUp events; the
// joystick from setTracking). The speed command is the joystick's y (dead zone 0.1), or +1
// while the trigger is held and the joystick is centred. Joystick x turns the CAVE about the
// head (joystickTurns, the CAVE default) or strafes (desktop). Button 1 cycles the modes;
// SelectMode events pick one; SpeedScale events scale every speed.
//   fly:    go where the wand points (3D) at speed command * maxSpeed; the velocity changes by
//           at most maxAcceleration * dt per update.
//   walk:   the same on the floor plane. The CAVE floor follows the world floor under the head:
//           steps up to stepHeight are climbed, lower floors are fallen to with gravity. Walls
//           stop the viewer bodyRadius away: each step moves along world X, then Z, each part
//           checked with rays at knee and head height, so a blocked axis stops and the other
//           slides along the wall.
//           Without a WorldQuery the height is kept and nothing blocks.
//   grab:   while the trigger is held the world sticks to the hand (translation and yaw):
//           worldFromCave = worldFromCave0 * caveFromHand0 * inverse(caveFromHand).
//   guided: Galyean's river analogy (1995). The current carries an anchor along the guide path
//           at guidePace; the viewer steers freely (joystick, as in walk, without collisions)
//           within corridorRadius of the anchor; beyond it the excess decays with time constant
//           pullBackSeconds (soft banks). The CAVE's front turns towards the path direction with
//           time constant alignSeconds. The anchor stops at the path's end.

#include "input/sample.h"

#include <glm/glm.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace cavewall::input {

enum class NavMode { Fly = 0, Walk = 1, Grab = 2, Guided = 3 };
inline constexpr int kNavModeCount = 4;
std::string_view toString(NavMode mode);

// Scene queries in the world frame, implemented outside the input library (for example by the
// scenes library). Not owned by the Navigator; must outlive it.
class WorldQuery {
public:
    virtual ~WorldQuery() = default;
    // World y of the highest floor at or below `point`, at most `maxDrop` below it; nullopt if none.
    virtual std::optional<double> floorBelow(const glm::dvec3& point, double maxDrop) const = 0;
    // Distance from `origin` along the unit `direction` to the first surface, if within maxDistance.
    virtual std::optional<double> castRay(const glm::dvec3& origin, const glm::dvec3& direction,
                                          double maxDistance) const = 0;
};

struct NavigatorConfig {
    double maxSpeed = 3.0;         // m/s at full speed command
    double maxAcceleration = 4.0;  // m/s²
    double turnRate = 1.0;         // rad/s at full joystick x
    bool joystickTurns = true;     // joystick x turns (true) or strafes (false)
    double deadZone = 0.1;         // joystick values below this count as 0
    double bodyRadius = 0.3;       // m kept between the head and walls (walk)
    double stepHeight = 0.4;       // m, highest step climbed (walk)
    double gravity = 9.81;         // m/s² (walk)
    double maxFall = 100.0;        // m searched below for a floor (walk)
    double pickDistance = 20.0;    // m, cursor ray length when nothing is hit
    double guidePace = 1.0;        // m/s of the current (guided)
    double corridorRadius = 2.0;   // m of free steering around the anchor (guided)
    double pullBackSeconds = 1.0;  // s, time constant of the pull back into the corridor
    double alignSeconds = 2.0;     // s, time constant of turning to the path direction
};

// What the renderer needs to draw the hand icon and its pointing ray, in the cave frame.
struct HandCursor {
    Pose hand;                                // the hand's pose
    glm::dvec3 rayOrigin{0.0};                // = hand position
    glm::dvec3 rayDirection{0.0, 0.0, -1.0};  // unit, the hand's -Z
    double rayLength = 0.0;                   // to the first surface hit, else pickDistance
    bool hit = false;
};

class Navigator {
public:
    explicit Navigator(NavigatorConfig config = {}, const WorldQuery* world = nullptr);

    void setMode(NavMode mode);
    NavMode mode() const { return _mode; }
    // The guide path in the world frame (at least 2 points, else guided mode stays put).
    void setGuidePath(std::vector<glm::dvec3> points);
    void setWorldFromCave(const glm::dvec3& origin, double yaw);

    void handle(const Event& event);
    // This frame's head and hand in the cave frame (from TrackingPipeline or DesktopMapper).
    void setTracking(const Pose& head, const Pose& hand, const WandState& wand);
    // Advances by dt seconds (dt <= 0 or not finite does nothing).
    void update(double dt);

    glm::dmat4 worldFromCave() const;
    const glm::dvec3& origin() const { return _origin; }  // the cave origin in the world
    double yaw() const { return _yaw; }                   // radians about +Y
    const glm::dvec3& velocity() const { return _velocity; }
    double guideDistance() const { return _guideS; }  // metres along the guide path
    HandCursor handCursor() const;

private:
    glm::dvec3 toWorldDirection(const glm::dvec3& caveDirection) const;
    glm::dvec3 headInWorld() const;
    double speedCommand() const;
    glm::dvec3 steeringVelocity(bool horizontal) const;
    void accelerateTowards(const glm::dvec3& target, double dt);
    void turn(double angle);
    void updateFly(double dt);
    double freeDistance(const glm::dvec3& move) const;
    void walkOnFloor(double dt);
    void updateWalk(double dt);
    void updateGrab();
    void updateGuided(double dt);
    glm::dvec3 guidePoint(double s, glm::dvec3* tangent = nullptr) const;
    double closestGuideDistance(const glm::dvec3& p) const;

    NavigatorConfig _config;
    const WorldQuery* _world;
    NavMode _mode = NavMode::Fly;
    glm::dvec3 _origin{0.0};
    double _yaw = 0.0;
    glm::dvec3 _velocity{0.0};
    double _fallSpeed = 0.0;
    double _speedScale = 1.0;
    Pose _head{{0.0, 1.7, 0.0}, {1.0, 0.0, 0.0, 0.0}}, _hand{{0.2, 1.3, -0.35}, {1.0, 0.0, 0.0, 0.0}};
    WandState _wand;
    bool _trigger = false;
    bool _grabbing = false;
    glm::dvec3 _grabOrigin{0.0}, _grabHand{0.0};
    double _grabYaw = 0.0, _grabHandYaw = 0.0;
    std::vector<glm::dvec3> _guide;
    std::vector<double> _guideLengths;  // cumulative arc length at each point
    double _guideS = 0.0;
    glm::dvec3 _guideOffset{0.0};  // cave origin - anchor, horizontal
};

}  // namespace cavewall::input
