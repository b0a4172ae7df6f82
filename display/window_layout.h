#pragma once
// Where each screen's window goes on the monitors of a desktop or an image generator: configured
// positions are kept (relative to their monitor), fullscreen windows cover their monitor, and the
// windows without a position are tiled over their monitor's work area in a grid, without
// overlapping, scaled down (keeping their aspect) when they do not fit. The rendered images keep
// the screens' resolution; a smaller window shows them scaled, and a window of another shape
// (resized by the user) shows them whole, undistorted, with black bars (fitImage), unless its
// screen reframes to the window's shape (display/display.h reframedQuad).
//
// Pure: the monitors come from the window system (display/gl); tests give their own.

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cavewall::display {

struct MonitorArea {
    glm::ivec2 position{0, 0};  // top-left corner of the area windows may use (the work area:
                                // without panels and docks), virtual-desktop pixels
    glm::ivec2 size{0, 0};      // pixels, > 0
};

struct WindowWish {
    std::string name;                    // the screen's, for messages
    glm::ivec2 size{0, 0};               // wanted content size, pixels, > 0
    std::optional<glm::ivec2> position;  // content's top-left, relative to the monitor; none: tiled
    int monitor = 0;                     // index into the monitors
    bool fullscreen = false;
    bool borderless = false;  // no title bar: nothing reserved above the content
};

struct WindowPlacement {
    glm::ivec2 position{0, 0};  // content's top-left, virtual-desktop pixels
    glm::ivec2 size{0, 0};      // content size, pixels (at most the wish's)
    double scale = 1.0;         // size / wished size
};

// Title bar height reserved above each decorated tiled window's content, pixels.
constexpr int kTitleBarPixels = 32;

// One placement per wish, in order. Throws cavewall::Error naming the screen when its monitor
// index is not among `monitors` ("screen 'left': window.monitor: expected a monitor index in
// [0, 1] (2 monitors), got 3"). Tiled windows of one monitor share a grid of equal cells chosen
// to lose the least scale; a window is never scaled up.
std::vector<WindowPlacement> layoutWindows(const std::vector<WindowWish>& wishes,
                                           const std::vector<MonitorArea>& monitors);

// Where an image of `image` pixels goes in a window of `window` pixels (both origin lower-left):
// the largest rectangle of the image's aspect that fits, centred, as (x0, y0, x1, y1); the whole
// window when the aspects agree to within a pixel, an empty rectangle when either size is not
// positive (a minimised window).
glm::ivec4 fitImage(glm::ivec2 image, glm::ivec2 window);

}  // namespace cavewall::display
