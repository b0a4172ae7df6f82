#include "walls/gl/wall_renderer.h"

#include <chrono>
#include <limits>

namespace cavewall::walls::gl {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

WallTextureRenderer::WallTextureRenderer(const scenes::Scene& scene, float ambient, double lodTexels)
    : _lodTexels(lodTexels), _renderer(scene, render::gl::RenderSettings{glm::vec4(0.0f), ambient, true, lodTexels}) {}

// Draws and waits for the GL (so that the timing splits drawing from reading back; the read
// would wait for it anyway), then reads the colour back.
scenes::Image WallTextureRenderer::draw(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                                        const std::vector<int>& objects) {
    const Clock::time_point start = Clock::now();
    if (!_target || _target->size() != resolution) _target = std::make_unique<OffscreenTarget>(resolution);
    const display::OffAxisFrustum frustum =
        display::offAxisFrustum(quad, eye, {0.05, std::numeric_limits<double>::infinity()});
    render::gl::ViewTarget target;
    target.framebuffer = _target->framebuffer();
    target.viewport = {0, 0, resolution.x, resolution.y};
    target.clearColor = glm::vec4(0.0f);  // alpha 0: nothing behind the wall here
    render::DrawFilter filter;
    filter.objects = &objects;
    filter.skipStructure = true;
    _lod = {};
    if (_lodTexels > 0.0) {
        _lod = render::chooseFrustumLods(_renderer.renderScene(), frustum, resolution, filter, _lodTexels);
        filter.lodLevels = &_lod.levels;
    }
    _stats = _renderer.renderFrustum(frustum, glm::dmat4(1.0), target, filter);
    _lastFrustum = frustum;
    glFinish();
    _timing.drawMs = msSince(start);
    const Clock::time_point read = Clock::now();
    scenes::Image colour = _target->read("wall texture");
    _timing.readMs = msSince(read);
    return colour;
}

scenes::Image WallTextureRenderer::render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                                          const std::vector<int>& objects) {
    return draw(quad, eye, resolution, objects);
}

scenes::Image WallTextureRenderer::render(const display::ScreenQuad& quad, glm::dvec3 eye, glm::ivec2 resolution,
                                          const std::vector<int>& objects, walls::DepthImage& depth) {
    scenes::Image colour = draw(quad, eye, resolution, objects);
    const Clock::time_point read = Clock::now();
    depth = {resolution.x, resolution.y, _target->readDepth()};
    for (float& d : depth.depth) d = walls::depthFromBuffer(d, _lastFrustum.clipFromView, _lastFrustum.eyeDistance);
    _timing.readMs += msSince(read);
    return colour;
}

}  // namespace cavewall::walls::gl
