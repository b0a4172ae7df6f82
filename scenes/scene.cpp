#include "scenes/scene.h"

namespace cavewall::scenes {

Bounds Bounds::transformed(const glm::dmat4& m) const {
    Bounds out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
        out.add(glm::dvec3(m * glm::dvec4(corner, 1.0)));
    }
    return out;
}

Bounds Scene::bounds() const {
    Bounds b;
    for (const Object& o : objects) b.add(o.worldBounds);
    return b;
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Object& o : objects) n += meshes[o.mesh].triangleCount();
    return n;
}

void Scene::updateObjectBounds() {
    for (Object& o : objects) {
        o.worldBounds = meshes[o.mesh].bounds.transformed(o.worldFromModel);
        o.flipWinding = glm::determinant(o.worldFromModel) < 0.0;
    }
}

int addObject(Scene& scene, int mesh, const glm::dmat4& worldFromModel, std::string name, Role role) {
    Object o;
    o.name = std::move(name);
    o.mesh = mesh;
    o.worldFromModel = worldFromModel;
    o.role = role;
    o.worldBounds = scene.meshes[mesh].bounds.transformed(worldFromModel);
    o.flipWinding = glm::determinant(worldFromModel) < 0.0;
    scene.objects.push_back(std::move(o));
    return static_cast<int>(scene.objects.size()) - 1;
}

}  // namespace cavewall::scenes
