#pragma once
// Which objects a view draws: plain data read by the render-list builder (render_list.h) and
// the level choice (lod_choice.h).

#include <vector>

namespace cavewall::render {

struct PortalSets;  // render/portal_cull.h

// An object is drawn when every given criterion selects it (and its bounds meet the view's
// frustum, unless frustumCull is false, and may be seen through its portals from the view's
// eye). The default draws all. Pointers are borrowed for the duration of the call only.
struct DrawFilter {
    const std::vector<int>* objects = nullptr;    // only these Scene::objects indices (any order;
                                                  // duplicates and indices out of range are
                                                  // ignored); nullptr: all
    bool skipStructure = false;                   // leave out Role::Structure objects (wall bakes)
    bool frustumCull = true;                      // false: submit every selected object (tests, benchmarks)
    const std::vector<int>* lodLevels = nullptr;  // per object index, the level of detail to draw
                                                  // (chooseLods; clamped to the mesh's levels);
                                                  // nullptr or beyond its end: level 0, full detail
    const PortalSets* portals = nullptr;          // portal culling per view (portal_cull.h); nullptr: none
};

}  // namespace cavewall::render
