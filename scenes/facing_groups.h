#pragma once
// Facing groups: a large mesh's triangles ordered into groups of similar facing and place, so
// that a renderer can skip, before any vertex is shaded, every group whose triangles all face
// away from the eye (back-face culling per group, on the CPU).
//
// Why: llvmpipe shades every vertex of a draw and rejects back faces only after, in its single
// vertex and set-up thread. A closed mesh seen from anywhere has about half its triangles facing
// away; grouped by facing (six classes, by the dominant axis of the triangle's geometric normal)
// and by place (a grid over the mesh's bounds), whole groups face away and are never submitted.
//
// The test is conservative: a group is reported facing away only when every one of its
// triangles is, for every point of the group's bounds. With the group's normals within an angle
// s of its axis a (sinSpread = sin s, cosSpread = cos s), a triangle with unit geometric normal
// n faces away from eye e when n . (p - e) > 0 for its points p. For all n within s of a and all
// p in the bounds B this holds when a . (p - e) > |p - e| sin s for every p in B (the angle
// between a and p - e is below 90° - s), which follows from
//     min_B a . (p - e)  >  max_B |p - e| * sin s,
// evaluated with min_B a.(p-e) = a.(c - e) - sum_k |a_k| h_k and max_B |p - e| <= |c - e| + |h|
// (c, h: the bounds' centre and half size). Model space throughout: which side of a plane the
// eye lies on survives any affine transform, mirrors included (a mirrored object's front faces
// turn clockwise, and the renderer culls accordingly).

#include "scenes/scene.h"

#include <cstdint>
#include <vector>

namespace cavewall::scenes {

// FacingGroup: scenes/scene.h (Mesh::facingGroups).

struct FacingOptions {
    std::size_t minTriangles = 4096;      // smaller meshes stay one range (no groups)
    std::size_t trianglesPerGroup = 2048; // aimed at: the grid is about cbrt(triangles / 6 / this) per side
    int maxGridDivisions = 16;            // per side
};

// Orders the triangles of `mesh` (at least options.minTriangles of them, else nothing changes
// and the result is empty) by facing class, then grid cell, keeping their order within a
// group (the vertex-cache order, when it was made first); degenerate triangles join class 0.
// Sets mesh.facingGroups to the groups, in index order, covering every index once (empty when
// nothing changed) and returns their number.
std::size_t groupByFacing(Mesh& mesh, const FacingOptions& options = {});

// Whether `mesh.facingGroups` cover its indices exactly, in order (a mesh whose indices were
// changed after grouping no longer does; renderers then ignore the groups).
bool facingGroupsValid(const Mesh& mesh);

// Whether every triangle of `group` faces away from `eyeModel` (the eye in the mesh's model
// frame), by the conservative test above. Never true for a group whose spread reaches 90°.
bool facesAway(const FacingGroup& group, const glm::dvec3& eyeModel);

}  // namespace cavewall::scenes
