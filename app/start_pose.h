#pragma once
// Where a viewer starts in a model that has no walk path (`cavewall view`, `run --start
// inside`): standing on a floor inside the building when one is found, else where the whole
// model is in view.
//
// The floor search, kept simple: B is the model's bounding box. Columns (x, z) are tried from
// B's centre outwards over a 9 x 9 grid spanning the middle half of B's floor plan. In each
// column a ray goes straight down from above B through the objects whose footprint is "large"
// (at least min(2 m, a quarter of B's smaller horizontal side) in x and in z: slabs, not
// chairs), and the lowest surface facing up (normal within 25° of +Y) is the column's floor.
// A column is taken when the eye, eyeHeight above that floor, is inside B and not inside a
// solid: of 16 horizontal rays from the eye (through every object), at most half first meet
// the back of a face. The viewer then faces the direction of the longest of those rays
// (capped at 100 m), the most open view.
//
// Cost: one ray per column against the large objects, 16 rays against all objects (each
// object tested only where the ray meets its bounding box); no index is built.

#include "display/display.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

namespace cavewall::app {

struct StartPose {
    glm::dvec3 eye{0.0};   // world, metres: where the head (cyclopean eye) starts
    double yaw = 0.0;      // radians about +Y; 0 looks down -Z
    bool onFloor = false;  // true: standing on a floor found inside the model
    double floorY = 0.0;   // world y of that floor (onFloor only)
};

// The floor search above; nullopt when no column qualifies (an empty scene, an object with no
// floor).
std::optional<StartPose> findFloorStart(const scenes::Scene& scene, double eyeHeight);

// The view-all pose (render/view_all.h): the eye the display's default head has when the CAVE
// is moved (translated only) so that the whole model is in view, yaw 0. An empty scene gives
// the default head's own position.
StartPose viewAllPose(const scenes::Scene& scene, const display::Display& display);

// findFloorStart, else viewAllPose.
StartPose startPose(const scenes::Scene& scene, const display::Display& display, double eyeHeight);

}  // namespace cavewall::app
