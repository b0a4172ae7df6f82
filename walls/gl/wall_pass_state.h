#pragma once
// The GL state both wall passes draw in (gl::WallPass and gl::DepthWallPass), and their
// depth-only programs, built on first use. Needs the rendering context current.

#include <epoxy/gl.h>

#include <cstddef>
#include <optional>

namespace cavewall::walls::gl {

// Runs `draw()` blended over the bound framebuffer: depth-tested (reversed-Z, GL_GREATER)
// without depth writes, no face culling, premultiplied colour (ONE, ONE_MINUS_SRC_ALPHA) that
// keeps the destination's alpha. Afterwards depth writes are on and blending is off.
template <typename Draw>
void drawBlendedWalls(const Draw& draw) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    draw();
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

// Runs `draw(*programs)` writing only depth: depth-tested (reversed-Z, GL_GREATER) with depth
// writes, no face culling, no blending, the colour mask off (all on afterwards). `programs` (an
// array of programs, [n - 1] for n textures) is filled with `build(n)` first when it is empty:
// only depth read-backs need them.
template <typename Programs, typename Build, typename Draw>
void drawWallDepth(std::optional<Programs>& programs, const Build& build, const Draw& draw) {
    if (!programs) {
        programs.emplace();
        for (std::size_t n = 1; n <= programs->size(); ++n) (*programs)[n - 1] = build(static_cast<int>(n));
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    draw(*programs);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace cavewall::walls::gl
