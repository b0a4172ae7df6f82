#include "walls/gl/wall_quad.h"

#include "config/error.h"
#include "display/gl/shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <string>

namespace cavewall::gl {

namespace {

constexpr const char* kName = "wall quad";

// The quad is the unit square (u, v) of its model frame; no vertex buffer is needed.
constexpr const char* kVertex = R"(#version 450 core
uniform mat4 uModelView;   // eye-relative: model (u, v, 0) -> view
uniform mat4 uProjection;
out vec2 vTexCoord;
void main() {
    vec2 uv = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vTexCoord = vec2(uv.x, 1.0 - uv.y);  // texel row 0 is the upper edge
    gl_Position = uProjection * (uModelView * vec4(uv, 0.0, 1.0));
}
)";

constexpr const char* kFragment = R"(#version 450 core
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

gl::GlObject uploadWallTexture(const walls::TextureLevels& levels) {
    if (levels.format == walls::TextureFormat::Rgba8) return uploadWallTexture(levels.rgba);
    const std::string name(walls::textureFormatName(levels.format));
    if (!supportsTextureFormat(levels.format))
        throw Error("wall texture: expected a context that samples " + name +
                    " (GL_EXT_texture_compression_s3tc with sRGB), got one without it; bake with --texture-format rgba8");
    const auto& l = levels.blocks;
    if (l.empty() || l[0].width <= 0 || l[0].height <= 0)
        throw Error("wall texture: expected at least one non-empty MIP level, got none");
    const GLenum internal = glInternalFormat(levels.format);
    gl::GlObject t = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), static_cast<GLsizei>(l.size()), internal, l[0].width, l[0].height);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    for (std::size_t i = 0; i < l.size(); ++i) {
        const int w = std::max(1, l[0].width >> i), h = std::max(1, l[0].height >> i);
        if (l[i].width != w || l[i].height != h || l[i].blocks.size() != walls::levelBytes(levels.format, w, h))
            throw Error("wall texture: " + name + " MIP level " + std::to_string(i) + ": expected " + std::to_string(w) +
                        " x " + std::to_string(h) + ", got " + std::to_string(l[i].width) + " x " +
                        std::to_string(l[i].height));
        glCompressedTextureSubImage2D(t.id(), static_cast<GLint>(i), 0, 0, w, h, internal,
                                      static_cast<GLsizei>(l[i].blocks.size()), l[i].blocks.data());
    }
    glTextureParameteri(t.id(), GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(l.size()) - 1);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

gl::GlObject uploadWallTexture(const std::vector<scenes::Image>& levels) {
    if (levels.empty() || levels[0].width <= 0 || levels[0].height <= 0)
        throw Error("wall texture: expected at least one non-empty MIP level, got none");
    gl::GlObject t = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), static_cast<GLsizei>(levels.size()), GL_SRGB8_ALPHA8, levels[0].width, levels[0].height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const scenes::Image& l = levels[i];
        const int w = std::max(1, levels[0].width >> i), h = std::max(1, levels[0].height >> i);
        if (l.width != w || l.height != h || l.rgba.size() != std::size_t(w) * h * 4)
            throw Error("wall texture '" + l.name + "': MIP level " + std::to_string(i) + ": expected " +
                        std::to_string(w) + " x " + std::to_string(h) + " RGBA, got " + std::to_string(l.width) +
                        " x " + std::to_string(l.height));
        glTextureSubImage2D(t.id(), static_cast<GLint>(i), 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, l.rgba.data());
    }
    glTextureParameteri(t.id(), GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.size()) - 1);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

WallQuadDrawer::WallQuadDrawer()
    : _program(gl::buildProgram(kName, kVertex, kFragment)), _vertexArray(gl::createVertexArray()) {
    _modelView = gl::uniformLocation(_program.id(), kName, "uModelView");
    _projection = gl::uniformLocation(_program.id(), kName, "uProjection");
    _weight = gl::uniformLocation(_program.id(), kName, "uWeight");
}

void WallQuadDrawer::draw(const display::OffAxisFrustum& frustum, const display::ScreenQuad& quad, unsigned texture,
                          float weight) {
    const glm::dvec3 right = quad.lowerRight - quad.lowerLeft, up = quad.upperLeft - quad.lowerLeft;
    const glm::dmat4 frameFromModel(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0),
                                    glm::dvec4(glm::cross(right, up), 0.0), glm::dvec4(quad.lowerLeft, 1.0));
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

}  // namespace cavewall::gl
