#pragma once
// Per-frame selection for textured virtual walls (Ebbesmeyer 1997, section 6): from the
// viewer's eye, which cell it is in, which textures each bounding wall shows with which
// weights, and which cells are drawn as geometry.
//
// One cyclopean eye per frame (the head position in the world), shared by both eyes and all
// screens, so stereo never mixes zones and every screen agrees.
//
// Weights are continuous in the eye position and sum to 1 per wall (textures + geometry).
// They follow the planner's layout (walls/zone_layout.cpp): in a wall's floor frame (s along
// the wall, d away from it), zones are rows of columns with blend strips of width b centred on
// every border, and a texture-to-geometry strip [dG, dG + b] in front of the geometry zone.
// A texture's weight is the product of a row tent and a column tent,
//   w = tau(dist_d / b) * tau(dist_s / b),  tau(x) = clamp(1 - x, 0, 1),
// where dist_* is the distance to the texture's core (its validated region less the blend
// strips). Rows and columns each form a partition of unity, so the weights sum to 1; they are
// non-zero only strictly inside the texture's validated region, so the planner's error bound
// holds for every texture drawn with non-zero weight. The far walls beyond a neighbour drawn
// as geometry are weighted the same way over their beyond zones (Plan::beyond), only while the
// eye is inside the zones' eye region; elsewhere they are drawn as geometry.

#include "scenes/scene_description.h"
#include "walls/plan.h"
#include "walls/visibility.h"
#include "walls/zone_index.h"

#include <utility>
#include <vector>

namespace cavewall::walls {

inline constexpr int kMaxWallTextures = 4;  // a blend zone mixes at most 2 rows x 2 columns

struct WallBlend {
    int wall = 0;                                  // index into Plan::walls
    int side = 0;                                  // 0: the viewer is in front of the wall
    int zone = -1;                                 // zone containing the eye, -1 if none
    std::vector<std::pair<int, double>> textures;  // (texture id, weight > 0), by id
    double geometryWeight = 0.0;                   // weight of the cell behind, drawn as geometry
};

struct FrameSelection {
    int cell = -1;  // the viewer's cell, scenes::findCell of the eye; -1 outside every cell (all geometry)
    std::vector<WallBlend> walls;  // every wall bounding the cell
    // The far walls of the neighbours drawn as geometry (the cell behind a wall in its geometry
    // zone or texture->geometry blend strip, or a cell seen through an open boundary): what lies
    // beyond them, blended like a cell's own walls over the zones the planner proved for the
    // eye's region (Plan::beyond), so the bound holds for them too. Only walls the eye faces
    // and whose cell behind is not drawn as geometry; a far wall in one of its geometry zones
    // adds its cell behind, whose far walls are selected the same way (second level); the far
    // walls of a cell added at the second level are not drawn.
    std::vector<WallBlend> beyond;
    std::vector<int> geometryCells;  // cells drawn as geometry this frame, sorted
    bool allGeometry() const { return cell < 0; }
};

class FrameSelector {
public:
    // Keeps references: plan, table and description must outlive the selector.
    FrameSelector(const Plan& plan, const VisibilityTable& table, const scenes::SceneDescription& description);

    FrameSelection select(glm::dvec3 eyeWorld) const;

    // The weights of one side at a floor point (x, z): textures and the geometry weight.
    // Exposed for tests and the stability report.
    WallBlend blendAt(int sideIndex, glm::dvec2 floorPoint) const;

private:
    struct Core {
        int texture = -1;           // -1 for the geometry core
        glm::dvec2 s{0.0}, d{0.0};  // core ranges in the side frame (may be infinite)
    };
    struct SideCores {
        glm::dvec2 origin{0.0}, along{1, 0}, inward{0, 1};
        std::vector<Core> cores;
    };
    SideCores buildSide(const WallSide& side) const;
    WallBlend blend(const WallSide& side, const SideCores& cores, glm::dvec2 floorPoint) const;
    void addBeyond(glm::dvec3 eye, FrameSelection& f) const;

    const Plan& _plan;
    const VisibilityTable& _table;
    const scenes::SceneDescription& _description;
    ZoneIndex _zones;
    std::vector<SideCores> _sides;   // parallel to Plan::sides
    std::vector<SideCores> _beyond;  // parallel to Plan::beyond
};

}  // namespace cavewall::walls
