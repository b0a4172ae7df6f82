#include "walls/gl/wall_pass.h"

#include "display/gl/shader.h"
#include "walls/gl/wall_pass_state.h"

#include <glm/gtc/type_ptr.hpp>

#include <string>

namespace cavewall::walls::gl {

namespace {

constexpr const char* kWallsName = "walls";

constexpr const char* kWallsVertex = R"(#version 450 core
uniform vec3 uCorners[4];    // lowerLeft, lowerRight, upperLeft, upperRight in the eye-relative view frame
uniform mat4 uProjection;
uniform vec4 uRect;          // the part of the wall drawn: u, t of its upper left and lower right corners
out vec2 vUv;
const vec2 kUv[4] = vec2[4](vec2(0.0, 1.0), vec2(1.0, 1.0), vec2(0.0, 0.0), vec2(1.0, 0.0));
void main() {
    vUv = mix(uRect.xy, uRect.zw, kUv[gl_VertexID]);
    gl_Position = uProjection * vec4(uCorners[gl_VertexID], 1.0);
}
)";

// One program per number of textures, each sampling exactly that many: llvmpipe runs the body
// of a uniform `if` for every fragment whatever the condition, so one shader with four
// conditional samples paid for four samples on every wall (2.5x the fill time of one sample
// at 1024 x 1024; bench/wall_pass_bench.cpp).
std::string wallsFragmentSource(int textures) {
    std::string s =
        "#version 450 core\nin vec2 vUv;\nuniform vec4 uWeights;\nout vec4 fragColor;  // premultiplied, linear\n";
    for (int i = 0; i < textures; ++i)
        s += "layout(binding = " + std::to_string(i) + ") uniform sampler2D uTexture" + std::to_string(i) + ";\n";
    s += "void main() {\n    fragColor = uWeights.x * texture(uTexture0, vUv)";
    for (int i = 1; i < textures; ++i)
        s += "\n        + uWeights[" + std::to_string(i) + "] * texture(uTexture" + std::to_string(i) + ", vUv)";
    return s + ";\n}\n";
}

// The depth-only variant: the same sum, and the pixel keeps the quad's depth where it covers
// at least half (drawDepth).
std::string wallsDepthFragmentSource(int textures) {
    std::string s = wallsFragmentSource(textures);
    s.replace(s.rfind(";\n}\n"), 4, ";\n    if (fragColor.a < 0.5) discard;\n}\n");
    return s;
}

}  // namespace

WallPass::Program WallPass::build(const std::string& fragment) {
    Program p;
    p.program = display::gl::buildProgram(kWallsName, kWallsVertex, fragment);
    p.corners = display::gl::uniformLocation(p.program.id(), kWallsName, "uCorners");
    p.projection = display::gl::uniformLocation(p.program.id(), kWallsName, "uProjection");
    p.weights = display::gl::uniformLocation(p.program.id(), kWallsName, "uWeights");
    p.rect = display::gl::uniformLocation(p.program.id(), kWallsName, "uRect");
    return p;
}

WallPass::WallPass() : _vertexArray(display::gl::createVertexArray()) {
    for (int n = 1; n <= kMaxWallTextures; ++n) _programs[n - 1] = build(wallsFragmentSource(n));
}

void WallPass::draw(const std::vector<WallDraw>& walls, const display::OffAxisFrustum& frustum,
                    const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const {
    if (walls.empty()) return;
    drawBlendedWalls([&] { drawWith(_programs, walls, frustum, caveFromWorld, sampler, stats); });
}

void WallPass::drawDepth(const std::vector<WallDraw>& walls, const display::OffAxisFrustum& frustum,
                         const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const {
    if (walls.empty()) return;
    drawWallDepth(
        _depthPrograms, [](int n) { return build(wallsDepthFragmentSource(n)); },
        [&](const Programs& programs) { drawWith(programs, walls, frustum, caveFromWorld, sampler, stats); });
}

void WallPass::drawWith(const Programs& programs, const std::vector<WallDraw>& walls,
                        const display::OffAxisFrustum& frustum, const glm::dmat4& caveFromWorld, GLuint sampler,
                        display::FrameStats& stats) const {
    glBindVertexArray(_vertexArray.id());
    const glm::mat4 projection(frustum.clipFromView);
    // Corners go to the view frame in double; only the eye-relative result is rounded to float.
    const glm::dmat4 viewFromWorld = frustum.viewFromFrame * caveFromWorld;
    for (const WallDraw& w : walls) {
        // Textures that are not there (id 0) are left out; the program samples the rest.
        glm::vec4 weights(0.0f);
        int used = 0;
        walls::TextureRect rect = walls::noRect();
        for (int i = 0; i < w.count && i < kMaxWallTextures; ++i) {
            if (w.textures[i] == 0) continue;
            rect = walls::unite(rect, w.contents[i]);
            weights[used] = w.weights[i];
            glBindTextureUnit(used, w.textures[i]);
            glBindSampler(used++, sampler);
        }
        if (used == 0 || rect.empty()) continue;
        const std::array<glm::dvec3, 4> corners = walls::stripCorners(w.quad, rect);
        glm::vec3 view[4];
        for (int i = 0; i < 4; ++i) view[i] = glm::vec3(viewFromWorld * glm::dvec4(corners[i], 1.0));
        const Program& p = programs[used - 1];
        glUseProgram(p.program.id());
        glUniformMatrix4fv(p.projection, 1, GL_FALSE, glm::value_ptr(projection));
        glUniform3fv(p.corners, 4, glm::value_ptr(view[0]));
        glUniform4fv(p.weights, 1, glm::value_ptr(weights));
        glUniform4f(p.rect, float(rect.lo.x), float(rect.lo.y), float(rect.hi.x), float(rect.hi.y));
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        ++stats.drawCalls;
        stats.triangles += 2;
    }
}

}  // namespace cavewall::walls::gl
