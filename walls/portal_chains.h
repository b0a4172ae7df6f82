#pragma once
// Which openings each cell drawn as geometry is seen through, for portal culling
// (render/portal_cull.h; Luebke & Georges 1995).
//
// From the viewer's cell E, everything outside E that a walls frame shows is seen through E's
// virtual walls: a neighbour drawn as geometry (its wall in a geometry zone or blend strip, or a
// wall that fell back to geometry) through the walls between E and it and those of E whose
// textures show it (VisibilityTable::throughWalls), and a cell beyond such a
// neighbour (Plan::beyond) through the chain of walls that leads there (the wall of E, then the
// far wall; three walls at the second level). So a view need not draw the parts of those cells
// that no such chain shows. Every wall and every beyond side planned for E counts, whatever its
// weight this frame, so the sets depend on E only and a view misses nothing a chain shows.
//
// A cell E sees directly (CellVisibility::Geometry: joined through open boundaries) is on E's
// storey, so a line of sight from E's eye to it leaves E's floor polygon through its side: through
// one of E's walls or through E's open boundary (walls/visibility.h: openBoundary), each part of
// which is an opening from 1 km below E's floor to 1 km above it. Such a cell is seen through any
// one of those openings. E itself, structure and objects without a cell are drawn without test,
// as is an object one of whose drawn cells is, and every cell when E has no opening at all.
// So is an object over or under E's floor box, whatever its cells: a cell of another storey
// stacked with E is seen within E's column, through a void or a stairwell, not through E's side.
//
// What this leaves out is what the textures leave out too: what real walls hide in the
// visibility model (walls/visibility.h) and what lies past a virtual wall's top.

#include "render/portal_cull.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/plan.h"
#include "walls/visibility.h"

#include <array>
#include <vector>

namespace cavewall::walls {

using PortalSets = render::PortalSets;

class PortalChains {
public:
    // Keeps nothing of its arguments; `table` must be the plan's cells' visibility of
    // `description`.
    PortalChains(const Plan& plan, const VisibilityTable& table, const scenes::SceneDescription& description);

    // The chains through which `cell` is seen from `eyeCell`, as indices into portals(); empty
    // when it is seen without test (the eye's own cell, or no chain known).
    const std::vector<std::vector<int>>& chains(int eyeCell, int cell) const;

    // The portal sets of a frame whose viewer is in `eyeCell` and which draws the cells marked
    // in `drawn` (per description cell): portals() as they are, one set per combination of
    // drawn cells seen through chains that an object belongs to, and objectSet over `scene`'s
    // objects. No sets (every object drawn without test) when eyeCell is outside every cell.
    void frameSets(int eyeCell, const std::vector<bool>& drawn, const scenes::Scene& scene,
                   render::PortalSets& out) const;

    // Every opening, its normal towards the side it is looked through from: Plan::walls[w]
    // seen from side s (from its cells[s], walls::quadSeenFrom) is 2w + s; then each cell's open
    // boundary parts, facing into the cell.
    const std::vector<display::ScreenQuad>& portals() const { return _quads; }

private:
    std::vector<std::vector<int>>& at(int eyeCell, int cell);
    bool valid(int cell) const;
    void addWallChains(const Plan& plan, const VisibilityTable& table, std::vector<std::vector<int>>& openings);
    void addBeyondChains(const Plan& plan);

    int _cellCount = 0;
    std::vector<display::ScreenQuad> _quads;             // walls, then open boundary parts
    std::vector<std::vector<std::vector<int>>> _chains;  // [eyeCell * cellCount + cell]
    std::vector<std::array<glm::dvec2, 2>> _columns;     // per cell: its floor box (x, z), shrunk
};

}  // namespace cavewall::walls
