#pragma once
// Small pose helpers shared by the input library. Angles in radians.

#include "input/sample.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>

namespace cavewall::input {

// `pose` moved by `bFromA` (pose in frame a -> pose in frame b): a rotation, or a rotation times
// a uniform scale, then a translation (a calibration); the orientation takes the rotation only.
Pose transformPose(const glm::dmat4& bFromA, const Pose& pose);

// Yaw about +Y (positive turns left, -Z towards -X), then pitch about the turned +X (positive
// looks up), then roll about the turned +Z (positive tilts the head to the left).
glm::dquat yawPitchRoll(double yaw, double pitch, double roll = 0.0);

// The yaw (about +Y) of the direction `forward` projected onto the floor; 0 for -Z.
double yawOf(const glm::dvec3& forward);

// `v` turned by `yaw` about +Y (the floor's normal).
inline glm::dvec3 rotateY(double yaw, const glm::dvec3& v) { return glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * v; }

// Where a pose points: its -Z axis.
inline glm::dvec3 forwardOf(const glm::dquat& q) { return q * glm::dvec3(0.0, 0.0, -1.0); }

// Shortest signed angle from a to b, in (-pi, pi].
double angleDifference(double a, double b);

// Spherical interpolation along the shorter arc; exact at u = 0 and u = 1.
glm::dquat slerpShortest(const glm::dquat& a, glm::dquat b, double u);

// Rotation vector (axis * angle, radians) of the rotation from a to b: b = R * a.
glm::dvec3 rotationBetween(const glm::dquat& a, const glm::dquat& b);

// The rotation by a rotation vector (axis * angle); identity for a zero vector.
glm::dquat fromRotationVector(const glm::dvec3& v);

// Deterministic random numbers (splitmix64): the same state gives the same sequence on every
// platform, unlike std:: distributions.
std::uint64_t nextRandom(std::uint64_t& state);
double uniform(std::uint64_t& state, double lo, double hi);
// A value in [-1, 1] that depends only on (seed, key), for jitter as a pure function of time.
double hashNoise(std::uint64_t seed, double key, std::uint64_t channel);

bool isFinite(const Pose& pose);

}  // namespace cavewall::input
