#pragma once
// Building blocks of the generated scenes (internal): a portable random generator and a mesh
// builder that turns boxes and cylinders into one coloured Mesh, with a detail level that
// controls how finely round parts are tessellated (and so the triangle count).

#include "scenes/scene.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cavewall::scenes {

// splitmix64: the same numbers on every platform and standard library.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : _state(seed) {}
    std::uint64_t next();
    double uniform(double lo, double hi);  // [lo, hi)
    int below(int n);                       // [0, n)
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

private:
    std::uint64_t _state;
};

// Appends parts to one mesh. Cylinders get 6 * detail segments (at least 6).
struct PartBuilder {
    Mesh mesh;
    int detail = 1;

    void box(glm::vec3 centre, glm::vec3 size, glm::vec4 color);
    // Along +Y from `base`, or along `axis` (0 = x, 1 = y, 2 = z) centred at `centre`.
    void cylinderY(glm::vec3 base, float radius, float height, glm::vec4 color);
    void cylinderAlong(int axis, glm::vec3 centre, float radius, float length, glm::vec4 color);
    // Finishes the mesh: drops texture coordinates (the generators use vertex colours), bounds.
    Mesh finish(std::string name);
};

// Kinds of content, each a function of the detail level (and a variant for machine tools).
Mesh makeMachineTool(int variant, int detail);
Mesh makeRobot(int detail);
Mesh makeConveyor(int detail);
Mesh makeCabinet(int detail);
Mesh makePipeRack(int detail);
// House furniture.
Mesh makeTable(int detail);
Mesh makeChair(int detail);
Mesh makeSofa(int detail);
Mesh makeBed(int detail);
Mesh makeShelf(int detail);
Mesh makeLamp(int detail);

// One placement of a part kind, before meshes exist.
struct Placement {
    int kind = 0;                 // index into the generator's kind list
    glm::dmat4 worldFromModel{1.0};
    std::string name;
};

// Smallest detail level (1..256) at which the placed content plus `fixedTriangles` reaches
// `target` drawn triangles (triangle counts are linear in the detail); `kinds(detail)` builds
// the meshes. Returns the meshes built at that level.
std::vector<Mesh> meshesForTarget(const std::vector<Placement>& placements, std::size_t fixedTriangles,
                                  std::size_t target, const std::function<std::vector<Mesh>(int)>& kinds);

}  // namespace cavewall::scenes
