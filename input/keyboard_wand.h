#pragma once
// The keyboard as a wand, for a tracked CAVE driven from a keyboard at the operator's desk (or
// a wireless keyboard in the CAVE): W/S push the joystick forward and back, A/D left and right
// (the navigator turns the CAVE or strafes, input/navigator.h), 1-4 pick the navigation mode.
// While none of W, A, S, D is held the tracked wand's joystick is left as it is. Letter keys are
// ignored while Control is held (Ctrl+Q quits, input/session_keys.h). Pure: events in, state out.

#include "input/sample.h"

#include <optional>

namespace cavewall::input {

class KeyboardWand {
public:
    // A window's key event; returns a SelectMode event for the keys 1-4.
    std::optional<Event> handle(const Event& event);

    // `tracked` with the keys' joystick while any of W, A, S, D is held.
    WandState apply(WandState tracked) const;

private:
    bool _w = false, _a = false, _s = false, _d = false, _control = false;
};

}  // namespace cavewall::input
