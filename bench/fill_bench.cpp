// What a full-screen layer costs on this renderer at a CAVE wall's 1024 x 1024 pixels, by
// framebuffer format, blending and texture format (headless EGL; llvmpipe here). Profiling
// aid for issue 14: the walls modes are bound by their wall layers' pixels, so this isolates
// the per-pixel price of each choice the wall pass makes. Each iteration clears colour and
// depth, draws `layers` full-screen textured quads (depth test on, as the wall pass draws
// after geometry) and waits for the GPU (glFinish). Counter ms_per_layer: (iteration ms -
// clear-only ms) / layers, with the clear-only time measured interleaved in the same run.
//
// Cases: framebuffer GL_SRGB8_ALPHA8 with GL_FRAMEBUFFER_SRGB (what the renderer uses today)
// or GL_RGBA8 (no conversion); blending premultiplied-over or off; texture GL_SRGB8_ALPHA8 or
// GL_RGBA8; one texture per layer, LINEAR_MIPMAP_NEAREST (the wall pass's sampler).
#include "display/gl/context.h"
#include "display/gl/gl_object.h"
#include "display/gl/shader.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <iostream>
#include <memory>
#include <vector>

namespace {

using namespace cavewall;

constexpr int kSize = 1024;

constexpr const char* kVertex = R"(#version 450 core
out vec2 vUv;
const vec2 kCorner[4] = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
void main() {
    vUv = kCorner[gl_VertexID] * 0.5 + 0.5;
    gl_Position = vec4(kCorner[gl_VertexID], 0.5, 1.0);   // reversed Z: 0.5 passes GREATER over a 0 clear
}
)";

constexpr const char* kFragment = R"(#version 450 core
in vec2 vUv;
layout(binding = 0) uniform sampler2D uTexture;
out vec4 fragColor;
void main() { fragColor = texture(uTexture, vUv); }
)";

gl::GlObject checkerTexture(GLenum format) {
    gl::GlObject t = gl::createTexture(GL_TEXTURE_2D);
    int levels = 0;
    for (int s = 512; s >= 1; s /= 2) ++levels;
    glTextureStorage2D(t.id(), levels, format, 512, 512);
    int level = 0;
    for (int s = 512; s >= 1; s /= 2, ++level) {
        std::vector<std::uint8_t> rgba(std::size_t(s) * s * 4, 255);
        for (int y = 0; y < s; ++y)
            for (int x = 0; x < s; ++x) {
                std::uint8_t* p = &rgba[(std::size_t(y) * s + x) * 4];
                p[0] = static_cast<std::uint8_t>(x * 255 / s), p[1] = ((x * 8 / s) + (y * 8 / s)) % 2 ? 200 : 60;
                p[2] = static_cast<std::uint8_t>(y * 255 / s);
            }
        glTextureSubImage2D(t.id(), level, 0, 0, s, s, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    }
    return t;
}

struct Target {
    gl::GlObject color = gl::createTexture(GL_TEXTURE_2D), depth = gl::createTexture(GL_TEXTURE_2D),
                 framebuffer = gl::createFramebuffer();
    bool srgb;
    explicit Target(GLenum format) : srgb(format == GL_SRGB8_ALPHA8) {
        glTextureStorage2D(color.id(), 1, format, kSize, kSize);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
        glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
        glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    }
};

struct Fixture {
    std::unique_ptr<gl::Context> context = gl::createHeadlessContext();
    gl::GlObject program = gl::buildProgram("fill", kVertex, kFragment);
    gl::GlObject vertexArray = gl::createVertexArray(), sampler = gl::createSampler();
    gl::GlObject srgbTexture = checkerTexture(GL_SRGB8_ALPHA8), unormTexture = checkerTexture(GL_RGBA8);
    Target srgbTarget{GL_SRGB8_ALPHA8}, unormTarget{GL_RGBA8};

    Fixture() {
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        std::cerr << "GL_RENDERER " << context->info().renderer << "\n";
    }
};

struct Case {
    const char* name;
    bool srgbTarget, blend, srgbTexture;
};

double frameMs(Fixture& f, const Case& c, int layers) {
    const auto start = std::chrono::steady_clock::now();
    const Target& target = c.srgbTarget ? f.srgbTarget : f.unormTarget;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, kSize, kSize);
    if (target.srgb) glEnable(GL_FRAMEBUFFER_SRGB);
    else glDisable(GL_FRAMEBUFFER_SRGB);
    glDepthMask(GL_TRUE);
    glClearDepth(0.0);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (layers > 0) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_FALSE);
        if (c.blend) {
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        } else {
            glDisable(GL_BLEND);
        }
        glUseProgram(f.program.id());
        glBindVertexArray(f.vertexArray.id());
        glBindTextureUnit(0, c.srgbTexture ? f.srgbTexture.id() : f.unormTexture.id());
        glBindSampler(0, f.sampler.id());
        for (int i = 0; i < layers; ++i) glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
    }
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void layerCost(benchmark::State& state, Fixture& f, const Case& c) {
    const int layers = static_cast<int>(state.range(0));
    double clearMs = 0.0, ms = 0.0;
    for (auto _ : state) {
        clearMs += frameMs(f, c, 0);  // interleaved: same load
        ms += frameMs(f, c, layers);
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["clear_ms"] = clearMs / n;
    state.counters["frame_ms"] = ms / n;
    state.counters["ms_per_layer"] = (ms - clearMs) / n / layers;
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    Fixture f;
    static const Case cases[] = {{"srgb_target/blend/srgb_texture", true, true, true},
                                 {"srgb_target/opaque/srgb_texture", true, false, true},
                                 {"srgb_target/blend/unorm_texture", true, true, false},
                                 {"unorm_target/blend/srgb_texture", false, true, true},
                                 {"unorm_target/opaque/srgb_texture", false, false, true},
                                 {"unorm_target/opaque/unorm_texture", false, false, false},
                                 {"unorm_target/blend/unorm_texture", false, true, false}};
    for (const Case& c : cases)
        benchmark::RegisterBenchmark((std::string("FillLayer/") + c.name).c_str(),
                                     [&f, &c](benchmark::State& s) { layerCost(s, f, c); })
            ->Arg(4)
            ->Iterations(10)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
