#pragma once
// An offscreen colour + depth target of one size: GL_SRGB8_ALPHA8 colour (shaders write linear
// light with GL_FRAMEBUFFER_SRGB on; stored bytes are sRGB) and GL_DEPTH_COMPONENT32F depth for
// reversed-Z. No multisampling. Used to bake wall textures and by the bake tests.

#include "display/gl/gl_object.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace cavewall::walls::gl {

class OffscreenTarget {
public:
    // Needs a current GL 4.5 context. Throws Error when the framebuffer is incomplete.
    explicit OffscreenTarget(glm::ivec2 size);

    glm::ivec2 size() const { return _size; }
    unsigned framebuffer() const { return _framebuffer.id(); }
    // Binds the framebuffer for drawing, sets the viewport to the whole target and clears
    // colour to `linearColor` and depth to 0 (the far value of reversed-Z).
    void bindAndClear(glm::vec4 linearColor) const;
    // 8-bit RGBA as stored (sRGB colour, linear alpha), rows top to bottom.
    scenes::Image read(const std::string& name) const;
    // The depth buffer as stored (reversed-Z float, 0 where nothing was drawn), rows top to
    // bottom like read().
    std::vector<float> readDepth() const;

private:
    glm::ivec2 _size;
    display::gl::GlObject _color, _depth, _framebuffer;
};

}  // namespace cavewall::walls::gl
