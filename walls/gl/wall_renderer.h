#pragma once
// Renders one wall texture: the display renderer (display/gl/scene_renderer.h) drawing a
// subset of the scene into an offscreen sRGB target through display::offAxisFrustum with the
// eye at the sampling point and the wall quad as the screen. No projection code of its own.

#include "display/gl/scene_renderer.h"
#include "display/off_axis.h"
#include "scenes/scene.h"
#include "walls/depth_wall.h"
#include "walls/gl/offscreen_target.h"

#include <memory>
#include <vector>

namespace cavewall::gl {

class WallTextureRenderer {
public:
    // Uploads `scene`; needs a current GL 4.5 context, in which every later call is made.
    // `ambient` as gl::RenderSettings::ambient.
    WallTextureRenderer(const scenes::Scene& scene, float ambient);

    // Draws `objects` (Scene::objects indices; structure is skipped even when listed) seen from
    // `eye` (world) through `quad` (world; its front side faces the eye) at `resolution` texels
    // and reads the result back: 8-bit RGBA, sRGB-encoded straight colour, alpha 0 where
    // nothing was drawn, rows top to bottom (row 0 along the quad's upper edge). Depth range
    // 0.05 m to infinity, reversed-Z.
    scenes::Image render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                         const std::vector<int>& objects);

    // As render(), and the depth of every texel behind the wall plane (walls/depth_wall.h:
    // metres along the wall's normal, kNoSurface where nothing was drawn), from the same frame's
    // 32-bit float depth buffer.
    scenes::Image render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                         const std::vector<int>& objects, walls::DepthImage& depth);

    const gl::ViewStats& lastStats() const { return _stats; }

private:
    gl::SceneRenderer _renderer;
    std::unique_ptr<OffscreenTarget> _target;  // reallocated when the resolution changes
    gl::ViewStats _stats;
    display::OffAxisFrustum _lastFrustum;
};

}  // namespace cavewall::gl
