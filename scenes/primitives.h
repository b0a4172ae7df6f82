#pragma once
// Small procedural meshes for built-in and generated scenes: boxes, cylinders and tiled quads
// with per-vertex colours. All are model-local, counter-clockwise front faces, with normals.

#include "scenes/scene.h"

namespace cavewall::scenes {

// An axis-aligned box centred at the origin with edge lengths `size`.
Mesh makeBox(glm::vec3 size, glm::vec4 color);

// A cylinder along +Y from y = 0 to `height`, `segments` around, capped.
Mesh makeCylinder(float radius, float height, int segments, glm::vec4 color);

// A quad from `origin` spanned by `right` and `up` (front face towards cross(right, up)), cut
// into tilesX x tilesY tiles coloured alternately `a` and `b` (a checkerboard grid).
Mesh makeTiledQuad(glm::vec3 origin, glm::vec3 right, glm::vec3 up, int tilesX, int tilesY, glm::vec4 a, glm::vec4 b);

// Appends `src` (transformed by `m`, normals by its inverse transpose) to `dst`.
void appendMesh(Mesh& dst, const Mesh& src, const glm::mat4& m = glm::mat4(1.0f));

// The built-in test scene: a 10 m x 3 m x 10 m room centred on the origin with a checkerboard
// floor (1 m tiles), tiled walls and ceiling, and coloured boxes (red, green, blue, yellow,
// magenta) around the centre; a CAVE standing at the origin sees all of it.
Scene builtinTestScene();

}  // namespace cavewall::scenes
