#include "input/desktop.h"

#include "input/pose_math.h"

#include <algorithm>
#include <cmath>

namespace cavewall::input {

DesktopMapper::DesktopMapper(DesktopConfig config, Pose defaultHead)
    : _config(config), _defaultHead(defaultHead), _yaw(yawOf(forwardOf(defaultHead.orientation))) {}

Event DesktopMapper::speedEvent(double time) const {
    return {EventType::SpeedScale, time, 0, {_speedLevel * (_fast ? _config.fastFactor : 1.0), 0.0}};
}

std::vector<Event> DesktopMapper::handle(const Event& e) {
    std::vector<Event> out;
    const double maxPitch = glm::radians(89.0);
    switch (e.type) {
    case EventType::MouseMove:
        if (!std::isfinite(e.value.x) || !std::isfinite(e.value.y)) break;
        _yaw -= glm::radians(e.value.x * _config.degreesPerPixel);
        _pitch = std::clamp(_pitch - glm::radians(e.value.y * _config.degreesPerPixel), -maxPitch, maxPitch);
        break;
    case EventType::KeyDown:
    case EventType::KeyUp: {
        const bool down = e.type == EventType::KeyDown;
        if (down) _keys.insert(e.code);
        else _keys.erase(e.code);
        if (e.code == kKeyShift) {
            _fast = down;
            out.push_back(speedEvent(e.time));
        }
        if (down && e.code >= '1' && e.code <= '4') out.push_back({EventType::SelectMode, e.time, e.code - '1', {}});
        break;
    }
    case EventType::Scroll:
        if (!std::isfinite(e.value.y)) break;
        _speedLevel = std::clamp(_speedLevel * std::pow(_config.scrollStep, e.value.y), 0.05, 20.0);
        out.push_back(speedEvent(e.time));
        break;
    case EventType::ButtonDown:
    case EventType::ButtonUp:
        if (e.code < 0 || e.code > 1) break;
        if (e.type == EventType::ButtonDown) _buttons |= 1u << e.code;
        else _buttons &= ~(1u << e.code);
        out.push_back(e);
        break;
    default: out.push_back(e); break;
    }
    return out;
}

Pose DesktopMapper::head() const { return {_defaultHead.position, yawPitchRoll(_yaw, _pitch)}; }

Pose DesktopMapper::hand() const {
    const Pose h = head();
    return {h.position + forwardOf(h.orientation) * _config.handDistance, h.orientation};
}

WandState DesktopMapper::wand() const {
    WandState w;
    w.buttons = _buttons;
    w.joystick.y = (_keys.count('W') ? 1.0 : 0.0) - (_keys.count('S') ? 1.0 : 0.0);
    w.joystick.x = (_keys.count('D') ? 1.0 : 0.0) - (_keys.count('A') ? 1.0 : 0.0);
    return w;
}

Sample DesktopMapper::sample(double time) const {
    Sample s;
    s.time = time;
    s.head = head();
    s.hand = hand();
    s.headValid = s.handValid = true;
    s.wand = wand();
    return s;
}

}  // namespace cavewall::input
