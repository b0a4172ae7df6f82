#pragma once
// Building blocks of the generated scenes (internal): a portable random generator and a mesh
// builder that turns boxes and cylinders into one coloured Mesh, with a detail level that sets
// the triangle count.
//
// Detail, for the plant's kinds (PartBuilder::cadLike): levels 1 to kFullTessellation refine
// round parts (6 segments per level) until they reach a CAD export's chordal deviation of
// kChordalDeviation, and never beyond it; every level above adds sub-parts (bolts, buttons,
// tool holders, cable links, rollers, valves, vents) in proportion, as large CAD models get
// their triangles from many parts rather than from ever finer circles. For the house's
// furniture the level only refines round parts (6 segments per level).

#include "scenes/scene.h"

#include <algorithm>
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
    int below(int n);                      // [0, n)
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

private:
    std::uint64_t _state;
};

inline constexpr int kFullTessellation = 8;
inline constexpr float kChordalDeviation = 0.001f;  // metres

// Appends parts to one mesh. Cylinders get 6 * detail segments (at least 6); with cadLike, at
// most as many as a chordal deviation of kChordalDeviation needs (and 6 * kFullTessellation).
struct PartBuilder {
    Mesh mesh;
    int detail = 1;
    bool cadLike = false;

    int segments(float radius) const;
    // Sub-parts per unit of a kind's repeated features: 0 up to kFullTessellation (cadLike only).
    int density() const { return cadLike ? std::max(0, detail - kFullTessellation) : 0; }

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
    int kind = 0;  // index into the generator's kind list
    glm::dmat4 worldFromModel{1.0};
    std::string name;
};

// Smallest detail level (1..256) at which the placed content plus `fixedTriangles` reaches
// `target` drawn triangles (triangle counts grow with the detail); `kinds(detail)` builds the
// meshes. Returns the meshes built at that level (at 256 when even that falls short).
std::vector<Mesh> meshesForTarget(const std::vector<Placement>& placements, std::size_t fixedTriangles,
                                  std::size_t target, const std::function<std::vector<Mesh>(int)>& kinds);

}  // namespace cavewall::scenes
