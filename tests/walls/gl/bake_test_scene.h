#pragma once
// A small scene for the bake tests, built in code and written as GLB + scene.json: a 6 m x 16 m
// hall (x in [-3, 3], z in [-8, 8]) cut at z = 0 by one 3 m high virtual wall facing +z, so cell
// 0 "front" is z > 0 and cell 1 "back" is z < 0. A structure floor spans both cells. Content:
//  - back cell: a red box, a green box and a blue box at different depths (behind the wall
//    seen from the front: baked into side-0 textures);
//  - front cell: a yellow box (baked into side-1 textures);
//  - a magenta box straddling the wall (intersecting: never baked).

#include "scenes/generate.h"
#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <string>

namespace cavewall::walls::gl::testing {

struct BakeTestObjects {
    int floor, red, green, blue, yellow, magenta;  // Scene::objects indices
};

inline int addBox(scenes::Scene& s, glm::vec3 size, glm::vec4 color, glm::dvec3 centre, const std::string& name) {
    s.meshes.push_back(scenes::makeBox(size, color));
    return scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre), name);
}

// `shift` moves the red box along x (metres), to test that a change re-bakes only what it touches.
inline scenes::GeneratedScene bakeTestScene(BakeTestObjects* objects = nullptr, double shift = 0.0) {
    scenes::GeneratedScene g;
    scenes::Scene& s = g.scene;
    s.name = "bake-test";
    BakeTestObjects o{};
    s.meshes.push_back(
        scenes::makeTiledQuad({-3, 0, 8}, {6, 0, 0}, {0, 0, -16}, 6, 16, {0.5f, 0.5f, 0.5f, 1}, {0.3f, 0.3f, 0.3f, 1}));
    o.floor = scenes::addObject(s, 0, glm::dmat4(1.0), "structure/floor", scenes::Role::Structure);
    o.red = addBox(s, {1.0f, 1.5f, 1.0f}, {0.9f, 0.1f, 0.1f, 1}, {-1.2 + shift, 0.75, -2.5}, "red");
    o.green = addBox(s, {1.5f, 2.5f, 0.8f}, {0.1f, 0.8f, 0.2f, 1}, {1.0, 1.25, -5.0}, "green");
    o.blue = addBox(s, {0.6f, 0.6f, 0.6f}, {0.1f, 0.2f, 0.9f, 1}, {0.2, 2.2, -7.0}, "blue");
    o.yellow = addBox(s, {1.0f, 1.0f, 1.0f}, {0.9f, 0.9f, 0.1f, 1}, {0.5, 0.5, 4.0}, "yellow");
    o.magenta = addBox(s, {0.5f, 0.5f, 1.0f}, {0.8f, 0.1f, 0.8f, 1}, {-2.0, 1.5, 0.0}, "magenta");
    if (objects) *objects = o;

    scenes::SceneDescription& d = g.description;
    d.name = "bake-test";
    scenes::ModelFile model;
    model.file = "bake-test.glb";
    model.structureNodes = {"structure/*"};
    d.models.push_back(model);
    // Counter-clockwise seen from above: from +x towards -z (scene_description.h).
    d.cells.push_back({"front", {{3, 8}, {3, 0}, {-3, 0}, {-3, 8}}, 0.0});
    d.cells.push_back({"back", {{3, 0}, {3, -8}, {-3, -8}, {-3, 0}}, 0.0});
    scenes::VirtualWall w;
    w.name = "middle";
    w.lowerLeft = {-3, 0, 0};
    w.lowerRight = {3, 0, 0};
    w.upperLeft = {-3, 3, 0};
    w.cells = {0, 1};
    d.walls.push_back(w);
    d.headHeightRange = {1.2, 2.0};
    return g;
}

// Writes the scene to `dir` and returns the scene.json path.
inline std::filesystem::path writeBakeTestScene(const std::filesystem::path& dir, double shift = 0.0) {
    scenes::GeneratedScene g = bakeTestScene(nullptr, shift);
    return scenes::writeGenerated(g, dir);
}

}  // namespace cavewall::walls::gl::testing
