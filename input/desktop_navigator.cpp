#include "input/desktop_navigator.h"

#include "input/pose_math.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace cavewall::input {
namespace {

NavigatorConfig bodyConfig(const DesktopNavigatorConfig& c) {
    NavigatorConfig n = c.navigator;
    n.maxSpeed = c.speed;
    n.maxAcceleration = c.accelerationPerSpeed * c.speed;
    n.joystickTurns = false;  // A and D strafe; the mouse turns
    return n;
}

}  // namespace

double viewSpeed(double diagonal, bool standingInside) {
    if (!std::isfinite(diagonal) || !(diagonal > 0.0)) return 1.0;
    const double speed = std::clamp(diagonal / 20.0, 0.05, 5.0);
    return standingInside ? std::min(speed, kWalkingSpeed) : speed;
}

DesktopNavigator::DesktopNavigator(DesktopNavigatorConfig config, Pose head, const WorldQuery* world)
    : _config(config), _head(head), _world(world), _nav(bodyConfig(config), world) {
    feedNavigator();
}

void DesktopNavigator::setMode(NavMode mode) {
    _nav.handle({EventType::ButtonUp, 0.0, 0, {}});  // a trigger held in grab must not walk on
    _grabOffset = glm::dvec2(0.0);
    feedNavigator();
    _nav.setMode(mode);
}

void DesktopNavigator::setGuidePath(std::vector<glm::dvec3> points) { _nav.setGuidePath(std::move(points)); }

void DesktopNavigator::setBody(const glm::dvec3& origin, double yaw) { _nav.setWorldFromCave(origin, yaw); }

void DesktopNavigator::setEye(const glm::dvec3& eye, double yaw) {
    _pitch = 0.0;
    const glm::dvec3 headBody(_head.position.x, _config.eyeHeight, _head.position.z);
    _nav.setWorldFromCave(eye - rotateY(yaw, headBody), yaw);
}

glm::dmat4 DesktopNavigator::caveFromBody() const {
    const glm::dvec3 right = _head.orientation * glm::dvec3(1.0, 0.0, 0.0);
    const glm::dmat4 pitchAboutHead = glm::translate(glm::dmat4(1.0), _head.position) *
                                      glm::mat4_cast(glm::angleAxis(_pitch, right)) *
                                      glm::translate(glm::dmat4(1.0), -_head.position);
    const glm::dmat4 lift = glm::translate(glm::dmat4(1.0), {0.0, _config.eyeHeight - _head.position.y, 0.0});
    return glm::inverse(lift * pitchAboutHead);
}

glm::dmat4 DesktopNavigator::worldFromCave() const { return _nav.worldFromCave() * glm::inverse(caveFromBody()); }

glm::dvec3 DesktopNavigator::eyeWorld() const { return glm::dvec3(worldFromCave() * glm::dvec4(_head.position, 1.0)); }

Pose DesktopNavigator::bodyPose(const Pose& cavePose) const {
    return transformPose(glm::inverse(caveFromBody()), cavePose);
}

double DesktopNavigator::speed() const {
    return _config.speed * _scale * (_keys.count(kKeyShift) ? _config.fastFactor : 1.0);
}

// The hand in the body frame: handDistance in front of the eyes, moved by a grab's drag.
Pose DesktopNavigator::handInBody() const {
    Pose hand = bodyPose({_head.position + forwardOf(_head.orientation) * _config.handDistance, _head.orientation});
    const double headYaw = yawOf(forwardOf(_head.orientation));
    hand.position += rotateY(headYaw, glm::dvec3(_grabOffset.x, 0.0, _grabOffset.y));
    return hand;
}

