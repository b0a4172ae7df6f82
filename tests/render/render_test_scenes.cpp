#include "tests/render/render_test_scenes.h"

#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace cavewall::render::testing {

config::DisplayConfig oneScreen(int pixels) {
    config::DisplayConfig c;
    c.name = "one";
    // Headless, any rank, no warp and no blend.
    c.screens.push_back(
        {"screen", {-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {pixels, pixels}, std::nullopt, {}, -1, "", ""});
    c.viewer.near = 0.05;
    c.viewer.far = INFINITY;
    config::validateDisplayConfig(c, "test");
    return c;
}

int addCube(scenes::Scene& scene, glm::dvec3 centre, double size, const Look& look) {
    scenes::Material material;
    material.baseColorFactor = look.color;
    material.alphaMode = look.alpha;
    material.doubleSided = look.doubleSided;
    material.baseColorTexture.image = look.image;
    scene.materials.push_back(material);
    scenes::Mesh m = scenes::makeBox(glm::vec3(static_cast<float>(size)), glm::vec4(1.0f));
    m.material = static_cast<int>(scene.materials.size()) - 1;
    scene.meshes.push_back(std::move(m));
    glm::dmat4 worldFromModel = glm::translate(glm::dmat4(1.0), centre);
    if (look.mirrored) worldFromModel = glm::scale(worldFromModel, glm::dvec3(-1, 1, 1));
    return scenes::addObject(scene, static_cast<int>(scene.meshes.size()) - 1, worldFromModel, "cube", look.role);
}

int addImage(scenes::Scene& scene) {
    scene.images.push_back({"pixel", 1, 1, {255, 255, 255, 255}});
    return static_cast<int>(scene.images.size()) - 1;
}

scenes::Bounds box(glm::dvec3 lo, glm::dvec3 hi) {
    scenes::Bounds b;
    b.add(lo);
    b.add(hi);
    return b;
}

}  // namespace cavewall::render::testing
