// The projector correction pass (display/gl/projector_pass.h) on one 1024 x 1024 screen image
// (headless EGL; llvmpipe here). Each iteration runs the pass once and waits for the GPU
// (glFinish), so the time per iteration is the pass's share of a frame. Cases: the identity
// mesh without a mask (the cheapest pass), and a 33 x 33 keystone mesh with a 1024 x 1024 16-bit
// blend mask and a black level (a calibrated projector). Counter: GPU ms (timer queries).
#include "display/gl/context.h"
#include "display/gl/gpu_timer.h"
#include "display/gl/projector_pass.h"

#include <benchmark/benchmark.h>

#include <memory>

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

void projectorPass(benchmark::State& state, bool calibratedMesh) {
    const auto context = display::gl::createHeadlessContext();
    display::gl::GlObject source = display::gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(source.id(), 1, GL_SRGB8_ALPHA8, kSize, kSize);
    const std::vector<std::uint8_t> grey(static_cast<std::size_t>(kSize) * kSize * 4, 128);
    glTextureSubImage2D(source.id(), 0, 0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, grey.data());
    display::gl::ProjectorPass pass(calibratedMesh ? calibrated() : display::ScreenCorrection{}, {kSize, kSize});
    display::gl::GpuTimer timer;
    double gpuMs = 0.0;
    for (auto _ : state) {
        timer.begin();
        pass.apply(source.id());
        timer.end();
        glFinish();
        gpuMs += timer.waitMs();
    }
    state.counters["gpu_ms"] = benchmark::Counter(gpuMs, benchmark::Counter::kAvgIterations);
    state.SetLabel(context->info().renderer);
}

BENCHMARK_CAPTURE(projectorPass, identity, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(projectorPass, keystone_blend_black, true)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
