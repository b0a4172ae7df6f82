#include "input/one_euro.h"

#include "input/pose_math.h"

#include <cmath>

namespace cavewall::input {

double oneEuroAlpha(double cutoffHz, double dt) {
    const double tau = 1.0 / (2.0 * M_PI * cutoffHz);
    return 1.0 / (1.0 + tau / dt);
}

glm::dvec3 OneEuroVec3::filter(const glm::dvec3& x, double time) {
    if (!_started) {
        _started = true;
        _time = time;
        _raw = _value = x;
        _velocity = glm::dvec3(0.0);
        return _value;
    }
    const double dt = time - _time;
    if (!(dt > 0.0)) return _value;
    _time = time;
    const glm::dvec3 rawVelocity = (x - _raw) / dt;
    _raw = x;
    _velocity += oneEuroAlpha(_config.dCutoff, dt) * (rawVelocity - _velocity);
    if (!_config.enabled) return _value = x;
    const double cutoff = _config.minCutoff + _config.beta * glm::length(_velocity);
    _value += oneEuroAlpha(cutoff, dt) * (x - _value);
    return _value;
}

glm::dquat OneEuroQuat::filter(const glm::dquat& q, double time) {
    if (!_started) {
        _started = true;
        _time = time;
        _raw = _value = q;
        _angularVelocity = glm::dvec3(0.0);
        return _value;
    }
    const double dt = time - _time;
    if (!(dt > 0.0)) return _value;
    _time = time;
    const glm::dvec3 rawVelocity = rotationBetween(_raw, q) / dt;
    _raw = q;
    _angularVelocity += oneEuroAlpha(_config.dCutoff, dt) * (rawVelocity - _angularVelocity);
    if (!_config.enabled) return _value = q;
    const double cutoff = _config.minCutoff + _config.beta * glm::length(_angularVelocity);
    _value = slerpShortest(_value, q, oneEuroAlpha(cutoff, dt));
    return _value;
}

}  // namespace cavewall::input
