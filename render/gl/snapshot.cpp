#include "render/gl/snapshot.h"

#include <algorithm>

namespace cavewall::render::gl {

Snapshotter::Snapshotter(const display::Display& display, const scenes::Scene& scene, display::gl::Context& context,
                         RenderSettings settings)
    : _display(display), _context(context), _targets(display, context), _renderer(scene, settings),
      _projectors(display, _targets) {}

Snapshot Snapshotter::render(const display::HeadPose& head, const glm::dmat4& worldFromCave,
                             double foldoutPixelsPerMetre) {
    Snapshot out;
    out.stats = _renderer.render(_display.views(head), _targets, worldFromCave);
    if (_projectors.any()) _projectors.apply(_targets);
    out.images = display::gl::readFrame(_display, _targets);
    out.warped = _projectors.read(out.images);
    out.stats.gpuMs = _renderer.waitGpuMs();  // the read-back has waited for the GPU already
    if (_context.windowCount() > 0) present(out);
    out.foldout = display::gl::foldoutOf(_display, out.images, foldoutPixelsPerMetre);
    return out;
}

void Snapshotter::present(Snapshot& snapshot) {
    const int windows = std::min(_context.windowCount(), _targets.screenCount());
    for (int s = 0; s < windows; ++s) {
        const display::gl::ProjectorPass* pass = _projectors.pass(s);
        display::gl::PresentImage image{pass ? pass->colorTexture(0) : _targets.colorTexture(s, 0), 0,
                                        _targets.size(s)};
        if (_targets.imageCount(s) > 1 && _context.info().stereoWindows)
            image.right = pass ? pass->colorTexture(1) : _targets.colorTexture(s, 1);
        std::vector<scenes::ScreenImage>& images = pass ? snapshot.warped : snapshot.images;
        scenes::Image shown;
        _context.present(s, image, &shown);
        for (scenes::ScreenImage& i : images)
            if (i.screen == s && i.image == 0 && shown.width == i.pixels.width && shown.height == i.pixels.height)
                i.pixels.rgba = std::move(shown.rgba);
    }
}

}  // namespace cavewall::render::gl
