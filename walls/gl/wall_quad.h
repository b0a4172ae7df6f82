#pragma once
// Drawing baked wall textures at run time (and in the bake tests): a MIP-mapped sRGB texture
// from the levels of a baked file, drawn on its wall quad through a display frustum with
// premultiplied-alpha blending.

#include "display/gl/gl_object.h"
#include "display/off_axis.h"
#include "scenes/scene.h"
#include "walls/texture_blocks.h"
#include "walls/upload_cursor.h"

#include <vector>

namespace cavewall::walls::gl {

// Uploads MIP levels (largest first, each the next MIP size of the previous, premultiplied as
// walls/texture_mips.h says) as one GL_SRGB8_ALPHA8 texture with trilinear filtering and
// clamped edges. Needs a current context. Throws Error for inconsistent levels.
display::gl::GlObject uploadWallTexture(std::vector<scenes::Image> levels);
// As above for any format of walls/texture_blocks.h: RGBA8 as above; Bc1 and Bc3 as
// GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT / _DXT5_EXT with their blocks uploaded as they are
// (glCompressedTextureSubImage2D), so the sampler decodes sRGB to linear as for RGBA8. Throws
// Error when the context lacks S3TC with sRGB (supportsTextureFormat) or levels are inconsistent.
display::gl::GlObject uploadWallTexture(const walls::TextureLevels& levels);
// uploadWallTexture in steps, for an uploader that spreads a texture over frames
// (walls/gl/texture_store.h): the texture with every level's storage and the sampling state but
// no texels (same checks and errors), then each band of walls/upload_cursor.h from `levels`
// (the same levels, unchanged). Sampling it before its last band is up reads undefined texels.
display::gl::GlObject createWallTexture(const walls::TextureLevels& levels);
void uploadWallTextureBand(GLuint texture, const walls::TextureLevels& levels, const walls::UploadPiece& piece);
// Whether the current context can sample `format` (Rgba8 always; Bc1, Bc3 need
// GL_EXT_texture_compression_s3tc and GL_EXT_texture_sRGB or ..._s3tc_srgb).
bool supportsTextureFormat(walls::TextureFormat format);
// The GL internal format of `format` (GL_SRGB8_ALPHA8 or the sRGB S3TC formats).
unsigned glInternalFormat(walls::TextureFormat format);

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
    display::gl::GlObject _program, _vertexArray;
    GLint _modelView = -1, _projection = -1, _weight = -1;
};

}  // namespace cavewall::walls::gl
