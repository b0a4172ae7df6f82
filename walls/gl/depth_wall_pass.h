#pragma once
// The depth wall pass (issue 16): each virtual wall drawn as one quad whose every pixel
// reprojects its baked textures, colour + per-texel depth (walls/depth_wall.h), to the current
// eye instead of showing them flat.
//
// Method: per pixel, a relief-impostor style search of the ray from the eye through the wall
// pixel behind the plane, in the texture's own parametrisation: the ray's image in the texture
// (seen from the sampling point) is a straight line, linear in sigma = s / (D_S + s) (s the
// depth behind the plane), so uniform steps in sigma between the baked depth range's ends are
// uniform steps across the texture. Steps = texels crossed, capped at maxSteps (64), then the
// exact first crossing within the last step (walls::texelCrossing: depths are constant per
// texel and a step crosses at most one texel edge per axis, so at most three texels, two
// fetches; `refine` (6) bisections come first only where maxSteps left a step longer than a
// texel); colour is sampled at the hit with the flat quad's gradients
// (the MIP level the flat wall would use, without seams at depth steps). walls::reproject is
// the same algorithm in double and is what the unit tests check against analytic truth.
//
// Why this method rather than a displaced grid mesh (textured depth meshes): it needs no mesh
// per texture (a depth texture of the same size as the colour, paged the same way), it has no
// skins to cut (the march never hits an empty texel, and disocclusions show a bounded stretch of
// the step's near side, which walls::depthWallErrorBound predicts), and its cost is per pixel,
// bounded by maxSteps, not per texel. Measured cost (bench/wall_pass_bench.cpp, one
// full-screen layer at 1024 x 1024 pixels, 512^2 textures, llvmpipe on 2 cores, ms per layer
// over the clear; 4 December 2026, load below 1): a flat layer 5.7-9.6 ms (two blended
// textures 8.7-12.7), a depth layer 40-42 ms (two blended 82-86), after the march moved to
// texel units with a division-free hit test (49-51 and 97-99 before, same runs' conditions);
// of the 49-51 ms before, a one-step march without refinement was about 15 ms (the per-pixel
// setup, the late depth test that gl_FragDepth and discard force, the gradient sampling) and
// 6 bisection steps about 8 ms. In the walkthrough the pass is a part of the frame: `bench --scale
// --walls depth` (cave4 at 1024 x 1024 per screen) ran 1.17-1.38x the flat walls' median
// frame time with 128-texel bakes and 1.70-1.72x with 512-texel ones, whose rays cross more
// texels (README, "Depth walls"); with empty-space skipping (below) 1.57-1.71x, and with the
// early depth test (below) 1.22-1.28x at 512 texels and 1.13-1.34x at 128.
// Since 4 December 2026 (session 17) the march ends in the exact crossing (two fetches instead
// of six bisections), counts its steps along the ray's longer texture axis (at most one texel
// per axis a step, as before, but up to sqrt(2) fewer for diagonal rays than the Euclidean
// length times the finer axis's texels per metre), and takes each layer's ray in texel units
// (ta, tb) from the vertex shader, where it is affine in the wall point so interpolation gives
// every pixel's exactly. One full-screen 512^2 layer at 1024 x 1024: 34.5 -> 30.7 ms with the
// crossing, 30.0 ms with both (flat 4.8-5.2). In the walkthrough at 512 texels (README, "Depth
// walls"; bench/results/scale/run18-depth-exact-crossing) depth / flat went from a median of
// 1.38 to 1.35 with the crossing and about 1.29-1.31 with both, at the same images; drawn in
// turn in one run (`bench --scale --walls flat,depth`) 1.27 at 512 texels (nine runs, 1.16-1.34)
// and 1.19 at 128 (four runs, 1.14-1.26); 1.31 over fourteen runs in session 18. Since session 19
// the frame's clear goes with its drawing (gl::SceneRenderer::beginFrame), which took 3-4 ms off
// both kinds of frame and none off this pass: 1.34-1.41 at 512 texels (four runs), 1.15-1.21 at
// 128 (two); then the bake writes, and the pass reads, halved depths (walls::marchDepths: each
// depth texel the nearest of 2 x 2 colour texels, so rays cross half as many): 1.22-1.30 at 512
// texels (five runs) and 1.23 at 128, at 39.6 dB instead of 39.3. Tried and
// not kept: half-float depths (GL_R16F, half the GPU bytes; 31.4 ms a layer, no faster) and at
// most 24 steps (no measurable gain, 0.1 dB lost).
// Empty-space skipping: a texture of its own (DepthTexture::skip; until session 18 the depth
// texture's MIP level 3, whose levels 1-2 took a quarter of the depth's GPU bytes unread) holds
// each 8 x 8 block's nearest depth over its 3 x 3 blocks; a run of walls::kSkipSteps steps whose last
// sample misses a surface at that depth is skipped (the test grows along the ray, so the hits
// are the uniform march's and walls::reproject stays its reference). The displaced-grid-mesh
// alternative is not measured.
//
// Blending and state as gl::WallPass: a premultiplied weighted sum of up to kMaxWallTextures
// layers, tested (reversed-Z GL_GREATER, no depth writes) at the quad's own depth, before the
// shader runs (early_fragment_tests), so wall pixels behind the cell's geometry cost no march.
// Pixels where no layer hits add nothing, so each wall is drawn only over the rectangle where a
// layer's march can hit (walls::depthDrawRect of each layer's content, for this view's eye,
// their union, grown by a texel): the other pixels, on average half a plant's wall texture
// (README, "Depth walls"), cost no march setup. The layers share one march (4 December 2026,
// session 15): the heaviest layer's (the plan lists weights largest first) finds the depth s
// of the ray's first hit, the next layer's only where it finds none, and every layer shows its
// texture where the ray is at s behind the wall. Each layer stays within its own bound: both
// forms of walls::depthEyeBound's proof use only that the ray depth s and the depth of the
// surface the texel shows lie in the wall's span, not that s is this layer's own hit, and every
// layer of a wall shares its span. Images change where the layers disagree about depth (what a
// blend mixes anyway). One layer costs as before; two blended 512^2 layers at 1024 x 1024
// (bench/wall_pass_bench.cpp, three alternating runs each, load about 1.5) 63.6-68.7 ms
// against 88.5-94.8 ms with a march per layer. Until 4 December 2026 (session 14) the pass tested
// the nearest reprojected surface's depth instead (gl_FragDepth), so that geometry drawn
// before behind the wall plane but in front of the baked content (structure, never baked; a
// neighbour blending in) hid it; that forced the test after the shader on every wall pixel,
// and such pixels are now drawn as a flat wall draws them. Measured side by side
// (`bench --scale 2M --bake-resolution 512 --walls depth`, cave4 at 1024 x 1024 per screen, 30
// frames, interleaved twice): median frame 58.0-59.2 ms against 65.5-67.9 ms (flat walls
// 45.4-45.5 ms in the same runs), pooled PSNR 40.2 against 40.4 dB, FLIP 0.0033 against
// 0.0030. A conservative-depth declaration (layout(depth_less) gl_FragDepth, which holds
// here) left llvmpipe's late test in place (65.4-68.2 ms).
// Since session 23 each wall is drawn over its layers' walls::depthDrawRect only (see the
// blending paragraph above): in the walkthrough at 512 texels depth / flat went from 1.18-1.33
// (three runs, whole quads) to 1.06-1.10 (three runs, flat walls still whole) and, with flat
// walls cropped to their covered rectangles as well, 1.14-1.19 (six runs, median 1.15; README,
// "Drawn only where a texture has content").

