#include "walls/gl/wall_pass.h"

#include "display/gl/shader.h"

#include <glm/gtc/type_ptr.hpp>

namespace cavewall::gl {

namespace {

constexpr const char* kName = "walls";

constexpr const char* kVertex = R"(#version 450 core
uniform vec3 uCorners[4];    // lowerLeft, lowerRight, upperLeft, upperRight in the eye-relative view frame
uniform mat4 uProjection;
out vec2 vUv;
const vec2 kUv[4] = vec2[4](vec2(0.0, 1.0), vec2(1.0, 1.0), vec2(0.0, 0.0), vec2(1.0, 0.0));
void main() {
    vUv = kUv[gl_VertexID];
    gl_Position = uProjection * vec4(uCorners[gl_VertexID], 1.0);
}
)";

constexpr const char* kFragment = R"(#version 450 core
in vec2 vUv;
layout(binding = 0) uniform sampler2D uTexture0;
layout(binding = 1) uniform sampler2D uTexture1;
layout(binding = 2) uniform sampler2D uTexture2;
layout(binding = 3) uniform sampler2D uTexture3;
uniform vec4 uWeights;
out vec4 fragColor;           // premultiplied, linear
void main() {
    vec4 c = uWeights.x * texture(uTexture0, vUv);
    if (uWeights.y > 0.0) c += uWeights.y * texture(uTexture1, vUv);
    if (uWeights.z > 0.0) c += uWeights.z * texture(uTexture2, vUv);
    if (uWeights.w > 0.0) c += uWeights.w * texture(uTexture3, vUv);
    fragColor = c;
}
)";

}  // namespace

WallPass::WallPass()
    : _program(buildProgram(kName, kVertex, kFragment)), _vertexArray(createVertexArray()) {
    _corners = uniformLocation(_program.id(), kName, "uCorners");
    _projection = uniformLocation(_program.id(), kName, "uProjection");
    _weights = uniformLocation(_program.id(), kName, "uWeights");
}

void WallPass::draw(const std::vector<WallDraw>& walls, const display::OffAxisFrustum& frustum,
                    const glm::dmat4& caveFromWorld, GLuint sampler, FrameStats& stats) const {
    if (walls.empty()) return;
    glUseProgram(_program.id());
    glBindVertexArray(_vertexArray.id());
    const glm::mat4 projection(frustum.clipFromView);
    glUniformMatrix4fv(_projection, 1, GL_FALSE, glm::value_ptr(projection));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    // Corners go to the view frame in double; only the eye-relative result is rounded to float.
    const glm::dmat4 viewFromWorld = frustum.viewFromFrame * caveFromWorld;
    for (const WallDraw& w : walls) {
        const glm::dvec3 corners[4] = {w.quad.lowerLeft, w.quad.lowerRight, w.quad.upperLeft,
                                       w.quad.lowerRight + w.quad.upperLeft - w.quad.lowerLeft};
        glm::vec3 view[4];
        for (int i = 0; i < 4; ++i) view[i] = glm::vec3(viewFromWorld * glm::dvec4(corners[i], 1.0));
        glUniform3fv(_corners, 4, glm::value_ptr(view[0]));
        glm::vec4 weights(0.0f);
        for (int i = 0; i < kMaxWallTextures; ++i) {
            const bool used = i < w.count && w.textures[i] != 0;
            weights[i] = used ? w.weights[i] : 0.0f;
            glBindTextureUnit(i, used ? w.textures[i] : w.textures[0]);
            glBindSampler(i, sampler);
        }
        glUniform4fv(_weights, 1, glm::value_ptr(weights));
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        ++stats.drawCalls;
        stats.triangles += 2;
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

}  // namespace cavewall::gl
