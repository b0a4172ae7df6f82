#include "display/stereo.h"

namespace cavewall::display {

const char* toString(Eye eye) {
    switch (eye) {
        case Eye::Center: return "center";
        case Eye::Left: return "left";
        case Eye::Right: return "right";
    }
    return "?";
}

glm::dvec3 eyePosition(glm::dvec3 head, const glm::dquat& orientation, double separation, Eye eye) {
    const double side = eye == Eye::Left ? -0.5 : eye == Eye::Right ? 0.5 : 0.0;
    return head + orientation * glm::dvec3(side * separation, 0.0, 0.0);
}

int imagesPerScreen(config::StereoMode mode) { return mode == config::StereoMode::Separate ? 2 : 1; }

std::vector<EyePass> eyePasses(config::StereoMode mode, glm::ivec2 resolution) {
    using config::StereoMode;
    const Viewport full{0, 0, resolution.x, resolution.y};
    EyePass left{Eye::Left, 0, full};
    EyePass right{Eye::Right, 0, full};
    switch (mode) {
        case StereoMode::Mono: return {EyePass{Eye::Center, 0, full}};
        case StereoMode::Separate: right.image = 1; break;
        case StereoMode::SideBySide: {
            const int half = resolution.x / 2;
            left.viewport = {0, 0, half, resolution.y};
            right.viewport = {half, 0, resolution.x - half, resolution.y};
            break;
        }
        case StereoMode::TopBottom: {
            const int half = resolution.y / 2;
            right.viewport = {0, 0, resolution.x, half};
            left.viewport = {0, half, resolution.x, resolution.y - half};
            break;
        }
        case StereoMode::Anaglyph:
            left.colorMask = {true, false, false, true};
            right.colorMask = {false, true, true, true};
            break;
        case StereoMode::QuadBuffer: right.backRight = true; break;
    }
    return {left, right};
}

}  // namespace cavewall::display
