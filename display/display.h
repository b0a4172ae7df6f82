#pragma once
// The runtime display: a validated configuration turned into screen quads, and the per-frame
// computation of every screen's and eye's frustum from one head pose.

#include "config/display_config.h"
#include "display/off_axis.h"
#include "display/stereo.h"

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace cavewall::display {

// A head pose in the cave frame.
struct HeadPose {
    glm::dvec3 position{0.0, 1.7, 0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // identity: looking down -Z
};

// One screen seen by one eye in one frame.
struct ScreenView {
    int screen = 0;          // index into Display::screens()
    EyePass pass;            // which eye, and where its pixels go
    OffAxisFrustum frustum;  // in the cave frame
};

class Display {
public:
    // `config` must have passed config::validateDisplayConfig.
    explicit Display(config::DisplayConfig config);

    const config::DisplayConfig& config() const { return _config; }
    const std::vector<config::Screen>& screens() const { return _config.screens; }
    const ScreenQuad& quad(int screen) const { return _quads[screen]; }
    DepthRange depthRange() const { return {_config.viewer.near, _config.viewer.far}; }
    HeadPose defaultHead() const { return {_config.viewer.headPosition, _config.viewer.headOrientation}; }
    bool isStereo() const { return _config.stereo != config::StereoMode::Mono; }

    // Every screen and eye for `head`, screens in configuration order, eyes in pass order.
    // Both eyes of a stereo pair share the head pose; a guarded eye is flagged per view.
    std::vector<ScreenView> views(const HeadPose& head) const;

    // Whether `screen` shows in a window that reframes when resized (output.window.resize).
    bool reframes(int screen) const;
    // A reframing screen's quad takes the shape of a window of `window` pixels (reframedQuad,
    // from the configured quad, so the shape never drifts); other screens, and a window without
    // pixels (minimised), keep theirs. The resolution is kept: the image is stretched to the
    // window. True when the quad changed.
    bool reframe(int screen, glm::ivec2 window);

private:
    config::DisplayConfig _config;
    std::vector<ScreenQuad> _quads;
};

// `quad` widened or narrowed about its centre, along its own right axis, to the width/height
// ratio of `window` (pixels, both positive), keeping its height, plane and orientation: a
// desktop window resized to another shape shows more or less of the scene to each side, not the
// same view stretched or between black bars.
ScreenQuad reframedQuad(const ScreenQuad& quad, glm::ivec2 window);

// The file name (without extension) of a view's image: "<file>" for one image per screen,
// "<file>-left" / "<file>-right" for separate stereo; <file> is the headless file stem or the
// screen name.
std::string imageStem(const Display& display, const ScreenView& view);

// The `cavewall frustum --json` document:
// {"screens":[{"name","eye","lowerLeft","lowerRight","upperLeft","eyePosition","resolution",
//              "near","far","view":[16],"projection":[16], "eyeGuard"}]}
// Matrices column-major, clip = projection * view * cave; far is null when infinite.
nlohmann::json frustumJson(const Display& display, const std::vector<ScreenView>& views);

}  // namespace cavewall::display
