// The wall pass's fill cost at a CAVE wall's 1024 x 1024 pixels (headless EGL; llvmpipe here):
// one full-screen wall layer drawn through walls::gl::WallPass over a cleared view, per texture kind
// and sampler, against the clear alone. Each iteration clears colour and depth, draws `layers`
// full-screen quads (each one WallDraw on a 4 m x 4 m quad 2 m in front of the eye, filling
// the 2 m x 2 m screen 1 m away) and waits for the GPU (glFinish), so the time per iteration
// is the frame's. Counter ms_per_layer: (iteration ms - clear-only ms) / layers, with the
// clear-only time measured in the same run.
//
// Depth walls (walls::gl::DepthWallPass): the same layer drawn by reprojecting a 512 x 512 colour +
// depth texture (a back plane 4 m behind the wall with 8 x 8 blocks 1-3 m behind it) baked from
// a sampling point 0.37 m from the eye, at the pass's default 64 steps at most and capped at
// 16; cases named depth_512/*. Their ms_per_layer beside the flat cases' is the cost of
// reprojection at 1024 x 1024. depth_512/sheets draws the default pass (rubber sheets cut) and
// one that keeps the sheets in turn within every iteration: cut_over_keep is the cut's cost.
//
// Fill cases (FillLayer/*, a profile of what a layer's pixels cost): the same full-screen layer
// drawn by a one-texture shader with the formats and blending as variables: target
// GL_SRGB8_ALPHA8 with GL_FRAMEBUFFER_SRGB (the renderer's) or GL_RGBA8, premultiplied blending
// or none, texture GL_SRGB8_ALPHA8 (the wall pass's) or GL_RGBA8.
//
// Compressed textures (FillLayer/compressed/*, walls/texture_blocks.h): the same 512 x 512
// texture as GL_SRGB8_ALPHA8, as S3TC BC1 and as BC3 (sRGB), drawn in turn within every
// iteration (clear alone, RGBA8, BC1, BC3: interleaved, so all share the load), sRGB target,
// premultiplied blending, GL_LINEAR_MIPMAP_NEAREST. Counters ms_per_layer_<format> as above and
// bc1_over_rgba8, bc3_over_rgba8: the ratio of the per-layer costs.
#include "display/gl/shader.h"
#include "display/gl/context.h"
#include "display/gl/gl_object.h"
#include "walls/gl/depth_wall_pass.h"
#include "walls/gl/wall_pass.h"
#include "walls/gl/wall_quad.h"
#include "walls/texture_blocks.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

namespace {

using namespace cavewall;

constexpr int kSize = 1024;

// MIP levels of a size x size checkerboard with a gradient (premultiplied, opaque).
std::vector<scenes::Image> mipChain(int size) {
    std::vector<scenes::Image> levels;
    for (int s = size; s >= 1; s /= 2) {
        scenes::Image l{"layer", s, s, std::vector<std::uint8_t>(std::size_t(s) * s * 4, 255)};
        for (int y = 0; y < s; ++y)
            for (int x = 0; x < s; ++x) {
                std::uint8_t* p = &l.rgba[(std::size_t(y) * s + x) * 4];
                const bool check = ((x * 8 / s) + (y * 8 / s)) % 2 == 0;
                p[0] = static_cast<std::uint8_t>(x * 255 / s);
                p[1] = check ? 200 : 60;
                p[2] = static_cast<std::uint8_t>(y * 255 / s);
            }
        levels.push_back(std::move(l));
    }
    return levels;
}

// 8 x 8 blocks at depths 1, 1.5, ... 3 m on a back plane at 4 m (metres behind the wall).
cavewall::walls::DepthImage blockDepth(int size) {
    cavewall::walls::DepthImage d{size, size, {}};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int bx = x * 16 / size, by = y * 16 / size;
            d.depth.push_back(bx % 2 == 1 && by % 2 == 1 ? 1.0f + 0.5f * ((bx + by) % 5) : 4.0f);
        }
    return d;
}

