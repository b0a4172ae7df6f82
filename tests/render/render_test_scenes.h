#pragma once
// Small scenes and a one-screen display for the render-list tests.

#include "config/display_config.h"
#include "render/render_scene.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

namespace cavewall::render::testing {

// One 2 m x 2 m screen on z = -1 (x, y in [-1, 1]), `pixels` square, infinite far plane: from
// an eye at the origin it spans 90° x 90°.
config::DisplayConfig oneScreen(int pixels = 64);

struct Look {
    glm::vec4 color{1.0f};
    scenes::AlphaMode alpha = scenes::AlphaMode::Opaque;
    int image = -1;  // base-colour texture (a Scene::images index), -1: none
    bool doubleSided = false;
    bool mirrored = false;  // worldFromModel mirrors x: clockwise front faces
    scenes::Role role = scenes::Role::Content;
};

// Adds a `size` cube centred at `centre` with its own mesh and material; returns its object index.
int addCube(scenes::Scene& scene, glm::dvec3 centre, double size = 0.5, const Look& look = {});

// The bounds with corners lo and hi.
scenes::Bounds box(glm::dvec3 lo, glm::dvec3 hi);

// Adds a 1 x 1 image so that materials can name a texture; returns its index.
int addImage(scenes::Scene& scene);

}  // namespace cavewall::render::testing
