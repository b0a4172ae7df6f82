#include "display/gl/shader.h"

#include "config/error.h"

#include <initializer_list>
#include <vector>

namespace cavewall::display::gl {

namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.data();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.data();
}

const char* stageName(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER: return "vertex";
        case GL_COMPUTE_SHADER: return "compute";
        default: return "fragment";
    }
}

GlObject link(std::string_view name, std::initializer_list<GLuint> shaders) {
    GlObject program = createProgram();
    for (GLuint s : shaders) glAttachShader(program.id(), s);
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) throw Error("shader program '" + std::string(name) + "': link stage failed: " + programLog(program.id()));
    for (GLuint s : shaders) glDetachShader(program.id(), s);
    return program;
}

GlObject compile(std::string_view name, GLenum stage, std::string_view source) {
    GlObject shader = createShader(stage);
    const GLchar* text = source.data();
    const auto length = static_cast<GLint>(source.size());
    glShaderSource(shader.id(), 1, &text, &length);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        throw Error("shader program '" + std::string(name) + "': " + stageName(stage) +
                    " stage failed to compile: " + shaderLog(shader.id()));
    return shader;
}

}  // namespace

GlObject buildProgram(std::string_view name, std::string_view vertexSource, std::string_view fragmentSource) {
    const GlObject vertex = compile(name, GL_VERTEX_SHADER, vertexSource);
    const GlObject fragment = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
    return link(name, {vertex.id(), fragment.id()});
}

GlObject buildComputeProgram(std::string_view name, std::string_view computeSource) {
    const GlObject compute = compile(name, GL_COMPUTE_SHADER, computeSource);
    return link(name, {compute.id()});
}

GLint uniformLocation(GLuint program, std::string_view programName, const char* uniform) {
    const GLint location = glGetUniformLocation(program, uniform);
    if (location < 0)
        throw Error("shader program '" + std::string(programName) + "': expected an active uniform '" + uniform +
                    "', got none");
    return location;
}

}  // namespace cavewall::display::gl
