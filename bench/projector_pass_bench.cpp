// The projector correction pass (display/gl/projector_pass.h) against the frame it corrects, in
// one interleaved run (headless EGL). Each round renders one view of the generated plant at
// 1024 x 1024 (bench/plant_views.h, frustum culling on, views cycling), then runs the pass on
// that image twice: a 33 x 33 keystone mesh with a 1024 x 1024 16-bit blend mask and a black
// level (a calibrated projector), and the identity mesh without a mask (the cheapest pass).
// Every step is timed twice: by the wall clock from its first call until glFinish returns, and
// by a GL_TIME_ELAPSED query around its commands (the GPU timer). Interleaving puts the pass
// and the frame under the same load, so their ratio is comparable even on a busy machine.
//
// Prints per step the median and mean over the rounds, wall and GPU side by side, and the
// pass's cost as a share of the frame by each clock (medians).
// Usage: build/bench/cavewall_bench_projector_pass [--rounds N]   (default 30; a first, untimed
// round warms up)
#include "bench/plant_views.h"
#include "display/gl/context.h"
#include "display/gl/gpu_timer.h"
#include "display/gl/projector_pass.h"
#include "render/gl/scene_renderer.h"
#include "scenes/loader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace cavewall;

constexpr int kSize = 1024;

display::ScreenCorrection calibrated() {
    display::ScreenCorrection c;
    c.warp = display::identityWarp(33, 33);
    for (display::WarpNode& n : c.warp.nodes)  // a keystone: x' = 0.5 + (x - 0.5) / (1 + y / 4)
        n.xy = {0.5f + (n.uv.x - 0.5f) / (1.0f + 0.25f * n.uv.y), n.uv.y / (1.0f + 0.25f * n.uv.y)};
    display::BlendMask mask{kSize, kSize, std::vector<std::uint16_t>(static_cast<std::size_t>(kSize) * kSize)};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            mask.weights[static_cast<std::size_t>(y) * kSize + x] =
                static_cast<std::uint16_t>(x < kSize * 3 / 4 ? 65535 : 65535 * (kSize - 1 - x) / (kSize / 4));
    c.blend = mask;
    c.blackLevel = glm::vec3(0.01f);
    return c;
}

// One timed step's samples, milliseconds.
struct Samples {
    std::string name;
    std::vector<double> wallMs, gpuMs;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
    double sum = 0.0;
    for (double x : v) sum += x;
    return sum / static_cast<double>(v.size());
}

// Runs `step` between a GPU timer's begin and end, waits for the GPU, and records both clocks.
void timeStep(display::gl::GpuTimer& timer, Samples& samples, const std::function<void()>& step, bool record) {
    const auto start = std::chrono::steady_clock::now();
    timer.begin();
    step();
    timer.end();
    glFinish();
    const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const double gpuMs = timer.waitMs();
    if (!record) return;
    samples.wallMs.push_back(wallMs);
    samples.gpuMs.push_back(gpuMs);
}

void printTable(const std::vector<Samples>& steps, int rounds) {
    std::printf(
        "| step | rounds | wall median ms | wall mean ms | GPU timer median ms | GPU timer mean ms |\n"
        "| --- | ---: | ---: | ---: | ---: | ---: |\n");
    for (const Samples& s : steps)
        std::printf("| %s | %d | %.2f | %.2f | %.2f | %.2f |\n", s.name.c_str(), rounds, median(s.wallMs),
                    mean(s.wallMs), median(s.gpuMs), mean(s.gpuMs));
    const Samples& frame = steps.front();
    std::printf(
        "\n| pass | share of the frame, wall (medians) | share of the frame, GPU timer (medians) |\n"
        "| --- | ---: | ---: |\n");
    for (std::size_t i = 1; i < steps.size(); ++i)
        std::printf("| %s | %.1f %% | %.1f %% |\n", steps[i].name.c_str(),
                    100.0 * median(steps[i].wallMs) / median(frame.wallMs),
                    100.0 * median(steps[i].gpuMs) / median(frame.gpuMs));
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 30;
    if (argc == 3 && !std::strcmp(argv[1], "--rounds")) rounds = std::max(1, std::atoi(argv[2]));
    const auto context = display::gl::createHeadlessContext();
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(bench::plantScenePath(), &description);
    render::gl::SceneRenderer renderer{scene};
    const std::vector<display::OffAxisFrustum> views = bench::plantViews(description.walkPath);
    display::gl::GlObject color = display::gl::createTexture(GL_TEXTURE_2D), depth = display::gl::createTexture(GL_TEXTURE_2D),
                 framebuffer = display::gl::createFramebuffer();
    glTextureStorage2D(color.id(), 1, GL_SRGB8_ALPHA8, kSize, kSize);
    glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
    glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    display::gl::ProjectorPass keystone(calibrated(), {kSize, kSize}), identity(display::ScreenCorrection{}, {kSize, kSize});
    std::fprintf(stderr, "plant: %zu triangles, %zu views, %d x %d; GL_RENDERER %s\n", scene.triangleCount(),
                 views.size(), kSize, kSize, context->info().renderer.c_str());

    render::DrawFilter filter;
    filter.frustumCull = true;
    const render::gl::ViewTarget target{framebuffer.id(), {0, 0, kSize, kSize}, glm::vec4(0.02f, 0.02f, 0.03f, 1.0f)};
    std::vector<Samples> steps{{"plant frame (the control)", {}, {}},
                               {"pass: 33 x 33 keystone mesh, 1024² 16-bit mask, black level", {}, {}},
                               {"pass: identity mesh (2 x 2), no mask", {}, {}}};
    display::gl::GpuTimer timer;
    for (int round = 0; round <= rounds; ++round) {
        const bool record = round > 0;  // round 0 warms up: shaders, first uploads
        const display::OffAxisFrustum& view = views[static_cast<std::size_t>(round) % views.size()];
        const auto frame = [&] { renderer.renderFrustum(view, glm::dmat4(1.0), target, filter); };
        const auto correctCalibrated = [&] { keystone.apply(color.id()); };
        const auto correctIdentity = [&] { identity.apply(color.id()); };
        timeStep(timer, steps[0], frame, record);
        timeStep(timer, steps[1], correctCalibrated, record);
        timeStep(timer, steps[2], correctIdentity, record);
    }
    printTable(steps, rounds);
    return 0;
}
