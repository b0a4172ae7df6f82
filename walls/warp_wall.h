#pragma once
// One wall drawn warped in a frame (Transition::Warp, walls/gl/warp_pass.h) and the GL-free
// geometry of its warp: the texture's frustum A, the view's clip-from-world B and the warp W
// between them (display/warp.h). The frame planner uses them to test conditioning; the warp
// pass uses them to draw.

#include "display/display.h"
#include "display/off_axis.h"

#include <glm/glm.hpp>

namespace cavewall::walls {

struct WarpWall {
    display::ScreenQuad quad;       // world frame, as seen from the texture's side (quadSeenFrom)
    glm::dvec3 samplingPoint{0.0};  // world, of the texture the structure is warped to
    int cell = -1;                  // also draw this cell's objects warped (warp-morph); -1: structure only
};

inline constexpr double kWarpTextureNear = 0.05;  // the baker's near plane (walls/gl/wall_renderer.h)

// The texture frustum A of `wall`: the quad as screen, the sampling point as eye, depth from
// kWarpTextureNear to infinity.
display::OffAxisFrustum warpTextureFrustum(const WarpWall& wall);
// B's clip from world for `view`: clipFromView · viewFromFrame · caveFromWorld.
glm::dmat4 clipFromWorldOf(const display::ScreenView& view, const glm::dmat4& caveFromWorld);
// The warp W of `wall` into `view` (display/warp.h); `nearB` is the display's near plane.
glm::dmat4 warpFor(const WarpWall& wall, const display::ScreenView& view, const glm::dmat4& caveFromWorld,
                   double nearB);

}  // namespace cavewall::walls
