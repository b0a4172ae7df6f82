#pragma once
// Mesh clean-up used by the loaders and generators: primitive-mode conversion, normal generation
// and bounds. Pure functions on model-local float data.

#include "scenes/scene.h"

#include <cstdint>
#include <vector>

namespace cavewall::scenes {

// Index lists for a triangle strip or fan of `indices` (glTF vertex order); strips alternate
// winding so every output triangle keeps the strip's front face. Fewer than 3 entries -> empty.
std::vector<std::uint32_t> stripToList(const std::vector<std::uint32_t>& indices);
std::vector<std::uint32_t> fanToList(const std::vector<std::uint32_t>& indices);

// True when the triangle has (numerically) zero area: repeated indices or collinear corners.
bool isDegenerateTriangle(const Mesh& mesh, std::size_t triangle);
std::size_t countDegenerateTriangles(const Mesh& mesh);

// Replaces mesh.normals with area-weighted vertex normals (sum of the unnormalised face
// normals of the triangles using the vertex). Degenerate triangles contribute nothing; a vertex
// used by no non-degenerate triangle gets +Y. The result is always unit length, never NaN.
void generateNormals(Mesh& mesh);

// Recomputes mesh.bounds from the positions.
void updateBounds(Mesh& mesh);

}  // namespace cavewall::scenes
