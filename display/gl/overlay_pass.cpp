#include "display/gl/overlay_pass.h"

#include "display/gl/shader.h"

#include <cstddef>

namespace cavewall::display::gl {
namespace {

constexpr const char* kOverlayName = "overlay";

constexpr const char* kOverlayVertex = R"(#version 450 core
layout(location = 0) in vec2 aPosition;   // window pixels, y down
layout(location = 1) in vec4 aColour;
uniform vec2 uSize;                        // the framebuffer's pixels
out vec4 vColour;
void main() {
    vColour = aColour;
    gl_Position = vec4(aPosition.x / uSize.x * 2.0 - 1.0, 1.0 - aPosition.y / uSize.y * 2.0, 0.0, 1.0);
}
)";

constexpr const char* kOverlayFragment = R"(#version 450 core
in vec4 vColour;
out vec4 fragColor;
void main() { fragColor = vColour; }
)";

}  // namespace

OverlayPass::OverlayPass()
    : _program(buildProgram(kOverlayName, kOverlayVertex, kOverlayFragment)), _vertexArray(createVertexArray()),
      _buffer(createBuffer()) {
    _size = uniformLocation(_program.id(), kOverlayName, "uSize");
    const GLuint vao = _vertexArray.id();
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 2, GL_FLOAT, GL_FALSE, offsetof(display::OverlayVertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribFormat(vao, 1, 4, GL_FLOAT, GL_FALSE, offsetof(display::OverlayVertex, colour));
    glVertexArrayAttribBinding(vao, 1, 0);
}

void OverlayPass::draw(const std::vector<display::OverlayVertex>& vertices, glm::ivec2 size) {
    if (vertices.empty() || size.x <= 0 || size.y <= 0) return;
    if (vertices.size() > _capacity) {  // buffers are re-made to grow (a named buffer's storage is set once)
        _buffer = createBuffer();
        _capacity = vertices.size();
        glNamedBufferData(_buffer.id(), _capacity * sizeof(display::OverlayVertex), nullptr, GL_DYNAMIC_DRAW);
        glVertexArrayVertexBuffer(_vertexArray.id(), 0, _buffer.id(), 0, sizeof(display::OverlayVertex));
    }
    glNamedBufferSubData(_buffer.id(), 0, vertices.size() * sizeof(display::OverlayVertex), vertices.data());
    glUseProgram(_program.id());
    glBindVertexArray(_vertexArray.id());
    glUniform2f(_size, static_cast<float>(size.x), static_cast<float>(size.y));
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace cavewall::display::gl
