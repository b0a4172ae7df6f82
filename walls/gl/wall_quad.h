#pragma once
// Drawing baked wall textures at run time (and in the bake tests): a MIP-mapped sRGB texture
// from the levels of a baked file, drawn on its wall quad through a display frustum with
// premultiplied-alpha blending.

#include "display/gl/gl_object.h"
#include "display/off_axis.h"
#include "scenes/scene.h"

#include <vector>

namespace cavewall::gl {

// Uploads MIP levels (largest first, each the next MIP size of the previous, premultiplied as
// walls/texture_mips.h says) as one GL_SRGB8_ALPHA8 texture with trilinear filtering and
// clamped edges. Needs a current context. Throws Error for inconsistent levels.
gl::GlObject uploadWallTexture(const std::vector<scenes::Image>& levels);

class WallQuadDrawer {
public:
    // Builds the shader; needs a current GL 4.5 context.
    WallQuadDrawer();

    // Draws `texture` on `quad` (frame F, e.g. the world, as seen from the texture's side;
    // texel row 0 along the upper edge) into the bound draw framebuffer with the current
    // viewport, seen through `frustum` (given in F). The sample is scaled by `weight` (blend
    // zones) and blended premultiplied: dst = src + (1 - src.a) dst, in linear light with
    // GL_FRAMEBUFFER_SRGB on. Reversed-Z depth test (GL_GREATER) without depth writes, so
    // geometry drawn before in front of the wall hides it.
    void draw(const display::OffAxisFrustum& frustum, const display::ScreenQuad& quad, unsigned texture,
              float weight = 1.0f);

private:
    gl::GlObject _program, _vertexArray;
    GLint _modelView = -1, _projection = -1, _weight = -1;
};

}  // namespace cavewall::gl
