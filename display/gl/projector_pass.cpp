#include "display/gl/projector_pass.h"

#include "display/gl/shader.h"

#include <cstdint>

namespace cavewall::display::gl {
namespace {

constexpr const char* kProjectorName = "projector";

constexpr const char* kProjectorVertex = R"(#version 450 core
layout(location = 0) in vec2 aOutput;  // projector output, [0, 1]², origin lower-left
layout(location = 1) in vec2 aUv;      // rendered image
out vec2 vUv;
void main() {
    vUv = aUv;
    gl_Position = vec4(aOutput * 2.0 - 1.0, 0.0, 1.0);
}
)";

// The formula of display/screen_correction.h. The mask is 16-bit: 1 is exactly 65535, so
// "alone" is any weight above the second-highest level. The shader encodes sRGB itself (sRGB
// writes are off): llvmpipe's fixed-function encode is up to 0.9 levels off the exact value
// (the shader's, 0.8), which puts two blended projectors more than a level off one.
constexpr const char* kProjectorFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D uImage;  // sRGB: sampling decodes to linear light
layout(binding = 1) uniform sampler2D uBlend;  // linear weights over the output
uniform vec2 uOutputSize;
uniform vec3 uBlack;
in vec2 vUv;
out vec4 fragColor;
vec3 encodeSrgb(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
    vec3 image = texture(uImage, vUv).rgb;
    float blend = texture(uBlend, gl_FragCoord.xy / uOutputSize).r;
    float alone = step(1.0 - 0.5 / 65535.0, blend);
    fragColor = vec4(encodeSrgb(image * blend + uBlack * (1.0 - image) * alone), 1.0);
}
)";

struct Vertex {
    glm::vec2 output, uv;
};

GlObject blendTexture(const std::optional<display::BlendMask>& mask) {
    const display::BlendMask white{1, 1, {65535}};
    const display::BlendMask& m = mask ? *mask : white;
    GlObject t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_R16, m.width, m.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glTextureSubImage2D(t.id(), 0, 0, 0, m.width, m.height, GL_RED, GL_UNSIGNED_SHORT, m.weights.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

// Linear filtering without MIP levels, clamped: the rendered image has one level.
GlObject linearSampler() {
    GlObject s = createSampler();
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return s;
}

}  // namespace

ProjectorPass::ProjectorPass(const display::ScreenCorrection& correction, glm::ivec2 size, int images)
    : _program(buildProgram(kProjectorName, kProjectorVertex, kProjectorFragment)), _vertexArray(createVertexArray()),
      _vertices(createBuffer()), _indices(createBuffer()), _blend(blendTexture(correction.blend)),
      _sampler(linearSampler()), _size(size), _black(correction.blackLevel) {
    _outputSizeUniform = uniformLocation(_program.id(), kProjectorName, "uOutputSize");
    _blackUniform = uniformLocation(_program.id(), kProjectorName, "uBlack");
    std::vector<Vertex> vertices;
    for (const display::WarpNode& n : correction.warp.nodes) vertices.push_back({n.xy, n.uv});
    const std::vector<unsigned> indices = display::warpTriangles(correction.warp);
    _indexCount = static_cast<int>(indices.size());
    glNamedBufferStorage(_vertices.id(), vertices.size() * sizeof(Vertex), vertices.data(), 0);
    if (!indices.empty()) glNamedBufferStorage(_indices.id(), indices.size() * sizeof(unsigned), indices.data(), 0);
    const GLuint vao = _vertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, _vertices.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, _indices.id());
    for (GLuint a = 0; a < 2; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 2, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec2));
        glVertexArrayAttribBinding(vao, a, 0);
    }
    for (int i = 0; i < images; ++i) {
        Output o{createTexture(GL_TEXTURE_2D), createFramebuffer()};
        glTextureStorage2D(o.color.id(), 1, GL_SRGB8_ALPHA8, size.x, size.y);
        glTextureParameteri(o.color.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(o.color.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glNamedFramebufferTexture(o.framebuffer.id(), GL_COLOR_ATTACHMENT0, o.color.id(), 0);
        _outputs.push_back(std::move(o));
    }
}

void ProjectorPass::apply(unsigned sourceTexture, int image) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, _outputs[image].framebuffer.id());
    glViewport(0, 0, _size.x, _size.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(_outputs[image].framebuffer.id(), GL_COLOR, 0, black);
    glDisable(GL_FRAMEBUFFER_SRGB);  // the shader encodes
    glUseProgram(_program.id());
    glUniform2f(_outputSizeUniform, static_cast<float>(_size.x), static_cast<float>(_size.y));
    glUniform3f(_blackUniform, _black.r, _black.g, _black.b);
    glBindTextureUnit(0, sourceTexture);
    glBindSampler(0, _sampler.id());
    glBindTextureUnit(1, _blend.id());
    glBindVertexArray(_vertexArray.id());
    glDrawElements(GL_TRIANGLES, _indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glBindSampler(0, 0);
    glUseProgram(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

scenes::Image ProjectorPass::read(int image, std::string name) const {
    return readFramebuffer(_outputs[image].framebuffer.id(), GL_COLOR_ATTACHMENT0, _size, std::move(name));
}

ProjectorPasses::ProjectorPasses(const display::Display& display, const RenderTargets& targets) {
    for (int s = 0; s < targets.screenCount(); ++s) {
        const auto correction = display::loadScreenCorrection(display.config(), s);
        _passes.push_back(correction
                              ? std::make_unique<ProjectorPass>(*correction, targets.size(s), targets.imageCount(s))
                              : nullptr);
    }
}

bool ProjectorPasses::any() const {
    for (const auto& p : _passes)
        if (p) return true;
    return false;
}

void ProjectorPasses::apply(const RenderTargets& targets) {
    for (int s = 0; s < static_cast<int>(_passes.size()); ++s)
        if (_passes[s])
            for (int i = 0; i < targets.imageCount(s); ++i) _passes[s]->apply(targets.colorTexture(s, i), i);
}

std::vector<scenes::ScreenImage> ProjectorPasses::read(const std::vector<scenes::ScreenImage>& frame) const {
    std::vector<scenes::ScreenImage> out;
    for (const scenes::ScreenImage& f : frame)
        if (ProjectorPass* p = pass(f.screen))
            out.push_back({f.screen, f.image, f.stem + "-warped", p->read(f.image, f.stem + "-warped")});
    return out;
}

}  // namespace cavewall::display::gl
