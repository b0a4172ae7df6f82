#include "input/pose_math.h"

#include <bit>
#include <cmath>

namespace cavewall::input {

Pose transformPose(const glm::dmat4& bFromA, const Pose& pose) {
    Pose out;
    out.position = glm::dvec3(bFromA * glm::dvec4(pose.position, 1.0));
    // A calibration may carry a uniform scale: the rotation is the 3x3 divided by it. A rigid
    // transform is used as it is, so its poses stay bit for bit what they were.
    const glm::dmat3 m(bFromA);
    const double scale = std::cbrt(glm::determinant(m));
    const glm::dmat3 rotation = std::abs(scale - 1.0) <= 1e-9 ? m : m / scale;
    out.orientation = glm::normalize(glm::quat_cast(rotation) * pose.orientation);
    return out;
}

glm::dquat yawPitchRoll(double yaw, double pitch, double roll) {
    return glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitch, glm::dvec3(1, 0, 0)) *
           glm::angleAxis(roll, glm::dvec3(0, 0, 1));
}

double yawOf(const glm::dvec3& forward) {
    if (forward.x == 0.0 && forward.z == 0.0) return 0.0;
    return std::atan2(-forward.x, -forward.z);
}

double angleDifference(double a, double b) {
    double d = std::remainder(b - a, 2.0 * M_PI);
    return d <= -M_PI ? d + 2.0 * M_PI : d;
}

glm::dquat slerpShortest(const glm::dquat& a, glm::dquat b, double u) {
    if (glm::dot(a, b) < 0.0) b = -b;
    if (u <= 0.0) return a;
    if (u >= 1.0) return b;
    return glm::normalize(glm::slerp(a, b, u));
}

glm::dvec3 rotationBetween(const glm::dquat& a, const glm::dquat& b) {
    glm::dquat d = b * glm::inverse(a);
    if (d.w < 0.0) d = -d;
    const glm::dvec3 v(d.x, d.y, d.z);
    const double s = glm::length(v);
    if (s < 1e-12) return 2.0 * v;  // small-angle limit: angle ≈ 2 |v|
    return v * (2.0 * std::atan2(s, d.w) / s);
}

glm::dquat fromRotationVector(const glm::dvec3& v) {
    const double angle = glm::length(v);
    if (angle < 1e-15) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    return glm::angleAxis(angle, v / angle);
}

std::uint64_t nextRandom(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double uniform(std::uint64_t& state, double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(nextRandom(state) >> 11) * 0x1.0p-53;
}

double hashNoise(std::uint64_t seed, double key, std::uint64_t channel) {
    std::uint64_t s = seed ^ (std::bit_cast<std::uint64_t>(key) * 0xD1B54A32D192ED03ull) ^ (channel << 56);
    return uniform(s, -1.0, 1.0);
}

bool isFinite(const Pose& p) {
    return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
           std::isfinite(p.orientation.w) && std::isfinite(p.orientation.x) && std::isfinite(p.orientation.y) &&
           std::isfinite(p.orientation.z);
}

}  // namespace cavewall::input
