#pragma once
// The wall pass: every virtual wall drawn as one quad that mixes its baked textures.
//
// A texture of a wall is baked with the wall as its screen (display::offAxisFrustum with eye =
// sampling point), so its image square is exactly the wall rectangle: every texture of a wall
// uses the same texture coordinates, u along lowerLeft -> lowerRight, v from the top edge down
// (texture rows are stored top to bottom). Texture colour is premultiplied by alpha, so the
// weighted sum  c = sum_i w_i tex_i  is itself premultiplied and is blended over what is drawn
// (ONE, ONE_MINUS_SRC_ALPHA; destination alpha kept). The weights sum to 1 - geometryWeight:
// as the geometry of the cell behind fades in, the texture fades out over it. Depth-tested
// (reversed-Z, GL_GREATER) against the geometry, without depth writes, no face culling. Only the
// union of the textures' content rectangles (WallDraw::contents) is drawn: elsewhere every
// texture is transparent, so the sum adds nothing.
// Needs the rendering context current; the program is built by the constructor (only scenes
// with virtual walls construct a WallPass).

#include "display/gl/gl_object.h"
#include "render/gl/scene_renderer.h"
#include "display/off_axis.h"
#include "walls/frame_select.h"
#include "walls/texture_rect.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::walls::gl {

using walls::kMaxWallTextures;  // walls/frame_select.h

struct WallDraw {
    display::ScreenQuad quad;  // world frame, metres
    std::array<GLuint, kMaxWallTextures> textures{};
    std::array<float, kMaxWallTextures> weights{};  // >= 0, sum <= 1
    int count = 0;                                  // textures used
    // Where each texture has content (walls::coveredRect, grown for MIP filtering; the whole
    // texture by default): the wall is drawn over their union only.
    std::array<walls::TextureRect, kMaxWallTextures> contents{};
};

class WallPass {
public:
    // Throws Error when the shaders do not build.
    WallPass();

    // Draws `walls` for one view into the bound framebuffer (viewport, scissor and colour mask
    // already set by the caller, depth holding the view's geometry). `frustum` is the view's
    // (cave frame); caveFromWorld places the world. Adds one draw call and 2 triangles per wall.
    void draw(const std::vector<WallDraw>& walls, const display::OffAxisFrustum& frustum,
              const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const;

    // The same walls, writing only depth: each pixel where the weighted sum's alpha is at least
    // 1/2 (the wall's texture covers it more than what lies behind shows) gets the quad's depth
    // if it is nearer than what the buffer holds; colour is left as it is (the colour mask is
    // all on afterwards). For reading back the depth a viewer sees (display/eye_distance.h)
    // after a frame is drawn; the programs are built on the first call.
    void drawDepth(const std::vector<WallDraw>& walls, const display::OffAxisFrustum& frustum,
                   const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const;

private:
    struct Program {
        display::gl::GlObject program;
        GLint corners = -1, projection = -1, weights = -1, rect = -1;
    };
    using Programs = std::array<Program, kMaxWallTextures>;  // [n - 1] samples n textures
    static Program build(const std::string& fragment);
    void drawWith(const Programs& programs, const std::vector<WallDraw>& walls, const display::OffAxisFrustum& frustum,
                  const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const;
    Programs _programs;
    mutable std::optional<Programs> _depthPrograms;
    display::gl::GlObject _vertexArray;
};

}  // namespace cavewall::walls::gl
