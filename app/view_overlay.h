#pragma once
// What a windowed session shows besides the scene: one status line over each window (the
// navigation mode, the movement speed, the last frame's time, what the walls draw and how far
// baking has come, the tracker's state and "F1: help"), or the help page while it is toggled
// on, and each window's title. Plain text; display::gl::Context draws it
// (display/overlay_text.h) and never into saved or compared images.

#include "display/overlay_text.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::app {

struct ViewStatus {
    std::string_view navigation;    // "fly", "walk", "grab", "guided" or "none"
    std::optional<double> speed{};  // m/s of a movement key (the desktop), else none
    double frameMs = 0.0;           // the last frame's time
    bool help = false;              // the help page instead of the status line
    double degreesPerPixel = 0.15;  // mouse look, for the help page
    // What the walls draw: "geometry" (no walls), "control" (cells without textures), "walls"
    // (textures), "hierarchy" (Maciel & Shirley's clusters); empty: not shown.
    std::string_view drawing{};
    int texturesToBake = 0;      // baking on demand: textures still to bake (0: none or done)
    int texturesBaked = 0;       // baked so far by this session
    std::string_view tracker{};  // "" (desktop or simulated), "no data", "data"
};

// The status line, e.g. "fly | 2.50 m/s | 16.7 ms | walls | F1: help", then a second line while
// there is more to say: "baking walls 12/340, geometry meanwhile" while baking on demand,
// "tracker: no data" for a network tracker. With help, the help page (helpLines) comes first.
display::OverlayText viewOverlay(const ViewStatus& status);

// The keys of the desktop fallback and the session (input/desktop_navigator.h,
// input/session_keys.h), one per line.
std::vector<std::string> helpLines(double degreesPerPixel);

// "cavewall - <screen> - <navigation>".
std::string windowTitle(std::string_view screen, std::string_view navigation);

}  // namespace cavewall::app
