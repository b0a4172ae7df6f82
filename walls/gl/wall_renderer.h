#pragma once
// Renders one wall texture: the scene renderer (render/gl/scene_renderer.h) drawing a
// subset of the scene into an offscreen sRGB target through display::offAxisFrustum with the
// eye at the sampling point and the wall quad as the screen. No projection code of its own.
//
// Levels of detail (lodTexels > 0): every mesh's level chain is built once (scenes/mesh_lod.h)
// and each texture draws every object at the coarsest level whose sampled geometric error
// covers at most lodTexels texels of that texture, seen from its sampling point
// (render::chooseFrustumLods: the exact pixels-per-radian bound of the wall quad as the
// screen, the same choice the walkthrough makes per frame). Objects outside the texture's
// frustum are culled either way (render/render_list.h).

#include "render/gl/scene_renderer.h"
#include "display/off_axis.h"
#include "render/lod_choice.h"
#include "scenes/scene.h"
#include "walls/depth_wall.h"
#include "walls/gl/offscreen_target.h"

#include <memory>
#include <vector>

namespace cavewall::walls::gl {

class WallTextureRenderer {
public:
    // Uploads `scene`; needs a current GL 4.5 context, in which every later call is made.
    // `ambient` as render::gl::RenderSettings::ambient; `lodTexels` > 0: draw at levels of detail
    // whose error covers at most that many texels (see above); 0: full detail.
    WallTextureRenderer(const scenes::Scene& scene, float ambient, double lodTexels = 0.0);

    // Draws `objects` (Scene::objects indices; structure is skipped even when listed) seen from
    // `eye` (world) through `quad` (world; its front side faces the eye) at `resolution` texels
    // and reads the result back: 8-bit RGBA, sRGB-encoded colour premultiplied by alpha (where a
    // blended surface lies over nothing; straight and premultiplied agree where alpha is 0 or
    // 1: walls::mipChainOfPremultiplied), alpha 0 where nothing was drawn, rows top to bottom
    // (row 0 along the quad's upper edge). Depth range 0.05 m to infinity, reversed-Z.
    scenes::Image render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                         const std::vector<int>& objects);

    // As render(), and the depth of every texel behind the wall plane (walls/depth_wall.h:
    // metres along the wall's normal, kNoSurface where nothing was drawn), from the same frame's
    // 32-bit float depth buffer. A texel where only translucent (blended) surfaces were drawn,
    // such as a window with nothing behind it, has the depth of the nearest of them (a second,
    // depth-only pass, drawn only for textures that have such texels).
    scenes::Image render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                         const std::vector<int>& objects, walls::DepthImage& depth);

    const display::ViewStats& lastStats() const { return _stats; }
    // The levels the last render() drew (all 0, maxErrorPx 0 at full detail).
    const render::FrameLod& lastLod() const { return _lod; }

    // Wall-clock milliseconds of the last render() on the calling thread.
    struct Timing {
        double drawMs = 0.0;  // level choice, culling, submission and the GL work until finished
        double readMs = 0.0;  // reading the colour (and depth) back, rows flipped
    };
    const Timing& lastTiming() const { return _timing; }

private:
    scenes::Image draw(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                       const std::vector<int>& objects);
    // `objects` without structure, at the last render()'s levels of detail.
    render::DrawFilter filterFor(const std::vector<int>& objects) const;
    void addTranslucentDepth(const scenes::Image& colour, const std::vector<int>& objects,
                             std::vector<float>& bufferDepth);

    double _lodTexels = 0.0;
    std::vector<bool> _blended;  // per scene object: its material blends (glass)
    render::gl::SceneRenderer _renderer;
    std::unique_ptr<OffscreenTarget> _target;  // reallocated when the resolution changes
    display::ViewStats _stats;
    display::OffAxisFrustum _lastFrustum;
    render::FrameLod _lod;
    Timing _timing;
};

}  // namespace cavewall::walls::gl
