#include "walkthrough/gl/hand_cursor.h"

#include "display/gl/shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>

namespace cavewall::walkthrough::gl {

namespace {

constexpr const char* kName = "hand cursor";

constexpr const char* kVertex = R"(#version 450 core
layout(location = 0) in vec3 aPosition;   // eye-relative view frame
uniform mat4 uProjection;
void main() { gl_Position = uProjection * vec4(aPosition, 1.0); }
)";

constexpr const char* kFragment = R"(#version 450 core
uniform vec4 uColor;
out vec4 fragColor;
void main() { fragColor = uColor; }
)";

// The icon in the hand frame (metres): palm quad and a pointing finger, then the ray's start.
constexpr int kIconVertices = 9;
const std::array<glm::dvec3, kIconVertices> kIcon = {{
    {-0.03, 0.0, 0.04},
    {0.03, 0.0, 0.04},
    {-0.03, 0.0, -0.04},  // palm
    {0.03, 0.0, 0.04},
    {0.03, 0.0, -0.04},
    {-0.03, 0.0, -0.04},
    {-0.01, 0.0, -0.04},
    {0.01, 0.0, -0.04},
    {0.0, 0.0, -0.09},  // finger
}};

}  // namespace

HandCursorPass::HandCursorPass()
    : _program(display::gl::buildProgram(kName, kVertex, kFragment)), _vertexArray(display::gl::createVertexArray()),
      _buffer(display::gl::createBuffer()) {
    _projection = display::gl::uniformLocation(_program.id(), kName, "uProjection");
    _color = display::gl::uniformLocation(_program.id(), kName, "uColor");
    glNamedBufferData(_buffer.id(), (kIconVertices + 2) * sizeof(glm::vec3), nullptr, GL_DYNAMIC_DRAW);
    glVertexArrayVertexBuffer(_vertexArray.id(), 0, _buffer.id(), 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(_vertexArray.id(), 0);
    glVertexArrayAttribFormat(_vertexArray.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(_vertexArray.id(), 0, 0);
}

void HandCursorPass::draw(const HandCursorPose& hand, const display::OffAxisFrustum& frustum,
                          display::FrameStats& stats) {
    const glm::dmat4 viewFromHand =
        frustum.viewFromFrame * glm::translate(glm::dmat4(1.0), hand.position) * glm::mat4_cast(hand.orientation);
    std::array<glm::vec3, kIconVertices + 2> vertices;
    for (int i = 0; i < kIconVertices; ++i) vertices[i] = glm::vec3(viewFromHand * glm::dvec4(kIcon[i], 1.0));
    vertices[kIconVertices] = glm::vec3(viewFromHand * glm::dvec4(0.0, 0.0, -0.09, 1.0));
    const double length = std::isfinite(hand.rayLength) && hand.rayLength > 0.0 ? hand.rayLength : 0.0;
    vertices[kIconVertices + 1] = glm::vec3(viewFromHand * glm::dvec4(0.0, 0.0, -0.09 - length, 1.0));
    glNamedBufferSubData(_buffer.id(), 0, sizeof vertices, vertices.data());

    glUseProgram(_program.id());
    glBindVertexArray(_vertexArray.id());
    const glm::mat4 projection(frustum.clipFromView);
    glUniformMatrix4fv(_projection, 1, GL_FALSE, glm::value_ptr(projection));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUniform4f(_color, 0.95f, 0.8f, 0.55f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, kIconVertices);
    glUniform4f(_color, 1.0f, 0.15f, 0.1f, 1.0f);
    glDrawArrays(GL_LINES, kIconVertices, 2);
    stats.drawCalls += 2;
    stats.triangles += kIconVertices / 3;
}

}  // namespace cavewall::walkthrough::gl
