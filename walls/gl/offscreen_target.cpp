#include "walls/gl/offscreen_target.h"

#include "config/error.h"
#include "display/gl/render_targets.h"

#include <algorithm>
#include <string>

namespace cavewall::walls::gl {

OffscreenTarget::OffscreenTarget(glm::ivec2 size)
    : _size(size), _color(display::gl::createTexture(GL_TEXTURE_2D)), _depth(display::gl::createTexture(GL_TEXTURE_2D)),
      _framebuffer(display::gl::createFramebuffer()) {
    glTextureStorage2D(_color.id(), 1, GL_SRGB8_ALPHA8, size.x, size.y);
    glTextureStorage2D(_depth.id(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
    glNamedFramebufferTexture(_framebuffer.id(), GL_COLOR_ATTACHMENT0, _color.id(), 0);
    glNamedFramebufferTexture(_framebuffer.id(), GL_DEPTH_ATTACHMENT, _depth.id(), 0);
    const GLenum status = glCheckNamedFramebufferStatus(_framebuffer.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("offscreen target " + std::to_string(size.x) + " x " + std::to_string(size.y) +
                    ": framebuffer is incomplete (GL status " + std::to_string(status) + ")");
}

void OffscreenTarget::bindAndClear(glm::vec4 c) const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, _framebuffer.id());
    glViewport(0, 0, _size.x, _size.y);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glClearColor(c.r, c.g, c.b, c.a);
    glClearDepth(0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

scenes::Image OffscreenTarget::read(const std::string& name) const {
    return display::gl::readFramebuffer(_framebuffer.id(), GL_COLOR_ATTACHMENT0, _size, name);
}

std::vector<float> OffscreenTarget::readDepth() const {
    std::vector<float> bottomUp(static_cast<std::size_t>(_size.x) * _size.y);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, _framebuffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, _size.x, _size.y, GL_DEPTH_COMPONENT, GL_FLOAT, bottomUp.data());
    std::vector<float> rows(bottomUp.size());
    for (int y = 0; y < _size.y; ++y)
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(_size.y - 1 - y) * _size.x, _size.x,
                    rows.begin() + std::ptrdiff_t(y) * _size.x);
    return rows;
}

}  // namespace cavewall::walls::gl
