#include "display/gl/gl_object.h"

namespace cavewall::display::gl {

GlObject createBuffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return {id, [](GLuint i) { glDeleteBuffers(1, &i); }};
}

GlObject createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return {id, [](GLuint i) { glDeleteVertexArrays(1, &i); }};
}

GlObject createTexture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return {id, [](GLuint i) { glDeleteTextures(1, &i); }};
}

GlObject createFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return {id, [](GLuint i) { glDeleteFramebuffers(1, &i); }};
}

GlObject createSampler() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return {id, [](GLuint i) { glDeleteSamplers(1, &i); }};
}

GlObject createProgram() {
    return {glCreateProgram(), [](GLuint i) { glDeleteProgram(i); }};
}

GlObject createShader(GLenum stage) {
    return {glCreateShader(stage), [](GLuint i) { glDeleteShader(i); }};
}

}  // namespace cavewall::display::gl
