#pragma once
// Plain input data: poses, wand state, tracker samples and desktop/wand events.
//
// Units and frames (config/conventions.h): metres, seconds, radians. A Sample from a
// TrackerSource is in the TRACKER frame (the tracking system's axes, already converted to
// metres by its adapter); TrackingPipeline turns it into the CAVE frame. Orientations are unit
// quaternions; the identity looks down -Z with +Y up, and a hand or wand points along its -Z.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>

namespace cavewall::input {

struct Pose {
    glm::dvec3 position{0.0};                    // metres
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // unit quaternion (w, x, y, z)
    bool operator==(const Pose&) const = default;
};

// Wand (Flystick) buttons and joystick. Button 0 is the trigger, button 1 the mode button.
struct WandState {
    std::uint32_t buttons = 0;  // bit i set = button i held (up to 32 buttons)
    glm::dvec2 joystick{0.0};   // x right, y forward/up, each in [-1, 1]
    bool pressed(int button) const { return button >= 0 && button < 32 && ((buttons >> button) & 1u); }
    bool operator==(const WandState&) const = default;
};

// One reading of a tracker at `time`. A `...Valid` flag is false when the tracker has no fresh
// data for that device (out of view, no packets, simulated drop-out); the pose is then the last
// one seen and the drop-out policy (input/dropout.h) decides what the viewer gets.
struct Sample {
    double time = 0.0;  // seconds on the clock passed to TrackerSource::poll
    Pose head;          // tracker frame
    Pose hand;          // tracker frame; the wand's pose
    bool headValid = false;
    bool handValid = false;
    WandState wand;
    bool operator==(const Sample&) const = default;
};

// Key codes: printable keys are their upper-case ASCII code ('W', '1', ' '); others below.
inline constexpr int kKeyShift = 256;
inline constexpr int kKeyEscape = 257;
inline constexpr int kKeyControl = 258;
inline constexpr int kKeyF1 = 259;

enum class EventType : std::uint8_t {
    ButtonDown,  // code = wand or mouse button (0 trigger / left, 1 mode / right, ...)
    ButtonUp,
    KeyDown,  // code = key code
    KeyUp,
    MouseMove,       // value = pointer motion in pixels (x right, y down)
    Scroll,          // value.y = wheel steps (positive away from the user)
    SelectMode,      // code = navigation mode (input::NavMode as int)
    SpeedScale,      // value.x = navigation speed multiplier (> 0)
    PointerCapture,  // code = 1: a window captured the pointer (a click); 0: released it (Escape)
};

struct Event {
    EventType type = EventType::KeyDown;
    double time = 0.0;  // seconds, same clock as samples
    int code = 0;
    glm::dvec2 value{0.0};
    bool operator==(const Event&) const = default;
};

// The button edges between two wand states, as ButtonDown/ButtonUp events at `time`, in
// increasing button order. Appends to `out`.
template <class Container>
void appendWandEvents(const WandState& before, const WandState& after, double time, Container& out) {
    const std::uint32_t changed = before.buttons ^ after.buttons;
    for (int b = 0; b < 32; ++b)
        if ((changed >> b) & 1u)
            out.push_back(Event{after.pressed(b) ? EventType::ButtonDown : EventType::ButtonUp, time, b, {}});
}

}  // namespace cavewall::input
