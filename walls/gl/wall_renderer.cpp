#include "walls/gl/wall_renderer.h"

#include <limits>

namespace cavewall::gl {

WallTextureRenderer::WallTextureRenderer(const scenes::Scene& scene, float ambient)
    : _renderer(scene, gl::RenderSettings{glm::vec4(0.0f), ambient}) {}

scenes::Image WallTextureRenderer::render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                                          const std::vector<int>& objects) {
    if (!_target || _target->size() != resolution) _target = std::make_unique<OffscreenTarget>(resolution);
    const display::OffAxisFrustum frustum =
        display::offAxisFrustum(quad, eye, {0.05, std::numeric_limits<double>::infinity()});
    gl::ViewTarget target;
    target.framebuffer = _target->framebuffer();
    target.viewport = {0, 0, resolution.x, resolution.y};
    target.clearColor = glm::vec4(0.0f);  // alpha 0: nothing behind the wall here
    render::DrawFilter filter;
    filter.objects = &objects;
    filter.skipStructure = true;
    _stats = _renderer.renderFrustum(frustum, glm::dmat4(1.0), target, filter);
    _lastFrustum = frustum;
    return _target->read("wall texture");
}

scenes::Image WallTextureRenderer::render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                                          const std::vector<int>& objects, walls::DepthImage& depth) {
    scenes::Image colour = render(quad, eye, resolution, objects);
    depth = {resolution.x, resolution.y, _target->readDepth()};
    for (float& d : depth.depth) d = walls::depthFromBuffer(d, _lastFrustum.clipFromView, _lastFrustum.eyeDistance);
    return colour;
}

}  // namespace cavewall::gl
