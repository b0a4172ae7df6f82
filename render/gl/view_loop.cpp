#include "render/gl/view_loop.h"

#include <chrono>

namespace cavewall::render::gl {

FrameStats forEachView(const std::vector<display::ScreenView>& views, const display::gl::RenderTargets& targets,
                       const ViewPass& pass) {
    using Clock = std::chrono::steady_clock;
    FrameStats frame;
    for (const display::ScreenView& view : views) {
        const auto start = Clock::now();
        targets.bind(view.screen, display::gl::RenderTargets::imageOf(view.pass));
        ViewStats stats = pass(view);
        stats.cpuMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        frame.add(stats);
    }
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return frame;
}

std::vector<ViewStats> statsPerScreen(const std::vector<display::ScreenView>& views, const FrameStats& frame,
                                      std::size_t screenCount) {
    std::vector<ViewStats> out(screenCount);
    for (std::size_t v = 0; v < frame.perView.size() && v < views.size(); ++v) {
        const std::size_t s = static_cast<std::size_t>(views[v].screen);
        if (s >= screenCount) continue;
        const ViewStats& view = frame.perView[v];
        out[s].objectsDrawn += view.objectsDrawn;
        out[s].drawCalls += view.drawCalls;
        out[s].triangles += view.triangles;
        out[s].cullMs += view.cullMs;
        out[s].cpuMs += view.cpuMs;
    }
    return out;
}

}  // namespace cavewall::render::gl
