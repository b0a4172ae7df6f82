#include "input/keyboard_wand.h"

#include "input/navigator.h"

namespace cavewall::input {

std::optional<Event> KeyboardWand::handle(const Event& e) {
    if (e.type != EventType::KeyDown && e.type != EventType::KeyUp) return std::nullopt;
    const bool down = e.type == EventType::KeyDown;
    if (e.code == kKeyControl) _control = down;
    if (_control && down) return std::nullopt;
    switch (e.code) {
        case 'W': _w = down; break;
        case 'A': _a = down; break;
        case 'S': _s = down; break;
        case 'D': _d = down; break;
        default: break;
    }
    if (down && e.code >= '1' && e.code < '1' + kNavModeCount)
        return Event{EventType::SelectMode, e.time, e.code - '1', {}};
    return std::nullopt;
}

WandState KeyboardWand::apply(WandState tracked) const {
    if (!(_w || _a || _s || _d)) return tracked;
    tracked.joystick = {(_d ? 1.0 : 0.0) - (_a ? 1.0 : 0.0), (_w ? 1.0 : 0.0) - (_s ? 1.0 : 0.0)};
    return tracked;
}

}  // namespace cavewall::input
