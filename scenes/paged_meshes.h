#pragma once
// Which meshes geometry paging loads together, GL-free. Paging is by cell
// (scenes::pagedWithCell), but a CAD export shares meshes between cells (one mesh per part
// kind, placed in many bays): storing a mesh once per cell would make the paged model larger
// than the whole one. So the paged meshes are grouped by the exact set of cells whose objects
// use them (every cell of each object: a wall of two rooms pages with both), and a group is the unit that is uploaded, counted and freed: a cell's geometry is
// the union of its groups, a group is stored once however many resident cells use it, and the
// resident meshes are the union of the resident cells' meshes. A mesh used by one cell only
// lands in that cell's own group (a model with unique meshes pages exactly by cell); a mesh
// used by any always-resident object (structure, no cell) is in no group: it stays in the
// shared buffers and every object using it draws from there.

#include "scenes/scene.h"

#include <vector>

namespace cavewall::scenes {

struct PagedMeshGroups {
    std::vector<int> groupOfMesh;               // per mesh: its group, or -1 (always resident or unused)
    std::vector<std::vector<int>> groupMeshes;  // per group: its meshes, ascending
    std::vector<std::vector<int>> groupCells;   // per group: the cells that use it, ascending
    std::vector<std::vector<int>> cellGroups;   // per cell (`cellCount`): the groups its objects use, ascending
    int groupCount() const { return static_cast<int>(groupMeshes.size()); }
};

// Groups the meshes of `scene`'s paged objects (pagedWithCell with `cellCount`); groups are
// numbered in the order of their first mesh, so the result is deterministic.
PagedMeshGroups pagedMeshGroups(const Scene& scene, int cellCount);

}  // namespace cavewall::scenes
