#include "app/bench/gl/draw_bench.h"

#include "config/display_config.h"
#include "display/display.h"
#include "display/gl/context.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"
#include "display/timing.h"
#include "scenes/image_io.h"

#include <cassert>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>

namespace cavewall::bench::gl {
namespace {

// Milliseconds of CPU time of this process, all threads (llvmpipe's workers included).
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// One screen on the home view's quad, the head at its eye; the CAVE frame is the world frame.
config::DisplayConfig homeDisplay(const bench::HomeView& view, int resolution) {
    config::DisplayConfig c;
    c.name = "draw-bench";
    config::Screen s;
    s.name = "view";
    s.lowerLeft = view.screen.lowerLeft;
    s.lowerRight = view.screen.lowerRight;
    s.upperLeft = view.screen.upperLeft;
    s.resolution = {resolution, resolution};
    c.screens.push_back(s);
    c.viewer.headPosition = view.eye;
    c.viewer.far = std::numeric_limits<double>::infinity();
    config::validateDisplayConfig(c, "draw-bench");
    return c;
}

// The configurations are timed frame by frame in turn, in ABBA order (culled, both, both,
// culled, ...; with more, forward then reverse), so that neither gains from running first or second under a changing load and
// both share the warm-up state of llvmpipe's threads and caches.
std::vector<DrawBenchRow> timeConfigurations(const scenes::Scene& scene, const display::Display& disp,
                                             const display::gl::Context& context, const DrawBenchOptions& options,
                                             DrawBenchResult& result) {
    struct Configuration {
        std::unique_ptr<render::gl::SceneRenderer> renderer;
        DrawBenchRow row;
    };
    std::vector<Configuration> configurations;
    for (bool cull : {true, false})
        for (bool perPixel : {false, true}) {
            if (perPixel && !options.compareLighting) continue;
            render::gl::RenderSettings settings;
            settings.cullBackFaces = cull;
            if (perPixel) settings.vertexLightingTolerance = 0.0;
            Configuration c{std::make_unique<render::gl::SceneRenderer>(scene, settings), {}};
            c.row.cullBackFaces = cull;
            c.row.perPixelOnly = perPixel;
            configurations.push_back(std::move(c));
        }
    const display::gl::RenderTargets targets(disp, context);
    const std::vector<display::ScreenView> views = disp.views(disp.defaultHead());
    auto frame = [&](Configuration& c, bool timed) {
        const double cpuStart = processCpuMs();
        const auto start = std::chrono::steady_clock::now();
        const display::FrameStats stats = c.renderer->render(views, targets);
        glFinish();
        const double ms = display::msSince(start);
        const double cpuMs = processCpuMs() - cpuStart;
        c.row.trianglesSubmitted = stats.triangles;
        if (!timed) return;
        c.row.frameMs.push_back(ms);
        c.row.cpuMs.push_back(cpuMs);
    };
    for (int i = 0; i < options.warmup + options.frames; ++i) {
        const bool timed = i >= options.warmup;
        const std::size_t n = configurations.size();
        for (std::size_t k = 0; k < n; ++k) frame(configurations[i % 2 == 0 ? k : n - 1 - k], timed);
    }
    const auto pixels = static_cast<std::size_t>(options.resolution) * static_cast<std::size_t>(options.resolution);
    const render::gl::SceneRenderer& any = *configurations[0].renderer;
    result.vertexBytesPerTriangle = static_cast<double>(any.gpu().vertexBytes()) / result.triangles;
    result.indexBytesPerTriangle = static_cast<double>(any.gpu().indexBytes()) / result.triangles;
    std::vector<DrawBenchRow> rows;
    for (Configuration& c : configurations) {
        c.row.timing = bench::drawTiming(c.row.frameMs, c.row.cpuMs, c.row.trianglesSubmitted, pixels);
        if (options.imageDir) {
            frame(c, false);  // the last frame drawn is the other configuration's
            const std::string name = std::string(c.row.cullBackFaces ? "culled" : "both") +
                                     (c.row.perPixelOnly ? "-per-pixel" : "") + ".png";
            scenes::writeImage(*options.imageDir / name, targets.read(0, 0));
        }
        rows.push_back(std::move(c.row));
    }
    return rows;
}

}  // namespace

DrawBenchResult runDrawBench(const scenes::Scene& scene, const DrawBenchOptions& options) {
    assert(!scene.objects.empty() && options.frames >= 1 && options.warmup >= 0);
    DrawBenchResult result;
    result.triangles = std::max<std::size_t>(scene.triangleCount(), 1);
    result.view = bench::osgHomeView(scene.bounds(), options.fovDeg, 1.0);
    const display::Display disp(homeDisplay(result.view, options.resolution));
    const auto context = display::gl::createHeadlessContext();
    result.glRenderer = context->info().renderer;
    result.rows = timeConfigurations(scene, disp, *context, options, result);
    return result;
}

}  // namespace cavewall::bench::gl
