#pragma once
// From tracker samples to the head and hand poses the renderer uses, in the cave frame.
//
// Per sample, for the head and the hand separately:
//   1. calibration: pose_cave = caveFromTracker * pose_tracker (rigid, metres)
//   2. drop-out policy (input/dropout.h) towards the default pose when not valid
//   3. One Euro filter (input/one_euro.h) on position and orientation
//   4. constant-velocity prediction to the expected display time, `latencySeconds` ahead:
//        position += velocity * latency; orientation = rotation(angularVelocity * latency) * q
//      using the filter's speed estimates; only while the device is tracked (a held or easing
//      pose is not extrapolated).
// Times are the samples' times (seconds); velocities are m/s and rad/s in the cave frame.

#include "config/display_config.h"
#include "input/dropout.h"
#include "input/one_euro.h"
#include "input/sample.h"

namespace cavewall::input {

struct PipelineConfig {
    glm::dmat4 caveFromTracker{1.0};  // rigid calibration (config tracking.caveFromTracker)
    double latencySeconds = 0.0;      // motion-to-photon latency to predict over, >= 0
    OneEuroConfig position = kPositionFilter;
    OneEuroConfig orientation = kOrientationFilter;
    DropoutConfig dropout;
    Pose defaultHead{{0.0, 1.7, 0.0}, {1.0, 0.0, 0.0, 0.0}};    // cave frame
    Pose defaultHand{{0.2, 1.3, -0.35}, {1.0, 0.0, 0.0, 0.0}};  // cave frame
};

// caveFromTracker and latency from the display's "tracking"; the default head is the viewer's;
// the default hand is 0.2 m right, 0.4 m below and 0.35 m in front of it, pointing ahead.
PipelineConfig pipelineConfigFor(const config::DisplayConfig& display);

struct TrackedDevice {
    Pose pose;                        // cave frame, filtered and predicted
    glm::dvec3 velocity{0.0};         // m/s, cave frame (filter estimate)
    glm::dvec3 angularVelocity{0.0};  // rad/s rotation vector, cave frame
    TrackState state = TrackState::Default;
};

struct TrackedFrame {
    double time = 0.0;  // the sample's time, seconds
    TrackedDevice head, hand;
    WandState wand;
};

// Constant-velocity extrapolation of `pose` by `seconds` (step 4 above).
Pose predictPose(const Pose& pose, const glm::dvec3& velocity, const glm::dvec3& angularVelocity, double seconds);

class TrackingPipeline {
public:
    explicit TrackingPipeline(PipelineConfig config);
    TrackedFrame update(const Sample& sample);
    const PipelineConfig& config() const { return _config; }

private:
    struct Device {
        DropoutPolicy dropout;
        OneEuroVec3 position;
        OneEuroQuat orientation;
    };
    TrackedDevice step(Device& device, double time, bool valid, const Pose& trackerPose);

    PipelineConfig _config;
    Device _head, _hand;
};

}  // namespace cavewall::input
