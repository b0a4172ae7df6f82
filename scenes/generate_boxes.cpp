// The box hall: a peer-comparison mesh that any viewer draws the same way, so a measured frame
// time compares draw paths and not scene handling.
#include "scenes/generate.h"
#include "scenes/generate_parts.h"
#include "scenes/mesh_tools.h"
#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

namespace cavewall::scenes {

Scene generateBoxHall(const GenerateOptions& options) {
    const std::size_t target = options.triangles ? options.triangles : kBoxHallDefaultTriangles;
    const std::size_t boxes = (target + 11) / 12;
    Rng rng(options.seed);
    Mesh hall;
    hall.name = "boxes";
    hall.positions.reserve(boxes * 24);
    hall.normals.reserve(boxes * 24);
    hall.indices.reserve(boxes * 36);
    for (std::size_t i = 0; i < boxes; ++i) {
        const glm::vec3 size(static_cast<float>(rng.uniform(kBoxHallMinEdge, kBoxHallMaxEdge)),
                             static_cast<float>(rng.uniform(kBoxHallMinEdge, kBoxHallMaxEdge)),
                             static_cast<float>(rng.uniform(kBoxHallMinEdge, kBoxHallMaxEdge)));
        // Centres keep every box inside the hall: [-30, 30] x [0, 8] x [-15, 15].
        const glm::vec3 half = 0.5f * size;
        const glm::vec3 centre(
            static_cast<float>(rng.uniform(-0.5 * kBoxHallSize.x + half.x, 0.5 * kBoxHallSize.x - half.x)),
            static_cast<float>(rng.uniform(half.y, kBoxHallSize.y - half.y)),
            static_cast<float>(rng.uniform(-0.5 * kBoxHallSize.z + half.z, 0.5 * kBoxHallSize.z - half.z)));
        appendMesh(hall, makeBox(size, glm::vec4(1.0f)), glm::translate(glm::mat4(1.0f), centre));
    }
    // One material gives the colour; vertex colours and texture coordinates would only be
    // data that an OBJ copy cannot carry.
    hall.colors.clear();
    hall.texCoords0.clear();
    hall.material = 0;
    updateBounds(hall);
    Scene scene;
    scene.name = "boxes";
    Material grey;
    grey.name = "boxes";
    grey.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    scene.materials.push_back(grey);
    scene.meshes.push_back(std::move(hall));
    addObject(scene, 0, glm::dmat4(1.0), "boxes");
    return scene;
}

}  // namespace cavewall::scenes
