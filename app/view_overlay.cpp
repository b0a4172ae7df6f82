#include "app/view_overlay.h"

#include <cstdio>

namespace cavewall::app {
namespace {

std::string statusLine(const ViewStatus& s) {
    char text[160];
    std::string line(s.navigation);
    if (s.speed) {
        std::snprintf(text, sizeof text, " | %.2f m/s", *s.speed);
        line += text;
    }
    std::snprintf(text, sizeof text, " | %.1f ms", s.frameMs);
    line += text;
    if (!s.drawing.empty()) line += " | " + std::string(s.drawing);
    return line + " | F1: help";
}

// Baking and the tracker, when there is something to say; empty otherwise.
std::string stateLine(const ViewStatus& s) {
    char text[160];
    std::string line;
    if (s.texturesToBake > 0) {
        std::snprintf(text, sizeof text, "baking walls %d/%d, geometry meanwhile", s.texturesBaked,
                      s.texturesBaked + s.texturesToBake);
        line = text;
    }
    if (!s.tracker.empty()) line += (line.empty() ? "" : " | ") + std::string("tracker: ") + std::string(s.tracker);
    return line;
}

}  // namespace

std::vector<std::string> helpLines(double degreesPerPixel) {
    char look[96];
    std::snprintf(look, sizeof look, "mouse (click, or drag): look around, %.2f deg per pixel", degreesPerPixel);
    return {"keys",
            look,
            "W A S D: forward, left, back, right",
            "Q E: down, up (fly)",
            "Shift: 4x faster while held; wheel: speed x1.25 per step",
            "1 2 3 4: fly, walk, grab (drag the world), guided",
            "F1 or H: this help",
            "Esc: free the pointer; Esc again: quit",
            "Ctrl+Q: quit"};
}

display::OverlayText viewOverlay(const ViewStatus& s) {
    display::OverlayText overlay;
    if (s.help) overlay.lines = helpLines(s.degreesPerPixel);
    overlay.lines.push_back(statusLine(s));
    if (const std::string state = stateLine(s); !state.empty()) overlay.lines.push_back(state);
    return overlay;
}

std::string windowTitle(std::string_view screen, std::string_view navigation) {
    return "cavewall - " + std::string(screen) + " - " + std::string(navigation);
}

}  // namespace cavewall::app
