#pragma once
// When the headlight may be evaluated per vertex instead of per pixel, with a proven bound on
// the difference.
//
// The scene shader (render/gl/scene_shaders.h) lights a surface by a headlight at the eye:
// light = ambient + (1 - ambient) * diffuse, diffuse = |n . v|, where n is the unit normal
// (turned towards the eye on back faces) and v the unit vector from the surface point to the
// eye. Per pixel this costs llvmpipe a normal and a position varying per vertex, their set-up
// per triangle and a normalisation per fragment; per vertex (Gouraud) the vertex shader
// evaluates the light and hands the fragment stage one colour. On the 1 M-triangle box hall at
// 1024², drawing everything per vertex took 11-14 % less time (docs/levels-of-detail.md).
//
// Per vertex is used only where it is provably invisible. For a triangle whose vertex normals
// all equal its face normal (up to sign; the mesh is "flat" there) and whose vertex colours are
// equal, the per-pixel diffuse term is f(x) = |n . x| / |x| (x: the point relative to the eye)
// with one constant n, and the per-vertex one is the linear (perspective-correct, i.e.
// barycentric in 3D) interpolation L of f at the vertices. f has a constant sign on the
// triangle's plane. Its second derivative along a unit direction w in that plane (n . w = 0) is,
// with u = x/|x|, b = u.w, c = n.u:  w^T H w = c (3 b^2 - 1) / |x|^2, and since b^2 <= 1 - c^2,
// |c (3 b^2 - 1)| <= max(|c|, |c| (2 - 3 c^2)) <= 1: the Hessian along the plane is at most
// 1 / d^2, d the least distance from the eye to the triangle. Taylor's theorem at x towards each
// vertex x_i (barycentric weights l_i, sum l_i x_i = x) gives
//     |f(x) - L(x)| <= (1 / (2 d^2)) sum_i l_i |x_i - x|^2 <= R^2 / (2 d^2),
// because sum_i l_i |x_i - x|^2 = sum_i l_i |x_i - c|^2 - |x - c|^2 <= R^2 for the centre c and
// radius R of the triangle's smallest enclosing circle, and R <= e / sqrt(3) for its longest
// edge e (Jung's theorem in the plane). So
//     |per pixel - per vertex| <= (e / d)^2 / 6    (diffuse; light differs by (1 - ambient) times that)
// Normals count as equal within kFlatNormalSlack (each unit of normal deviation moves the
// diffuse term by at most as much, at a vertex and at the pixel), which the bound adds as
// 2 * kFlatNormalSlack. The render list takes d from the object's world bounds (a lower bound).
//
// kVertexLightingTolerance: 1/512 of the light factor. Turned into sRGB bytes it is at most half
// a step for any base colour when ambient >= 0.35 (the sRGB slope, 1.055/2.4 * y^(-0.583) for
// y > 0.0031, times 255 and the colour, is at most 206 per unit of light at light >= 0.35).
// Tests check the bound on random triangles and eyes and that it is not loose by 2x
// (tests/render/vertex_lighting_test.cpp).

#include "scenes/scene.h"

#include <cstdint>
#include <span>

namespace cavewall::render {

inline constexpr double kVertexLightingTolerance = 1.0 / 512.0;
inline constexpr double kFlatNormalSlack = 1e-4;  // |n_vertex - (+-n_face)|, unit vectors

// The longest edge (model units) of the triangles `indices` of `mesh` names, when every one of
// them is flat (vertex normals within kFlatNormalSlack of the face normal or its opposite, equal
// vertex colours when the mesh has colours; degenerate triangles are skipped), else -1. 0 for no
// triangles. Indices out of range make it -1 (never vertex-lit).
double flatMaxEdge(const scenes::Mesh& mesh, std::span<const std::uint32_t> indices);

// The bound above on the difference of the diffuse term, for a flat mesh level with longest edge
// `edge` (world units, >= 0) drawn with every point at least `distance` from the eye; +infinity
// when distance <= 0 or not finite.
double vertexLightingError(double edge, double distance);

// Whether a draw of a level with flatMaxEdge `edge` (model units; < 0: not flat), scaled by
// `stretch` into the world, at least `distance` from the eye may be lit per vertex under
// `tolerance` (<= 0: never).
bool litPerVertex(double edge, double stretch, double distance, double tolerance);

}  // namespace cavewall::render