#include "display/gl/gl_object.h"
#include "display/gl/scene_renderer.h"
#include "display/off_axis.h"
#include "walls/depth_wall.h"
#include "walls/frame_planner.h"

#include <array>
#include <vector>

namespace cavewall::gl {

// One baked texture of a depth wall: colour (uploadWallTexture) and depth (uploadDepthTexture).
struct DepthWallLayer {
    GLuint colour = 0, depth = 0;   // 0: not there (left out, like WallPass)
    glm::dvec3 samplingPoint{0.0};  // world
    glm::dvec2 range{0.0};          // walls::depthRange of the depth image, metres
    float weight = 0.0f;
    GLuint skip = 0;                // DepthTexture::skip; 0: none (the march skips nothing)
    walls::TextureRect content;     // DepthTextureData::content; the whole texture by default
    glm::ivec2 depthTexels{1, 1};   // the depth texture's size: the draw rectangle grows by a texel
};

struct DepthWallDraw {
    display::ScreenQuad quad;  // world, as seen from the textures' side
    std::array<DepthWallLayer, walls::kMaxWallTextures> layers{};
    int count = 0;
};

// A depth wall's depth on the GPU: GL_R32F holding walls::DepthImage (rows top to bottom, like
// the colour: row 0 is the wall's upper edge), one level, read with texelFetch; and, for images
// of at least 8 x 8 texels, the march's skip blocks (walls::depthBlockMinimum with dilate 1) in
// a GL_R32F texture of their own (empty otherwise).
struct DepthTexture {
    GlObject depth, skip;
};
// Needs a current context.
DepthTexture uploadDepthTexture(const walls::DepthImage& image);
// The same from data whose block minima are made already (walls::depthTextureData, on the
// texture pager's thread).
DepthTexture uploadDepthTexture(const walls::DepthTextureData& data);

class DepthWallPass {
public:
    // Throws Error when the shaders do not build or the settings are out of range
    // (maxSteps [1, 1024], refine [0, 16]).
    explicit DepthWallPass(walls::ReprojectSettings settings = {});

    // As WallPass::draw: into the bound framebuffer for one view; `frustum` in the cave frame,
    // caveFromWorld places the world; `sampler` filters the colour (0: the texture's own).
    void draw(const std::vector<DepthWallDraw>& walls, const display::OffAxisFrustum& frustum,
              const glm::dmat4& caveFromWorld, GLuint sampler, FrameStats& stats) const;

private:
    struct Program {
        GlObject program;
        GLint corners = -1, projection = -1, weights = -1, eye = -1, size = -1, samples = -1, ranges = -1,
              maxSteps = -1, refine = -1, rect = -1;
    };
    walls::ReprojectSettings _settings;
    std::array<Program, walls::kMaxWallTextures> _programs;  // [n - 1] marches n layers
    GlObject _vertexArray;
    GlObject _noSkip;  // one texel of depth 0: a layer without skip blocks skips nothing
};

}  // namespace cavewall::gl
