#pragma once
// Preparing meshes for drawing: welding split vertices and ordering triangles and vertices for
// the GPU's vertex cache. Pure functions on model-local float data; the drawn shape and the
// triangle count never change (within the stated tolerances).
//
// CAD exports and simple generators often store every face with its own vertices (a triangle
// soup): every triangle then shades three new vertices and a simplifier (scenes/mesh_lod.h) sees
// no connectivity. Welding restores the shared vertices wherever the attributes agree; where
// they do not (a hard edge, a texture seam), the vertices stay apart but get exactly the same
// position, which is how the simplifier recognises a seam.

#include "scenes/scene.h"

#include <cstddef>

namespace cavewall::scenes {

// Tolerances under which two vertices are the same. Positions are compared per coordinate
// (Chebyshev distance); the position tolerance is relative to the mesh's largest extent, but
// never below 4 float ulps of its largest coordinate (coordinates far from the origin carry
// less precision than that).
struct WeldTolerance {
    double relativePosition = 1e-6;  // of the largest bounds extent
    float normal = 1e-4f;            // per component of unit normals
    float texCoord = 1e-6f;          // per component, texture units
    float color = 1e-5f;             // per component, linear colour
};

struct WeldResult {
    std::size_t verticesBefore = 0, verticesAfter = 0;
    std::size_t positionsSnapped = 0;  // vertices moved (by at most the tolerance) onto a twin
};

// Merges vertices whose positions and attributes agree within `tolerance` and rewrites the
// indices; vertices at the same position with different attributes keep their own slot but
// get bit-identical positions. Unused vertices are dropped. Triangles and their order are
// kept (degenerate ones too), and bounds are recomputed.
WeldResult weldVertices(Mesh& mesh, const WeldTolerance& tolerance = {});

// Reorders the triangles for a small vertex cache (meshoptimizer's Forsyth-style optimiser) and
// then the vertices in first-use order. Changes which triangle is drawn first, so callers leave
// out meshes whose material blends (their triangle order is their drawing order).
void optimizeVertexOrder(Mesh& mesh);

// The average number of vertex shader runs per triangle for a FIFO cache of `cacheSize`
// vertices (3 for a triangle soup, about 0.6-0.8 for a well-ordered closed mesh).
double averageCacheMissRatio(const Mesh& mesh, unsigned cacheSize = 16);

}  // namespace cavewall::scenes
