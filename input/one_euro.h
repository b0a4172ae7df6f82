#pragma once
// The One Euro filter (Casiez, Roussel and Vogel, CHI 2012): a first-order low-pass filter
// whose cutoff rises with speed, so a still head does not jitter and a moving head does not lag.
//
// Per sample at time t (seconds), with dt = t - previous t:
//   alpha(fc) = 1 / (1 + 1 / (2π fc dt))
//   derivative estimate  d = lowpass((x - previous x) / dt, alpha(dCutoff))   (raw samples)
//   cutoff               fc = minCutoff + beta |d|
//   output               x̂ = lowpass(x, alpha(fc))
// The first sample passes through unchanged. A sample with dt <= 0 (same or older time) is
// ignored and the previous output returned, so the filter never divides by zero.
// Orientation uses the same rule on the rotation from the last output to the new sample (an
// angular speed in rad/s) and slerps by alpha. The speed estimates also serve prediction.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace cavewall::input {

struct OneEuroConfig {
    double minCutoff = 1.0;  // Hz: cutoff at rest; lower = less jitter, more lag when slow
    double beta = 20.0;      // Hz per unit of speed (m/s or rad/s): higher = less lag when fast
    double dCutoff = 1.0;    // Hz: cutoff of the speed estimate
    bool enabled = true;     // false: pass samples through (the speed is still estimated)
    bool operator==(const OneEuroConfig&) const = default;
};

// The defaults for head positions (metres) and orientations (radians).
inline constexpr OneEuroConfig kPositionFilter{1.0, 20.0, 1.0, true};
inline constexpr OneEuroConfig kOrientationFilter{1.0, 10.0, 1.0, true};

double oneEuroAlpha(double cutoffHz, double dt);

class OneEuroVec3 {
public:
    explicit OneEuroVec3(OneEuroConfig config = kPositionFilter) : _config(config) {}
    glm::dvec3 filter(const glm::dvec3& x, double time);
    const glm::dvec3& value() const { return _value; }
    const glm::dvec3& velocity() const { return _velocity; }  // filtered, units per second
    void reset() { _started = false; }

private:
    OneEuroConfig _config;
    bool _started = false;
    double _time = 0.0;
    glm::dvec3 _raw{0.0}, _value{0.0}, _velocity{0.0};
};

class OneEuroQuat {
public:
    explicit OneEuroQuat(OneEuroConfig config = kOrientationFilter) : _config(config) {}
    glm::dquat filter(const glm::dquat& q, double time);
    const glm::dquat& value() const { return _value; }
    // Filtered angular velocity (rotation vector per second) in the frame the quaternions map to.
    const glm::dvec3& angularVelocity() const { return _angularVelocity; }
    void reset() { _started = false; }

private:
    OneEuroConfig _config;
    bool _started = false;
    double _time = 0.0;
    glm::dquat _raw{1.0, 0.0, 0.0, 0.0}, _value{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 _angularVelocity{0.0};
};

}  // namespace cavewall::input
