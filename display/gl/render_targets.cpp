#include "display/gl/render_targets.h"

#include "config/error.h"

#include <algorithm>
#include <cassert>
#include <cstring>

namespace cavewall::display::gl {

namespace {

GlObject texture2d(GLenum format, glm::ivec2 size) {
    GlObject t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, size.x, size.y);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

}  // namespace

RenderTargets::RenderTargets(const display::Display& display, const Context& context) {
    const config::StereoMode mode = display.config().stereo;
    if (mode == config::StereoMode::QuadBuffer && !context.info().stereoWindows)
        throw Error("display '" + display.config().name +
                    "': stereo mode quad-buffer needs windows with "
                    "quad-buffer stereo (GL_BACK_LEFT and GL_BACK_RIGHT), but the " +
                    context.info().provider + " context (" + context.info().renderer +
                    ") has none; use separate, side-by-side, "
                    "top-bottom or anaglyph");
    const int images = mode == config::StereoMode::QuadBuffer ? 2 : display::imagesPerScreen(mode);
    for (const config::Screen& s : display.screens()) {
        Screen screen{s.name, s.resolution, {}};
        for (int i = 0; i < images; ++i) {
            Output out{texture2d(GL_SRGB8_ALPHA8, s.resolution), texture2d(GL_DEPTH_COMPONENT32F, s.resolution),
                       createFramebuffer()};
            glNamedFramebufferTexture(out.framebuffer.id(), GL_COLOR_ATTACHMENT0, out.color.id(), 0);
            glNamedFramebufferTexture(out.framebuffer.id(), GL_DEPTH_ATTACHMENT, out.depth.id(), 0);
            const GLenum status = glCheckNamedFramebufferStatus(out.framebuffer.id(), GL_FRAMEBUFFER);
            if (status != GL_FRAMEBUFFER_COMPLETE)
                throw Error("screen '" + s.name + "': render target is incomplete (GL status " +
                            std::to_string(status) + ") on " + context.info().renderer);
            screen.images.push_back(std::move(out));
        }
        _screens.push_back(std::move(screen));
    }
}

void RenderTargets::bind(int screen, int image) const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, _screens[screen].images[image].framebuffer.id());
}

scenes::Image RenderTargets::read(int screen, int image) const {
    const Screen& s = _screens[screen];
    return readFramebuffer(s.images[image].framebuffer.id(), GL_COLOR_ATTACHMENT0, s.size, s.name);
}

std::vector<float> RenderTargets::readDepth(int screen, int image, const display::Viewport& viewport) const {
    const Screen& s = _screens[screen];
    assert(viewport.x >= 0 && viewport.y >= 0 && viewport.width > 0 && viewport.height > 0 &&
           viewport.x + viewport.width <= s.size.x && viewport.y + viewport.height <= s.size.y);
    std::vector<float> bottomUp(std::size_t(viewport.width) * viewport.height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, s.images[image].framebuffer.id());
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(viewport.x, viewport.y, viewport.width, viewport.height, GL_DEPTH_COMPONENT, GL_FLOAT,
                 bottomUp.data());
    std::vector<float> depth(bottomUp.size());
    const std::size_t row = std::size_t(viewport.width);
    for (int y = 0; y < viewport.height; ++y)
        std::memcpy(&depth[y * row], &bottomUp[(viewport.height - 1 - y) * row], row * sizeof(float));
    return depth;
}

scenes::Image readFramebuffer(unsigned framebuffer, unsigned buffer, glm::ivec2 size, std::string name) {
    scenes::Image image{std::move(name), size.x, size.y, std::vector<std::uint8_t>(std::size_t(size.x) * size.y * 4)};
    // Not glNamedFramebufferReadBuffer: on framebuffer 0 (a window) Mesa 22 then fails glReadPixels.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(buffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    // GL rows go bottom to top; files go top to bottom.
    const std::size_t row = std::size_t(size.x) * 4;
    std::vector<std::uint8_t> swap(row);
    for (int y = 0; y < size.y / 2; ++y) {
        std::uint8_t* a = &image.rgba[y * row];
        std::uint8_t* b = &image.rgba[(size.y - 1 - y) * row];
        std::memcpy(swap.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, swap.data(), row);
    }
    return image;
}

}  // namespace cavewall::display::gl
