#include "walls/warp_wall.h"

#include "display/warp.h"

#include <limits>

namespace cavewall::walls {

display::OffAxisFrustum warpTextureFrustum(const WarpWall& wall) {
    const display::DepthRange depth{kWarpTextureNear, std::numeric_limits<double>::infinity()};
    return display::offAxisFrustum(wall.quad, wall.samplingPoint, depth);
}

glm::dmat4 clipFromWorldOf(const display::ScreenView& view, const glm::dmat4& caveFromWorld) {
    return view.frustum.clipFromView * view.frustum.viewFromFrame * caveFromWorld;
}

glm::dmat4 warpFor(const WarpWall& wall, const display::ScreenView& view, const glm::dmat4& caveFromWorld,
                   double nearB) {
    return display::warpMatrix(warpTextureFrustum(wall), wall.quad, clipFromWorldOf(view, caveFromWorld), nearB);
}

}  // namespace cavewall::walls