// The fill cases' shader: one texture over the whole viewport, at reversed-Z depth 0.5.
constexpr const char* kFillVertex = R"(#version 450 core
out vec2 vUv;
const vec2 kCorner[4] = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
void main() {
    vUv = kCorner[gl_VertexID] * 0.5 + 0.5;
    gl_Position = vec4(kCorner[gl_VertexID], 0.5, 1.0);
}
)";
constexpr const char* kFillFragment = R"(#version 450 core
in vec2 vUv;
layout(binding = 0) uniform sampler2D uTexture;
out vec4 fragColor;
void main() { fragColor = texture(uTexture, vUv); }
)";

// mipChain(512) in GL_RGBA8 (no sRGB decode when sampled).
display::gl::GlObject unormTexture() {
    const std::vector<scenes::Image> levels = mipChain(512);
    display::gl::GlObject t = display::gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), static_cast<GLsizei>(levels.size()), GL_RGBA8, 512, 512);
    for (std::size_t l = 0; l < levels.size(); ++l)
        glTextureSubImage2D(t.id(), static_cast<GLint>(l), 0, 0, levels[l].width, levels[l].height, GL_RGBA,
                            GL_UNSIGNED_BYTE, levels[l].rgba.data());
    return t;
}

struct FillCase {
    bool srgbTarget, blend, srgbTexture;
};

struct Fixture {
    std::unique_ptr<display::gl::Context> context = display::gl::createHeadlessContext();
    display::gl::GlObject color = display::gl::createTexture(GL_TEXTURE_2D),
                          depth = display::gl::createTexture(GL_TEXTURE_2D),
                          framebuffer = display::gl::createFramebuffer();
    display::gl::GlObject unormColor = display::gl::createTexture(GL_TEXTURE_2D),
                          unormFramebuffer = display::gl::createFramebuffer();
    display::gl::GlObject fillProgram = display::gl::buildProgram("fill", kFillVertex, kFillFragment);
    display::gl::GlObject fillVertexArray = display::gl::createVertexArray();
    walls::gl::WallPass pass;
    display::gl::GlObject bare = walls::gl::uploadWallTexture({scenes::Image{"bare", 1, 1, {128, 128, 128, 255}}});
    display::gl::GlObject baked = walls::gl::uploadWallTexture(mipChain(512));
    display::gl::GlObject bakedUnorm = unormTexture();
    display::gl::GlObject bakedBc1 =
        walls::gl::uploadWallTexture(walls::encodeLevels(mipChain(512), walls::TextureFormat::Bc1));
    display::gl::GlObject bakedBc3 =
        walls::gl::uploadWallTexture(walls::encodeLevels(mipChain(512), walls::TextureFormat::Bc3));
    display::gl::GlObject nearestMip = display::gl::createSampler(), linearMip = display::gl::createSampler(),
                          bilinear = display::gl::createSampler();
    walls::gl::DepthTexture depthBlocks = walls::gl::uploadDepthTexture(blockDepth(512));
    walls::gl::DepthWallPass depthPass, depthPass16{walls::ReprojectSettings{16, 6}},
        depthPassKeep{walls::ReprojectSettings{.cutSheets = false}};
    display::OffAxisFrustum frustum;
    display::ScreenQuad wall;

