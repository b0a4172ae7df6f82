#pragma once
// "View all": navigating the CAVE so that a whole model is in view (display/ cannot see scene
// bounds, so it lives here).
//
// The CAVE is only translated through the world (no rotation, no scale: the model keeps its
// real size). The screen chosen is the one the head faces most directly (the largest dot
// product between the head's forward direction, -Z turned by its orientation, and the
// direction from the eye to the screen's centre). The model's bounding sphere is placed on the
// ray from the eye through that screen's centre, just far enough that the sphere lies inside
// all four side planes of the eye-screen pyramid, and at least `near` beyond the eye. Every
// point of the model then projects inside that screen (the sphere is conservative: the box may
// fill less of it).

#include "display/display.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

namespace cavewall::render {

struct ViewAll {
    glm::dmat4 worldFromCave{1.0};  // pure translation
    int screen = -1;                // the screen the model is framed in; -1 for empty bounds
    double distance = 0.0;          // metres from the eye to the sphere's centre
};

// `bounds` in the world frame (metres). Empty bounds give the identity. `head` in the cave
// frame; the cyclopean eye (head position) is used.
ViewAll viewAll(const display::Display& display, const display::HeadPose& head, const scenes::Bounds& bounds);

}  // namespace cavewall::render
