#include "input/dropout.h"

#include "input/pose_math.h"

#include <algorithm>

namespace cavewall::input {

std::string_view toString(TrackState state) {
    switch (state) {
        case TrackState::Tracked: return "tracked";
        case TrackState::Holding: return "holding";
        case TrackState::Easing: return "easing";
        case TrackState::Default: return "default";
    }
    return "?";
}

Pose DropoutPolicy::update(double time, const std::optional<Pose>& measured) {
    if (measured) {
        _seen = true;
        _last = *measured;
        _lastTime = time;
        _state = TrackState::Tracked;
        return _last;
    }
    const double lost = time - _lastTime;
    if (!_seen || lost > _config.holdSeconds + _config.easeSeconds) {
        _state = TrackState::Default;
        return _default;
    }
    if (lost <= _config.holdSeconds) {
        _state = TrackState::Holding;
        return _last;
    }
    _state = TrackState::Easing;
    const double u = std::clamp((lost - _config.holdSeconds) / _config.easeSeconds, 0.0, 1.0);
    const double s = u * u * (3.0 - 2.0 * u);
    return {glm::mix(_last.position, _default.position, s), slerpShortest(_last.orientation, _default.orientation, s)};
}

}  // namespace cavewall::input
