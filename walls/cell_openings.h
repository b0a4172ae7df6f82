#pragma once
// The openings of each cell, for portal culling (render/portal_cull.h; Luebke & Georges 1995).
//
// From the viewer's cell E, a line of sight to anything of another cell on E's storey leaves E's
// floor polygon through its side: through one of E's virtual walls or portals, or through a part
// of E's boundary no wall covers (walls/visibility.h: openBoundary), taken as an opening from
// 1 km below E's floor to 1 km above it; real walls occlude, as in the visibility model. So each
// view draws an object of another cell only where its box may be seen through one of E's
// openings. E's own objects, structure, objects without a cell, objects one of whose drawn cells
// is E, and objects over, under or within half a metre of E's floor box (another storey seen
// within E's column through a void or a stairwell; what is in or on E's own walls: a window
// pane, a switch) are drawn without test, and everything when E has no opening. A pane of glass
// (a thin, blended object) within half a metre of the edge of E's floor box is an opening too:
// a window in a real wall.
//
// What this leaves out is what the textures leave out too: what real walls hide in the
// visibility model and what lies past a virtual wall's top.

#include "render/portal_cull.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/plan.h"

#include <array>
#include <vector>

namespace cavewall::walls {

using PortalSets = render::PortalSets;

class CellOpenings {
public:
    // Keeps nothing of its arguments; `plan` is planned for `description`, whose cells hold
    // `scene`'s objects.
    CellOpenings(const Plan& plan, const scenes::SceneDescription& description, const scenes::Scene& scene);

    // The openings of `cell`, as indices into portals(); empty for a cell out of range.
    const std::vector<int>& openings(int cell) const;

    // The portal sets of a frame whose viewer is in `eyeCell` and which draws the cells marked
    // in `drawn` (per description cell): eyeCell's openings as the portals, in openings()'s
    // order, one chain each, one set of all of them, and objectSet over `scene`'s objects (the
    // constructor's scene; the set for those tested, -1 for the others). No portals and no
    // sets (every object drawn without test) when eyeCell is outside every cell or has no
    // opening.
    void frameSets(int eyeCell, const std::vector<bool>& drawn, const scenes::Scene& scene,
                   render::PortalSets& out) const;

    // Every opening, its normal towards the side it is looked through from: Plan::walls[w]
    // seen from side s (from its cells[s], walls::quadSeenFrom) is 2w + s; then per cell its
    // open boundary parts and its windows, facing into the cell.
    const std::vector<display::ScreenQuad>& portals() const { return _quads; }

private:
    int _cellCount = 0;
    std::vector<display::ScreenQuad> _quads;          // walls seen from each side, then per cell
    std::vector<std::vector<int>> _openings;          // per cell: indices into _quads
    std::vector<std::array<glm::dvec2, 2>> _columns;  // per cell: its floor box (x, z) and wall band
};

}  // namespace cavewall::walls
