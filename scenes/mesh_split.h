#pragma once
// Cutting large meshes into chunks, so that a model exported as one huge mesh (a game level, a
// merged CAD export: the real SponzaLOD4 and zdm2 models are one mesh each) can be culled per
// view and divided into cells: a cell draws every object it overlaps
// (scenes/cell_assignment.h), so one object spanning the whole building is drawn by every cell
// and defeats every frustum test.
//
// splitLargeObjects cuts each object of role `role` (content by default; the loader also cuts
// wide structure, scenes/loader.h) of scene.objects[first, end) whose world bounds are wider
// than `chunkMetres` along x or z (the floor plane, where cells are cut) and that has at least
// `minTriangles` triangles: its triangles are grouped by the square column of side
// `chunkMetres` (world x, z from the object's bounds' minimum) holding their world centroid;
// each group becomes a mesh of its own (its vertices copied with every attribute the mesh has,
// indices renumbered, triangle order kept) and an object with the same placement, winding,
// role and material, named "<name> [chunk i,j]". Triangles are not clipped: a chunk's bounds
// reach as far as its triangles do. An object left in one group is unchanged. A mesh no longer
// used by any object is removed (mesh indices renumbered); a mesh shared by several objects is
// cut for each of them that is split (the chunks are not shared), so split only what needs it.
// Deterministic. Returns how many objects were cut.

#include "scenes/scene.h"

#include <cstddef>

namespace cavewall::scenes {

struct SplitStats {
    int objectsCut = 0;  // objects replaced by chunks
    int chunks = 0;      // objects they became
};

// Throws cavewall::Error when chunkMetres is not finite and > 0.
SplitStats splitLargeObjects(Scene& scene, std::size_t first, std::size_t end, double chunkMetres,
                             std::size_t minTriangles = 1024, Role role = Role::Content);

}  // namespace cavewall::scenes
