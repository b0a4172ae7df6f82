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
    : _lodTexels(lodTexels), _renderer(scene, render::gl::RenderSettings{glm::vec4(0.0f), ambient, true, lodTexels}) {
    for (const scenes::Object& o : scene.objects) _blended.push_back(scenes::blends(scene, o));
}

render::DrawFilter WallTextureRenderer::filterFor(const std::vector<int>& objects) const {
    render::DrawFilter filter;
    filter.objects = &objects;
    filter.skipStructure = true;
    if (!_lod.levels.empty()) filter.lodLevels = &_lod.levels;
    return filter;
}

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
    _lod = {};
    if (_lodTexels > 0.0)
        _lod = render::chooseFrustumLods(_renderer.renderScene(), frustum, resolution, filterFor(objects), _lodTexels);
    _stats = _renderer.renderFrustum(frustum, glm::dmat4(1.0), target, filterFor(objects));
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
    addTranslucentDepth(colour, objects, depth.depth);
    for (float& d : depth.depth) d = walls::depthFromBuffer(d, _lastFrustum.clipFromView, _lastFrustum.eyeDistance);
    _timing.readMs += msSince(read);
    return colour;
}

// Buffer depth 0 (cleared) where something was drawn (alpha > 0): only blended surfaces were,
// since they write no depth. Those texels get the depth of the nearest blended surface from a
// second pass over the blended objects alone, colour writes off and depth writes on (no opaque
// surface is under those texels, so none is missing from that pass); every other texel keeps
// the depth of its opaque surface (what shows through a pane in front of it is reprojected at
// its own depth). Only textures with such texels pay for the pass.
void WallTextureRenderer::addTranslucentDepth(const scenes::Image& colour, const std::vector<int>& objects,
                                              std::vector<float>& bufferDepth) {
    auto uncovered = [&](std::size_t i) { return bufferDepth[i] == 0.0f && colour.rgba[i * 4 + 3] > 0; };
    bool any = false;
    for (std::size_t i = 0; i < bufferDepth.size() && !any; ++i) any = uncovered(i);
    if (!any) return;
    std::vector<int> blended;
    for (int o : objects)
        if (o >= 0 && o < static_cast<int>(_blended.size()) && _blended[static_cast<std::size_t>(o)])
            blended.push_back(o);
    render::gl::ViewTarget target;
    target.framebuffer = _target->framebuffer();
    target.viewport = {0, 0, colour.width, colour.height};
    target.colorMask = glm::bvec4(false);
    target.blendedWriteDepth = true;
    _renderer.renderFrustum(_lastFrustum, glm::dmat4(1.0), target, filterFor(blended));
    const std::vector<float> nearest = _target->readDepth();
    for (std::size_t i = 0; i < bufferDepth.size(); ++i)
        if (uncovered(i)) bufferDepth[i] = nearest[i];
}

}  // namespace cavewall::walls::gl
