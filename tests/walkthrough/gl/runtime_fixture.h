#pragma once
// Shared set-up of the walkthrough GL tests: a small generated plant (20 k triangles) planned
// and baked once per test program into the test output folder, and helpers to place the viewer.

#include "config/display_config.h"
#include "display/display.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walkthrough/gl/walkthrough.h"

#include <filesystem>
#include <optional>

namespace cavewall::testing {

struct SmallPlant {
    std::filesystem::path sceneFile;
    scenes::Scene scene;
    scenes::SceneDescription description;
    walls::WallSetup walls;  // planned with alpha 20°, zones >= 4 m, 2 texels/degree
};

// Generated, planned and baked on first use (bakes with its own headless context).
const SmallPlant& smallPlant();

// Two open cells, A (x in [-10, 0]) and B (x in [0, 10]), z in [-5, 5], split by the virtual
// wall "A|B" on x = 0 (4 m high, front facing A). Structure is only the floor; content is a
// red box in B (x = 5, 1 m x 3 m x 8 m) and a green one in A. Nothing else: where the box is
// not drawn, the clear colour shows. Planned with alpha 10°, zones >= 2 m, 4 texels/degree.
const SmallPlant& twoCells();

// cave4 at `pixels` x `pixels` per screen, optionally separate stereo with `eyeSeparation`.
display::Display testDisplay(int pixels, bool stereo = false, double eyeSeparation = 0.064);

// worldFromCave that puts the default head (0, 1.7, 0) at world `eye`, the CAVE's front wall
// facing +X (towards the plant's wall A|B from cell A).
glm::dmat4 cavePlacedAt(glm::dvec3 eye);

// Index of the wall named `name` in the plan.
int wallIndex(const walls::WallSetup& walls, const std::string& name);

}  // namespace cavewall::testing
