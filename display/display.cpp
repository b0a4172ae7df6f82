#include "display/display.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace cavewall::display {

Display::Display(config::DisplayConfig config) : _config(std::move(config)) {
    for (const auto& s : _config.screens) _quads.push_back({s.lowerLeft, s.lowerRight, s.upperLeft});
}

std::vector<ScreenView> Display::views(const HeadPose& head) const {
    std::vector<ScreenView> out;
    for (int i = 0; i < static_cast<int>(_quads.size()); ++i) {
        for (const EyePass& pass : eyePasses(_config.stereo, _config.screens[i].resolution)) {
            const glm::dvec3 eye = eyePosition(head.position, head.orientation, _config.viewer.eyeSeparation, pass.eye);
            out.push_back({i, pass, offAxisFrustum(_quads[i], eye, depthRange(), _config.minEyeDistance)});
        }
    }
    return out;
}

bool Display::reframes(int screen) const {
    const auto& window = _config.screens[screen].window;
    return window && window->reframe;
}

bool Display::reframe(int screen, glm::ivec2 window) {
    if (!reframes(screen) || window.x <= 0 || window.y <= 0) return false;
    const config::Screen& s = _config.screens[screen];
    const ScreenQuad quad = reframedQuad({s.lowerLeft, s.lowerRight, s.upperLeft}, window);
    if (quad == _quads[screen]) return false;
    _quads[screen] = quad;
    return true;
}

ScreenQuad reframedQuad(const ScreenQuad& quad, glm::ivec2 window) {
    const ScreenBasis b = screenBasis(quad);
    const glm::dvec3 centre = quad.lowerLeft + 0.5 * (b.width * b.right + b.height * b.up);
    const double width = b.height * static_cast<double>(window.x) / static_cast<double>(window.y);
    const glm::dvec3 lowerLeft = centre - 0.5 * (width * b.right + b.height * b.up);
    return {lowerLeft, lowerLeft + width * b.right, lowerLeft + b.height * b.up};
}

std::string imageStem(const Display& display, const ScreenView& view) {
    const config::Screen& s = display.screens()[view.screen];
    std::string stem = s.headless.file.empty() ? s.name : s.headless.file;
    if (imagesPerScreen(display.config().stereo) == 2) stem += view.pass.eye == Eye::Left ? "-left" : "-right";
    return stem;
}

namespace {

nlohmann::json toJson(glm::dvec3 v) { return {v.x, v.y, v.z}; }

nlohmann::json toJson(const glm::dmat4& m) {
    nlohmann::json a = nlohmann::json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) a.push_back(m[c][r]);
    return a;
}

}  // namespace

nlohmann::json frustumJson(const Display& display, const std::vector<ScreenView>& views) {
    nlohmann::json screens = nlohmann::json::array();
    const DepthRange depth = display.depthRange();
    for (const ScreenView& v : views) {
        const config::Screen& s = display.screens()[v.screen];
        screens.push_back({
            {"name", s.name},
            {"eye", toString(v.pass.eye)},
            {"lowerLeft", toJson(s.lowerLeft)},
            {"lowerRight", toJson(s.lowerRight)},
            {"upperLeft", toJson(s.upperLeft)},
            {"eyePosition", toJson(v.frustum.eye)},
            {"resolution", {s.resolution.x, s.resolution.y}},
            {"near", depth.near},
            {"far", std::isinf(depth.far) ? nlohmann::json(nullptr) : nlohmann::json(depth.far)},
            {"view", toJson(v.frustum.viewFromFrame)},
            {"projection", toJson(v.frustum.clipFromView)},
            {"eyeGuard", toString(v.frustum.guard)},
        });
    }
    return {{"depth", "reversed-Z: depth = z_clip / w_clip in [0, 1], 1 at near, 0 at far (or infinity)"},
            {"screens", screens}};
}

}  // namespace cavewall::display
