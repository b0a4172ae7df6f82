#include "input/tracking_pipeline.h"

#include "input/pose_math.h"

namespace cavewall::input {

PipelineConfig pipelineConfigFor(const config::DisplayConfig& display) {
    PipelineConfig c;
    c.caveFromTracker = display.tracking.caveFromTracker;
    c.latencySeconds = display.tracking.latencyMs * 1e-3;
    c.defaultHead = {display.viewer.headPosition, display.viewer.headOrientation};
    const glm::dquat body = yawPitchRoll(yawOf(forwardOf(display.viewer.headOrientation)), 0.0);
    c.defaultHand = {display.viewer.headPosition + body * glm::dvec3(0.2, -0.4, -0.35), body};
    return c;
}

Pose predictPose(const Pose& pose, const glm::dvec3& velocity, const glm::dvec3& angularVelocity, double seconds) {
    return {pose.position + velocity * seconds,
            glm::normalize(fromRotationVector(angularVelocity * seconds) * pose.orientation)};
}

TrackingPipeline::TrackingPipeline(PipelineConfig config)
    : _config(config), _head{DropoutPolicy(config.dropout, config.defaultHead), OneEuroVec3(config.position),
                             OneEuroQuat(config.orientation)},
      _hand{DropoutPolicy(config.dropout, config.defaultHand), OneEuroVec3(config.position),
            OneEuroQuat(config.orientation)} {}

TrackedDevice TrackingPipeline::step(Device& d, double time, bool valid, const Pose& trackerPose) {
    std::optional<Pose> measured;
    if (valid && isFinite(trackerPose)) measured = transformPose(_config.caveFromTracker, trackerPose);
    const Pose policy = d.dropout.update(time, measured);
    TrackedDevice out;
    out.state = d.dropout.state();
    out.pose = {d.position.filter(policy.position, time), d.orientation.filter(policy.orientation, time)};
    out.velocity = d.position.velocity();
    out.angularVelocity = d.orientation.angularVelocity();
    if (out.state == TrackState::Tracked && _config.latencySeconds > 0.0)
        out.pose = predictPose(out.pose, out.velocity, out.angularVelocity, _config.latencySeconds);
    return out;
}

TrackedFrame TrackingPipeline::update(const Sample& s) {
    TrackedFrame f;
    f.time = s.time;
    f.head = step(_head, s.time, s.headValid, s.head);
    f.hand = step(_hand, s.time, s.handValid, s.hand);
    f.wand = s.wand;
    return f;
}

}  // namespace cavewall::input