    Fixture() {
        glTextureStorage2D(color.id(), 1, GL_SRGB8_ALPHA8, kSize, kSize);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, kSize, kSize);
        glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
        glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        glTextureStorage2D(unormColor.id(), 1, GL_RGBA8, kSize, kSize);
        glNamedFramebufferTexture(unormFramebuffer.id(), GL_COLOR_ATTACHMENT0, unormColor.id(), 0);
        glNamedFramebufferTexture(unormFramebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        for (GLuint s : {nearestMip.id(), linearMip.id(), bilinear.id()}) {
            glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        }
        glSamplerParameteri(nearestMip.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
        glSamplerParameteri(linearMip.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(bilinear.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        const glm::dvec3 eye(0.0);
        frustum = display::offAxisFrustum({{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}}, eye, {0.05, INFINITY});
        wall = {{-2, -2, -2}, {2, -2, -2}, {-2, 2, -2}};
        std::cerr << "GL_RENDERER " << context->info().renderer << "\n";
    }

    void clear(bool srgbTarget = true) const {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, srgbTarget ? framebuffer.id() : unormFramebuffer.id());
        glViewport(0, 0, kSize, kSize);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        if (srgbTarget)
            glEnable(GL_FRAMEBUFFER_SRGB);
        else
            glDisable(GL_FRAMEBUFFER_SRGB);
        glDepthMask(GL_TRUE);
        glClearDepth(0.0);
        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
};

// `keep`: depth walls that keep their rubber sheets (walls::ReprojectSettings::cutSheets false).
double frameMs(Fixture& f, int layers, GLuint texture, GLuint sampler, int texturesPerLayer, int depthSteps = 0,
               bool keep = false) {
    const auto start = std::chrono::steady_clock::now();
    f.clear();
    if (depthSteps > 0) {
        std::vector<walls::gl::DepthWallDraw> draws;
        for (int i = 0; i < layers; ++i) {
            walls::gl::DepthWallDraw d{f.wall, {}, texturesPerLayer};
            for (int t = 0; t < texturesPerLayer; ++t)
                d.layers[t] = {texture,
                               f.depthBlocks.depth.id(),
                               glm::dvec3(0.3, 0.1, 0.2 * (t + 1)),
                               glm::dvec2(1.0, 4.0),
                               1.0f / texturesPerLayer,
                               f.depthBlocks.skip.id()};
            draws.push_back(d);
        }
        display::FrameStats stats;
        (keep               ? f.depthPassKeep
         : depthSteps == 16 ? f.depthPass16
                            : f.depthPass)
            .draw(draws, f.frustum, glm::dmat4(1.0), sampler, stats);
        glFinish();
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    std::vector<walls::gl::WallDraw> draws;
    for (int i = 0; i < layers; ++i) {
        walls::gl::WallDraw d{f.wall, {}, {}, texturesPerLayer};
        for (int t = 0; t < texturesPerLayer; ++t) d.textures[t] = texture, d.weights[t] = 1.0f / texturesPerLayer;
        draws.push_back(d);
    }
    display::FrameStats stats;
    f.pass.draw(draws, f.frustum, glm::dmat4(1.0), sampler, stats);
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// `texture` 0: the case's own (baked or bakedUnorm).
double fillFrameMs(Fixture& f, const FillCase& c, int layers, GLuint texture = 0) {
    const auto start = std::chrono::steady_clock::now();
    f.clear(c.srgbTarget);
    if (layers > 0) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_FALSE);
        if (c.blend)
            glEnable(GL_BLEND), glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        else
            glDisable(GL_BLEND);
        glUseProgram(f.fillProgram.id());
        glBindVertexArray(f.fillVertexArray.id());
        glBindTextureUnit(0, texture != 0 ? texture : c.srgbTexture ? f.baked.id() : f.bakedUnorm.id());
        glBindSampler(0, f.nearestMip.id());
        for (int i = 0; i < layers; ++i) glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
    }
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Interleaves the clear alone (frame(0)) with `layers` layers (frame(layers)), so both share the
// load; counters as the header says.
template <typename Frame>
void layerCost(benchmark::State& state, Frame frame) {
    const int layers = static_cast<int>(state.range(0));
    frame(layers);  // untimed: llvmpipe compiles a shader variant at its first draw
    double clearMs = 0.0, ms = 0.0;
    for (auto _ : state) {
        clearMs += frame(0);
        ms += frame(layers);
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["clear_ms"] = clearMs / n;
    state.counters["frame_ms"] = ms / n;
    state.counters["ms_per_layer"] = (ms - clearMs) / n / layers;
}

// FillLayer/compressed: the clear, RGBA8, BC1 and BC3 frames in turn each iteration.
void compressedFill(benchmark::State& state, Fixture& f) {
    const int layers = static_cast<int>(state.range(0));
    const FillCase c{true, true, true};
    const GLuint textures[3] = {f.baked.id(), f.bakedBc1.id(), f.bakedBc3.id()};
    double clearMs = 0.0, ms[3] = {0.0, 0.0, 0.0};
    for (auto _ : state) {
        clearMs += fillFrameMs(f, c, 0);
        for (int t = 0; t < 3; ++t) ms[t] += fillFrameMs(f, c, layers, textures[t]);
    }
    const double n = static_cast<double>(state.iterations());
    const char* names[3] = {"rgba8", "bc1", "bc3"};
    double perLayer[3];
    for (int t = 0; t < 3; ++t) {
        perLayer[t] = (ms[t] - clearMs) / n / layers;
        state.counters[std::string("ms_per_layer_") + names[t]] = perLayer[t];
    }
    state.counters["clear_ms"] = clearMs / n;
    state.counters["bc1_over_rgba8"] = perLayer[1] / perLayer[0];
    state.counters["bc3_over_rgba8"] = perLayer[2] / perLayer[0];
}

// WallLayer/depth_512/sheets: the clear, the default depth pass (sheets cut) and one that keeps
// them, in turn each iteration. Counters ms_per_layer_cut, ms_per_layer_keep and cut_over_keep.
void sheetsCost(benchmark::State& state, Fixture& f) {
    const int layers = static_cast<int>(state.range(0));
    frameMs(f, layers, f.baked.id(), f.nearestMip.id(), 1, 64);  // untimed: shader variants compile
    frameMs(f, layers, f.baked.id(), f.nearestMip.id(), 1, 64, true);
    double clearMs = 0.0, cut = 0.0, keep = 0.0;
    for (auto _ : state) {
        clearMs += frameMs(f, 0, f.baked.id(), f.nearestMip.id(), 1);
        cut += frameMs(f, layers, f.baked.id(), f.nearestMip.id(), 1, 64);
        keep += frameMs(f, layers, f.baked.id(), f.nearestMip.id(), 1, 64, true);
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["clear_ms"] = clearMs / n;
    state.counters["ms_per_layer_cut"] = (cut - clearMs) / n / layers;
    state.counters["ms_per_layer_keep"] = (keep - clearMs) / n / layers;
    state.counters["cut_over_keep"] = (cut - clearMs) / (keep - clearMs);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    Fixture f;
    struct Case {
        const char* name;
        GLuint texture, sampler;
        int textures;
        int depthSteps = 0;  // > 0: walls::gl::DepthWallPass with this many steps at most
    };
    const Case cases[] = {{"bare_1x1", f.bare.id(), 0, 1},
                          {"baked_512/linear_mipmap_nearest", f.baked.id(), f.nearestMip.id(), 1},
                          {"baked_512/linear_mipmap_linear", f.baked.id(), f.linearMip.id(), 1},
                          {"baked_512/linear_no_mipmap", f.baked.id(), f.bilinear.id(), 1},
                          {"baked_512/two_textures_blending", f.baked.id(), f.nearestMip.id(), 2},
                          {"depth_512/steps_64", f.baked.id(), f.nearestMip.id(), 1, 64},
                          {"depth_512/steps_16", f.baked.id(), f.nearestMip.id(), 1, 16},
                          {"depth_512/two_textures_steps_64", f.baked.id(), f.nearestMip.id(), 2, 64}};
    for (const Case& c : cases)
        benchmark::RegisterBenchmark((std::string("WallLayer/") + c.name).c_str(),
                                     [&f, c](benchmark::State& s) {
                                         layerCost(s, [&](int layers) {
                                             return frameMs(f, layers, c.texture, c.sampler, c.textures,
                                                            layers > 0 ? c.depthSteps : 0);
                                         });
                                     })
            ->Arg(1)
            ->Arg(4)
            ->Iterations(10)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("WallLayer/depth_512/sheets", [&f](benchmark::State& s) { sheetsCost(s, f); })
        ->Arg(4)
        ->Iterations(10)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    const std::pair<const char*, FillCase> fills[] = {{"srgb_target/blend/srgb_texture", {true, true, true}},
                                                      {"srgb_target/opaque/srgb_texture", {true, false, true}},
                                                      {"srgb_target/blend/unorm_texture", {true, true, false}},
                                                      {"unorm_target/blend/srgb_texture", {false, true, true}},
                                                      {"unorm_target/opaque/srgb_texture", {false, false, true}},
                                                      {"unorm_target/opaque/unorm_texture", {false, false, false}},
                                                      {"unorm_target/blend/unorm_texture", {false, true, false}}};
    for (const auto& [name, c] : fills)
        benchmark::RegisterBenchmark(
            (std::string("FillLayer/") + name).c_str(),
            [&f, c = c](benchmark::State& s) { layerCost(s, [&](int layers) { return fillFrameMs(f, c, layers); }); })
            ->Arg(4)
            ->Iterations(10)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("FillLayer/compressed/srgb_target/blend",
                                 [&f](benchmark::State& s) { compressedFill(s, f); })
        ->Arg(4)
        ->Iterations(10)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
