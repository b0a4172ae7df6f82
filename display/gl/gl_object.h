#pragma once
// Owning handles for OpenGL objects: move-only, deleted with the right glDelete* call when they
// go out of scope. The context that created an object must be current when it is destroyed.

#include <epoxy/gl.h>

#include <utility>

namespace cavewall::display::gl {

class GlObject {
public:
    using Deleter = void (*)(GLuint);

    GlObject() = default;
    GlObject(GLuint id, Deleter deleter) : _id(id), _deleter(deleter) {}
    GlObject(GlObject&& o) noexcept : _id(std::exchange(o._id, 0)), _deleter(o._deleter) {}
    GlObject& operator=(GlObject&& o) noexcept {
        if (this != &o) {
            reset();
            _id = std::exchange(o._id, 0);
            _deleter = o._deleter;
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    ~GlObject() { reset(); }

    GLuint id() const { return _id; }
    explicit operator bool() const { return _id != 0; }
    void reset() {
        if (_id && _deleter) _deleter(_id);
        _id = 0;
    }

private:
    GLuint _id = 0;
    Deleter _deleter = nullptr;
};

// Creation through DSA (GL 4.5): the objects exist (and have their type) right away.
GlObject createBuffer();
GlObject createVertexArray();
GlObject createTexture(GLenum target);
GlObject createFramebuffer();
GlObject createSampler();
GlObject createProgram();
GlObject createShader(GLenum stage);

}  // namespace cavewall::display::gl
