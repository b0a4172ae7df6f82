#pragma once
// The fold-out picture of a display: every screen's image laid flat in one canvas, like the net
// of a box, so one picture shows what a whole CAVE showed.
//
// The layout unfolds the screens into the plane of a root screen. The root is the floor (the
// screen facing up, +Y) when there is one, otherwise the screen sharing edges with the most
// others (the front wall of a floorless CAVE), ties going to the first. Screens that share an
// edge with an unfolded screen are hinged about that edge into the root plane, recursively; so
// for a CAVE the walls fold out around the floor: front above it, left to its left, right to
// its right, back below it, and the ceiling above the front. Screens parallel to the root that
// share no edge (a power wall with bezels) are placed where they are on the wall (projected
// onto the root plane); any other unconnected screen is turned flat about its own centre.
//
// Canvas: pixels, x right, y down, origin at the top-left corner; the root screen's up is the
// canvas' up. The root (floor) is seen from its front side, as its own image shows it.
// GL-free: compose the pixels with whatever holds images.

#include "config/display_config.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace cavewall::display {

struct FoldoutTile {
    int screen = 0;               // index into the screens
    glm::ivec2 resolution{0, 0};  // that screen's image size, pixels
    // Affine map from canvas positions to the screen's image positions (both in pixels, x right,
    // y down, origin at the top-left corner), applied to (x, y, 1).
    glm::dmat3 imageFromCanvas{1.0};
};

struct FoldoutSample {
    int screen = 0;
    glm::ivec2 pixel{0, 0};  // pixel in that screen's image (x right, y down)
    bool operator==(const FoldoutSample&) const = default;
};

struct FoldoutLayout {
    glm::ivec2 size{0, 0};  // canvas pixels
    double pixelsPerMetre = 0.0;
    std::vector<FoldoutTile> tiles;  // root first, then in unfolding order

    // Which screen pixel shows at canvas pixel `canvas` (sampled at its centre): the first tile
    // that covers it, or nullopt for background.
    std::optional<FoldoutSample> sample(glm::ivec2 canvas) const;
};

// The layout for `screens` (a validated configuration). `pixelsPerMetre` <= 0 picks the finest
// screen's pixel density, so no screen loses detail; the canvas is then clamped to at most
// config::kMaxResolution pixels per side by lowering the density.
FoldoutLayout foldoutLayout(const std::vector<config::Screen>& screens, double pixelsPerMetre = 0.0);

}  // namespace cavewall::display
