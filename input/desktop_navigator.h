#pragma once
// The desktop fallback's navigation (`cavewall view`, `--tracker desktop`): keyboard and mouse
// move the viewer through the world, with no tracker. A pure state machine like
// input::Navigator: window events and update(dt) go in; worldFromCave() comes out. No clock, no
// I/O; floors and walls come through the injected WorldQuery (walk, grab's cursor ray).
//
// The head stays at the display's default head (cave frame) and the world turns instead, so
// the view changes on a fixed screen. The viewer is a standing body: its eye is eyeHeight above
// its floor whatever the display's head height (a desktop head sits at 1.2 m). With yaw about
// +Y and pitch about the view's right axis, both about the head,
//   worldFromCave = translate(origin) * rotateY(yaw) * translate(0, eyeHeight - head.y, 0)
//                   * [rotateX(pitch) about the head].
// (origin, yaw) is an input::Navigator's upright body, which walk, grab and guided move.
//
// Controls (events as display::gl::Context::takeInputEvents gives them):
//   mouse motion     look: yaw -= dx * degreesPerPixel, pitch -= dy * degreesPerPixel, pitch
//                    within ±maxPitchDeg (the window sends motion while the pointer is captured:
//                    a click captures it, so dragging with the left button looks too). In grab
//                    mode, motion with the left button held moves the hand instead.
//   W / S, A / D     forward / back along the view, left / right (fly: the view direction with
//                    its pitch; walk and guided: on the floor)
//   Q / E            down / up (fly only)
//   Shift (held)     speed × fastFactor; wheel: speed × scrollStep per step, within
//                    [minScale, maxScale]
//   1, 2, 3, 4       fly, walk, grab, guided
//   left button      grab: the trigger (the world sticks to the hand while held)
// Letter keys are ignored while Control is held (Ctrl+Q quits the session: session_keys.h).
//   fly:    free flight at speed, with no acceleration and nothing blocking: each update moves
//           the eye by (forward (W - S) + right (D - A) + up (E - Q)) * speed * dt.
//   walk, guided, grab: input::Navigator's modes, the hand straight ahead of the eyes (walk
//           forward is the view's yaw). The Navigator is given maxSpeed = speed and an
//           acceleration of accelerationPerSpeed * speed, so it reaches full speed in
//           1 / accelerationPerSpeed s. Grab: a drag of one pixel moves the hand
//           speed() * grabSecondsPerPixel across the floor (x right, y towards the viewer).

#include "input/navigator.h"
#include "input/sample.h"

#include <set>
#include <vector>

namespace cavewall::input {

struct DesktopNavigatorConfig {
    double degreesPerPixel = 0.15;            // mouse look, degrees per pixel of motion
    double maxPitchDeg = 89.0;                // looking up or down at most this far
    double speed = 3.0;                       // m/s of a movement key at speed scale 1 (viewSpeed())
    double fastFactor = 4.0;                  // speed multiplier while Shift is held
    double scrollStep = 1.25;                 // speed multiplier per wheel step
    double minScale = 0.05, maxScale = 20.0;  // the wheel's speed scale stays within these
    double eyeHeight = 1.7;                   // m, the standing eye above the body's floor
    double handDistance = 0.5;                // m, the hand in front of the eyes
    double accelerationPerSpeed = 8.0;        // walk, guided: acceleration = this * speed, per s
    double grabSecondsPerPixel = 0.01;        // grab: a pixel of drag moves the hand speed() * this m
    NavigatorConfig navigator;                // walk and guided: body radius, steps, the guide's pace
};

// A movement speed for a model of bounding-box diagonal `diagonal` metres: diagonal / 20 per
// second (a building crossed in 20 s), within [0.05, 5] m/s (no faster than a brisk run, and a
// model of centimetres still moves); `standingInside` (the viewer starts on a floor inside a
// building) caps it at kWalkingSpeed, a brisk walk (Shift and the wheel go faster). A non-finite
// or non-positive diagonal gives 1 m/s.
inline constexpr double kWalkingSpeed = 2.0;  // m/s
double viewSpeed(double diagonal, bool standingInside = false);

class DesktopNavigator {
public:
    // `head`: the display's default head, cave frame (it never moves). `world` is not owned
    // and may be null (then walking keeps its height and nothing blocks).
    DesktopNavigator(DesktopNavigatorConfig config, Pose head, const WorldQuery* world = nullptr);

    void setMode(NavMode mode);
    NavMode mode() const { return _nav.mode(); }
    // The guide path in the world frame (floor points; at least 2, else guided stays put).
    void setGuidePath(std::vector<glm::dvec3> points);
    // Puts the eye at `eye` (world) looking along `yaw` (radians about +Y; 0 looks down -Z) with
    // no pitch.
    void setEye(const glm::dvec3& eye, double yaw);
    // Places the body's floor at `origin` (world) facing `yaw`, as Navigator::setWorldFromCave.
    void setBody(const glm::dvec3& origin, double yaw);

    void handle(const Event& event);
    // Advances by dt seconds (dt <= 0 or not finite does nothing).
    void update(double dt);

    glm::dmat4 worldFromCave() const;
    glm::dvec3 eyeWorld() const;                // the head's position in the world
    double yaw() const { return _nav.yaw(); }   // radians about +Y, 0 looking down -Z
    double pitch() const { return _pitch; }     // radians, positive looks up
    double speed() const;                       // m/s of a movement key now (scale, Shift)
    const Pose& head() const { return _head; }  // cave frame
    // The hand (cave frame) and the first surface along its ray (Navigator::handCursor).
    HandCursor handCursor() const;

private:
    glm::dmat4 caveFromBody() const;  // the display cave from the Navigator's body
    Pose bodyPose(const Pose& cavePose) const;
    Pose handInBody() const;
    void look(const glm::dvec2& pixels);
    void handleKey(int code, bool down);
    void updateFly(double dt);
    void sendSpeed();
    void feedNavigator();
    double axis(int positive, int negative) const;

    DesktopNavigatorConfig _config;
    Pose _head;
    const WorldQuery* _world;
    Navigator _nav;
    double _pitch = 0.0;
    double _scale = 1.0;
    std::set<int> _keys;
    bool _leftButton = false;
    glm::dvec2 _grabOffset{0.0};  // the hand's drag across the floor, m
};

}  // namespace cavewall::input
