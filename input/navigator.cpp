#include "input/navigator.h"

#include "input/pose_math.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace cavewall::input {
namespace {

glm::dvec3 horizontal(glm::dvec3 v) {
    v.y = 0.0;
    const double len = glm::length(v);
    return len > 1e-9 ? v / len : glm::dvec3(0.0);
}

double applyDeadZone(double v, double zone) {
    const double a = std::fabs(v);
    if (!(a > zone)) return 0.0;
    return std::copysign(std::min(1.0, (a - zone) / (1.0 - zone)), v);
}

}  // namespace

std::string_view toString(NavMode mode) {
    switch (mode) {
        case NavMode::Fly: return "fly";
        case NavMode::Walk: return "walk";
        case NavMode::Grab: return "grab";
        case NavMode::Guided: return "guided";
    }
    return "?";
}

Navigator::Navigator(NavigatorConfig config, const WorldQuery* world) : _config(config), _world(world) {}

void Navigator::setMode(NavMode mode) {
    _mode = mode;
    _velocity = glm::dvec3(0.0);
    _fallSpeed = 0.0;
    _grabbing = false;
    if (mode == NavMode::Guided && _guide.size() >= 2) {
        _guideS = closestGuideDistance(_origin);
        const glm::dvec3 anchor = guidePoint(_guideS);
        _guideOffset = glm::dvec3(_origin.x - anchor.x, 0.0, _origin.z - anchor.z);
    }
}

void Navigator::setGuidePath(std::vector<glm::dvec3> points) {
    _guide = std::move(points);
    _guideLengths.assign(_guide.size(), 0.0);
    for (std::size_t i = 1; i < _guide.size(); ++i)
        _guideLengths[i] = _guideLengths[i - 1] + glm::length(_guide[i] - _guide[i - 1]);
    if (_mode == NavMode::Guided) setMode(NavMode::Guided);
}

void Navigator::setWorldFromCave(const glm::dvec3& origin, double yaw) {
    _origin = origin;
    _yaw = yaw;
}

void Navigator::handle(const Event& e) {
    switch (e.type) {
        case EventType::ButtonDown:
        case EventType::ButtonUp: {
            const bool down = e.type == EventType::ButtonDown;
            if (e.code == 0) {
                _trigger = down;
                if (_mode == NavMode::Grab && down) {
                    _grabbing = true;
                    _grabOrigin = _origin;
                    _grabYaw = _yaw;
                    _grabHand = _hand.position;
                    _grabHandYaw = yawOf(forwardOf(_hand.orientation));
                }
                if (!down) _grabbing = false;
            } else if (e.code == 1 && down) {
                setMode(static_cast<NavMode>((static_cast<int>(_mode) + 1) % kNavModeCount));
            }
            break;
        }
        case EventType::SelectMode:
            if (e.code >= 0 && e.code < kNavModeCount) setMode(static_cast<NavMode>(e.code));
            break;
        case EventType::SpeedScale:
            if (std::isfinite(e.value.x) && e.value.x > 0.0) _speedScale = std::clamp(e.value.x, 0.01, 100.0);
            break;
        default: break;
    }
}

void Navigator::setTracking(const Pose& head, const Pose& hand, const WandState& wand) {
    if (isFinite(head)) _head = head;
    if (isFinite(hand)) _hand = hand;
    _wand = wand;
    if (!std::isfinite(_wand.joystick.x) || !std::isfinite(_wand.joystick.y)) _wand.joystick = glm::dvec2(0.0);
}

glm::dmat4 Navigator::worldFromCave() const {
    return glm::translate(glm::dmat4(1.0), _origin) * glm::mat4_cast(glm::angleAxis(_yaw, glm::dvec3(0, 1, 0)));
}

glm::dvec3 Navigator::toWorldDirection(const glm::dvec3& d) const { return rotateY(_yaw, d); }
glm::dvec3 Navigator::headInWorld() const { return _origin + rotateY(_yaw, _head.position); }

