#pragma once
// The depth wall pass: each virtual wall drawn as one quad whose every pixel reprojects its
// baked textures, colour + per-texel depth (walls/depth_wall.h), to the current eye instead of
// showing them flat.
//
// Method: per pixel, a relief-impostor style search of the ray from the eye through the wall
// pixel behind the plane, in the texture's own parametrisation: the ray's image in the texture
// (seen from the sampling point) is a straight line, linear in sigma = s / (D_S + s) (s the
// depth behind the plane), so uniform steps in sigma between the baked depth range's ends are
// uniform steps across the texture. Each layer's ray comes in texel units (ta, tb) from the
// vertex shader, where it is affine in the wall point, so every pixel's is exact. Steps =
// texels crossed along the ray's longer texture axis (at most one texel per axis a step),
// capped at maxSteps (64), then the exact first crossing within the last step
// (walls::texelCrossing: depths are constant per texel, so at most three texels, two fetches;
// `refine` (6) bisections come first only where maxSteps left a step longer than a texel);
// colour is sampled at the hit with the flat quad's gradients (the MIP level the flat wall
// would use, without seams at depth steps). Rubber sheets are cut: a hit where the ray entered
// a texel behind its surface from a texel across a depth jump (walls::depthJump) shows the far
// side's colour texel just before the entry instead, or nothing when the far side is empty
// (walls::reproject, "Cutting rubber sheets"). The march reads the bake's halved depths
// (walls::marchDepths). walls::reproject is the same algorithm in double and is what the unit
// tests check against analytic truth.
//
// Empty-space skipping: a texture of its own (DepthTexture::skip) holds each 8 x 8 block's
// nearest depth over its 3 x 3 blocks; a run of walls::kSkipSteps steps whose last sample
// misses a surface at that depth is skipped (the test grows along the ray, so the hits are the
// uniform march's and walls::reproject stays its reference).
//
// Blending and state as gl::WallPass: a premultiplied weighted sum of up to kMaxWallTextures
// layers, tested (reversed-Z GL_GREATER, no depth writes) at the quad's own depth, before the
// shader runs (early_fragment_tests), so wall pixels behind the cell's geometry cost no march;
// geometry drawn behind the wall plane but in front of the baked content is therefore drawn
// over as a flat wall draws over it. Pixels where no layer hits add nothing, so each wall is
// drawn only over the rectangle where a layer's march can hit (walls::depthDrawRect of each
// layer's content, for this view's eye, their union, grown by a texel). The layers share one
// march: the heaviest layer's (the plan lists weights largest first) finds the depth s of the
// ray's first hit, the next layer's only where it finds none, and every layer shows its texture
// where the ray is at s behind the wall (where the march cut a sheet, every layer shows its
// colour texel just before its own ray point at s). Each layer stays within its own bound: both forms of
// walls::depthEyeBound's proof use only that the ray depth s and the depth of the surface the
// texel shows lie in the wall's span, not that s is this layer's own hit, and every layer of a
// wall shares its span. Images change where the layers disagree about depth (what a blend
// mixes anyway).
//
// Why a march rather than a displaced grid mesh (textured depth meshes): it needs no mesh per
// texture (a depth texture of the same size as the colour, paged the same way), its sheets are
// cut per pixel where the depths jump (disocclusions show a bounded stretch of the step's far
// side, which walls::depthWallErrorBound predicts), and its cost is per pixel,
// bounded by maxSteps, not per texel. The exact crossing, the skip blocks, the halved depths,
// the shared march, the early depth test and the draw rectangles each make the pass faster;
// depths stay 32-bit floats because half floats draw no faster.
// Derivation: docs/depth-walls.md.

#include "display/gl/gl_object.h"
#include "render/gl/scene_renderer.h"
#include "display/off_axis.h"
#include "walls/depth_wall.h"
#include "walls/frame_select.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::walls::gl {

// One baked texture of a depth wall: colour (uploadWallTexture) and depth (uploadDepthTexture).
struct DepthWallLayer {
    GLuint colour = 0, depth = 0;   // 0: not there (left out, like WallPass)
    glm::dvec3 samplingPoint{0.0};  // world
    glm::dvec2 range{0.0};          // walls::depthRange of the depth image, metres
    float weight = 0.0f;
    GLuint skip = 0;               // DepthTexture::skip; 0: none (the march skips nothing)
    walls::TextureRect content{};  // DepthTextureData::content; the whole texture by default
    glm::ivec2 depthTexels{1, 1};  // the depth texture's size: the draw rectangle grows by a texel
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
    display::gl::GlObject depth, skip;
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
              const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const;

    // The same walls, writing only depth: each pixel where a layer's march hits and the
    // layers' summed alpha is at least 1/2 gets the depth of the hit (the point s behind the
    // wall on the eye's ray) if it is nearer than what the buffer holds; colour is left as it is
    // (the colour mask is all on afterwards). For reading back the depth a viewer sees
    // (display/eye_distance.h) after a frame is drawn; the programs are built on the first call.
    void drawDepth(const std::vector<DepthWallDraw>& walls, const display::OffAxisFrustum& frustum,
                   const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const;

private:
    struct Program {
        display::gl::GlObject program;
        GLint corners = -1, projection = -1, weights = -1, eye = -1, size = -1, samples = -1, ranges = -1,
              maxSteps = -1, refine = -1, cutSheets = -1, jumps = -1, rect = -1;
    };
    using Programs = std::array<Program, walls::kMaxWallTextures>;  // [n - 1] marches n layers
    static Program build(int layers, const std::string& fragment);
    void drawWith(const Programs& programs, const std::vector<DepthWallDraw>& walls,
                  const display::OffAxisFrustum& frustum, const glm::dmat4& caveFromWorld, GLuint sampler,
                  display::FrameStats& stats) const;
    walls::ReprojectSettings _settings;
    Programs _programs;
    mutable std::optional<Programs> _depthPrograms;
    display::gl::GlObject _vertexArray;
    display::gl::GlObject _noSkip;  // one texel of depth 0: a layer without skip blocks skips nothing
};

}  // namespace cavewall::walls::gl
