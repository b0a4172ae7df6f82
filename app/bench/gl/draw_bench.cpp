#include "app/bench/gl/draw_bench.h"

#include "config/display_config.h"
#include "display/display.h"
#include "display/gl/context.h"
#include "display/gl/render_targets.h"
#include "display/gl/scene_renderer.h"
#include "display/timing.h"
#include "scenes/image_io.h"

#include <cassert>
#include <chrono>
#include <cmath>
#include <ctime>

namespace cavewall::gl {
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

DrawBenchRow timeConfiguration(const scenes::Scene& scene, const display::Display& disp, const Context& context,
                               bool cull, const DrawBenchOptions& options, DrawBenchResult& result) {
    RenderSettings settings;
    settings.cullBackFaces = cull;
    SceneRenderer renderer(scene, settings);
    const RenderTargets targets(disp, context);
    const std::vector<display::ScreenView> views = disp.views(disp.defaultHead());
    DrawBenchRow row;
    row.cullBackFaces = cull;
    for (int i = 0; i < options.warmup + options.frames; ++i) {
        const double cpuStart = processCpuMs();
        const auto start = std::chrono::steady_clock::now();
        const FrameStats stats = renderer.render(views, targets);
        glFinish();
        const double ms = display::msSince(start);
        const double cpuMs = processCpuMs() - cpuStart;
        row.trianglesSubmitted = stats.triangles;
        if (i < options.warmup) continue;
        row.frameMs.push_back(ms);
        row.cpuMs.push_back(cpuMs);
    }
    const auto pixels = static_cast<std::size_t>(options.resolution) * static_cast<std::size_t>(options.resolution);
    row.timing = bench::drawTiming(row.frameMs, row.cpuMs, row.trianglesSubmitted, pixels);
    result.vertexBytesPerTriangle = static_cast<double>(renderer.gpu().vertexBytes()) / result.triangles;
    result.indexBytesPerTriangle = static_cast<double>(renderer.gpu().indexBytes()) / result.triangles;
    if (options.imageDir) scenes::writeImage(*options.imageDir / (cull ? "culled.png" : "both.png"), targets.read(0, 0));
    return row;
}

}  // namespace

DrawBenchResult runDrawBench(const scenes::Scene& scene, const DrawBenchOptions& options) {
    assert(!scene.objects.empty() && options.frames >= 1 && options.warmup >= 0);
    DrawBenchResult result;
    result.triangles = std::max<std::size_t>(scene.triangleCount(), 1);
    result.view = bench::osgHomeView(scene.bounds(), options.fovDeg, 1.0);
    const display::Display disp(homeDisplay(result.view, options.resolution));
    const auto context = createHeadlessContext();
    result.glRenderer = context->info().renderer;
    for (bool cull : {true, false})
        result.rows.push_back(timeConfiguration(scene, disp, *context, cull, options, result));
    return result;
}

}  // namespace cavewall::gl
