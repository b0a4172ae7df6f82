#pragma once
// Text over a window (the session's status line and help page), laid out as plain triangles
// without GL: display/gl/overlay_pass.h draws them. Glyphs are stb_easy_font's (Sean Barrett,
// public domain; Debian's libstb-dev): ASCII 32-126 as axis-aligned quads of a 7-unit-high
// font on 12-unit lines; other bytes (line breaks included) draw nothing and take no room.
//
// Layout in window pixels, origin at the window's top-left corner, y down. The lines start
// `margin` pixels in from the top-left corner, each glyph unit `scale` pixels; behind them is
// one backdrop rectangle, `padding` pixels larger than the text on every side.

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace cavewall::display {

struct OverlayText {
    std::vector<std::string> lines;              // top to bottom; none: nothing is drawn
    float scale = 2.0f;                          // pixels per font unit
    float margin = 8.0f;                         // pixels from the window's top-left corner
    float padding = 6.0f;                        // pixels of backdrop around the text
    glm::vec4 colour{1.0f, 1.0f, 1.0f, 1.0f};    // text, straight alpha
    glm::vec4 backdrop{0.0f, 0.0f, 0.0f, 0.6f};  // behind the text, straight alpha
    bool operator==(const OverlayText&) const = default;
};

struct OverlayVertex {
    glm::vec2 position;  // window pixels, y down
    glm::vec4 colour;    // straight alpha
};

// Triangles (three vertices each), the backdrop's first, to be drawn in order with alpha
// blending. Empty for no lines.
std::vector<OverlayVertex> layoutOverlay(const OverlayText& text);

// The text's size in pixels without margin and padding: the widest line and the lines' height.
glm::vec2 overlayTextSize(const OverlayText& text);

// `text` with its scale lowered, if needed, so that the widest line with margin and padding fits
// `windowWidth` pixels; never below 1 pixel per font unit (a narrower window cuts the line).
OverlayText fitOverlay(OverlayText text, float windowWidth);

}  // namespace cavewall::display
