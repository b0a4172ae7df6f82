#pragma once
// The drop-out policy: what the viewer gets while a tracked device is lost.
//
//   tracked                      -> the measured pose
//   lost for t <= holdSeconds    -> the last measured pose, unchanged (short occlusions are
//                                   invisible and do not shake the view)
//   lost for t in (hold, hold + easeSeconds]
//                                -> eases from the last pose to the default pose: position
//                                   lerped and orientation slerped by smoothstep((t - hold) / ease)
//   lost for longer, or never tracked -> the default pose
// t counts from the time of the last valid measurement. When the device is seen again its
// measured pose is used at once (the One Euro filter that follows softens the jump).

#include "input/sample.h"

#include <optional>
#include <string_view>

namespace cavewall::input {

struct DropoutConfig {
    double holdSeconds = 0.5;  // hold the last pose this long
    double easeSeconds = 1.0;  // then ease to the default pose over this long (0 = jump)
    bool operator==(const DropoutConfig&) const = default;
};

enum class TrackState { Tracked, Holding, Easing, Default };
std::string_view toString(TrackState state);

class DropoutPolicy {
public:
    DropoutPolicy(DropoutConfig config, Pose defaultPose) : _config(config), _default(defaultPose) {}
    // The pose at `time` (seconds, not decreasing) given this time's measurement, or nullopt
    // when the device is not tracked now.
    Pose update(double time, const std::optional<Pose>& measured);
    TrackState state() const { return _state; }

private:
    DropoutConfig _config;
    Pose _default;
    Pose _last;
    double _lastTime = 0.0;
    bool _seen = false;
    TrackState _state = TrackState::Default;
};

}  // namespace cavewall::input