double Navigator::speedCommand() const {
    const double y = applyDeadZone(_wand.joystick.y, _config.deadZone);
    if (y != 0.0) return y;
    return _trigger ? 1.0 : 0.0;
}

glm::dvec3 Navigator::steeringVelocity(bool onFloor) const {
    glm::dvec3 forward = toWorldDirection(forwardOf(_hand.orientation));
    glm::dvec3 right = toWorldDirection(_hand.orientation * glm::dvec3(1, 0, 0));
    if (onFloor) {
        forward = horizontal(forward);
        right = horizontal(right);
    }
    glm::dvec3 v = forward * speedCommand();
    if (!_config.joystickTurns) v += right * applyDeadZone(_wand.joystick.x, _config.deadZone);
    return v * (_config.maxSpeed * _speedScale);
}

void Navigator::accelerateTowards(const glm::dvec3& target, double dt) {
    const glm::dvec3 change = target - _velocity;
    const double limit = _config.maxAcceleration * _speedScale * dt, len = glm::length(change);
    _velocity = len <= limit ? target : _velocity + change * (limit / len);
}

void Navigator::turn(double angle) {
    if (angle == 0.0) return;
    const glm::dvec3 head = headInWorld();
    _yaw += angle;
    _origin = head - rotateY(_yaw, _head.position);  // turn about the head, not the cave centre
}

void Navigator::update(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) return;
    if (_config.joystickTurns && _mode != NavMode::Grab)
        turn(-applyDeadZone(_wand.joystick.x, _config.deadZone) * _config.turnRate * dt);
    switch (_mode) {
        case NavMode::Fly: updateFly(dt); break;
        case NavMode::Walk: updateWalk(dt); break;
        case NavMode::Grab: updateGrab(); break;
        case NavMode::Guided: updateGuided(dt); break;
    }
}

void Navigator::updateFly(double dt) {
    accelerateTowards(steeringVelocity(false), dt);
    _origin += _velocity * dt;
}

double Navigator::freeDistance(const glm::dvec3& move) const {
    const double distance = glm::length(move);
    if (!_world || distance == 0.0) return distance;
    const glm::dvec3 dir = move / distance, head = headInWorld();
    double allowed = distance;
    for (double height : {_origin.y + _config.stepHeight + 0.05, head.y}) {
        const glm::dvec3 from(head.x, height, head.z);
        if (auto hit = _world->castRay(from, dir, distance + _config.bodyRadius))
            allowed = std::min(allowed, std::max(0.0, *hit - _config.bodyRadius));
    }
    return allowed;
}

void Navigator::walkOnFloor(double dt) {
    const glm::dvec3 head = headInWorld();
    const auto floor =
        _world->floorBelow({head.x, _origin.y + _config.stepHeight, head.z}, _config.stepHeight + _config.maxFall);
    if (!floor) {
        _fallSpeed = 0.0;
    } else if (*floor >= _origin.y) {
        _origin.y = *floor;  // on the floor or a step up
        _fallSpeed = 0.0;
    } else {
        _fallSpeed += _config.gravity * dt;
        _origin.y = std::max(*floor, _origin.y - _fallSpeed * dt);
        if (_origin.y == *floor) _fallSpeed = 0.0;
    }
}

void Navigator::updateWalk(double dt) {
    accelerateTowards(steeringVelocity(true), dt);
    // Move along world X, then Z, each checked on its own: the clearance is kept across each
    // axis, and a walk at an angle to a wall slides along it instead of sticking.
    const glm::dvec3 move = _velocity * dt;
    glm::dvec3 kept(0.0);
    for (const glm::dvec3 axis : {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)}) {
        const glm::dvec3 part = axis * glm::dot(move, axis);
        const double length = glm::length(part);
        if (length == 0.0) continue;
        const double free = freeDistance(part);
        _origin += part * (free / length);
        if (free == length) kept += axis * glm::dot(_velocity, axis);  // a blocked axis stops
    }
    _velocity = kept;
    if (_world) walkOnFloor(dt);
}