HandCursor DesktopNavigator::handCursor() const {
    const Pose body = handInBody();
    HandCursor c;
    c.hand = transformPose(caveFromBody(), body);
    c.rayOrigin = c.hand.position;
    c.rayDirection = glm::normalize(forwardOf(c.hand.orientation));
    c.rayLength = _config.navigator.pickDistance;
    if (_world) {
        const glm::dvec3 from(_nav.worldFromCave() * glm::dvec4(body.position, 1.0));
        const glm::dvec3 along = rotateY(_nav.yaw(), glm::normalize(forwardOf(body.orientation)));
        if (auto hit = _world->castRay(from, along, c.rayLength)) {
            c.rayLength = *hit;
            c.hit = true;
        }
    }
    return c;
}

void DesktopNavigator::look(const glm::dvec2& pixels) {
    const double k = glm::radians(_config.degreesPerPixel), maxPitch = glm::radians(_config.maxPitchDeg);
    _pitch = std::clamp(_pitch - pixels.y * k, -maxPitch, maxPitch);
    // Turn the body about the head: the eye stays where it is.
    const glm::dvec3 eye = eyeWorld(), headBody(_head.position.x, _config.eyeHeight, _head.position.z);
    const double yaw = _nav.yaw() - pixels.x * k;
    _nav.setWorldFromCave(eye - rotateY(yaw, headBody), yaw);
}

void DesktopNavigator::sendSpeed() { _nav.handle({EventType::SpeedScale, 0.0, 0, {speed() / _config.speed, 0.0}}); }

void DesktopNavigator::handle(const Event& e) {
    switch (e.type) {
        case EventType::MouseMove:
            if (!std::isfinite(e.value.x) || !std::isfinite(e.value.y)) break;
            if (mode() == NavMode::Grab && _leftButton)
                _grabOffset += e.value * (speed() * _config.grabSecondsPerPixel);
            else
                look(e.value);
            break;
        case EventType::KeyDown:
        case EventType::KeyUp: handleKey(e.code, e.type == EventType::KeyDown); break;
        case EventType::Scroll:
            if (!std::isfinite(e.value.y)) break;
            _scale = std::clamp(_scale * std::pow(_config.scrollStep, e.value.y), _config.minScale, _config.maxScale);
            sendSpeed();
            break;
        case EventType::ButtonDown:
        case EventType::ButtonUp:
            if (e.code != 0) break;
            _leftButton = e.type == EventType::ButtonDown;
            if (mode() == NavMode::Grab) {
                feedNavigator();  // the grab starts from the hand where it is now
                _nav.handle(e);
            }
            break;
        default: break;
    }
}

void DesktopNavigator::handleKey(int code, bool down) {
    const bool letter = code >= 'A' && code <= 'Z';
    if (down && letter && _keys.count(kKeyControl)) return;  // Ctrl+Q and the like are the session's
    if (down)
        _keys.insert(code);
    else
        _keys.erase(code);
    if (code == kKeyShift) sendSpeed();
    if (down && code >= '1' && code <= '4') setMode(static_cast<NavMode>(code - '1'));
}

double DesktopNavigator::axis(int positive, int negative) const {
    return (_keys.count(positive) ? 1.0 : 0.0) - (_keys.count(negative) ? 1.0 : 0.0);
}

void DesktopNavigator::feedNavigator() {
    WandState wand;
    wand.joystick = {axis('D', 'A'), axis('W', 'S')};
    _nav.setTracking(bodyPose(_head), handInBody(), wand);
}

void DesktopNavigator::updateFly(double dt) {
    const glm::dmat4 world = worldFromCave();
    const glm::dvec3 forward = glm::dvec3(world * glm::dvec4(forwardOf(_head.orientation), 0.0));
    const glm::dvec3 right = glm::dvec3(world * glm::dvec4(_head.orientation * glm::dvec3(1, 0, 0), 0.0));
    const glm::dvec3 move = forward * axis('W', 'S') + right * axis('D', 'A') + glm::dvec3(0, 1, 0) * axis('E', 'Q');
    _nav.setWorldFromCave(_nav.origin() + move * (speed() * dt), _nav.yaw());
}

void DesktopNavigator::update(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) return;
    feedNavigator();
    if (mode() == NavMode::Fly)
        updateFly(dt);
    else
        _nav.update(dt);
}

}  // namespace cavewall::input
