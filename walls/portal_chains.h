#pragma once
// Which virtual walls each cell drawn as geometry is seen through, for portal culling
// (render/portal_cull.h; Luebke & Georges 1995).
//
// From the viewer's cell E, everything outside E that a walls frame shows is seen through E's
// virtual walls: a neighbour drawn as geometry (its wall in a geometry zone or blend strip, or a
// wall that fell back to geometry) through the walls between E and it, and a cell beyond such a
// neighbour (Plan::beyond) through the chain of walls that leads there (the wall of E, then the
// far wall; three walls at the second level). So a view need not draw the parts of those cells
// that no such chain shows. Every wall and every beyond side planned for E counts, whatever its
// weight this frame, so the sets depend on E only and a view misses nothing a chain shows. E
// itself, cells E sees through open boundaries (CellVisibility::Geometry), structure and objects
// without a cell are drawn without test, as is an object one of whose drawn cells is.
//
// What this leaves out is what the textures leave out too: a neighbour seen past the virtual
// walls (through a gap between a portal and the real wall around it) is drawn in no zone.

#include "render/portal_cull.h"
#include "scenes/scene.h"
#include "walls/plan.h"
#include "walls/visibility.h"

#include <vector>

namespace cavewall::walls {

using PortalSets = render::PortalSets;

class PortalChains {
public:
    // Keeps nothing of its arguments; `table` must be the plan's cells' visibility.
    PortalChains(const Plan& plan, const VisibilityTable& table);

    // The chains (indices into Plan::walls) through which `cell` is seen from `eyeCell`; empty
    // when it is seen without test (the eye's own cell, an open boundary, or no chain known).
    const std::vector<std::vector<int>>& chains(int eyeCell, int cell) const;

    // The portal sets of a frame whose viewer is in `eyeCell` and which draws the cells marked
    // in `drawn` (per description cell): portals are the planned walls' quads, one set per
    // drawn cell seen through chains, and objectSet over `scene`'s objects. No sets (every
    // object drawn without test) when eyeCell is outside every cell.
    void frameSets(int eyeCell, const std::vector<bool>& drawn, const scenes::Scene& scene,
                   render::PortalSets& out) const;

private:
    int _cellCount = 0;
    std::vector<display::ScreenQuad> _quads;             // parallel to Plan::walls
    std::vector<std::vector<std::vector<int>>> _chains;  // [eyeCell * cellCount + cell]
};

}  // namespace cavewall::walls