void Navigator::updateGrab() {
    if (!_grabbing) return;
    // worldFromCave0 * caveFromHand0 * inverse(caveFromHand), keeping translation and yaw only.
    const double handYaw = yawOf(forwardOf(_hand.orientation));
    _yaw = _grabYaw + angleDifference(handYaw, _grabHandYaw);
    _origin = _grabOrigin + rotateY(_grabYaw, _grabHand) - rotateY(_yaw, _hand.position);
}

glm::dvec3 Navigator::guidePoint(double s, glm::dvec3* tangent) const {
    const auto it = std::upper_bound(_guideLengths.begin(), _guideLengths.end(), s);
    std::size_t i = it == _guideLengths.begin() ? 0 : static_cast<std::size_t>(it - _guideLengths.begin()) - 1;
    i = std::min(i, _guide.size() - 2);
    const double len = _guideLengths[i + 1] - _guideLengths[i];
    const double u = len > 0.0 ? std::clamp((s - _guideLengths[i]) / len, 0.0, 1.0) : 0.0;
    if (tangent) *tangent = len > 0.0 ? (_guide[i + 1] - _guide[i]) / len : glm::dvec3(0.0, 0.0, -1.0);
    return glm::mix(_guide[i], _guide[i + 1], u);
}

double Navigator::closestGuideDistance(const glm::dvec3& p) const {
    double best = 0.0, bestDistance = INFINITY;
    for (std::size_t i = 0; i + 1 < _guide.size(); ++i) {
        const glm::dvec3 a = _guide[i], ab = _guide[i + 1] - a;
        const double len2 = glm::dot(ab, ab);
        const double u = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
        const double d = glm::length(p - (a + ab * u));
        if (d < bestDistance) {
            bestDistance = d;
            best = _guideLengths[i] + u * std::sqrt(len2);
        }
    }
    return best;
}

void Navigator::updateGuided(double dt) {
    if (_guide.size() < 2) return;
    const glm::dvec3 before = guidePoint(_guideS);
    _guideOffset = glm::dvec3(_origin.x - before.x, 0.0, _origin.z - before.z);  // keeps joystick turns
    _guideS = std::min(_guideS + _config.guidePace * _speedScale * dt, _guideLengths.back());
    accelerateTowards(steeringVelocity(true), dt);
    _guideOffset += _velocity * dt;
    const double r = glm::length(_guideOffset);
    if (r > _config.corridorRadius) {
        const double excess = (r - _config.corridorRadius) * std::exp(-dt / _config.pullBackSeconds);
        _guideOffset *= (_config.corridorRadius + excess) / r;
    }
    glm::dvec3 tangent;
    const glm::dvec3 anchor = guidePoint(_guideS, &tangent);
    _origin = anchor + _guideOffset;
    if (glm::length(horizontal(tangent)) > 0.0) {
        turn(angleDifference(_yaw, yawOf(tangent)) * (1.0 - std::exp(-dt / _config.alignSeconds)));
        _guideOffset = glm::dvec3(_origin.x - anchor.x, 0.0, _origin.z - anchor.z);
        _origin.y = anchor.y;
    }
}

HandCursor Navigator::handCursor() const {
    HandCursor c;
    c.hand = _hand;
    c.rayOrigin = _hand.position;
    c.rayDirection = glm::normalize(forwardOf(_hand.orientation));
    c.rayLength = _config.pickDistance;
    if (_world) {
        const glm::dvec3 from = glm::dvec3(worldFromCave() * glm::dvec4(c.rayOrigin, 1.0));
        if (auto hit = _world->castRay(from, toWorldDirection(c.rayDirection), _config.pickDistance)) {
            c.rayLength = *hit;
            c.hit = true;
        }
    }
    return c;
}

}  // namespace cavewall::input
