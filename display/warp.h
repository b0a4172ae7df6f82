#pragma once
// Aliaga & Lastra's (1997) geometry warp (their section 2) for textured virtual walls.
//
// A wall texture is baked with the frustum A = offAxisFrustum(wall, samplingPoint, ...): the
// wall quad is the "screen", so the texture's NDC square [-1, 1]² is exactly the wall. Drawn at
// run time from another eye, geometry next to the texture (floor, side walls crossing the wall
// plane) no longer lines up with the texture's image of the geometry behind the wall. The warp
// makes it line up: a vertex x is projected through the sampling point onto the wall plane (A),
// and that wall point q is drawn where the current view B sees it. So behind-the-wall geometry
// lands exactly on its image in the texture, and anything on the wall plane stays where it is
// (C0 continuity across the wall plane).
//
//   clip = W · clipFromWorldA · x       (W = warpMatrix(A, wall, clipFromWorldB))
//
// W acts on A's homogeneous clip coordinates (x, y, ·, w) as the 4-corner perspective mapping
// of the wall square into B's clip space (its x, y, w rows), and passes A's depth through: with
// reversed-Z, the warped depth is B's depth of q scaled by dA / wA(x) ∈ (0, 1], so warped
// geometry keeps A's depth order among itself and always lies behind the wall plane for B (near
// geometry in front of the wall still occludes it). A must have an infinite far plane (then
// A's z_clip is the constant nearA, which the z row turns into dA · nearB).
//
// Conditioning: as B's eye approaches the wall plane, the wall projects to a line and W becomes
// singular. warpCondition() gives the 2-norm condition number of W's 3x3 core (x, y, w rows on
// A's (x, y, w)); the runtime falls back to geometry above kMaxWarpCondition and flags it.

#include "display/off_axis.h"

namespace cavewall::display {

// Above this condition number the warp is not used (see above): float's relative precision of
// 6e-8 amplified 1e4 times is 6e-4 of the image, a third of a pixel at 1024 pixels. For a
// CAVE-sized view the condition grows like 3 m / (eye distance from the wall plane), so the
// guard trips within about 0.3 mm of the plane.
inline constexpr double kMaxWarpCondition = 1e4;

// The warp for texture frustum `a` (built by offAxisFrustum(wall, samplingPoint, {near, inf}))
// of `wall` (both in the world frame) into the current view `clipFromWorldB` (reversed-Z,
// e.g. clipFromView · viewFromCave · caveFromWorld of one screen and eye). `nearB` is B's
// near plane.
glm::dmat4 warpMatrix(const OffAxisFrustum& a, const ScreenQuad& wall, const glm::dmat4& clipFromWorldB, double nearB);

// The 2-norm condition number of the warp's 3x3 core (1 for a pure similarity, +inf when
// singular).
double warpCondition(const glm::dmat4& warp);

}  // namespace cavewall::display
