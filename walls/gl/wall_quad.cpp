#include "walls/gl/wall_quad.h"

#include "config/error.h"
#include "display/gl/shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <string>
#include <utility>

namespace cavewall::walls::gl {

namespace {

constexpr const char* kQuadName = "wall quad";

// The quad is the unit square (u, v) of its model frame; no vertex buffer is needed.
constexpr const char* kQuadVertex = R"(#version 450 core
uniform mat4 uModelView;   // eye-relative: model (u, v, 0) -> view
uniform mat4 uProjection;
out vec2 vTexCoord;
void main() {
    vec2 uv = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vTexCoord = vec2(uv.x, 1.0 - uv.y);  // texel row 0 is the upper edge
    gl_Position = uProjection * (uModelView * vec4(uv, 0.0, 1.0));
}
)";

constexpr const char* kQuadFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D uTexture;  // sRGB: sampled as linear premultiplied
uniform float uWeight;
in vec2 vTexCoord;
out vec4 fragColor;
void main() { fragColor = uWeight * texture(uTexture, vTexCoord); }
)";

}  // namespace

bool supportsTextureFormat(walls::TextureFormat format) {
    if (format == walls::TextureFormat::Rgba8) return true;
    return epoxy_has_gl_extension("GL_EXT_texture_compression_s3tc") &&
           (epoxy_has_gl_extension("GL_EXT_texture_sRGB") ||
            epoxy_has_gl_extension("GL_EXT_texture_compression_s3tc_srgb"));
}

unsigned glInternalFormat(walls::TextureFormat format) {
    switch (format) {
        case walls::TextureFormat::Bc1: return GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;
        case walls::TextureFormat::Bc3: return GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT;
        case walls::TextureFormat::Rgba8: break;
    }
    return GL_SRGB8_ALPHA8;
}

namespace {

// Throws unless level i of `levels` has the i-th MIP size of level 0 and its bytes.
void checkLevels(const walls::TextureLevels& levels) {
    if (levels.count() == 0 || levels.width() <= 0 || levels.height() <= 0)
        throw Error("wall texture: expected at least one non-empty MIP level, got none");
    const bool rgba = levels.format == walls::TextureFormat::Rgba8;
    const std::string name =
        rgba ? "'" + levels.rgba[0].name + "'" : std::string(walls::textureFormatName(levels.format));
    for (std::size_t i = 0; i < levels.count(); ++i) {
        const int w = std::max(1, levels.width() >> i), h = std::max(1, levels.height() >> i);
        const int gotW = rgba ? levels.rgba[i].width : levels.blocks[i].width;
        const int gotH = rgba ? levels.rgba[i].height : levels.blocks[i].height;
        const std::size_t bytes = rgba ? levels.rgba[i].rgba.size() : levels.blocks[i].blocks.size();
        if (gotW != w || gotH != h || bytes != walls::levelBytes(levels.format, w, h))
            throw Error("wall texture " + name + ": MIP level " + std::to_string(i) + ": expected " +
                        std::to_string(w) + " x " + std::to_string(h) + " (" +
                        std::to_string(walls::levelBytes(levels.format, w, h)) + " bytes), got " +
                        std::to_string(gotW) + " x " + std::to_string(gotH) + " (" + std::to_string(bytes) + " bytes)");
    }
}

}  // namespace

display::gl::GlObject createWallTexture(const walls::TextureLevels& levels) {
    if (levels.format != walls::TextureFormat::Rgba8 && !supportsTextureFormat(levels.format))
        throw Error(
            "wall texture: expected a context that samples " + std::string(walls::textureFormatName(levels.format)) +
            " (GL_EXT_texture_compression_s3tc with sRGB), got one without it; bake with --texture-format rgba8");
    checkLevels(levels);
    display::gl::GlObject t = display::gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), static_cast<GLsizei>(levels.count()), glInternalFormat(levels.format), levels.width(),
                       levels.height());
    glTextureParameteri(t.id(), GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.count()) - 1);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

void uploadWallTextureBand(GLuint texture, const walls::TextureLevels& levels, const walls::UploadPiece& piece) {
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    const auto level = static_cast<std::size_t>(piece.level);
    if (levels.format == walls::TextureFormat::Rgba8) {
        const scenes::Image& l = levels.rgba[level];
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(texture, piece.level, 0, piece.y, l.width, piece.rows, GL_RGBA, GL_UNSIGNED_BYTE,
                            l.rgba.data() + piece.offset);
        return;
    }
    const walls::BlockLevel& l = levels.blocks[level];
    glCompressedTextureSubImage2D(texture, piece.level, 0, piece.y, l.width, piece.rows,
                                  glInternalFormat(levels.format), static_cast<GLsizei>(piece.bytes),
                                  l.blocks.data() + piece.offset);
}

display::gl::GlObject uploadWallTexture(const walls::TextureLevels& levels) {
    display::gl::GlObject t = createWallTexture(levels);
    walls::UploadCursor cursor(levels);
    while (!cursor.done()) uploadWallTextureBand(t.id(), levels, cursor.next(levels.bytes()));
    return t;
}

display::gl::GlObject uploadWallTexture(std::vector<scenes::Image> levels) {
    return uploadWallTexture(walls::TextureLevels(std::move(levels)));
}

WallQuadDrawer::WallQuadDrawer()
    : _program(display::gl::buildProgram(kQuadName, kQuadVertex, kQuadFragment)),
      _vertexArray(display::gl::createVertexArray()) {
    _modelView = display::gl::uniformLocation(_program.id(), kQuadName, "uModelView");
    _projection = display::gl::uniformLocation(_program.id(), kQuadName, "uProjection");
    _weight = display::gl::uniformLocation(_program.id(), kQuadName, "uWeight");
}

void WallQuadDrawer::draw(const display::OffAxisFrustum& frustum, const display::ScreenQuad& quad, unsigned texture,
                          float weight) {
    const glm::dvec3 right = quad.lowerRight - quad.lowerLeft, up = quad.upperLeft - quad.lowerLeft;
    const glm::dmat4 frameFromModel(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0), glm::dvec4(glm::cross(right, up), 0.0),
                                    glm::dvec4(quad.lowerLeft, 1.0));
    const glm::mat4 modelView = display::eyeRelativeModelView(frustum, frameFromModel);
    const glm::mat4 projection(frustum.clipFromView);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(_program.id());
    glUniformMatrix4fv(_modelView, 1, GL_FALSE, glm::value_ptr(modelView));
    glUniformMatrix4fv(_projection, 1, GL_FALSE, glm::value_ptr(projection));
    glUniform1f(_weight, weight);
    glBindTextureUnit(0, texture);
    glBindSampler(0, 0);
    glBindVertexArray(_vertexArray.id());
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace cavewall::walls::gl
