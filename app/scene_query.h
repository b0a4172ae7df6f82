#pragma once
// input::WorldQuery over a scene's structure, for walk navigation: the floor under the viewer
// and the distance to the first wall along a ray. A small CPU query: the structure objects'
// triangles in the world frame, grouped per object and tested only when the object's world
// bounds are hit. Content (machines, furniture) neither carries nor blocks the viewer.
// Lives in app/, above both, because input may not depend on scenes.

#include "input/navigator.h"
#include "scenes/scene.h"

#include <array>
#include <vector>

namespace cavewall::app {

class SceneQuery : public input::WorldQuery {
public:
    // Copies the structure triangles of `scene` (world frame); keeps no reference.
    explicit SceneQuery(const scenes::Scene& scene);

    // Highest upward-facing structure surface at or below `point` (within maxDrop), world y.
    std::optional<double> floorBelow(const glm::dvec3& point, double maxDrop) const override;
    // First structure triangle hit from `origin` along unit `direction`, within maxDistance.
    std::optional<double> castRay(const glm::dvec3& origin, const glm::dvec3& direction,
                                  double maxDistance) const override;

    std::size_t triangleCount() const;

private:
    struct Group {
        scenes::Bounds bounds;
        std::vector<std::array<glm::dvec3, 3>> triangles;
    };
    std::vector<Group> _groups;
};

// Möller-Trumbore: the ray parameter t >= 0 of the hit with triangle (a, b, c), either side.
std::optional<double> rayTriangle(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a,
                                  const glm::dvec3& b, const glm::dvec3& c);

}  // namespace cavewall::app
