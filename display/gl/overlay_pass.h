#pragma once
// Draws an overlay's triangles (display/overlay_text.h) over whatever the bound draw
// framebuffer holds: alpha-blended, no depth test, no sRGB conversion (the bytes are written as
// given, as the window's blit copies the image's). Window overlays only: the scene's saved and
// compared images never pass through here.

#include "display/gl/gl_object.h"
#include "display/overlay_text.h"

#include <glm/glm.hpp>

#include <vector>

namespace cavewall::display::gl {

class OverlayPass {
public:
    // Builds the program and buffers in the current context (they belong to it: vertex arrays
    // are not shared between contexts, so each window has its own pass).
    OverlayPass();

    // Draws `vertices` (window pixels, y down) into the bound draw framebuffer of `size` pixels.
    // Leaves blending off and the program and vertex array unbound.
    void draw(const std::vector<display::OverlayVertex>& vertices, glm::ivec2 size);

private:
    GlObject _program, _vertexArray, _buffer;
    GLint _size = -1;
    std::size_t _capacity = 0;  // vertices the buffer holds
};

}  // namespace cavewall::display::gl
