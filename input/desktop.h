#pragma once
// The desktop fallback: mouse and keyboard mapped to a head, a hand and a wand, so every
// navigation mode works without a tracker. Pure: events in, poses out.
//
//   mouse motion     look: yaw -= dx * degreesPerPixel, pitch -= dy * degreesPerPixel (pitch
//                    within ±89°). The window adapter sends MouseMove only while it has the
//                    pointer captured.
//   W / S, D / A     joystick y = +1 / -1, joystick x = +1 / -1 (use NavigatorConfig
//                    joystickTurns = false so A and D strafe)
//   left / right mouse button   wand button 0 (trigger) / button 1 (cycles the modes)
//   1, 2, 3, 4       select fly, walk, grab, guided
//   Shift (held)     speed × fastFactor; mouse wheel: speed × scrollStep per step, in [0.05, 20]
// The head stays at its default position and turns; the hand is handDistance in front of the
// eyes with the head's orientation, so its icon sits at the centre of the view and its ray
// points where the viewer looks. Poses are in the cave frame.

#include "input/sample.h"

#include <set>
#include <vector>

namespace cavewall::input {

struct DesktopConfig {
    double degreesPerPixel = 0.15;   // mouse look sensitivity
    double handDistance = 0.5;       // m in front of the eyes
    double fastFactor = 4.0;         // speed multiplier while Shift is held
    double scrollStep = 1.25;        // speed multiplier per wheel step
};

class DesktopMapper {
public:
    explicit DesktopMapper(DesktopConfig config = {}, Pose defaultHead = {{0.0, 1.7, 0.0}, {1.0, 0.0, 0.0, 0.0}});
    // Takes one desktop event (keys, mouse) and returns the events for the Navigator.
    std::vector<Event> handle(const Event& event);
    Pose head() const;
    Pose hand() const;
    WandState wand() const;
    // A valid sample of head, hand and wand at `time`, cave frame.
    Sample sample(double time) const;

private:
    Event speedEvent(double time) const;

    DesktopConfig _config;
    Pose _defaultHead;
    double _yaw, _pitch = 0.0;       // radians
    double _speedLevel = 1.0;
    bool _fast = false;
    std::set<int> _keys;
    std::uint32_t _buttons = 0;
};

}  // namespace cavewall::input
