// The draw path on the generated plant (default: 2 M drawn triangles) at 1024 x 1024 pixels on
// one screen, with and without CPU frustum culling (headless EGL; llvmpipe here).
//
// Scene and views: bench/plant_views.h (reversed-Z with an infinite far plane).
// Each iteration renders one view (cycling) and waits for the GPU (glFinish), so the time per
// iteration is the frame time. Counters per frame: objects, triangles and draw calls
// submitted, CPU culling ms (BVH + filter), CPU submit ms, GPU ms (timer queries), and
// triangles/s (submitted triangles over wall-clock frame time).
#include "bench/plant_views.h"
#include "display/gl/context.h"
#include "display/gl/gpu_timer.h"
#include "render/gl/scene_renderer.h"
#include "scenes/generate.h"
#include "scenes/loader.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

namespace {

using namespace cavewall;

constexpr int kSize = 1024;

struct Fixture {
    std::unique_ptr<display::gl::Context> context = display::gl::createHeadlessContext();
    scenes::SceneDescription description;
    scenes::Scene scene = scenes::loadSceneFile(bench::plantScenePath(), &description);
    render::gl::SceneRenderer renderer{scene};
    display::gl::GpuTimer timer;
    display::gl::GlObject color = display::gl::createTexture(GL_TEXTURE_2D),
                          depth = display::gl::createTexture(GL_TEXTURE_2D),
                          framebuffer = display::gl::createFramebuffer();
    std::vector<display::OffAxisFrustum> views;

    Fixture() {
        glTextureStorage2D(color.id(), 1, GL_SRGB8_ALPHA8, kSize, kSize);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
        glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
        glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        views = bench::plantViews(description.walkPath);
        std::cerr << "plant: " << scene.objects.size() << " objects, " << scene.triangleCount() << " triangles; "
                  << views.size() << " views; GL_RENDERER " << context->info().renderer << "\n";
    }
};

void plantFrame(benchmark::State& state, Fixture& f, bool culling) {
    render::DrawFilter filter;
    filter.frustumCull = culling;
    const render::gl::ViewTarget target{f.framebuffer.id(), {0, 0, kSize, kSize}, glm::vec4(0.02f, 0.02f, 0.03f, 1.0f)};
    double objects = 0, triangles = 0, drawCalls = 0, cullMs = 0, cpuMs = 0, gpuMs = 0;
    std::size_t view = 0;
    for (auto _ : state) {
        f.timer.begin();
        const display::ViewStats s =
            f.renderer.renderFrustum(f.views[view++ % f.views.size()], glm::dmat4(1.0), target, filter);
        f.timer.end();
        glFinish();
        gpuMs += f.timer.waitMs();
        objects += s.objectsDrawn;
        triangles += static_cast<double>(s.triangles);
        drawCalls += s.drawCalls;
        cullMs += s.cullMs;
        cpuMs += s.cpuMs;
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["objects"] = objects / n;
    state.counters["triangles"] = triangles / n;
    state.counters["draw_calls"] = drawCalls / n;
    state.counters["cull_ms"] = cullMs / n;
    state.counters["cpu_ms"] = cpuMs / n;
    state.counters["gpu_ms"] = gpuMs / n;
    state.counters["triangles_per_s"] = benchmark::Counter(triangles, benchmark::Counter::kIsRate);
}
}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    Fixture f;  // one context and one upload for every benchmark
    // Without culling a frame takes seconds on llvmpipe: 12 frames cycle through the first
    // three walk-path points in all four directions.
    for (const bool culling : {true, false})
        benchmark::RegisterBenchmark(culling ? "PlantFrame/culling" : "PlantFrame/no_culling",
                                     [&f, culling](benchmark::State& s) { plantFrame(s, f, culling); })
            ->Iterations(12)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
